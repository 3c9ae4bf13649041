//! Stiff integration of the compliant peg: a peg jammed against the wall
//! (sustained Hertz contacts with periods of a fraction of a millisecond and
//! a regularized friction law with microsecond time constants). The
//! Rosenbrock method with the generated exact Jacobian takes steps many
//! contact periods long where nothing happens and needs far fewer steps
//! than Dormand–Prince, which is held to the stability limit; both agree.
//! (Step and call counts only: timings are in `docs/compliant.md`.)

use pegdyn::compliant_peg::{CompliantParams, CompliantSpec, CompliantSystem, Load, PegState};
use pegdyn::integrate::{Method, Options, Solver};

#[test]
fn rosenbrock_steps_over_contact_periods_where_dopri5_cannot() {
    let p = CompliantParams::try_new(CompliantSpec::steel_cylinder(0.05, 0.002, 0.1, 0.1)).unwrap();
    let load = Load {
        axial: 2.0,
        radial: 50.0,
        torque: 0.0,
    };
    let sys = CompliantSystem::new(&p, &load);
    let mut start = PegState::centred(&p, 0.02);
    start.x = 0.025 - p.spec.geometry.peg_radius + 2e-7;
    let run = |method| {
        let mut o = Options::with_tolerances(1e-6, 1e-10);
        o.max_steps = 10_000_000;
        Solver::new(method, o)
            .solve(&sys, 0.0, start.to_vector(), 0.5)
            .unwrap()
    };
    let (explicit, implicit) = (run(Method::Dopri5), run(Method::Rodas3));
    assert!(explicit.stop.is_success() && implicit.stop.is_success());
    // The contact period at the final (stuck) state: 2π √(m / k_lin), k_lin = 1.5 k √δ.
    let s = sys.sample(&implicit.x_final);
    assert!(
        s.f_edge > 10.0 && s.f_wall > 10.0,
        "jammed in two-point contact: {s:?}"
    );
    let k_lin = 1.5 * p.pair.wall.stiffness() * s.delta_wall.sqrt();
    let period = 2.0 * std::f64::consts::PI * (p.spec.mass / k_lin).sqrt();
    let h_max = implicit
        .t
        .windows(2)
        .map(|w| w[1] - w[0])
        .fold(0.0, f64::max);
    assert!(
        h_max > 20.0 * period,
        "largest implicit step {h_max} vs contact period {period}"
    );
    assert!(implicit.stats.jacobian_calls > 0);
    assert!(
        5 * implicit.stats.steps < explicit.stats.steps,
        "implicit {} steps vs explicit {}",
        implicit.stats.steps,
        explicit.stats.steps
    );
    let diff = (implicit.x_final - explicit.x_final)
        .fixed_rows::<3>(0)
        .abs()
        .max();
    assert!(diff < 1e-6, "final positions differ by {diff}");
}
