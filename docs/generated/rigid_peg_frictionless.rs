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
    /// 58 add/sub, 121 mul, 4 div, 1 sqrt, 6 transcendental, 0 branches; 59 `let`s.
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
        let t14 = T::from_f64(0.5) * e;
        let t15 = T::from_f64(1.0 / 12.0) * t8;
        let t16 = sin_sum * sin_diff;
        let t17 = t16 * d_hole;
        let lever = T::from_f64(0.5) * h - T::from_f64(0.5) * t2;
        let ob = (t17 * t1).hypot(half_d);
        let t18 = d_peg * sin_half_gamma * cos_half_gamma;
        let t19 = t18 * t1;
        let t20 = sin_gamma * lever;
        let t21 = t4 / (sin_gamma * sin_gamma * sin_gamma);
        let t22 = h - t2;
        let t23 = t22 * t22;
        let t24 = t1 / ob;
        let t25 = t24 * t17;
        let t26 = t1 * (t14 + t17 * cos_gamma) * t24;
        let t27 = m * gammadot * psidot;
        let t28 = t1 * t1;
        let t29 = cos_gamma * t28;
        let t30 = t17 * t29;
        let bb1 = (-T::from_f64(2.0) * t30 * (d_hole + T::from_f64(2.0) * t30)).sqrt();
        let t31 = bb1 / ob;
        let t32 = t29 * e;
        let t33 = t19 - T::from_f64(0.5) * t32;
        let t34 = sin_gamma * t33;
        let t35 = cos_gamma * (t17 * t28 - t33);
        let t36 = half_d + t35 - t20;
        let t37 = t3 * (T::from_f64(2.0) * h - T::from_f64(2.0) * t2)
            * (-t32 + T::from_f64(2.0) * t19);
        let t38 = -(cos_gamma * lever) + t34;
        let t39 = lever
            + t1
                * (-(T::from_f64(0.5)
                    * (d_peg * (-cos_half_gamma * cos_half_gamma + t0))) + t14) + t21 * e
            - T::from_f64(2.0) * t18 * t29;
        let t40 = sin_gamma * t39 + T::from_f64(2.0) * cos_gamma * t33;
        let t41 = d_hole
            * (t16 * (t1 + T::from_f64(2.0) * t21) + T::from_f64(0.5) * cos_gamma * t1)
            + cos_gamma * t39 - T::from_f64(2.0) * t34;
        let t42 = t38 * t40;
        let t43 = (d_hole + T::from_f64(2.0) * t35 - T::from_f64(2.0) * t20) * t41;
        let a = Matrix5::new(
            m * (t15 + t38 * t38 + t36 * t36),
            T::from_f64(0.0),
            T::from_f64(0.0),
            T::from_f64(0.0),
            T::from_f64(0.0),
            T::from_f64(0.0),
            m * (t3 * (T::from_f64(0.25) * t23 + t15) + T::from_f64(0.125) * t4 * t7),
            T::from_f64(0.0),
            T::from_f64(0.0),
            T::from_f64(0.0),
            m * t38,
            T::from_f64(0.0),
            -cos_gamma,
            t26,
            t26,
            T::from_f64(0.0),
            -t20 * m,
            T::from_f64(0.0),
            t31,
            -t31,
            m * t36,
            T::from_f64(0.0),
            -sin_gamma,
            t25,
            t25,
        );
        let b = Vector5::new(
            m_gamma
                - m
                    * (-(t6 * (-(T::from_f64(0.125) * t7) + t15) * t12)
                        + T::from_f64(0.5)
                            * (-(t5 * (T::from_f64(2.0) * t42 - t43)
                                + t6
                                    * (T::from_f64(0.5) * t12 * t23 - T::from_f64(0.25) * t37))
                                + t5 * (T::from_f64(4.0) * t42 - T::from_f64(2.0) * t43))
                        + g * t36) + t38 * (t9 + t10) + f_z * t36,
            m_psi + t20 * (t13 + t11)
                + t27
                    * (-(t12
                        * (T::from_f64(0.5) * t23 - T::from_f64(0.25) * t7
                            + T::from_f64(1.0 / 6.0) * t8)) + T::from_f64(0.25) * t37),
            t9 + t10 - m * (t40 * t5 + t20 * t6),
            -t13 - t11 - t27 * t38 * (T::from_f64(1.0) + T::from_f64(1.0)),
            f_z - m * g + m * t5 * t41,
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
    /// 61 add/sub, 123 mul, 4 div, 1 sqrt, 6 transcendental, 0 branches; 59 `let`s.
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
        let t14 = T::from_f64(0.5) * e;
        let t15 = T::from_f64(1.0 / 12.0) * t8;
        let t16 = sin_sum * sin_diff;
        let t17 = t16 * d_hole;
        let lever = T::from_f64(0.5) * h - T::from_f64(0.5) * t2;
        let ob = (t17 * t1).hypot(half_d);
        let t18 = d_peg * sin_half_gamma * cos_half_gamma;
        let t19 = t18 * t1;
        let t20 = sin_gamma * lever;
        let t21 = t4 / (sin_gamma * sin_gamma * sin_gamma);
        let t22 = h - t2;
        let t23 = t22 * t22;
        let t24 = t1 / ob;
        let t25 = t24 * t17;
        let t26 = t1 * (t14 + t17 * cos_gamma) * t24;
        let t27 = t1 * t1;
        let t28 = cos_gamma * t27;
        let t29 = t17 * t28;
        let bb1 = (-T::from_f64(2.0) * t29 * (d_hole + T::from_f64(2.0) * t29)).sqrt();
        let t30 = bb1 / ob;
        let t31 = t28 * e;
        let t32 = t19 - T::from_f64(0.5) * t31;
        let t33 = sin_gamma * t32;
        let t34 = cos_gamma * (t17 * t27 - t32);
        let t35 = half_d + t34 - t20;
        let t36 = t3 * (T::from_f64(2.0) * h - T::from_f64(2.0) * t2)
            * (-t31 + T::from_f64(2.0) * t19);
        let t37 = -(cos_gamma * lever) + t33;
        let t38 = lever
            + t1
                * (-(T::from_f64(0.5)
                    * (d_peg * (-cos_half_gamma * cos_half_gamma + t0))) + t14) + t21 * e
            - T::from_f64(2.0) * t18 * t28;
        let t39 = sin_gamma * t38 + T::from_f64(2.0) * cos_gamma * t32;
        let t40 = d_hole
            * (t16 * (t1 + T::from_f64(2.0) * t21) + T::from_f64(0.5) * cos_gamma * t1)
            + cos_gamma * t38 - T::from_f64(2.0) * t33;
        let t41 = t37 * t39;
        let t42 = (d_hole + T::from_f64(2.0) * t34 - T::from_f64(2.0) * t20) * t40;
        let t43 = gammadot * psidot;
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
            t26,
            t26,
            T::from_f64(0.0),
            T::from_f64(0.0),
            T::from_f64(0.0),
            t30,
            -t30,
            T::from_f64(0.0),
            T::from_f64(0.0),
            -sin_gamma,
            t25,
            t25,
        );
        let b = Vector5::new(
            -(m
                * (t6 * (T::from_f64(0.125) * t7 - T::from_f64(1.0 / 12.0) * t8) * t13
                    + T::from_f64(0.5)
                        * (-(t5 * (T::from_f64(2.0) * t41 - t42)
                            + t6
                                * (T::from_f64(0.5) * t13 * t23 - T::from_f64(0.25) * t36))
                            + t5 * (T::from_f64(4.0) * t41 - T::from_f64(2.0) * t42))
                    + g * t35 + gammaddot * (t15 + t37 * t37 + t35 * t35)))
                + t37 * (t9 + t10) + f_z * t35,
            m
                * (t43
                    * (-(t13
                        * (T::from_f64(0.5) * t23 - T::from_f64(0.25) * t7
                            + T::from_f64(1.0 / 6.0) * t8)) + T::from_f64(0.25) * t36)
                    - psiddot
                        * (t3 * (T::from_f64(0.25) * t23 + t15)
                            + T::from_f64(0.125) * t4 * t7)) + t20 * (-t11 + t12),
            t9 + t10 - m * (t39 * t5 + gammaddot * t37 + t20 * t6),
            t11 - t12
                + m
                    * (-(t43 * ((T::from_f64(1.0) + T::from_f64(1.0)) * t37))
                        + t20 * psiddot),
            f_z - m * g - m * (-(t5 * t40) + gammaddot * t35),
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
}
