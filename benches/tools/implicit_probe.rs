//! Where the steps of an `insert_rcc` run go, and what limits them.
//!
//! `implicit_probe SCENE METHOD RTOL [ATOL]` (METHOD `dopri5`, `rodas3`,
//! `rodas4`) runs the scene with its terminal events only and prints the
//! work counters, the CPU time and, per window of `WIN` seconds (0.05 by
//! default), the number of steps and their smallest, median and largest
//! size.
//!
//! `implicit_probe limit SCENE TA TB` starts from the state at `TA`
//! (RODAS4, rtol 1e-9), prints the eigenvalues of the Jacobian there, and counts the steps to `TB` of RODAS4 and DOPRI5
//! at rtol 1e-4 to 1e-8; of RODAS4 with its Jacobian and/or time
//! derivative replaced by central differences; and of RODAS4 at rtol 1e-6
//! with the tolerance of each state component in turn relaxed by 10^3.
use std::time::Instant;

use nalgebra::SVector;
use pegdyn::compliant_peg_3d::insertion::{Insertion, N_STATE};
use pegdyn::compliant_peg_3d::outcome::terminal_events;
use pegdyn::integrate::{Method, Options, Solver};
use pegdyn::scene::document::Document;
use pegdyn::scene::shared::compliant_peg_3d::insertion::RccScene;
use pegdyn::system::OdeSystem;

/// The system in scaled variables `z = s ∘ y` (per-component tolerances).
struct Scaled<'a> {
    inner: &'a Insertion,
    s: SVector<f64, N_STATE>,
}

impl OdeSystem<N_STATE> for Scaled<'_> {
    fn rhs(&self, t: f64, z: &SVector<f64, N_STATE>) -> SVector<f64, N_STATE> {
        self.inner
            .rhs(t, &z.component_div(&self.s))
            .component_mul(&self.s)
    }
    fn jacobian(
        &self,
        t: f64,
        z: &SVector<f64, N_STATE>,
    ) -> nalgebra::SMatrix<f64, N_STATE, N_STATE> {
        let j = self.inner.jacobian(t, &z.component_div(&self.s));
        nalgebra::SMatrix::from_fn(|r, c| j[(r, c)] * self.s[r] / self.s[c])
    }
    fn time_derivative(&self, t: f64, z: &SVector<f64, N_STATE>) -> SVector<f64, N_STATE> {
        self.inner
            .time_derivative(t, &z.component_div(&self.s))
            .component_mul(&self.s)
    }
}

/// The insertion with its Jacobian and/or time derivative replaced by
/// central differences of the right-hand side.
struct Fd<'a> {
    inner: &'a Insertion,
    jac: bool,
    dt: bool,
}

impl OdeSystem<N_STATE> for Fd<'_> {
    fn rhs(&self, t: f64, y: &SVector<f64, N_STATE>) -> SVector<f64, N_STATE> {
        self.inner.rhs(t, y)
    }
    fn jacobian(
        &self,
        t: f64,
        y: &SVector<f64, N_STATE>,
    ) -> nalgebra::SMatrix<f64, N_STATE, N_STATE> {
        if !self.jac {
            let _ = self.inner.rhs(t, y);
            return self.inner.jacobian(t, y);
        }
        let mut j = nalgebra::SMatrix::<f64, N_STATE, N_STATE>::zeros();
        for c in 0..N_STATE {
            let h = if c < 7 { 1e-10 } else { 1e-8 };
            let (mut a, mut b) = (*y, *y);
            a[c] += h;
            b[c] -= h;
            j.set_column(
                c,
                &((self.inner.rhs(t, &a) - self.inner.rhs(t, &b)) / (2.0 * h)),
            );
        }
        j
    }
    fn time_derivative(&self, t: f64, y: &SVector<f64, N_STATE>) -> SVector<f64, N_STATE> {
        if !self.dt {
            let _ = self.inner.rhs(t, y);
            let _ = self.inner.jacobian(t, y);
            return self.inner.time_derivative(t, y);
        }
        let h = 1e-7;
        (self.inner.rhs(t + h, y) - self.inner.rhs(t - h, y)) / (2.0 * h)
    }
    fn kinematic_split(&self) -> Option<pegdyn::system::KinematicSplit> {
        self.inner.kinematic_split()
    }
}

/// The `limit` mode of the module documentation.
fn limit() {
    let args: Vec<String> = std::env::args().collect();
    let text = std::fs::read_to_string(&args[2]).unwrap();
    let (ta, tb): (f64, f64) = (args[3].parse().unwrap(), args[4].parse().unwrap());
    let scene: RccScene = Document::parse(&text).and_then(|d| d.body()).unwrap();
    let b = scene.build().unwrap();
    let sys = Insertion::new(b.params, Some(b.held), 0.0);
    let y0 = sys.held_start().unwrap();
    let mut o = Options::with_tolerances(1e-9, 1e-13);
    o.max_steps = 2_000_000;
    let sol = Solver::new(Method::Rodas4, o)
        .solve(&sys, 0.0, y0, ta)
        .unwrap();
    let ya = sol.x_final;
    let _ = sys.rhs(ta, &ya);
    let mut eig: Vec<_> = sys
        .jacobian(ta, &ya)
        .complex_eigenvalues()
        .iter()
        .copied()
        .collect();
    eig.sort_by(|a, b| b.norm().total_cmp(&a.norm()));
    for e in eig.iter().filter(|e| e.norm() > 1.0) {
        println!(
            "eigenvalue {:.4e} {:+.4e}i (|λ| {:.3e} 1/s, damping ratio {:.2e})",
            e.re,
            e.im,
            e.norm(),
            -e.re / e.norm()
        );
    }
    for rtol in [1e-4, 1e-5, 1e-6, 1e-7, 1e-8] {
        for m in [Method::Rodas4, Method::Dopri5] {
            let mut o = Options::with_tolerances(rtol, rtol * 1e-4);
            o.max_steps = 2_000_000;
            let s = Solver::new(m, o).solve(&sys, ta, ya, tb).unwrap();
            println!("{m:?} rtol {rtol:e}: {:?}", s.stats);
        }
    }
    for (jac, dt) in [(false, false), (true, false), (false, true), (true, true)] {
        for rtol in [1e-4, 1e-5, 1e-6, 1e-7, 1e-8] {
            let mut o = Options::with_tolerances(rtol, rtol * 1e-4);
            o.max_steps = 2_000_000;
            let fd = Fd {
                inner: &sys,
                jac,
                dt,
            };
            let s = Solver::new(Method::Rodas4, o)
                .solve(&fd, ta, ya, tb)
                .unwrap();
            println!(
                "central-difference jac {jac} dfdt {dt}, rtol {rtol:e}: {} steps {} rejected",
                s.stats.steps, s.stats.rejected
            );
        }
    }
    for k in 0..=N_STATE {
        let mut sv = SVector::<f64, N_STATE>::repeat(1.0);
        if k < N_STATE {
            sv[k] = 1e-3;
        }
        let scaled = Scaled { inner: &sys, s: sv };
        let mut o = Options::with_tolerances(1e-6, 1e-10);
        o.max_steps = 2_000_000;
        let s = Solver::new(Method::Rodas4, o)
            .solve(&scaled, ta, ya.component_mul(&sv), tb)
            .unwrap();
        println!(
            "relax component {k}: {} steps {} rejected",
            s.stats.steps, s.stats.rejected
        );
    }
}

fn main() {
    if std::env::args().nth(1).as_deref() == Some("limit") {
        return limit();
    }
    let args: Vec<String> = std::env::args().collect();
    let method = match args[2].as_str() {
        "dopri5" => Method::Dopri5,
        "rodas3" => Method::Rodas3,
        _ => Method::Rodas4,
    };
    let rtol: f64 = args[3].parse().unwrap();
    let atol: f64 = args.get(4).map_or(1e-10, |s| s.parse().unwrap());
    let text = std::fs::read_to_string(&args[1]).unwrap();
    let scene: RccScene = Document::parse(&text).and_then(|d| d.body()).unwrap();
    let b = scene.build().unwrap();
    let sys = Insertion::new(b.params, Some(b.held), 0.0);
    let y0 = match b.start_depth {
        Some(d) => sys.centred_start(d),
        None => sys.held_start(),
    }
    .unwrap();
    let mut opts = Options::with_tolerances(rtol, atol);
    opts.max_steps = 2_000_000;
    let mut solver = terminal_events(&sys, b.criteria)
        .into_iter()
        .fold(Solver::new(method, opts), Solver::with_event);
    let t0 = Instant::now();
    let sol = solver.solve(&sys, 0.0, y0, scene.integrator.t_end).unwrap();
    let wall = t0.elapsed().as_secs_f64();
    println!("{:?} stop {:?}", sol.stats, sol.stop);
    println!(
        "wall {wall:.3} s, per simulated s {:.3}",
        wall / sol.t_final
    );
    let w = std::env::var("WIN").map_or(0.05, |s| s.parse().unwrap());
    let mut k = 0;
    let mut win = 0.0;
    while win < sol.t_final {
        let mut hs = Vec::new();
        while k + 1 < sol.t.len() && sol.t[k + 1] <= win + w {
            hs.push(sol.t[k + 1] - sol.t[k]);
            k += 1;
        }
        hs.sort_by(f64::total_cmp);
        if !hs.is_empty() {
            let n = sys.contacts(&sol.x[k]).len();
            println!(
                "[{win:.4},{:.4}) steps {:6} h min {:.2e} med {:.2e} max {:.2e} contacts@end {n}",
                win + w,
                hs.len(),
                hs[0],
                hs[hs.len() / 2],
                hs[hs.len() - 1]
            );
        }
        win += w;
    }
}
