// @generated readable copy of `pegdyn::generated::rigid_peg` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generator snapshot::

/// Rigid three-point peg leaning on the hole edge at K, B1, B2 (*Peg-on-hole: fundamental principles of motion of a peg leaning on a horizontal hole edge*), variant `Full`, derived by the generator (equations/src/models/rigid_peg.rs).
/// State x = (`gamma`, `psi`, `gammadot`, `psidot`); parameters p = (D_hole, d_peg, H, m, g, f, gamma0); loads = (`M_gamma`, `M_psi`, `F_x`, `F_y`, `F_z`); friction directions t = (`t_K_eta`, `t_K_n`, `t_K_z`, `t_B1_eta`, `t_B1_n`, `t_B1_z`, `t_B2_eta`, `t_B2_n`, `t_B2_z`) (unit, force on the peg).
/// Vectors in rotating components (e_η, e_n, e_z). SI units.
pub mod rigid_peg {
    use nalgebra::{Matrix3, Matrix5, SMatrix, SVector, Vector5};
    use pegdyn::scalar::Real;
    /// Symbol names of the components of `x`, in order.
    pub const X_NAMES: [&str; 4] = ["gamma", "psi", "gammadot", "psidot"];
    /// Symbol names of the components of `p`, in order.
    pub const P_NAMES: [&str; 7] = ["D_hole", "d_peg", "H", "m", "g", "f", "gamma0"];
    /// Symbol names of the components of `loads`, in order.
    pub const LOADS_NAMES: [&str; 5] = ["M_gamma", "M_psi", "F_x", "F_y", "F_z"];
    /// Symbol names of the components of `t`, in order.
    pub const T_NAMES: [&str; 9] = [
        "t_K_eta",
        "t_K_n",
        "t_K_z",
        "t_B1_eta",
        "t_B1_n",
        "t_B1_z",
        "t_B2_eta",
        "t_B2_n",
        "t_B2_z",
    ];
    /// Symbol names of the components of `qdd`, in order.
    pub const QDD_NAMES: [&str; 2] = ["gammaddot", "psiddot"];
    /// Symbol names of the components of `u`, in order.
    pub const U_NAMES: [&str; 5] = ["gammaddot", "psiddot", "N_K", "N_B1", "N_B2"];
    /// The parameters of `rigid_peg`: the input `p` of its functions as a struct, one field per component in vector order (`From`/`Into` convert both ways).
    #[derive(Clone, Copy, Debug, PartialEq)]
    #[allow(non_snake_case)]
    pub struct Params<T> {
        /// Hole diameter D, m.
        pub D_hole: T,
        /// Peg diameter d, m.
        pub d_peg: T,
        /// Peg height H, m.
        pub H: T,
        /// Mass m of the peg, kg.
        pub m: T,
        /// Gravitational acceleration g (along −z), m/s².
        pub g: T,
        /// Coulomb friction coefficient f, dimensionless.
        pub f: T,
        /// Γ0 = arccos(d/D), the tilt where the three-point contact begins (consistent with D and d), rad.
        pub gamma0: T,
    }
    impl<T> Params<T> {
        /// The field names in vector order: the symbol names of `p` ([`P_NAMES`]).
        pub const NAMES: [&'static str; 7] = P_NAMES;
    }
    impl<T: Real> From<Params<T>> for SVector<T, 7> {
        /// The `p` vector of these values, in field order.
        fn from(v: Params<T>) -> SVector<T, 7> {
            SVector::from([v.D_hole, v.d_peg, v.H, v.m, v.g, v.f, v.gamma0])
        }
    }
    impl<T: Real> From<&SVector<T, 7>> for Params<T> {
        /// The fields of a `p` vector, in field order.
        fn from(v: &SVector<T, 7>) -> Params<T> {
            Params {
                D_hole: v[0],
                d_peg: v[1],
                H: v[2],
                m: v[3],
                g: v[4],
                f: v[5],
                gamma0: v[6],
            }
        }
    }
    impl<T: Real> From<SVector<T, 7>> for Params<T> {
        /// The fields of a `p` vector, in field order.
        fn from(v: SVector<T, 7>) -> Params<T> {
            Params::from(&v)
        }
    }
    /// The state x = (γ, ψ, γ̇, ψ̇).
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct State<T> {
        /// Nutation angle γ between the peg's axis and the hole's axis, rad.
        pub gamma: T,
        /// Precession angle ψ of the symmetry plane about the hole's axis, rad.
        pub psi: T,
        /// Nutation rate γ̇, rad/s.
        pub gammadot: T,
        /// Precession rate ψ̇, rad/s.
        pub psidot: T,
    }
    impl<T> State<T> {
        /// The field names in vector order: the symbol names of `x` ([`X_NAMES`]).
        pub const NAMES: [&'static str; 4] = X_NAMES;
    }
    impl<T: Real> From<State<T>> for SVector<T, 4> {
        /// The `x` vector of these values, in field order.
        fn from(v: State<T>) -> SVector<T, 4> {
            SVector::from([v.gamma, v.psi, v.gammadot, v.psidot])
        }
    }
    impl<T: Real> From<&SVector<T, 4>> for State<T> {
        /// The fields of a `x` vector, in field order.
        fn from(v: &SVector<T, 4>) -> State<T> {
            State {
                gamma: v[0],
                psi: v[1],
                gammadot: v[2],
                psidot: v[3],
            }
        }
    }
    impl<T: Real> From<SVector<T, 4>> for State<T> {
        /// The fields of a `x` vector, in field order.
        fn from(v: SVector<T, 4>) -> State<T> {
            State::from(&v)
        }
    }
    /// The applied loads: the moments conjugate to γ and ψ and the assembly force at the centre of mass in fixed-frame components.
    #[derive(Clone, Copy, Debug, PartialEq)]
    #[allow(non_snake_case)]
    pub struct Loads<T> {
        /// Generalized moment M_γ conjugate to γ, N·m.
        pub M_gamma: T,
        /// Moment M_ψ about the hole's axis, conjugate to ψ, N·m.
        pub M_psi: T,
        /// Assembly force at the centre of mass, fixed-frame x component, N.
        pub F_x: T,
        /// Assembly force at the centre of mass, fixed-frame y component, N.
        pub F_y: T,
        /// Assembly force at the centre of mass, fixed-frame z component, N.
        pub F_z: T,
    }
    impl<T> Loads<T> {
        /// The field names in vector order: the symbol names of `loads` ([`LOADS_NAMES`]).
        pub const NAMES: [&'static str; 5] = LOADS_NAMES;
    }
    impl<T: Real> From<Loads<T>> for SVector<T, 5> {
        /// The `loads` vector of these values, in field order.
        fn from(v: Loads<T>) -> SVector<T, 5> {
            SVector::from([v.M_gamma, v.M_psi, v.F_x, v.F_y, v.F_z])
        }
    }
    impl<T: Real> From<&SVector<T, 5>> for Loads<T> {
        /// The fields of a `loads` vector, in field order.
        fn from(v: &SVector<T, 5>) -> Loads<T> {
            Loads {
                M_gamma: v[0],
                M_psi: v[1],
                F_x: v[2],
                F_y: v[3],
                F_z: v[4],
            }
        }
    }
    impl<T: Real> From<SVector<T, 5>> for Loads<T> {
        /// The fields of a `loads` vector, in field order.
        fn from(v: SVector<T, 5>) -> Loads<T> {
            Loads::from(&v)
        }
    }
    /// The friction direction at each contact (unit or shorter, force on the peg) in rotating components (e_η, e_n, e_z).
    #[derive(Clone, Copy, Debug, PartialEq)]
    #[allow(non_snake_case)]
    pub struct FrictionDirections<T> {
        /// Friction direction at K, e_η component (unit or shorter, force on the peg), dimensionless.
        pub t_K_eta: T,
        /// Friction direction at K, e_n component (unit or shorter, force on the peg), dimensionless.
        pub t_K_n: T,
        /// Friction direction at K, e_z component (unit or shorter, force on the peg), dimensionless.
        pub t_K_z: T,
        /// Friction direction at B1, e_η component (unit or shorter, force on the peg), dimensionless.
        pub t_B1_eta: T,
        /// Friction direction at B1, e_n component (unit or shorter, force on the peg), dimensionless.
        pub t_B1_n: T,
        /// Friction direction at B1, e_z component (unit or shorter, force on the peg), dimensionless.
        pub t_B1_z: T,
        /// Friction direction at B2, e_η component (unit or shorter, force on the peg), dimensionless.
        pub t_B2_eta: T,
        /// Friction direction at B2, e_n component (unit or shorter, force on the peg), dimensionless.
        pub t_B2_n: T,
        /// Friction direction at B2, e_z component (unit or shorter, force on the peg), dimensionless.
        pub t_B2_z: T,
    }
    impl<T> FrictionDirections<T> {
        /// The field names in vector order: the symbol names of `t` ([`T_NAMES`]).
        pub const NAMES: [&'static str; 9] = T_NAMES;
    }
    impl<T: Real> From<FrictionDirections<T>> for SVector<T, 9> {
        /// The `t` vector of these values, in field order.
        fn from(v: FrictionDirections<T>) -> SVector<T, 9> {
            SVector::from([
                v.t_K_eta,
                v.t_K_n,
                v.t_K_z,
                v.t_B1_eta,
                v.t_B1_n,
                v.t_B1_z,
                v.t_B2_eta,
                v.t_B2_n,
                v.t_B2_z,
            ])
        }
    }
    impl<T: Real> From<&SVector<T, 9>> for FrictionDirections<T> {
        /// The fields of a `t` vector, in field order.
        fn from(v: &SVector<T, 9>) -> FrictionDirections<T> {
            FrictionDirections {
                t_K_eta: v[0],
                t_K_n: v[1],
                t_K_z: v[2],
                t_B1_eta: v[3],
                t_B1_n: v[4],
                t_B1_z: v[5],
                t_B2_eta: v[6],
                t_B2_n: v[7],
                t_B2_z: v[8],
            }
        }
    }
    impl<T: Real> From<SVector<T, 9>> for FrictionDirections<T> {
        /// The fields of a `t` vector, in field order.
        fn from(v: SVector<T, 9>) -> FrictionDirections<T> {
            FrictionDirections::from(&v)
        }
    }
    /// A linear system A u = b for the unknowns u (see the function returning it).
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct LinearSystem<T: Real> {
        /// The matrix A = ∂R/∂u.
        pub a: SMatrix<T, 5, 5>,
        /// The right-hand side b = −R at u = 0.
        pub b: SVector<T, 5>,
    }
    /// Forward dynamics (replaces paper (24)–(31)): A u = b for u = (`gammaddot`, `psiddot`, `N_K`, `N_B1`, `N_B2`) (rad/s², N), the applied loads and friction directions given.
    /// Rows: the Lagrange equations of γ and ψ (paper (26), (27)), then the centre-of-mass equations (28)–(31) along e_η, e_n, e_z (the fixed-frame (29)–(31) rotated by −ψ).
    /// A = ∂R/∂u, b = −R at u = 0, R the residual derived from T, V and the generalized forces.
    ///
    /// # Inputs
    /// - `x` = (`gamma`, `psi`, `gammadot`, `psidot`)
    /// - `p` = (`D_hole`, `d_peg`, `H`, `m`, `g`, `f`, `gamma0`)
    /// - `loads` = (`M_gamma`, `M_psi`, `F_x`, `F_y`, `F_z`)
    /// - `t` = (`t_K_eta`, `t_K_n`, `t_K_z`, `t_B1_eta`, `t_B1_n`, `t_B1_z`, `t_B2_eta`, `t_B2_n`, `t_B2_z`)
    ///
    /// # Outputs
    /// The fields of [`LinearSystem`]:
    /// - `a`: 5×5 matrix
    /// - `b`: vector of 5
    ///
    /// # Cost
    /// 73 add/sub, 147 mul, 3 div, 1 sqrt, 6 transcendental, 0 branches; 64 `let`s.
    #[inline]
    pub fn forward<T: Real>(
        x: &SVector<T, 4>,
        p: &SVector<T, 7>,
        loads: &SVector<T, 5>,
        t: &SVector<T, 9>,
    ) -> LinearSystem<T> {
        let gamma = x[0];
        let psi = x[1];
        let gammadot = x[2];
        let psidot = x[3];
        let d_hole = p[0];
        let d_peg = p[1];
        let h = p[2];
        let m = p[3];
        let g = p[4];
        let f = p[5];
        let gamma0 = p[6];
        let m_gamma = loads[0];
        let m_psi = loads[1];
        let f_x = loads[2];
        let f_y = loads[3];
        let f_z = loads[4];
        let t_k_eta = t[0];
        let t_k_n = t[1];
        let t_k_z = t[2];
        let t_b1_eta = t[3];
        let t_b1_n = t[4];
        let t_b1_z = t[5];
        let t_b2_eta = t[6];
        let t_b2_n = t[7];
        let t_b2_z = t[8];
        let (sin_gamma, cos_gamma) = gamma.sin_cos();
        let half_gamma0 = T::from_f64(0.5) * gamma0;
        let half_gamma = T::from_f64(0.5) * gamma;
        let sin_sum = (half_gamma0 + half_gamma).sin();
        let (sin_half_gamma, cos_half_gamma) = half_gamma.sin_cos();
        let t0 = sin_half_gamma * sin_half_gamma;
        let e = d_hole - d_peg + T::from_f64(2.0) * d_peg * t0;
        let t1 = T::from_f64(1.0) / sin_gamma;
        let twice_a2 = e * t1;
        let t2 = sin_gamma * sin_gamma;
        let half_d = T::from_f64(0.5) * d_hole;
        let t3 = cos_gamma * cos_gamma;
        let t4 = gammadot * gammadot;
        let t5 = psidot * psidot;
        let t6 = d_peg * d_peg;
        let t7 = T::from_f64(0.75) * t6 + h * h;
        let (sin_psi, cos_psi) = psi.sin_cos();
        let t8 = f_x * cos_psi;
        let t9 = f_y * sin_psi;
        let t10 = f_x * sin_psi;
        let t11 = sin_gamma * cos_gamma;
        let t12 = -f_y * cos_psi;
        let t13 = f * t_k_n;
        let t14 = t3 / (sin_gamma * sin_gamma * sin_gamma);
        let half_e = T::from_f64(0.5) * e;
        let t15 = T::from_f64(1.0 / 12.0) * t7;
        let lever = T::from_f64(0.5) * h - T::from_f64(0.5) * twice_a2;
        let t16 = d_peg * sin_half_gamma * cos_half_gamma;
        let t17 = t16 * t1;
        let t18 = sin_gamma * lever;
        let twice_lever = h - twice_a2;
        let t19 = twice_lever * twice_lever;
        let t20 = m * gammadot * psidot;
        let t21 = t1 * t1;
        let t22 = cos_gamma * t21;
        let t23 = t22 * e;
        let t24 = t17 - T::from_f64(0.5) * t23;
        let t25 = sin_gamma * t24;
        let t26 = T::from_f64(0.25)
            * (t2 * (T::from_f64(2.0) * h - T::from_f64(2.0) * twice_a2)
                * (T::from_f64(2.0) * t17 - t23));
        let t27 = t25 - cos_gamma * lever;
        let t28 = lever
            + t1
                * (half_e
                    - T::from_f64(0.5)
                        * (d_peg * (t0 - cos_half_gamma * cos_half_gamma))) + t14 * e
            - T::from_f64(2.0) * t16 * t22;
        let t29 = sin_gamma * t28 + T::from_f64(2.0) * cos_gamma * t24;
        let t30 = t27 * t29;
        let sin_diff = (half_gamma0 - half_gamma).sin();
        let t31 = sin_sum * sin_diff;
        let neg_half_delta = t31 * d_hole;
        let neg_a1 = neg_half_delta * t1;
        let ob = neg_a1.hypot(half_d);
        let t32 = T::from_f64(1.0) / ob;
        let t33 = neg_a1 * t32;
        let s1 = t1 * (half_e + neg_half_delta * cos_gamma) * t1;
        let t34 = -s1 * t32;
        let neg_half_gap = neg_half_delta * t22;
        let bb1 = (-T::from_f64(2.0) * neg_half_gap
            * (d_hole + T::from_f64(2.0) * neg_half_gap))
            .sqrt();
        let t35 = bb1 * t32;
        let t36 = cos_gamma * (neg_half_delta * t21 - t24);
        let t37 = half_d + t36 - t18;
        let t38 = d_hole
            * (t31 * (t1 + T::from_f64(2.0) * t14) + T::from_f64(0.5) * cos_gamma * t1)
            + cos_gamma * t28 - T::from_f64(2.0) * t25;
        let t39 = (d_hole + T::from_f64(2.0) * t36 - T::from_f64(2.0) * t18) * t38;
        let t40 = t25 - neg_a1;
        let twice_s1 = half_d + t36 + s1;
        LinearSystem {
            a: Matrix5::new(
                m * (t15 + t27 * t27 + t37 * t37),
                T::from_f64(0.0),
                -(f * (t_k_eta * t40 + t36 * t_k_z)),
                -(f * (t_b1_eta * t40 + t_b1_z * twice_s1)),
                -(f * (t_b2_eta * t40 + t_b2_z * twice_s1)),
                T::from_f64(0.0),
                m
                    * (t2 * (T::from_f64(0.25) * t19 + t15)
                        + T::from_f64(0.125) * t3 * t6),
                T::from_f64(0.5) * t13 * d_hole,
                f * (t_b1_eta * bb1 - s1 * t_b1_n),
                -(f * (t_b2_eta * bb1 + s1 * t_b2_n)),
                m * t27,
                T::from_f64(0.0),
                -(f * t_k_eta) - cos_gamma,
                -(f * t_b1_eta) - t34,
                -(f * t_b2_eta) - t34,
                T::from_f64(0.0),
                -t18 * m,
                -t13,
                t35 - f * t_b1_n,
                -(f * t_b2_n) - t35,
                m * t37,
                T::from_f64(0.0),
                -(f * t_k_z) - sin_gamma,
                t33 - f * t_b1_z,
                t33 - f * t_b2_z,
            ),
            b: Vector5::new(
                m_gamma
                    - m
                        * (-(t5 * (t15 - T::from_f64(0.125) * t6) * t11)
                            + T::from_f64(0.5)
                                * (t4 * (T::from_f64(4.0) * t30 - T::from_f64(2.0) * t39)
                                    - (t4 * (T::from_f64(2.0) * t30 - t39)
                                        + t5 * (T::from_f64(0.5) * t11 * t19 - t26))) + g * t37)
                    + t27 * (t8 + t9) + f_z * t37,
                m_psi + t18 * (t12 + t10)
                    + t20
                        * (t26
                            - t11
                                * (T::from_f64(0.5) * t19 - T::from_f64(0.25) * t6
                                    + T::from_f64(1.0 / 6.0) * t7)),
                t8 + t9 - m * (t29 * t4 + t18 * t5),
                -t12 - t10 - T::from_f64(2.0) * t20 * t27,
                f_z - m * g + m * t4 * t38,
            ),
        }
    }
    /// Prescribed motion (paper (26)–(31), Fig. 9): A u = b for u = (`M_gamma`, `M_psi`, `N_K`, `N_B1`, `N_B2`) (N·m, N) given q̈ (the moment components of `loads` are unused: they are the unknowns).
    /// Rows: the Lagrange equations of γ and ψ (paper (26), (27)), then the centre-of-mass equations (28)–(31) along e_η, e_n, e_z (the fixed-frame (29)–(31) rotated by −ψ).
    ///
    /// # Inputs
    /// - `x` = (`gamma`, `psi`, `gammadot`, `psidot`)
    /// - `qdd` = (`gammaddot`, `psiddot`)
    /// - `p` = (`D_hole`, `d_peg`, `H`, `m`, `g`, `f`, `gamma0`)
    /// - `loads` = (`M_gamma`, `M_psi`, `F_x`, `F_y`, `F_z`)
    /// - `t` = (`t_K_eta`, `t_K_n`, `t_K_z`, `t_B1_eta`, `t_B1_n`, `t_B1_z`, `t_B2_eta`, `t_B2_n`, `t_B2_z`)
    ///
    /// # Outputs
    /// The fields of [`LinearSystem`]:
    /// - `a`: 5×5 matrix
    /// - `b`: vector of 5
    ///
    /// # Cost
    /// 76 add/sub, 148 mul, 3 div, 1 sqrt, 6 transcendental, 0 branches; 64 `let`s.
    #[inline]
    pub fn prescribed<T: Real>(
        x: &SVector<T, 4>,
        qdd: &SVector<T, 2>,
        p: &SVector<T, 7>,
        loads: &SVector<T, 5>,
        t: &SVector<T, 9>,
    ) -> LinearSystem<T> {
        let gamma = x[0];
        let psi = x[1];
        let gammadot = x[2];
        let psidot = x[3];
        let gammaddot = qdd[0];
        let psiddot = qdd[1];
        let d_hole = p[0];
        let d_peg = p[1];
        let h = p[2];
        let m = p[3];
        let g = p[4];
        let f = p[5];
        let gamma0 = p[6];
        let f_x = loads[2];
        let f_y = loads[3];
        let f_z = loads[4];
        let t_k_eta = t[0];
        let t_k_n = t[1];
        let t_k_z = t[2];
        let t_b1_eta = t[3];
        let t_b1_n = t[4];
        let t_b1_z = t[5];
        let t_b2_eta = t[6];
        let t_b2_n = t[7];
        let t_b2_z = t[8];
        let (sin_gamma, cos_gamma) = gamma.sin_cos();
        let half_gamma0 = T::from_f64(0.5) * gamma0;
        let half_gamma = T::from_f64(0.5) * gamma;
        let sin_sum = (half_gamma0 + half_gamma).sin();
        let (sin_half_gamma, cos_half_gamma) = half_gamma.sin_cos();
        let t0 = sin_half_gamma * sin_half_gamma;
        let e = d_hole - d_peg + T::from_f64(2.0) * d_peg * t0;
        let t1 = T::from_f64(1.0) / sin_gamma;
        let twice_a2 = e * t1;
        let t2 = sin_gamma * sin_gamma;
        let half_d = T::from_f64(0.5) * d_hole;
        let t3 = cos_gamma * cos_gamma;
        let t4 = gammadot * gammadot;
        let t5 = psidot * psidot;
        let t6 = d_peg * d_peg;
        let t7 = T::from_f64(0.75) * t6 + h * h;
        let (sin_psi, cos_psi) = psi.sin_cos();
        let t8 = f_x * cos_psi;
        let t9 = f_y * sin_psi;
        let t10 = f_x * sin_psi;
        let t11 = sin_gamma * cos_gamma;
        let t12 = -f_y * cos_psi;
        let t13 = f * t_k_n;
        let t14 = t3 / (sin_gamma * sin_gamma * sin_gamma);
        let half_e = T::from_f64(0.5) * e;
        let t15 = T::from_f64(1.0 / 12.0) * t7;
        let lever = T::from_f64(0.5) * h - T::from_f64(0.5) * twice_a2;
        let t16 = d_peg * sin_half_gamma * cos_half_gamma;
        let t17 = t16 * t1;
        let t18 = sin_gamma * lever;
        let twice_lever = h - twice_a2;
        let t19 = twice_lever * twice_lever;
        let t20 = t1 * t1;
        let t21 = cos_gamma * t20;
        let t22 = t21 * e;
        let t23 = t17 - T::from_f64(0.5) * t22;
        let t24 = sin_gamma * t23;
        let t25 = T::from_f64(0.25)
            * (t2 * (T::from_f64(2.0) * h - T::from_f64(2.0) * twice_a2)
                * (T::from_f64(2.0) * t17 - t22));
        let t26 = t24 - cos_gamma * lever;
        let t27 = lever
            + t1
                * (half_e
                    - T::from_f64(0.5)
                        * (d_peg * (t0 - cos_half_gamma * cos_half_gamma))) + t14 * e
            - T::from_f64(2.0) * t16 * t21;
        let t28 = sin_gamma * t27 + T::from_f64(2.0) * cos_gamma * t23;
        let t29 = t26 * t28;
        let sin_diff = (half_gamma0 - half_gamma).sin();
        let t30 = sin_sum * sin_diff;
        let neg_half_delta = t30 * d_hole;
        let neg_a1 = neg_half_delta * t1;
        let ob = neg_a1.hypot(half_d);
        let t31 = T::from_f64(1.0) / ob;
        let t32 = neg_a1 * t31;
        let s1 = t1 * (half_e + neg_half_delta * cos_gamma) * t1;
        let t33 = -s1 * t31;
        let neg_half_gap = neg_half_delta * t21;
        let bb1 = (-T::from_f64(2.0) * neg_half_gap
            * (d_hole + T::from_f64(2.0) * neg_half_gap))
            .sqrt();
        let t34 = bb1 * t31;
        let t35 = cos_gamma * (neg_half_delta * t20 - t23);
        let t36 = half_d + t35 - t18;
        let t37 = d_hole
            * (t30 * (t1 + T::from_f64(2.0) * t14) + T::from_f64(0.5) * cos_gamma * t1)
            + cos_gamma * t27 - T::from_f64(2.0) * t24;
        let t38 = (d_hole + T::from_f64(2.0) * t35 - T::from_f64(2.0) * t18) * t37;
        let t39 = t24 - neg_a1;
        let twice_s1 = half_d + t35 + s1;
        let t40 = gammadot * psidot;
        LinearSystem {
            a: Matrix5::new(
                -T::from_f64(1.0),
                T::from_f64(0.0),
                -(f * (t_k_eta * t39 + t35 * t_k_z)),
                -(f * (t_b1_eta * t39 + t_b1_z * twice_s1)),
                -(f * (t_b2_eta * t39 + t_b2_z * twice_s1)),
                T::from_f64(0.0),
                -T::from_f64(1.0),
                T::from_f64(0.5) * t13 * d_hole,
                f * (t_b1_eta * bb1 - s1 * t_b1_n),
                -(f * (t_b2_eta * bb1 + s1 * t_b2_n)),
                T::from_f64(0.0),
                T::from_f64(0.0),
                -(f * t_k_eta) - cos_gamma,
                -(f * t_b1_eta) - t33,
                -(f * t_b2_eta) - t33,
                T::from_f64(0.0),
                T::from_f64(0.0),
                -t13,
                t34 - f * t_b1_n,
                -(f * t_b2_n) - t34,
                T::from_f64(0.0),
                T::from_f64(0.0),
                -(f * t_k_z) - sin_gamma,
                t32 - f * t_b1_z,
                t32 - f * t_b2_z,
            ),
            b: Vector5::new(
                -(m
                    * (t5 * (T::from_f64(0.125) * t6 - t15) * t11
                        + T::from_f64(0.5)
                            * (t4 * (T::from_f64(4.0) * t29 - T::from_f64(2.0) * t38)
                                - (t4 * (T::from_f64(2.0) * t29 - t38)
                                    + t5 * (T::from_f64(0.5) * t11 * t19 - t25))) + g * t36
                        + gammaddot * (t15 + t26 * t26 + t36 * t36))) + t26 * (t8 + t9)
                    + f_z * t36,
                m
                    * (t40
                        * (t25
                            - t11
                                * (T::from_f64(0.5) * t19 - T::from_f64(0.25) * t6
                                    + T::from_f64(1.0 / 6.0) * t7))
                        - psiddot
                            * (t2 * (T::from_f64(0.25) * t19 + t15)
                                + T::from_f64(0.125) * t3 * t6)) + t18 * (t12 + t10),
                t8 + t9 - m * (t28 * t4 + gammaddot * t26 + t18 * t5),
                -t12 - t10 - m * (T::from_f64(2.0) * t40 * t26 - t18 * psiddot),
                f_z - m * g - m * (gammaddot * t36 - t4 * t37),
            ),
        }
    }
    /// Material velocity of the peg at K, B1, B2 (rows) in rotating components (e_η, e_n, e_z) (m/s); replaces paper (10)–(13). The friction directions are −v/|v|.
    ///
    /// # Inputs
    /// - `x` = (`gamma`, `psi`, `gammadot`, `psidot`)
    /// - `p` = (`D_hole`, `d_peg`, `H`, `m`, `g`, `f`, `gamma0`)
    ///
    /// # Outputs
    /// - `v`: 3×3 matrix
    ///
    /// # Cost
    /// 22 add/sub, 38 mul, 1 div, 1 sqrt, 4 transcendental, 0 branches; 27 `let`s.
    #[inline]
    pub fn contact_velocities<T: Real>(
        x: &SVector<T, 4>,
        p: &SVector<T, 7>,
    ) -> SMatrix<T, 3, 3> {
        let gamma = x[0];
        let gammadot = x[2];
        let psidot = x[3];
        let d_hole = p[0];
        let d_peg = p[1];
        let h = p[2];
        let gamma0 = p[6];
        let (sin_gamma, cos_gamma) = gamma.sin_cos();
        let half_gamma0 = T::from_f64(0.5) * gamma0;
        let half_gamma = T::from_f64(0.5) * gamma;
        let sin_sum = (half_gamma0 + half_gamma).sin();
        let (sin_half_gamma, cos_half_gamma) = half_gamma.sin_cos();
        let e = d_hole - d_peg
            + T::from_f64(2.0) * d_peg * (sin_half_gamma * sin_half_gamma);
        let t0 = T::from_f64(1.0) / sin_gamma;
        let half_d = T::from_f64(0.5) * d_hole;
        let lever = T::from_f64(0.5) * h - T::from_f64(0.5) * e * t0;
        let t1 = sin_gamma * lever;
        let t2 = -cos_gamma * lever;
        let t3 = t0 * t0;
        let t4 = cos_gamma * t3;
        let sin_diff = (half_gamma0 - half_gamma).sin();
        let t5 = half_d - t1;
        let t6 = d_peg * sin_half_gamma * t0 * cos_half_gamma
            - T::from_f64(0.5) * t4 * e;
        let neg_half_delta = d_hole * sin_sum * sin_diff;
        let t7 = t0 * t0 * (T::from_f64(0.5) * e + neg_half_delta * cos_gamma) + t1;
        let t8 = -psidot * (t1 - t7);
        let neg_half_gap = neg_half_delta * t4;
        let bb1 = (-T::from_f64(2.0) * neg_half_gap
            * (d_hole + T::from_f64(2.0) * neg_half_gap))
            .sqrt();
        let t9 = psidot * bb1;
        let t10 = half_d + cos_gamma * (neg_half_delta * t3 - t6) - t1;
        let t11 = gammadot * (neg_half_delta * t0 + t2 - (t2 + sin_gamma * t6));
        let t12 = gammadot * (t10 + t7);
        Matrix3::new(
            -t11,
            -psidot * (t1 + t5),
            gammadot * (t10 - t5),
            -t11 - t9,
            t8,
            t12,
            t9 - t11,
            t8,
            t12,
        )
    }
    /// The outputs of [`energy`].
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct EnergyOut<T: Real> {
        /// Kinetic energy T, J.
        pub kinetic: T,
        /// Total energy T + V, J.
        pub total: T,
    }
    /// Kinetic energy T = ½ m|v_C|² + ½ ωᵀIω (paper (22)–(23)) and total energy T + V with V = m g z_C (J).
    ///
    /// # Inputs
    /// - `x` = (`gamma`, `psi`, `gammadot`, `psidot`)
    /// - `p` = (`D_hole`, `d_peg`, `H`, `m`, `g`, `f`, `gamma0`)
    ///
    /// # Outputs
    /// The fields of [`EnergyOut`]:
    /// - `kinetic`: scalar
    /// - `total`: scalar
    ///
    /// # Cost
    /// 21 add/sub, 47 mul, 1 div, 0 sqrt, 4 transcendental, 0 branches; 27 `let`s.
    #[inline]
    pub fn energy<T: Real>(x: &SVector<T, 4>, p: &SVector<T, 7>) -> EnergyOut<T> {
        let gamma = x[0];
        let gammadot = x[2];
        let psidot = x[3];
        let d_hole = p[0];
        let d_peg = p[1];
        let h = p[2];
        let m = p[3];
        let g = p[4];
        let gamma0 = p[6];
        let (sin_gamma, cos_gamma) = gamma.sin_cos();
        let half_gamma0 = T::from_f64(0.5) * gamma0;
        let half_gamma = T::from_f64(0.5) * gamma;
        let sin_sum = (half_gamma0 + half_gamma).sin();
        let (sin_half_gamma, cos_half_gamma) = half_gamma.sin_cos();
        let e = d_hole - d_peg
            + T::from_f64(2.0) * d_peg * (sin_half_gamma * sin_half_gamma);
        let t0 = T::from_f64(1.0) / sin_gamma;
        let twice_a2 = e * t0;
        let half_d = T::from_f64(0.5) * d_hole;
        let t1 = gammadot * gammadot;
        let t2 = psidot * psidot;
        let t3 = d_peg * d_peg;
        let t4 = sin_gamma * sin_gamma * t2;
        let lever = T::from_f64(0.5) * h - T::from_f64(0.5) * twice_a2;
        let t5 = -cos_gamma * lever;
        let twice_lever = h - twice_a2;
        let t6 = t0 * t0;
        let sin_diff = (half_gamma0 - half_gamma).sin();
        let neg_half_delta = d_hole * sin_sum * sin_diff;
        let t7 = T::from_f64(0.0625) * (cos_gamma * cos_gamma) * t2 * t3;
        let t8 = T::from_f64(1.0 / 24.0) * (T::from_f64(0.75) * t3 + h * h) * (t1 + t4);
        let t9 = d_peg * sin_half_gamma * t0 * cos_half_gamma
            - T::from_f64(0.5) * cos_gamma * e * t6;
        let t10 = t5 + sin_gamma * t9;
        let t11 = half_d + cos_gamma * (neg_half_delta * t6 - t9) - sin_gamma * lever;
        let t12 = T::from_f64(0.5)
            * (t1 * (t10 * t10 + t11 * t11)
                + T::from_f64(0.25) * t4 * (twice_lever * twice_lever));
        EnergyOut {
            kinetic: m * (t12 + t7 + t8),
            total: m * (t12 + t7 + t8 - g * (neg_half_delta * t0 + t5)),
        }
    }
    /// Planar geometry at γ (m): a1, a2 (paper (1)), S1, S2 (2), b = BB1, sin τ, cos τ, η_C, z_C (3), KL, BL (5), η_L, z_L (4b).
    ///
    /// # Inputs
    /// - `x` = (`gamma`, `psi`, `gammadot`, `psidot`)
    /// - `p` = (`D_hole`, `d_peg`, `H`, `m`, `g`, `f`, `gamma0`)
    ///
    /// # Outputs
    /// - `geo`: vector of 13
    ///
    /// # Cost
    /// 10 add/sub, 32 mul, 3 div, 1 sqrt, 5 transcendental, 0 branches; 21 `let`s.
    #[inline]
    pub fn geometry<T: Real>(x: &SVector<T, 4>, p: &SVector<T, 7>) -> SVector<T, 13> {
        let gamma = x[0];
        let d_hole = p[0];
        let d_peg = p[1];
        let h = p[2];
        let gamma0 = p[6];
        let (sin_gamma, cos_gamma) = gamma.sin_cos();
        let half_gamma0 = T::from_f64(0.5) * gamma0;
        let half_gamma = T::from_f64(0.5) * gamma;
        let sin_sum = (half_gamma0 + half_gamma).sin();
        let sin_half_gamma = half_gamma.sin();
        let e = d_hole - d_peg
            + T::from_f64(2.0) * d_peg * (sin_half_gamma * sin_half_gamma);
        let t0 = T::from_f64(1.0) / sin_gamma;
        let t1 = T::from_f64(0.5) * h;
        let t2 = t0 * t0;
        let sin_diff = (half_gamma0 - half_gamma).sin();
        let neg_half_delta = d_hole * sin_sum * sin_diff;
        let neg_a1 = neg_half_delta * t0;
        let t3 = neg_half_delta * cos_gamma;
        let a2 = T::from_f64(0.5) * (e * t0);
        let lever = t1 - a2;
        let s1 = t0 * (T::from_f64(0.5) * e + t3) * t0;
        let s2 = t0 * (T::from_f64(0.5) * cos_gamma * e + neg_half_delta) * t0;
        let t4 = s1.hypot(neg_a1);
        let neg_half_gap = t3 * t2;
        let bb1 = (-T::from_f64(2.0) * neg_half_gap
            * (d_hole + T::from_f64(2.0) * neg_half_gap))
            .sqrt();
        SMatrix::<
            T,
            13,
            1,
        >::from_row_slice(
            &[
                -neg_a1,
                a2,
                s1,
                s2,
                bb1,
                T::from_f64(2.0) * bb1 / d_hole,
                T::from_f64(2.0) * s1 / d_hole,
                sin_gamma * (a2 - t1),
                cos_gamma * lever - neg_a1,
                -T::from_f64(2.0) * neg_half_delta * t2,
                T::from_f64(2.0) * t4,
                -s1,
                -T::from_f64(2.0) * neg_a1,
            ],
        )
    }
    /// Exact parameter Jacobian of the solution u of the linear system A u = b of [`forward`]: ∂(b − A u)/∂p at the given u (columns in `P_NAMES` order), so that A ∂u/∂p equals it.
    ///
    /// # Inputs
    /// - `x` = (`gamma`, `psi`, `gammadot`, `psidot`)
    /// - `u` = (`gammaddot`, `psiddot`, `N_K`, `N_B1`, `N_B2`)
    /// - `p` = (`D_hole`, `d_peg`, `H`, `m`, `g`, `f`, `gamma0`)
    /// - `loads` = (`M_gamma`, `M_psi`, `F_x`, `F_y`, `F_z`)
    /// - `t` = (`t_K_eta`, `t_K_n`, `t_K_z`, `t_B1_eta`, `t_B1_n`, `t_B1_z`, `t_B2_eta`, `t_B2_n`, `t_B2_z`)
    ///
    /// # Outputs
    /// - `residual_p`: 5×7 matrix
    ///
    /// # Cost
    /// 219 add/sub, 449 mul, 6 div, 2 sqrt, 7 transcendental, 0 branches; 129 `let`s.
    pub fn forward_p<T: Real>(
        x: &SVector<T, 4>,
        u: &SVector<T, 5>,
        p: &SVector<T, 7>,
        loads: &SVector<T, 5>,
        t: &SVector<T, 9>,
    ) -> SMatrix<T, 5, 7> {
        let gamma = x[0];
        let psi = x[1];
        let gammadot = x[2];
        let psidot = x[3];
        let gammaddot = u[0];
        let psiddot = u[1];
        let n_k = u[2];
        let n_b1 = u[3];
        let n_b2 = u[4];
        let d_hole = p[0];
        let d_peg = p[1];
        let h = p[2];
        let m = p[3];
        let g = p[4];
        let f = p[5];
        let gamma0 = p[6];
        let f_x = loads[2];
        let f_y = loads[3];
        let f_z = loads[4];
        let t_k_eta = t[0];
        let t_k_n = t[1];
        let t_k_z = t[2];
        let t_b1_eta = t[3];
        let t_b1_n = t[4];
        let t_b1_z = t[5];
        let t_b2_eta = t[6];
        let t_b2_n = t[7];
        let t_b2_z = t[8];
        let (sin_gamma, cos_gamma) = gamma.sin_cos();
        let half_gamma0 = T::from_f64(0.5) * gamma0;
        let half_gamma = T::from_f64(0.5) * gamma;
        let sin_sum = (half_gamma0 + half_gamma).sin();
        let (sin_half_gamma, cos_half_gamma) = half_gamma.sin_cos();
        let t0 = sin_half_gamma * sin_half_gamma;
        let e = d_hole - d_peg + T::from_f64(2.0) * d_peg * t0;
        let t1 = T::from_f64(1.0) / sin_gamma;
        let twice_a2 = e * t1;
        let t2 = sin_gamma * sin_gamma;
        let half_d = T::from_f64(0.5) * d_hole;
        let t3 = sin_half_gamma * cos_half_gamma;
        let t4 = cos_half_gamma * cos_half_gamma;
        let t5 = T::from_f64(1.0) / (sin_gamma * sin_gamma * sin_gamma);
        let t6 = cos_gamma * cos_gamma;
        let t7 = gammadot * gammadot;
        let t8 = psidot * psidot;
        let t9 = d_peg * d_peg;
        let t10 = h * h;
        let t11 = T::from_f64(0.75) * t9 + t10;
        let (sin_psi, cos_psi) = psi.sin_cos();
        let t12 = f_x * cos_psi + f_y * sin_psi;
        let t13 = sin_gamma * cos_gamma;
        let t14 = cos_gamma * t1;
        let t15 = t5 * t6;
        let t16 = T::from_f64(0.5) * t1 + t15;
        let sin_gamma0 = gamma0.sin();
        let t17 = n_k * t_k_n;
        let t18 = n_b1 * t_b1_n;
        let t19 = n_b2 * t_b2_n;
        let t20 = f_x * sin_psi - f_y * cos_psi;
        let half_e = T::from_f64(0.5) * e;
        let t21 = T::from_f64(1.0 / 12.0) * t11;
        let lever = T::from_f64(0.5) * h - T::from_f64(0.5) * twice_a2;
        let t22 = sin_gamma * lever;
        let twice_lever = h - twice_a2;
        let t23 = twice_lever * twice_lever;
        let t24 = T::from_f64(0.25) * t23;
        let t25 = T::from_f64(2.0) * h - T::from_f64(2.0) * twice_a2;
        let t26 = t1 * t1;
        let t27 = cos_gamma * t26;
        let t28 = t27 * e;
        let sin_diff = (half_gamma0 - half_gamma).sin();
        let t29 = sin_sum * sin_diff;
        let neg_half_delta = t29 * d_hole;
        let neg_a1 = neg_half_delta * t1;
        let ob = neg_a1.hypot(half_d);
        let t30 = T::from_f64(1.0) / ob;
        let t31 = half_e + neg_half_delta * cos_gamma;
        let t32 = t1 * t31;
        let s1 = t32 * t1;
        let t33 = t29 * (t1 + T::from_f64(2.0) * t15);
        let t34 = gammadot * psidot;
        let t35 = T::from_f64(0.5) * t20;
        let t36 = n_b1 + n_b2;
        let t37 = t1 * t36;
        let t38 = T::from_f64(1.0) - T::from_f64(2.0) * t0;
        let t39 = t3 * t1;
        let t40 = t39 * d_peg;
        let t41 = t14 * t38;
        let t42 = t25 * t38;
        let t43 = T::from_f64(0.5) - sin_gamma * t16 + t26 * t6;
        let t44 = t27 * d_hole;
        let t45 = t40 - T::from_f64(0.5) * t28;
        let t46 = sin_gamma * t45;
        let t47 = t27 * t3;
        let t48 = T::from_f64(2.0) * t40 - t28;
        let t49 = t2 * t48;
        let t50 = t49 * t25;
        let t51 = t46 - cos_gamma * lever;
        let t52 = lever + t1 * (half_e - T::from_f64(0.5) * (d_peg * (t0 - t4)))
            + t15 * e - T::from_f64(2.0) * t47 * d_peg;
        let t53 = sin_gamma * t52 + T::from_f64(2.0) * cos_gamma * t45;
        let t54 = t51 * t53;
        let t55 = sin_gamma * t48;
        let t56 = T::from_f64(0.5) * t55 - T::from_f64(0.25) * cos_gamma * t25;
        let t57 = t27 * t38;
        let t58 = t39 + T::from_f64(0.5) * t57;
        let t59 = cos_gamma * t58;
        let t60 = T::from_f64(0.5) - t0 + t59;
        let t61 = sin_gamma * t58;
        let t62 = T::from_f64(2.0) * t61;
        let t63 = t59 + T::from_f64(0.5) * t26 * t38;
        let t64 = t61 - T::from_f64(0.5) * t41;
        let t65 = T::from_f64(0.5) * (t38 - t4 + t0) * t1 + t15 * t38
            + T::from_f64(2.0) * t47;
        let t66 = t51 * t43;
        let t67 = T::from_f64(0.5) - t0 - sin_gamma * t65 + T::from_f64(2.0) * t59;
        let t68 = t62 - cos_gamma * (T::from_f64(0.5) * t1 * t38 - t65);
        let t69 = t51 * t67;
        let t70 = t53 * (t62 - t41);
        let t71 = t2 * (t57 + T::from_f64(2.0) * t39);
        let t72 = T::from_f64(0.5) * t55 * t38;
        let t73 = t1 * (T::from_f64(0.5) * cos_gamma + t29);
        let t74 = sin_sum * sin_sum * (sin_diff * sin_diff);
        let t75 = T::from_f64(1.0) / (ob * ob * ob);
        let t76 = t29 * cos_gamma;
        let t77 = T::from_f64(0.5) + t76;
        let t78 = t1 * t77 * t1;
        let t79 = t5 * t75;
        let t80 = t29 * (d_hole * d_hole);
        let t81 = cos_gamma * (t1 + t16) + t33;
        let t82 = d_hole + T::from_f64(2.0) * t44 * t29;
        let t83 = t44 * t82;
        let t84 = -T::from_f64(2.0) * t83 * t29;
        let bb1 = t84.sqrt();
        let t85 = t27 * t29;
        let t86 = T::from_f64(1.0) / t84.sqrt();
        let t87 = cos_gamma * (neg_half_delta * t26 - t45);
        let t88 = half_d + t87 - t22;
        let t89 = d_hole + T::from_f64(2.0) * t87 - T::from_f64(2.0) * t22;
        let t90 = d_hole * (t33 + T::from_f64(0.5) * t14) + cos_gamma * t52
            - T::from_f64(2.0) * t46;
        let t91 = t89 * t90;
        let t92 = t46 - neg_a1;
        let twice_s1 = half_d + t87 + s1;
        let t93 = t26 * (t76 + T::from_f64(0.5) * t6);
        let t94 = t93 + T::from_f64(1.0);
        let t95 = t93 + T::from_f64(0.5) + t78;
        let t96 = t75 * (d_hole * (T::from_f64(0.25) + t74 * t26));
        let t97 = t89 * t81;
        let t98 = g + gammaddot * t89;
        let t99 = t85
            * (t86 * (t82 + d_hole * (T::from_f64(1.0) + T::from_f64(2.0) * t85)));
        let t100 = t86 * (T::from_f64(2.0) * t80 * t6 / sin_gamma.powi(4) + t83);
        let t101 = t99 * t30 + t96 * bb1;
        let t102 = t90 * (t26 * (t6 + T::from_f64(2.0) * t76) + T::from_f64(2.0));
        let t103 = t89 * t68;
        let t104 = t90 * (T::from_f64(2.0) * (t59 - t0) + T::from_f64(1.0));
        let t105 = sin_gamma * (t51 + t90);
        SMatrix::<
            T,
            5,
            7,
        >::from_row_slice(
            &[
                -(m
                    * (t94 * t98
                        - T::from_f64(0.5)
                            * (t7
                                * (T::from_f64(2.0) * (t97 + t102) + T::from_f64(4.0) * t66)
                                - (t7 * (T::from_f64(2.0) * t66 + t97 + t102) - t8 * t56))))
                    - f
                        * (n_k * (t73 * t_k_eta - t93 * t_k_z)
                            + n_b1 * (t73 * t_b1_eta - t_b1_z * t95)
                            + n_b2 * (t73 * t_b2_eta - t_b2_z * t95)) + f_z * t94,
                -(m
                    * (T::from_f64(0.5)
                        * (t7
                            * (T::from_f64(2.0) * (t70 + t103 + t104)
                                + T::from_f64(4.0) * t69)
                            - (t7 * (T::from_f64(2.0) * t69 + t70 + t103 + t104)
                                - t8
                                    * (t72
                                        - t25
                                            * (T::from_f64(0.5) * cos_gamma * t38
                                                - T::from_f64(0.25) * t71)))) - g * t60
                        + T::from_f64(0.125) * t13 * d_peg * t8))
                    + f
                        * (n_k * t58 * (t_k_eta * sin_gamma - t_k_z * cos_gamma)
                            + n_b1 * (t61 * t_b1_eta - t_b1_z * t63)
                            + n_b2 * (t61 * t_b2_eta - t_b2_z * t63)) + t12 * t64
                    - f_z * t60
                    - gammaddot
                        * (m
                            * (T::from_f64(0.125) * d_peg
                                - T::from_f64(0.5)
                                    * (T::from_f64(2.0) * t89 * t60
                                        - T::from_f64(4.0) * t51 * t64))),
                m
                    * (sin_gamma
                        * (T::from_f64(0.5) * g
                            + T::from_f64(1.0 / 6.0) * h * cos_gamma * t8)
                        + T::from_f64(0.5)
                            * (t7 * (t105 - cos_gamma * (t53 + T::from_f64(0.5) * t89))
                                + T::from_f64(0.5) * (t13 * t25 - t49) * t8
                                + t7
                                    * (cos_gamma * (T::from_f64(2.0) * t53 + t89)
                                        - T::from_f64(2.0) * t105)))
                    - T::from_f64(0.5) * (cos_gamma * t12 + f_z * sin_gamma)
                    - gammaddot
                        * (m
                            * (T::from_f64(1.0 / 6.0) * h
                                - T::from_f64(0.5)
                                    * (T::from_f64(2.0) * cos_gamma * t51 + sin_gamma * t89))),
                -(t8
                    * (T::from_f64(0.125) * t50
                        - t13 * (t24 - T::from_f64(0.125) * t9 + t21)))
                    + t7
                        * (t54
                            - T::from_f64(0.5)
                                * (t91 + T::from_f64(4.0) * t54 - T::from_f64(2.0) * t91))
                    - g * t88
                    - gammaddot
                        * (t51 * t51 + t88 * t88 + T::from_f64(0.0625) * t9
                            + T::from_f64(1.0 / 12.0) * t10),
                -m * t88,
                n_k * (t_k_eta * t92 + t87 * t_k_z)
                    + n_b1 * (t_b1_eta * t92 + t_b1_z * twice_s1)
                    + n_b2 * (t_b2_eta * t92 + t_b2_z * twice_s1),
                -(sin_gamma0
                    * (-(t27 * (T::from_f64(0.5) * f_z - T::from_f64(0.5) * t98 * m))
                        + f
                            * (T::from_f64(0.5) * n_k * (t_k_eta * t1 - t27 * t_k_z)
                                + n_b1 * (T::from_f64(0.5) * t_b1_eta * t1 - t27 * t_b1_z)
                                + n_b2 * (T::from_f64(0.5) * t_b2_eta * t1 - t27 * t_b2_z))
                        - T::from_f64(0.5) * m * (t89 * t16 + t27 * t90) * t7) * d_hole),
                -(T::from_f64(0.5) * t17 * f)
                    - m * (t34 * t56 - T::from_f64(0.25) * psiddot * sin_gamma * t25)
                    + f
                        * (n_b1 * (t99 * t_b1_eta + t78 * t_b1_n)
                            - n_b2 * (t99 * t_b2_eta - t78 * t_b2_n)) - t35,
                t38 * (t35 - T::from_f64(0.5) * (t26 * (t18 + t19)) * f)
                    + m
                        * (t34
                            * (cos_gamma
                                * (T::from_f64(0.25) * d_peg * sin_gamma
                                    - T::from_f64(0.5) * t42) + T::from_f64(0.25) * t71 * t25
                                + t72)
                            - psiddot
                                * (d_peg
                                    * (T::from_f64(0.25) * t6 + T::from_f64(0.125) * t2)
                                    + T::from_f64(0.25) * t42 * sin_gamma)),
                m
                    * (t34
                        * (T::from_f64(0.5) * t49
                            - t13
                                * (T::from_f64(0.5) * t25 + T::from_f64(1.0 / 3.0) * h))
                        - psiddot * t2
                            * (T::from_f64(0.25) * t25 + T::from_f64(1.0 / 6.0) * h))
                    + T::from_f64(0.5) * sin_gamma * t20,
                t34
                    * (T::from_f64(0.25) * t50
                        - t13
                            * (T::from_f64(0.5) * t23 - T::from_f64(0.25) * t9
                                + T::from_f64(1.0 / 6.0) * t11))
                    - psiddot * (t2 * (t24 + t21) + T::from_f64(0.125) * t6 * t9),
                T::from_f64(0.0),
                -(T::from_f64(0.5) * t17 * d_hole)
                    - n_b1 * (t_b1_eta * bb1 - s1 * t_b1_n)
                    + n_b2 * (t_b2_eta * bb1 + s1 * t_b2_n),
                T::from_f64(0.5)
                    * (f
                        * (n_b1 * (t100 * t_b1_eta + t44 * t_b1_n)
                            + n_b2 * (t44 * t_b2_n - t100 * t_b2_eta))) * sin_gamma0,
                m * (t7 * t43 + T::from_f64(0.5) * t8)
                    - t37 * (t30 * t77 - t96 * t31) * t1,
                T::from_f64(0.5) * (t36 * t38 * t30) * t26
                    - m * (t7 * t67 + T::from_f64(0.5) * t8 * t38 + gammaddot * t64),
                T::from_f64(0.5) * (gammaddot * cos_gamma - (t7 + t8) * sin_gamma) * m,
                -(t22 * t8) - t53 * t7 - gammaddot * t51,
                T::from_f64(0.0),
                n_k * t_k_eta + n_b1 * t_b1_eta + n_b2 * t_b2_eta,
                -T::from_f64(0.5) * (sin_gamma0 * t36 * (t44 * t30 - t79 * t80 * t32)),
                -(T::from_f64(0.5) * m * psiddot) + n_b1 * t101 - n_b2 * t101,
                -(m * (T::from_f64(2.0) * t34 * t64 - T::from_f64(0.5) * psiddot * t38)),
                m * (t34 * cos_gamma + T::from_f64(0.5) * psiddot * sin_gamma),
                t22 * psiddot - T::from_f64(2.0) * t34 * t51,
                T::from_f64(0.0),
                t17 + t18 + t19,
                T::from_f64(0.5) * (sin_gamma0 * (n_b1 - n_b2))
                    * (t100 * t30 + t80 * t26 * bb1 * t75),
                t37 * t29 * (t96 * d_hole - t30) - m * (gammaddot * t94 - t7 * t81),
                m * (gammaddot * t60 - t7 * t68),
                T::from_f64(0.5) * (cos_gamma * t7 + gammaddot * sin_gamma) * m,
                -g + t7 * t90 - gammaddot * t88,
                -m,
                n_k * t_k_z + n_b1 * t_b1_z + n_b2 * t_b2_z,
                -(sin_gamma0
                    * (d_hole * (T::from_f64(0.5) * t27 * gammaddot - t7 * t16) * m
                        + T::from_f64(0.5) * t36
                            * (d_hole * t1 * t30
                                - t74 * t79 * (d_hole * d_hole * d_hole)))),
            ],
        )
    }
}
