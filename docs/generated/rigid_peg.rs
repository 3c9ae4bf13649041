// @generated readable copy of `pegdyn::generated::rigid_peg` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generated_snapshot

/// Rigid peg leaning on the hole edge at K, B1, B2 (seed 000), variant `Full`, derived by the generator (equations/src/models/rigid_peg.rs).
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
    /// - `a`: 5×5 matrix
    /// - `b`: vector of 5
    ///
    /// # Cost
    /// 92 add/sub, 253 mul, 4 div, 1 sqrt, 6 transcendental, 0 branches; 59 `let`s.
    #[inline]
    pub fn forward<T: Real>(
        x: &SVector<T, 4>,
        p: &SVector<T, 7>,
        loads: &SVector<T, 5>,
        t: &SVector<T, 9>,
    ) -> (SMatrix<T, 5, 5>, SVector<T, 5>) {
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
        let t0 = T::from_f64(0.5) * gamma0;
        let t1 = T::from_f64(0.5) * gamma;
        let t2 = (t0 + t1).sin();
        let t3 = (t0 - T::from_f64(0.5) * gamma).sin();
        let (t4, t23) = t1.sin_cos();
        let t5 = t4 * t4;
        let t6 = d_hole - d_peg + T::from_f64(2.0) * d_peg * t5;
        let t7 = T::from_f64(1.0) / sin_gamma;
        let t8 = -d_hole * t2 * t3 * t7;
        let t9 = T::from_f64(0.5) * t6 * t7;
        let t10 = t9 + d_hole * cos_gamma * t2 * t3 * t7;
        let t11 = sin_gamma * sin_gamma;
        let t12 = T::from_f64(1.0) / (sin_gamma * sin_gamma);
        let t13 = T::from_f64(2.0) * d_hole * cos_gamma * t2 * t3 * t12;
        let t14 = d_hole * cos_gamma * t2 * t3 * t12;
        let t15 = (-T::from_f64(2.0) * d_hole * cos_gamma * t2 * t3 * t12
            * (d_hole + t13))
            .sqrt();
        let t16 = T::from_f64(0.5) * d_hole;
        let t17 = -T::from_f64(0.5) * t6 * t7;
        let t18 = T::from_f64(0.5) * h + t17;
        let t19 = -(T::from_f64(0.5) * h) + t9;
        let t20 = (d_hole * t2 * t3 * t7).hypot(t16);
        let t21 = T::from_f64(1.0) / t20;
        let t22 = cos_gamma * t19;
        let t24 = d_peg * t4 * t7 * t23 - T::from_f64(0.5) * cos_gamma * t6 * t12;
        let t25 = sin_gamma * t24;
        let t26 = t22 + t25;
        let t27 = -sin_gamma * t18;
        let t28 = -(d_peg * t4 * t7 * t23) + T::from_f64(0.5) * cos_gamma * t6 * t12;
        let t29 = cos_gamma * t28;
        let t30 = t16 + t14 + t27 + t29;
        let t31 = -sin_gamma * t19;
        let t32 = t23 * t23;
        let t33 = T::from_f64(1.0) / (sin_gamma * sin_gamma * sin_gamma);
        let t34 = cos_gamma * cos_gamma;
        let t35 = t31
            + sin_gamma
                * (t9 + T::from_f64(0.5) * d_peg * t7 * t32
                    - T::from_f64(0.5) * d_peg * t5 * t7 + t6 * t33 * t34
                    - T::from_f64(2.0) * d_peg * cos_gamma * t4 * t12 * t23)
            + T::from_f64(2.0) * cos_gamma * t24;
        let t36 = gammadot * gammadot;
        let t37 = t8 - T::from_f64(2.0) * d_hole * t2 * t3 * t33 * t34
            - T::from_f64(0.5) * d_hole * cos_gamma * t7 - cos_gamma * t18
            + cos_gamma
                * (t17 - T::from_f64(0.5) * d_peg * t7 * t32
                    + T::from_f64(0.5) * d_peg * t5 * t7 - t6 * t33 * t34
                    + T::from_f64(2.0) * d_peg * cos_gamma * t4 * t12 * t23)
            - T::from_f64(2.0) * sin_gamma * t28;
        let t38 = psidot * psidot;
        let t39 = d_peg * d_peg;
        let t40 = T::from_f64(0.75) * t39 + h * h;
        let t41 = h - t6 * t7;
        let t42 = t41 * t41;
        let (sin_psi, cos_psi) = psi.sin_cos();
        let t43 = f_x * cos_psi;
        let t44 = f_y * sin_psi;
        let t45 = f_y * cos_psi;
        let t46 = -f_x * sin_psi;
        let t47 = t8 + cos_gamma * t18 + t22 + t25;
        let t48 = t16 + t7 * t10 + t14 + t27 + t29 + t31;
        let t49 = T::from_f64(2.0) * cos_gamma * t19
            + T::from_f64(2.0) * sin_gamma * t24;
        let t50 = d_hole + t13 - T::from_f64(2.0) * sin_gamma * t18
            + T::from_f64(2.0) * cos_gamma * t28;
        let t51 = cos_gamma * t6 * t12 - T::from_f64(2.0) * d_peg * t4 * t7 * t23;
        let t52 = T::from_f64(2.0) * h - T::from_f64(2.0) * t6 * t7;
        let t53 = t7 * t10 * t21;
        let t54 = d_hole * t2 * t3 * t7 * t21;
        let a = Matrix5::new(
            m
                * (T::from_f64(0.08333333333333333) * t40
                    + T::from_f64(0.5)
                        * (T::from_f64(2.0) * (t26 * t26)
                            + T::from_f64(2.0) * (t30 * t30))),
            T::from_f64(0.0),
            f * (-(t_k_eta * t47) - t_k_z * (t14 + t27 + t29 + t31)),
            f * (-(t_b1_eta * t47) - t_b1_z * t48),
            f * (-(t_b2_eta * t47) - t_b2_z * t48),
            T::from_f64(0.0),
            m
                * (T::from_f64(0.25) * t11 * t42 + T::from_f64(0.125) * t34 * t39
                    + T::from_f64(0.08333333333333333) * t11 * t40),
            T::from_f64(0.5) * d_hole * f * t_k_n,
            f * (t_b1_eta * t15 - t_b1_n * t7 * t10),
            f * (-(t_b2_eta * t15) - t_b2_n * t7 * t10),
            m * t26,
            T::from_f64(0.0),
            -(f * t_k_eta) - cos_gamma,
            -(f * t_b1_eta) + t53,
            -(f * t_b2_eta) + t53,
            T::from_f64(0.0),
            m * sin_gamma * t19,
            -f * t_k_n,
            -(f * t_b1_n) + t15 * t21,
            -(f * t_b2_n) - t15 * t21,
            m * t30,
            T::from_f64(0.0),
            -(f * t_k_z) - sin_gamma,
            -(f * t_b1_z) + t54,
            -(f * t_b2_z) + t54,
        );
        let b = Vector5::new(
            m_gamma + t26 * (t43 + t44) + f_z * t30 - m * g * t30
                + T::from_f64(0.5) * m
                    * (t35 * t36 * t49
                        + T::from_f64(0.5) * sin_gamma * cos_gamma * t38 * t42
                        + T::from_f64(0.25) * t11 * t38 * t51 * t52 + t36 * t37 * t50)
                - T::from_f64(0.125) * m * sin_gamma * cos_gamma * t38 * t39
                + T::from_f64(0.08333333333333333) * m * sin_gamma * cos_gamma * t38
                    * t40
                - T::from_f64(0.5) * m * gammadot
                    * (gammadot
                        * (T::from_f64(2.0) * t35 * t49 + T::from_f64(2.0) * t37 * t50)),
            m_psi + sin_gamma * t19 * (t45 + t46)
                - gammadot
                    * (m * psidot
                        * (T::from_f64(0.5) * sin_gamma * cos_gamma * t42
                            + T::from_f64(0.25) * t11 * t51 * t52
                            - T::from_f64(0.25) * sin_gamma * cos_gamma * t39
                            + T::from_f64(0.16666666666666666) * sin_gamma * cos_gamma
                                * t40)),
            t43 + t44 - m * (t35 * t36 - sin_gamma * t19 * t38),
            t45 + t46
                - m
                    * (gammadot
                        * (psidot * (cos_gamma * t19 + sin_gamma * t24) + psidot * t26)),
            f_z - m * g - m * t36 * t37,
        );
        (a, b)
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
    /// - `a`: 5×5 matrix
    /// - `b`: vector of 5
    ///
    /// # Cost
    /// 95 add/sub, 256 mul, 4 div, 1 sqrt, 6 transcendental, 0 branches; 59 `let`s.
    #[inline]
    pub fn prescribed<T: Real>(
        x: &SVector<T, 4>,
        qdd: &SVector<T, 2>,
        p: &SVector<T, 7>,
        loads: &SVector<T, 5>,
        t: &SVector<T, 9>,
    ) -> (SMatrix<T, 5, 5>, SVector<T, 5>) {
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
        let t0 = T::from_f64(0.5) * gamma0;
        let t1 = T::from_f64(0.5) * gamma;
        let t2 = (t0 + t1).sin();
        let t3 = (t0 - T::from_f64(0.5) * gamma).sin();
        let (t4, t23) = t1.sin_cos();
        let t5 = t4 * t4;
        let t6 = d_hole - d_peg + T::from_f64(2.0) * d_peg * t5;
        let t7 = T::from_f64(1.0) / sin_gamma;
        let t8 = -d_hole * t2 * t3 * t7;
        let t9 = T::from_f64(0.5) * t6 * t7;
        let t10 = t9 + d_hole * cos_gamma * t2 * t3 * t7;
        let t11 = sin_gamma * sin_gamma;
        let t12 = T::from_f64(1.0) / (sin_gamma * sin_gamma);
        let t13 = T::from_f64(2.0) * d_hole * cos_gamma * t2 * t3 * t12;
        let t14 = d_hole * cos_gamma * t2 * t3 * t12;
        let t15 = (-T::from_f64(2.0) * d_hole * cos_gamma * t2 * t3 * t12
            * (d_hole + t13))
            .sqrt();
        let t16 = T::from_f64(0.5) * d_hole;
        let t17 = -T::from_f64(0.5) * t6 * t7;
        let t18 = T::from_f64(0.5) * h + t17;
        let t19 = -(T::from_f64(0.5) * h) + t9;
        let t20 = (d_hole * t2 * t3 * t7).hypot(t16);
        let t21 = T::from_f64(1.0) / t20;
        let t22 = cos_gamma * t19;
        let t24 = d_peg * t4 * t7 * t23 - T::from_f64(0.5) * cos_gamma * t6 * t12;
        let t25 = sin_gamma * t24;
        let t26 = t22 + t25;
        let t27 = -sin_gamma * t18;
        let t28 = -(d_peg * t4 * t7 * t23) + T::from_f64(0.5) * cos_gamma * t6 * t12;
        let t29 = cos_gamma * t28;
        let t30 = t16 + t14 + t27 + t29;
        let t31 = -sin_gamma * t19;
        let t32 = t23 * t23;
        let t33 = T::from_f64(1.0) / (sin_gamma * sin_gamma * sin_gamma);
        let t34 = cos_gamma * cos_gamma;
        let t35 = t31
            + sin_gamma
                * (t9 + T::from_f64(0.5) * d_peg * t7 * t32
                    - T::from_f64(0.5) * d_peg * t5 * t7 + t6 * t33 * t34
                    - T::from_f64(2.0) * d_peg * cos_gamma * t4 * t12 * t23)
            + T::from_f64(2.0) * cos_gamma * t24;
        let t36 = gammadot * gammadot;
        let t37 = t8 - T::from_f64(2.0) * d_hole * t2 * t3 * t33 * t34
            - T::from_f64(0.5) * d_hole * cos_gamma * t7 - cos_gamma * t18
            + cos_gamma
                * (t17 - T::from_f64(0.5) * d_peg * t7 * t32
                    + T::from_f64(0.5) * d_peg * t5 * t7 - t6 * t33 * t34
                    + T::from_f64(2.0) * d_peg * cos_gamma * t4 * t12 * t23)
            - T::from_f64(2.0) * sin_gamma * t28;
        let t38 = psidot * psidot;
        let t39 = d_peg * d_peg;
        let t40 = T::from_f64(0.75) * t39 + h * h;
        let t41 = h - t6 * t7;
        let t42 = t41 * t41;
        let (sin_psi, cos_psi) = psi.sin_cos();
        let t43 = f_x * cos_psi;
        let t44 = f_y * sin_psi;
        let t45 = f_y * cos_psi;
        let t46 = -f_x * sin_psi;
        let t47 = t8 + cos_gamma * t18 + t22 + t25;
        let t48 = t16 + t7 * t10 + t14 + t27 + t29 + t31;
        let t49 = T::from_f64(2.0) * cos_gamma * t19
            + T::from_f64(2.0) * sin_gamma * t24;
        let t50 = d_hole + t13 - T::from_f64(2.0) * sin_gamma * t18
            + T::from_f64(2.0) * cos_gamma * t28;
        let t51 = cos_gamma * t6 * t12 - T::from_f64(2.0) * d_peg * t4 * t7 * t23;
        let t52 = T::from_f64(2.0) * h - T::from_f64(2.0) * t6 * t7;
        let t53 = t7 * t10 * t21;
        let t54 = d_hole * t2 * t3 * t7 * t21;
        let a = Matrix5::new(
            -T::from_f64(1.0),
            T::from_f64(0.0),
            f * (-(t_k_eta * t47) - t_k_z * (t14 + t27 + t29 + t31)),
            f * (-(t_b1_eta * t47) - t_b1_z * t48),
            f * (-(t_b2_eta * t47) - t_b2_z * t48),
            T::from_f64(0.0),
            -T::from_f64(1.0),
            T::from_f64(0.5) * d_hole * f * t_k_n,
            f * (t_b1_eta * t15 - t_b1_n * t7 * t10),
            f * (-(t_b2_eta * t15) - t_b2_n * t7 * t10),
            T::from_f64(0.0),
            T::from_f64(0.0),
            -(f * t_k_eta) - cos_gamma,
            -(f * t_b1_eta) + t53,
            -(f * t_b2_eta) + t53,
            T::from_f64(0.0),
            T::from_f64(0.0),
            -f * t_k_n,
            -(f * t_b1_n) + t15 * t21,
            -(f * t_b2_n) - t15 * t21,
            T::from_f64(0.0),
            T::from_f64(0.0),
            -(f * t_k_z) - sin_gamma,
            -(f * t_b1_z) + t54,
            -(f * t_b2_z) + t54,
        );
        let b = Vector5::new(
            t26 * (t43 + t44) + f_z * t30 - m * g * t30
                + T::from_f64(0.5) * m
                    * (t35 * t36 * t49
                        + T::from_f64(0.5) * sin_gamma * cos_gamma * t38 * t42
                        + T::from_f64(0.25) * t11 * t38 * t51 * t52 + t36 * t37 * t50)
                - T::from_f64(0.125) * m * sin_gamma * cos_gamma * t38 * t39
                + T::from_f64(0.08333333333333333) * m * sin_gamma * cos_gamma * t38
                    * t40
                - T::from_f64(0.5) * m * gammadot
                    * (gammadot
                        * (T::from_f64(2.0) * t35 * t49 + T::from_f64(2.0) * t37 * t50))
                - gammaddot
                    * (m
                        * (T::from_f64(0.08333333333333333) * t40
                            + T::from_f64(0.5)
                                * (T::from_f64(2.0) * (t26 * t26)
                                    + T::from_f64(2.0) * (t30 * t30)))),
            sin_gamma * t19 * (t45 + t46)
                - gammadot
                    * (m * psidot
                        * (T::from_f64(0.5) * sin_gamma * cos_gamma * t42
                            + T::from_f64(0.25) * t11 * t51 * t52
                            - T::from_f64(0.25) * sin_gamma * cos_gamma * t39
                            + T::from_f64(0.16666666666666666) * sin_gamma * cos_gamma
                                * t40))
                - psiddot
                    * (m
                        * (T::from_f64(0.25) * t11 * t42 + T::from_f64(0.125) * t34 * t39
                            + T::from_f64(0.08333333333333333) * t11 * t40)),
            t43 + t44 - m * (t35 * t36 + gammaddot * t26 - sin_gamma * t19 * t38),
            t45 + t46
                - m
                    * (gammadot * (psidot * (cos_gamma * t19 + sin_gamma * t24))
                        + psiddot * sin_gamma * t19 + gammadot * psidot * t26),
            f_z - m * g - m * (t36 * t37 + gammaddot * t30),
        );
        (a, b)
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
    /// 26 add/sub, 67 mul, 2 div, 1 sqrt, 4 transcendental, 0 branches; 24 `let`s.
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
        let t0 = T::from_f64(0.5) * gamma0;
        let t1 = T::from_f64(0.5) * gamma;
        let t2 = (t0 + t1).sin();
        let t3 = (t0 - T::from_f64(0.5) * gamma).sin();
        let (t4, t12) = t1.sin_cos();
        let t5 = d_hole - d_peg + T::from_f64(2.0) * d_peg * (t4 * t4);
        let t6 = T::from_f64(1.0) / sin_gamma;
        let t7 = T::from_f64(0.5) * t5 * t6;
        let t8 = T::from_f64(1.0) / (sin_gamma * sin_gamma);
        let t9 = (-T::from_f64(2.0) * d_hole * cos_gamma * t2 * t3 * t8
            * (d_hole + T::from_f64(2.0) * d_hole * cos_gamma * t2 * t3 * t8))
            .sqrt();
        let t10 = T::from_f64(0.5) * h - T::from_f64(0.5) * t5 * t6;
        let t11 = -(T::from_f64(0.5) * h) + t7;
        let t13 = gammadot
            * (cos_gamma * t11
                + sin_gamma
                    * (d_peg * t4 * t6 * t12 - T::from_f64(0.5) * cos_gamma * t5 * t8));
        let t14 = gammadot
            * (T::from_f64(0.5) * d_hole + d_hole * cos_gamma * t2 * t3 * t8
                - sin_gamma * t10
                + cos_gamma
                    * (-(d_peg * t4 * t6 * t12)
                        + T::from_f64(0.5) * cos_gamma * t5 * t8));
        let t15 = psidot * sin_gamma * t11;
        let t16 = -sin_gamma * t11;
        let t17 = -(T::from_f64(0.5) * d_hole) + t16;
        let t18 = -gammadot * (d_hole * t2 * t3 * t6 - cos_gamma * t10);
        let t19 = t6 * (t7 + d_hole * cos_gamma * t2 * t3 * t6) + t16;
        let t20 = t15 + psidot * t19;
        let t21 = t14 + gammadot * t19;
        Matrix3::new(
            t13 + t18,
            t15 + psidot * t17,
            t14 + gammadot * t17,
            t13 + t18 - psidot * t9,
            t20,
            t21,
            t13 + t18 + psidot * t9,
            t20,
            t21,
        )
    }
    /// Kinetic energy T = ½ m|v_C|² + ½ ωᵀIω (paper (22)–(23)) and total energy T + V with V = m g z_C (J).
    ///
    /// # Inputs
    /// - `x` = (`gamma`, `psi`, `gammadot`, `psidot`)
    /// - `p` = (`D_hole`, `d_peg`, `H`, `m`, `g`, `f`, `gamma0`)
    ///
    /// # Outputs
    /// - `kinetic`: scalar
    /// - `total`: scalar
    ///
    /// # Cost
    /// 23 add/sub, 66 mul, 2 div, 0 sqrt, 4 transcendental, 0 branches; 22 `let`s.
    #[inline]
    pub fn energy<T: Real>(x: &SVector<T, 4>, p: &SVector<T, 7>) -> (T, T) {
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
        let t0 = T::from_f64(0.5) * gamma0;
        let t1 = T::from_f64(0.5) * gamma;
        let t2 = (t0 + t1).sin();
        let t3 = (t0 - T::from_f64(0.5) * gamma).sin();
        let (t4, t10) = t1.sin_cos();
        let t5 = d_hole - d_peg + T::from_f64(2.0) * d_peg * (t4 * t4);
        let t6 = T::from_f64(1.0) / sin_gamma;
        let t7 = sin_gamma * sin_gamma;
        let t8 = T::from_f64(1.0) / (sin_gamma * sin_gamma);
        let t9 = T::from_f64(0.5) * h - T::from_f64(0.5) * t5 * t6;
        let t11 = cos_gamma * (-(T::from_f64(0.5) * h) + T::from_f64(0.5) * t5 * t6)
            + sin_gamma
                * (d_peg * t4 * t6 * t10 - T::from_f64(0.5) * cos_gamma * t5 * t8);
        let t12 = T::from_f64(0.5) * d_hole + d_hole * cos_gamma * t2 * t3 * t8
            - sin_gamma * t9
            + cos_gamma
                * (-(d_peg * t4 * t6 * t10) + T::from_f64(0.5) * cos_gamma * t5 * t8);
        let t13 = gammadot * gammadot;
        let t14 = psidot * psidot;
        let t15 = d_peg * d_peg;
        let t16 = h - t5 * t6;
        let t17 = T::from_f64(0.5) * m
            * (t13 * (t11 * t11) + T::from_f64(0.25) * t7 * t14 * (t16 * t16)
                + t13 * (t12 * t12));
        let t18 = T::from_f64(0.0625) * m * (cos_gamma * cos_gamma) * t14 * t15;
        let t19 = T::from_f64(0.041666666666666664) * m
            * (T::from_f64(0.75) * t15 + h * h) * (t13 + t7 * t14);
        let kinetic = t17 + t18 + t19;
        let total = t17 + t18 + t19
            + m * g * (-(d_hole * t2 * t3 * t6) + cos_gamma * t9);
        (kinetic, total)
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
    /// 10 add/sub, 56 mul, 3 div, 1 sqrt, 5 transcendental, 0 branches; 18 `let`s.
    #[inline]
    pub fn geometry<T: Real>(x: &SVector<T, 4>, p: &SVector<T, 7>) -> SVector<T, 13> {
        let gamma = x[0];
        let d_hole = p[0];
        let d_peg = p[1];
        let h = p[2];
        let gamma0 = p[6];
        let (sin_gamma, cos_gamma) = gamma.sin_cos();
        let t0 = T::from_f64(0.5) * gamma0;
        let t1 = T::from_f64(0.5) * gamma;
        let t2 = (t0 + t1).sin();
        let t3 = (t0 - T::from_f64(0.5) * gamma).sin();
        let t4 = t1.sin();
        let t5 = d_hole - d_peg + T::from_f64(2.0) * d_peg * (t4 * t4);
        let t6 = T::from_f64(1.0) / sin_gamma;
        let t7 = -d_hole * t2 * t3 * t6;
        let t8 = T::from_f64(0.5) * t5 * t6;
        let t9 = t8 + d_hole * cos_gamma * t2 * t3 * t6;
        let t10 = t6 * t9;
        let t11 = d_hole * t2 * t3 * t6;
        let t12 = T::from_f64(1.0) / (sin_gamma * sin_gamma);
        let t13 = (-T::from_f64(2.0) * d_hole * cos_gamma * t2 * t3 * t12
            * (d_hole + T::from_f64(2.0) * d_hole * cos_gamma * t2 * t3 * t12))
            .sqrt();
        let t14 = T::from_f64(1.0) / d_hole;
        let t15 = t10.hypot(t11);
        SMatrix::<
            T,
            13,
            1,
        >::from_row_slice(
            &[
                t7,
                t8,
                t10,
                t6 * (T::from_f64(0.5) * cos_gamma * t5 * t6 + t11),
                t13,
                T::from_f64(2.0) * t13 * t14,
                T::from_f64(2.0) * t6 * t9 * t14,
                sin_gamma * (-(T::from_f64(0.5) * h) + t8),
                t7 + cos_gamma * (T::from_f64(0.5) * h - T::from_f64(0.5) * t5 * t6),
                -T::from_f64(2.0) * d_hole * t2 * t3 * t12,
                T::from_f64(2.0) * t15,
                -t6 * t9,
                -T::from_f64(2.0) * d_hole * t2 * t3 * t6,
            ],
        )
    }
}
