//! The generated modules of the planar compliant peg-in-hole
//! ([`super`]): `compliant_peg` with all four contacts (either
//! lean, any contact state of the paper's Fig. 4) and `compliant_peg_lean`
//! with only the two contacts of the paper's Fig. 5 (left edge, right wall:
//! the peg leaning with θ > 0), for scenes that never lean the other way.

use super::PlanarPeg;
use super::geometry::Contact;
use crate::expr::Expr;
use crate::graph::Graph;
use crate::model::{FnSpec, Input, Module, Output};

/// All four contacts.
pub fn module(g: &Graph) -> Module {
    build_module(g, "compliant_peg", &Contact::ALL)
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
    let pp = super::build(g, contacts);
    let names: Vec<&str> = contacts.iter().map(|c| c.name()).collect();
    let fns = vec![
        function(
            "rhs",
            "Right-hand side of y = (x, z, theta, xdot, zdot, thetadot, work, dissipation): \
             M qdd = applied (50) + contact normal forces (-grad of the Hertz potential (62)) + Coulomb \
             friction; work and dissipation rates. SI units.",
            &pp,
            vec![("ydot", Output::vector(&pp.rhs))],
        ),
        function(
            "jacobian",
            "Exact Jacobian d(rhs)/dy, row-major 8x8.",
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
        function(
            "energy",
            "Kinetic energy (59) (J), contact potential (63) (J) and insertion depth of the bottom face (m).",
            &pp,
            vec![
                ("kinetic", Output::scalar(pp.kinetic)),
                ("potential", Output::scalar(pp.potential)),
                ("depth", Output::scalar(pp.depth)),
            ],
        ),
    ];
    Module {
        name: name.to_owned(),
        doc: format!(
            "Compliant planar peg (*Dynamic analysis for peg-in-hole assembly with contact deformation*, (31)-(51), (55)-(64)) with contacts {}. \
             Inputs: state y (see STATE) and parameters p (see P_NAMES). SI units.",
            names.join(", ")
        ),
        functions: fns,
    }
}
