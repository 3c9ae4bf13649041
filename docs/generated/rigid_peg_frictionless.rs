// @generated readable copy of `pegdyn::generated::rigid_peg_frictionless` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generated_snapshot

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
    /// - `a`: 5×5 matrix
    /// - `b`: vector of 5
    ///
    /// # Cost
    /// 65 add/sub, 130 mul, 5 div, 1 sqrt, 6 transcendental, 0 branches; 63 `let`s.
    #[inline]
    pub fn forward<T: Real>(
        x: &SVector<T, 4>,
        p: &SVector<T, 7>,
        loads: &SVector<T, 5>,
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
        let gamma0 = p[6];
        let m_gamma = loads[0];
        let m_psi = loads[1];
        let f_x = loads[2];
        let f_y = loads[3];
        let f_z = loads[4];
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
        let t25 = T::from_f64(0.5) * t6;
        let t26 = T::from_f64(0.08333333333333333) * t19;
        let t27 = t2 * t3;
        let t28 = t27 * d_hole;
        let t29 = t13 * t28;
        let t30 = (-T::from_f64(2.0) * t29 * (d_hole + T::from_f64(2.0) * t29)).sqrt();
        let t31 = T::from_f64(0.5) * h - T::from_f64(0.5) * t8;
        let t32 = (t28 * t7).hypot(t11);
        let t33 = t30 / t32;
        let t34 = d_peg * t4 * t12;
        let t35 = t34 * t7;
        let t36 = t13 * t6;
        let t37 = t35 - T::from_f64(0.5) * t36;
        let t38 = sin_gamma * t31;
        let t39 = -t35 + T::from_f64(0.5) * t36;
        let t40 = t15 / (sin_gamma * sin_gamma * sin_gamma);
        let t41 = t40 * t6;
        let t42 = t13 * t34;
        let t43 = h - t8;
        let t44 = t43 * t43;
        let t45 = t7 / t32;
        let t46 = t45 * t28;
        let t47 = -(T::from_f64(0.5) * h) + T::from_f64(0.5) * t8;
        let t48 = cos_gamma * t47 + sin_gamma * t37;
        let t49 = cos_gamma * (t28 * t10 + t39);
        let t50 = t11 + t49 - t38;
        let t51 = sin_gamma
            * (-t47 + t7 * (T::from_f64(0.5) * (t14 - t5) * d_peg + t25) + t41
                - T::from_f64(2.0) * t42) + T::from_f64(2.0) * cos_gamma * t37;
        let t52 = d_hole
            * (t27 * (-t7 - T::from_f64(2.0) * t40) - T::from_f64(0.5) * cos_gamma * t7)
            + cos_gamma
                * (-t31
                    + t7
                        * (T::from_f64(0.5) * (-t14 + t5) * d_peg
                            - T::from_f64(0.5) * t6) - t41 + T::from_f64(2.0) * t42)
            - T::from_f64(2.0) * sin_gamma * t39;
        let t53 = sin_gamma * t47;
        let t54 = t48 * t51;
        let t55 = t52 * (d_hole + T::from_f64(2.0) * t49 - T::from_f64(2.0) * t38);
        let t56 = T::from_f64(0.25) * t9 * (t36 - T::from_f64(2.0) * t35)
            * (T::from_f64(2.0) * h - T::from_f64(2.0) * t8);
        let t57 = t7 * (t25 + t28 * cos_gamma) * t45;
        let t58 = m * gammadot * psidot;
        let a = Matrix5::new(
            m * (t26 + t48 * t48 + t50 * t50),
            T::from_f64(0.0),
            T::from_f64(0.0),
            T::from_f64(0.0),
            T::from_f64(0.0),
            T::from_f64(0.0),
            m * (t9 * (T::from_f64(0.25) * t44 + t26) + T::from_f64(0.125) * t15 * t18),
            T::from_f64(0.0),
            T::from_f64(0.0),
            T::from_f64(0.0),
            m * t48,
            T::from_f64(0.0),
            -cos_gamma,
            t57,
            t57,
            T::from_f64(0.0),
            t53 * m,
            T::from_f64(0.0),
            t33,
            -t33,
            m * t50,
            T::from_f64(0.0),
            -sin_gamma,
            t46,
            t46,
        );
        let b = Vector5::new(
            m_gamma
                + m
                    * (t17 * (-(T::from_f64(0.125) * t18) + t26) * t24
                        + T::from_f64(0.5)
                            * (t16 * (T::from_f64(2.0) * t54 + t55)
                                + t17 * (T::from_f64(0.5) * t24 * t44 + t56)
                                - t16 * (T::from_f64(4.0) * t54 + T::from_f64(2.0) * t55))
                        - g * t50) + t48 * (t20 + t21) + f_z * t50,
            m_psi + t53 * (t22 + t23)
                - t58
                    * (t24
                        * (T::from_f64(0.5) * t44 - T::from_f64(0.25) * t18
                            + T::from_f64(0.16666666666666666) * t19) + t56),
            t20 + t21 - m * (t51 * t16 - t53 * t17),
            t22 + t23 - t58 * t48 * (T::from_f64(1.0) + T::from_f64(1.0)),
            f_z - m * g - m * t16 * t52,
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
    ///
    /// # Outputs
    /// - `a`: 5×5 matrix
    /// - `b`: vector of 5
    ///
    /// # Cost
    /// 68 add/sub, 131 mul, 5 div, 1 sqrt, 6 transcendental, 0 branches; 63 `let`s.
    #[inline]
    pub fn prescribed<T: Real>(
        x: &SVector<T, 4>,
        qdd: &SVector<T, 2>,
        p: &SVector<T, 7>,
        loads: &SVector<T, 5>,
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
        let gamma0 = p[6];
        let f_x = loads[2];
        let f_y = loads[3];
        let f_z = loads[4];
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
        let t25 = T::from_f64(0.5) * t6;
        let t26 = T::from_f64(0.08333333333333333) * t19;
        let t27 = t2 * t3;
        let t28 = t27 * d_hole;
        let t29 = t13 * t28;
        let t30 = (-T::from_f64(2.0) * t29 * (d_hole + T::from_f64(2.0) * t29)).sqrt();
        let t31 = T::from_f64(0.5) * h - T::from_f64(0.5) * t8;
        let t32 = (t28 * t7).hypot(t11);
        let t33 = t30 / t32;
        let t34 = d_peg * t4 * t12;
        let t35 = t34 * t7;
        let t36 = t13 * t6;
        let t37 = t35 - T::from_f64(0.5) * t36;
        let t38 = sin_gamma * t31;
        let t39 = -t35 + T::from_f64(0.5) * t36;
        let t40 = t15 / (sin_gamma * sin_gamma * sin_gamma);
        let t41 = t40 * t6;
        let t42 = t13 * t34;
        let t43 = h - t8;
        let t44 = t43 * t43;
        let t45 = t7 / t32;
        let t46 = t45 * t28;
        let t47 = -(T::from_f64(0.5) * h) + T::from_f64(0.5) * t8;
        let t48 = cos_gamma * t47 + sin_gamma * t37;
        let t49 = cos_gamma * (t28 * t10 + t39);
        let t50 = t11 + t49 - t38;
        let t51 = sin_gamma
            * (-t47 + t7 * (T::from_f64(0.5) * (t14 - t5) * d_peg + t25) + t41
                - T::from_f64(2.0) * t42) + T::from_f64(2.0) * cos_gamma * t37;
        let t52 = d_hole
            * (t27 * (-t7 - T::from_f64(2.0) * t40) - T::from_f64(0.5) * cos_gamma * t7)
            + cos_gamma
                * (-t31
                    + t7
                        * (T::from_f64(0.5) * (-t14 + t5) * d_peg
                            - T::from_f64(0.5) * t6) - t41 + T::from_f64(2.0) * t42)
            - T::from_f64(2.0) * sin_gamma * t39;
        let t53 = sin_gamma * t47;
        let t54 = t48 * t51;
        let t55 = t52 * (d_hole + T::from_f64(2.0) * t49 - T::from_f64(2.0) * t38);
        let t56 = T::from_f64(0.25) * t9 * (t36 - T::from_f64(2.0) * t35)
            * (T::from_f64(2.0) * h - T::from_f64(2.0) * t8);
        let t57 = t7 * (t25 + t28 * cos_gamma) * t45;
        let t58 = gammadot * psidot;
        let a = Matrix5::new(
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
            t57,
            t57,
            T::from_f64(0.0),
            T::from_f64(0.0),
            T::from_f64(0.0),
            t33,
            -t33,
            T::from_f64(0.0),
            T::from_f64(0.0),
            -sin_gamma,
            t46,
            t46,
        );
        let b = Vector5::new(
            m
                * (t17 * (-(T::from_f64(0.125) * t18) + t26) * t24
                    + T::from_f64(0.5)
                        * (t16 * (T::from_f64(2.0) * t54 + t55)
                            + t17 * (T::from_f64(0.5) * t24 * t44 + t56)
                            - t16 * (T::from_f64(4.0) * t54 + T::from_f64(2.0) * t55))
                    - g * t50 - gammaddot * (t26 + t48 * t48 + t50 * t50))
                + t48 * (t20 + t21) + f_z * t50,
            m
                * (-(t58
                    * (t24
                        * (T::from_f64(0.5) * t44 - T::from_f64(0.25) * t18
                            + T::from_f64(0.16666666666666666) * t19) + t56))
                    - psiddot
                        * (t9 * (T::from_f64(0.25) * t44 + t26)
                            + T::from_f64(0.125) * t15 * t18)) + t53 * (t22 + t23),
            t20 + t21 - m * (t51 * t16 + gammaddot * t48 - t53 * t17),
            t22 + t23
                - m
                    * (t58 * (t48 * (T::from_f64(1.0) + T::from_f64(1.0)))
                        + t53 * psiddot),
            f_z - m * g - m * (t16 * t52 + gammaddot * t50),
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
}
