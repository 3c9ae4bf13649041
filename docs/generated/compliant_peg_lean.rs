// @generated readable copy of `pegdyn::generated::compliant_peg_lean` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generated_snapshot

/// Planar compliant peg-in-hole (paper 001, (31)-(51), (55)-(64)) with contacts edge_left, wall_right. Inputs: state y (see STATE) and parameters p (see P_NAMES). SI units.
pub mod compliant_peg_lean {
    use nalgebra::{SMatrix, SVector, Vector2};
    /// Symbol names of the components of `y`, in order.
    pub const Y_NAMES: [&str; 8] = [
        "x",
        "z",
        "theta",
        "xdot",
        "zdot",
        "thetadot",
        "work",
        "dissipation",
    ];
    /// Symbol names of the components of `p`, in order.
    pub const P_NAMES: [&str; 23] = [
        "m",
        "J",
        "r",
        "l_c",
        "D",
        "rho_p",
        "rho_h",
        "mu",
        "v_s",
        "k_edge",
        "k_wall",
        "f1",
        "f2",
        "M",
        "e_star",
        "edge_sum",
        "edge_ma",
        "edge_mb",
        "edge_dstar",
        "wall_sum",
        "wall_ma",
        "wall_mb",
        "wall_dstar",
    ];
    /// Right-hand side of y = (x, z, theta, xdot, zdot, thetadot, work, dissipation): M qdd = applied (50) + contact normal forces (-grad of the Hertz potential (62)) + Coulomb friction; work and dissipation rates. SI units.
    ///
    /// # Inputs
    /// - `y` = (`x`, `z`, `theta`, `xdot`, `zdot`, `thetadot`, `work`, `dissipation`)
    /// - `p` = (`m`, `J`, `r`, `l_c`, `D`, `rho_p`, `rho_h`, `mu`, `v_s`, `k_edge`, `k_wall`, `f1`, `f2`, `M`, `e_star`, `edge_sum`, `edge_ma`, `edge_mb`, `edge_dstar`, `wall_sum`, `wall_ma`, `wall_mb`, `wall_dstar`)
    ///
    /// # Outputs
    /// - `ydot`: vector of 8
    ///
    /// # Cost
    /// 43 add/sub, 88 mul, 4 div, 2 sqrt, 5 transcendental, 6 branches; 32 `let`s.
    #[inline]
    pub fn rhs(y: &SVector<f64, 8>, p: &SVector<f64, 23>) -> SVector<f64, 8> {
        let x = y[0];
        let z = y[1];
        let theta = y[2];
        let xdot = y[3];
        let zdot = y[4];
        let thetadot = y[5];
        let m = p[0];
        let j = p[1];
        let r = p[2];
        let l_c = p[3];
        let d = p[4];
        let rho_p = p[5];
        let rho_h = p[6];
        let mu = p[7];
        let v_s = p[8];
        let k_edge = p[9];
        let k_wall = p[10];
        let f1 = p[11];
        let f2 = p[12];
        let m_2 = p[13];
        let sin_theta = theta.sin();
        let cos_theta = theta.cos();
        let t0 = f1 * sin_theta;
        let t1 = f2 * cos_theta;
        let t2 = f1 * cos_theta;
        let t3 = -f2 * sin_theta;
        let t4 = -0.5 * d;
        let t5 = -rho_h + t4 - x;
        let t6 = rho_h - z;
        let t7 = r + rho_h + cos_theta * t5 - sin_theta * t6;
        let t8 = sin_theta * t5 + cos_theta * t6;
        let t9 = cos_theta * t8 + r * sin_theta;
        let t10 = -(sin_theta * t8) + r * cos_theta;
        let t11 = sin_theta * (xdot + thetadot * t9)
            + cos_theta * (zdot + thetadot * t10);
        let t12 = if t7 > 0.0 || t7.is_nan() { t7 } else { 0.0 };
        let t13 = t12 * t12.sqrt();
        let t14 = v_s.hypot(t11);
        let t15 = 1.0 / t14;
        let t16 = if t7 > 0.0 { 1.0 } else if t7.is_nan() { t7 } else { 0.0 };
        let t17 = -rho_p;
        let t18 = l_c + t17;
        let t19 = r + t17;
        let t20 = x + rho_p + t4 + sin_theta * t18 + cos_theta * t19;
        let t21 = (0.5 * theta).sin();
        let t22 = -(sin_theta * (l_c + t17 + rho_p * sin_theta))
            - cos_theta * (r - 2.0 * rho_p * (t21 * t21));
        let t23 = zdot + thetadot * t22;
        let t24 = if t20 > 0.0 || t20.is_nan() { t20 } else { 0.0 };
        let t25 = t24 * t24.sqrt();
        let t26 = v_s.hypot(t23);
        let t27 = 1.0 / t26;
        let t28 = if t20 > 0.0 { 1.0 } else if t20.is_nan() { t20 } else { 0.0 };
        let t29 = 1.0 / m;
        SMatrix::<
            f64,
            8,
            1,
        >::from_row_slice(
            &[
                xdot,
                zdot,
                thetadot,
                (t0 + t1 + k_edge * cos_theta * t13 * t16
                    - mu * k_edge * sin_theta * t11 * t13 * t15 - k_wall * t25 * t28)
                    * t29,
                (t2 + t3 - k_edge * sin_theta * t13 * t16
                    - mu * k_edge * cos_theta * t11 * t13 * t15
                    - mu * k_wall * t23 * t25 * t27) * t29,
                (m_2 - k_edge * t13 * t16 * (-(sin_theta * t5) - cos_theta * t6)
                    - mu * k_edge * t11 * t13 * t15 * (sin_theta * t9 + cos_theta * t10)
                    - k_wall * t25 * t28 * (cos_theta * t18 - sin_theta * t19)
                    - mu * k_wall * t22 * t23 * t25 * t27) / j,
                xdot * (t0 + t1) + zdot * (t2 + t3) + thetadot * m_2,
                mu * k_edge * t13 * t15 * (t11 * t11)
                    + mu * k_wall * t25 * t27 * (t23 * t23),
            ],
        )
    }
    /// Exact Jacobian d(rhs)/dy, row-major 8x8.
    ///
    /// # Inputs
    /// - `y` = (`x`, `z`, `theta`, `xdot`, `zdot`, `thetadot`, `work`, `dissipation`)
    /// - `p` = (`m`, `J`, `r`, `l_c`, `D`, `rho_p`, `rho_h`, `mu`, `v_s`, `k_edge`, `k_wall`, `f1`, `f2`, `M`, `e_star`, `edge_sum`, `edge_ma`, `edge_mb`, `edge_dstar`, `wall_sum`, `wall_ma`, `wall_mb`, `wall_dstar`)
    ///
    /// # Outputs
    /// - `jac`: 8×8 matrix
    ///
    /// # Cost
    /// 116 add/sub, 525 mul, 6 div, 4 sqrt, 6 transcendental, 6 branches; 79 `let`s.
    #[inline]
    pub fn jacobian(y: &SVector<f64, 8>, p: &SVector<f64, 23>) -> SMatrix<f64, 8, 8> {
        let x = y[0];
        let z = y[1];
        let theta = y[2];
        let xdot = y[3];
        let zdot = y[4];
        let thetadot = y[5];
        let m = p[0];
        let j = p[1];
        let r = p[2];
        let l_c = p[3];
        let d = p[4];
        let rho_p = p[5];
        let rho_h = p[6];
        let mu = p[7];
        let v_s = p[8];
        let k_edge = p[9];
        let k_wall = p[10];
        let f1 = p[11];
        let f2 = p[12];
        let m_2 = p[13];
        let sin_theta = theta.sin();
        let cos_theta = theta.cos();
        let t0 = f1 * cos_theta;
        let t1 = -f2 * sin_theta;
        let t2 = t0 + t1;
        let t3 = -0.5 * d;
        let t4 = -rho_h + t3 - x;
        let t5 = rho_h - z;
        let t6 = cos_theta * t4;
        let t7 = -sin_theta * t5;
        let t8 = t6 + t7;
        let t9 = r + rho_h + t6 + t7;
        let t10 = sin_theta * t4 + cos_theta * t5;
        let t11 = cos_theta * t10 + r * sin_theta;
        let t12 = xdot + thetadot * t11;
        let t13 = -sin_theta * t10;
        let t14 = r * cos_theta;
        let t15 = t13 + t14;
        let t16 = zdot + thetadot * t15;
        let t17 = sin_theta * t12 + cos_theta * t16;
        let t18 = if t9 > 0.0 || t9.is_nan() { t9 } else { 0.0 };
        let t19 = t18 * t18.sqrt();
        let t20 = v_s.hypot(t17);
        let t21 = 1.0 / t20;
        let t22 = if t9 > 0.0 { 1.0 } else if t9.is_nan() { t9 } else { 0.0 };
        let t23 = -k_edge * cos_theta * t19 * t22;
        let t24 = -k_edge * sin_theta * t19 * t22;
        let t25 = -(sin_theta * t4) - cos_theta * t5;
        let t26 = sin_theta * t11 + cos_theta * t15;
        let t27 = t17 * t17;
        let t28 = -rho_p;
        let t29 = l_c + t28;
        let t30 = r + t28;
        let t31 = x + rho_p + t3 + sin_theta * t29 + cos_theta * t30;
        let t32 = l_c + t28 + rho_p * sin_theta;
        let t33 = 0.5 * theta;
        let t34 = t33.sin();
        let t35 = r - 2.0 * rho_p * (t34 * t34);
        let t36 = -(sin_theta * t32) - cos_theta * t35;
        let t37 = zdot + thetadot * t36;
        let t38 = if t31 > 0.0 || t31.is_nan() { t31 } else { 0.0 };
        let t39 = t38 * t38.sqrt();
        let t40 = v_s.hypot(t37);
        let t41 = 1.0 / t40;
        let t42 = if t31 > 0.0 { 1.0 } else if t31.is_nan() { t31 } else { 0.0 };
        let t43 = cos_theta * t29 - sin_theta * t30;
        let t44 = t37 * t37;
        let t45 = 1.0 / m;
        let t46 = 1.0 / j;
        let t47 = t18.sqrt();
        let t48 = cos_theta * cos_theta;
        let t49 = t22 * t22;
        let t50 = sin_theta * sin_theta;
        let t51 = t38.sqrt();
        let t52 = t42 * t42;
        let t53 = 1.5 * k_edge * sin_theta * cos_theta * t47 * t49;
        let t54 = 1.5 * k_edge * cos_theta * t25 * t47 * t49;
        let t55 = t13 + t14 + cos_theta * t8;
        let t56 = -(r * sin_theta) - cos_theta * t10 - sin_theta * t8;
        let t57 = cos_theta * t12 + thetadot * sin_theta * t55 - sin_theta * t16
            + thetadot * cos_theta * t56;
        let t58 = 1.0 / (t20 * t20 * t20);
        let t59 = -1.5 * k_wall * t43 * t51 * t52;
        let t60 = t45
            * (-(mu * k_edge * sin_theta * cos_theta * t19 * t21)
                + mu * k_edge * sin_theta * cos_theta * t19 * t27 * t58);
        let t61 = -(mu * k_edge * sin_theta * t19 * t21 * t26)
            + mu * k_edge * sin_theta * t19 * t26 * t27 * t58;
        let t62 = -f1 * sin_theta;
        let t63 = -f2 * cos_theta;
        let t64 = -1.5 * k_edge * sin_theta * t25 * t47 * t49;
        let t65 = t33.cos();
        let t66 = sin_theta * t35 - cos_theta * t32 - rho_p * sin_theta * cos_theta
            + 2.0 * rho_p * cos_theta * t34 * t65;
        let t67 = 1.0 / (t40 * t40 * t40);
        let t68 = -(mu * k_edge * cos_theta * t19 * t21 * t26)
            + mu * k_edge * cos_theta * t19 * t26 * t27 * t58
            - mu * k_wall * t36 * t39 * t41 + mu * k_wall * t36 * t39 * t44 * t67;
        let t69 = sin_theta * t30 - cos_theta * t29;
        let t70 = t26 * t26;
        let t71 = cos_theta * t35 + sin_theta * t32;
        let t72 = t71 * t71;
        let t73 = t17 * t17 * t17;
        let t74 = 2.0 * sin_theta * t12 + 2.0 * cos_theta * t16;
        let t75 = t37 * t37 * t37;
        let t76 = 2.0 * zdot + 2.0 * thetadot * t36;
        SMatrix::<
            f64,
            8,
            8,
        >::from_row_slice(
            &[
                0.0,
                0.0,
                0.0,
                1.0,
                0.0,
                0.0,
                0.0,
                0.0,
                0.0,
                0.0,
                0.0,
                0.0,
                1.0,
                0.0,
                0.0,
                0.0,
                0.0,
                0.0,
                0.0,
                0.0,
                0.0,
                1.0,
                0.0,
                0.0,
                t45
                    * (-(1.5 * k_edge * t47 * t48 * t49)
                        + 1.5 * mu * k_edge * sin_theta * cos_theta * t17 * t21 * t22
                            * t47 - 1.5 * k_wall * t51 * t52),
                t45 * (t53 - 1.5 * mu * k_edge * t17 * t21 * t22 * t47 * t50),
                t45
                    * (t0 + t1 + t24 - mu * k_edge * cos_theta * t17 * t19 * t21 + t54
                        - mu * k_edge * sin_theta * t19 * t21 * t57
                        - 1.5 * mu * k_edge * sin_theta * t17 * t21 * t22 * t25 * t47
                        + mu * k_edge * sin_theta * t19 * t27 * t57 * t58 + t59),
                t45
                    * (-(mu * k_edge * t19 * t21 * t50)
                        + mu * k_edge * t19 * t27 * t50 * t58),
                t60,
                t45 * t61,
                0.0,
                0.0,
                t45
                    * (t53 + 1.5 * mu * k_edge * t17 * t21 * t22 * t47 * t48
                        - 1.5 * mu * k_wall * t37 * t41 * t42 * t51),
                t45
                    * (-(1.5 * k_edge * t47 * t49 * t50)
                        - 1.5 * mu * k_edge * sin_theta * cos_theta * t17 * t21 * t22
                            * t47),
                t45
                    * (t23 + mu * k_edge * sin_theta * t17 * t19 * t21 + t62 + t63 + t64
                        - mu * k_edge * cos_theta * t19 * t21 * t57
                        - 1.5 * mu * k_edge * cos_theta * t17 * t21 * t22 * t25 * t47
                        + mu * k_edge * cos_theta * t19 * t27 * t57 * t58
                        - thetadot * mu * k_wall * t39 * t41 * t66
                        - 1.5 * mu * k_wall * t37 * t41 * t42 * t43 * t51
                        + thetadot * mu * k_wall * t39 * t44 * t66 * t67),
                t60,
                t45
                    * (-(mu * k_edge * t19 * t21 * t48)
                        + mu * k_edge * t19 * t27 * t48 * t58 - mu * k_wall * t39 * t41
                        + mu * k_wall * t39 * t44 * t67),
                t45 * t68,
                0.0,
                0.0,
                t46
                    * (t24 + t54 + t59
                        + 1.5 * mu * k_edge * cos_theta * t17 * t21 * t22 * t26 * t47
                        - 1.5 * mu * k_wall * t36 * t37 * t41 * t42 * t51),
                t46
                    * (t23 + t64
                        - 1.5 * mu * k_edge * sin_theta * t17 * t21 * t22 * t26 * t47),
                t46
                    * (-(1.5 * k_edge * t47 * t49 * (t10 * t10))
                        - k_edge * (sin_theta * t5 - cos_theta * t4) * t19 * t22
                        - mu * k_edge * t19 * t21 * t26 * t57
                        - 1.5 * mu * k_edge * t17 * t21 * t22 * t25 * t26 * t47
                        + mu * k_edge * t19 * t26 * t27 * t57 * t58
                        - mu * k_edge * t17 * t19 * t21
                            * (cos_theta * t11 + sin_theta * t55 - sin_theta * t15
                                + cos_theta * t56) - 1.5 * k_wall * t51 * t52 * (t69 * t69)
                        - k_wall * t39 * t42 * (-(sin_theta * t29) - cos_theta * t30)
                        - mu * k_wall * t37 * t39 * t41 * t66
                        - thetadot * mu * k_wall * t36 * t39 * t41 * t66
                        - 1.5 * mu * k_wall * t36 * t37 * t41 * t42 * t43 * t51
                        + thetadot * mu * k_wall * t36 * t39 * t44 * t66 * t67),
                t46 * t61,
                t46 * t68,
                t46
                    * (-(mu * k_edge * t19 * t21 * t70)
                        + mu * k_edge * t19 * t27 * t58 * t70
                        - mu * k_wall * t39 * t41 * t72
                        + mu * k_wall * t39 * t44 * t67 * t72),
                0.0,
                0.0,
                0.0,
                0.0,
                xdot * t2 + zdot * (t62 + t63),
                f1 * sin_theta + f2 * cos_theta,
                t2,
                m_2,
                0.0,
                0.0,
                -(1.5 * mu * k_edge * cos_theta * t21 * t22 * t27 * t47)
                    + 1.5 * mu * k_wall * t41 * t42 * t44 * t51,
                1.5 * mu * k_edge * sin_theta * t21 * t22 * t27 * t47,
                1.5 * mu * k_edge * t21 * t22 * t25 * t27 * t47
                    - mu * k_edge * t19 * t57 * t58 * t73
                    + mu * k_edge * t19 * t21 * t57 * t74
                    + 1.5 * mu * k_wall * t41 * t42 * t43 * t44 * t51
                    - thetadot * mu * k_wall * t39 * t66 * t67 * t75
                    + thetadot * mu * k_wall * t39 * t41 * t66 * t76,
                -(mu * k_edge * sin_theta * t19 * t58 * t73)
                    + mu * k_edge * sin_theta * t19 * t21 * t74,
                -(mu * k_edge * cos_theta * t19 * t58 * t73)
                    + mu * k_edge * cos_theta * t19 * t21 * t74
                    - mu * k_wall * t39 * t67 * t75 + mu * k_wall * t39 * t41 * t76,
                -(mu * k_edge * t19 * t26 * t58 * t73)
                    + mu * k_edge * t19 * t21 * t26 * t74
                    - mu * k_wall * t36 * t39 * t67 * t75
                    + mu * k_wall * t36 * t39 * t41 * t76,
                0.0,
                0.0,
            ],
        )
    }
    /// Per contact (edge_left, wall_right): normal force f (N), friction force along the tangent (N), penetration delta (m), sliding velocity (m/s), contact ellipse a, b (m) and maximum pressure p0 (Pa) ((9)-(11)).
    ///
    /// # Inputs
    /// - `y` = (`x`, `z`, `theta`, `xdot`, `zdot`, `thetadot`, `work`, `dissipation`)
    /// - `p` = (`m`, `J`, `r`, `l_c`, `D`, `rho_p`, `rho_h`, `mu`, `v_s`, `k_edge`, `k_wall`, `f1`, `f2`, `M`, `e_star`, `edge_sum`, `edge_ma`, `edge_mb`, `edge_dstar`, `wall_sum`, `wall_ma`, `wall_mb`, `wall_dstar`)
    ///
    /// # Outputs
    /// - `normal`: vector of 2
    /// - `friction`: vector of 2
    /// - `delta`: vector of 2
    /// - `slip`: vector of 2
    /// - `a`: vector of 2
    /// - `b`: vector of 2
    /// - `p0`: vector of 2
    ///
    /// # Cost
    /// 23 add/sub, 55 mul, 7 div, 2 sqrt, 11 transcendental, 2 branches; 25 `let`s.
    #[inline]
    pub fn contacts(
        y: &SVector<f64, 8>,
        p: &SVector<f64, 23>,
    ) -> (
        SVector<f64, 2>,
        SVector<f64, 2>,
        SVector<f64, 2>,
        SVector<f64, 2>,
        SVector<f64, 2>,
        SVector<f64, 2>,
        SVector<f64, 2>,
    ) {
        let x = y[0];
        let z = y[1];
        let theta = y[2];
        let xdot = y[3];
        let zdot = y[4];
        let thetadot = y[5];
        let r = p[2];
        let l_c = p[3];
        let d = p[4];
        let rho_p = p[5];
        let rho_h = p[6];
        let mu = p[7];
        let v_s = p[8];
        let k_edge = p[9];
        let k_wall = p[10];
        let e_star = p[14];
        let edge_sum = p[15];
        let edge_ma = p[16];
        let edge_mb = p[17];
        let wall_sum = p[19];
        let wall_ma = p[20];
        let wall_mb = p[21];
        let sin_theta = theta.sin();
        let cos_theta = theta.cos();
        let t0 = -0.5 * d;
        let t1 = -rho_h + t0 - x;
        let t2 = rho_h - z;
        let t3 = r + rho_h + cos_theta * t1 - sin_theta * t2;
        let t4 = sin_theta * t1 + cos_theta * t2;
        let t5 = sin_theta * (xdot + thetadot * (cos_theta * t4 + r * sin_theta))
            + cos_theta * (zdot + thetadot * (-(sin_theta * t4) + r * cos_theta));
        let t6 = if t3 > 0.0 || t3.is_nan() { t3 } else { 0.0 };
        let t7 = t6 * t6.sqrt();
        let t8 = v_s.hypot(t5);
        let t9 = 1.0 / e_star;
        let t10 = (1.5 * k_edge * t7 * t9 / edge_sum).powf(0.3333333333333333);
        let t11 = (1.5 * k_edge * t7).powf(0.3333333333333333);
        let t12 = (e_star * edge_sum).powf(0.6666666666666666);
        let t13 = -rho_p;
        let t14 = x + rho_p + t0 + sin_theta * (l_c + t13) + cos_theta * (r + t13);
        let t15 = (0.5 * theta).sin();
        let t16 = zdot
            + thetadot
                * (-(sin_theta * (l_c + t13 + rho_p * sin_theta))
                    - cos_theta * (r - 2.0 * rho_p * (t15 * t15)));
        let t17 = if t14 > 0.0 || t14.is_nan() { t14 } else { 0.0 };
        let t18 = t17 * t17.sqrt();
        let t19 = v_s.hypot(t16);
        let t20 = (1.5 * k_wall * t9 * t18 / wall_sum).powf(0.3333333333333333);
        let t21 = (1.5 * k_wall * t18).powf(0.3333333333333333);
        let t22 = (e_star * wall_sum).powf(0.6666666666666666);
        let normal = Vector2::new(k_edge * t7, k_wall * t18);
        let friction = Vector2::new(
            -mu * k_edge * t5 * t7 / t8,
            -mu * k_wall * t16 * t18 / t19,
        );
        let delta = Vector2::new(t3, t14);
        let slip = Vector2::new(t5, t16);
        let a = Vector2::new(edge_ma * t10, wall_ma * t20);
        let b = Vector2::new(edge_mb * t10, wall_mb * t20);
        let p0 = Vector2::new(
            0.3183098861837907 * t11 * t12 / (edge_ma * edge_mb),
            0.3183098861837907 * t21 * t22 / (wall_ma * wall_mb),
        );
        (normal, friction, delta, slip, a, b, p0)
    }
    /// Kinetic energy (59) (J), contact potential (63) (J) and insertion depth of the bottom face (m).
    ///
    /// # Inputs
    /// - `y` = (`x`, `z`, `theta`, `xdot`, `zdot`, `thetadot`, `work`, `dissipation`)
    /// - `p` = (`m`, `J`, `r`, `l_c`, `D`, `rho_p`, `rho_h`, `mu`, `v_s`, `k_edge`, `k_wall`, `f1`, `f2`, `M`, `e_star`, `edge_sum`, `edge_ma`, `edge_mb`, `edge_dstar`, `wall_sum`, `wall_ma`, `wall_mb`, `wall_dstar`)
    ///
    /// # Outputs
    /// - `kinetic`: scalar
    /// - `potential`: scalar
    /// - `depth`: scalar
    ///
    /// # Cost
    /// 16 add/sub, 17 mul, 0 div, 0 sqrt, 4 transcendental, 2 branches; 10 `let`s.
    #[inline]
    pub fn energy(y: &SVector<f64, 8>, p: &SVector<f64, 23>) -> (f64, f64, f64) {
        let x = y[0];
        let z = y[1];
        let theta = y[2];
        let xdot = y[3];
        let zdot = y[4];
        let thetadot = y[5];
        let m = p[0];
        let j = p[1];
        let r = p[2];
        let l_c = p[3];
        let d = p[4];
        let rho_p = p[5];
        let rho_h = p[6];
        let k_edge = p[9];
        let k_wall = p[10];
        let sin_theta = theta.sin();
        let cos_theta = theta.cos();
        let t0 = -0.5 * d;
        let t1 = r + rho_h + cos_theta * (-rho_h + t0 - x) - sin_theta * (rho_h - z);
        let t2 = if t1 > 0.0 || t1.is_nan() { t1 } else { 0.0 };
        let t3 = t2.powf(2.5);
        let t4 = -rho_p;
        let t5 = x + rho_p + t0 + sin_theta * (l_c + t4) + cos_theta * (r + t4);
        let t6 = if t5 > 0.0 || t5.is_nan() { t5 } else { 0.0 };
        let t7 = t6.powf(2.5);
        let kinetic = 0.5 * m * (xdot * xdot + zdot * zdot)
            + 0.5 * j * (thetadot * thetadot);
        let potential = 0.4 * k_edge * t3 + 0.4 * k_wall * t7;
        let depth = z + l_c * cos_theta;
        (kinetic, potential, depth)
    }
}
