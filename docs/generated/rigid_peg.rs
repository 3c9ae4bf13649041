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
    /// 78 add/sub, 151 mul, 3 div, 1 sqrt, 6 transcendental, 0 branches; 66 `let`s.
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
        let half_gamma0 = T::from_f64(0.5) * gamma0;
        let half_gamma = T::from_f64(0.5) * gamma;
        let sin_sum = (half_gamma0 + half_gamma).sin();
        let sin_diff = (half_gamma0 - T::from_f64(0.5) * gamma).sin();
        let (sin_half_gamma, cos_half_gamma) = half_gamma.sin_cos();
        let t0 = sin_half_gamma * sin_half_gamma;
        let e = d_hole - d_peg + T::from_f64(2.0) * d_peg * t0;
        let t1 = T::from_f64(1.0) / sin_gamma;
        let t2 = e * t1;
        let t3 = sin_gamma * sin_gamma;
        let half_d = T::from_f64(0.5) * d_hole;
        let t4 = cos_gamma * cos_gamma;
        let t5 = gammadot * gammadot;
        let t6 = psidot * psidot;
        let t7 = d_peg * d_peg;
        let t8 = T::from_f64(0.75) * t7 + h * h;
        let (sin_psi, cos_psi) = psi.sin_cos();
        let t9 = f_x * cos_psi;
        let t10 = f_y * sin_psi;
        let t11 = f_x * sin_psi;
        let t12 = sin_gamma * cos_gamma;
        let t13 = -f_y * cos_psi;
        let t14 = f * t_k_n;
        let t15 = T::from_f64(0.5) * e;
        let t16 = T::from_f64(1.0 / 12.0) * t8;
        let t17 = sin_sum * sin_diff;
        let t18 = t17 * d_hole;
        let neg_a1 = t18 * t1;
        let lever = T::from_f64(0.5) * h - T::from_f64(0.5) * t2;
        let ob = neg_a1.hypot(half_d);
        let t19 = T::from_f64(1.0) / ob;
        let t20 = d_peg * sin_half_gamma * cos_half_gamma;
        let t21 = t20 * t1;
        let t22 = sin_gamma * lever;
        let t23 = t4 / (sin_gamma * sin_gamma * sin_gamma);
        let t24 = h - t2;
        let t25 = t24 * t24;
        let t26 = neg_a1 * t19;
        let t27 = t1 * (t15 + t18 * cos_gamma) * t1;
        let t28 = -t27 * t19;
        let t29 = lever - lever;
        let t30 = sin_gamma * t29;
        let t31 = m * gammadot * psidot;
        let t32 = t1 * t1;
        let t33 = cos_gamma * t32;
        let t34 = t18 * t33;
        let bb1 = (-T::from_f64(2.0) * t34 * (d_hole + T::from_f64(2.0) * t34)).sqrt();
        let t35 = bb1 * t19;
        let t36 = t33 * e;
        let t37 = t21 - T::from_f64(0.5) * t36;
        let t38 = sin_gamma * t37;
        let t39 = cos_gamma * (t18 * t32 - t37);
        let t40 = half_d + t39 - t22;
        let t41 = t3 * (T::from_f64(2.0) * h - T::from_f64(2.0) * t2)
            * (-t36 + T::from_f64(2.0) * t21);
        let t42 = -(cos_gamma * lever) + t38;
        let t43 = lever
            + t1
                * (-(T::from_f64(0.5)
                    * (d_peg * (-cos_half_gamma * cos_half_gamma + t0))) + t15) + t23 * e
            - T::from_f64(2.0) * t20 * t33;
        let t44 = sin_gamma * t43 + T::from_f64(2.0) * cos_gamma * t37;
        let t45 = cos_gamma * t29 - neg_a1 + t38;
        let t46 = d_hole
            * (t17 * (t1 + T::from_f64(2.0) * t23) + T::from_f64(0.5) * cos_gamma * t1)
            + cos_gamma * t43 - T::from_f64(2.0) * t38;
        let t47 = half_d + t39 - t30 + t27;
        let t48 = t42 * t44;
        let t49 = (d_hole + T::from_f64(2.0) * t39 - T::from_f64(2.0) * t22) * t46;
        let a = Matrix5::new(
            m * (t16 + t42 * t42 + t40 * t40),
            T::from_f64(0.0),
            -(f * (t_k_eta * t45 - t_k_z * (-t39 + t30))),
            -(f * (t_b1_eta * t45 + t_b1_z * t47)),
            -(f * (t_b2_eta * t45 + t_b2_z * t47)),
            T::from_f64(0.0),
            m * (t3 * (T::from_f64(0.25) * t25 + t16) + T::from_f64(0.125) * t4 * t7),
            T::from_f64(0.5) * t14 * d_hole,
            f * (t_b1_eta * bb1 - t27 * t_b1_n),
            -(f * (t_b2_eta * bb1 + t27 * t_b2_n)),
            m * t42,
            T::from_f64(0.0),
            -(f * t_k_eta) - cos_gamma,
            -(f * t_b1_eta) - t28,
            -(f * t_b2_eta) - t28,
            T::from_f64(0.0),
            -t22 * m,
            -t14,
            t35 - f * t_b1_n,
            -(f * t_b2_n) - t35,
            m * t40,
            T::from_f64(0.0),
            -(f * t_k_z) - sin_gamma,
            -(f * t_b1_z) + t26,
            -(f * t_b2_z) + t26,
        );
        let b = Vector5::new(
            m_gamma
                - m
                    * (-(t6 * (-(T::from_f64(0.125) * t7) + t16) * t12)
                        + T::from_f64(0.5)
                            * (-(t5 * (T::from_f64(2.0) * t48 - t49)
                                + t6
                                    * (T::from_f64(0.5) * t12 * t25 - T::from_f64(0.25) * t41))
                                + t5 * (T::from_f64(4.0) * t48 - T::from_f64(2.0) * t49))
                        + g * t40) + t42 * (t9 + t10) + f_z * t40,
            m_psi + t22 * (t13 + t11)
                + t31
                    * (-(t12
                        * (T::from_f64(0.5) * t25 - T::from_f64(0.25) * t7
                            + T::from_f64(1.0 / 6.0) * t8)) + T::from_f64(0.25) * t41),
            t9 + t10 - m * (t44 * t5 + t22 * t6),
            -t13 - t11 - t31 * t42 * (T::from_f64(1.0) + T::from_f64(1.0)),
            f_z - m * g + m * t5 * t46,
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
    /// 81 add/sub, 153 mul, 3 div, 1 sqrt, 6 transcendental, 0 branches; 66 `let`s.
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
        let half_gamma0 = T::from_f64(0.5) * gamma0;
        let half_gamma = T::from_f64(0.5) * gamma;
        let sin_sum = (half_gamma0 + half_gamma).sin();
        let sin_diff = (half_gamma0 - T::from_f64(0.5) * gamma).sin();
        let (sin_half_gamma, cos_half_gamma) = half_gamma.sin_cos();
        let t0 = sin_half_gamma * sin_half_gamma;
        let e = d_hole - d_peg + T::from_f64(2.0) * d_peg * t0;
        let t1 = T::from_f64(1.0) / sin_gamma;
        let t2 = e * t1;
        let t3 = sin_gamma * sin_gamma;
        let half_d = T::from_f64(0.5) * d_hole;
        let t4 = cos_gamma * cos_gamma;
        let t5 = gammadot * gammadot;
        let t6 = psidot * psidot;
        let t7 = d_peg * d_peg;
        let t8 = T::from_f64(0.75) * t7 + h * h;
        let (sin_psi, cos_psi) = psi.sin_cos();
        let t9 = f_x * cos_psi;
        let t10 = f_y * sin_psi;
        let t11 = f_y * cos_psi;
        let t12 = f_x * sin_psi;
        let t13 = sin_gamma * cos_gamma;
        let t14 = f * t_k_n;
        let t15 = T::from_f64(0.5) * e;
        let t16 = T::from_f64(1.0 / 12.0) * t8;
        let t17 = sin_sum * sin_diff;
        let t18 = t17 * d_hole;
        let neg_a1 = t18 * t1;
        let lever = T::from_f64(0.5) * h - T::from_f64(0.5) * t2;
        let ob = neg_a1.hypot(half_d);
        let t19 = T::from_f64(1.0) / ob;
        let t20 = d_peg * sin_half_gamma * cos_half_gamma;
        let t21 = t20 * t1;
        let t22 = sin_gamma * lever;
        let t23 = t4 / (sin_gamma * sin_gamma * sin_gamma);
        let t24 = h - t2;
        let t25 = t24 * t24;
        let t26 = neg_a1 * t19;
        let t27 = t1 * (t15 + t18 * cos_gamma) * t1;
        let t28 = -t27 * t19;
        let t29 = lever - lever;
        let t30 = sin_gamma * t29;
        let t31 = t1 * t1;
        let t32 = cos_gamma * t31;
        let t33 = t18 * t32;
        let bb1 = (-T::from_f64(2.0) * t33 * (d_hole + T::from_f64(2.0) * t33)).sqrt();
        let t34 = bb1 * t19;
        let t35 = t32 * e;
        let t36 = t21 - T::from_f64(0.5) * t35;
        let t37 = sin_gamma * t36;
        let t38 = cos_gamma * (t18 * t31 - t36);
        let t39 = half_d + t38 - t22;
        let t40 = t3 * (T::from_f64(2.0) * h - T::from_f64(2.0) * t2)
            * (-t35 + T::from_f64(2.0) * t21);
        let t41 = -(cos_gamma * lever) + t37;
        let t42 = lever
            + t1
                * (-(T::from_f64(0.5)
                    * (d_peg * (-cos_half_gamma * cos_half_gamma + t0))) + t15) + t23 * e
            - T::from_f64(2.0) * t20 * t32;
        let t43 = sin_gamma * t42 + T::from_f64(2.0) * cos_gamma * t36;
        let t44 = cos_gamma * t29 - neg_a1 + t37;
        let t45 = d_hole
            * (t17 * (t1 + T::from_f64(2.0) * t23) + T::from_f64(0.5) * cos_gamma * t1)
            + cos_gamma * t42 - T::from_f64(2.0) * t37;
        let t46 = half_d + t38 - t30 + t27;
        let t47 = t41 * t43;
        let t48 = (d_hole + T::from_f64(2.0) * t38 - T::from_f64(2.0) * t22) * t45;
        let t49 = gammadot * psidot;
        let a = Matrix5::new(
            -T::from_f64(1.0),
            T::from_f64(0.0),
            -(f * (t_k_eta * t44 - t_k_z * (-t38 + t30))),
            -(f * (t_b1_eta * t44 + t_b1_z * t46)),
            -(f * (t_b2_eta * t44 + t_b2_z * t46)),
            T::from_f64(0.0),
            -T::from_f64(1.0),
            T::from_f64(0.5) * t14 * d_hole,
            f * (t_b1_eta * bb1 - t27 * t_b1_n),
            -(f * (t_b2_eta * bb1 + t27 * t_b2_n)),
            T::from_f64(0.0),
            T::from_f64(0.0),
            -(f * t_k_eta) - cos_gamma,
            -(f * t_b1_eta) - t28,
            -(f * t_b2_eta) - t28,
            T::from_f64(0.0),
            T::from_f64(0.0),
            -t14,
            t34 - f * t_b1_n,
            -(f * t_b2_n) - t34,
            T::from_f64(0.0),
            T::from_f64(0.0),
            -(f * t_k_z) - sin_gamma,
            -(f * t_b1_z) + t26,
            -(f * t_b2_z) + t26,
        );
        let b = Vector5::new(
            -(m
                * (t6 * (T::from_f64(0.125) * t7 - T::from_f64(1.0 / 12.0) * t8) * t13
                    + T::from_f64(0.5)
                        * (-(t5 * (T::from_f64(2.0) * t47 - t48)
                            + t6
                                * (T::from_f64(0.5) * t13 * t25 - T::from_f64(0.25) * t40))
                            + t5 * (T::from_f64(4.0) * t47 - T::from_f64(2.0) * t48))
                    + g * t39 + gammaddot * (t16 + t41 * t41 + t39 * t39)))
                + t41 * (t9 + t10) + f_z * t39,
            m
                * (t49
                    * (-(t13
                        * (T::from_f64(0.5) * t25 - T::from_f64(0.25) * t7
                            + T::from_f64(1.0 / 6.0) * t8)) + T::from_f64(0.25) * t40)
                    - psiddot
                        * (t3 * (T::from_f64(0.25) * t25 + t16)
                            + T::from_f64(0.125) * t4 * t7)) + t22 * (-t11 + t12),
            t9 + t10 - m * (t43 * t5 + gammaddot * t41 + t22 * t6),
            t11 - t12
                + m
                    * (-(t49 * ((T::from_f64(1.0) + T::from_f64(1.0)) * t41))
                        + t22 * psiddot),
            f_z - m * g - m * (-(t5 * t45) + gammaddot * t39),
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
    /// 22 add/sub, 39 mul, 1 div, 1 sqrt, 4 transcendental, 0 branches; 27 `let`s.
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
        let sin_diff = (half_gamma0 - T::from_f64(0.5) * gamma).sin();
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
        let t5 = d_hole * sin_sum * sin_diff;
        let t6 = half_d - t1;
        let t7 = t0 * t0 * (T::from_f64(0.5) * e + t5 * cos_gamma) + t1;
        let t8 = -psidot * (t1 - t7);
        let t9 = t5 * t4;
        let bb1 = (-T::from_f64(2.0) * t9 * (d_hole + T::from_f64(2.0) * t9)).sqrt();
        let t10 = d_peg * sin_half_gamma * t0 * cos_half_gamma
            - T::from_f64(0.5) * t4 * e;
        let t11 = psidot * bb1;
        let t12 = half_d + cos_gamma * (t5 * t3 - t10) - t1;
        let t13 = gammadot * (-(t2 + sin_gamma * t10) + t5 * t0 + t2);
        let t14 = gammadot * (t12 + t7);
        Matrix3::new(
            -t13,
            -psidot * (t1 + t6),
            gammadot * (t12 - t6),
            -t13 - t11,
            t8,
            t14,
            t11 - t13,
            t8,
            t14,
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
    /// 21 add/sub, 48 mul, 1 div, 0 sqrt, 4 transcendental, 0 branches; 27 `let`s.
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
        let half_gamma0 = T::from_f64(0.5) * gamma0;
        let half_gamma = T::from_f64(0.5) * gamma;
        let sin_sum = (half_gamma0 + half_gamma).sin();
        let sin_diff = (half_gamma0 - T::from_f64(0.5) * gamma).sin();
        let (sin_half_gamma, cos_half_gamma) = half_gamma.sin_cos();
        let e = d_hole - d_peg
            + T::from_f64(2.0) * d_peg * (sin_half_gamma * sin_half_gamma);
        let t0 = T::from_f64(1.0) / sin_gamma;
        let t1 = e * t0;
        let half_d = T::from_f64(0.5) * d_hole;
        let t2 = gammadot * gammadot;
        let t3 = psidot * psidot;
        let t4 = d_peg * d_peg;
        let t5 = sin_gamma * sin_gamma * t3;
        let lever = T::from_f64(0.5) * h - T::from_f64(0.5) * t1;
        let t6 = -cos_gamma * lever;
        let t7 = h - t1;
        let t8 = t0 * t0;
        let t9 = d_hole * sin_sum * sin_diff;
        let t10 = T::from_f64(0.0625) * (cos_gamma * cos_gamma) * t3 * t4;
        let t11 = T::from_f64(1.0 / 24.0) * (T::from_f64(0.75) * t4 + h * h) * (t2 + t5);
        let t12 = d_peg * sin_half_gamma * t0 * cos_half_gamma
            - T::from_f64(0.5) * cos_gamma * e * t8;
        let t13 = half_d + cos_gamma * (t9 * t8 - t12) - sin_gamma * lever;
        let t14 = t6 + sin_gamma * t12;
        let t15 = T::from_f64(0.5)
            * (t2 * (t14 * t14 + t13 * t13) + T::from_f64(0.25) * t5 * (t7 * t7));
        let kinetic = m * (t15 + t10 + t11);
        let total = m * (t15 + t10 + t11 - g * (t9 * t0 + t6));
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
    /// 10 add/sub, 35 mul, 3 div, 1 sqrt, 5 transcendental, 0 branches; 21 `let`s.
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
        let sin_diff = (half_gamma0 - T::from_f64(0.5) * gamma).sin();
        let sin_half_gamma = half_gamma.sin();
        let e = d_hole - d_peg
            + T::from_f64(2.0) * d_peg * (sin_half_gamma * sin_half_gamma);
        let t0 = T::from_f64(1.0) / sin_gamma;
        let t1 = e * t0;
        let lever = T::from_f64(0.5) * h - T::from_f64(0.5) * t1;
        let t2 = t0 * t0;
        let t3 = d_hole * sin_sum * sin_diff;
        let neg_a1 = t3 * t0;
        let t4 = t3 * cos_gamma;
        let a2 = T::from_f64(0.5) * t1;
        let s1 = t0 * (T::from_f64(0.5) * e + t4) * t0;
        let s2 = t0 * (T::from_f64(0.5) * cos_gamma * e + t3) * t0;
        let t5 = s1.hypot(neg_a1);
        let t6 = t4 * t2;
        let bb1 = (-T::from_f64(2.0) * t6 * (d_hole + T::from_f64(2.0) * t6)).sqrt();
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
                sin_gamma * (-(T::from_f64(0.5) * h) + a2),
                cos_gamma * lever - neg_a1,
                -T::from_f64(2.0) * t3 * t2,
                T::from_f64(2.0) * t5,
                -s1,
                -T::from_f64(2.0) * neg_a1,
            ],
        )
    }
}
