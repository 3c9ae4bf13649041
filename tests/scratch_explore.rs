use nalgebra::{Vector2, Vector4};
use pegdyn::integrate::{Method, Options};
use pegdyn::rigid::forward::ForwardModel;
use pegdyn::rigid::stick::start_from_rest;
use pegdyn::rigid::trajectory::simulate;
use pegdyn::rigid::{Loads, PegParams};

#[test]
fn explore() {
    let o = Options::with_tolerances(1e-10, 1e-12);
    for (f, mg, fz, g, gd, pd) in [
        (0.0, -0.02, -20.0, 0.06, -0.2, 0.0),
        (0.2, -0.05, -20.0, 0.06, -0.2, 0.0),
        (0.0, 0.0, -50.0, 0.06, -0.5, 0.0),
        (0.0, -0.02, -20.0, 0.06, -0.2, 1.0),
        (0.2, -0.2, -50.0, 0.06, -0.2, 1.0),
    ] {
        let p = PegParams {
            friction: f,
            ..PegParams::fig9()
        };
        let m = ForwardModel::new(
            p,
            Loads {
                m_gamma: mg,
                force: [0.0, 0.0, fz],
                ..Loads::default()
            },
        )
        .unwrap();
        let tr = simulate(
            &m,
            Vector4::new(g, 0.0, gd, pd),
            0.0,
            1.0,
            Method::Dopri5,
            &o,
        )
        .unwrap();
        println!(
            "f {f} mg {mg} fz {fz} g {g} gd {gd} pd {pd}: {} rows {} restarts {}",
            tr.stop,
            tr.rows.len(),
            tr.restarts.len()
        );
    }
    let p = PegParams::fig9();
    for (mg, mp) in [
        (0.0, 0.0),
        (0.0, 0.02),
        (0.0, 0.2),
        (0.0, 1.0),
        (0.3, 0.0),
        (1.0, 0.0),
        (-0.1, 0.0),
        (-0.3, 0.0),
        (-1.0, 0.0),
        (0.2, 0.5),
    ] {
        let m = ForwardModel::new(
            p,
            Loads {
                m_gamma: mg,
                m_psi: mp,
                ..Loads::default()
            },
        )
        .unwrap();
        let r = start_from_rest(&m, Vector2::new(0.3, 0.0)).unwrap();
        println!("rest mg {mg} mp {mp}: {r:?}");
    }
}
