//! The mouth's capture rule: which initial lateral and angular errors the
//! rounded chamfer guides into the bore (derivation in `docs/insertion.md`,
//! "Chamfer acceptance with a compliance centre").
//!
//! The robot positions the compliance centre, `L_c` above the tip on the
//! peg's axis, with a lateral error `e_c` (a horizontal vector) and tilts
//! the axis by `θ` towards the azimuth `ψ`. The tip lies `L_c` below the
//! centre along the axis `a = (sin θ cos ψ, sin θ sin ψ, cos θ)`, so its
//! lateral error is
//!
//! ```text
//! e_t = e_c − L_c sin θ (cos ψ, sin ψ)                      (m)
//! ```
//!
//! The rim's tube centres lie on a circle of radius `r − ρ_p` about the
//! tip, in the plane normal to `a`; seen from above it is an ellipse with
//! semi-axes `(r − ρ_p) cos θ` along the tilt and `r − ρ_p` across it, so
//! its reach in the direction of `e_t` (angle `β` from the tilt's azimuth)
//! is `(r − ρ_p) √(cos²θ cos²β + sin²β)`. The rim lands on the mouth's
//! rounded edge (tube centres on radius `R + ρ_h`, `ρ_h` below the top
//! face) in the vertical plane through both axes; the contact normal runs
//! between the two tube centres and makes the angle `α` with the vertical,
//! `sin α = δ / (ρ_h + ρ_p)`, `δ = R + ρ_h − (|e_t| + reach)`. Pushed down,
//! the rim slides inwards only if the normal is steeper than the friction
//! angle, `tan α > μ`, i.e.
//!
//! ```text
//! |e_t| + reach < W_μ = R + ρ_h − (ρ_h + ρ_p) μ / √(1 + μ²)    (m)
//! ```
//!
//! Without friction the bound is `W_0 = R + ρ_h`, i.e. the aligned, centred
//! capture width `(R − r) + ρ_h + ρ_p`.

/// The capture geometry: peg, hole, fillets, friction and where the
/// compliance centre sits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Capture {
    /// Peg radius `r` (m).
    pub peg_radius: f64,
    /// Bore radius `R` (m).
    pub bore_radius: f64,
    /// Rim fillet `ρ_p` (m).
    pub rim_fillet: f64,
    /// Mouth fillet `ρ_h` (m): the chamfer's width.
    pub mouth_fillet: f64,
    /// Coulomb friction `μ`.
    pub friction: f64,
    /// Height `L_c` of the compliance centre above the tip (m).
    pub centre_height: f64,
}

/// One initial error of the robot: the compliance centre's lateral error
/// and the axis's tilt.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InitialError {
    /// Lateral error of the compliance centre, `(x, y)` (m).
    pub centre: [f64; 2],
    /// Tilt `θ` of the axis (rad).
    pub tilt: f64,
    /// Azimuth `ψ` of the tilt (rad from `x`).
    pub azimuth: f64,
}

/// What the rule says about one initial error.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Verdict {
    /// The tip's lateral error `e_t` (m).
    pub tip: [f64; 2],
    /// Largest horizontal distance of a rim tube centre from the hole's
    /// axis, `|e_t| + reach` (m).
    pub reach: f64,
    /// `W_μ − reach` (m): positive when the chamfer accepts the error.
    pub margin: f64,
    /// `W_0 − reach` (m): positive when a frictionless chamfer would.
    pub frictionless_margin: f64,
}

impl Verdict {
    /// True when the rule predicts that the chamfer guides the peg in.
    pub fn accepts(&self) -> bool {
        self.margin > 0.0
    }
}

impl Capture {
    /// `W_0 = R + ρ_h` (m): the largest tube-centre distance a frictionless
    /// chamfer captures.
    pub fn frictionless_width(&self) -> f64 {
        self.bore_radius + self.mouth_fillet
    }

    /// `W_μ = R + ρ_h − (ρ_h + ρ_p) μ/√(1 + μ²)` (m).
    pub fn width(&self) -> f64 {
        let mu = self.friction;
        self.frictionless_width() - (self.mouth_fillet + self.rim_fillet) * mu / mu.hypot(1.0)
    }

    /// The largest lateral error of the tip an aligned peg may have,
    /// `W_μ − (r − ρ_p)` (m); `(R − r) + ρ_h + ρ_p` without friction.
    pub fn aligned_tip_error(&self) -> f64 {
        self.width() - (self.peg_radius - self.rim_fillet)
    }

    /// The tip's lateral error `e_t = e_c − L_c sin θ (cos ψ, sin ψ)` (m).
    pub fn tip_error(&self, e: &InitialError) -> [f64; 2] {
        let s = self.centre_height * e.tilt.sin();
        [
            e.centre[0] - s * e.azimuth.cos(),
            e.centre[1] - s * e.azimuth.sin(),
        ]
    }

    /// The rule applied to `e`.
    pub fn verdict(&self, e: &InitialError) -> Verdict {
        let tip = self.tip_error(e);
        let n = tip[0].hypot(tip[1]);
        // Angle between the tip's error and the tilt's azimuth (any, when
        // the tip is centred: the reach is then at most r − ρ_p).
        let beta = if n > 0.0 {
            tip[1].atan2(tip[0]) - e.azimuth
        } else {
            0.0
        };
        let (c, sb) = (e.tilt.cos() * beta.cos(), beta.sin());
        let reach = n + (self.peg_radius - self.rim_fillet) * (c * c + sb * sb).sqrt();
        Verdict {
            tip,
            reach,
            margin: self.width() - reach,
            frictionless_margin: self.frictionless_width() - reach,
        }
    }

    /// The compliance-centre errors `e_c` along the unit direction `dir`
    /// (rad from `x`) at which the rule's margin (`frictionless`: the
    /// frictionless margin) is zero, at tilt `tilt` towards `azimuth`: the
    /// two ends `(lower, upper)` of the accepted interval, or `None` when
    /// no error is accepted. Bisection on the margin, which is concave in
    /// `e_c` (a norm plus a bounded term), to 1e-12 of the width.
    pub fn boundary(
        &self,
        dir: f64,
        tilt: f64,
        azimuth: f64,
        frictionless: bool,
    ) -> Option<(f64, f64)> {
        let m = |s: f64| {
            let v = self.verdict(&InitialError {
                centre: [s * dir.cos(), s * dir.sin()],
                tilt,
                azimuth,
            });
            if frictionless {
                v.frictionless_margin
            } else {
                v.margin
            }
        };
        // The centre of the accepted interval: where the tip is centred
        // along `dir`.
        let s0 = self.centre_height * tilt.sin() * (azimuth - dir).cos();
        if m(s0) <= 0.0 {
            return None;
        }
        let span = 2.0 * self.frictionless_width() + self.centre_height.abs();
        let solve = |outside: f64| {
            let (mut a, mut b) = (s0, outside);
            for _ in 0..200 {
                let c = 0.5 * (a + b);
                if m(c) > 0.0 {
                    a = c;
                } else {
                    b = c;
                }
                if (b - a).abs() < 1e-12 * span {
                    break;
                }
            }
            0.5 * (a + b)
        };
        Some((solve(s0 - span), solve(s0 + span)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
        // The interval is centred where the tip is centred, −L_c sin θ,
        // and its half-width is the aligned width less the tilt's
        // (r − ρ_p)(1 − cos θ) gain.
        let half = c.width() - (c.peg_radius - c.rim_fillet) * e.tilt.cos();
        let mid = -0.025 * e.tilt.sin();
        assert!((hi - (mid + half)).abs() < 1e-12, "{hi}");
        assert!((lo - (mid - half)).abs() < 1e-12, "{lo}");
        assert!(c.verdict(&InitialError { centre: [hi - 1e-9, 0.0], ..e }).accepts());
        assert!(!c.verdict(&InitialError { centre: [hi + 1e-9, 0.0], ..e }).accepts());
    }
}
