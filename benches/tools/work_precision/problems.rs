//! The dynamic systems of the study, each with its start, end time, the
//! state components whose error is reported, and the method settings.

use nalgebra::SVector;
use pegdyn::compliant_peg::{CompliantSystem, ElasticSystem, FrictionLaw, Load};
use pegdyn::integrate::Method;
use pegdyn::jamming::dynamic::{SweepSetup, SweepSpec};
use pegdyn::jamming::forces::{Wrench, to_paper_frame};
use pegdyn::rigid_peg::forward::{ForwardModel, PegSystem};
use pegdyn::rigid_peg::{Loads, PegParams};
use pegdyn::scene::document::Document;
use pegdyn::scene::kinds::align_forward::AlignForwardScene;
use pegdyn::system::OdeSystem;
use pegdyn::textbook::double_pendulum::{DoublePendulumParams, DoublePendulumSystem};
use pegdyn::textbook::pendulum::{PendulumParams, PendulumSystem};

/// One problem: a system from `y0` at t = 0 to `t_end`.
pub struct Problem<const N: usize, S> {
    /// Name used in file names and tables.
    pub name: &'static str,
    /// What it is and why `t_end` is what it is.
    pub about: &'static str,
    /// The system.
    pub system: S,
    /// Initial state.
    pub y0: SVector<f64, N>,
    /// End time (s).
    pub t_end: f64,
    /// State components whose error is reported (the coordinates), and
    /// their unit.
    pub coords: (&'static [usize], &'static str),
    /// `atol = atol_scale · rtol` (the state's scale).
    pub atol_scale: f64,
    /// RK4 steps (s).
    pub rk4_steps: &'static [f64],
    /// DOPRI5 relative tolerances.
    pub dopri5_rtols: &'static [f64],
    /// Tolerances of the RODAS3 and RODAS4 runs.
    pub rodas3_rtols: &'static [f64],
    /// Reference: `reference_method` at this rtol; its error is estimated
    /// against a run at 10× this rtol.
    pub reference_rtol: f64,
    /// The reference's method (DOPRI5, or RODAS4 where DOPRI5 cannot
    /// finish: a stuck peg under the regularized friction law).
    pub reference_method: Method,
}

const DOPRI5_RTOLS: &[f64] = &[
    1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12,
];
const RODAS3_RTOLS: &[f64] = &[1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8];

/// `scenes/pendulum.toml`: released from rest at 60°, five periods.
pub fn pendulum() -> Problem<2, PendulumSystem> {
    let p = PendulumParams {
        length: 1.0,
        mass: 1.0,
        gravity: 9.80665,
        theta0_deg: 60.0,
        omega0: 0.0,
    };
    Problem {
        name: "pendulum",
        about: "simple pendulum from rest at 60 deg (scenes/pendulum.toml), 10 s (about 4.7 periods)",
        system: PendulumSystem::new(&p),
        y0: SVector::<f64, 2>::new(60f64.to_radians(), 0.0),
        t_end: 10.0,
        coords: (&[0], "rad"),
        atol_scale: 1.0,
        rk4_steps: &[0.1, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001],
        dopri5_rtols: DOPRI5_RTOLS,
        rodas3_rtols: RODAS3_RTOLS,
        reference_rtol: 1e-14,
        reference_method: Method::Dopri5,
    }
}

/// `scenes/double_pendulum.toml` (from rest at (120°, −10°)), cut at the
/// horizon where a reference is still meaningful (see `t_end`).
pub fn double_pendulum(t_end: f64) -> Problem<4, DoublePendulumSystem> {
    let p = DoublePendulumParams {
        mass1: 1.0,
        mass2: 1.0,
        length1: 1.0,
        length2: 1.0,
        gravity: 9.80665,
        theta1_deg: 120.0,
        theta2_deg: -10.0,
        omega1: 0.0,
        omega2: 0.0,
    };
    Problem {
        name: "double_pendulum",
        about: "double pendulum from rest at (120, -10) deg (scenes/double_pendulum.toml), cut at 5 s: it is \
                chaotic, and the reference's own error estimate grows from 1e-13 rad at 5 s to 1e-9 at 12 s \
                and 1.5e-6 at the scene's 20 s, where DOPRI5 at rtol 1e-6 is off by over 1 rad",
        system: DoublePendulumSystem::new(&p),
        y0: SVector::<f64, 4>::new(120f64.to_radians(), (-10f64).to_radians(), 0.0, 0.0),
        t_end,
        coords: (&[0, 1], "rad"),
        atol_scale: 1.0,
        rk4_steps: &[0.02, 0.01, 0.005, 0.002, 0.001, 0.0005],
        dopri5_rtols: DOPRI5_RTOLS,
        rodas3_rtols: RODAS3_RTOLS,
        reference_rtol: 1e-14,
        reference_method: Method::Dopri5,
    }
}

/// The model, loads and start of `scenes/insert_compliant.toml`, read from
/// the shipped file so that the diagrams follow it.
fn shipped_insertion() -> pegdyn::scene::kinds::insert_compliant::Built {
    let text = include_str!("../../../scenes/insert_compliant.toml");
    let scene: pegdyn::scene::kinds::insert_compliant::InsertCompliantScene =
        pegdyn::scene::document::Document::parse(text)
            .and_then(|d| d.body())
            .expect("shipped scene parses");
    scene.build().expect("shipped scene is valid")
}

/// `scenes/insert_compliant.toml` (steel peg, D = 50 mm, c = 0.002,
/// μ = 0.1, tilted 0.01 rad in two-point contact, f₁ = 5 N,
/// M = −0.002 N·m), to 0.1 s (the peg reaches the 30 mm target at 0.11 s).
pub fn insertion() -> Problem<8, CompliantSystem> {
    let built = shipped_insertion();
    let (params, load, start) = (built.params, built.load, built.initial);
    Problem {
        name: "insert_compliant",
        about: "compliant insertion (scenes/insert_compliant.toml) over 0.1 s: two-point contact, sliding, \
                righting; stiff Hertz contacts (contact periods of microseconds)",
        system: CompliantSystem::new(&params, &load),
        y0: start.to_vector(),
        t_end: 0.1,
        coords: (&[0, 1, 2], "m or rad"),
        atol_scale: 1e-4,
        rk4_steps: &[4e-6, 2e-6, 1e-6, 5e-7],
        dopri5_rtols: DOPRI5_RTOLS,
        rodas3_rtols: RODAS3_RTOLS,
        reference_rtol: 1e-14,
        reference_method: Method::Dopri5,
    }
}

/// The rigid peg's forward model as an owned [`OdeSystem`]: the
/// right-hand side of [`PegSystem`] (sliding, no start direction), without
/// its contact events. It has no analytic Jacobian: RODAS3 uses the
/// default forward difference (5 right-hand sides per Jacobian, not counted
/// in `rhs_calls`).
pub struct RigidSystem(pub ForwardModel);

impl OdeSystem<4> for RigidSystem {
    fn rhs(&self, t: f64, x: &SVector<f64, 4>) -> SVector<f64, 4> {
        PegSystem {
            model: &self.0,
            start: None,
        }
        .rhs(t, x)
    }

    fn time_derivative(&self, _t: f64, _x: &SVector<f64, 4>) -> SVector<f64, 4> {
        SVector::zeros()
    }
}

/// `scenes/align_forward.toml` and its forward model.
pub fn align_forward_scene() -> (AlignForwardScene, ForwardModel) {
    let text = include_str!("../../../scenes/align_forward.toml");
    let scene: AlignForwardScene = Document::parse(text)
        .and_then(|d| d.body())
        .expect("shipped scene parses");
    let model = scene.forward_model().expect("shipped scene is valid");
    (scene, model)
}

const RIGID_RK4_SHORT: &[f64] = &[1e-3, 5e-4, 2e-4, 1e-4, 5e-5, 2e-5, 1e-5];

/// The shipped rigid forward scene (Fig. 9 peg, f = 0.2, γ = 0.3 rad,
/// ψ̇ = 10 1/s, M_γ = −0.15 N·m), cut at 12 ms: it lifts off K at
/// 12.98 ms, so every method integrates the same smooth sliding motion.
pub fn rigid_forward() -> Problem<4, RigidSystem> {
    let (scene, model) = align_forward_scene();
    Problem {
        name: "rigid_forward",
        about: "rigid peg, scenes/align_forward.toml (Fig. 9 peg, f = 0.2, released at gamma = 0.3 rad with \
                psidot = 10 1/s, M_gamma = -0.15 N m, exact Coulomb sliding on K, B1, B2), cut at 12 ms, before \
                its first event (lift-off of K at 12.98 ms): a smooth sliding motion for every method",
        system: RigidSystem(model),
        y0: scene.initial_state(),
        t_end: 0.012,
        coords: (&[0, 1], "rad"),
        atol_scale: 1e-2,
        rk4_steps: RIGID_RK4_SHORT,
        dopri5_rtols: DOPRI5_RTOLS,
        rodas3_rtols: RODAS3_RTOLS,
        reference_rtol: 1e-14,
        reference_method: Method::Dopri5,
    }
}

/// The frictionless Fig. 9 peg rocking on three points for 1 s (released
/// at γ = 1.2 rad with ψ̇ = 2 1/s, no loads; `tests/rigid_peg/forward.rs`
/// checks that it conserves energy and keeps all three contacts).
pub fn rigid_rocking() -> Problem<4, RigidSystem> {
    let model = ForwardModel::new(
        PegParams {
            friction: 0.0,
            ..PegParams::fig9()
        },
        Loads::default(),
    )
    .expect("Fig. 9 peg is valid");
    Problem {
        name: "rigid_rocking",
        about: "frictionless Fig. 9 peg released at gamma = 1.2 rad with psidot = 2 1/s, no loads, 1 s: it \
                rocks about its lying position on K, B1, B2 (several oscillations, energy conserved, no event)",
        system: RigidSystem(model),
        y0: SVector::<f64, 4>::new(1.2, 0.0, 0.0, 2.0),
        t_end: 1.0,
        coords: (&[0, 1], "rad"),
        atol_scale: 1e-2,
        rk4_steps: &[1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4, 1e-4],
        dopri5_rtols: DOPRI5_RTOLS,
        rodas3_rtols: RODAS3_RTOLS,
        reference_rtol: 1e-14,
        reference_method: Method::Dopri5,
    }
}

/// `scenes/insert_compliant.toml` with the elastic friction law
/// (Hertz–Mindlin capped by Coulomb), to 0.1 s.
pub fn insertion_elastic() -> Problem<12, ElasticSystem> {
    let built = shipped_insertion();
    let mut spec = built.params.spec;
    spec.friction_law = FrictionLaw::Elastic;
    let params = pegdyn::compliant_peg::CompliantParams::try_new(spec).expect("valid elastic law");
    Problem {
        name: "insert_compliant_elastic",
        about: "the compliant insertion above with the elastic friction law (Hertz-Mindlin capped by \
                Coulomb, 12 states)",
        system: ElasticSystem::new(&params, &built.load),
        y0: built.initial.to_vector_elastic(),
        t_end: 0.1,
        coords: (&[0, 1, 2], "m or rad"),
        atol_scale: 1e-4,
        rk4_steps: &[],
        dopri5_rtols: &[1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9],
        rodas3_rtols: &[1e-3, 1e-4, 1e-5, 1e-6],
        reference_rtol: 1e-10,
        reference_method: Method::Rodas4,
    }
}

/// The stuck run of the shipped jamming sweep (`scenes/jamming.toml`:
/// steel peg r = 12.5 mm, c = 0.01, μ = 0.3, F_z = 20 N, load ratio
/// (0, 1.5 × the parallelogram's top corner moment)) from its two-point
/// start, its load and the setup with friction law `law`.
fn jammed_setup(law: FrictionLaw) -> (SweepSetup, Load) {
    let setup = SweepSetup::new(SweepSpec {
        ..SweepSpec::reference()
    })
    .and_then(|s| s.with_friction_law(law))
    .expect("valid sweep");
    let fz = setup.spec.fz;
    let w = Wrench {
        fx: 0.0,
        fz,
        m: 1.5 * setup.diagram.corners[2][1] * setup.spec.peg.r() * fz,
    };
    let (axial, radial, torque) = to_paper_frame(&w, setup.theta, setup.params.spec.com_height);
    (
        setup,
        Load {
            axial,
            radial,
            torque,
        },
    )
}

const JAMMED_ABOUT: &str = "the stuck run of the jamming sweep (scenes/jamming.toml, load ratio (0, 1.5 x the \
     top corner moment)) over 0.05 s from its two-point start: impacts, then held";

/// The jammed peg under the regularized law (`v_s = 1e-5 m/s`), to 0.05 s.
pub fn jammed() -> Problem<8, CompliantSystem> {
    let (setup, load) = jammed_setup(FrictionLaw::Regularized);
    Problem {
        name: "jammed",
        about: JAMMED_ABOUT,
        system: CompliantSystem::new(&setup.params, &load),
        y0: setup.start.to_vector(),
        t_end: 0.05,
        coords: (&[0, 1, 2], "m or rad"),
        atol_scale: 1e-4,
        rk4_steps: &[],
        dopri5_rtols: &[1e-4],
        rodas3_rtols: RODAS3_RTOLS,
        reference_rtol: 1e-10,
        reference_method: Method::Rodas4,
    }
}

/// The jammed peg under the elastic law, to 0.05 s.
pub fn jammed_elastic() -> Problem<12, ElasticSystem> {
    let (setup, load) = jammed_setup(FrictionLaw::Elastic);
    Problem {
        name: "jammed_elastic",
        about: "the same jammed peg with the elastic friction law",
        system: ElasticSystem::new(&setup.params, &load),
        y0: setup.start.to_vector_elastic(),
        t_end: 0.05,
        coords: (&[0, 1, 2], "m or rad"),
        atol_scale: 1e-4,
        rk4_steps: &[],
        dopri5_rtols: &[1e-4, 1e-5, 1e-6, 1e-7, 1e-8],
        rodas3_rtols: RODAS3_RTOLS,
        reference_rtol: 1e-10,
        reference_method: Method::Rodas4,
    }
}
