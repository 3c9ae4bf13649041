//! Integrates the spherical pendulum over its floor for 5 s and prints the
//! energy and angular-momentum drift and the floor contacts.

use own_model::generated::spherical_pendulum as sp;
use own_model::{initial_state, parameters};
use pegdyn::integrate::{Event, Method, Options, Solver};

fn main() {
    let system = sp::System::new(parameters());
    let p = system.p; // the parameter vector the generated functions take
    let x0 = initial_state();
    // An event when the bob touches the floor (penetration crosses zero).
    let touch = Event::new(move |_t, x| sp::penetration(x, &p));
    let mut solver =
        Solver::new(Method::Rodas3, Options::with_tolerances(1e-8, 1e-11)).with_event(touch);
    let sol = match solver.solve(&system, 0.0, x0, 5.0) {
        Ok(sol) => sol,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(1);
        }
    };
    let Some(x1) = sol.x.last() else {
        eprintln!("error: empty solution");
        std::process::exit(1);
    };
    let (e0, e1) = (sp::energy(&x0, &p), sp::energy(x1, &p));
    let (l0, l1) = (sp::angular_momentum(&x0, &p), sp::angular_momentum(x1, &p));
    println!(
        "steps {}, jacobians {}",
        sol.stats.steps, sol.stats.jacobian_calls
    );
    println!("floor crossings: {}", sol.events.len());
    println!("energy     {e0:.9} J -> {e1:.9} J");
    println!("L_z        {l0:.9} -> {l1:.9} kg m^2/s");
    println!(
        "theta, phi at t = 5 s: {:.6}, {:.6} rad",
        x1[sp::X_THETA],
        x1[sp::X_PHI]
    );
}
