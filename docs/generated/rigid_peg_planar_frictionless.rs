// @generated readable copy of `pegdyn::generated::rigid_peg_planar_frictionless` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generated_snapshot

/// Rigid peg leaning on the hole edge at K, B1, B2 (seed 000), variant `PlanarFrictionless`, derived by the generator (equations/src/models/rigid_peg.rs).
/// State x = (`gamma`, `gammadot`); parameters p = (D_hole, d_peg, H, m, g, f, gamma0); loads = (`M_gamma`, `F_x`, `F_z`).
/// Vectors in rotating components (e_η, e_n, e_z); ψ ≡ 0, so `F_x` is the in-plane horizontal force (along e_η) and N_B = N_B1 = N_B2. SI units.
pub mod rigid_peg_planar_frictionless {
    use nalgebra::{Matrix3, SMatrix, SVector, Vector3};
    /// Symbol names of the components of `x`, in order.
    pub const X_NAMES: [&str; 2] = ["gamma", "gammadot"];
    /// Symbol names of the components of `p`, in order.
    pub const P_NAMES: [&str; 7] = ["D_hole", "d_peg", "H", "m", "g", "f", "gamma0"];
    /// Symbol names of the components of `loads`, in order.
    pub const LOADS_NAMES: [&str; 3] = ["M_gamma", "F_x", "F_z"];
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
    ///
    /// # Outputs
    /// - `a`: 3×3 matrix
    /// - `b`: vector of 3
    ///
    /// # Cost
    /// 49 add/sub, 173 mul, 4 div, 0 sqrt, 9 transcendental, 0 branches; 34 `let`s.
    #[inline]
    pub fn forward(
        x: &SVector<f64, 2>,
        p: &SVector<f64, 7>,
        loads: &SVector<f64, 3>,
    ) -> (SMatrix<f64, 3, 3>, SVector<f64, 3>) {
        let gamma = x[0];
        let gammadot = x[1];
        let d_hole = p[0];
        let d_peg = p[1];
        let h = p[2];
        let m = p[3];
        let g = p[4];
        let gamma0 = p[6];
        let m_gamma = loads[0];
        let f_x = loads[1];
        let f_z = loads[2];
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
        let t11 = 1.0 / (sin_gamma * sin_gamma);
        let t12 = -0.5 * t8 * t9;
        let t13 = 0.5 * h + t12;
        let t14 = t10 - 0.5 * h;
        let t15 = (d_hole * t3 * t5 * t9).hypot(0.5 * d_hole);
        let t16 = 1.0 / t15;
        let t17 = t1.cos();
        let t18 = d_peg * t6 * t9 * t17 - 0.5 * cos_gamma * t8 * t11;
        let t19 = cos_gamma * t14 + sin_gamma * t18;
        let t20 = t2.cos();
        let t21 = t4.cos();
        let t22 = -(d_peg * t6 * t9 * t17) + 0.5 * cos_gamma * t8 * t11;
        let t23 = d_hole * cos_gamma * t3 * t5 * t11 - 0.5 * d_hole * t5 * t9 * t20
            + 0.5 * d_hole * t3 * t9 * t21 - sin_gamma * t13 + cos_gamma * t22;
        let t24 = t17 * t17;
        let t25 = 1.0 / (sin_gamma * sin_gamma * sin_gamma);
        let t26 = cos_gamma * cos_gamma;
        let t27 = -(sin_gamma * t14)
            + sin_gamma
                * (t10 + 0.5 * d_peg * t9 * t24 - 0.5 * d_peg * t7 * t9 + t8 * t25 * t26
                    - 2.0 * d_peg * cos_gamma * t6 * t11 * t17) + 2.0 * cos_gamma * t18;
        let t28 = gammadot * gammadot;
        let t29 = -(2.0 * d_hole * t3 * t5 * t25 * t26)
            + d_hole * cos_gamma * t5 * t11 * t20 - cos_gamma * t13
            + cos_gamma
                * (t12 - 0.5 * d_peg * t9 * t24 + 0.5 * d_peg * t7 * t9 - t8 * t25 * t26
                    + 2.0 * d_peg * cos_gamma * t6 * t11 * t17)
            - 0.5 * d_hole * t3 * t5 * t9 - d_hole * cos_gamma * t3 * t11 * t21
            + 0.5 * d_hole * t9 * t20 * t21 - 2.0 * sin_gamma * t22;
        let t30 = 2.0 * cos_gamma * t14 + 2.0 * sin_gamma * t18;
        let t31 = 2.0 * d_hole * cos_gamma * t3 * t5 * t11 + d_hole * t3 * t9 * t21
            - d_hole * t5 * t9 * t20 - 2.0 * sin_gamma * t13 + 2.0 * cos_gamma * t22;
        let a = Matrix3::new(
            0.08333333333333333 * m * (0.75 * (d_peg * d_peg) + h * h)
                + 0.5 * m * (2.0 * (t19 * t19) + 2.0 * (t23 * t23)),
            0.0,
            0.0,
            m * t19,
            -cos_gamma,
            2.0 * t9 * (t10 + d_hole * cos_gamma * t3 * t5 * t9) * t16,
            m * t23,
            -sin_gamma,
            2.0 * d_hole * t3 * t5 * t9 * t16,
        );
        let b = Vector3::new(
            m_gamma + f_z * t23 - m * g * t23
                - 0.5 * m * gammadot
                    * (2.0 * gammadot * t27 * t30 + 2.0 * gammadot * t29 * t31)
                + f_x * t19 + 0.5 * m * (t27 * t28 * t30 + t28 * t29 * t31),
            f_x - m * t27 * t28,
            f_z - m * g - m * t28 * t29,
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
    ///
    /// # Outputs
    /// - `a`: 3×3 matrix
    /// - `b`: vector of 3
    ///
    /// # Cost
    /// 51 add/sub, 174 mul, 4 div, 0 sqrt, 9 transcendental, 0 branches; 34 `let`s.
    #[inline]
    pub fn prescribed(
        x: &SVector<f64, 2>,
        qdd: &SVector<f64, 1>,
        p: &SVector<f64, 7>,
        loads: &SVector<f64, 3>,
    ) -> (SMatrix<f64, 3, 3>, SVector<f64, 3>) {
        let gamma = x[0];
        let gammadot = x[1];
        let gammaddot = qdd[0];
        let d_hole = p[0];
        let d_peg = p[1];
        let h = p[2];
        let m = p[3];
        let g = p[4];
        let gamma0 = p[6];
        let f_x = loads[1];
        let f_z = loads[2];
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
        let t11 = 1.0 / (sin_gamma * sin_gamma);
        let t12 = -0.5 * t8 * t9;
        let t13 = 0.5 * h + t12;
        let t14 = t10 - 0.5 * h;
        let t15 = (d_hole * t3 * t5 * t9).hypot(0.5 * d_hole);
        let t16 = 1.0 / t15;
        let t17 = t1.cos();
        let t18 = d_peg * t6 * t9 * t17 - 0.5 * cos_gamma * t8 * t11;
        let t19 = cos_gamma * t14 + sin_gamma * t18;
        let t20 = t2.cos();
        let t21 = t4.cos();
        let t22 = -(d_peg * t6 * t9 * t17) + 0.5 * cos_gamma * t8 * t11;
        let t23 = d_hole * cos_gamma * t3 * t5 * t11 - 0.5 * d_hole * t5 * t9 * t20
            + 0.5 * d_hole * t3 * t9 * t21 - sin_gamma * t13 + cos_gamma * t22;
        let t24 = t17 * t17;
        let t25 = 1.0 / (sin_gamma * sin_gamma * sin_gamma);
        let t26 = cos_gamma * cos_gamma;
        let t27 = -(sin_gamma * t14)
            + sin_gamma
                * (t10 + 0.5 * d_peg * t9 * t24 - 0.5 * d_peg * t7 * t9 + t8 * t25 * t26
                    - 2.0 * d_peg * cos_gamma * t6 * t11 * t17) + 2.0 * cos_gamma * t18;
        let t28 = gammadot * gammadot;
        let t29 = -(2.0 * d_hole * t3 * t5 * t25 * t26)
            + d_hole * cos_gamma * t5 * t11 * t20 - cos_gamma * t13
            + cos_gamma
                * (t12 - 0.5 * d_peg * t9 * t24 + 0.5 * d_peg * t7 * t9 - t8 * t25 * t26
                    + 2.0 * d_peg * cos_gamma * t6 * t11 * t17)
            - 0.5 * d_hole * t3 * t5 * t9 - d_hole * cos_gamma * t3 * t11 * t21
            + 0.5 * d_hole * t9 * t20 * t21 - 2.0 * sin_gamma * t22;
        let t30 = 2.0 * cos_gamma * t14 + 2.0 * sin_gamma * t18;
        let t31 = 2.0 * d_hole * cos_gamma * t3 * t5 * t11 + d_hole * t3 * t9 * t21
            - d_hole * t5 * t9 * t20 - 2.0 * sin_gamma * t13 + 2.0 * cos_gamma * t22;
        let a = Matrix3::new(
            -1.0,
            0.0,
            0.0,
            0.0,
            -cos_gamma,
            2.0 * t9 * (t10 + d_hole * cos_gamma * t3 * t5 * t9) * t16,
            0.0,
            -sin_gamma,
            2.0 * d_hole * t3 * t5 * t9 * t16,
        );
        let b = Vector3::new(
            f_z * t23 - m * g * t23
                - 0.5 * m * gammadot
                    * (2.0 * gammadot * t27 * t30 + 2.0 * gammadot * t29 * t31)
                + f_x * t19 + 0.5 * m * (t27 * t28 * t30 + t28 * t29 * t31)
                - gammaddot
                    * (0.08333333333333333 * m * (0.75 * (d_peg * d_peg) + h * h)
                        + 0.5 * m * (2.0 * (t19 * t19) + 2.0 * (t23 * t23))),
            f_x - m * (t27 * t28 + gammaddot * t19),
            f_z - m * g - m * (t28 * t29 + gammaddot * t23),
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
    /// 20 add/sub, 57 mul, 2 div, 0 sqrt, 8 transcendental, 0 branches; 22 `let`s.
    #[inline]
    pub fn contact_velocities(
        x: &SVector<f64, 2>,
        p: &SVector<f64, 7>,
    ) -> SMatrix<f64, 3, 3> {
        let gamma = x[0];
        let gammadot = x[1];
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
        let t11 = 0.5 * h - 0.5 * t7 * t8;
        let t12 = t9 - 0.5 * h;
        let t13 = t1.cos();
        let t14 = t2.cos();
        let t15 = t4.cos();
        let t16 = gammadot
            * (d_hole * cos_gamma * t3 * t5 * t10 - 0.5 * d_hole * t5 * t8 * t14
                + 0.5 * d_hole * t3 * t8 * t15 - sin_gamma * t11
                + cos_gamma * (-(d_peg * t6 * t8 * t13) + 0.5 * cos_gamma * t7 * t10));
        let t17 = -sin_gamma * t12;
        let t18 = gammadot
            * (cos_gamma * t12
                + sin_gamma * (d_peg * t6 * t8 * t13 - 0.5 * cos_gamma * t7 * t10))
            - gammadot * (d_hole * t3 * t5 * t8 - cos_gamma * t11);
        let t19 = t16 + gammadot * (t8 * (t9 + d_hole * cos_gamma * t3 * t5 * t8) + t17);
        Matrix3::new(
            t18,
            0.0,
            t16 + gammadot * (-(0.5 * d_hole) + t17),
            t18,
            0.0,
            t19,
            t18,
            0.0,
            t19,
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
    /// 19 add/sub, 60 mul, 2 div, 0 sqrt, 8 transcendental, 0 branches; 21 `let`s.
    #[inline]
    pub fn energy(x: &SVector<f64, 2>, p: &SVector<f64, 7>) -> (f64, f64) {
        let gamma = x[0];
        let gammadot = x[1];
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
        let t9 = 1.0 / (sin_gamma * sin_gamma);
        let t10 = 0.5 * h - 0.5 * t7 * t8;
        let t11 = t1.cos();
        let t12 = cos_gamma * (0.5 * t7 * t8 - 0.5 * h)
            + sin_gamma * (d_peg * t6 * t8 * t11 - 0.5 * cos_gamma * t7 * t9);
        let t13 = t2.cos();
        let t14 = t4.cos();
        let t15 = d_hole * cos_gamma * t3 * t5 * t9 - 0.5 * d_hole * t5 * t8 * t13
            + 0.5 * d_hole * t3 * t8 * t14 - sin_gamma * t10
            + cos_gamma * (-(d_peg * t6 * t8 * t11) + 0.5 * cos_gamma * t7 * t9);
        let t16 = gammadot * gammadot;
        let t17 = 0.5 * m * (t16 * (t12 * t12) + t16 * (t15 * t15));
        let t18 = 0.041666666666666664 * m * t16 * (0.75 * (d_peg * d_peg) + h * h);
        let kinetic = t17 + t18;
        let total = m * g * (-(d_hole * t3 * t5 * t8) + cos_gamma * t10) + t17 + t18;
        (kinetic, total)
    }
}
