//! The generated modules of the planar compliant peg-in-hole
//! ([`super`]): `compliant_peg` with all four contacts (either
//! lean, any contact state of the paper's Fig. 4) and `compliant_peg_lean`
//! with only the two contacts of the paper's Fig. 5 (left edge, right wall:
//! the peg leaning with θ > 0), for scenes that never lean the other way;
//! `compliant_peg_elastic` with all four contacts and the stick-capable
//! friction law ([`super::elastic`]).

use super::geometry::Contact;
use super::{FrictionLaw, PlanarPeg};
use crate::expr::Expr;
use crate::graph::Graph;
use crate::model::{FnSpec, Input, Module, Output};

/// All four contacts.
pub fn module(g: &Graph) -> Module {
    build_module(g, "compliant_peg", &Contact::ALL)
}

/// All four contacts, elastic (stick-capable) friction.
pub fn module_elastic(g: &Graph) -> Module {
    build_module_law(
        g,
        "compliant_peg_elastic",
        &Contact::ALL,
        FrictionLaw::Elastic,
    )
}

/// Only the two contacts of a lean with θ > 0.
pub fn module_lean(g: &Graph) -> Module {
    build_module(
        g,
        "compliant_peg_lean",
        &[Contact::EdgeLeft, Contact::WallRight],
    )
}

fn function(name: &str, doc: &str, pp: &PlanarPeg<'_>, outputs: Vec<(&str, Output)>) -> FnSpec {
    FnSpec::new(
        name,
        doc,
        vec![Input::new("y", &pp.state), Input::new("p", &pp.params)],
        outputs,
    )
}

fn per<'g>(xs: &[Expr<'g>]) -> Output {
    Output::vector(xs)
}

fn build_module(g: &Graph, name: &str, contacts: &[Contact]) -> Module {
    build_module_law(g, name, contacts, FrictionLaw::Regularized)
}

fn build_module_law(g: &Graph, name: &str, contacts: &[Contact], law: FrictionLaw) -> Module {
    let pp = super::build_law(g, contacts, law);
    let names: Vec<&str> = contacts.iter().map(|c| c.name()).collect();
    let elastic = law == FrictionLaw::Elastic;
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
    let mut energy = vec![
        ("kinetic", Output::scalar(pp.kinetic)),
        ("potential", Output::scalar(pp.potential)),
        ("depth", Output::scalar(pp.depth)),
    ];
    let mut energy_doc =
        "Kinetic energy (59) (J), contact potential (63) (J) and insertion depth of the bottom face (m)."
            .to_owned();
    if elastic {
        energy.push(("tangential", Output::scalar(pp.tangential)));
        energy_doc = "Kinetic energy (59) (J), contact potential (63) (J), insertion depth of the \
                      bottom face (m) and stored tangential energy (J)."
            .to_owned();
    }
    let fns = vec![
        function(
            "rhs",
            &rhs_doc,
            &pp,
            vec![("ydot", Output::vector(&pp.rhs))],
        ),
        function(
            "jacobian",
            &jac_doc,
            &pp,
            vec![("jac", Output::matrix(&pp.jacobian))],
        ),
        function(
            "contacts",
            &format!(
                "Per contact ({}): normal force f (N), friction force along the tangent (N), penetration \
                 delta (m), sliding velocity (m/s), contact ellipse a, b (m) and maximum pressure p0 (Pa) \
                 ((9)-(11)).",
                names.join(", ")
            ),
            &pp,
            vec![
                ("normal", per(&pp.normal)),
                ("friction", per(&pp.friction)),
                ("delta", per(&pp.delta)),
                ("slip", per(&pp.slip)),
                (
                    "a",
                    per(&pp.ellipse.iter().map(|e| e.a).collect::<Vec<_>>()),
                ),
                (
                    "b",
                    per(&pp.ellipse.iter().map(|e| e.b).collect::<Vec<_>>()),
                ),
                (
                    "p0",
                    per(&pp.ellipse.iter().map(|e| e.p0).collect::<Vec<_>>()),
                ),
            ],
        ),
        function("energy", &energy_doc, &pp, energy),
    ];
    Module {
        name: name.to_owned(),
        doc: format!(
            "Compliant planar peg (*Dynamic analysis for peg-in-hole assembly with contact deformation*, (31)-(51), (55)-(64)) with contacts {}{}. \
             Inputs: state y (see STATE) and parameters p (see P_NAMES). SI units.",
            names.join(", "),
            if elastic {
                ", Hertz-Mindlin friction capped by Coulomb"
            } else {
                ""
            }
        ),
        functions: fns,
    }
}
