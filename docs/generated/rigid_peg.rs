// @generated readable copy of `pegdyn::generated::rigid_peg` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generated_snapshot

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
    /// 86 add/sub, 160 mul, 4 div, 1 sqrt, 6 transcendental, 0 branches; 72 `let`s.
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
        let (t4, t12) = t1.sin_cos();
        let t5 = t4 * t4;
        let t6 = d_hole - d_peg + T::from_f64(2.0) * d_peg * t5;
        let t7 = T::from_f64(1.0) / sin_gamma;
        let t8 = t6 * t7;
        let t9 = sin_gamma * sin_gamma;
        let t10 = T::from_f64(1.0) / (sin_gamma * sin_gamma);
        let t11 = T::from_f64(0.5) * d_hole;
        let t13 = cos_gamma * t10;
        let t14 = t12 * t12;
        let t15 = cos_gamma * cos_gamma;
        let t16 = gammadot * gammadot;
        let t17 = psidot * psidot;
        let t18 = d_peg * d_peg;
        let t19 = T::from_f64(0.75) * t18 + h * h;
        let (sin_psi, cos_psi) = psi.sin_cos();
        let t20 = f_x * cos_psi;
        let t21 = f_y * sin_psi;
        let t22 = f_y * cos_psi;
        let t23 = -f_x * sin_psi;
        let t24 = sin_gamma * cos_gamma;
        let t25 = f * t_k_n;
        let t26 = T::from_f64(0.5) * t6;
        let t27 = T::from_f64(0.08333333333333333) * t19;
        let t28 = t2 * t3;
        let t29 = t28 * d_hole;
        let t30 = t29 * t7;
        let t31 = t29 * t13;
        let t32 = (-T::from_f64(2.0) * t31 * (d_hole + T::from_f64(2.0) * t31)).sqrt();
        let t33 = T::from_f64(0.5) * h - T::from_f64(0.5) * t8;
        let t34 = t30.hypot(t11);
        let t35 = T::from_f64(1.0) / t34;
        let t36 = t32 * t35;
        let t37 = d_peg * t4 * t12;
        let t38 = t37 * t7;
        let t39 = t13 * t6;
        let t40 = t38 - T::from_f64(0.5) * t39;
        let t41 = sin_gamma * t40;
        let t42 = sin_gamma * t33;
        let t43 = -t38 + T::from_f64(0.5) * t39;
        let t44 = t15 / (sin_gamma * sin_gamma * sin_gamma);
        let t45 = t44 * t6;
        let t46 = t13 * t37;
        let t47 = h - t8;
        let t48 = t47 * t47;
        let t49 = t30 * t35;
        let t50 = -(T::from_f64(0.5) * h) + T::from_f64(0.5) * t8;
        let t51 = cos_gamma * t50 + t41;
        let t52 = cos_gamma * (t29 * t10 + t43);
        let t53 = t11 + t52 - t42;
        let t54 = -t50;
        let t55 = sin_gamma
            * (t54 + t7 * (T::from_f64(0.5) * (t14 - t5) * d_peg + t26) + t45
                - T::from_f64(2.0) * t46) + T::from_f64(2.0) * cos_gamma * t40;
        let t56 = -t33;
        let t57 = d_hole
            * (t28 * (-t7 - T::from_f64(2.0) * t44) - T::from_f64(0.5) * cos_gamma * t7)
            + cos_gamma
                * (t56
                    + t7
                        * (T::from_f64(0.5) * (-t14 + t5) * d_peg
                            - T::from_f64(0.5) * t6) - t45 + T::from_f64(2.0) * t46)
            - T::from_f64(2.0) * sin_gamma * t43;
        let t58 = sin_gamma * t50;
        let t59 = cos_gamma * (t33 + t50) - t30 + t41;
        let t60 = sin_gamma * (t56 + t54);
        let t61 = t7 * (t26 + t29 * cos_gamma) * t7;
        let t62 = t11 + t52 + t60 + t61;
        let t63 = t51 * t55;
        let t64 = t57 * (d_hole + T::from_f64(2.0) * t52 - T::from_f64(2.0) * t42);
        let t65 = T::from_f64(0.25) * t9 * (t39 - T::from_f64(2.0) * t38)
            * (T::from_f64(2.0) * h - T::from_f64(2.0) * t8);
        let t66 = t61 * t35;
        let t67 = m * gammadot * psidot;
        let a = Matrix5::new(
            m * (t27 + t51 * t51 + t53 * t53),
            T::from_f64(0.0),
            f * (-(t_k_eta * t59) - t_k_z * (t52 + t60)),
            f * (-(t_b1_eta * t59) - t_b1_z * t62),
            f * (-(t_b2_eta * t59) - t_b2_z * t62),
            T::from_f64(0.0),
            m * (t9 * (T::from_f64(0.25) * t48 + t27) + T::from_f64(0.125) * t15 * t18),
            T::from_f64(0.5) * t25 * d_hole,
            f * (t_b1_eta * t32 - t61 * t_b1_n),
            f * (-(t_b2_eta * t32) - t61 * t_b2_n),
            m * t51,
            T::from_f64(0.0),
            -(f * t_k_eta) - cos_gamma,
            -(f * t_b1_eta) + t66,
            -(f * t_b2_eta) + t66,
            T::from_f64(0.0),
            t58 * m,
            -t25,
            -(f * t_b1_n) + t36,
            -(f * t_b2_n) - t36,
            m * t53,
            T::from_f64(0.0),
            -(f * t_k_z) - sin_gamma,
            -(f * t_b1_z) + t49,
            -(f * t_b2_z) + t49,
        );
        let b = Vector5::new(
            m_gamma
                + m
                    * (t17 * (-(T::from_f64(0.125) * t18) + t27) * t24
                        + T::from_f64(0.5)
                            * (t16 * (T::from_f64(2.0) * t63 + t64)
                                + t17 * (T::from_f64(0.5) * t24 * t48 + t65)
                                - t16 * (T::from_f64(4.0) * t63 + T::from_f64(2.0) * t64))
                        - g * t53) + t51 * (t20 + t21) + f_z * t53,
            m_psi + t58 * (t22 + t23)
                - t67
                    * (t24
                        * (T::from_f64(0.5) * t48 - T::from_f64(0.25) * t18
                            + T::from_f64(0.16666666666666666) * t19) + t65),
            t20 + t21 - m * (t55 * t16 - t58 * t17),
            t22 + t23 - t67 * t51 * (T::from_f64(1.0) + T::from_f64(1.0)),
            f_z - m * g - m * t16 * t57,
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
    /// 89 add/sub, 161 mul, 4 div, 1 sqrt, 6 transcendental, 0 branches; 72 `let`s.
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
        let (t4, t12) = t1.sin_cos();
        let t5 = t4 * t4;
        let t6 = d_hole - d_peg + T::from_f64(2.0) * d_peg * t5;
        let t7 = T::from_f64(1.0) / sin_gamma;
        let t8 = t6 * t7;
        let t9 = sin_gamma * sin_gamma;
        let t10 = T::from_f64(1.0) / (sin_gamma * sin_gamma);
        let t11 = T::from_f64(0.5) * d_hole;
        let t13 = cos_gamma * t10;
        let t14 = t12 * t12;
        let t15 = cos_gamma * cos_gamma;
        let t16 = gammadot * gammadot;
        let t17 = psidot * psidot;
        let t18 = d_peg * d_peg;
        let t19 = T::from_f64(0.75) * t18 + h * h;
        let (sin_psi, cos_psi) = psi.sin_cos();
        let t20 = f_x * cos_psi;
        let t21 = f_y * sin_psi;
        let t22 = f_y * cos_psi;
        let t23 = -f_x * sin_psi;
        let t24 = sin_gamma * cos_gamma;
        let t25 = f * t_k_n;
        let t26 = T::from_f64(0.5) * t6;
        let t27 = T::from_f64(0.08333333333333333) * t19;
        let t28 = t2 * t3;
        let t29 = t28 * d_hole;
        let t30 = t29 * t7;
        let t31 = t29 * t13;
        let t32 = (-T::from_f64(2.0) * t31 * (d_hole + T::from_f64(2.0) * t31)).sqrt();
        let t33 = T::from_f64(0.5) * h - T::from_f64(0.5) * t8;
        let t34 = t30.hypot(t11);
        let t35 = T::from_f64(1.0) / t34;
        let t36 = t32 * t35;
        let t37 = d_peg * t4 * t12;
        let t38 = t37 * t7;
        let t39 = t13 * t6;
        let t40 = t38 - T::from_f64(0.5) * t39;
        let t41 = sin_gamma * t40;
        let t42 = sin_gamma * t33;
        let t43 = -t38 + T::from_f64(0.5) * t39;
        let t44 = t15 / (sin_gamma * sin_gamma * sin_gamma);
        let t45 = t44 * t6;
        let t46 = t13 * t37;
        let t47 = h - t8;
        let t48 = t47 * t47;
        let t49 = t30 * t35;
        let t50 = -(T::from_f64(0.5) * h) + T::from_f64(0.5) * t8;
        let t51 = cos_gamma * t50 + t41;
        let t52 = cos_gamma * (t29 * t10 + t43);
        let t53 = t11 + t52 - t42;
        let t54 = -t50;
        let t55 = sin_gamma
            * (t54 + t7 * (T::from_f64(0.5) * (t14 - t5) * d_peg + t26) + t45
                - T::from_f64(2.0) * t46) + T::from_f64(2.0) * cos_gamma * t40;
        let t56 = -t33;
        let t57 = d_hole
            * (t28 * (-t7 - T::from_f64(2.0) * t44) - T::from_f64(0.5) * cos_gamma * t7)
            + cos_gamma
                * (t56
                    + t7
                        * (T::from_f64(0.5) * (-t14 + t5) * d_peg
                            - T::from_f64(0.5) * t6) - t45 + T::from_f64(2.0) * t46)
            - T::from_f64(2.0) * sin_gamma * t43;
        let t58 = sin_gamma * t50;
        let t59 = cos_gamma * (t33 + t50) - t30 + t41;
        let t60 = sin_gamma * (t56 + t54);
        let t61 = t7 * (t26 + t29 * cos_gamma) * t7;
        let t62 = t11 + t52 + t60 + t61;
        let t63 = t51 * t55;
        let t64 = t57 * (d_hole + T::from_f64(2.0) * t52 - T::from_f64(2.0) * t42);
        let t65 = T::from_f64(0.25) * t9 * (t39 - T::from_f64(2.0) * t38)
            * (T::from_f64(2.0) * h - T::from_f64(2.0) * t8);
        let t66 = t61 * t35;
        let t67 = gammadot * psidot;
        let a = Matrix5::new(
            -T::from_f64(1.0),
            T::from_f64(0.0),
            f * (-(t_k_eta * t59) - t_k_z * (t52 + t60)),
            f * (-(t_b1_eta * t59) - t_b1_z * t62),
            f * (-(t_b2_eta * t59) - t_b2_z * t62),
            T::from_f64(0.0),
            -T::from_f64(1.0),
            T::from_f64(0.5) * t25 * d_hole,
            f * (t_b1_eta * t32 - t61 * t_b1_n),
            f * (-(t_b2_eta * t32) - t61 * t_b2_n),
            T::from_f64(0.0),
            T::from_f64(0.0),
            -(f * t_k_eta) - cos_gamma,
            -(f * t_b1_eta) + t66,
            -(f * t_b2_eta) + t66,
            T::from_f64(0.0),
            T::from_f64(0.0),
            -t25,
            -(f * t_b1_n) + t36,
            -(f * t_b2_n) - t36,
            T::from_f64(0.0),
            T::from_f64(0.0),
            -(f * t_k_z) - sin_gamma,
            -(f * t_b1_z) + t49,
            -(f * t_b2_z) + t49,
        );
        let b = Vector5::new(
            m
                * (t17 * (-(T::from_f64(0.125) * t18) + t27) * t24
                    + T::from_f64(0.5)
                        * (t16 * (T::from_f64(2.0) * t63 + t64)
                            + t17 * (T::from_f64(0.5) * t24 * t48 + t65)
                            - t16 * (T::from_f64(4.0) * t63 + T::from_f64(2.0) * t64))
                    - g * t53 - gammaddot * (t27 + t51 * t51 + t53 * t53))
                + t51 * (t20 + t21) + f_z * t53,
            m
                * (-(t67
                    * (t24
                        * (T::from_f64(0.5) * t48 - T::from_f64(0.25) * t18
                            + T::from_f64(0.16666666666666666) * t19) + t65))
                    - psiddot
                        * (t9 * (T::from_f64(0.25) * t48 + t27)
                            + T::from_f64(0.125) * t15 * t18)) + t58 * (t22 + t23),
            t20 + t21 - m * (t55 * t16 + gammaddot * t51 - t58 * t17),
            t22 + t23
                - m
                    * (t67 * (t51 * (T::from_f64(1.0) + T::from_f64(1.0)))
                        + t58 * psiddot),
            f_z - m * g - m * (t16 * t57 + gammaddot * t53),
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
    /// 24 add/sub, 45 mul, 2 div, 1 sqrt, 4 transcendental, 0 branches; 29 `let`s.
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
        let (t4, t9) = t1.sin_cos();
        let t5 = d_hole - d_peg + T::from_f64(2.0) * d_peg * (t4 * t4);
        let t6 = T::from_f64(1.0) / sin_gamma;
        let t7 = t5 * t6;
        let t8 = T::from_f64(1.0) / (sin_gamma * sin_gamma);
        let t10 = cos_gamma * t8;
        let t11 = T::from_f64(0.5) * h - T::from_f64(0.5) * t7;
        let t12 = t10 * t5;
        let t13 = -(T::from_f64(0.5) * h) + T::from_f64(0.5) * t7;
        let t14 = sin_gamma * t13;
        let t15 = d_hole * t2 * t3;
        let t16 = t15 * t10;
        let t17 = (-T::from_f64(2.0) * t16 * (d_hole + T::from_f64(2.0) * t16)).sqrt();
        let t18 = d_peg * t4 * (t6 * t9);
        let t19 = psidot * t17;
        let t20 = T::from_f64(0.5) * d_hole
            + cos_gamma * (t15 * t8 + -t18 + T::from_f64(0.5) * t12) - sin_gamma * t11;
        let t21 = -t14;
        let t22 = -(T::from_f64(0.5) * d_hole) + t21;
        let t23 = gammadot
            * (cos_gamma * t13 + sin_gamma * (t18 - T::from_f64(0.5) * t12)
                - (t15 * t6 - cos_gamma * t11));
        let t24 = t6 * t6 * (T::from_f64(0.5) * t5 + t15 * cos_gamma) + t21;
        let t25 = psidot * (t14 + t24);
        let t26 = gammadot * (t20 + t24);
        Matrix3::new(
            t23,
            psidot * (t14 + t22),
            gammadot * (t20 + t22),
            t23 - t19,
            t25,
            t26,
            t23 + t19,
            t25,
            t26,
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
    /// 23 add/sub, 52 mul, 2 div, 0 sqrt, 4 transcendental, 0 branches; 26 `let`s.
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
        let (t4, t9) = t1.sin_cos();
        let t5 = d_hole - d_peg + T::from_f64(2.0) * d_peg * (t4 * t4);
        let t6 = T::from_f64(1.0) / sin_gamma;
        let t7 = t5 * t6;
        let t8 = T::from_f64(1.0) / (sin_gamma * sin_gamma);
        let t10 = gammadot * gammadot;
        let t11 = psidot * psidot;
        let t12 = d_peg * d_peg;
        let t13 = sin_gamma * sin_gamma * t11;
        let t14 = T::from_f64(0.5) * h - T::from_f64(0.5) * t7;
        let t15 = h - t7;
        let t16 = d_hole * t2 * t3;
        let t17 = d_peg * t4 * (t6 * t9);
        let t18 = T::from_f64(0.0625) * (cos_gamma * cos_gamma) * t11 * t12;
        let t19 = T::from_f64(0.041666666666666664) * (T::from_f64(0.75) * t12 + h * h)
            * (t10 + t13);
        let t20 = cos_gamma * t5 * t8;
        let t21 = cos_gamma * (-(T::from_f64(0.5) * h) + T::from_f64(0.5) * t7)
            + sin_gamma * (t17 - T::from_f64(0.5) * t20);
        let t22 = T::from_f64(0.5) * d_hole
            + cos_gamma * (t16 * t8 + -t17 + T::from_f64(0.5) * t20) - sin_gamma * t14;
        let t23 = T::from_f64(0.5)
            * (t10 * (t21 * t21 + t22 * t22) + T::from_f64(0.25) * t13 * (t15 * t15));
        let kinetic = m * (t23 + t18 + t19);
        let total = m * (t23 + t18 + t19 + g * (-(t16 * t6) + cos_gamma * t14));
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
    /// 10 add/sub, 35 mul, 4 div, 1 sqrt, 5 transcendental, 0 branches; 20 `let`s.
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
        let t7 = t5 * t6;
        let t8 = T::from_f64(1.0) / (sin_gamma * sin_gamma);
        let t9 = T::from_f64(0.5) * t7;
        let t10 = d_hole * t2 * t3;
        let t11 = t10 * t6;
        let t12 = t10 * cos_gamma;
        let t13 = -t11;
        let t14 = t12 * t8;
        let t15 = (-T::from_f64(2.0) * t14 * (d_hole + T::from_f64(2.0) * t14)).sqrt();
        let t16 = t6 * (T::from_f64(0.5) * t5 + t12) * t6;
        let t17 = t16.hypot(t11);
        SMatrix::<
            T,
            13,
            1,
        >::from_row_slice(
            &[
                t13,
                t9,
                t16,
                t6 * (T::from_f64(0.5) * cos_gamma * t5 + t10) * t6,
                t15,
                T::from_f64(2.0) * t15 / d_hole,
                T::from_f64(2.0) * t16 / d_hole,
                sin_gamma * (-(T::from_f64(0.5) * h) + t9),
                t13 + cos_gamma * (T::from_f64(0.5) * h - T::from_f64(0.5) * t7),
                -T::from_f64(2.0) * t10 * t8,
                T::from_f64(2.0) * t17,
                -t16,
                -T::from_f64(2.0) * t11,
            ],
        )
    }
}
