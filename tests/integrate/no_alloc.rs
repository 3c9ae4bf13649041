//! The hot path allocates nothing: every generated right-hand side and
//! Jacobian, the generated rigid contact systems (`forward`, `prescribed`,
//! four variants), the `OdeSystem` adapters the integrators call (the
//! compliant model's `rhs` / `jacobian` / `time_derivative`, the pendulum
//! scenes' systems, the rigid `PegSystem`), and the interpreter's
//! `Tape::eval_into` with reused buffers (every function of every model)
//! are measured with a counting global allocator; so are the compliant 3-D
//! peg's right-hand side and exact Jacobian (cold and warm contact
//! search), the wrist insertion's and the prescribed 3-D peg's adapters.
//!
//! The counter is per thread (the test harness allocates on other threads),
//! and each measured closure is first called once outside the window so
//! that lazy one-time initialisation cannot count.

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::hint::black_box;

use nalgebra::{SVector, Vector2, Vector3, Vector4};
use pegdyn::compliant_peg::{
    CompliantParams, CompliantSpec, CompliantSystem, ContactSet, Load, PegState,
};
use pegdyn::generated::{cart_pole, compliant_peg, compliant_peg_lean, double_pendulum, pendulum};
use pegdyn::rigid_peg::forward::{ForwardModel, PegSystem};
use pegdyn::rigid_peg::{Loads, PegParams};
use pegdyn::system::OdeSystem;
use pegdyn::textbook::double_pendulum::{DoublePendulumParams, DoublePendulumSystem};
use pegdyn::textbook::pendulum::{PendulumParams, PendulumSystem};

struct Counting;

thread_local! {
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

// SAFETY: forwards every call to the system allocator unchanged; only
// counts allocations of the current thread.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
        // SAFETY: same contract as the caller's.
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: same contract as the caller's.
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
        // SAFETY: same contract as the caller's.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

fn allocations() -> usize {
    ALLOCATIONS.with(Cell::get)
}

/// Allocations made by 100 calls of `f` (after one warm-up call).
fn allocs_of<R>(mut f: impl FnMut() -> R) -> usize {
    black_box(f());
    let before = allocations();
    for _ in 0..100 {
        black_box(f());
    }
    allocations() - before
}

#[test]
fn the_counter_sees_allocations() {
    assert_eq!(allocs_of(|| vec![1.0_f64; 8]), 100);
}

fn scene(contacts: ContactSet) -> (CompliantSystem, SVector<f64, 24>, SVector<f64, 8>) {
    let mut spec = CompliantSpec::steel_cylinder(0.05, 0.002, 0.1, 0.1);
    spec.contacts = contacts;
    let params = CompliantParams::try_new(spec).expect("reference spec");
    let load = Load {
        axial: 5.0,
        radial: 0.0,
        torque: -0.002,
    };
    let y = PegState::two_point(&params, 0.01, 0.0)
        .expect("two-point start")
        .to_vector();
    (
        CompliantSystem::new(&params, &load),
        params.vector(&load),
        y,
    )
}

#[test]
fn generated_compliant_rhs_and_jacobian_allocate_nothing() {
    let (_, p, y) = scene(ContactSet::All);
    assert_eq!(allocs_of(|| compliant_peg::rhs(black_box(&y), &p)), 0);
    assert_eq!(allocs_of(|| compliant_peg::jacobian(black_box(&y), &p)), 0);
    assert_eq!(allocs_of(|| compliant_peg_lean::rhs(black_box(&y), &p)), 0);
    assert_eq!(
        allocs_of(|| compliant_peg_lean::jacobian(black_box(&y), &p)),
        0
    );
}

#[test]
fn elastic_friction_adapter_and_samples_allocate_nothing() {
    use pegdyn::compliant_peg::{ElasticSystem, FrictionLaw};
    let mut spec = CompliantSpec::steel_cylinder(0.05, 0.002, 0.1, 0.1);
    spec.friction_law = FrictionLaw::Elastic;
    let params = CompliantParams::try_new(spec).expect("reference spec");
    let load = Load {
        axial: 5.0,
        radial: 0.0,
        torque: -0.002,
    };
    let start = PegState::two_point(&params, 0.01, 0.0).expect("two-point start");
    let sys = ElasticSystem::new(&params, &load);
    let y = start.to_vector_elastic();
    assert_eq!(allocs_of(|| sys.rhs(0.0, black_box(&y))), 0);
    assert_eq!(allocs_of(|| sys.jacobian(0.0, black_box(&y))), 0);
    assert_eq!(allocs_of(|| sys.sample(black_box(&y))), 0);
    let (regularized, _, y8) = scene(ContactSet::All);
    assert_eq!(allocs_of(|| regularized.sample(black_box(&y8))), 0);
}

#[test]
fn compliant_ode_adapters_allocate_nothing() {
    for contacts in [ContactSet::All, ContactSet::Lean] {
        let (sys, _, y) = scene(contacts);
        assert_eq!(allocs_of(|| sys.rhs(0.0, black_box(&y))), 0);
        assert_eq!(allocs_of(|| sys.jacobian(0.0, black_box(&y))), 0);
        assert_eq!(allocs_of(|| sys.time_derivative(0.0, black_box(&y))), 0);
    }
}

#[test]
fn generated_textbook_rhs_and_jacobian_terms_allocate_nothing() {
    let x2 = Vector2::new(0.3, -0.2);
    let p3 = SVector::<f64, 3>::from([1.0, 0.8, 9.81]);
    let x4 = Vector4::new(0.3, -0.2, 0.5, 0.1);
    let p5 = SVector::<f64, 5>::from([1.0, 0.7, 0.8, 0.6, 9.81]);
    let q1 = SVector::<f64, 1>::new(0.4);
    let q2 = Vector2::new(0.4, -0.3);
    assert_eq!(allocs_of(|| pendulum::rhs(black_box(&x2), &p3)), 0);
    assert_eq!(
        allocs_of(|| pendulum::jacobian_terms(black_box(&x2), &q1, &p3)),
        0
    );
    assert_eq!(allocs_of(|| double_pendulum::rhs(black_box(&x4), &p5)), 0);
    assert_eq!(
        allocs_of(|| double_pendulum::jacobian_terms(black_box(&x4), &q2, &p5)),
        0
    );
    assert_eq!(allocs_of(|| cart_pole::rhs(black_box(&x4), &p5)), 0);
    assert_eq!(
        allocs_of(|| cart_pole::jacobian_terms(black_box(&x4), &q2, &p5)),
        0
    );
}

#[test]
fn pendulum_ode_adapters_allocate_nothing() {
    let single = PendulumSystem::new(&PendulumParams {
        length: 1.0,
        mass: 1.0,
        gravity: 9.81,
        theta0_deg: 60.0,
        omega0: 0.0,
    });
    let x2 = Vector2::new(0.3, -0.2);
    assert_eq!(allocs_of(|| single.rhs(0.0, black_box(&x2))), 0);
    assert_eq!(allocs_of(|| single.jacobian(0.0, black_box(&x2))), 0);
    let double = DoublePendulumSystem::new(&DoublePendulumParams {
        mass1: 1.0,
        mass2: 1.0,
        length1: 1.0,
        length2: 1.0,
        gravity: 9.81,
        theta1_deg: 120.0,
        theta2_deg: -10.0,
        omega1: 0.0,
        omega2: 0.0,
    });
    let x4 = Vector4::new(0.3, -0.2, 0.5, 0.1);
    assert_eq!(allocs_of(|| double.rhs(0.0, black_box(&x4))), 0);
    assert_eq!(allocs_of(|| double.jacobian(0.0, black_box(&x4))), 0);
}

#[test]
fn integration_steps_allocate_nothing() {
    use pegdyn::integrate::{Method, Options, Solver};
    // Allocations of a whole solve without stored output do not grow with
    // the number of steps: the per-step path allocates nothing.
    let (sys, _, y) = scene(ContactSet::All);
    for method in [Method::Dopri5, Method::Rodas3, Method::Rk4 { h: 1e-5 }] {
        let count = |t_end: f64| {
            let mut o = Options::with_tolerances(1e-8, 1e-12);
            o.store = false;
            let before = allocations();
            let sol = Solver::new(method, o)
                .solve(&sys, 0.0, y, t_end)
                .expect("valid options");
            (allocations() - before, sol.stats.steps)
        };
        let (short, short_steps) = count(1e-3);
        let (long, long_steps) = count(4e-3);
        assert!(
            long_steps > short_steps + 10,
            "{method:?}: {short_steps} vs {long_steps} steps"
        );
        assert_eq!(short, long, "{method:?}: allocations grow with the steps");
    }
}

#[test]
fn generated_rigid_systems_allocate_nothing() {
    use pegdyn::generated::{
        rigid_peg, rigid_peg_frictionless, rigid_peg_planar, rigid_peg_planar_frictionless,
    };
    let p = PegParams::fig9().to_vector();
    let loads = SVector::<f64, 5>::from([0.02, -0.01, 0.3, -0.2, 1.5]);
    let planar_loads = Vector3::new(0.02, 0.3, 1.5);
    let x4 = Vector4::new(0.3, 0.7, -2.0, 10.0);
    let x2 = Vector2::new(0.3, -2.0);
    let t9 = SVector::<f64, 9>::from_fn(|i, _| 0.1 * i as f64 - 0.4);
    let t4 = SVector::<f64, 4>::new(0.6, -0.8, 0.0, 1.0);
    let q2 = Vector2::new(3.0, -40.0);
    let q1 = SVector::<f64, 1>::new(3.0);
    assert_eq!(
        allocs_of(|| rigid_peg::forward(black_box(&x4), &p, &loads, &t9)),
        0
    );
    assert_eq!(
        allocs_of(|| rigid_peg::prescribed(black_box(&x4), &q2, &p, &loads, &t9)),
        0
    );
    assert_eq!(
        allocs_of(|| rigid_peg_frictionless::forward(black_box(&x4), &p, &loads)),
        0
    );
    assert_eq!(
        allocs_of(|| rigid_peg_frictionless::prescribed(black_box(&x4), &q2, &p, &loads)),
        0
    );
    assert_eq!(
        allocs_of(|| rigid_peg_planar::forward(black_box(&x2), &p, &planar_loads, &t4)),
        0
    );
    assert_eq!(
        allocs_of(|| rigid_peg_planar::prescribed(black_box(&x2), &q1, &p, &planar_loads, &t4)),
        0
    );
    assert_eq!(
        allocs_of(|| rigid_peg_planar_frictionless::forward(black_box(&x2), &p, &planar_loads)),
        0
    );
    assert_eq!(
        allocs_of(|| {
            rigid_peg_planar_frictionless::prescribed(black_box(&x2), &q1, &p, &planar_loads)
        }),
        0
    );
}

#[test]
fn rigid_ode_adapter_allocates_nothing() {
    let loads = Loads {
        m_gamma: 0.02,
        m_psi: -0.01,
        force: [0.3, -0.2, 1.5],
    };
    let model = ForwardModel::new(PegParams::fig9(), loads).expect("Fig. 9 peg");
    // Sliding in both coordinates, and at rest with a sliding start
    // direction (the start path of the friction directions).
    for (x, start) in [
        (Vector4::new(0.3, 0.7, -2.0, 10.0), None),
        (
            Vector4::new(0.3, 0.0, 0.0, 0.0),
            Some(Vector2::new(-1.0, 0.0)),
        ),
    ] {
        let sys = PegSystem {
            model: &model,
            start,
        };
        assert!(sys.rhs(0.0, &x).iter().all(|v| v.is_finite()), "{x:?}");
        assert_eq!(allocs_of(|| sys.rhs(0.0, black_box(&x))), 0, "{x:?}");
    }
}

#[test]
fn interpreter_tape_with_reused_buffers_allocates_nothing() {
    use pegdyn_equations::eval::Tape;
    use pegdyn_equations::{Graph, models};
    for build in models::ALL {
        let g = Graph::new();
        let m = build.module(&g);
        for f in &m.functions {
            let roots: Vec<_> = f
                .outputs
                .iter()
                .flat_map(|(_, o)| o.ids().iter().copied())
                .collect();
            let tape = Tape::new(&g, &roots);
            let values = vec![0.5; g.symbols().len()];
            let (mut scratch, mut out) = (Vec::new(), vec![0.0; roots.len()]);
            assert_eq!(
                allocs_of(|| tape.eval_into(black_box(&values), &mut scratch, &mut out)),
                0,
                "{}::{}",
                m.name,
                f.name
            );
        }
    }
}

/// Allocations made by one call of `f` on a value built outside the
/// window (a cold first call: no warm start, no cached clearance).
fn allocs_of_first<T, R>(build: impl FnOnce() -> T, f: impl FnOnce(&T) -> R) -> usize {
    let value = build();
    let before = allocations();
    black_box(f(black_box(&value)));
    allocations() - before
}

#[test]
fn compliant_3d_rhs_and_jacobian_allocate_nothing() {
    // The contact search, the Hertz setups and the law run in fixed-capacity
    // arrays: the right-hand side and the exact Jacobian allocate nothing,
    // in contact or apart, at a cold first call and at warm later ones.
    // The stiffness from the curvatures at a one-point rim-on-mouth
    // contact; fixed where the curvatures make no point contact (the side
    // pressed along the wall, the rim's two mouth points merging).
    use crate::common::peg3d::{fig9, rim_on_mouth};
    use nalgebra::UnitQuaternion;
    use pegdyn::compliant_peg_3d::{HertzMode, Peg3d, pose_state};
    let (curvature, mut fixed) = (fig9(), fig9());
    fixed.hertz = HertzMode::Fixed(2e10);
    let pressed = pose_state(
        Vector3::new(40e-6, 0.0, -0.02),
        UnitQuaternion::identity(),
        Vector3::new(1e-3, 0.0, -1e-3),
        Vector3::new(0.0, 0.0, 2.0),
    );
    let apart = pose_state(
        Vector3::new(0.06, 0.0, 0.05),
        UnitQuaternion::identity(),
        Vector3::zeros(),
        Vector3::zeros(),
    );
    let cases = [
        (curvature, rim_on_mouth(&curvature, 0.02, 8e-6), 1),
        (curvature, apart, 0),
        (fixed, pressed, 2),
        (fixed, rim_on_mouth(&fixed, 0.0455, 2e-6), 1),
        (fixed, apart, 0),
    ];
    for (prm, y, at_least) in &cases {
        let sys = Peg3d::new(*prm);
        assert!(sys.contacts(y).len() >= *at_least, "{y:?}");
        let rhs = sys.try_rhs(0.0, y).expect("a point contact");
        let jac = sys.try_jacobian(0.0, y).expect("a point contact");
        assert!(rhs.iter().chain(jac.iter()).all(|v| v.is_finite()));
        let cold = |f: fn(&Peg3d, &SVector<f64, 15>) -> bool| {
            allocs_of_first(|| Peg3d::new(*prm), |s| f(s, y))
        };
        assert_eq!(cold(|s, y| s.try_rhs(0.0, y).is_ok()), 0, "{y:?}");
        assert_eq!(cold(|s, y| s.try_jacobian(0.0, y).is_ok()), 0, "{y:?}");
        assert_eq!(allocs_of(|| sys.try_rhs(0.0, black_box(y))), 0);
        assert_eq!(allocs_of(|| sys.rhs(0.0, black_box(y))), 0);
        assert_eq!(allocs_of(|| sys.try_jacobian(0.0, black_box(y))), 0);
        assert_eq!(allocs_of(|| sys.jacobian(0.0, black_box(y))), 0);
        assert_eq!(allocs_of(|| sys.contact_wrench(black_box(y))), 0);
    }
}

#[test]
fn elastic_3d_rhs_allocates_nothing() {
    // The 3-D peg with a tracked tangential displacement: a 10 mm peg
    // standing on the block's top face beside the bore, its rim's ring
    // 1 µm into the face (one slot, touching), sliding along x.
    use nalgebra::UnitQuaternion;
    use pegdyn::compliant_peg_3d::{
        ElasticPeg3d, FrictionLaw, Pair, Peg3dParams, SlotKey, pose_state,
    };
    let mut prm = Peg3dParams::steel(0.010, 0.020, 0.0101, 5e-4, 5e-4, 0.02);
    prm.friction = 0.3;
    prm.friction_law = FrictionLaw::Elastic;
    let sys = ElasticPeg3d::<18>::try_new(prm, &[SlotKey::ring(Pair::RimTop)]).expect("valid");
    let y15 = pose_state(
        Vector3::new(0.02, 0.0, 0.5 * prm.length - 1e-6),
        UnitQuaternion::identity(),
        Vector3::new(1e-3, 0.0, 0.0),
        Vector3::zeros(),
    );
    let mut y = ElasticPeg3d::<18>::state(&y15);
    y[15] = 1e-7;
    let slots = sys.slot_forces(&y).expect("a ring contact");
    assert!(
        slots[0].touching && slots[0].normal_force > 0.0,
        "{slots:?}"
    );
    assert!(
        sys.try_rhs(0.0, &y)
            .expect("valid")
            .iter()
            .all(|v| v.is_finite())
    );
    assert_eq!(allocs_of(|| sys.try_rhs(0.0, black_box(&y))), 0);
    assert_eq!(allocs_of(|| sys.rhs(0.0, black_box(&y))), 0);
}

#[test]
fn wrist_and_prescribed_3d_adapters_allocate_nothing() {
    // The wrist-held insertion of the shipped scene and the peg driven
    // along a prescribed orientation: right-hand side, the
    // finite-difference Jacobian and time derivative an implicit method
    // calls, leaning on the mouth and at the start above the hole.
    use pegdyn::compliant_peg_3d::insertion::{Insertion, N_STATE};
    use pegdyn::compliant_peg_3d::outcome::counts;
    use pegdyn::compliant_peg_3d::prescribed::{Motion, PrescribedPeg};
    use pegdyn::scene::shared::compliant_peg_3d::insertion::RccScene;
    let scene = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/insert_rcc.toml"
    ))
    .expect("the shipped scene");
    let mut doc: toml::Table = toml::from_str(&scene).expect("TOML");
    doc.remove("kind");
    doc.remove("description");
    let rcc: RccScene = doc.try_into().expect("an insert_rcc scene");
    let built = rcc.build().expect("valid");
    let held = Insertion::new(built.params, Some(built.held), 0.0);
    let start = held.held_start().expect("held");
    let mut leaning = SVector::<f64, N_STATE>::zeros();
    leaning
        .fixed_rows_mut::<15>(0)
        .copy_from(&crate::common::peg3d::rim_on_mouth(
            &built.params,
            0.02,
            1e-6,
        ));
    assert!(held.contacts(&start).is_empty());
    assert!(!held.contacts(&leaning).is_empty());
    for y in [&start, &leaning] {
        assert_eq!(allocs_of(|| held.try_rhs(0.1, black_box(y))), 0);
        assert_eq!(allocs_of(|| held.jacobian(0.1, black_box(y))), 0);
        assert_eq!(allocs_of(|| held.time_derivative(0.1, black_box(y))), 0);
    }
    // The contact-transition events' counts: a new state searches, the
    // same state again reads the memo; neither allocates.
    let cache = pegdyn::compliant_peg_3d::outcome::CountCache::new(&held);
    for y in [&start, &leaning, &start] {
        assert_eq!(allocs_of(|| cache.counts(0.1, black_box(y))), 0);
        assert_eq!(allocs_of(|| cache.counts(0.1, black_box(y))), 0);
    }
    assert_eq!(
        cache.counts(0.1, &leaning),
        counts(&held.contacts(&leaning))
    );
    let mut prm = crate::common::peg3d::fig9();
    prm.hertz = pegdyn::compliant_peg_3d::HertzMode::Fixed(2e10);
    let merging = crate::common::peg3d::rim_on_mouth(&prm, 0.0455, 2e-6);
    let driven = PrescribedPeg::try_new(
        prm,
        Motion {
            gamma: 0.0455,
            gammadot: -2.0,
            psi: 0.0,
            psidot: 10.0,
        },
    )
    .expect("a valid peg");
    let y7 = SVector::<f64, 7>::from_column_slice(&[
        merging[0], merging[1], merging[2], 0.0, 0.0, 0.0, 0.0,
    ]);
    assert!(!driven.forces(0.0, &y7).expect("valid").is_empty());
    assert_eq!(allocs_of(|| driven.try_rhs(0.0, black_box(&y7))), 0);
    assert_eq!(allocs_of(|| driven.jacobian(0.0, black_box(&y7))), 0);
    assert_eq!(allocs_of(|| driven.time_derivative(0.0, black_box(&y7))), 0);
}
