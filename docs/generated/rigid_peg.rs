// @generated readable copy of `pegdyn::generated::rigid_peg` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generated_snapshot

/// Rigid peg leaning on the hole edge at K, B1, B2 (seed 000), variant `Full`, derived by the generator (equations/src/models/rigid_peg.rs).
/// State x = (`gamma`, `psi`, `gammadot`, `psidot`); parameters p = (D_hole, d_peg, H, m, g, f, gamma0); loads = (`M_gamma`, `M_psi`, `F_x`, `F_y`, `F_z`); friction directions t = (`t_K_eta`, `t_K_n`, `t_K_z`, `t_B1_eta`, `t_B1_n`, `t_B1_z`, `t_B2_eta`, `t_B2_n`, `t_B2_z`) (unit, force on the peg).
/// Vectors in rotating components (e_η, e_n, e_z). SI units.
pub mod rigid_peg {
    use nalgebra::{Matrix3, Matrix5, SMatrix, SVector, Vector5};
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
    /// 100 add/sub, 298 mul, 4 div, 1 sqrt, 11 transcendental, 0 branches; 63 `let`s.
    #[inline]
    pub fn forward(
        x: &SVector<f64, 4>,
        p: &SVector<f64, 7>,
        loads: &SVector<f64, 5>,
        t: &SVector<f64, 9>,
    ) -> (SMatrix<f64, 5, 5>, SVector<f64, 5>) {
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
        let sin_gamma = gamma.sin();
        let cos_gamma = gamma.cos();
        let t0 = 0.5 * gamma0;
        let t1 = 0.5 * gamma;
        let t2 = t0 + t1;
        let t3 = t2.sin();
        let t4 = t0 - 0.5 * gamma;
        let t5 = t4.sin();
        let t6 = t1.sin();
        let t7 = t6 * t6;
        let t8 = d_hole - d_peg + 2.0 * d_peg * t7;
        let t9 = 1.0 / sin_gamma;
        let t10 = 0.5 * t8 * t9;
        let t11 = t10 + d_hole * cos_gamma * t3 * t5 * t9;
        let t12 = sin_gamma * sin_gamma;
        let t13 = 1.0 / (sin_gamma * sin_gamma);
        let t14 = 2.0 * d_hole * cos_gamma * t3 * t5 * t13;
        let t15 = d_hole * cos_gamma * t3 * t5 * t13;
        let t16 = (-2.0 * d_hole * cos_gamma * t3 * t5 * t13 * (d_hole + t14)).sqrt();
        let t17 = -0.5 * t8 * t9;
        let t18 = 0.5 * h + t17;
        let t19 = t10 - 0.5 * h;
        let t20 = (d_hole * t3 * t5 * t9).hypot(0.5 * d_hole);
        let t21 = 1.0 / t20;
        let t22 = cos_gamma * t19;
        let t23 = t1.cos();
        let t24 = d_peg * t6 * t9 * t23 - 0.5 * cos_gamma * t8 * t13;
        let t25 = sin_gamma * t24;
        let t26 = t22 + t25;
        let t27 = t2.cos();
        let t28 = -0.5 * d_hole * t5 * t9 * t27;
        let t29 = t4.cos();
        let t30 = 0.5 * d_hole * t3 * t9 * t29;
        let t31 = -sin_gamma * t18;
        let t32 = -(d_peg * t6 * t9 * t23) + 0.5 * cos_gamma * t8 * t13;
        let t33 = cos_gamma * t32;
        let t34 = t15 + t28 + t30 + t31 + t33;
        let t35 = -sin_gamma * t19;
        let t36 = t23 * t23;
        let t37 = 1.0 / (sin_gamma * sin_gamma * sin_gamma);
        let t38 = cos_gamma * cos_gamma;
        let t39 = t35
            + sin_gamma
                * (t10 + 0.5 * d_peg * t9 * t36 - 0.5 * d_peg * t7 * t9 + t8 * t37 * t38
                    - 2.0 * d_peg * cos_gamma * t6 * t13 * t23) + 2.0 * cos_gamma * t24;
        let t40 = gammadot * gammadot;
        let t41 = -(2.0 * d_hole * t3 * t5 * t37 * t38)
            + d_hole * cos_gamma * t5 * t13 * t27 - cos_gamma * t18
            + cos_gamma
                * (t17 - 0.5 * d_peg * t9 * t36 + 0.5 * d_peg * t7 * t9 - t8 * t37 * t38
                    + 2.0 * d_peg * cos_gamma * t6 * t13 * t23)
            - 0.5 * d_hole * t3 * t5 * t9 - d_hole * cos_gamma * t3 * t13 * t29
            + 0.5 * d_hole * t9 * t27 * t29 - 2.0 * sin_gamma * t32;
        let t42 = psidot * psidot;
        let t43 = d_peg * d_peg;
        let t44 = 0.75 * t43 + h * h;
        let t45 = h - t8 * t9;
        let t46 = t45 * t45;
        let sin_psi = psi.sin();
        let cos_psi = psi.cos();
        let t47 = f_x * cos_psi;
        let t48 = f_y * sin_psi;
        let t49 = f_y * cos_psi;
        let t50 = -f_x * sin_psi;
        let t51 = -(d_hole * t3 * t5 * t9) + cos_gamma * t18 + t22 + t25;
        let t52 = t9 * t11 + t15 + t28 + t30 + t31 + t33 + t35;
        let t53 = 2.0 * cos_gamma * t19 + 2.0 * sin_gamma * t24;
        let t54 = t14 + d_hole * t3 * t9 * t29 - d_hole * t5 * t9 * t27
            - 2.0 * sin_gamma * t18 + 2.0 * cos_gamma * t32;
        let t55 = cos_gamma * t8 * t13 - 2.0 * d_peg * t6 * t9 * t23;
        let t56 = 2.0 * h - 2.0 * t8 * t9;
        let t57 = t9 * t11 * t21;
        let t58 = d_hole * t3 * t5 * t9 * t21;
        let a = Matrix5::new(
            0.08333333333333333 * m * t44
                + 0.5 * m * (2.0 * (t26 * t26) + 2.0 * (t34 * t34)),
            0.0,
            -(f * t_k_eta * t51)
                - f * t_k_z * (t15 - 0.5 * d_hole + t28 + t30 + t31 + t33 + t35),
            -(f * t_b1_eta * t51) - f * t_b1_z * t52,
            -(f * t_b2_eta * t51) - f * t_b2_z * t52,
            0.0,
            0.25 * m * t12 * t46 + 0.125 * m * t38 * t43
                + 0.08333333333333333 * m * t12 * t44,
            0.5 * d_hole * f * t_k_n,
            f * t_b1_eta * t16 - f * t_b1_n * t9 * t11,
            -(f * t_b2_eta * t16) - f * t_b2_n * t9 * t11,
            m * t26,
            0.0,
            -cos_gamma - f * t_k_eta,
            t57 - f * t_b1_eta,
            t57 - f * t_b2_eta,
            0.0,
            m * sin_gamma * t19,
            -f * t_k_n,
            t16 * t21 - f * t_b1_n,
            -(t16 * t21) - f * t_b2_n,
            m * t34,
            0.0,
            -sin_gamma - f * t_k_z,
            t58 - f * t_b1_z,
            t58 - f * t_b2_z,
        );
        let b = Vector5::new(
            m_gamma + t26 * (t47 + t48) + f_z * t34 - m * g * t34
                + 0.5 * m
                    * (t39 * t40 * t53 + 0.5 * sin_gamma * cos_gamma * t42 * t46
                        + 0.25 * t12 * t42 * t55 * t56 + t40 * t41 * t54)
                - 0.125 * m * sin_gamma * cos_gamma * t42 * t43
                + 0.08333333333333333 * m * sin_gamma * cos_gamma * t42 * t44
                - 0.5 * m * gammadot
                    * (2.0 * gammadot * t39 * t53 + 2.0 * gammadot * t41 * t54),
            m_psi + sin_gamma * t19 * (t49 + t50)
                - gammadot
                    * (0.5 * m * psidot * sin_gamma * cos_gamma * t46
                        + 0.25 * m * psidot * t12 * t55 * t56
                        - 0.25 * m * psidot * sin_gamma * cos_gamma * t43
                        + 0.16666666666666666 * m * psidot * sin_gamma * cos_gamma
                            * t44),
            t47 + t48 - m * (t39 * t40 - sin_gamma * t19 * t42),
            t49 + t50
                - m
                    * (gammadot * (psidot * cos_gamma * t19 + psidot * sin_gamma * t24)
                        + gammadot * psidot * t26),
            f_z - m * g - m * t40 * t41,
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
    /// 103 add/sub, 300 mul, 4 div, 1 sqrt, 11 transcendental, 0 branches; 63 `let`s.
    #[inline]
    pub fn prescribed(
        x: &SVector<f64, 4>,
        qdd: &SVector<f64, 2>,
        p: &SVector<f64, 7>,
        loads: &SVector<f64, 5>,
        t: &SVector<f64, 9>,
    ) -> (SMatrix<f64, 5, 5>, SVector<f64, 5>) {
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
        let sin_gamma = gamma.sin();
        let cos_gamma = gamma.cos();
        let t0 = 0.5 * gamma0;
        let t1 = 0.5 * gamma;
        let t2 = t0 + t1;
        let t3 = t2.sin();
        let t4 = t0 - 0.5 * gamma;
        let t5 = t4.sin();
        let t6 = t1.sin();
        let t7 = t6 * t6;
        let t8 = d_hole - d_peg + 2.0 * d_peg * t7;
        let t9 = 1.0 / sin_gamma;
        let t10 = 0.5 * t8 * t9;
        let t11 = t10 + d_hole * cos_gamma * t3 * t5 * t9;
        let t12 = sin_gamma * sin_gamma;
        let t13 = 1.0 / (sin_gamma * sin_gamma);
        let t14 = 2.0 * d_hole * cos_gamma * t3 * t5 * t13;
        let t15 = d_hole * cos_gamma * t3 * t5 * t13;
        let t16 = (-2.0 * d_hole * cos_gamma * t3 * t5 * t13 * (d_hole + t14)).sqrt();
        let t17 = -0.5 * t8 * t9;
        let t18 = 0.5 * h + t17;
        let t19 = t10 - 0.5 * h;
        let t20 = (d_hole * t3 * t5 * t9).hypot(0.5 * d_hole);
        let t21 = 1.0 / t20;
        let t22 = cos_gamma * t19;
        let t23 = t1.cos();
        let t24 = d_peg * t6 * t9 * t23 - 0.5 * cos_gamma * t8 * t13;
        let t25 = sin_gamma * t24;
        let t26 = t22 + t25;
        let t27 = t2.cos();
        let t28 = -0.5 * d_hole * t5 * t9 * t27;
        let t29 = t4.cos();
        let t30 = 0.5 * d_hole * t3 * t9 * t29;
        let t31 = -sin_gamma * t18;
        let t32 = -(d_peg * t6 * t9 * t23) + 0.5 * cos_gamma * t8 * t13;
        let t33 = cos_gamma * t32;
        let t34 = t15 + t28 + t30 + t31 + t33;
        let t35 = -sin_gamma * t19;
        let t36 = t23 * t23;
        let t37 = 1.0 / (sin_gamma * sin_gamma * sin_gamma);
        let t38 = cos_gamma * cos_gamma;
        let t39 = t35
            + sin_gamma
                * (t10 + 0.5 * d_peg * t9 * t36 - 0.5 * d_peg * t7 * t9 + t8 * t37 * t38
                    - 2.0 * d_peg * cos_gamma * t6 * t13 * t23) + 2.0 * cos_gamma * t24;
        let t40 = gammadot * gammadot;
        let t41 = -(2.0 * d_hole * t3 * t5 * t37 * t38)
            + d_hole * cos_gamma * t5 * t13 * t27 - cos_gamma * t18
            + cos_gamma
                * (t17 - 0.5 * d_peg * t9 * t36 + 0.5 * d_peg * t7 * t9 - t8 * t37 * t38
                    + 2.0 * d_peg * cos_gamma * t6 * t13 * t23)
            - 0.5 * d_hole * t3 * t5 * t9 - d_hole * cos_gamma * t3 * t13 * t29
            + 0.5 * d_hole * t9 * t27 * t29 - 2.0 * sin_gamma * t32;
        let t42 = psidot * psidot;
        let t43 = d_peg * d_peg;
        let t44 = 0.75 * t43 + h * h;
        let t45 = h - t8 * t9;
        let t46 = t45 * t45;
        let sin_psi = psi.sin();
        let cos_psi = psi.cos();
        let t47 = f_x * cos_psi;
        let t48 = f_y * sin_psi;
        let t49 = f_y * cos_psi;
        let t50 = -f_x * sin_psi;
        let t51 = -(d_hole * t3 * t5 * t9) + cos_gamma * t18 + t22 + t25;
        let t52 = t9 * t11 + t15 + t28 + t30 + t31 + t33 + t35;
        let t53 = 2.0 * cos_gamma * t19 + 2.0 * sin_gamma * t24;
        let t54 = t14 + d_hole * t3 * t9 * t29 - d_hole * t5 * t9 * t27
            - 2.0 * sin_gamma * t18 + 2.0 * cos_gamma * t32;
        let t55 = cos_gamma * t8 * t13 - 2.0 * d_peg * t6 * t9 * t23;
        let t56 = 2.0 * h - 2.0 * t8 * t9;
        let t57 = t9 * t11 * t21;
        let t58 = d_hole * t3 * t5 * t9 * t21;
        let a = Matrix5::new(
            -1.0,
            0.0,
            -(f * t_k_eta * t51)
                - f * t_k_z * (t15 - 0.5 * d_hole + t28 + t30 + t31 + t33 + t35),
            -(f * t_b1_eta * t51) - f * t_b1_z * t52,
            -(f * t_b2_eta * t51) - f * t_b2_z * t52,
            0.0,
            -1.0,
            0.5 * d_hole * f * t_k_n,
            f * t_b1_eta * t16 - f * t_b1_n * t9 * t11,
            -(f * t_b2_eta * t16) - f * t_b2_n * t9 * t11,
            0.0,
            0.0,
            -cos_gamma - f * t_k_eta,
            t57 - f * t_b1_eta,
            t57 - f * t_b2_eta,
            0.0,
            0.0,
            -f * t_k_n,
            t16 * t21 - f * t_b1_n,
            -(t16 * t21) - f * t_b2_n,
            0.0,
            0.0,
            -sin_gamma - f * t_k_z,
            t58 - f * t_b1_z,
            t58 - f * t_b2_z,
        );
        let b = Vector5::new(
            t26 * (t47 + t48) + f_z * t34 - m * g * t34
                + 0.5 * m
                    * (t39 * t40 * t53 + 0.5 * sin_gamma * cos_gamma * t42 * t46
                        + 0.25 * t12 * t42 * t55 * t56 + t40 * t41 * t54)
                - 0.125 * m * sin_gamma * cos_gamma * t42 * t43
                + 0.08333333333333333 * m * sin_gamma * cos_gamma * t42 * t44
                - 0.5 * m * gammadot
                    * (2.0 * gammadot * t39 * t53 + 2.0 * gammadot * t41 * t54)
                - gammaddot
                    * (0.08333333333333333 * m * t44
                        + 0.5 * m * (2.0 * (t26 * t26) + 2.0 * (t34 * t34))),
            sin_gamma * t19 * (t49 + t50)
                - gammadot
                    * (0.5 * m * psidot * sin_gamma * cos_gamma * t46
                        + 0.25 * m * psidot * t12 * t55 * t56
                        - 0.25 * m * psidot * sin_gamma * cos_gamma * t43
                        + 0.16666666666666666 * m * psidot * sin_gamma * cos_gamma * t44)
                - psiddot
                    * (0.25 * m * t12 * t46 + 0.125 * m * t38 * t43
                        + 0.08333333333333333 * m * t12 * t44),
            t47 + t48 - m * (t39 * t40 + gammaddot * t26 - sin_gamma * t19 * t42),
            t49 + t50
                - m
                    * (gammadot * (psidot * cos_gamma * t19 + psidot * sin_gamma * t24)
                        + psiddot * sin_gamma * t19 + gammadot * psidot * t26),
            f_z - m * g - m * (t40 * t41 + gammaddot * t34),
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
    /// 27 add/sub, 74 mul, 2 div, 1 sqrt, 8 transcendental, 0 branches; 28 `let`s.
    #[inline]
    pub fn contact_velocities(
        x: &SVector<f64, 4>,
        p: &SVector<f64, 7>,
    ) -> SMatrix<f64, 3, 3> {
        let gamma = x[0];
        let gammadot = x[2];
        let psidot = x[3];
        let d_hole = p[0];
        let d_peg = p[1];
        let h = p[2];
        let gamma0 = p[6];
        let sin_gamma = gamma.sin();
        let cos_gamma = gamma.cos();
        let t0 = 0.5 * gamma0;
        let t1 = 0.5 * gamma;
        let t2 = t0 + t1;
        let t3 = t2.sin();
        let t4 = t0 - 0.5 * gamma;
        let t5 = t4.sin();
        let t6 = t1.sin();
        let t7 = d_hole - d_peg + 2.0 * d_peg * (t6 * t6);
        let t8 = 1.0 / sin_gamma;
        let t9 = 0.5 * t7 * t8;
        let t10 = 1.0 / (sin_gamma * sin_gamma);
        let t11 = (-2.0 * d_hole * cos_gamma * t3 * t5 * t10
            * (d_hole + 2.0 * d_hole * cos_gamma * t3 * t5 * t10))
            .sqrt();
        let t12 = 0.5 * h - 0.5 * t7 * t8;
        let t13 = t9 - 0.5 * h;
        let t14 = t1.cos();
        let t15 = gammadot
            * (cos_gamma * t13
                + sin_gamma * (d_peg * t6 * t8 * t14 - 0.5 * cos_gamma * t7 * t10));
        let t16 = t2.cos();
        let t17 = t4.cos();
        let t18 = gammadot
            * (d_hole * cos_gamma * t3 * t5 * t10 - 0.5 * d_hole * t5 * t8 * t16
                + 0.5 * d_hole * t3 * t8 * t17 - sin_gamma * t12
                + cos_gamma * (-(d_peg * t6 * t8 * t14) + 0.5 * cos_gamma * t7 * t10));
        let t19 = psidot * sin_gamma * t13;
        let t20 = -sin_gamma * t13;
        let t21 = -(0.5 * d_hole) + t20;
        let t22 = -gammadot * (d_hole * t3 * t5 * t8 - cos_gamma * t12);
        let t23 = t8 * (t9 + d_hole * cos_gamma * t3 * t5 * t8) + t20;
        let t24 = t19 + psidot * t23;
        let t25 = t18 + gammadot * t23;
        Matrix3::new(
            t15 + t22,
            t19 + psidot * t21,
            t18 + gammadot * t21,
            t15 + t22 - psidot * t11,
            t24,
            t25,
            t15 + t22 + psidot * t11,
            t24,
            t25,
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
    /// 24 add/sub, 73 mul, 2 div, 0 sqrt, 8 transcendental, 0 branches; 26 `let`s.
    #[inline]
    pub fn energy(x: &SVector<f64, 4>, p: &SVector<f64, 7>) -> (f64, f64) {
        let gamma = x[0];
        let gammadot = x[2];
        let psidot = x[3];
        let d_hole = p[0];
        let d_peg = p[1];
        let h = p[2];
        let m = p[3];
        let g = p[4];
        let gamma0 = p[6];
        let sin_gamma = gamma.sin();
        let cos_gamma = gamma.cos();
        let t0 = 0.5 * gamma0;
        let t1 = 0.5 * gamma;
        let t2 = t0 + t1;
        let t3 = t2.sin();
        let t4 = t0 - 0.5 * gamma;
        let t5 = t4.sin();
        let t6 = t1.sin();
        let t7 = d_hole - d_peg + 2.0 * d_peg * (t6 * t6);
        let t8 = 1.0 / sin_gamma;
        let t9 = sin_gamma * sin_gamma;
        let t10 = 1.0 / (sin_gamma * sin_gamma);
        let t11 = 0.5 * h - 0.5 * t7 * t8;
        let t12 = t1.cos();
        let t13 = cos_gamma * (0.5 * t7 * t8 - 0.5 * h)
            + sin_gamma * (d_peg * t6 * t8 * t12 - 0.5 * cos_gamma * t7 * t10);
        let t14 = t2.cos();
        let t15 = t4.cos();
        let t16 = d_hole * cos_gamma * t3 * t5 * t10 - 0.5 * d_hole * t5 * t8 * t14
            + 0.5 * d_hole * t3 * t8 * t15 - sin_gamma * t11
            + cos_gamma * (-(d_peg * t6 * t8 * t12) + 0.5 * cos_gamma * t7 * t10);
        let t17 = gammadot * gammadot;
        let t18 = psidot * psidot;
        let t19 = d_peg * d_peg;
        let t20 = h - t7 * t8;
        let t21 = 0.5 * m
            * (t17 * (t13 * t13) + 0.25 * t9 * t18 * (t20 * t20) + t17 * (t16 * t16));
        let t22 = 0.0625 * m * (cos_gamma * cos_gamma) * t18 * t19;
        let t23 = 0.041666666666666664 * m * (0.75 * t19 + h * h) * (t17 + t9 * t18);
        let kinetic = t21 + t22 + t23;
        let total = t21 + t22 + t23
            + m * g * (-(d_hole * t3 * t5 * t8) + cos_gamma * t11);
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
    /// 10 add/sub, 56 mul, 3 div, 1 sqrt, 6 transcendental, 0 branches; 18 `let`s.
    #[inline]
    pub fn geometry(x: &SVector<f64, 4>, p: &SVector<f64, 7>) -> SVector<f64, 13> {
        let gamma = x[0];
        let d_hole = p[0];
        let d_peg = p[1];
        let h = p[2];
        let gamma0 = p[6];
        let sin_gamma = gamma.sin();
        let cos_gamma = gamma.cos();
        let t0 = 0.5 * gamma0;
        let t1 = 0.5 * gamma;
        let t2 = (t0 + t1).sin();
        let t3 = (t0 - 0.5 * gamma).sin();
        let t4 = t1.sin();
        let t5 = d_hole - d_peg + 2.0 * d_peg * (t4 * t4);
        let t6 = 1.0 / sin_gamma;
        let t7 = -d_hole * t2 * t3 * t6;
        let t8 = 0.5 * t5 * t6;
        let t9 = t8 + d_hole * cos_gamma * t2 * t3 * t6;
        let t10 = t6 * t9;
        let t11 = d_hole * t2 * t3 * t6;
        let t12 = 1.0 / (sin_gamma * sin_gamma);
        let t13 = (-2.0 * d_hole * cos_gamma * t2 * t3 * t12
            * (d_hole + 2.0 * d_hole * cos_gamma * t2 * t3 * t12))
            .sqrt();
        let t14 = 1.0 / d_hole;
        let t15 = t10.hypot(t11);
        SMatrix::<
            f64,
            13,
            1,
        >::from_row_slice(
            &[
                t7,
                t8,
                t10,
                t6 * (0.5 * cos_gamma * t5 * t6 + t11),
                t13,
                2.0 * t13 * t14,
                2.0 * t6 * t9 * t14,
                sin_gamma * (t8 - 0.5 * h),
                t7 + cos_gamma * (0.5 * h - 0.5 * t5 * t6),
                -2.0 * d_hole * t2 * t3 * t12,
                2.0 * t15,
                -t6 * t9,
                -2.0 * d_hole * t2 * t3 * t6,
            ],
        )
    }
}
