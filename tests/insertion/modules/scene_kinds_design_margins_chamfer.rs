//! The items of `src/scene/kinds/design_margins/chamfer.rs`.

use pegdyn::scene::kinds::design_margins::chamfer::*;

fn shipped() -> Capture {
    Capture {
        peg_radius: 0.5 * 0.025 * (1.0 - 0.003),
        bore_radius: 0.0125,
        rim_fillet: 3e-4,
        mouth_fillet: 5e-4,
        friction: 0.2,
        centre_height: 0.025,
    }
}

#[test]
fn an_aligned_peg_is_captured_within_the_fillets_and_clearance() {
    let c = Capture {
        friction: 0.0,
        ..shipped()
    };
    // (R − r) + ρ_h + ρ_p = 37.5 µm + 0.5 mm + 0.3 mm.
    assert!((c.aligned_tip_error() - 0.8375e-3).abs() < 1e-12);
    let c = shipped();
    // Less (ρ_h + ρ_p) μ/√(1 + μ²) = 0.8 mm × 0.196116 = 0.156893 mm.
    assert!((c.aligned_tip_error() - (0.8375e-3 - 0.8e-3 * 0.2 / 1.04f64.sqrt())).abs() < 1e-12);
}

#[test]
fn the_tilt_moves_the_tip_by_the_lever_of_the_compliance_centre() {
    let c = shipped();
    let e = InitialError {
        centre: [1e-4, 0.0],
        tilt: 1f64.to_radians(),
        azimuth: std::f64::consts::PI,
    };
    let v = c.verdict(&e);
    // Tilted towards −x, the tip lies at +x by L_c sin θ = 0.4363 mm.
    assert!((v.tip[0] - (1e-4 + 0.025 * 1f64.to_radians().sin())).abs() < 1e-15);
    assert!(v.tip[1].abs() < 1e-15);
    let (lo, hi) = c
        .boundary(0.0, e.tilt, e.azimuth, false)
        .expect("accepted interval");
    // Towards −x the rim is lowered: it touches first in the error's
    // plane at its farthest point, the tube centre (r − ρ_p) cos θ +
    // ρ_p sin θ beyond the tip, so the lower edge is the planar one.
    let (st, ct) = e.tilt.sin_cos();
    let tip_lo = -(c.width() - (c.peg_radius - c.rim_fillet) * ct - c.rim_fillet * st);
    assert!((lo - (tip_lo - 0.025 * st)).abs() < 1e-9, "{lo}");
    let at_lo = c.verdict(&InitialError {
        centre: [lo + 1e-7, 0.0],
        ..e
    });
    assert!(
        matches!(at_lo.touch, Touch::Round { rim_angle, .. } if rim_angle.min(std::f64::consts::TAU - rim_angle) < 1e-6),
        "{at_lo:?}"
    );
    // Towards +x the rim is raised by up to (r − ρ_p) sin θ = 0.21 mm:
    // lower rim points off the error's plane touch first, on the
    // steeper inner part of the round, and the band reaches further.
    let tip_hi_planar = c.width() - (c.peg_radius - c.rim_fillet) * ct + c.rim_fillet * st;
    assert!(hi + 0.025 * st > tip_hi_planar + 1e-5, "{hi}");
    let at_hi = c.verdict(&InitialError {
        centre: [hi - 1e-7, 0.0],
        ..e
    });
    assert!(at_hi.accepts(), "{at_hi:?}");
    assert!(
        !c.verdict(&InitialError {
            centre: [hi + 1e-7, 0.0],
            ..e
        })
        .accepts()
    );
}
