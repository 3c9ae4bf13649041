//! The generated modules of the planar compliant peg-in-hole
//! ([`super`]): `compliant_peg` with all four contacts (either
//! lean, any contact state of the paper's Fig. 4) and `compliant_peg_lean`
//! with only the two contacts of the paper's Fig. 5 (left edge, right wall:
//! the peg leaning with θ > 0), for scenes that never lean the other way;
//! `compliant_peg_elastic` with all four contacts and the stick-capable
//! friction law ([`super::elastic`]).

use super::geometry::Contact;
use super::{
    ELASTIC_PARAM_DOCS, ELASTIC_PARAMS, FrictionLaw, PARAM_DOCS, PARAMS, PlanarPeg, STATE,
    STATE_DOCS,
};
use crate::GenError;
use crate::builder::{ModelBuilder, Outputs};
use crate::expr::Expr;
use crate::model::Output;

/// `compliant_peg`: all four contacts.
///
/// # Errors
/// Those of [`ModelBuilder`] (none for this fixed model).
pub fn declare_all_contacts(b: &mut ModelBuilder<'_>) -> Result<(), GenError> {
    declare(b, &Contact::ALL, FrictionLaw::Regularized)
}

/// `compliant_peg_elastic`: all four contacts, elastic (stick-capable)
/// friction.
///
/// # Errors
/// Those of [`ModelBuilder`] (none for this fixed model).
pub fn declare_elastic(b: &mut ModelBuilder<'_>) -> Result<(), GenError> {
    declare(b, &Contact::ALL, FrictionLaw::Elastic)
}

/// `compliant_peg_lean`: only the two contacts of a lean with θ > 0.
///
/// # Errors
/// Those of [`ModelBuilder`] (none for this fixed model).
pub fn declare_lean(b: &mut ModelBuilder<'_>) -> Result<(), GenError> {
    // The same parameters as `compliant_peg`: one value serves both.
    b.share_input_type("p", "compliant_peg");
    b.share_output_type("EnergyOut", "compliant_peg");
    declare(
        b,
        &[Contact::EdgeLeft, Contact::WallRight],
        FrictionLaw::Regularized,
    )
}

fn per<'g>(xs: &[Expr<'g>]) -> Output {
    Output::vector(xs)
}

/// Declares the model with `contacts` and the friction `law`: the
/// derivation ([`super::build_law`]) first, then its state and parameter
/// symbols with their meanings, then the functions of `(y, p)`.
fn declare(
    b: &mut ModelBuilder<'_>,
    contacts: &[Contact],
    law: FrictionLaw,
) -> Result<(), GenError> {
    let pp = super::build_law(b.g(), contacts, law);
    let names: Vec<&str> = contacts.iter().map(|c| c.name()).collect();
    let elastic = law == FrictionLaw::Elastic;
    b.doc(&format!(
        "Compliant planar peg (*Dynamic analysis for peg-in-hole assembly with contact deformation*, (31)-(51), (55)-(64)) with contacts {}{}. \
         Inputs: state y (see STATE) and parameters p (see P_NAMES). SI units.",
        names.join(", "),
        if elastic {
            ", Hertz-Mindlin friction capped by Coulomb"
        } else {
            ""
        }
    ));
    b.outputs(Outputs::NONE);
    for (name, doc) in STATE.iter().zip(STATE_DOCS) {
        b.state(name, doc)?;
    }
    for (name, doc) in PARAMS.iter().zip(PARAM_DOCS) {
        b.parameter(name, doc)?;
    }
    if elastic {
        for c in &names {
            b.state(
                &format!("u_{c}"),
                &format!("utilisation ξ/ξ_max of the tangential spring at {c}, dimensionless"),
            )?;
        }
        for (name, doc) in ELASTIC_PARAMS.iter().zip(ELASTIC_PARAM_DOCS) {
            b.parameter(name, doc)?;
        }
    }
    declare_functions(b, &pp, &names, elastic)
}

/// `rhs`, `jacobian`, `contacts` and `energy`, each of `(y, p)`.
fn declare_functions<'g>(
    b: &mut ModelBuilder<'g>,
    pp: &PlanarPeg<'g>,
    names: &[&str],
    elastic: bool,
) -> Result<(), GenError> {
    let y: &[(&str, &[Expr<'g>])] = &[("y", &pp.state)];
    let (rhs_doc, jac_doc) = if elastic {
        (
            format!(
                "Right-hand side of y = (x, z, theta, xdot, zdot, thetadot, work, dissipation, \
                 u_{}): M qdd = applied (50) + contact normal forces (-grad of the Hertz potential \
                 (62) and of the stored tangential energy) + Hertz-Mindlin friction capped by \
                 Coulomb; work, dissipation and utilisation rates. SI units.",
                names.join(", u_")
            ),
            format!(
                "Exact Jacobian d(rhs)/dy, row-major {0}x{0}.",
                pp.state.len()
            ),
        )
    } else {
        (
            "Right-hand side of y = (x, z, theta, xdot, zdot, thetadot, work, dissipation): \
             M qdd = applied (50) + contact normal forces (-grad of the Hertz potential (62)) + Coulomb \
             friction; work and dissipation rates. SI units."
                .to_owned(),
            "Exact Jacobian d(rhs)/dy, row-major 8x8.".to_owned(),
        )
    };
    b.function(
        "rhs",
        &rhs_doc,
        y,
        vec![(
            "ydot",
            "the state's rate dy/dt, SI units per s",
            Output::vector(&pp.rhs),
        )],
    )?;
    b.parameter_jacobian("rhs")?;
    b.function(
        "jacobian",
        &jac_doc,
        y,
        vec![(
            "jac",
            "d(ydot)/dy, entry (i, j) = d(ydot_i)/dy_j",
            Output::matrix(&pp.jacobian),
        )],
    )?;
    let each = |what: &str| format!("{what}, per contact ({})", names.join(", "));
    let a: Vec<Expr<'g>> = pp.ellipse.iter().map(|e| e.a).collect();
    let semi_minor: Vec<Expr<'g>> = pp.ellipse.iter().map(|e| e.b).collect();
    let p0: Vec<Expr<'g>> = pp.ellipse.iter().map(|e| e.p0).collect();
    b.function(
        "contacts",
        &format!(
            "Per contact ({}): normal force f (N), friction force along the tangent (N), penetration \
             delta (m), sliding velocity (m/s), contact ellipse a, b (m) and maximum pressure p0 (Pa) \
             ((9)-(11)).",
            names.join(", ")
        ),
        y,
        vec![
            ("normal", each("normal force f on the peg, N").as_str(), per(&pp.normal)),
            ("friction", each("friction force along the contact tangent, N").as_str(), per(&pp.friction)),
            ("delta", each("penetration δ (negative: gap), m").as_str(), per(&pp.delta)),
            ("slip", each("sliding velocity of the peg's material point, m/s").as_str(), per(&pp.slip)),
            ("a", each("semi-major axis a of the Hertz ellipse (9), m").as_str(), per(&a)),
            ("b", each("semi-minor axis b of the Hertz ellipse (10), m").as_str(), per(&semi_minor)),
            ("p0", each("maximum Hertz pressure p₀ (11), Pa").as_str(), per(&p0)),
        ],
    )?;
    let mut energy = vec![
        (
            "kinetic",
            "kinetic energy T (59), J",
            Output::scalar(pp.kinetic),
        ),
        (
            "potential",
            "contact potential P (63), J",
            Output::scalar(pp.potential),
        ),
        (
            "depth",
            "insertion depth l of the bottom face's centre, m",
            Output::scalar(pp.depth),
        ),
    ];
    let mut energy_doc =
        "Kinetic energy (59) (J), contact potential (63) (J) and insertion depth of the bottom face (m)."
            .to_owned();
    if elastic {
        energy.push((
            "tangential",
            "energy stored in the tangential springs, J",
            Output::scalar(pp.tangential),
        ));
        energy_doc = "Kinetic energy (59) (J), contact potential (63) (J), insertion depth of the \
                      bottom face (m) and stored tangential energy (J)."
            .to_owned();
    }
    b.function("energy", &energy_doc, y, energy)
}
