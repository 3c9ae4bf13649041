//! The paper's Eq. 52 (two-point contact forces and moment about the centre
//! of mass, paper frame) agrees with the Whitney-frame solution at the tip,
//! and its solutions satisfy Eq. 51; the one-point forms (Eqs. 53–54,
//! corrected) satisfy Eq. 51 with the other force zero; and the generated
//! model `quasi_static` (derived from the contact geometry in
//! `equations/src/models/quasi_static.rs`) reproduces all of them.

use pegdyn::jamming::PegHole;
use pegdyn::jamming::forces::{sliding_contact_forces, sliding_moment};
use pegdyn::jamming::quasi_static::*;

fn peg() -> PaperPeg {
    PaperPeg {
        theta: 0.04,
        mu: 0.3,
        r: 0.0125,
        l: 0.01,
        l_c: 0.06,
        m: 0.4,
        j: 2e-4,
    }
}

/// Residuals of Eq. 51 for a candidate solution.
fn eq51(p: &PaperPeg, u: PegLoad, a: PegAcc, s: PaperSolution) -> [f64; 3] {
    let (sn, cs) = p.theta.sin_cos();
    let k1 = cs - p.mu * sn;
    let k2 = sn + p.mu * cs;
    let (sax, say, sbx, sby) = p.arms();
    [
        p.m * a.xdd - (u.f1 * sn + u.f2 * cs + k1 * s.f_a - s.f_b),
        p.m * a.ydd - (u.f1 * cs - u.f2 * sn - k2 * s.f_a - p.mu * s.f_b),
        p.j * a.thdd - (s.m + (say - p.mu * sax) * s.f_a - (sby - p.mu * sbx) * s.f_b),
    ]
}

#[test]
fn eq52_solves_eq51() {
    let p = peg();
    let u = PegLoad { f1: 12.0, f2: -1.5 };
    let a = PegAcc {
        xdd: 0.3,
        ydd: 1.2,
        thdd: -4.0,
    };
    let s = p.two_point(u, a);
    for r in eq51(&p, u, a, s) {
        assert!(r.abs() < 1e-12, "{r}");
    }
}

#[test]
fn eq52_matches_whitney_frame_at_the_tip() {
    let p = peg();
    let hp = PegHole::try_new(p.r, 0.01, p.mu).unwrap();
    let (sn, cs) = p.theta.sin_cos();
    for (f1, f2) in [(10.0, 0.0), (10.0, 2.0), (5.0, -1.0)] {
        let s = p.two_point(PegLoad { f1, f2 }, PegAcc::default());
        // paper frame is the mirror image of Whitney's: F_x = −X, F_z = Y
        let (x, y) = (f1 * sn + f2 * cs, f1 * cs - f2 * sn);
        let (fx, fz) = (-x, y);
        let w = sliding_contact_forces(&hp, p.theta, fx, fz);
        assert!((w.edge - s.f_a).abs() < 1e-12 && (w.tip - s.f_b).abs() < 1e-12);
        // moment about C moved to the tip: C − T = l_c (sinθ, −cosθ)
        let m_tip = s.m + p.l_c * (sn * fz + cs * fx);
        let whitney = sliding_moment(&hp, p.l, p.theta, fx, fz);
        assert!((m_tip - whitney).abs() < 1e-12, "{m_tip} vs {whitney}");
    }
}

#[test]
fn one_point_forms_solve_eq51_with_other_force_zero() {
    let p = peg();
    let u = PegLoad { f1: 8.0, f2: -2.0 };
    let (sn, cs) = p.theta.sin_cos();
    let k2 = sn + p.mu * cs;
    // edge only: choose ẍ, then ÿ consistent with the tangential balance
    let s_a = {
        let xdd = 0.5;
        // solve the pair for (f_A, ÿ): x-eq gives f_A, y-eq gives ÿ
        let k1 = cs - p.mu * sn;
        let f_a = (p.m * xdd - u.f1 * sn - u.f2 * cs) / k1;
        let ydd = (u.f1 * cs - u.f2 * sn - k2 * f_a) / p.m;
        let a = PegAcc {
            xdd,
            ydd,
            thdd: 1.0,
        };
        (p.edge_only(u, a), a)
    };
    for r in eq51(&p, u, s_a.1, s_a.0) {
        assert!(r.abs() < 1e-12, "edge-only residual {r}");
    }
    let a = PegAcc {
        xdd: 0.2,
        ydd: 0.0,
        thdd: -2.0,
    };
    let s_b = p.tip_only(u, a);
    let ydd = (u.f1 * cs - u.f2 * sn - p.mu * s_b.f_b) / p.m;
    let a = PegAcc { ydd, ..a };
    for r in eq51(&p, u, a, p.tip_only(u, a)) {
        assert!(r.abs() < 1e-12, "tip-only residual {r}");
    }
}

#[test]
fn generated_model_matches_hand_written_solution() {
    use nalgebra::SVector;
    use pegdyn::generated::quasi_static as qs;
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * (1.0 + a.abs().max(b.abs()));
    for (theta, l, f1, f2, acc) in [
        (0.04, 0.01, 12.0, -1.5, [0.3, 1.2, -4.0]),
        (0.2, 0.03, 5.0, 2.0, [0.0, 0.0, 0.0]),
        (-0.1, 0.02, 8.0, 0.5, [-1.0, 0.4, 2.5]),
    ] {
        let p = PaperPeg { theta, l, ..peg() };
        let (u, a) = (
            PegLoad { f1, f2 },
            PegAcc {
                xdd: acc[0],
                ydd: acc[1],
                thdd: acc[2],
            },
        );
        let pose = SVector::from([theta, l]);
        let load = SVector::from([f1, f2]);
        let accv = SVector::from(acc);
        let params = qs::Params {
            mu: p.mu,
            r: p.r,
            l_c: p.l_c,
            m: p.m,
            J: p.j,
        }
        .into();
        let qs::TwoPointOut {
            f_a: fa,
            f_b: fb,
            moment: m,
        } = qs::two_point(&pose, &load, &accv, &params);
        let h = p.two_point(u, a);
        assert!(
            close(fa, h.f_a) && close(fb, h.f_b) && close(m, h.m),
            "{fa} {fb} {m} vs {h:?}"
        );
        let qs::EdgeOnlyOut { f_a: fa, moment: m } = qs::edge_only(&pose, &load, &accv, &params);
        let h = p.edge_only(u, a);
        assert!(
            close(fa, h.f_a) && close(m, h.m),
            "edge only {fa} {m} vs {h:?}"
        );
        let qs::TipOnlyOut { f_b: fb, moment: m } = qs::tip_only(&pose, &load, &accv, &params);
        let h = p.tip_only(u, a);
        assert!(
            close(fb, h.f_b) && close(m, h.m),
            "tip only {fb} {m} vs {h:?}"
        );

        let hp = PegHole::try_new(p.r, 0.01, p.mu).unwrap();
        let (fx, fz) = (f2, f1);
        let q = qs::WhitneyParams { mu: p.mu, r: p.r }.into();
        let qs::WhitneyTipOut {
            f_tip: ft,
            f_edge: fe,
            moment: mt,
        } = qs::whitney_tip(&pose, &SVector::from([fx, fz]), &q);
        let w = sliding_contact_forces(&hp, theta, fx, fz);
        assert!(close(ft, w.tip) && close(fe, w.edge), "{ft} {fe} vs {w:?}");
        assert!(close(mt, sliding_moment(&hp, l, theta, fx, fz)));
    }
}

#[test]
fn whitney_load_converted_to_paper_frame_gives_the_same_contact_forces() {
    use pegdyn::jamming::forces::{Wrench, to_paper_frame};
    let p = peg();
    let hp = PegHole::try_new(p.r, 0.01, p.mu).unwrap();
    for (fx, fz) in [(0.0, 10.0), (2.0, 10.0), (-3.0, 5.0)] {
        let m = sliding_moment(&hp, p.l, p.theta, fx, fz);
        let (f1, f2, m_c) = to_paper_frame(&Wrench { fx, fz, m }, p.theta, p.l_c);
        let s = p.two_point(PegLoad { f1, f2 }, PegAcc::default());
        let w = sliding_contact_forces(&hp, p.theta, fx, fz);
        assert!((s.f_a - w.edge).abs() < 1e-12 && (s.f_b - w.tip).abs() < 1e-12);
        assert!((s.m - m_c).abs() < 1e-12, "{} vs {m_c}", s.m);
    }
}

/// The exact two-point segment seen in the paper's plane reproduces the
/// paper's (75) bounds `−1/μ < f₂/f₁ < k₁/k₂` at its ends and lies on the
/// line (78) `M = c₁ f₁ + c₂ f₂` (moment about C).
#[test]
fn two_point_segment_in_the_paper_plane_is_eqs_75_and_78() {
    use pegdyn::jamming::diagram::{to_paper_plane, two_point_segment};
    let p = peg();
    let hp = PegHole::try_new(p.r, 0.01, p.mu).unwrap();
    let (p2, p1) = two_point_segment(&hp, p.l, p.theta);
    let a = to_paper_plane(p1, p.r, p.theta, p.l_c);
    let b = to_paper_plane(p2, p.r, p.theta, p.l_c);
    let (sn, cs) = p.theta.sin_cos();
    let (k1, k2) = (cs - p.mu * sn, sn + p.mu * cs);
    assert!((a[0] + 1.0 / p.mu).abs() < 1e-12, "{a:?}");
    assert!((b[0] - k1 / k2).abs() < 1e-12, "{b:?}");
    let c1 = p
        .two_point(PegLoad { f1: 1.0, f2: 0.0 }, PegAcc::default())
        .m;
    let c2 = p
        .two_point(PegLoad { f1: 0.0, f2: 1.0 }, PegAcc::default())
        .m;
    for q in [a, b] {
        assert!((q[1] - (c2 * q[0] + c1) / p.r).abs() < 1e-12, "{q:?}");
    }
}

/// With μ = 2 the factor k3 = (1 − μ²) sin θ + 2μ cos θ of Eq. 52 vanishes
/// inside the physical range, at θ* = π − 2 atan μ ≈ 0.927 rad, where it
/// rounds to 0 exactly. Every checked entry point (Whitney frame, moment,
/// paper frame) returns the typed `SlidingIndeterminate` there, not ±∞ or
/// NaN; one ulp-scale step away the unchecked forms agree with them.
#[test]
fn k3_exactly_zero_is_refused_by_every_checked_form() {
    use pegdyn::jamming::SlidingIndeterminate;
    use pegdyn::jamming::forces::{k_factors, try_sliding_contact_forces, try_sliding_moment};
    let mu: f64 = 2.0;
    let theta = std::f64::consts::PI - 2.0 * mu.atan();
    assert_eq!(k_factors(mu, theta).2, 0.0, "k3 rounds to 0 at θ*");
    let hp = PegHole::try_new(0.0125, 0.002, mu).expect("valid peg");
    let refused = |e: SlidingIndeterminate| e.theta == theta && e.k3 == 0.0;
    assert!(try_sliding_contact_forces(&hp, theta, 0.2, 1.0).is_err_and(refused));
    assert!(try_sliding_moment(&hp, 0.01, theta, 0.2, 1.0).is_err_and(refused));
    let p = PaperPeg { theta, mu, ..peg() };
    let u = PegLoad { f1: 1.0, f2: 0.2 };
    assert!(p.try_two_point(u, PegAcc::default()).is_err_and(refused));
    // The unchecked forms divide by zero here.
    assert!(
        !sliding_contact_forces(&hp, theta, 0.2, 1.0)
            .edge
            .is_finite()
    );
    // Away from θ* (k3 ≈ −0.1) the checked forms return the closed forms.
    let th = theta + 0.02;
    let f = try_sliding_contact_forces(&hp, th, 0.2, 1.0).expect("determinate");
    assert_eq!(f, sliding_contact_forces(&hp, th, 0.2, 1.0));
    let m = try_sliding_moment(&hp, 0.01, th, 0.2, 1.0).expect("determinate");
    assert_eq!(m, sliding_moment(&hp, 0.01, th, 0.2, 1.0));
    let q = PaperPeg { theta: th, ..p };
    assert_eq!(
        q.try_two_point(u, PegAcc::default()),
        Ok(q.two_point(u, PegAcc::default()))
    );
}
