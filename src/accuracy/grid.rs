//! The hard points of each model: where the `f64` evaluation of a
//! generated formula is most likely to lose digits (small clearances, tiny
//! Hertz approaches, angles near 0 or π, zero velocities, loads on the edge
//! of the jamming parallelogram).
//!
//! A point gives a value to every input symbol of its module by name, so a
//! new model needs only a base point and its variations here.

use crate::compliant_peg::{CompliantParams, CompliantSpec, Load};
use crate::generated::{compliant_peg, compliant_peg_elastic};
use crate::rigid_peg::PegParams;

/// One grid point: a label and a value for each symbol name.
#[derive(Clone, Debug, PartialEq)]
pub struct Point {
    /// What the point is (printed where the worst error occurs).
    pub label: String,
    values: Vec<(String, f64)>,
}

impl Point {
    /// A point with the given values.
    pub fn new(label: impl Into<String>, values: &[(&str, f64)]) -> Point {
        Point {
            label: label.into(),
            values: values.iter().map(|&(n, v)| (n.to_owned(), v)).collect(),
        }
    }

    /// The value of symbol `name`.
    pub fn value(&self, name: &str) -> Option<f64> {
        self.values
            .iter()
            .rev()
            .find(|(n, _)| n == name)
            .map(|&(_, v)| v)
    }

    /// This point with `name = value` (added or replaced), label unchanged.
    pub fn with(&self, name: &str, value: f64) -> Point {
        let mut p = self.clone();
        p.values.push((name.to_owned(), value));
        p
    }

    /// This point relabelled.
    pub fn labelled(mut self, label: impl Into<String>) -> Point {
        self.label = label.into();
        self
    }
}

/// Hole diameter of the compliant grid (m).
pub const HOLE_DIAMETER: f64 = 0.05;
/// Radial clearances D − 2r of the compliant grid (m).
pub const CLEARANCES: [f64; 5] = [50e-6, 1e-6, 1e-7, 1e-8, 1e-9];
/// Hertz approaches δ of the compliant grid (m): steel on steel.
pub const APPROACHES: [f64; 5] = [1e-12, 1e-10, 1e-8, 1e-7, 1e-5];
/// Tilts θ of the compliant grid (rad).
pub const TILTS: [f64; 2] = [0.0, 2e-4];

/// The grid of `module`, or `None` if none is defined for it.
pub fn points(module: &str) -> Option<Vec<Point>> {
    match module {
        "pendulum" => Some(angles(
            &[("m", 1.0), ("l", 1.0), ("g", 9.81)],
            &["theta"],
            "thetadot",
        )),
        "double_pendulum" => Some(angles(
            &[
                ("m1", 1.0),
                ("m2", 0.5),
                ("l1", 1.0),
                ("l2", 0.7),
                ("g", 9.81),
                ("theta2", 0.3),
                ("theta2dot", 0.0),
            ],
            &["theta1"],
            "theta1dot",
        )),
        "cart_pole" => Some(angles(
            &[
                ("mc", 1.0),
                ("m", 0.1),
                ("l", 0.5),
                ("g", 9.81),
                ("u", 0.0),
                ("xc", 0.0),
                ("xcdot", 0.0),
            ],
            &["theta"],
            "thetadot",
        )),
        "hertz" => Some(hertz()),
        "compliant_peg" | "compliant_peg_lean" => Some(compliant(&steel_params, &[])),
        "compliant_peg_elastic" => Some(compliant(&steel_params_elastic, &UTILISATIONS)),
        "quasi_static" => Some(quasi_static()),
        "jamming_design" => Some(jamming_design()),
        "chamfer_capture" => Some(chamfer_capture()),
        "compliant_peg_3d" => Some(compliant_peg_3d()),
        "rigid_peg"
        | "rigid_peg_frictionless"
        | "rigid_peg_planar"
        | "rigid_peg_planar_frictionless" => Some(rigid()),
        _ => None,
    }
}

/// Angles near 0 and π and 1.2 rad, rates 0, 1e-12 and 1; accelerations 0.5.
fn angles(base: &[(&str, f64)], angle: &[&str], rate: &str) -> Vec<Point> {
    let base = Point::new("", base);
    let mut out = Vec::new();
    for &a in &[0.0, 1e-8, 1e-4, 0.5, 1.2, std::f64::consts::PI - 1e-7] {
        for &w in &[0.0, 1e-12, 1.0] {
            let mut p = base.with(rate, w);
            for n in angle {
                p = p.with(n, a);
            }
            // Accelerations of `jacobian_terms` (names end in "ddot").
            for n in ["thetaddot", "theta1ddot", "theta2ddot", "xcddot"] {
                p = p.with(n, 0.5);
            }
            out.push(p.labelled(format!("angle={a:e} rate={w:e}")));
        }
    }
    out
}

/// The steel reference peg of `scenes/insert_compliant.toml` with
/// clearance `c` (m) at D = 50 mm: (name, value) of every model parameter.
fn steel_params(clearance: f64) -> Vec<(&'static str, f64)> {
    steel_params_named(
        clearance,
        &compliant_peg::Params::<f64>::NAMES,
        |p, load| p.vector(load).as_slice().to_vec(),
    )
}

/// As [`steel_params`], for the parameters of the elastic (Hertz–Mindlin)
/// friction model.
fn steel_params_elastic(clearance: f64) -> Vec<(&'static str, f64)> {
    let names = compliant_peg_elastic::Params::<f64>::NAMES;
    steel_params_named(clearance, &names, |p, load| {
        p.vector_elastic(load).as_slice().to_vec()
    })
}

/// Tangential utilisations `u = ξ/ξ_max` of the four contacts of the
/// elastic friction model: at rest, half way to sliding, sliding backwards.
const UTILISATIONS: [(&str, [f64; 3]); 4] = [
    ("u_edge_left", [0.0, 0.5, -1.0]),
    ("u_wall_right", [0.0, -0.5, 1.0]),
    ("u_edge_right", [0.0, 0.25, 0.0]),
    ("u_wall_left", [0.0, 0.0, -0.25]),
];

/// (name, value) of `names` for the steel reference peg with clearance `c`:
/// `names` the fields of a generated `Params` in vector order, `vector` the
/// vector of that `Params` (so the pairs match by construction).
fn steel_params_named(
    clearance: f64,
    names: &[&'static str],
    vector: impl Fn(&CompliantParams, &Load) -> Vec<f64>,
) -> Vec<(&'static str, f64)> {
    let spec = CompliantSpec::steel_cylinder(HOLE_DIAMETER, clearance / HOLE_DIAMETER, 0.1, 0.1);
    let load = Load {
        axial: 10.0,
        radial: 1.0,
        torque: 0.01,
    };
    match CompliantParams::try_new(spec) {
        Ok(p) => names
            .iter()
            .zip(vector(&p, &load))
            .map(|(&n, x)| (n, x))
            .collect(),
        Err(_) => Vec::new(),
    }
}

/// Hertz loads from 1e-9 N to 1 kN on the steel edge contact.
fn hertz() -> Vec<Point> {
    let p = steel_params(CLEARANCES[0]);
    let get = |n: &str| {
        p.iter()
            .find(|(k, _)| *k == n)
            .map_or(f64::NAN, |&(_, v)| v)
    };
    let base = Point::new(
        "",
        &[
            ("c_sum", get("edge_sum")),
            ("e_star", get("e_star")),
            ("c_ma", get("edge_ma")),
            ("c_mb", get("edge_mb")),
            ("c_dstar", get("edge_dstar")),
        ],
    );
    [0.0, 1e-9, 1e-6, 1e-3, 1.0, 1e3]
        .iter()
        .map(|&q| base.with("load", q).labelled(format!("load={q:e} N")))
        .collect()
}

/// The compliant peg 10 mm deep, touching the left hole edge with approach
/// δ, for every clearance, approach and tilt; plus zero and tiny rates;
/// with `extra` state components (name, values) taken in turn.
fn compliant(
    params_of: &dyn Fn(f64) -> Vec<(&'static str, f64)>,
    extra: &[(&str, [f64; 3])],
) -> Vec<Point> {
    let mut out = Vec::new();
    for &c in &CLEARANCES {
        let params = params_of(c);
        let base = Point::new("", &params);
        let (Some(r), Some(d), Some(rho_h)) =
            (base.value("r"), base.value("D"), base.value("rho_h"))
        else {
            continue;
        };
        let z = 0.01;
        for &delta in &APPROACHES {
            for &theta in &TILTS {
                // Edge-left penetration r − D/2 − x − sinθ(ρh − z) + (D + 2ρh + 2x) sin²(θ/2) = δ,
                // solved for x (the 2x sin² term neglected: δ is then approximate).
                let s2 = (0.5 * theta).sin().powi(2);
                let x = r - 0.5 * d - delta - theta.sin() * (rho_h - z) + (d + 2.0 * rho_h) * s2;
                for &(rate, label) in &[
                    (0.0, "at rest"),
                    (1e-12, "thetadot=1e-12"),
                    (0.01, "sliding"),
                ] {
                    let p = base
                        .with("x", x)
                        .with("z", z)
                        .with("theta", theta)
                        .with("xdot", 0.0)
                        .with("zdot", if rate == 0.01 { 0.01 } else { 0.0 })
                        .with("thetadot", if rate == 1e-12 { 1e-12 } else { 0.0 })
                        .with("work", 0.0)
                        .with("dissipation", 0.0);
                    let label = format!("clearance={c:e} delta~{delta:e} theta={theta:e} {label}");
                    if extra.is_empty() {
                        out.push(p.labelled(label));
                        continue;
                    }
                    for k in 0..3 {
                        let q = extra
                            .iter()
                            .fold(p.clone(), |q, (name, values)| q.with(name, values[k]));
                        out.push(q.labelled(format!("{label} utilisation set {k}")));
                    }
                }
            }
        }
    }
    out
}

/// The compliant 3-D peg (the Fig. 9 peg, 1 mm fillets): tilts 2e-4, 0.05
/// and 0.3 rad, the centre of mass inside and above the mouth, angles away
/// from the stationary points (where `g′` vanishes and has no relative
/// accuracy to measure), moving with a spin.
fn compliant_peg_3d() -> Vec<Point> {
    use crate::compliant_peg_3d::Peg3dParams;
    use crate::generated::compliant_peg_3d as peg3d;
    use nalgebra::{Unit, UnitQuaternion, Vector3};
    let prm = Peg3dParams::steel(0.04995, 0.070, 0.050, 1e-3, 1e-3, 0.1);
    let pv = prm.vector();
    let named: Vec<(&str, f64)> = peg3d::Params::<f64>::NAMES
        .iter()
        .copied()
        .zip(pv.iter().copied())
        .collect();
    let mut base = Point::new("", &named);
    // Velocities, body rates (with spin), work, dissipation and a contact
    // wrench of a few newtons.
    for (n, v) in [
        ("vx", 0.01),
        ("vy", -0.02),
        ("vz", -0.1),
        ("wx", 1.0),
        ("wy", -2.0),
        ("wz", 5.0),
        ("work", 0.0),
        ("dissipation", 0.0),
        ("Fx", 1.0),
        ("Fy", 2.0),
        ("Fz", -3.0),
        ("Tx", 0.01),
        ("Ty", -0.02),
        ("Tz", 0.005),
        ("Sdot", 0.1),
    ] {
        base = base.with(n, v);
    }
    let mut out = Vec::new();
    for &gamma in &[2e-4, 0.05, 0.3] {
        let tilt = Unit::new_normalize(Vector3::new(-0.6, 0.8, 0.0));
        let q = UnitQuaternion::from_axis_angle(&tilt, gamma)
            * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 0.7);
        for &z in &[-0.02, 0.01] {
            for &angle in &[0.3, 1.9, 4.4] {
                let p = base
                    .with("px", 3.7e-4)
                    .with("py", -2e-4)
                    .with("pz", z)
                    .with("q0", q.w)
                    .with("q1", q.i)
                    .with("q2", q.j)
                    .with("q3", q.k)
                    .with("angle", angle);
                out.push(p.labelled(format!("gamma={gamma:e} z={z:e} angle={angle}")));
            }
        }
    }
    out
}

/// The quasi-static planar peg near the edges of the jamming
/// parallelogram: small tilts and depths, force ratios from 0 to beyond the
/// friction cone.
fn quasi_static() -> Vec<Point> {
    let base = Point::new(
        "",
        &[
            ("mu", 0.3),
            ("r", 0.0125),
            ("l_c", 0.05),
            ("m", 0.1),
            ("J", 1e-4),
            ("xdd", 0.0),
            ("ydd", 0.0),
            ("thdd", 0.0),
        ],
    );
    let mut out = Vec::new();
    for &theta in &[1e-8, 1e-4, 1e-2, 0.1] {
        for &l in &[1e-9, 1e-6, 1e-3, 0.05] {
            for &ratio in &[0.0, 0.3, 1.0 / 0.3, 10.0] {
                let p = base
                    .with("theta", theta)
                    .with("l", l)
                    .with("f1", 1.0)
                    .with("f2", ratio)
                    .with("fx", ratio)
                    .with("fz", 1.0);
                out.push(p.labelled(format!("theta={theta:e} l={l:e} ratio={ratio:.3}")));
            }
        }
    }
    out
}

/// The quasi-static design quantities of a 25 mm peg: clearance ratios
/// 1e-5, 1e-3 and 0.04, friction 0.1, 0.5 and 1, depths 1.1, 2 and 100
/// times the shallowest two-point depth √(D² − d²) (the exact tilt's
/// square root loses digits as l → l_min), each where the exact wedging
/// angle exists with a margin ((1 − c)² (1 + μ²) ≥ 1.01; at 1 its
/// derivative is unbounded).
fn jamming_design() -> Vec<Point> {
    let (r, d) = (0.0125, 0.025);
    let mut out = Vec::new();
    for &c in &[1e-5, 1e-3, 0.04] {
        for &mu in &[0.1, 0.5, 1.0] {
            if (1.0f64 - c).powi(2) * (1.0 + mu * mu) < 1.01 {
                continue;
            }
            let big_d = d / (1.0 - c);
            let l_min = ((big_d - d) * (big_d + d)).sqrt();
            for &k in &[1.1, 2.0, 100.0] {
                let p = Point::new(
                    format!("c={c:e} mu={mu} l={k} l_min"),
                    &[("r", r), ("c", c), ("mu", mu), ("l", k * l_min)],
                );
                out.push(p);
            }
        }
    }
    out
}

/// The chamfer's capture widths: a 25 mm bore, radial clearances 50 µm
/// and 1 µm, fillets from 0.1 to 2 mm, friction 0, 1e-6, 0.2 and 1.
fn chamfer_capture() -> Vec<Point> {
    let mut out = Vec::new();
    for &gap in &[50e-6, 1e-6] {
        for &(rho_p, rho_h) in &[(1e-4, 5e-4), (3e-4, 2e-3)] {
            for &mu in &[0.0, 1e-6, 0.2, 1.0] {
                out.push(Point::new(
                    format!("gap={gap:e} rho_p={rho_p:e} rho_h={rho_h:e} mu={mu}"),
                    &[
                        ("r_peg", 0.0125 - gap),
                        ("r_bore", 0.0125),
                        ("rho_p", rho_p),
                        ("rho_h", rho_h),
                        ("mu", mu),
                    ],
                ));
            }
        }
    }
    out
}

/// The rigid three-point peg (Fig. 9 dimensions, D = 50 mm) for
/// clearances 50 µm, 1 µm and 1 nm: γ = γ0(1 + ε) for ε = 1e-3, 1e-6,
/// 1e-9, 1e-12 and γ = 0.3, 1.2 rad; ψ̇ = 0, 1e-12 and 1 rad/s (reactions
/// 2, 1, 1 N where a parameter Jacobian takes them); γ0 given
/// by [`PegParams::gamma0`], `2 asin(√((D − d)/(2D)))` rounded to `f64`.
fn rigid() -> Vec<Point> {
    let mut out = Vec::new();
    for &c in &[50e-6f64, 1e-6, 1e-9] {
        let (dh, dp) = (0.05, 0.05 - c);
        let gamma0 = PegParams {
            hole_diameter: dh,
            peg_diameter: dp,
            height: 0.07,
            mass: 1.0,
            gravity: 9.81,
            friction: 0.2,
        }
        .gamma0();
        let base = Point::new(
            "",
            &[
                ("D_hole", dh),
                ("d_peg", dp),
                ("H", 0.07),
                ("m", 1.0),
                ("g", 9.81),
                ("f", 0.2),
                ("gamma0", gamma0),
                ("psi", 0.4),
                ("gammadot", 0.1),
                ("M_gamma", 0.01),
                ("M_psi", 0.0),
                ("F_x", 0.0),
                ("F_y", 0.0),
                ("F_z", -1.0),
                ("gammaddot", 0.5),
                ("psiddot", 0.5),
                ("N_K", 2.0),
                ("N_B1", 1.0),
                ("N_B2", 1.0),
            ],
        );
        let mut with_t = base.clone();
        for (n, v) in [
            ("t_K_eta", 0.6),
            ("t_K_n", 0.8),
            ("t_K_z", 0.0),
            ("t_B1_eta", 0.0),
            ("t_B1_n", 0.6),
            ("t_B1_z", -0.8),
            ("t_B2_eta", 0.0),
            ("t_B2_n", -0.6),
            ("t_B2_z", -0.8),
            ("t_B_eta", 0.6),
            ("t_B_z", -0.8),
        ] {
            with_t = with_t.with(n, v);
        }
        let gammas = [1e-3, 1e-6, 1e-9, 1e-12]
            .map(|e| (gamma0 * (1.0 + e), format!("gamma=gamma0(1+{e:e})")))
            .into_iter()
            .chain([(0.3, "gamma=0.3".to_owned()), (1.2, "gamma=1.2".to_owned())]);
        for (gamma, glabel) in gammas {
            for &psidot in &[0.0, 1e-12, 1.0] {
                let p = with_t.with("gamma", gamma).with("psidot", psidot);
                out.push(p.labelled(format!("clearance={c:e} {glabel} psidot={psidot:e}")));
            }
        }
    }
    out
}
