//! Several sweep points per call: the generated compliant-peg functions
//! instantiated at a four-lane scalar (`Lanes`, element-wise arithmetic on
//! `[f64; 4]`, which the compiler may vectorize; the elementary functions
//! stay one `f64` call per lane) against four calls at `f64`, on one
//! thread. Prints the time per sweep point of `rhs` and `jacobian` of the
//! regularized (`compliant_peg`) and elastic (`compliant_peg_elastic`)
//! models at the jamming sweep's two-point start under four loads.
//!
//! Run: `cargo run --release -p pegdyn-benches --bin simd_lanes`.

use std::hint::black_box;
use std::ops::{Add, Div, Mul, Neg, Sub};
use std::time::Instant;

use nalgebra::SVector;
use pegdyn::compliant_peg::{CompliantParams, CompliantSpec, FrictionLaw, Load, PegState};
use pegdyn::generated::{compliant_peg, compliant_peg_elastic};
use pegdyn::scalar::Real;

/// Four lanes, element-wise.
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
struct Lanes([f64; 4]);

impl Lanes {
    #[inline(always)]
    fn map(self, f: impl Fn(f64) -> f64) -> Lanes {
        Lanes([f(self.0[0]), f(self.0[1]), f(self.0[2]), f(self.0[3])])
    }
    #[inline(always)]
    fn zip(self, o: Lanes, f: impl Fn(f64, f64) -> f64) -> Lanes {
        Lanes([
            f(self.0[0], o.0[0]),
            f(self.0[1], o.0[1]),
            f(self.0[2], o.0[2]),
            f(self.0[3], o.0[3]),
        ])
    }
}

macro_rules! binop {
    ($tr:ident, $m:ident, $op:tt) => {
        impl $tr for Lanes {
            type Output = Lanes;
            #[inline(always)]
            fn $m(self, o: Lanes) -> Lanes {
                self.zip(o, |a, b| a $op b)
            }
        }
    };
}
binop!(Add, add, +);
binop!(Sub, sub, -);
binop!(Mul, mul, *);
binop!(Div, div, /);

impl Neg for Lanes {
    type Output = Lanes;
    #[inline(always)]
    fn neg(self) -> Lanes {
        self.map(|a| -a)
    }
}

macro_rules! unary {
    ($($m:ident),*) => { $( #[inline(always)] fn $m(self) -> Lanes { self.map(|a| Real::$m(a)) } )* };
}

impl Real for Lanes {
    fn from_f64(v: f64) -> Lanes {
        Lanes([v; 4])
    }
    fn to_f64(self) -> f64 {
        self.0[0]
    }
    unary!(
        sin, cos, tan, asin, acos, atan, exp, exp_m1, ln, ln_1p, sqrt, cbrt, abs, tanh, sign, max0,
        step
    );
    fn atan2(self, x: Lanes) -> Lanes {
        self.zip(x, f64::atan2)
    }
    fn sin_cos(self) -> (Lanes, Lanes) {
        (Real::sin(self), Real::cos(self))
    }
    fn powi(self, n: i32) -> Lanes {
        self.map(|a| a.powi(n))
    }
    fn powf(self, e: Lanes) -> Lanes {
        self.zip(e, f64::powf)
    }
    fn hypot(self, y: Lanes) -> Lanes {
        self.zip(y, f64::hypot)
    }
    fn is_nan(self) -> bool {
        self.0.iter().any(|a| a.is_nan())
    }
}

fn lanes<const N: usize>(v: &[SVector<f64, N>; 4]) -> SVector<Lanes, N> {
    SVector::from_fn(|i, _| Lanes([v[0][i], v[1][i], v[2][i], v[3][i]]))
}

/// Seconds per sweep point of `f` over `reps` repetitions of 4 points.
fn time(reps: usize, mut f: impl FnMut()) -> f64 {
    let start = Instant::now();
    for _ in 0..reps {
        f();
    }
    start.elapsed().as_secs_f64() / (4 * reps) as f64
}

fn main() {
    let loads: [Load; 4] = std::array::from_fn(|k| Load {
        axial: 20.0,
        radial: 2.0 * k as f64,
        torque: -0.1 * k as f64,
    });
    let reps = 200_000;
    println!("model,function,f64_ns_per_point,lanes4_ns_per_point,ratio,max_abs_difference");
    for law in [FrictionLaw::Regularized, FrictionLaw::Elastic] {
        let mut spec = CompliantSpec::steel_cylinder(0.025 / 0.99, 0.01, 0.1, 0.3);
        spec.friction_law = law;
        let params = CompliantParams::try_new(spec).expect("valid spec");
        let start = PegState::two_point(&params, 0.026, 1e-7).expect("two-point start");
        match law {
            FrictionLaw::Regularized => {
                let p: [SVector<f64, 24>; 4] = std::array::from_fn(|k| params.vector(&loads[k]));
                let y: [SVector<f64, 8>; 4] = std::array::from_fn(|_| start.to_vector());
                let (pl, yl) = (lanes(&p), lanes(&y));
                let diff = (0..4)
                    .map(|k| {
                        let a = compliant_peg::rhs(&y[k], &p[k]);
                        let b = compliant_peg::rhs(&yl, &pl);
                        (0..8).map(|i| (a[i] - b[i].0[k]).abs()).fold(0.0, f64::max)
                    })
                    .fold(0.0, f64::max);
                let t1 = time(reps, || {
                    for k in 0..4 {
                        black_box(compliant_peg::rhs(black_box(&y[k]), &p[k]));
                    }
                });
                let t4 = time(reps, || {
                    black_box(compliant_peg::rhs(black_box(&yl), &pl));
                });
                println!(
                    "compliant_peg,rhs,{:.1},{:.1},{:.2},{diff:e}",
                    t1 * 1e9,
                    t4 * 1e9,
                    t4 / t1
                );
                let t1 = time(reps / 4, || {
                    for k in 0..4 {
                        black_box(compliant_peg::jacobian(black_box(&y[k]), &p[k]));
                    }
                });
                let t4 = time(reps / 4, || {
                    black_box(compliant_peg::jacobian(black_box(&yl), &pl));
                });
                println!(
                    "compliant_peg,jacobian,{:.1},{:.1},{:.2},",
                    t1 * 1e9,
                    t4 * 1e9,
                    t4 / t1
                );
            }
            FrictionLaw::Elastic => {
                let p: [SVector<f64, 27>; 4] =
                    std::array::from_fn(|k| params.vector_elastic(&loads[k]));
                let y: [SVector<f64, 12>; 4] = std::array::from_fn(|_| start.to_vector_elastic());
                let (pl, yl) = (lanes(&p), lanes(&y));
                let diff = (0..4)
                    .map(|k| {
                        let a = compliant_peg_elastic::rhs(&y[k], &p[k]);
                        let b = compliant_peg_elastic::rhs(&yl, &pl);
                        (0..12)
                            .map(|i| (a[i] - b[i].0[k]).abs())
                            .fold(0.0, f64::max)
                    })
                    .fold(0.0, f64::max);
                let t1 = time(reps, || {
                    for k in 0..4 {
                        black_box(compliant_peg_elastic::rhs(black_box(&y[k]), &p[k]));
                    }
                });
                let t4 = time(reps, || {
                    black_box(compliant_peg_elastic::rhs(black_box(&yl), &pl));
                });
                println!(
                    "compliant_peg_elastic,rhs,{:.1},{:.1},{:.2},{diff:e}",
                    t1 * 1e9,
                    t4 * 1e9,
                    t4 / t1
                );
                let t1 = time(reps / 4, || {
                    for k in 0..4 {
                        black_box(compliant_peg_elastic::jacobian(black_box(&y[k]), &p[k]));
                    }
                });
                let t4 = time(reps / 4, || {
                    black_box(compliant_peg_elastic::jacobian(black_box(&yl), &pl));
                });
                println!(
                    "compliant_peg_elastic,jacobian,{:.1},{:.1},{:.2},",
                    t1 * 1e9,
                    t4 * 1e9,
                    t4 / t1
                );
            }
        }
    }
}
