//! The Rosenbrock methods on a state of positions with a kinematic map
//! (`OdeSystem::kinematic_split`): a rigid body with a unit quaternion
//! (`ṗ = v`, `q̇ = ½ q ⊗ (0, ω)`) hung from a stiff spring–damper at a
//! point off its centre, with its dissipated energy as a trailing
//! integral, integrated with the velocity-block solve and with the full
//! factorization: the same solution to rounding.

use nalgebra::{SMatrix, SVector};
use pegdyn::integrate::{Method, Options, solve};
use pegdyn::scalar::{Dual, Real};
use pegdyn::system::{KinematicSplit, OdeSystem};

type V3<T> = [T; 3];

fn cross<T: Real>(a: &V3<T>, b: &V3<T>) -> V3<T> {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `R(q) v` for `q = (w, u)` (normalized here).
fn rotate<T: Real>(q: &[T; 4], v: &V3<T>, transpose: bool) -> V3<T> {
    let n = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]).sqrt();
    let (w, u) = (q[0] / n, [q[1] / n, q[2] / n, q[3] / n]);
    let u = if transpose { u.map(|x| -x) } else { u };
    let t = cross(&u, v).map(|x| x * T::from_f64(2.0));
    let c = cross(&u, &t);
    std::array::from_fn(|k| w * t[k] + c[k] + v[k])
}

/// The body: mass 1 kg, inertia (0.02, 0.03, 0.05) kg·m², a spring
/// `K = 10⁶ N/m` with damper `C = 20 N·s/m` from the body point
/// `b = (0.1, 0.05, 0.2)` m to the origin, gravity: contact-like
/// stiffness (ω ≈ 10³ rad/s) on a tumbling body.
struct Body {
    split: bool,
}

const INERTIA: [f64; 3] = [0.02, 0.03, 0.05];
const B: [f64; 3] = [0.1, 0.05, 0.2];

fn rate<T: Real>(y: &[T]) -> [T; 14] {
    let c = T::from_f64;
    let q = [y[3], y[4], y[5], y[6]];
    let v = [y[7], y[8], y[9]];
    let w = [y[10], y[11], y[12]];
    let b = B.map(c);
    let arm = rotate(&q, &b, false);
    let xb: V3<T> = std::array::from_fn(|k| y[k] + arm[k]);
    let wb = rotate(&q, &w, false);
    let vb: V3<T> = {
        let r = cross(&wb, &arm);
        std::array::from_fn(|k| v[k] + r[k])
    };
    let mut f: V3<T> = std::array::from_fn(|k| -(c(1e6) * xb[k]) - c(20.0) * vb[k]);
    f[2] = f[2] - c(9.81);
    let tau = cross(&b, &rotate(&q, &f, true));
    let iw: V3<T> = std::array::from_fn(|k| c(INERTIA[k]) * w[k]);
    let gyro = cross(&w, &iw);
    let half = c(0.5);
    [
        v[0],
        v[1],
        v[2],
        -half * (q[1] * w[0] + q[2] * w[1] + q[3] * w[2]),
        half * (q[0] * w[0] + q[2] * w[2] - q[3] * w[1]),
        half * (q[0] * w[1] + q[3] * w[0] - q[1] * w[2]),
        half * (q[0] * w[2] + q[1] * w[1] - q[2] * w[0]),
        f[0],
        f[1],
        f[2],
        (tau[0] - gyro[0]) / c(INERTIA[0]),
        (tau[1] - gyro[1]) / c(INERTIA[1]),
        (tau[2] - gyro[2]) / c(INERTIA[2]),
        c(20.0) * (vb[0] * vb[0] + vb[1] * vb[1] + vb[2] * vb[2]),
    ]
}

impl OdeSystem<14> for Body {
    fn rhs(&self, _t: f64, y: &SVector<f64, 14>) -> SVector<f64, 14> {
        SVector::from(rate(y.as_slice()))
    }

    /// Exact, in dual numbers of the 13 components the rates read.
    fn jacobian(&self, _t: f64, y: &SVector<f64, 14>) -> SMatrix<f64, 14, 14> {
        let yd: [Dual<13>; 14] = std::array::from_fn(|k| {
            if k < 13 {
                Dual::variable(y[k], k)
            } else {
                Dual::constant(y[k])
            }
        });
        let f = rate(&yd);
        SMatrix::from_fn(|r, c| if c < 13 { f[r].d[c] } else { 0.0 })
    }

    fn time_derivative(&self, _t: f64, _y: &SVector<f64, 14>) -> SVector<f64, 14> {
        SVector::zeros()
    }

    fn kinematic_split(&self) -> Option<KinematicSplit> {
        self.split.then_some(KinematicSplit {
            positions: 7,
            velocities: 6,
        })
    }
}

fn start() -> SVector<f64, 14> {
    let mut y = SVector::<f64, 14>::zeros();
    // Pose: the spring stretched by 1 mm, tumbling.
    let n = (1.0f64 + 0.04 + 0.09 + 0.01).sqrt();
    let q = [1.0 / n, 0.2 / n, -0.3 / n, 0.1 / n];
    let arm = rotate(&q, &B, false);
    for k in 0..3 {
        y[k] = -arm[k] + [1e-3, -5e-4, 2e-4][k];
        y[3 + k] = q[k];
        y[10 + k] = [3.0, -2.0, 8.0][k];
    }
    y[6] = q[3];
    y
}

#[test]
fn the_velocity_block_solve_gives_the_full_solve_s_solution() {
    for method in [Method::Rodas3, Method::Rodas4] {
        let opts = Options::with_tolerances(1e-7, 1e-10);
        let end = 0.05;
        let reduced = solve(&Body { split: true }, method, (0.0, start()), end, &opts).unwrap();
        let full = solve(&Body { split: false }, method, (0.0, start()), end, &opts).unwrap();
        assert!(reduced.stop.is_success() && full.stop.is_success());
        let (a, b) = (&reduced.x_final, &full.x_final);
        eprintln!(
            "{}: {} and {} steps, difference {:.2e}",
            method.name(),
            reduced.stats.steps,
            full.stats.steps,
            (a - b).amax()
        );
        // Same step sequence, solutions equal to rounding.
        assert_eq!(reduced.stats.steps, full.stats.steps);
        assert!((a - b).amax() < 1e-11 * b.amax(), "{a} vs {b}");
        // And it is the body's motion: a stiff oscillation about the
        // sag that the damper drains, energy going into the integral.
        assert!(b[13] > 0.0, "no dissipation: {b}");
    }
}

#[test]
fn the_exact_jacobian_of_the_test_body_matches_central_differences() {
    let y = start();
    let sys = Body { split: true };
    let j = sys.jacobian(0.0, &y);
    for c in 0..14 {
        let h = 1e-7;
        let (mut a, mut b) = (y, y);
        a[c] += h;
        b[c] -= h;
        let fd = (sys.rhs(0.0, &a) - sys.rhs(0.0, &b)) / (2.0 * h);
        let err = (fd - j.column(c)).amax();
        assert!(err <= 1e-6 * j.amax(), "column {c}: {err:.2e}");
    }
}
