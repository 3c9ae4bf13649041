// @generated readable copy of `pegdyn::generated::rigid_peg_frictionless` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generator snapshot::

/// Rigid three-point peg leaning on the hole edge at K, B1, B2 (*Peg-on-hole: fundamental principles of motion of a peg leaning on a horizontal hole edge*), variant `Frictionless`, derived by the generator (equations/src/models/rigid_peg.rs).
/// State x = (`gamma`, `psi`, `gammadot`, `psidot`); parameters p = (D_hole, d_peg, H, m, g, f, gamma0); loads = (`M_gamma`, `M_psi`, `F_x`, `F_y`, `F_z`).
/// Vectors in rotating components (e_η, e_n, e_z). SI units.
pub mod rigid_peg_frictionless {
    use nalgebra::{Matrix3, Matrix5, SMatrix, SVector, Vector5};
    use pegdyn::scalar::Real;
    /// Symbol names of the components of `x`, in order.
    pub const X_NAMES: [&str; 4] = ["gamma", "psi", "gammadot", "psidot"];
    /// Symbol names of the components of `p`, in order.
    pub const P_NAMES: [&str; 7] = ["D_hole", "d_peg", "H", "m", "g", "f", "gamma0"];
    /// Symbol names of the components of `loads`, in order.
    pub const LOADS_NAMES: [&str; 5] = ["M_gamma", "M_psi", "F_x", "F_y", "F_z"];
    /// Symbol names of the components of `qdd`, in order.
    pub const QDD_NAMES: [&str; 2] = ["gammaddot", "psiddot"];
    /// The struct of `p`, shared with `rigid_peg` (same components).
    pub use super::rigid_peg::Params;
    /// The struct of `x`, shared with `rigid_peg` (same components).
    pub use super::rigid_peg::State;
    /// The struct of `loads`, shared with `rigid_peg` (same components).
    pub use super::rigid_peg::Loads;
    /// The outputs' struct, shared with `rigid_peg` (same fields).
    pub use super::rigid_peg::LinearSystem;
    /// Forward dynamics (replaces paper (24)–(31)): A u = b for u = (`gammaddot`, `psiddot`, `N_K`, `N_B1`, `N_B2`) (rad/s², N), the applied loads and friction directions given.
    /// Rows: the Lagrange equations of γ and ψ (paper (26), (27)), then the centre-of-mass equations (28)–(31) along e_η, e_n, e_z (the fixed-frame (29)–(31) rotated by −ψ).
    /// A = ∂R/∂u, b = −R at u = 0, R the residual derived from T, V and the generalized forces.
    ///
    /// # Inputs
    /// - `x` = (`gamma`, `psi`, `gammadot`, `psidot`)
    /// - `p` = (`D_hole`, `d_peg`, `H`, `m`, `g`, `f`, `gamma0`)
    /// - `loads` = (`M_gamma`, `M_psi`, `F_x`, `F_y`, `F_z`)
    ///
    /// # Outputs
    /// The fields of [`LinearSystem`]:
    /// - `a`: 5×5 matrix
    /// - `b`: vector of 5
    ///
    /// # Cost
    /// 57 add/sub, 119 mul, 4 div, 1 sqrt, 6 transcendental, 0 branches; 59 `let`s.
    #[inline]
    pub fn forward<T: Real>(
        x: &SVector<T, 4>,
        p: &SVector<T, 7>,
        loads: &SVector<T, 5>,
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
        let gamma0 = p[6];
        let m_gamma = loads[0];
        let m_psi = loads[1];
        let f_x = loads[2];
        let f_y = loads[3];
        let f_z = loads[4];
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
        let half_e = T::from_f64(0.5) * e;
        let t13 = T::from_f64(1.0 / 12.0) * t7;
        let lever = T::from_f64(0.5) * h - T::from_f64(0.5) * twice_a2;
        let t14 = d_peg * sin_half_gamma * cos_half_gamma;
        let t15 = t14 * t1;
        let t16 = sin_gamma * lever;
        let t17 = t3 / (sin_gamma * sin_gamma * sin_gamma);
        let twice_lever = h - twice_a2;
        let t18 = twice_lever * twice_lever;
        let t19 = m * gammadot * psidot;
        let t20 = t1 * t1;
        let t21 = cos_gamma * t20;
        let t22 = t21 * e;
        let t23 = t15 - T::from_f64(0.5) * t22;
        let t24 = sin_gamma * t23;
        let t25 = T::from_f64(0.25)
            * (t2 * (T::from_f64(2.0) * h - T::from_f64(2.0) * twice_a2)
                * (T::from_f64(2.0) * t15 - t22));
        let t26 = t24 - cos_gamma * lever;
        let t27 = lever
            + t1
                * (half_e
                    - T::from_f64(0.5)
                        * (d_peg * (t0 - cos_half_gamma * cos_half_gamma))) + t17 * e
            - T::from_f64(2.0) * t14 * t21;
        let t28 = sin_gamma * t27 + T::from_f64(2.0) * cos_gamma * t23;
        let t29 = t26 * t28;
        let sin_diff = (half_gamma0 - half_gamma).sin();
        let t30 = sin_sum * sin_diff;
        let neg_half_delta = t30 * d_hole;
        let ob = (neg_half_delta * t1).hypot(half_d);
        let t31 = t1 / ob;
        let t32 = t31 * neg_half_delta;
        let t33 = t1 * (half_e + neg_half_delta * cos_gamma) * t31;
        let neg_half_gap = neg_half_delta * t21;
        let bb1 = (-T::from_f64(2.0) * neg_half_gap
            * (d_hole + T::from_f64(2.0) * neg_half_gap))
            .sqrt();
        let t34 = bb1 / ob;
        let t35 = cos_gamma * (neg_half_delta * t20 - t23);
        let t36 = half_d + t35 - t16;
        let t37 = d_hole
            * (t30 * (t1 + T::from_f64(2.0) * t17) + T::from_f64(0.5) * cos_gamma * t1)
            + cos_gamma * t27 - T::from_f64(2.0) * t24;
        let t38 = (d_hole + T::from_f64(2.0) * t35 - T::from_f64(2.0) * t16) * t37;
        LinearSystem {
            a: Matrix5::new(
                m * (t13 + t26 * t26 + t36 * t36),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                m
                    * (t2 * (T::from_f64(0.25) * t18 + t13)
                        + T::from_f64(0.125) * t3 * t6),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                m * t26,
                T::from_f64(0.0),
                -cos_gamma,
                t33,
                t33,
                T::from_f64(0.0),
                -t16 * m,
                T::from_f64(0.0),
                t34,
                -t34,
                m * t36,
                T::from_f64(0.0),
                -sin_gamma,
                t32,
                t32,
            ),
            b: Vector5::new(
                m_gamma
                    - m
                        * (-(t5 * (t13 - T::from_f64(0.125) * t6) * t11)
                            + T::from_f64(0.5)
                                * (t4 * (T::from_f64(4.0) * t29 - T::from_f64(2.0) * t38)
                                    - (t4 * (T::from_f64(2.0) * t29 - t38)
                                        + t5 * (T::from_f64(0.5) * t11 * t18 - t25))) + g * t36)
                    + t26 * (t8 + t9) + f_z * t36,
                m_psi + t16 * (t12 + t10)
                    + t19
                        * (t25
                            - t11
                                * (T::from_f64(0.5) * t18 - T::from_f64(0.25) * t6
                                    + T::from_f64(1.0 / 6.0) * t7)),
                t8 + t9 - m * (t28 * t4 + t16 * t5),
                -t12 - t10 - T::from_f64(2.0) * t19 * t26,
                f_z - m * g + m * t4 * t37,
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
    ///
    /// # Outputs
    /// The fields of [`LinearSystem`]:
    /// - `a`: 5×5 matrix
    /// - `b`: vector of 5
    ///
    /// # Cost
    /// 60 add/sub, 120 mul, 4 div, 1 sqrt, 6 transcendental, 0 branches; 59 `let`s.
    #[inline]
    pub fn prescribed<T: Real>(
        x: &SVector<T, 4>,
        qdd: &SVector<T, 2>,
        p: &SVector<T, 7>,
        loads: &SVector<T, 5>,
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
        let gamma0 = p[6];
        let f_x = loads[2];
        let f_y = loads[3];
        let f_z = loads[4];
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
        let half_e = T::from_f64(0.5) * e;
        let t13 = T::from_f64(1.0 / 12.0) * t7;
        let lever = T::from_f64(0.5) * h - T::from_f64(0.5) * twice_a2;
        let t14 = d_peg * sin_half_gamma * cos_half_gamma;
        let t15 = t14 * t1;
        let t16 = sin_gamma * lever;
        let t17 = t3 / (sin_gamma * sin_gamma * sin_gamma);
        let twice_lever = h - twice_a2;
        let t18 = twice_lever * twice_lever;
        let t19 = t1 * t1;
        let t20 = cos_gamma * t19;
        let t21 = t20 * e;
        let t22 = t15 - T::from_f64(0.5) * t21;
        let t23 = sin_gamma * t22;
        let t24 = T::from_f64(0.25)
            * (t2 * (T::from_f64(2.0) * h - T::from_f64(2.0) * twice_a2)
                * (T::from_f64(2.0) * t15 - t21));
        let t25 = t23 - cos_gamma * lever;
        let t26 = lever
            + t1
                * (half_e
                    - T::from_f64(0.5)
                        * (d_peg * (t0 - cos_half_gamma * cos_half_gamma))) + t17 * e
            - T::from_f64(2.0) * t14 * t20;
        let t27 = sin_gamma * t26 + T::from_f64(2.0) * cos_gamma * t22;
        let t28 = t25 * t27;
        let sin_diff = (half_gamma0 - half_gamma).sin();
        let t29 = sin_sum * sin_diff;
        let neg_half_delta = t29 * d_hole;
        let ob = (neg_half_delta * t1).hypot(half_d);
        let t30 = t1 / ob;
        let t31 = t30 * neg_half_delta;
        let t32 = t1 * (half_e + neg_half_delta * cos_gamma) * t30;
        let neg_half_gap = neg_half_delta * t20;
        let bb1 = (-T::from_f64(2.0) * neg_half_gap
            * (d_hole + T::from_f64(2.0) * neg_half_gap))
            .sqrt();
        let t33 = bb1 / ob;
        let t34 = cos_gamma * (neg_half_delta * t19 - t22);
        let t35 = half_d + t34 - t16;
        let t36 = d_hole
            * (t29 * (t1 + T::from_f64(2.0) * t17) + T::from_f64(0.5) * cos_gamma * t1)
            + cos_gamma * t26 - T::from_f64(2.0) * t23;
        let t37 = (d_hole + T::from_f64(2.0) * t34 - T::from_f64(2.0) * t16) * t36;
        let t38 = gammadot * psidot;
        LinearSystem {
            a: Matrix5::new(
                -T::from_f64(1.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                -T::from_f64(1.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                -cos_gamma,
                t32,
                t32,
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t33,
                -t33,
                T::from_f64(0.0),
                T::from_f64(0.0),
                -sin_gamma,
                t31,
                t31,
            ),
            b: Vector5::new(
                -(m
                    * (t5 * (T::from_f64(0.125) * t6 - t13) * t11
                        + T::from_f64(0.5)
                            * (t4 * (T::from_f64(4.0) * t28 - T::from_f64(2.0) * t37)
                                - (t4 * (T::from_f64(2.0) * t28 - t37)
                                    + t5 * (T::from_f64(0.5) * t11 * t18 - t24))) + g * t35
                        + gammaddot * (t13 + t25 * t25 + t35 * t35))) + t25 * (t8 + t9)
                    + f_z * t35,
                m
                    * (t38
                        * (t24
                            - t11
                                * (T::from_f64(0.5) * t18 - T::from_f64(0.25) * t6
                                    + T::from_f64(1.0 / 6.0) * t7))
                        - psiddot
                            * (t2 * (T::from_f64(0.25) * t18 + t13)
                                + T::from_f64(0.125) * t3 * t6)) + t16 * (t12 + t10),
                t8 + t9 - m * (t27 * t4 + gammaddot * t25 + t16 * t5),
                -t12 - t10 - m * (T::from_f64(2.0) * t38 * t25 - t16 * psiddot),
                f_z - m * g - m * (gammaddot * t35 - t4 * t36),
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
    /// The outputs' struct, shared with `rigid_peg` (same fields).
    pub use super::rigid_peg::EnergyOut;
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
}
