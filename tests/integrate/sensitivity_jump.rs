//! Forward sensitivities through a switch of the right-hand side at a
//! state-dependent event, against the closed form: `ẏ = a` until `y = 1`,
//! then `ẏ = −b y`. With `t_e = (1 − y₀)/a`, `y(T) = e^{−b (T − t_e)}`, so
//! `∂y/∂a = −b y (1 − y₀)/a²` and `∂y/∂b = −(T − t_e) y`; the jump
//! `Δs = (f⁻ − f⁺) ∂t_e/∂p` is what makes `∂y/∂a` right.

use nalgebra::{SMatrix, SVector, Vector1, Vector2};
use pegdyn::integrate::{Direction, Method, Options, StopReason};
use pegdyn::sensitivity::{ParameterJacobian, SensitivityEvent, event_jump, integrate};
use pegdyn::system::OdeSystem;

#[derive(Clone, Copy)]
struct Phase {
    a: f64,
    b: f64,
    second: bool,
}

impl OdeSystem<1> for Phase {
    fn rhs(&self, _t: f64, y: &SVector<f64, 1>) -> SVector<f64, 1> {
        Vector1::new(if self.second { -self.b * y[0] } else { self.a })
    }
    fn jacobian(&self, _t: f64, _y: &SVector<f64, 1>) -> SMatrix<f64, 1, 1> {
        SMatrix::from_element(if self.second { -self.b } else { 0.0 })
    }
}

impl ParameterJacobian<1, 2> for Phase {
    fn parameters(&self) -> SVector<f64, 2> {
        Vector2::new(self.a, self.b)
    }
    fn parameter_jacobian(&self, _t: f64, y: &SVector<f64, 1>) -> SMatrix<f64, 1, 2> {
        if self.second {
            SMatrix::from_row_slice(&[0.0, -y[0]])
        } else {
            SMatrix::from_row_slice(&[1.0, 0.0])
        }
    }
}

#[test]
fn the_event_jump_gives_the_closed_form_sensitivities() {
    let (a, b, y0, t_end) = (2.0, 3.0, 0.2, 1.0);
    let first = Phase {
        a,
        b,
        second: false,
    };
    let second = Phase {
        second: true,
        ..first
    };
    let tight = Options::with_tolerances(1e-11, 1e-13);
    let hit = SensitivityEvent::new(
        |_, y: &SVector<f64, 1>| y[0] - 1.0,
        |_, _| (Vector1::new(1.0), Vector2::zeros()),
    )
    .direction(Direction::Rising)
    .terminal();
    let one = integrate::<_, 1, 2, 3>(
        &first,
        (0.0, Vector1::new(y0), SMatrix::zeros()),
        t_end,
        Method::Dopri5,
        &tight,
        vec![hit],
    )
    .unwrap();
    let StopReason::Event { index: 0, t: te } = one.stop else {
        panic!("{:?}", one.stop)
    };
    let e = &one.events[0];
    let t_e = (1.0 - y0) / a;
    assert!((te - t_e).abs() < 1e-12);
    assert!((e.dt_dp[0] + t_e / a).abs() < 1e-10 && e.dt_dp[1] == 0.0);
    let s_plus = event_jump(&e.s, &e.f, &second.rhs(te, &e.y), &e.dt_dp);
    let two = integrate::<_, 1, 2, 3>(
        &second,
        (te, e.y, s_plus),
        t_end,
        Method::Dopri5,
        &tight,
        Vec::new(),
    )
    .unwrap();
    let y = (-b * (t_end - t_e)).exp();
    let want = [-b * y * (1.0 - y0) / (a * a), -(t_end - t_e) * y];
    for (k, w) in want.iter().enumerate() {
        assert!(
            (two.s[(0, k)] - w).abs() < 1e-8 * w.abs(),
            "∂y/∂p{k}: {} vs {w}",
            two.s[(0, k)]
        );
    }
    // Without the jump ∂y/∂a would be off by (f⁻ − f⁺) ∂t_e/∂a · e^{−b (T − t_e)}.
    let without = e.s[(0, 0)] * y;
    assert!((without - want[0]).abs() > 0.1 * want[0].abs());
}

#[test]
fn a_wrong_augmented_dimension_is_refused() {
    let p = Phase {
        a: 1.0,
        b: 1.0,
        second: false,
    };
    let r = integrate::<_, 1, 2, 4>(
        &p,
        (0.0, Vector1::new(0.0), SMatrix::zeros()),
        1.0,
        Method::Dopri5,
        &Options::default(),
        Vec::new(),
    );
    assert!(matches!(
        r,
        Err(pegdyn::sensitivity::SensitivityError::Dimension { m: 4, expected: 3 })
    ));
}
