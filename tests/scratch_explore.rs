use nalgebra::{Vector2, Vector4};
use pegdyn::integrate::{Method, Options};
use pegdyn::rigid::forward::ForwardModel;
use pegdyn::rigid::modes::classify;
use pegdyn::rigid::trajectory::simulate;
use pegdyn::rigid::{Loads, PegParams};
#[test]
fn scan() {
    let p = PegParams::fig9();
    let m = ForwardModel::new(
        p,
        Loads {
            m_gamma: 0.3,
            ..Loads::default()
        },
    )
    .unwrap();
    let tr = simulate(
        &m,
        Vector4::new(0.05, 0.0, 0.5, 3.0),
        0.0,
        0.5,
        Method::Dopri5,
        &Options::with_tolerances(1e-10, 1e-12),
    )
    .unwrap();
    for r in tr.rows.iter().rev().take(12) {
        println!(
            "t {:.10e} x {:.6?} N {:.4e} det {:.3e}",
            r.t,
            r.x.as_slice(),
            r.normal[0],
            m.contact_determinant(&r.x, None)
        );
    }
    // fig9 psidot 0 state with driving moment
    let q = Vector2::new(p.gamma0() * (1.0 + 1e-6), 0.0);
    let qd = Vector2::new(-2.0, 0.0);
    let r = pegdyn::rigid::prescribed::reactions(&p, &Loads::default(), q, qd, Vector2::zeros())
        .unwrap();
    let d = ForwardModel::new(
        p,
        Loads {
            m_gamma: r.m_gamma,
            m_psi: r.m_psi,
            ..Loads::default()
        },
    )
    .unwrap();
    println!(
        "fig9 psidot0: det {:e} {:?}",
        d.contact_determinant(&Vector4::new(q[0], 0.0, -2.0, 0.0), None),
        classify(&d, q, qd)
    );
    for rel in [1e-6, 1e-3, 0.01, 0.05, 0.06] {
        let q = Vector2::new(p.gamma0() * (1.0 + rel), 0.0);
        let qd = Vector2::new(-2.0, 10.0);
        let r =
            pegdyn::rigid::prescribed::reactions(&p, &Loads::default(), q, qd, Vector2::zeros())
                .unwrap();
        let d = ForwardModel::new(
            p,
            Loads {
                m_gamma: r.m_gamma,
                m_psi: r.m_psi,
                ..Loads::default()
            },
        )
        .unwrap();
        println!(
            "fig9 psidot10 rel {rel}: det {:e} {}",
            d.contact_determinant(&Vector4::new(q[0], 0.0, -2.0, 10.0), None),
            format!("{:?}", classify(&d, q, qd))
                .chars()
                .take(100)
                .collect::<String>()
        );
    }
}
