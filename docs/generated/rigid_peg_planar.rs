// @generated readable copy of `pegdyn::generated::rigid_peg_planar` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generated_snapshot

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
    /// - `a`: 3×3 matrix
    /// - `b`: vector of 3
    ///
    /// # Cost
    /// 58 add/sub, 103 mul, 5 div, 0 sqrt, 5 transcendental, 0 branches; 47 `let`s.
    #[inline]
    pub fn forward<T: Real>(
        x: &SVector<T, 2>,
        p: &SVector<T, 7>,
        loads: &SVector<T, 3>,
        t: &SVector<T, 4>,
    ) -> (SMatrix<T, 3, 3>, SVector<T, 3>) {
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
        let t0 = T::from_f64(0.5) * gamma0;
        let t1 = T::from_f64(0.5) * gamma;
        let t2 = (t0 + t1).sin();
        let t3 = (t0 - T::from_f64(0.5) * gamma).sin();
        let (t4, t11) = t1.sin_cos();
        let t5 = t4 * t4;
        let t6 = d_hole - d_peg + T::from_f64(2.0) * d_peg * t5;
        let t7 = T::from_f64(1.0) / sin_gamma;
        let t8 = t6 * t7;
        let t9 = T::from_f64(1.0) / (sin_gamma * sin_gamma);
        let t10 = T::from_f64(0.5) * d_hole;
        let t12 = cos_gamma * t9;
        let t13 = t11 * t11;
        let t14 = gammadot * gammadot;
        let t15 = T::from_f64(0.5) * t6;
        let t16 = t2 * t3;
        let t17 = t16 * d_hole;
        let t18 = t17 * t7;
        let t19 = T::from_f64(0.5) * h - T::from_f64(0.5) * t8;
        let t20 = t18.hypot(t10);
        let t21 = d_peg * t4 * t11;
        let t22 = t21 * t7;
        let t23 = t12 * t6;
        let t24 = t22 - T::from_f64(0.5) * t23;
        let t25 = sin_gamma * t24;
        let t26 = sin_gamma * t19;
        let t27 = -t22 + T::from_f64(0.5) * t23;
        let t28 = cos_gamma * cos_gamma / (sin_gamma * sin_gamma * sin_gamma);
        let t29 = t28 * t6;
        let t30 = t12 * t21;
        let t31 = -(T::from_f64(0.5) * h) + T::from_f64(0.5) * t8;
        let t32 = cos_gamma * t31 + t25;
        let t33 = cos_gamma * (t17 * t9 + t27);
        let t34 = t10 + t33 - t26;
        let t35 = -t31;
        let t36 = sin_gamma
            * (t35 + t7 * (T::from_f64(0.5) * (t13 - t5) * d_peg + t15) + t29
                - T::from_f64(2.0) * t30) + T::from_f64(2.0) * cos_gamma * t24;
        let t37 = -t19;
        let t38 = d_hole
            * (t16 * (-t7 - T::from_f64(2.0) * t28) - T::from_f64(0.5) * cos_gamma * t7)
            + cos_gamma
                * (t37
                    + t7
                        * (T::from_f64(0.5) * (-t13 + t5) * d_peg
                            - T::from_f64(0.5) * t6) - t29 + T::from_f64(2.0) * t30)
            - T::from_f64(2.0) * sin_gamma * t27;
        let t39 = cos_gamma * (t19 + t31) - t18 + t25;
        let t40 = sin_gamma * (t37 + t35);
        let t41 = t7 * (t15 + t17 * cos_gamma) * t7;
        let t42 = t32 * t36;
        let t43 = t38 * (d_hole + T::from_f64(2.0) * t33 - T::from_f64(2.0) * t26);
        let t44 = m * t14;
        let a = Matrix3::new(
            m
                * (T::from_f64(0.08333333333333333)
                    * (T::from_f64(0.75) * (d_peg * d_peg) + h * h) + t32 * t32
                    + t34 * t34),
            f * (-(t_k_eta * t39) - t_k_z * (t33 + t40)),
            T::from_f64(2.0) * (-(t39 * t_b_eta) - (t10 + t33 + t40 + t41) * t_b_z) * f,
            m * t32,
            -(f * t_k_eta) - T::from_f64(1.0) + T::from_f64(2.0) * t5,
            -(T::from_f64(2.0) * f * t_b_eta) + T::from_f64(2.0) * t41 / t20,
            m * t34,
            -(f * t_k_z) - sin_gamma,
            -(T::from_f64(2.0) * f * t_b_z) + T::from_f64(2.0) * t18 / t20,
        );
        let b = Vector3::new(
            m_gamma
                + m
                    * (T::from_f64(0.5)
                        * (-(T::from_f64(4.0) * t42 + T::from_f64(2.0) * t43)
                            + T::from_f64(2.0) * t42 + t43) * t14 - g * t34) + f_z * t34
                + f_x * t32,
            f_x - t44 * t36,
            f_z - m * g - t44 * t38,
        );
        (a, b)
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
    /// - `a`: 3×3 matrix
    /// - `b`: vector of 3
    ///
    /// # Cost
    /// 60 add/sub, 104 mul, 5 div, 0 sqrt, 5 transcendental, 0 branches; 46 `let`s.
    #[inline]
    pub fn prescribed<T: Real>(
        x: &SVector<T, 2>,
        qdd: &SVector<T, 1>,
        p: &SVector<T, 7>,
        loads: &SVector<T, 3>,
        t: &SVector<T, 4>,
    ) -> (SMatrix<T, 3, 3>, SVector<T, 3>) {
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
        let t0 = T::from_f64(0.5) * gamma0;
        let t1 = T::from_f64(0.5) * gamma;
        let t2 = (t0 + t1).sin();
        let t3 = (t0 - T::from_f64(0.5) * gamma).sin();
        let (t4, t11) = t1.sin_cos();
        let t5 = t4 * t4;
        let t6 = d_hole - d_peg + T::from_f64(2.0) * d_peg * t5;
        let t7 = T::from_f64(1.0) / sin_gamma;
        let t8 = t6 * t7;
        let t9 = T::from_f64(1.0) / (sin_gamma * sin_gamma);
        let t10 = T::from_f64(0.5) * d_hole;
        let t12 = cos_gamma * t9;
        let t13 = t11 * t11;
        let t14 = gammadot * gammadot;
        let t15 = T::from_f64(0.5) * t6;
        let t16 = t2 * t3;
        let t17 = t16 * d_hole;
        let t18 = t17 * t7;
        let t19 = T::from_f64(0.5) * h - T::from_f64(0.5) * t8;
        let t20 = t18.hypot(t10);
        let t21 = d_peg * t4 * t11;
        let t22 = t21 * t7;
        let t23 = t12 * t6;
        let t24 = t22 - T::from_f64(0.5) * t23;
        let t25 = sin_gamma * t24;
        let t26 = sin_gamma * t19;
        let t27 = -t22 + T::from_f64(0.5) * t23;
        let t28 = cos_gamma * cos_gamma / (sin_gamma * sin_gamma * sin_gamma);
        let t29 = t28 * t6;
        let t30 = t12 * t21;
        let t31 = -(T::from_f64(0.5) * h) + T::from_f64(0.5) * t8;
        let t32 = cos_gamma * t31 + t25;
        let t33 = cos_gamma * (t17 * t9 + t27);
        let t34 = t10 + t33 - t26;
        let t35 = -t31;
        let t36 = sin_gamma
            * (t35 + t7 * (T::from_f64(0.5) * (t13 - t5) * d_peg + t15) + t29
                - T::from_f64(2.0) * t30) + T::from_f64(2.0) * cos_gamma * t24;
        let t37 = -t19;
        let t38 = d_hole
            * (t16 * (-t7 - T::from_f64(2.0) * t28) - T::from_f64(0.5) * cos_gamma * t7)
            + cos_gamma
                * (t37
                    + t7
                        * (T::from_f64(0.5) * (-t13 + t5) * d_peg
                            - T::from_f64(0.5) * t6) - t29 + T::from_f64(2.0) * t30)
            - T::from_f64(2.0) * sin_gamma * t27;
        let t39 = cos_gamma * (t19 + t31) - t18 + t25;
        let t40 = sin_gamma * (t37 + t35);
        let t41 = t7 * (t15 + t17 * cos_gamma) * t7;
        let t42 = t32 * t36;
        let t43 = t38 * (d_hole + T::from_f64(2.0) * t33 - T::from_f64(2.0) * t26);
        let a = Matrix3::new(
            -T::from_f64(1.0),
            f * (-(t_k_eta * t39) - t_k_z * (t33 + t40)),
            T::from_f64(2.0) * (-(t39 * t_b_eta) - (t10 + t33 + t40 + t41) * t_b_z) * f,
            T::from_f64(0.0),
            -(f * t_k_eta) - T::from_f64(1.0) + T::from_f64(2.0) * t5,
            -(T::from_f64(2.0) * f * t_b_eta) + T::from_f64(2.0) * t41 / t20,
            T::from_f64(0.0),
            -(f * t_k_z) - sin_gamma,
            -(T::from_f64(2.0) * f * t_b_z) + T::from_f64(2.0) * t18 / t20,
        );
        let b = Vector3::new(
            m
                * (T::from_f64(0.5)
                    * (-(T::from_f64(4.0) * t42 + T::from_f64(2.0) * t43)
                        + T::from_f64(2.0) * t42 + t43) * t14 - g * t34
                    - gammaddot
                        * (T::from_f64(0.08333333333333333)
                            * (T::from_f64(0.75) * (d_peg * d_peg) + h * h) + t32 * t32
                            + t34 * t34)) + f_z * t34 + f_x * t32,
            f_x - m * (t36 * t14 + gammaddot * t32),
            f_z - m * g - m * (t14 * t38 + gammaddot * t34),
        );
        (a, b)
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
    /// 19 add/sub, 38 mul, 2 div, 0 sqrt, 4 transcendental, 0 branches; 21 `let`s.
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
        let t0 = T::from_f64(0.5) * gamma0;
        let t1 = T::from_f64(0.5) * gamma;
        let t2 = (t0 + t1).sin();
        let t3 = (t0 - T::from_f64(0.5) * gamma).sin();
        let (t4, t9) = t1.sin_cos();
        let t5 = d_hole - d_peg + T::from_f64(2.0) * d_peg * (t4 * t4);
        let t6 = T::from_f64(1.0) / sin_gamma;
        let t7 = t5 * t6;
        let t8 = T::from_f64(1.0) / (sin_gamma * sin_gamma);
        let t10 = T::from_f64(0.5) * h - T::from_f64(0.5) * t7;
        let t11 = -(T::from_f64(0.5) * h) + T::from_f64(0.5) * t7;
        let t12 = d_hole * t2 * t3;
        let t13 = d_peg * t4 * (t6 * t9);
        let t14 = cos_gamma * t5 * t8;
        let t15 = T::from_f64(0.5) * d_hole
            + cos_gamma * (t12 * t8 + -t13 + T::from_f64(0.5) * t14) - sin_gamma * t10;
        let t16 = -sin_gamma * t11;
        let t17 = gammadot
            * (cos_gamma * t11 + sin_gamma * (t13 - T::from_f64(0.5) * t14)
                - (t12 * t6 - cos_gamma * t10));
        let t18 = gammadot
            * (t15 + t6 * t6 * (T::from_f64(0.5) * t5 + t12 * cos_gamma) + t16);
        Matrix3::new(
            t17,
            T::from_f64(0.0),
            gammadot * (t15 + -(T::from_f64(0.5) * d_hole) + t16),
            t17,
            T::from_f64(0.0),
            t18,
            t17,
            T::from_f64(0.0),
            t18,
        )
    }
    /// Kinetic energy T = ½ m|v_C|² + ½ ωᵀIω (paper (22)–(23)) and total energy T + V with V = m g z_C (J).
    ///
    /// # Inputs
    /// - `x` = (`gamma`, `gammadot`)
    /// - `p` = (`D_hole`, `d_peg`, `H`, `m`, `g`, `f`, `gamma0`)
    ///
    /// # Outputs
    /// - `kinetic`: scalar
    /// - `total`: scalar
    ///
    /// # Cost
    /// 17 add/sub, 41 mul, 2 div, 0 sqrt, 4 transcendental, 0 branches; 19 `let`s.
    #[inline]
    pub fn energy<T: Real>(x: &SVector<T, 2>, p: &SVector<T, 7>) -> (T, T) {
        let gamma = x[0];
        let gammadot = x[1];
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
        let t10 = T::from_f64(0.5) * h - T::from_f64(0.5) * t7;
        let t11 = d_hole * t2 * t3;
        let t12 = d_peg * t4 * (t6 * t9);
        let t13 = cos_gamma * t5 * t8;
        let t14 = cos_gamma * (-(T::from_f64(0.5) * h) + T::from_f64(0.5) * t7)
            + sin_gamma * (t12 - T::from_f64(0.5) * t13);
        let t15 = T::from_f64(0.5) * d_hole
            + cos_gamma * (t11 * t8 + -t12 + T::from_f64(0.5) * t13) - sin_gamma * t10;
        let t16 = gammadot * gammadot
            * (T::from_f64(0.5) * (t14 * t14 + t15 * t15)
                + T::from_f64(0.041666666666666664)
                    * (T::from_f64(0.75) * (d_peg * d_peg) + h * h));
        let kinetic = t16 * m;
        let total = m * (t16 + g * (-(t11 * t6) + cos_gamma * t10));
        (kinetic, total)
    }
}
