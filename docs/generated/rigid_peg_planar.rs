// @generated readable copy of `pegdyn::generated::rigid_peg_planar` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generator snapshot::

/// Rigid three-point peg leaning on the hole edge at K, B1, B2 (*Peg-on-hole: fundamental principles of motion of a peg leaning on a horizontal hole edge*), variant `Planar`, derived by the generator (equations/src/models/rigid_peg.rs).
/// State x = (`gamma`, `gammadot`); parameters p = (D_hole, d_peg, H, m, g, f, gamma0); loads = (`M_gamma`, `F_x`, `F_z`); friction directions t = (`t_K_eta`, `t_K_z`, `t_B_eta`, `t_B_z`) (unit, force on the peg).
/// Vectors in rotating components (e_η, e_n, e_z); ψ ≡ 0, so `F_x` is the in-plane horizontal force (along e_η) and N_B = N_B1 = N_B2. SI units.
pub mod rigid_peg_planar {
    use nalgebra::{Matrix3, SMatrix, SVector, Vector3};
    use pegdyn::scalar::Real;
    /// Symbol names of the components of `x`, in order.
    pub const X_NAMES: [&str; 2] = ["gamma", "gammadot"];
    /// Symbol names of the components of `p`, in order.
    pub const P_NAMES: [&str; 7] = ["D_hole", "d_peg", "H", "m", "g", "f", "gamma0"];
    /// Symbol names of the components of `loads`, in order.
    pub const LOADS_NAMES: [&str; 3] = ["M_gamma", "F_x", "F_z"];
    /// Symbol names of the components of `t`, in order.
    pub const T_NAMES: [&str; 4] = ["t_K_eta", "t_K_z", "t_B_eta", "t_B_z"];
    /// Symbol names of the components of `qdd`, in order.
    pub const QDD_NAMES: [&str; 1] = ["gammaddot"];
    /// The struct of `p`, shared with `rigid_peg` (same components).
    pub use super::rigid_peg::Params;
    /// The state x = (γ, γ̇) of the planar motion (ψ ≡ 0).
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct State<T> {
        /// Nutation angle γ between the peg's axis and the hole's axis, rad.
        pub gamma: T,
        /// Nutation rate γ̇, rad/s.
        pub gammadot: T,
    }
    impl<T> State<T> {
        /// The field names in vector order: the symbol names of `x` ([`X_NAMES`]).
        pub const NAMES: [&'static str; 2] = X_NAMES;
    }
    impl<T: Real> From<State<T>> for SVector<T, 2> {
        /// The `x` vector of these values, in field order.
        fn from(v: State<T>) -> SVector<T, 2> {
            SVector::from([v.gamma, v.gammadot])
        }
    }
    impl<T: Real> From<&SVector<T, 2>> for State<T> {
        /// The fields of a `x` vector, in field order.
        fn from(v: &SVector<T, 2>) -> State<T> {
            State {
                gamma: v[0],
                gammadot: v[1],
            }
        }
    }
    impl<T: Real> From<SVector<T, 2>> for State<T> {
        /// The fields of a `x` vector, in field order.
        fn from(v: SVector<T, 2>) -> State<T> {
            State::from(&v)
        }
    }
    /// The applied loads of the planar motion: the moment conjugate to γ and the in-plane components of the assembly force.
    #[derive(Clone, Copy, Debug, PartialEq)]
    #[allow(non_snake_case)]
    pub struct Loads<T> {
        /// Generalized moment M_γ conjugate to γ, N·m.
        pub M_gamma: T,
        /// Assembly force at the centre of mass, in-plane horizontal component (along e_η), N.
        pub F_x: T,
        /// Assembly force at the centre of mass, fixed-frame z component, N.
        pub F_z: T,
    }
    impl<T> Loads<T> {
        /// The field names in vector order: the symbol names of `loads` ([`LOADS_NAMES`]).
        pub const NAMES: [&'static str; 3] = LOADS_NAMES;
    }
    impl<T: Real> From<Loads<T>> for SVector<T, 3> {
        /// The `loads` vector of these values, in field order.
        fn from(v: Loads<T>) -> SVector<T, 3> {
            SVector::from([v.M_gamma, v.F_x, v.F_z])
        }
    }
    impl<T: Real> From<&SVector<T, 3>> for Loads<T> {
        /// The fields of a `loads` vector, in field order.
        fn from(v: &SVector<T, 3>) -> Loads<T> {
            Loads {
                M_gamma: v[0],
                F_x: v[1],
                F_z: v[2],
            }
        }
    }
    impl<T: Real> From<SVector<T, 3>> for Loads<T> {
        /// The fields of a `loads` vector, in field order.
        fn from(v: SVector<T, 3>) -> Loads<T> {
            Loads::from(&v)
        }
    }
    /// The friction direction at each contact (unit or shorter, force on the peg) in rotating components (e_η, e_n, e_z).
    #[derive(Clone, Copy, Debug, PartialEq)]
    #[allow(non_snake_case)]
    pub struct FrictionDirections<T> {
        /// Friction direction at K, e_η component (unit or shorter, force on the peg), dimensionless.
        pub t_K_eta: T,
        /// Friction direction at K, e_z component (unit or shorter, force on the peg), dimensionless.
        pub t_K_z: T,
        /// Friction direction at B, e_η component (unit or shorter, force on the peg), dimensionless.
        pub t_B_eta: T,
        /// Friction direction at B, e_z component (unit or shorter, force on the peg), dimensionless.
        pub t_B_z: T,
    }
    impl<T> FrictionDirections<T> {
        /// The field names in vector order: the symbol names of `t` ([`T_NAMES`]).
        pub const NAMES: [&'static str; 4] = T_NAMES;
    }
    impl<T: Real> From<FrictionDirections<T>> for SVector<T, 4> {
        /// The `t` vector of these values, in field order.
        fn from(v: FrictionDirections<T>) -> SVector<T, 4> {
            SVector::from([v.t_K_eta, v.t_K_z, v.t_B_eta, v.t_B_z])
        }
    }
    impl<T: Real> From<&SVector<T, 4>> for FrictionDirections<T> {
        /// The fields of a `t` vector, in field order.
        fn from(v: &SVector<T, 4>) -> FrictionDirections<T> {
            FrictionDirections {
                t_K_eta: v[0],
                t_K_z: v[1],
                t_B_eta: v[2],
                t_B_z: v[3],
            }
        }
    }
    impl<T: Real> From<SVector<T, 4>> for FrictionDirections<T> {
        /// The fields of a `t` vector, in field order.
        fn from(v: SVector<T, 4>) -> FrictionDirections<T> {
            FrictionDirections::from(&v)
        }
    }
    /// A linear system A u = b for the unknowns u (see the function returning it).
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct LinearSystem<T: Real> {
        /// The matrix A = ∂R/∂u.
        pub a: SMatrix<T, 3, 3>,
        /// The right-hand side b = −R at u = 0.
        pub b: SVector<T, 3>,
    }
    /// Forward dynamics (replaces paper (24)–(31)): A u = b for u = (`gammaddot`, `N_K`, `N_B`) (rad/s², N), the applied loads and friction directions given.
    /// Rows: the Lagrange equation of γ (paper (26)/(32)), then the centre-of-mass equations along e_η and e_z ((29), (31)/(33), (34)); the ψ row and the lateral row vanish identically.
    /// A = ∂R/∂u, b = −R at u = 0, R the residual derived from T, V and the generalized forces.
    ///
    /// # Inputs
    /// - `x` = (`gamma`, `gammadot`)
    /// - `p` = (`D_hole`, `d_peg`, `H`, `m`, `g`, `f`, `gamma0`)
    /// - `loads` = (`M_gamma`, `F_x`, `F_z`)
    /// - `t` = (`t_K_eta`, `t_K_z`, `t_B_eta`, `t_B_z`)
    ///
    /// # Outputs
    /// The fields of [`LinearSystem`]:
    /// - `a`: 3×3 matrix
    /// - `b`: vector of 3
    ///
    /// # Cost
    /// 46 add/sub, 91 mul, 4 div, 0 sqrt, 5 transcendental, 0 branches; 37 `let`s.
    #[inline]
    pub fn forward<T: Real>(
        x: &SVector<T, 2>,
        p: &SVector<T, 7>,
        loads: &SVector<T, 3>,
        t: &SVector<T, 4>,
    ) -> LinearSystem<T> {
        let gamma = x[0];
        let gammadot = x[1];
        let d_hole = p[0];
        let d_peg = p[1];
        let h = p[2];
        let m = p[3];
        let g = p[4];
        let f = p[5];
        let gamma0 = p[6];
        let m_gamma = loads[0];
        let f_x = loads[1];
        let f_z = loads[2];
        let t_k_eta = t[0];
        let t_k_z = t[1];
        let t_b_eta = t[2];
        let t_b_z = t[3];
        let (sin_gamma, cos_gamma) = gamma.sin_cos();
        let half_gamma0 = T::from_f64(0.5) * gamma0;
        let half_gamma = T::from_f64(0.5) * gamma;
        let sin_sum = (half_gamma0 + half_gamma).sin();
        let (sin_half_gamma, cos_half_gamma) = half_gamma.sin_cos();
        let t0 = sin_half_gamma * sin_half_gamma;
        let e = d_hole - d_peg + T::from_f64(2.0) * d_peg * t0;
        let t1 = T::from_f64(1.0) / sin_gamma;
        let half_d = T::from_f64(0.5) * d_hole;
        let lever = T::from_f64(0.5) * h - T::from_f64(0.5) * e * t1;
        let t2 = sin_gamma * lever;
        let t3 = gammadot * gammadot;
        let half_e = T::from_f64(0.5) * e;
        let t4 = d_peg * sin_half_gamma * cos_half_gamma;
        let t5 = cos_gamma * cos_gamma / (sin_gamma * sin_gamma * sin_gamma);
        let t6 = m * t3;
        let t7 = t1 * t1;
        let t8 = cos_gamma * t7;
        let t9 = t4 * t1 - T::from_f64(0.5) * t8 * e;
        let t10 = sin_gamma * t9;
        let t11 = t10 - cos_gamma * lever;
        let t12 = lever
            + t1
                * (half_e
                    - T::from_f64(0.5)
                        * (d_peg * (t0 - cos_half_gamma * cos_half_gamma))) + t5 * e
            - T::from_f64(2.0) * t4 * t8;
        let t13 = sin_gamma * t12 + T::from_f64(2.0) * cos_gamma * t9;
        let t14 = t11 * t13;
        let sin_diff = (half_gamma0 - half_gamma).sin();
        let t15 = sin_sum * sin_diff;
        let neg_half_delta = t15 * d_hole;
        let neg_a1 = neg_half_delta * t1;
        let ob = neg_a1.hypot(half_d);
        let s1 = t1 * (half_e + neg_half_delta * cos_gamma) * t1;
        let t16 = cos_gamma * (neg_half_delta * t7 - t9);
        let t17 = half_d + t16 - t2;
        let t18 = d_hole
            * (t15 * (t1 + T::from_f64(2.0) * t5) + T::from_f64(0.5) * cos_gamma * t1)
            + cos_gamma * t12 - T::from_f64(2.0) * t10;
        let t19 = (d_hole + T::from_f64(2.0) * t16 - T::from_f64(2.0) * t2) * t18;
        let t20 = t10 - neg_a1;
        LinearSystem {
            a: Matrix3::new(
                m
                    * (T::from_f64(1.0 / 12.0)
                        * (T::from_f64(0.75) * (d_peg * d_peg) + h * h) + t11 * t11
                        + t17 * t17),
                -(f * (t_k_eta * t20 + t16 * t_k_z)),
                -T::from_f64(2.0) * (f * (t20 * t_b_eta + (half_d + t16 + s1) * t_b_z)),
                m * t11,
                -(f * t_k_eta) - T::from_f64(1.0) + T::from_f64(2.0) * t0,
                T::from_f64(2.0) * s1 / ob - T::from_f64(2.0) * f * t_b_eta,
                m * t17,
                -(f * t_k_z) - sin_gamma,
                T::from_f64(2.0) * neg_a1 / ob - T::from_f64(2.0) * f * t_b_z,
            ),
            b: Vector3::new(
                m_gamma
                    - m
                        * (T::from_f64(0.5)
                            * (T::from_f64(4.0) * t14 - T::from_f64(2.0) * t19
                                - (T::from_f64(2.0) * t14 - t19)) * t3 + g * t17)
                    + f_z * t17 + f_x * t11,
                f_x - t6 * t13,
                f_z - m * g + t6 * t18,
            ),
        }
    }
    /// Prescribed motion (paper (26)–(31), Fig. 9): A u = b for u = (`M_gamma`, `N_K`, `N_B`) (N·m, N) given q̈ (the moment components of `loads` are unused: they are the unknowns).
    /// Rows: the Lagrange equation of γ (paper (26)/(32)), then the centre-of-mass equations along e_η and e_z ((29), (31)/(33), (34)); the ψ row and the lateral row vanish identically.
    ///
    /// # Inputs
    /// - `x` = (`gamma`, `gammadot`)
    /// - `qdd` = (`gammaddot`)
    /// - `p` = (`D_hole`, `d_peg`, `H`, `m`, `g`, `f`, `gamma0`)
    /// - `loads` = (`M_gamma`, `F_x`, `F_z`)
    /// - `t` = (`t_K_eta`, `t_K_z`, `t_B_eta`, `t_B_z`)
    ///
    /// # Outputs
    /// The fields of [`LinearSystem`]:
    /// - `a`: 3×3 matrix
    /// - `b`: vector of 3
    ///
    /// # Cost
    /// 48 add/sub, 92 mul, 4 div, 0 sqrt, 5 transcendental, 0 branches; 36 `let`s.
    #[inline]
    pub fn prescribed<T: Real>(
        x: &SVector<T, 2>,
        qdd: &SVector<T, 1>,
        p: &SVector<T, 7>,
        loads: &SVector<T, 3>,
        t: &SVector<T, 4>,
    ) -> LinearSystem<T> {
        let gamma = x[0];
        let gammadot = x[1];
        let gammaddot = qdd[0];
        let d_hole = p[0];
        let d_peg = p[1];
        let h = p[2];
        let m = p[3];
        let g = p[4];
        let f = p[5];
        let gamma0 = p[6];
        let f_x = loads[1];
        let f_z = loads[2];
        let t_k_eta = t[0];
        let t_k_z = t[1];
        let t_b_eta = t[2];
        let t_b_z = t[3];
        let (sin_gamma, cos_gamma) = gamma.sin_cos();
        let half_gamma0 = T::from_f64(0.5) * gamma0;
        let half_gamma = T::from_f64(0.5) * gamma;
        let sin_sum = (half_gamma0 + half_gamma).sin();
        let (sin_half_gamma, cos_half_gamma) = half_gamma.sin_cos();
        let t0 = sin_half_gamma * sin_half_gamma;
        let e = d_hole - d_peg + T::from_f64(2.0) * d_peg * t0;
        let t1 = T::from_f64(1.0) / sin_gamma;
        let half_d = T::from_f64(0.5) * d_hole;
        let lever = T::from_f64(0.5) * h - T::from_f64(0.5) * e * t1;
        let t2 = sin_gamma * lever;
        let t3 = gammadot * gammadot;
        let half_e = T::from_f64(0.5) * e;
        let t4 = d_peg * sin_half_gamma * cos_half_gamma;
        let t5 = cos_gamma * cos_gamma / (sin_gamma * sin_gamma * sin_gamma);
        let t6 = t1 * t1;
        let t7 = cos_gamma * t6;
        let t8 = t4 * t1 - T::from_f64(0.5) * t7 * e;
        let t9 = sin_gamma * t8;
        let t10 = t9 - cos_gamma * lever;
        let t11 = lever
            + t1
                * (half_e
                    - T::from_f64(0.5)
                        * (d_peg * (t0 - cos_half_gamma * cos_half_gamma))) + t5 * e
            - T::from_f64(2.0) * t4 * t7;
        let t12 = sin_gamma * t11 + T::from_f64(2.0) * cos_gamma * t8;
        let t13 = t10 * t12;
        let sin_diff = (half_gamma0 - half_gamma).sin();
        let t14 = sin_sum * sin_diff;
        let neg_half_delta = t14 * d_hole;
        let neg_a1 = neg_half_delta * t1;
        let ob = neg_a1.hypot(half_d);
        let s1 = t1 * (half_e + neg_half_delta * cos_gamma) * t1;
        let t15 = cos_gamma * (neg_half_delta * t6 - t8);
        let t16 = half_d + t15 - t2;
        let t17 = d_hole
            * (t14 * (t1 + T::from_f64(2.0) * t5) + T::from_f64(0.5) * cos_gamma * t1)
            + cos_gamma * t11 - T::from_f64(2.0) * t9;
        let t18 = (d_hole + T::from_f64(2.0) * t15 - T::from_f64(2.0) * t2) * t17;
        let t19 = t9 - neg_a1;
        LinearSystem {
            a: Matrix3::new(
                -T::from_f64(1.0),
                -(f * (t_k_eta * t19 + t15 * t_k_z)),
                -T::from_f64(2.0) * (f * (t19 * t_b_eta + (half_d + t15 + s1) * t_b_z)),
                T::from_f64(0.0),
                -(f * t_k_eta) - T::from_f64(1.0) + T::from_f64(2.0) * t0,
                T::from_f64(2.0) * s1 / ob - T::from_f64(2.0) * f * t_b_eta,
                T::from_f64(0.0),
                -(f * t_k_z) - sin_gamma,
                T::from_f64(2.0) * neg_a1 / ob - T::from_f64(2.0) * f * t_b_z,
            ),
            b: Vector3::new(
                -(m
                    * (T::from_f64(0.5)
                        * (T::from_f64(4.0) * t13 - T::from_f64(2.0) * t18
                            - (T::from_f64(2.0) * t13 - t18)) * t3 + g * t16
                        + gammaddot
                            * (T::from_f64(1.0 / 12.0)
                                * (T::from_f64(0.75) * (d_peg * d_peg) + h * h) + t10 * t10
                                + t16 * t16))) + f_z * t16 + f_x * t10,
                f_x - m * (t12 * t3 + gammaddot * t10),
                f_z - m * g - m * (gammaddot * t16 - t3 * t17),
            ),
        }
    }
    /// Material velocity of the peg at K, B1, B2 (rows) in rotating components (e_η, e_n, e_z) (m/s); replaces paper (10)–(13). The friction directions are −v/|v|.
    ///
    /// # Inputs
    /// - `x` = (`gamma`, `gammadot`)
    /// - `p` = (`D_hole`, `d_peg`, `H`, `m`, `g`, `f`, `gamma0`)
    ///
    /// # Outputs
    /// - `v`: 3×3 matrix
    ///
    /// # Cost
    /// 17 add/sub, 31 mul, 1 div, 0 sqrt, 4 transcendental, 0 branches; 20 `let`s.
    #[inline]
    pub fn contact_velocities<T: Real>(
        x: &SVector<T, 2>,
        p: &SVector<T, 7>,
    ) -> SMatrix<T, 3, 3> {
        let gamma = x[0];
        let gammadot = x[1];
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
        let sin_diff = (half_gamma0 - half_gamma).sin();
        let t4 = d_peg * sin_half_gamma * t0 * cos_half_gamma
            - T::from_f64(0.5) * cos_gamma * e * t3;
        let neg_half_delta = d_hole * sin_sum * sin_diff;
        let t5 = half_d + cos_gamma * (neg_half_delta * t3 - t4) - t1;
        let t6 = -gammadot * (neg_half_delta * t0 + t2 - (t2 + sin_gamma * t4));
        let t7 = gammadot
            * (t5 + t0 * t0 * (T::from_f64(0.5) * e + neg_half_delta * cos_gamma) + t1);
        Matrix3::new(
            t6,
            T::from_f64(0.0),
            gammadot * (t5 - (half_d - t1)),
            t6,
            T::from_f64(0.0),
            t7,
            t6,
            T::from_f64(0.0),
            t7,
        )
    }
    /// The outputs' struct, shared with `rigid_peg` (same fields).
    pub use super::rigid_peg::EnergyOut;
    /// Kinetic energy T = ½ m|v_C|² + ½ ωᵀIω (paper (22)–(23)) and total energy T + V with V = m g z_C (J).
    ///
    /// # Inputs
    /// - `x` = (`gamma`, `gammadot`)
    /// - `p` = (`D_hole`, `d_peg`, `H`, `m`, `g`, `f`, `gamma0`)
    ///
    /// # Outputs
    /// The fields of [`EnergyOut`]:
    /// - `kinetic`: scalar
    /// - `total`: scalar
    ///
    /// # Cost
    /// 15 add/sub, 36 mul, 1 div, 0 sqrt, 4 transcendental, 0 branches; 19 `let`s.
    #[inline]
    pub fn energy<T: Real>(x: &SVector<T, 2>, p: &SVector<T, 7>) -> EnergyOut<T> {
        let gamma = x[0];
        let gammadot = x[1];
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
        let half_d = T::from_f64(0.5) * d_hole;
        let lever = T::from_f64(0.5) * h - T::from_f64(0.5) * e * t0;
        let t1 = -cos_gamma * lever;
        let t2 = t0 * t0;
        let sin_diff = (half_gamma0 - half_gamma).sin();
        let t3 = d_peg * sin_half_gamma * t0 * cos_half_gamma
            - T::from_f64(0.5) * cos_gamma * e * t2;
        let t4 = t1 + sin_gamma * t3;
        let neg_half_delta = d_hole * sin_sum * sin_diff;
        let t5 = half_d + cos_gamma * (neg_half_delta * t2 - t3) - sin_gamma * lever;
        let t6 = gammadot * gammadot
            * (T::from_f64(0.5) * (t4 * t4 + t5 * t5)
                + T::from_f64(1.0 / 24.0)
                    * (T::from_f64(0.75) * (d_peg * d_peg) + h * h));
        EnergyOut {
            kinetic: t6 * m,
            total: -m * (g * (neg_half_delta * t0 + t1) - t6),
        }
    }
}
