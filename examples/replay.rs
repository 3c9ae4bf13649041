//! Writes the replay page of a shipped 3-D or planar scene:
//!
//! ```sh
//! cargo run --release --example replay -- scenes/insert_rcc.toml --out out
//! ```
//!
//! writes `out/insert_rcc.html` and prints its size. Kinds: `insert_rcc`,
//! `drop_3d`, `insert_compliant`, and one run of `rotation_assist` (its
//! last grid point: the largest errors and rates) and of `design_margins`
//! (the nominal insertion). It runs each model through the library the way
//! the scene kinds do, then hands the run to `pegdyn::replay`.

use nalgebra::{SVector, Vector3};
use pegdyn::compliant_peg::{CompliantSystem, ElasticSystem, FrictionLaw, Sample};
use pegdyn::compliant_peg_3d::insertion::{Insertion, N_STATE, lean_pose};
use pegdyn::compliant_peg_3d::outcome::{CountCache, TERMINAL_NAMES, transition_events};
use pegdyn::compliant_peg_3d::pose_state;
use pegdyn::integrate::{
    Direction, Event, EventHit, MethodKind, Options, OutputMode, Solution, Solver,
};
use pegdyn::replay::peg3d::{Meaning, Run3d};
use pegdyn::replay::planar::Run2d;
use pegdyn::replay::{Budget, MarkKind, Replay};
use pegdyn::scene::document::Document;
use pegdyn::scene::integrator::DefaultMethod;
use pegdyn::scene::kinds::drop_3d::DropScene;
use pegdyn::scene::kinds::insert_compliant::InsertCompliantScene;
use pegdyn::scene::kinds::rotation_assist::SweepScene;
use pegdyn::scene::shared::compliant_peg_3d::insertion::{RccScene, outcome_text, run_one};
use pegdyn::scene::validate::Checker;
use pegdyn::scene::{IntegratorSpec, Progress};
use pegdyn::system::OdeSystem;
use std::error::Error;
use std::path::PathBuf;

fn main() -> Result<(), Box<dyn Error>> {
    // Paths need not be UTF-8: arguments are taken as the OS gives them.
    let mut args = std::env::args_os().skip(1);
    let mut scene = None;
    let mut out = PathBuf::from("out");
    while let Some(a) = args.next() {
        if a == "--out" {
            out = PathBuf::from(args.next().ok_or("--out needs a directory")?);
        } else {
            scene = Some(PathBuf::from(a));
        }
    }
    let path = scene.ok_or("usage: replay SCENE.toml [--out DIR]")?;
    let name = path
        .file_stem()
        .ok_or("scene name")?
        .to_string_lossy()
        .into_owned();
    let text = std::fs::read_to_string(&path)?;
    let doc = Document::parse(&text).map_err(|e| e.to_string())?;
    let replay = match doc.kind() {
        "insert_rcc" => rcc(&name, &doc.body::<RccScene>().map_err(|e| e.to_string())?)?,
        "rotation_assist" => {
            let s: SweepScene = doc.body().map_err(|e| e.to_string())?;
            let g = &s.grid;
            let mut robot = s.robot.clone();
            robot.lateral_error = *g.lateral_errors.last().ok_or("grid")?;
            robot.angular_error_deg = *g.angular_errors_deg.last().ok_or("grid")?;
            robot.precession_rate = *g.precession_rates.last().ok_or("grid")?;
            robot.spin_rate = *g.spin_rates.last().ok_or("grid")?;
            let one = RccScene {
                peg: s.peg,
                wrist: s.wrist,
                robot,
                criteria: s.criteria,
                integrator: s.integrator,
            };
            rcc(&name, &one)?
        }
        "design_margins" => {
            let s: pegdyn::scene::kinds::design_margins::DesignScene =
                doc.body().map_err(|e| e.to_string())?;
            rcc(&name, &s.nominal())?
        }
        "drop_3d" => drop(&name, &doc.body::<DropScene>().map_err(|e| e.to_string())?)?,
        "insert_compliant" => planar(
            &name,
            &doc.body::<InsertCompliantScene>()
                .map_err(|e| e.to_string())?,
        )?,
        other => return Err(format!("no replay for kind {other}").into()),
    };
    let html = pegdyn::replay::html(&replay)?;
    std::fs::create_dir_all(&out)?;
    let file = out.join(format!("{name}.html"));
    std::fs::write(&file, &html)?;
    println!(
        "{}: {} bytes ({} frames of {} states, {} events)",
        file.display(),
        html.len(),
        replay.frames.len(),
        replay.states,
        replay.marks.len()
    );
    Ok(())
}

/// The scene's integration as the scene kinds run it (method, tolerances,
/// output times of the `[integrator]` table).
fn integrate<const N: usize>(
    sys: &impl OdeSystem<N>,
    y0: SVector<f64, N>,
    spec: &IntegratorSpec,
    events: Vec<Event<'_, N>>,
) -> Result<Solution<N>, Box<dyn Error>> {
    let kind = spec.method.kind().unwrap_or(MethodKind::Dopri5);
    let method = kind.with_step(spec.h).ok_or("rk4 needs h")?;
    let mut options = Options::with_tolerances(spec.rtol, spec.atol);
    options.max_steps = spec.max_steps;
    options.output = OutputMode::AtTimes(spec.output_times().collect());
    if spec.method.is_adaptive() {
        options.h0 = spec.h;
    }
    let mut solver = events
        .into_iter()
        .fold(Solver::new(method, options), Solver::with_event);
    Ok(solver.solve(sys, spec.t0, y0, spec.t_end)?)
}

fn resolved(spec: &IntegratorSpec) -> IntegratorSpec {
    spec.resolved(DefaultMethod::NON_STIFF).0
}

fn rcc(name: &str, s: &RccScene) -> Result<Replay, Box<dyn Error>> {
    let built = s.build().map_err(|e| e.to_string())?;
    let run = run_one(
        &built,
        &resolved(&s.integrator),
        true,
        &mut Progress::silent(),
    )?;
    let n = run.transitions.len();
    let transitions = run.transitions.clone();
    // Transition events come first; the terminal ones were shifted below 0.
    let meaning = move |e: &EventHit<N_STATE>| {
        if e.index < n {
            return Some(Meaning::Transition(transitions[e.index]));
        }
        match e.index.wrapping_add(TERMINAL_NAMES.len()) {
            0 => Some(Meaning::Seated),
            1 => Some(Meaning::WristForceLimit),
            2 => Some(Meaning::ContactForceLimit),
            3 => Some(Meaning::Missed),
            _ => None,
        }
    };
    let r = Run3d {
        title: name,
        subtitle: format!(
            "compliant 3-D peg held by a compliant wrist; outcome: {}",
            outcome_text(&run.outcome)
        ),
        system: &run.system,
        solution: &run.solution,
        meaning: &meaning,
    };
    Ok(pegdyn::replay::peg3d::replay(&r, Budget::default())?)
}

fn drop(name: &str, s: &DropScene) -> Result<Replay, Box<dyn Error>> {
    let mut c = Checker::default();
    let params = s.peg.build(&mut c);
    c.finish().map_err(|e| e.to_string())?;
    let (p, q) = lean_pose(&params, s.drop.gamma, s.drop.azimuth_deg.to_radians())?;
    let omega = q.inverse() * Vector3::new(0.0, 0.0, s.drop.spin_rate);
    let mut start = SVector::<f64, N_STATE>::zeros();
    start
        .fixed_rows_mut::<15>(0)
        .copy_from(&pose_state(p, q, Vector3::zeros(), omega));
    let sys = Insertion::new(params, None, s.drop.aligning_moment);
    let counter = Insertion::new(params, None, 0.0);
    let cache = CountCache::new(&counter);
    let (events, what) = transition_events(&cache);
    let sol = integrate(&sys, start, &resolved(&s.integrator), events)?;
    let meaning = |e: &EventHit<N_STATE>| what.get(e.index).map(|w| Meaning::Transition(*w));
    let r = Run3d {
        title: name,
        subtitle: "compliant 3-D peg released leaning on the mouth, spinning, under an aligning \
                   moment"
            .into(),
        system: &sys,
        solution: &sol,
        meaning: &meaning,
    };
    Ok(pegdyn::replay::peg3d::replay(&r, Budget::default())?)
}

fn planar(name: &str, s: &InsertCompliantScene) -> Result<Replay, Box<dyn Error>> {
    let b = s.build().map_err(|e| e.to_string())?;
    fn inserted<'a, const N: usize>(lc: f64, target: f64) -> Event<'a, N> {
        Event::new(move |_t, y: &SVector<f64, N>| y[1] + lc * y[2].cos() - target)
            .direction(Direction::Rising)
            .terminal()
    }
    fn go<const N: usize>(
        name: &str,
        s: &InsertCompliantScene,
        b: &pegdyn::scene::kinds::insert_compliant::Built,
        sys: &impl OdeSystem<N>,
        y0: SVector<f64, N>,
        sample: &dyn Fn(&SVector<f64, N>) -> Sample,
    ) -> Result<Replay, Box<dyn Error>> {
        let p = &s.insert_compliant;
        let spec = s.integrator.resolved(DefaultMethod::STIFF_CONTACT).0;
        let event = inserted(b.params.spec.com_height, p.target_depth);
        let sol = integrate(sys, y0, &spec, vec![event])?;
        let mark = |_: &EventHit<N>| Some((MarkKind::Seat, "target depth reached".to_string()));
        let r = Run2d {
            title: name,
            subtitle: format!(
                "compliant planar peg pushed in from a two-point start: f1 = {} N, M = {} N m, \
                 mu = {}",
                p.axial_force, p.torque, p.friction
            ),
            params: &b.params,
            peg_length: p.peg_length,
            wall_depth: p.target_depth + 0.3 * p.peg_length,
            solution: &sol,
            sample,
            mark: &mark,
        };
        Ok(pegdyn::replay::planar::replay(&r, Budget::default())?)
    }
    match b.params.spec.friction_law {
        FrictionLaw::Regularized => {
            let sys = CompliantSystem::new(&b.params, &b.load);
            let y0 = b.initial.to_vector();
            go(name, s, &b, &sys, y0, &|y| sys.sample(y))
        }
        FrictionLaw::Elastic => {
            let sys = ElasticSystem::new(&b.params, &b.load);
            let y0 = b.initial.to_vector_elastic();
            go(name, s, &b, &sys, y0, &|y| sys.sample(y))
        }
    }
}
