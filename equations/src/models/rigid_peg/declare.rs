//! The four variants of the rigid three-point peg declared as models
//! through the builder: the derivation ([`super::derive`]) and its
//! specialization ([`specialize`]) first, then the symbols the functions
//! take with their meanings and units, the typed inputs and outputs, and
//! `forward`, `prescribed`, `contact_velocities`, `energy` (and `geometry`
//! for the full variant).

use super::variants::{Variant, linear_system, specialize};
use crate::GenError;
use crate::builder::{ModelBuilder, Outputs};
use crate::expr::Expr;
use crate::model::Output;

/// `rigid_peg`.
///
/// # Errors
/// Those of [`ModelBuilder`] (none for this fixed model).
pub fn declare_full(b: &mut ModelBuilder<'_>) -> Result<(), GenError> {
    declare(b, Variant::Full)
}
/// `rigid_peg_frictionless`.
///
/// # Errors
/// Those of [`ModelBuilder`] (none for this fixed model).
pub fn declare_frictionless(b: &mut ModelBuilder<'_>) -> Result<(), GenError> {
    declare(b, Variant::Frictionless)
}
/// `rigid_peg_planar`.
///
/// # Errors
/// Those of [`ModelBuilder`] (none for this fixed model).
pub fn declare_planar(b: &mut ModelBuilder<'_>) -> Result<(), GenError> {
    declare(b, Variant::Planar)
}
/// `rigid_peg_planar_frictionless`.
///
/// # Errors
/// Those of [`ModelBuilder`] (none for this fixed model).
pub fn declare_planar_frictionless(b: &mut ModelBuilder<'_>) -> Result<(), GenError> {
    declare(b, Variant::PlanarFrictionless)
}

/// What each symbol a variant's functions take is, with its unit.
fn symbol_doc(name: &str, planar: bool) -> String {
    let axis = |a: &str| match a {
        "eta" => "e_η",
        "n" => "e_n",
        _ => "e_z",
    };
    match name {
        "gamma" => "nutation angle γ between the peg's axis and the hole's axis, rad".to_owned(),
        "psi" => "precession angle ψ of the symmetry plane about the hole's axis, rad".to_owned(),
        "gammadot" => "nutation rate γ̇, rad/s".to_owned(),
        "psidot" => "precession rate ψ̇, rad/s".to_owned(),
        "gammaddot" => "nutation acceleration γ̈, rad/s²".to_owned(),
        "psiddot" => "precession acceleration ψ̈, rad/s²".to_owned(),
        "D_hole" => "hole diameter D, m".to_owned(),
        "d_peg" => "peg diameter d, m".to_owned(),
        "H" => "peg height H, m".to_owned(),
        "m" => "mass m of the peg, kg".to_owned(),
        "g" => "gravitational acceleration g (along −z), m/s²".to_owned(),
        "f" => "Coulomb friction coefficient f, dimensionless".to_owned(),
        "gamma0" => "γ0 = arccos(d/D), the tilt where the three-point contact begins \
                     (consistent with D and d), rad"
            .to_owned(),
        "M_gamma" => "generalized moment M_γ conjugate to γ, N·m".to_owned(),
        "M_psi" => "moment M_ψ about the hole's axis, conjugate to ψ, N·m".to_owned(),
        "F_x" if planar => {
            "assembly force at the centre of mass, in-plane horizontal component (along e_η), N"
                .to_owned()
        }
        "F_x" | "F_y" | "F_z" => format!(
            "assembly force at the centre of mass, fixed-frame {} component, N",
            &name[2..].to_lowercase()
        ),
        _ => match name.strip_prefix("t_").and_then(|r| r.split_once('_')) {
            Some((contact, a)) => format!(
                "friction direction at {contact}, {} component (unit or shorter, force on the peg), dimensionless",
                axis(a)
            ),
            None => String::new(),
        },
    }
}

/// The typed inputs and outputs of `variant`: `Params`, `State`, `Loads`,
/// `FrictionDirections`, `LinearSystem` (of `forward` and `prescribed`)
/// and `EnergyOut`; each variant shares those of the largest variant with
/// the same components.
fn declare_types(b: &mut ModelBuilder<'_>, variant: Variant) -> Result<(), GenError> {
    let (state_doc, loads_doc) = if variant.is_planar() {
        (
            "The state x = (γ, γ̇) of the planar motion (ψ ≡ 0).",
            "The applied loads of the planar motion: the moment conjugate to γ and the \
             in-plane components of the assembly force.",
        )
    } else {
        (
            "The state x = (γ, ψ, γ̇, ψ̇).",
            "The applied loads: the moments conjugate to γ and ψ and the assembly force at the \
             centre of mass in fixed-frame components.",
        )
    };
    b.typed_input("x", "State", state_doc)?;
    b.typed_input("loads", "Loads", loads_doc)?;
    if variant.has_friction() {
        b.typed_input(
            "t",
            "FrictionDirections",
            "The friction direction at each contact (unit or shorter, force on the peg) in \
             rotating components (e_η, e_n, e_z).",
        )?;
    }
    b.shared_output(
        "LinearSystem",
        "A linear system A u = b for the unknowns u (see the function returning it).",
        &["forward", "prescribed"],
    )?;
    let largest = if variant.is_planar() {
        Variant::Planar
    } else {
        Variant::Full
    };
    if variant != Variant::Full {
        b.share_input_type("p", Variant::Full.module_name());
        b.share_output_type("EnergyOut", Variant::Full.module_name());
    }
    if variant != largest {
        b.share_input_type("x", largest.module_name());
        b.share_input_type("loads", largest.module_name());
        b.share_output_type("LinearSystem", largest.module_name());
    }
    Ok(())
}

/// Declares the rigid peg's `variant`: the derivation and its
/// specialization first, then the symbols its functions take with their
/// meanings, then `forward`, `prescribed`, `contact_velocities`, `energy`
/// (and `geometry` for the full variant).
///
/// # Panics
/// If a row the planar specialization must make vanish does not (a bug in
/// the derivation: the planar motion would not solve the 2-DOF equations).
fn declare<'g>(b: &mut ModelBuilder<'g>, variant: Variant) -> Result<(), GenError> {
    let g = b.g();
    let d = super::derive(g);
    let sp = specialize(g, &d, variant);
    for (k, r) in sp.vanished.iter().enumerate() {
        assert!(
            r.as_const() == Some(0.0),
            "{}: dropped row {k} does not vanish identically: {r}",
            variant.module_name()
        );
    }
    let forward_unknowns: Vec<Expr<'_>> = sp.accel.iter().chain(&sp.normal).copied().collect();
    let prescribed_unknowns: Vec<Expr<'_>> = sp.moments.iter().chain(&sp.normal).copied().collect();
    let (fa, fb) = linear_system(g, &sp.rows, &forward_unknowns);
    let (pa, pb) = linear_system(g, &sp.rows, &prescribed_unknowns);

    let planar = variant.is_planar();
    let doc = |e: &Expr<'_>| symbol_doc(&e.to_string(), planar);
    b.outputs(Outputs::NONE);
    for e in &sp.state {
        b.symbol(&e.to_string(), &doc(e))?;
    }
    for e in &sp.accel {
        b.symbol(&e.to_string(), &doc(e))?;
    }
    for e in d.p.all() {
        b.parameter(&e.to_string(), &doc(&e))?;
    }
    for e in sp.loads.iter().chain(&sp.friction_dir) {
        b.input_parameter(&e.to_string(), &doc(e))?;
    }
    let names = |es: &[Expr<'_>]| {
        es.iter()
            .map(|e| format!("`{e}`"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    b.doc(&format!(
        "Rigid three-point peg leaning on the hole edge at K, B1, B2 (*Peg-on-hole: fundamental principles of motion of a peg leaning on a horizontal hole edge*), variant `{variant:?}`, derived \
         by the generator (equations/src/models/rigid_peg.rs).\n\
         State x = ({}); parameters p = (D_hole, d_peg, H, m, g, f, gamma0); loads = ({}){}.\n\
         Vectors in rotating components (e_η, e_n, e_z){}. SI units.",
        names(&sp.state),
        names(&sp.loads),
        if sp.friction_dir.is_empty() {
            String::new()
        } else {
            format!(
                "; friction directions t = ({}) (unit, force on the peg)",
                names(&sp.friction_dir)
            )
        },
        if planar {
            "; ψ ≡ 0, so `F_x` is the in-plane horizontal force (along e_η) and N_B = N_B1 = N_B2"
        } else {
            ""
        }
    ));

    declare_types(b, variant)?;
    let params = d.p.all();
    let (x, p) = (("x", sp.state.as_slice()), ("p", params.as_slice()));
    let (loads, qdd) = (("loads", sp.loads.as_slice()), ("qdd", sp.accel.as_slice()));
    let t = ("t", sp.friction_dir.as_slice());
    let dynamic: Vec<(&str, &[Expr<'g>])> = if sp.friction_dir.is_empty() {
        vec![loads]
    } else {
        vec![loads, t]
    };
    let forward_inputs: Vec<(&str, &[Expr<'g>])> =
        [x, p].into_iter().chain(dynamic.iter().copied()).collect();
    let prescribed_inputs: Vec<(&str, &[Expr<'g>])> = [x, qdd, p]
        .into_iter()
        .chain(dynamic.iter().copied())
        .collect();
    let rows_doc = if planar {
        "Rows: the Lagrange equation of γ (paper (26)/(32)), then the centre-of-mass equations along \
         e_η and e_z ((29), (31)/(33), (34)); the ψ row and the lateral row vanish identically."
    } else {
        "Rows: the Lagrange equations of γ and ψ (paper (26), (27)), then the centre-of-mass \
         equations (28)–(31) along e_η, e_n, e_z (the fixed-frame (29)–(31) rotated by −ψ)."
    };
    b.function(
        "forward",
        &format!(
            "Forward dynamics (replaces paper (24)–(31)): A u = b for u = ({}) (rad/s², N), \
             the applied loads and friction directions given.\n{rows_doc}\n\
             A = ∂R/∂u, b = −R at u = 0, R the residual derived from T, V and the generalized forces.",
            names(&forward_unknowns)
        ),
        &forward_inputs,
        vec![
            ("a", "the matrix A = ∂R/∂u", Output::matrix(&fa)),
            ("b", "the right-hand side b = −R at u = 0", Output::vector(&fb)),
        ],
    )?;
    b.solution_parameter_jacobian("forward", &forward_unknowns)?;
    b.function(
        "prescribed",
        &format!(
            "Prescribed motion (paper (26)–(31), Fig. 9): A u = b for u = ({}) (N·m, N) given \
             q̈ (the moment components of `loads` are unused: they are the unknowns).\n{rows_doc}",
            names(&prescribed_unknowns)
        ),
        &prescribed_inputs,
        vec![
            ("a", "the matrix A = ∂R/∂u", Output::matrix(&pa)),
            (
                "b",
                "the right-hand side b = −R at u = 0",
                Output::vector(&pb),
            ),
        ],
    )?;
    b.function(
        "contact_velocities",
        "Material velocity of the peg at K, B1, B2 (rows) in rotating components (e_η, e_n, e_z) \
         (m/s); replaces paper (10)–(13). The friction directions are −v/|v|.",
        &[x, p],
        vec![(
            "v",
            "velocity of the peg at K, B1, B2 (rows), rotating components, m/s",
            Output::matrix(&sp.contact_velocities),
        )],
    )?;
    b.function(
        "energy",
        "Kinetic energy T = ½ m|v_C|² + ½ ωᵀIω (paper (22)–(23)) and total energy T + V with \
         V = m g z_C (J).",
        &[x, p],
        vec![
            ("kinetic", "kinetic energy T, J", Output::scalar(sp.kinetic)),
            ("total", "total energy T + V, J", Output::scalar(sp.energy)),
        ],
    )?;
    if variant == Variant::Full {
        let geo = &d.geo;
        let outs = [
            geo.a1,
            geo.a2,
            geo.s1,
            geo.s2,
            geo.b,
            geo.sin_tau,
            geo.cos_tau,
            geo.eta_c,
            geo.z_c,
            geo.kl,
            geo.bl,
            geo.centre_l[0],
            geo.centre_l[1],
        ];
        b.function(
            "geometry",
            "Planar geometry at γ (m): a1, a2 (paper (1)), S1, S2 (2), b = BB1, sin τ, cos τ, η_C, z_C \
             (3), KL, BL (5), η_L, z_L (4b).",
            &[x, p],
            vec![(
                "geo",
                "a1, a2, S1, S2, b, sin τ, cos τ, η_C, z_C, KL, BL, η_L, z_L (lengths in m)",
                Output::vector(&outs),
            )],
        )?;
    }
    Ok(())
}
