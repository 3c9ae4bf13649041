// @generated readable copy of `pegdyn::generated::rigid_peg_frictionless` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generated_snapshot

/// Rigid peg leaning on the hole edge at K, B1, B2 (seed 000), variant `Frictionless`, derived by the generator (equations/src/models/rigid_peg.rs).
/// State x = (`gamma`, `psi`, `gammadot`, `psidot`); parameters p = (D_hole, d_peg, H, m, g, f, gamma0); loads = (`M_gamma`, `M_psi`, `F_x`, `F_y`, `F_z`).
/// Vectors in rotating components (e_η, e_n, e_z). SI units.
pub mod rigid_peg_frictionless {
    use nalgebra::{Matrix3, Matrix5, SMatrix, SVector, Vector5};
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
    /// 72 add/sub, 258 mul, 4 div, 1 sqrt, 11 transcendental, 0 branches; 52 `let`s.
    #[inline]
    pub fn forward(
        x: &SVector<f64, 4>,
        p: &SVector<f64, 7>,
        loads: &SVector<f64, 5>,
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
        let gamma0 = p[6];
        let m_gamma = loads[0];
        let m_psi = loads[1];
        let f_x = loads[2];
        let f_y = loads[3];
        let f_z = loads[4];
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
        let t11 = sin_gamma * sin_gamma;
        let t12 = 1.0 / (sin_gamma * sin_gamma);
        let t13 = 2.0 * d_hole * cos_gamma * t3 * t5 * t12;
        let t14 = (-2.0 * d_hole * cos_gamma * t3 * t5 * t12 * (d_hole + t13)).sqrt();
        let t15 = -0.5 * t8 * t9;
        let t16 = 0.5 * h + t15;
        let t17 = t10 - 0.5 * h;
        let t18 = (d_hole * t3 * t5 * t9).hypot(0.5 * d_hole);
        let t19 = 1.0 / t18;
        let t20 = t1.cos();
        let t21 = d_peg * t6 * t9 * t20 - 0.5 * cos_gamma * t8 * t12;
        let t22 = cos_gamma * t17 + sin_gamma * t21;
        let t23 = t2.cos();
        let t24 = t4.cos();
        let t25 = -(d_peg * t6 * t9 * t20) + 0.5 * cos_gamma * t8 * t12;
        let t26 = d_hole * cos_gamma * t3 * t5 * t12 - 0.5 * d_hole * t5 * t9 * t23
            + 0.5 * d_hole * t3 * t9 * t24 - sin_gamma * t16 + cos_gamma * t25;
        let t27 = t20 * t20;
        let t28 = 1.0 / (sin_gamma * sin_gamma * sin_gamma);
        let t29 = cos_gamma * cos_gamma;
        let t30 = -(sin_gamma * t17)
            + sin_gamma
                * (t10 + 0.5 * d_peg * t9 * t27 - 0.5 * d_peg * t7 * t9 + t8 * t28 * t29
                    - 2.0 * d_peg * cos_gamma * t6 * t12 * t20) + 2.0 * cos_gamma * t21;
        let t31 = gammadot * gammadot;
        let t32 = -(2.0 * d_hole * t3 * t5 * t28 * t29)
            + d_hole * cos_gamma * t5 * t12 * t23 - cos_gamma * t16
            + cos_gamma
                * (t15 - 0.5 * d_peg * t9 * t27 + 0.5 * d_peg * t7 * t9 - t8 * t28 * t29
                    + 2.0 * d_peg * cos_gamma * t6 * t12 * t20)
            - 0.5 * d_hole * t3 * t5 * t9 - d_hole * cos_gamma * t3 * t12 * t24
            + 0.5 * d_hole * t9 * t23 * t24 - 2.0 * sin_gamma * t25;
        let t33 = psidot * psidot;
        let t34 = d_peg * d_peg;
        let t35 = 0.75 * t34 + h * h;
        let t36 = h - t8 * t9;
        let t37 = t36 * t36;
        let sin_psi = psi.sin();
        let cos_psi = psi.cos();
        let t38 = f_x * cos_psi;
        let t39 = f_y * sin_psi;
        let t40 = f_y * cos_psi;
        let t41 = -f_x * sin_psi;
        let t42 = 2.0 * cos_gamma * t17 + 2.0 * sin_gamma * t21;
        let t43 = t13 + d_hole * t3 * t9 * t24 - d_hole * t5 * t9 * t23
            - 2.0 * sin_gamma * t16 + 2.0 * cos_gamma * t25;
        let t44 = cos_gamma * t8 * t12 - 2.0 * d_peg * t6 * t9 * t20;
        let t45 = 2.0 * h - 2.0 * t8 * t9;
        let t46 = t9 * (t10 + d_hole * cos_gamma * t3 * t5 * t9) * t19;
        let t47 = d_hole * t3 * t5 * t9 * t19;
        let a = Matrix5::new(
            0.08333333333333333 * m * t35
                + 0.5 * m * (2.0 * (t22 * t22) + 2.0 * (t26 * t26)),
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.25 * m * t11 * t37 + 0.125 * m * t29 * t34
                + 0.08333333333333333 * m * t11 * t35,
            0.0,
            0.0,
            0.0,
            m * t22,
            0.0,
            -cos_gamma,
            t46,
            t46,
            0.0,
            m * sin_gamma * t17,
            0.0,
            t14 * t19,
            -t14 * t19,
            m * t26,
            0.0,
            -sin_gamma,
            t47,
            t47,
        );
        let b = Vector5::new(
            m_gamma + t22 * (t38 + t39) + f_z * t26 - m * g * t26
                + 0.5 * m
                    * (t30 * t31 * t42 + 0.5 * sin_gamma * cos_gamma * t33 * t37
                        + 0.25 * t11 * t33 * t44 * t45 + t31 * t32 * t43)
                - 0.125 * m * sin_gamma * cos_gamma * t33 * t34
                + 0.08333333333333333 * m * sin_gamma * cos_gamma * t33 * t35
                - 0.5 * m * gammadot
                    * (2.0 * gammadot * t30 * t42 + 2.0 * gammadot * t32 * t43),
            m_psi + sin_gamma * t17 * (t40 + t41)
                - gammadot
                    * (0.5 * m * psidot * sin_gamma * cos_gamma * t37
                        + 0.25 * m * psidot * t11 * t44 * t45
                        - 0.25 * m * psidot * sin_gamma * cos_gamma * t34
                        + 0.16666666666666666 * m * psidot * sin_gamma * cos_gamma
                            * t35),
            t38 + t39 - m * (t30 * t31 - sin_gamma * t17 * t33),
            t40 + t41
                - m
                    * (gammadot * (psidot * cos_gamma * t17 + psidot * sin_gamma * t21)
                        + gammadot * psidot * t22),
            f_z - m * g - m * t31 * t32,
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
    /// 75 add/sub, 260 mul, 4 div, 1 sqrt, 11 transcendental, 0 branches; 52 `let`s.
    #[inline]
    pub fn prescribed(
        x: &SVector<f64, 4>,
        qdd: &SVector<f64, 2>,
        p: &SVector<f64, 7>,
        loads: &SVector<f64, 5>,
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
        let gamma0 = p[6];
        let f_x = loads[2];
        let f_y = loads[3];
        let f_z = loads[4];
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
        let t11 = sin_gamma * sin_gamma;
        let t12 = 1.0 / (sin_gamma * sin_gamma);
        let t13 = 2.0 * d_hole * cos_gamma * t3 * t5 * t12;
        let t14 = (-2.0 * d_hole * cos_gamma * t3 * t5 * t12 * (d_hole + t13)).sqrt();
        let t15 = -0.5 * t8 * t9;
        let t16 = 0.5 * h + t15;
        let t17 = t10 - 0.5 * h;
        let t18 = (d_hole * t3 * t5 * t9).hypot(0.5 * d_hole);
        let t19 = 1.0 / t18;
        let t20 = t1.cos();
        let t21 = d_peg * t6 * t9 * t20 - 0.5 * cos_gamma * t8 * t12;
        let t22 = cos_gamma * t17 + sin_gamma * t21;
        let t23 = t2.cos();
        let t24 = t4.cos();
        let t25 = -(d_peg * t6 * t9 * t20) + 0.5 * cos_gamma * t8 * t12;
        let t26 = d_hole * cos_gamma * t3 * t5 * t12 - 0.5 * d_hole * t5 * t9 * t23
            + 0.5 * d_hole * t3 * t9 * t24 - sin_gamma * t16 + cos_gamma * t25;
        let t27 = t20 * t20;
        let t28 = 1.0 / (sin_gamma * sin_gamma * sin_gamma);
        let t29 = cos_gamma * cos_gamma;
        let t30 = -(sin_gamma * t17)
            + sin_gamma
                * (t10 + 0.5 * d_peg * t9 * t27 - 0.5 * d_peg * t7 * t9 + t8 * t28 * t29
                    - 2.0 * d_peg * cos_gamma * t6 * t12 * t20) + 2.0 * cos_gamma * t21;
        let t31 = gammadot * gammadot;
        let t32 = -(2.0 * d_hole * t3 * t5 * t28 * t29)
            + d_hole * cos_gamma * t5 * t12 * t23 - cos_gamma * t16
            + cos_gamma
                * (t15 - 0.5 * d_peg * t9 * t27 + 0.5 * d_peg * t7 * t9 - t8 * t28 * t29
                    + 2.0 * d_peg * cos_gamma * t6 * t12 * t20)
            - 0.5 * d_hole * t3 * t5 * t9 - d_hole * cos_gamma * t3 * t12 * t24
            + 0.5 * d_hole * t9 * t23 * t24 - 2.0 * sin_gamma * t25;
        let t33 = psidot * psidot;
        let t34 = d_peg * d_peg;
        let t35 = 0.75 * t34 + h * h;
        let t36 = h - t8 * t9;
        let t37 = t36 * t36;
        let sin_psi = psi.sin();
        let cos_psi = psi.cos();
        let t38 = f_x * cos_psi;
        let t39 = f_y * sin_psi;
        let t40 = f_y * cos_psi;
        let t41 = -f_x * sin_psi;
        let t42 = 2.0 * cos_gamma * t17 + 2.0 * sin_gamma * t21;
        let t43 = t13 + d_hole * t3 * t9 * t24 - d_hole * t5 * t9 * t23
            - 2.0 * sin_gamma * t16 + 2.0 * cos_gamma * t25;
        let t44 = cos_gamma * t8 * t12 - 2.0 * d_peg * t6 * t9 * t20;
        let t45 = 2.0 * h - 2.0 * t8 * t9;
        let t46 = t9 * (t10 + d_hole * cos_gamma * t3 * t5 * t9) * t19;
        let t47 = d_hole * t3 * t5 * t9 * t19;
        let a = Matrix5::new(
            -1.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            -1.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            -cos_gamma,
            t46,
            t46,
            0.0,
            0.0,
            0.0,
            t14 * t19,
            -t14 * t19,
            0.0,
            0.0,
            -sin_gamma,
            t47,
            t47,
        );
        let b = Vector5::new(
            t22 * (t38 + t39) + f_z * t26 - m * g * t26
                + 0.5 * m
                    * (t30 * t31 * t42 + 0.5 * sin_gamma * cos_gamma * t33 * t37
                        + 0.25 * t11 * t33 * t44 * t45 + t31 * t32 * t43)
                - 0.125 * m * sin_gamma * cos_gamma * t33 * t34
                + 0.08333333333333333 * m * sin_gamma * cos_gamma * t33 * t35
                - 0.5 * m * gammadot
                    * (2.0 * gammadot * t30 * t42 + 2.0 * gammadot * t32 * t43)
                - gammaddot
                    * (0.08333333333333333 * m * t35
                        + 0.5 * m * (2.0 * (t22 * t22) + 2.0 * (t26 * t26))),
            sin_gamma * t17 * (t40 + t41)
                - gammadot
                    * (0.5 * m * psidot * sin_gamma * cos_gamma * t37
                        + 0.25 * m * psidot * t11 * t44 * t45
                        - 0.25 * m * psidot * sin_gamma * cos_gamma * t34
                        + 0.16666666666666666 * m * psidot * sin_gamma * cos_gamma * t35)
                - psiddot
                    * (0.25 * m * t11 * t37 + 0.125 * m * t29 * t34
                        + 0.08333333333333333 * m * t11 * t35),
            t38 + t39 - m * (t30 * t31 + gammaddot * t22 - sin_gamma * t17 * t33),
            t40 + t41
                - m
                    * (gammadot * (psidot * cos_gamma * t17 + psidot * sin_gamma * t21)
                        + psiddot * sin_gamma * t17 + gammadot * psidot * t22),
            f_z - m * g - m * (t31 * t32 + gammaddot * t26),
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
}
