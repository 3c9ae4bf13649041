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
    pub const P_NAMES: [&str; 24] = [
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
        "hc_alpha",
    ];
    /// Right-hand side of y = (x, z, theta, xdot, zdot, thetadot, work, dissipation): M qdd = applied (50) + contact normal forces (-grad of the Hertz potential (62)) + Coulomb friction; work and dissipation rates. SI units.
    ///
    /// # Inputs
    /// - `y` = (`x`, `z`, `theta`, `xdot`, `zdot`, `thetadot`, `work`, `dissipation`)
    /// - `p` = (`m`, `J`, `r`, `l_c`, `D`, `rho_p`, `rho_h`, `mu`, `v_s`, `k_edge`, `k_wall`, `f1`, `f2`, `M`, `e_star`, `edge_sum`, `edge_ma`, `edge_mb`, `edge_dstar`, `wall_sum`, `wall_ma`, `wall_mb`, `wall_dstar`, `hc_alpha`)
    ///
    /// # Outputs
    /// - `ydot`: vector of 8
    ///
    /// # Cost
    /// 58 add/sub, 116 mul, 4 div, 2 sqrt, 5 transcendental, 8 branches; 42 `let`s.
    #[inline]
    pub fn rhs(y: &SVector<f64, 8>, p: &SVector<f64, 24>) -> SVector<f64, 8> {
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
        let hc_alpha = p[23];
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
        let t14 = -(sin_theta * t5) - cos_theta * t6;
        let t15 = -(xdot * cos_theta) + zdot * sin_theta + thetadot * t14;
        let t16 = 1.0 + hc_alpha * t15;
        let t17 = if t16 > 0.0 || t16.is_nan() { t16 } else { 0.0 };
        let t18 = k_edge * t13 * t17 - k_edge * t13;
        let t19 = v_s.hypot(t11);
        let t20 = 1.0 / t19;
        let t21 = if t7 > 0.0 { 1.0 } else if t7.is_nan() { t7 } else { 0.0 };
        let t22 = -rho_p;
        let t23 = l_c + t22;
        let t24 = r + t22;
        let t25 = x + rho_p + t4 + sin_theta * t23 + cos_theta * t24;
        let t26 = (0.5 * theta).sin();
        let t27 = -(sin_theta * (l_c + t22 + rho_p * sin_theta))
            - cos_theta * (r - 2.0 * rho_p * (t26 * t26));
        let t28 = zdot + thetadot * t27;
        let t29 = if t25 > 0.0 || t25.is_nan() { t25 } else { 0.0 };
        let t30 = t29 * t29.sqrt();
        let t31 = cos_theta * t23 - sin_theta * t24;
        let t32 = xdot + thetadot * t31;
        let t33 = 1.0 + hc_alpha * t32;
        let t34 = if t33 > 0.0 || t33.is_nan() { t33 } else { 0.0 };
        let t35 = k_wall * t30 * t34 - k_wall * t30;
        let t36 = v_s.hypot(t28);
        let t37 = 1.0 / t36;
        let t38 = if t25 > 0.0 { 1.0 } else if t25.is_nan() { t25 } else { 0.0 };
        let t39 = 1.0 / m;
        SMatrix::<
            f64,
            8,
            1,
        >::from_row_slice(
            &[
                xdot,
                zdot,
                thetadot,
                (t0 + t1 + k_edge * cos_theta * t13 * t21 + cos_theta * t18
                    - mu * k_edge * sin_theta * t11 * t13 * t17 * t20 + k_wall * t30
                    - k_wall * t30 * t38 - k_wall * t30 * t34) * t39,
                (t2 + t3 - k_edge * sin_theta * t13 * t21 - sin_theta * t18
                    - mu * k_edge * cos_theta * t11 * t13 * t17 * t20
                    - mu * k_wall * t28 * t30 * t34 * t37) * t39,
                (m_2 - k_edge * t13 * t14 * t21 - t14 * t18
                    - mu * k_edge * t11 * t13 * t17 * t20
                        * (sin_theta * t9 + cos_theta * t10) - k_wall * t30 * t31 * t38
                    - t31 * t35 - mu * k_wall * t27 * t28 * t30 * t34 * t37) / j,
                xdot * (t0 + t1) + zdot * (t2 + t3) + thetadot * m_2,
                mu * k_edge * t13 * t17 * t20 * (t11 * t11) + t15 * t18
                    + mu * k_wall * t30 * t34 * t37 * (t28 * t28) + t32 * t35,
            ],
        )
    }
    /// Exact Jacobian d(rhs)/dy, row-major 8x8.
    ///
    /// # Inputs
    /// - `y` = (`x`, `z`, `theta`, `xdot`, `zdot`, `thetadot`, `work`, `dissipation`)
    /// - `p` = (`m`, `J`, `r`, `l_c`, `D`, `rho_p`, `rho_h`, `mu`, `v_s`, `k_edge`, `k_wall`, `f1`, `f2`, `M`, `e_star`, `edge_sum`, `edge_ma`, `edge_mb`, `edge_dstar`, `wall_sum`, `wall_ma`, `wall_mb`, `wall_dstar`, `hc_alpha`)
    ///
    /// # Outputs
    /// - `jac`: 8×8 matrix
    ///
    /// # Cost
    /// 227 add/sub, 1027 mul, 6 div, 4 sqrt, 6 transcendental, 12 branches; 113 `let`s.
    #[inline]
    pub fn jacobian(y: &SVector<f64, 8>, p: &SVector<f64, 24>) -> SMatrix<f64, 8, 8> {
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
        let hc_alpha = p[23];
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
        let t9 = sin_theta * t5 - cos_theta * t4;
        let t10 = r + rho_h + t6 + t7;
        let t11 = sin_theta * t4 + cos_theta * t5;
        let t12 = cos_theta * t11 + r * sin_theta;
        let t13 = xdot + thetadot * t12;
        let t14 = -sin_theta * t11;
        let t15 = r * cos_theta;
        let t16 = t14 + t15;
        let t17 = zdot + thetadot * t16;
        let t18 = sin_theta * t13 + cos_theta * t17;
        let t19 = if t10 > 0.0 || t10.is_nan() { t10 } else { 0.0 };
        let t20 = t19 * t19.sqrt();
        let t21 = -(sin_theta * t4) - cos_theta * t5;
        let t22 = -(xdot * cos_theta) + zdot * sin_theta + thetadot * t21;
        let t23 = 1.0 + hc_alpha * t22;
        let t24 = if t23 > 0.0 || t23.is_nan() { t23 } else { 0.0 };
        let t25 = k_edge * t20 * t24 - k_edge * t20;
        let t26 = v_s.hypot(t18);
        let t27 = 1.0 / t26;
        let t28 = if t10 > 0.0 { 1.0 } else if t10.is_nan() { t10 } else { 0.0 };
        let t29 = -k_edge * cos_theta * t20 * t28;
        let t30 = -cos_theta * t25;
        let t31 = -k_edge * sin_theta * t20 * t28;
        let t32 = -sin_theta * t25;
        let t33 = sin_theta * t12 + cos_theta * t16;
        let t34 = t18 * t18;
        let t35 = -rho_p;
        let t36 = l_c + t35;
        let t37 = r + t35;
        let t38 = x + rho_p + t3 + sin_theta * t36 + cos_theta * t37;
        let t39 = l_c + t35 + rho_p * sin_theta;
        let t40 = 0.5 * theta;
        let t41 = t40.sin();
        let t42 = r - 2.0 * rho_p * (t41 * t41);
        let t43 = -(sin_theta * t39) - cos_theta * t42;
        let t44 = zdot + thetadot * t43;
        let t45 = if t38 > 0.0 || t38.is_nan() { t38 } else { 0.0 };
        let t46 = t45 * t45.sqrt();
        let t47 = cos_theta * t36 - sin_theta * t37;
        let t48 = xdot + thetadot * t47;
        let t49 = 1.0 + hc_alpha * t48;
        let t50 = if t49 > 0.0 || t49.is_nan() { t49 } else { 0.0 };
        let t51 = k_wall * t46 * t50;
        let t52 = -k_wall * t46;
        let t53 = t51 + t52;
        let t54 = v_s.hypot(t44);
        let t55 = 1.0 / t54;
        let t56 = if t38 > 0.0 { 1.0 } else if t38.is_nan() { t38 } else { 0.0 };
        let t57 = t44 * t44;
        let t58 = 1.0 / m;
        let t59 = 1.0 / j;
        let t60 = t19.sqrt();
        let t61 = cos_theta * cos_theta;
        let t62 = t28 * t28;
        let t63 = if t23 > 0.0 { 1.0 } else if t23.is_nan() { t23 } else { 0.0 };
        let t64 = -(1.5 * k_edge * cos_theta * t24 * t28 * t60)
            + thetadot * k_edge * hc_alpha * sin_theta * t20 * t63
            + 1.5 * k_edge * cos_theta * t28 * t60;
        let t65 = sin_theta * sin_theta;
        let t66 = t45.sqrt();
        let t67 = t56 * t56;
        let t68 = 1.5 * k_edge * sin_theta * cos_theta * t60 * t62;
        let t69 = 1.5 * k_edge * sin_theta * t24 * t28 * t60
            + thetadot * k_edge * hc_alpha * cos_theta * t20 * t63
            - 1.5 * k_edge * sin_theta * t28 * t60;
        let t70 = -thetadot * mu * k_edge * hc_alpha * sin_theta * cos_theta * t18 * t20
            * t27 * t63;
        let t71 = 1.5 * k_edge * cos_theta * t21 * t60 * t62;
        let t72 = xdot * sin_theta + zdot * cos_theta + thetadot * t9;
        let t73 = 1.5 * k_edge * t21 * t24 * t28 * t60
            + k_edge * hc_alpha * t20 * t63 * t72 - 1.5 * k_edge * t21 * t28 * t60;
        let t74 = t14 + t15 + cos_theta * t8;
        let t75 = -(r * sin_theta) - cos_theta * t11 - sin_theta * t8;
        let t76 = cos_theta * t13 + thetadot * sin_theta * t74 - sin_theta * t17
            + thetadot * cos_theta * t75;
        let t77 = 1.0 / (t26 * t26 * t26);
        let t78 = -1.5 * k_wall * t47 * t66 * t67;
        let t79 = -(sin_theta * t36) - cos_theta * t37;
        let t80 = if t49 > 0.0 { 1.0 } else if t49.is_nan() { t49 } else { 0.0 };
        let t81 = k_edge * hc_alpha * sin_theta * cos_theta * t20 * t63;
        let t82 = -mu * k_edge * sin_theta * cos_theta * t20 * t24 * t27;
        let t83 = mu * k_edge * sin_theta * cos_theta * t20 * t24 * t34 * t77;
        let t84 = k_edge * hc_alpha * cos_theta * t20 * t21 * t63;
        let t85 = -mu * k_edge * sin_theta * t20 * t24 * t27 * t33;
        let t86 = mu * k_edge * sin_theta * t20 * t24 * t33 * t34 * t77;
        let t87 = -k_wall * hc_alpha * t46 * t47 * t80;
        let t88 = -f1 * sin_theta;
        let t89 = -f2 * cos_theta;
        let t90 = -1.5 * k_edge * sin_theta * t21 * t60 * t62;
        let t91 = t40.cos();
        let t92 = sin_theta * t42 - cos_theta * t39 - rho_p * sin_theta * cos_theta
            + 2.0 * rho_p * cos_theta * t41 * t91;
        let t93 = 1.0 / (t54 * t54 * t54);
        let t94 = -k_edge * hc_alpha * sin_theta * t20 * t21 * t63;
        let t95 = -mu * k_edge * cos_theta * t20 * t24 * t27 * t33;
        let t96 = mu * k_edge * cos_theta * t20 * t24 * t33 * t34 * t77;
        let t97 = -mu * k_wall * t43 * t46 * t50 * t55;
        let t98 = mu * k_wall * t43 * t46 * t50 * t57 * t93;
        let t99 = 1.5 * k_wall * t50 * t56 * t66 - 1.5 * k_wall * t56 * t66;
        let t100 = t11 * t11;
        let t101 = sin_theta * t37 - cos_theta * t36;
        let t102 = t101 * t101;
        let t103 = thetadot * k_wall * hc_alpha * t46 * t79 * t80
            + 1.5 * k_wall * t47 * t50 * t56 * t66 - 1.5 * k_wall * t47 * t56 * t66;
        let t104 = t33 * t33;
        let t105 = cos_theta * t42 + sin_theta * t39;
        let t106 = t105 * t105;
        let t107 = t18 * t18 * t18;
        let t108 = 2.0 * sin_theta * t13 + 2.0 * cos_theta * t17;
        let t109 = t44 * t44 * t44;
        let t110 = 2.0 * zdot + 2.0 * thetadot * t43;
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
                t58
                    * (-(1.5 * k_edge * t60 * t61 * t62) + cos_theta * t64
                        + 1.5 * mu * k_edge * sin_theta * cos_theta * t18 * t24 * t27
                            * t28 * t60
                        - thetadot * mu * k_edge * hc_alpha * t18 * t20 * t27 * t63 * t65
                        + 1.5 * k_wall * t56 * t66 - 1.5 * k_wall * t66 * t67
                        - 1.5 * k_wall * t50 * t56 * t66),
                t58
                    * (t68 + cos_theta * t69
                        - 1.5 * mu * k_edge * t18 * t24 * t27 * t28 * t60 * t65 + t70),
                t58
                    * (t0 + t1 + t31 + t32
                        - mu * k_edge * cos_theta * t18 * t20 * t24 * t27 + t71
                        + cos_theta * t73
                        - mu * k_edge * sin_theta * t20 * t24 * t27 * t76
                        - 1.5 * mu * k_edge * sin_theta * t18 * t21 * t24 * t27 * t28
                            * t60
                        - mu * k_edge * hc_alpha * sin_theta * t18 * t20 * t27 * t63
                            * t72 + mu * k_edge * sin_theta * t20 * t24 * t34 * t76 * t77
                        + 1.5 * k_wall * t47 * t56 * t66 + t78
                        - 1.5 * k_wall * t47 * t50 * t56 * t66
                        - thetadot * k_wall * hc_alpha * t46 * t79 * t80),
                t58
                    * (-(k_edge * hc_alpha * t20 * t61 * t63)
                        - mu * k_edge * t20 * t24 * t27 * t65
                        + mu * k_edge * hc_alpha * sin_theta * cos_theta * t18 * t20
                            * t27 * t63 + mu * k_edge * t20 * t24 * t34 * t65 * t77
                        - k_wall * hc_alpha * t46 * t80),
                t58
                    * (t81 + t82 - mu * k_edge * hc_alpha * t18 * t20 * t27 * t63 * t65
                        + t83),
                t58
                    * (t84 + t85
                        - mu * k_edge * hc_alpha * sin_theta * t18 * t20 * t21 * t27
                            * t63 + t86 + t87),
                0.0,
                0.0,
                t58
                    * (t68 + t70 - sin_theta * t64
                        + 1.5 * mu * k_edge * t18 * t24 * t27 * t28 * t60 * t61
                        - 1.5 * mu * k_wall * t44 * t50 * t55 * t56 * t66),
                t58
                    * (-(1.5 * k_edge * t60 * t62 * t65) - sin_theta * t69
                        - 1.5 * mu * k_edge * sin_theta * cos_theta * t18 * t24 * t27
                            * t28 * t60
                        - thetadot * mu * k_edge * hc_alpha * t18 * t20 * t27 * t61
                            * t63),
                t58
                    * (t29 + t30 + mu * k_edge * sin_theta * t18 * t20 * t24 * t27 + t88
                        + t89 + t90 - sin_theta * t73
                        - mu * k_edge * cos_theta * t20 * t24 * t27 * t76
                        - 1.5 * mu * k_edge * cos_theta * t18 * t21 * t24 * t27 * t28
                            * t60
                        - mu * k_edge * hc_alpha * cos_theta * t18 * t20 * t27 * t63
                            * t72 + mu * k_edge * cos_theta * t20 * t24 * t34 * t76 * t77
                        - thetadot * mu * k_wall * t46 * t50 * t55 * t92
                        - 1.5 * mu * k_wall * t44 * t47 * t50 * t55 * t56 * t66
                        - thetadot * mu * k_wall * hc_alpha * t44 * t46 * t55 * t79 * t80
                        + thetadot * mu * k_wall * t46 * t50 * t57 * t92 * t93),
                t58
                    * (t81 + t82 + t83
                        + mu * k_edge * hc_alpha * t18 * t20 * t27 * t61 * t63
                        - mu * k_wall * hc_alpha * t44 * t46 * t55 * t80),
                t58
                    * (-(k_edge * hc_alpha * t20 * t63 * t65)
                        - mu * k_edge * t20 * t24 * t27 * t61
                        - mu * k_edge * hc_alpha * sin_theta * cos_theta * t18 * t20
                            * t27 * t63 + mu * k_edge * t20 * t24 * t34 * t61 * t77
                        - mu * k_wall * t46 * t50 * t55
                        + mu * k_wall * t46 * t50 * t57 * t93),
                t58
                    * (t94 + t95
                        - mu * k_edge * hc_alpha * cos_theta * t18 * t20 * t21 * t27
                            * t63 + t96 + t97
                        - mu * k_wall * hc_alpha * t44 * t46 * t47 * t55 * t80 + t98),
                0.0,
                0.0,
                t59
                    * (t31 + t32 + t71 + t78 - t21 * t64
                        + 1.5 * mu * k_edge * cos_theta * t18 * t24 * t27 * t28 * t33
                            * t60
                        - thetadot * mu * k_edge * hc_alpha * sin_theta * t18 * t20 * t27
                            * t33 * t63 - t47 * t99
                        - 1.5 * mu * k_wall * t43 * t44 * t50 * t55 * t56 * t66),
                t59
                    * (t29 + t30 + t90 - t21 * t69
                        - 1.5 * mu * k_edge * sin_theta * t18 * t24 * t27 * t28 * t33
                            * t60
                        - thetadot * mu * k_edge * hc_alpha * cos_theta * t18 * t20 * t27
                            * t33 * t63),
                t59
                    * (-(1.5 * k_edge * t60 * t62 * t100) - k_edge * t9 * t20 * t28
                        - t9 * t25 - t21 * t73
                        - mu * k_edge * t20 * t24 * t27 * t33 * t76
                        - 1.5 * mu * k_edge * t18 * t21 * t24 * t27 * t28 * t33 * t60
                        - mu * k_edge * hc_alpha * t18 * t20 * t27 * t33 * t63 * t72
                        + mu * k_edge * t20 * t24 * t33 * t34 * t76 * t77
                        - mu * k_edge * t18 * t20 * t24 * t27
                            * (cos_theta * t12 + sin_theta * t74 - sin_theta * t16
                                + cos_theta * t75) - 1.5 * k_wall * t66 * t67 * t102
                        - k_wall * t46 * t56 * t79 - t53 * t79 - t47 * t103
                        - mu * k_wall * t44 * t46 * t50 * t55 * t92
                        - thetadot * mu * k_wall * t43 * t46 * t50 * t55 * t92
                        - 1.5 * mu * k_wall * t43 * t44 * t47 * t50 * t55 * t56 * t66
                        - thetadot * mu * k_wall * hc_alpha * t43 * t44 * t46 * t55 * t79
                            * t80
                        + thetadot * mu * k_wall * t43 * t46 * t50 * t57 * t92 * t93),
                t59
                    * (t84 + t85 + t86 + t87
                        + mu * k_edge * hc_alpha * cos_theta * t18 * t20 * t27 * t33
                            * t63
                        - mu * k_wall * hc_alpha * t43 * t44 * t46 * t55 * t80),
                t59
                    * (t94 + t95 + t96 + t97 + t98
                        - mu * k_edge * hc_alpha * sin_theta * t18 * t20 * t27 * t33
                            * t63),
                t59
                    * (-(k_edge * hc_alpha * t20 * t63 * t100)
                        - mu * k_edge * t20 * t24 * t27 * t104
                        - mu * k_edge * hc_alpha * t18 * t20 * t21 * t27 * t33 * t63
                        + mu * k_edge * t20 * t24 * t34 * t77 * t104
                        - k_wall * hc_alpha * t46 * t80 * t102
                        - mu * k_wall * t46 * t50 * t55 * t106
                        - mu * k_wall * hc_alpha * t43 * t44 * t46 * t47 * t55 * t80
                        + mu * k_wall * t46 * t50 * t57 * t93 * t106),
                0.0,
                0.0,
                0.0,
                0.0,
                xdot * t2 + zdot * (t88 + t89),
                f1 * sin_theta + f2 * cos_theta,
                t2,
                m_2,
                0.0,
                0.0,
                -(1.5 * mu * k_edge * cos_theta * t24 * t27 * t28 * t34 * t60)
                    + thetadot * mu * k_edge * hc_alpha * sin_theta * t20 * t27 * t34
                        * t63 + thetadot * sin_theta * t25 + t22 * t64
                    + 1.5 * mu * k_wall * t50 * t55 * t56 * t57 * t66 + t48 * t99,
                1.5 * mu * k_edge * sin_theta * t24 * t27 * t28 * t34 * t60
                    + thetadot * mu * k_edge * hc_alpha * cos_theta * t20 * t27 * t34
                        * t63 + thetadot * cos_theta * t25 + t22 * t69,
                1.5 * mu * k_edge * t21 * t24 * t27 * t28 * t34 * t60
                    + mu * k_edge * hc_alpha * t20 * t27 * t34 * t63 * t72
                    - mu * k_edge * t20 * t24 * t76 * t77 * t107
                    + mu * k_edge * t20 * t24 * t27 * t76 * t108 + t25 * t72 + t22 * t73
                    + 1.5 * mu * k_wall * t47 * t50 * t55 * t56 * t57 * t66
                    + thetadot * mu * k_wall * hc_alpha * t46 * t55 * t57 * t79 * t80
                    - thetadot * mu * k_wall * t46 * t50 * t92 * t93 * t109
                    + thetadot * mu * k_wall * t46 * t50 * t55 * t92 * t110
                    + thetadot * t53 * t79 + t48 * t103,
                t30 + t51 + t52
                    - mu * k_edge * hc_alpha * cos_theta * t20 * t27 * t34 * t63
                    - mu * k_edge * sin_theta * t20 * t24 * t77 * t107
                    + mu * k_edge * sin_theta * t20 * t24 * t27 * t108
                    - k_edge * hc_alpha * cos_theta * t20 * t22 * t63
                    + mu * k_wall * hc_alpha * t46 * t55 * t57 * t80
                    + k_wall * hc_alpha * t46 * t48 * t80,
                sin_theta * t25
                    + mu * k_edge * hc_alpha * sin_theta * t20 * t27 * t34 * t63
                    - mu * k_edge * cos_theta * t20 * t24 * t77 * t107
                    + mu * k_edge * cos_theta * t20 * t24 * t27 * t108
                    + k_edge * hc_alpha * sin_theta * t20 * t22 * t63
                    - mu * k_wall * t46 * t50 * t93 * t109
                    + mu * k_wall * t46 * t50 * t55 * t110,
                t21 * t25 + t47 * t53
                    + mu * k_edge * hc_alpha * t20 * t21 * t27 * t34 * t63
                    - mu * k_edge * t20 * t24 * t33 * t77 * t107
                    + mu * k_edge * t20 * t24 * t27 * t33 * t108
                    + k_edge * hc_alpha * t20 * t21 * t22 * t63
                    + mu * k_wall * hc_alpha * t46 * t47 * t55 * t57 * t80
                    - mu * k_wall * t43 * t46 * t50 * t93 * t109
                    + mu * k_wall * t43 * t46 * t50 * t55 * t110
                    + k_wall * hc_alpha * t46 * t47 * t48 * t80,
                0.0,
                0.0,
            ],
        )
    }
    /// Per contact (edge_left, wall_right): normal force f (N), friction force along the tangent (N), penetration delta (m), sliding velocity (m/s), contact ellipse a, b (m) and maximum pressure p0 (Pa) ((9)-(11)).
    ///
    /// # Inputs
    /// - `y` = (`x`, `z`, `theta`, `xdot`, `zdot`, `thetadot`, `work`, `dissipation`)
    /// - `p` = (`m`, `J`, `r`, `l_c`, `D`, `rho_p`, `rho_h`, `mu`, `v_s`, `k_edge`, `k_wall`, `f1`, `f2`, `M`, `e_star`, `edge_sum`, `edge_ma`, `edge_mb`, `edge_dstar`, `wall_sum`, `wall_ma`, `wall_mb`, `wall_dstar`, `hc_alpha`)
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
    /// 30 add/sub, 73 mul, 7 div, 2 sqrt, 11 transcendental, 4 branches; 31 `let`s.
    #[inline]
    pub fn contacts(
        y: &SVector<f64, 8>,
        p: &SVector<f64, 24>,
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
        let hc_alpha = p[23];
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
        let t8 = 1.0
            + hc_alpha
                * (-(xdot * cos_theta) + zdot * sin_theta
                    + thetadot * (-(sin_theta * t1) - cos_theta * t2));
        let t9 = if t8 > 0.0 || t8.is_nan() { t8 } else { 0.0 };
        let t10 = v_s.hypot(t5);
        let t11 = 1.0 / e_star;
        let t12 = (1.5 * k_edge * t7 * t9 * t11 / edge_sum).powf(0.3333333333333333);
        let t13 = (1.5 * k_edge * t7 * t9).powf(0.3333333333333333);
        let t14 = (e_star * edge_sum).powf(0.6666666666666666);
        let t15 = -rho_p;
        let t16 = l_c + t15;
        let t17 = r + t15;
        let t18 = x + rho_p + t0 + sin_theta * t16 + cos_theta * t17;
        let t19 = (0.5 * theta).sin();
        let t20 = zdot
            + thetadot
                * (-(sin_theta * (l_c + t15 + rho_p * sin_theta))
                    - cos_theta * (r - 2.0 * rho_p * (t19 * t19)));
        let t21 = if t18 > 0.0 || t18.is_nan() { t18 } else { 0.0 };
        let t22 = t21 * t21.sqrt();
        let t23 = 1.0
            + hc_alpha * (xdot + thetadot * (cos_theta * t16 - sin_theta * t17));
        let t24 = if t23 > 0.0 || t23.is_nan() { t23 } else { 0.0 };
        let t25 = v_s.hypot(t20);
        let t26 = (1.5 * k_wall * t11 * t22 * t24 / wall_sum).powf(0.3333333333333333);
        let t27 = (1.5 * k_wall * t22 * t24).powf(0.3333333333333333);
        let t28 = (e_star * wall_sum).powf(0.6666666666666666);
        let normal = Vector2::new(k_edge * t7 * t9, k_wall * t22 * t24);
        let friction = Vector2::new(
            -mu * k_edge * t5 * t7 * t9 / t10,
            -mu * k_wall * t20 * t22 * t24 / t25,
        );
        let delta = Vector2::new(t3, t18);
        let slip = Vector2::new(t5, t20);
        let a = Vector2::new(edge_ma * t12, wall_ma * t26);
        let b = Vector2::new(edge_mb * t12, wall_mb * t26);
        let p0 = Vector2::new(
            0.3183098861837907 * t13 * t14 / (edge_ma * edge_mb),
            0.3183098861837907 * t27 * t28 / (wall_ma * wall_mb),
        );
        (normal, friction, delta, slip, a, b, p0)
    }
    /// Kinetic energy (59) (J), contact potential (63) (J) and insertion depth of the bottom face (m).
    ///
    /// # Inputs
    /// - `y` = (`x`, `z`, `theta`, `xdot`, `zdot`, `thetadot`, `work`, `dissipation`)
    /// - `p` = (`m`, `J`, `r`, `l_c`, `D`, `rho_p`, `rho_h`, `mu`, `v_s`, `k_edge`, `k_wall`, `f1`, `f2`, `M`, `e_star`, `edge_sum`, `edge_ma`, `edge_mb`, `edge_dstar`, `wall_sum`, `wall_ma`, `wall_mb`, `wall_dstar`, `hc_alpha`)
    ///
    /// # Outputs
    /// - `kinetic`: scalar
    /// - `potential`: scalar
    /// - `depth`: scalar
    ///
    /// # Cost
    /// 16 add/sub, 17 mul, 0 div, 0 sqrt, 4 transcendental, 2 branches; 10 `let`s.
    #[inline]
    pub fn energy(y: &SVector<f64, 8>, p: &SVector<f64, 24>) -> (f64, f64, f64) {
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
