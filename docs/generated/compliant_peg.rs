// @generated readable copy of `pegdyn::generated::compliant_peg` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generated_snapshot

/// Planar compliant peg-in-hole (paper 001, (31)-(51), (55)-(64)) with contacts edge_left, wall_right, edge_right, wall_left. Inputs: state y (see STATE) and parameters p (see P_NAMES). SI units.
pub mod compliant_peg {
    use nalgebra::{SMatrix, SVector, Vector4};
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
    /// 78 add/sub, 162 mul, 6 div, 4 sqrt, 7 transcendental, 12 branches; 56 `let`s.
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
        let t5 = -x;
        let t6 = -rho_h + t4 + t5;
        let t7 = rho_h - z;
        let t8 = r + rho_h + cos_theta * t6 - sin_theta * t7;
        let t9 = cos_theta * t7;
        let t10 = sin_theta * t6 + t9;
        let t11 = -r;
        let t12 = cos_theta * t10 + r * sin_theta;
        let t13 = -(sin_theta * t10) + r * cos_theta;
        let t14 = sin_theta * (xdot + thetadot * t12)
            + cos_theta * (zdot + thetadot * t13);
        let t15 = if t8 > 0.0 || t8.is_nan() { t8 } else { 0.0 };
        let t16 = t15 * t15.sqrt();
        let t17 = v_s.hypot(t14);
        let t18 = 1.0 / t17;
        let t19 = if t8 > 0.0 { 1.0 } else if t8.is_nan() { t8 } else { 0.0 };
        let t20 = -rho_p;
        let t21 = l_c + t20;
        let t22 = r + t20;
        let t23 = x + rho_p + t4 + sin_theta * t21 + cos_theta * t22;
        let t24 = (0.5 * theta).sin();
        let t25 = t24 * t24;
        let t26 = -(sin_theta * (l_c + t20 + rho_p * sin_theta))
            - cos_theta * (r - 2.0 * rho_p * t25);
        let t27 = zdot + thetadot * t26;
        let t28 = if t23 > 0.0 || t23.is_nan() { t23 } else { 0.0 };
        let t29 = t28 * t28.sqrt();
        let t30 = v_s.hypot(t27);
        let t31 = 1.0 / t30;
        let t32 = if t23 > 0.0 { 1.0 } else if t23.is_nan() { t23 } else { 0.0 };
        let t33 = rho_h + 0.5 * d + t5;
        let t34 = r + rho_h + sin_theta * t7 - cos_theta * t33;
        let t35 = t9 + sin_theta * t33;
        let t36 = -(r * sin_theta) + cos_theta * t35;
        let t37 = -(r * cos_theta) - sin_theta * t35;
        let t38 = sin_theta * (xdot + thetadot * t36)
            + cos_theta * (zdot + thetadot * t37);
        let t39 = if t34 > 0.0 || t34.is_nan() { t34 } else { 0.0 };
        let t40 = t39 * t39.sqrt();
        let t41 = v_s.hypot(t38);
        let t42 = 1.0 / t41;
        let t43 = if t34 > 0.0 { 1.0 } else if t34.is_nan() { t34 } else { 0.0 };
        let t44 = rho_p + t11;
        let t45 = rho_p + t4 + t5 - sin_theta * t21 - cos_theta * t44;
        let t46 = -(sin_theta * (l_c + t20 - rho_p * sin_theta))
            - cos_theta * (t11 + 2.0 * rho_p * t25);
        let t47 = zdot + thetadot * t46;
        let t48 = if t45 > 0.0 || t45.is_nan() { t45 } else { 0.0 };
        let t49 = t48 * t48.sqrt();
        let t50 = v_s.hypot(t47);
        let t51 = 1.0 / t50;
        let t52 = if t45 > 0.0 { 1.0 } else if t45.is_nan() { t45 } else { 0.0 };
        let t53 = 1.0 / m;
        SMatrix::<
            f64,
            8,
            1,
        >::from_row_slice(
            &[
                xdot,
                zdot,
                thetadot,
                (t0 + t1 + k_edge * cos_theta * t16 * t19
                    - mu * k_edge * sin_theta * t14 * t16 * t18 - k_wall * t29 * t32
                    - k_edge * cos_theta * t40 * t43
                    - mu * k_edge * sin_theta * t38 * t40 * t42 + k_wall * t49 * t52)
                    * t53,
                (t2 + t3 - k_edge * sin_theta * t16 * t19
                    - mu * k_edge * cos_theta * t14 * t16 * t18
                    - mu * k_wall * t27 * t29 * t31 + k_edge * sin_theta * t40 * t43
                    - mu * k_edge * cos_theta * t38 * t40 * t42
                    - mu * k_wall * t47 * t49 * t51) * t53,
                (m_2 - k_edge * t16 * t19 * (-(sin_theta * t6) - cos_theta * t7)
                    - mu * k_edge * t14 * t16 * t18 * (sin_theta * t12 + cos_theta * t13)
                    - k_wall * t29 * t32 * (cos_theta * t21 - sin_theta * t22)
                    - mu * k_wall * t26 * t27 * t29 * t31 - k_edge * t35 * t40 * t43
                    - mu * k_edge * t38 * t40 * t42 * (sin_theta * t36 + cos_theta * t37)
                    - k_wall * t49 * t52 * (-(cos_theta * t21) + sin_theta * t44)
                    - mu * k_wall * t46 * t47 * t49 * t51) / j,
                xdot * (t0 + t1) + zdot * (t2 + t3) + thetadot * m_2,
                mu * k_edge * t16 * t18 * (t14 * t14)
                    + mu * k_wall * t29 * t31 * (t27 * t27)
                    + mu * k_edge * t40 * t42 * (t38 * t38)
                    + mu * k_wall * t49 * t51 * (t47 * t47),
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
    /// 240 add/sub, 1008 mul, 10 div, 8 sqrt, 8 transcendental, 12 branches; 144 `let`s.
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
        let t4 = -x;
        let t5 = -rho_h + t3 + t4;
        let t6 = rho_h - z;
        let t7 = cos_theta * t5;
        let t8 = -sin_theta * t6;
        let t9 = sin_theta * t6;
        let t10 = t7 + t8;
        let t11 = r + rho_h + t7 + t8;
        let t12 = cos_theta * t6;
        let t13 = sin_theta * t5 + t12;
        let t14 = -r;
        let t15 = -r * sin_theta;
        let t16 = r * sin_theta;
        let t17 = cos_theta * t13 + t16;
        let t18 = xdot + thetadot * t17;
        let t19 = -sin_theta * t13;
        let t20 = -r * cos_theta;
        let t21 = r * cos_theta;
        let t22 = t19 + t21;
        let t23 = zdot + thetadot * t22;
        let t24 = sin_theta * t18 + cos_theta * t23;
        let t25 = if t11 > 0.0 || t11.is_nan() { t11 } else { 0.0 };
        let t26 = t25 * t25.sqrt();
        let t27 = v_s.hypot(t24);
        let t28 = 1.0 / t27;
        let t29 = if t11 > 0.0 { 1.0 } else if t11.is_nan() { t11 } else { 0.0 };
        let t30 = -k_edge * cos_theta * t26 * t29;
        let t31 = -k_edge * sin_theta * t26 * t29;
        let t32 = -(sin_theta * t5) - cos_theta * t6;
        let t33 = sin_theta * t17 + cos_theta * t22;
        let t34 = t24 * t24;
        let t35 = -rho_p;
        let t36 = l_c + t35;
        let t37 = r + t35;
        let t38 = sin_theta * t36;
        let t39 = x + rho_p + t3 + t38 + cos_theta * t37;
        let t40 = l_c + t35 + rho_p * sin_theta;
        let t41 = 0.5 * theta;
        let t42 = t41.sin();
        let t43 = t42 * t42;
        let t44 = r - 2.0 * rho_p * t43;
        let t45 = -(sin_theta * t40) - cos_theta * t44;
        let t46 = zdot + thetadot * t45;
        let t47 = if t39 > 0.0 || t39.is_nan() { t39 } else { 0.0 };
        let t48 = t47 * t47.sqrt();
        let t49 = v_s.hypot(t46);
        let t50 = 1.0 / t49;
        let t51 = if t39 > 0.0 { 1.0 } else if t39.is_nan() { t39 } else { 0.0 };
        let t52 = cos_theta * t36 - sin_theta * t37;
        let t53 = t46 * t46;
        let t54 = rho_h + 0.5 * d + t4;
        let t55 = t8 + cos_theta * t54;
        let t56 = r + rho_h + t9 - cos_theta * t54;
        let t57 = t12 + sin_theta * t54;
        let t58 = t15 + cos_theta * t57;
        let t59 = xdot + thetadot * t58;
        let t60 = -sin_theta * t57;
        let t61 = t20 + t60;
        let t62 = zdot + thetadot * t61;
        let t63 = sin_theta * t59 + cos_theta * t62;
        let t64 = if t56 > 0.0 || t56.is_nan() { t56 } else { 0.0 };
        let t65 = t64 * t64.sqrt();
        let t66 = v_s.hypot(t63);
        let t67 = 1.0 / t66;
        let t68 = if t56 > 0.0 { 1.0 } else if t56.is_nan() { t56 } else { 0.0 };
        let t69 = k_edge * cos_theta * t65 * t68;
        let t70 = k_edge * sin_theta * t65 * t68;
        let t71 = sin_theta * t58 + cos_theta * t61;
        let t72 = t63 * t63;
        let t73 = rho_p + t14;
        let t74 = -sin_theta * t36;
        let t75 = rho_p + t3 + t4 + t74 - cos_theta * t73;
        let t76 = l_c + t35 - rho_p * sin_theta;
        let t77 = t14 + 2.0 * rho_p * t43;
        let t78 = -(sin_theta * t76) - cos_theta * t77;
        let t79 = zdot + thetadot * t78;
        let t80 = if t75 > 0.0 || t75.is_nan() { t75 } else { 0.0 };
        let t81 = t80 * t80.sqrt();
        let t82 = v_s.hypot(t79);
        let t83 = 1.0 / t82;
        let t84 = if t75 > 0.0 { 1.0 } else if t75.is_nan() { t75 } else { 0.0 };
        let t85 = -cos_theta * t36;
        let t86 = t85 + sin_theta * t73;
        let t87 = t79 * t79;
        let t88 = 1.0 / m;
        let t89 = 1.0 / j;
        let t90 = t25.sqrt();
        let t91 = cos_theta * cos_theta;
        let t92 = t29 * t29;
        let t93 = sin_theta * sin_theta;
        let t94 = t47.sqrt();
        let t95 = t51 * t51;
        let t96 = t64.sqrt();
        let t97 = t68 * t68;
        let t98 = t80.sqrt();
        let t99 = t84 * t84;
        let t100 = 1.5 * k_edge * sin_theta * cos_theta * t90 * t92;
        let t101 = 1.5 * k_edge * sin_theta * cos_theta * t96 * t97;
        let t102 = 1.5 * k_edge * cos_theta * t32 * t90 * t92;
        let t103 = t19 + t21 + cos_theta * t10;
        let t104 = t15 - cos_theta * t13 - sin_theta * t10;
        let t105 = cos_theta * t18 + thetadot * sin_theta * t103 - sin_theta * t23
            + thetadot * cos_theta * t104;
        let t106 = 1.0 / (t27 * t27 * t27);
        let t107 = -1.5 * k_wall * t52 * t94 * t95;
        let t108 = -1.5 * k_edge * cos_theta * t57 * t96 * t97;
        let t109 = t20 + t60 + cos_theta * t55;
        let t110 = t16 - cos_theta * t57 - sin_theta * t55;
        let t111 = cos_theta * t59 + thetadot * sin_theta * t109 - sin_theta * t62
            + thetadot * cos_theta * t110;
        let t112 = 1.0 / (t66 * t66 * t66);
        let t113 = 1.5 * k_wall * t86 * t98 * t99;
        let t114 = t88
            * (-(mu * k_edge * sin_theta * cos_theta * t26 * t28)
                + mu * k_edge * sin_theta * cos_theta * t26 * t34 * t106
                - mu * k_edge * sin_theta * cos_theta * t65 * t67
                + mu * k_edge * sin_theta * cos_theta * t65 * t72 * t112);
        let t115 = -(mu * k_edge * sin_theta * t26 * t28 * t33)
            + mu * k_edge * sin_theta * t26 * t33 * t34 * t106
            - mu * k_edge * sin_theta * t65 * t67 * t71
            + mu * k_edge * sin_theta * t65 * t71 * t72 * t112;
        let t116 = -f1 * sin_theta;
        let t117 = -f2 * cos_theta;
        let t118 = -1.5 * k_edge * sin_theta * t32 * t90 * t92;
        let t119 = t41.cos();
        let t120 = sin_theta * t44 - cos_theta * t40 - rho_p * sin_theta * cos_theta
            + 2.0 * rho_p * cos_theta * t42 * t119;
        let t121 = 1.0 / (t49 * t49 * t49);
        let t122 = 1.5 * k_edge * sin_theta * t57 * t96 * t97;
        let t123 = sin_theta * t77 + rho_p * sin_theta * cos_theta - cos_theta * t76
            - 2.0 * rho_p * cos_theta * t42 * t119;
        let t124 = 1.0 / (t82 * t82 * t82);
        let t125 = -(mu * k_edge * cos_theta * t26 * t28 * t33)
            + mu * k_edge * cos_theta * t26 * t33 * t34 * t106
            - mu * k_wall * t45 * t48 * t50 + mu * k_wall * t45 * t48 * t53 * t121
            - mu * k_edge * cos_theta * t65 * t67 * t71
            + mu * k_edge * cos_theta * t65 * t71 * t72 * t112
            - mu * k_wall * t78 * t81 * t83 + mu * k_wall * t78 * t81 * t87 * t124;
        let t126 = sin_theta * t37 + t85;
        let t127 = t33 * t33;
        let t128 = cos_theta * t44 + sin_theta * t40;
        let t129 = t128 * t128;
        let t130 = t71 * t71;
        let t131 = cos_theta * t77 + sin_theta * t76;
        let t132 = t131 * t131;
        let t133 = t24 * t24 * t24;
        let t134 = 2.0 * sin_theta * t18 + 2.0 * cos_theta * t23;
        let t135 = t46 * t46 * t46;
        let t136 = 2.0 * zdot;
        let t137 = t136 + 2.0 * thetadot * t45;
        let t138 = t63 * t63 * t63;
        let t139 = 2.0 * sin_theta * t59 + 2.0 * cos_theta * t62;
        let t140 = t79 * t79 * t79;
        let t141 = t136 + 2.0 * thetadot * t78;
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
                t88
                    * (-(1.5 * k_edge * t90 * t91 * t92)
                        + 1.5 * mu * k_edge * sin_theta * cos_theta * t24 * t28 * t29
                            * t90 - 1.5 * k_wall * t94 * t95
                        - 1.5 * k_edge * t91 * t96 * t97
                        - 1.5 * mu * k_edge * sin_theta * cos_theta * t63 * t67 * t68
                            * t96 - 1.5 * k_wall * t98 * t99),
                t88
                    * (t100 - 1.5 * mu * k_edge * t24 * t28 * t29 * t90 * t93 + t101
                        + 1.5 * mu * k_edge * t63 * t67 * t68 * t93 * t96),
                t88
                    * (t0 + t1 + t31 - mu * k_edge * cos_theta * t24 * t26 * t28 + t70
                        - mu * k_edge * cos_theta * t63 * t65 * t67 + t102
                        - mu * k_edge * sin_theta * t26 * t28 * t105
                        - 1.5 * mu * k_edge * sin_theta * t24 * t28 * t29 * t32 * t90
                        + mu * k_edge * sin_theta * t26 * t34 * t105 * t106 + t107 + t108
                        - mu * k_edge * sin_theta * t65 * t67 * t111
                        - 1.5 * mu * k_edge * sin_theta * t57 * t63 * t67 * t68 * t96
                        + mu * k_edge * sin_theta * t65 * t72 * t111 * t112 + t113),
                t88
                    * (-(mu * k_edge * t26 * t28 * t93)
                        + mu * k_edge * t26 * t34 * t93 * t106
                        - mu * k_edge * t65 * t67 * t93
                        + mu * k_edge * t65 * t72 * t93 * t112),
                t114,
                t88 * t115,
                0.0,
                0.0,
                t88
                    * (t100 + t101 + 1.5 * mu * k_edge * t24 * t28 * t29 * t90 * t91
                        - 1.5 * mu * k_wall * t46 * t50 * t51 * t94
                        - 1.5 * mu * k_edge * t63 * t67 * t68 * t91 * t96
                        + 1.5 * mu * k_wall * t79 * t83 * t84 * t98),
                t88
                    * (-(1.5 * k_edge * t90 * t92 * t93)
                        - 1.5 * mu * k_edge * sin_theta * cos_theta * t24 * t28 * t29
                            * t90 - 1.5 * k_edge * t93 * t96 * t97
                        + 1.5 * mu * k_edge * sin_theta * cos_theta * t63 * t67 * t68
                            * t96),
                t88
                    * (t30 + mu * k_edge * sin_theta * t24 * t26 * t28 + t69
                        + mu * k_edge * sin_theta * t63 * t65 * t67 + t116 + t117 + t118
                        - mu * k_edge * cos_theta * t26 * t28 * t105
                        - 1.5 * mu * k_edge * cos_theta * t24 * t28 * t29 * t32 * t90
                        + mu * k_edge * cos_theta * t26 * t34 * t105 * t106
                        - thetadot * mu * k_wall * t48 * t50 * t120
                        - 1.5 * mu * k_wall * t46 * t50 * t51 * t52 * t94
                        + thetadot * mu * k_wall * t48 * t53 * t120 * t121 + t122
                        - mu * k_edge * cos_theta * t65 * t67 * t111
                        - 1.5 * mu * k_edge * cos_theta * t57 * t63 * t67 * t68 * t96
                        + mu * k_edge * cos_theta * t65 * t72 * t111 * t112
                        - thetadot * mu * k_wall * t81 * t83 * t123
                        - 1.5 * mu * k_wall * t79 * t83 * t84 * t86 * t98
                        + thetadot * mu * k_wall * t81 * t87 * t123 * t124),
                t114,
                t88
                    * (-(mu * k_edge * t26 * t28 * t91)
                        + mu * k_edge * t26 * t34 * t91 * t106 - mu * k_wall * t48 * t50
                        + mu * k_wall * t48 * t53 * t121 - mu * k_edge * t65 * t67 * t91
                        + mu * k_edge * t65 * t72 * t91 * t112 - mu * k_wall * t81 * t83
                        + mu * k_wall * t81 * t87 * t124),
                t88 * t125,
                0.0,
                0.0,
                t89
                    * (t31 + t70 + t102 + t107 + t108 + t113
                        + 1.5 * mu * k_edge * cos_theta * t24 * t28 * t29 * t33 * t90
                        - 1.5 * mu * k_wall * t45 * t46 * t50 * t51 * t94
                        - 1.5 * mu * k_edge * cos_theta * t63 * t67 * t68 * t71 * t96
                        + 1.5 * mu * k_wall * t78 * t79 * t83 * t84 * t98),
                t89
                    * (t30 + t69 + t118 + t122
                        - 1.5 * mu * k_edge * sin_theta * t24 * t28 * t29 * t33 * t90
                        + 1.5 * mu * k_edge * sin_theta * t63 * t67 * t68 * t71 * t96),
                t89
                    * (-(1.5 * k_edge * t90 * t92 * (t13 * t13))
                        - k_edge * (t9 - cos_theta * t5) * t26 * t29
                        - mu * k_edge * t26 * t28 * t33 * t105
                        - 1.5 * mu * k_edge * t24 * t28 * t29 * t32 * t33 * t90
                        + mu * k_edge * t26 * t33 * t34 * t105 * t106
                        - mu * k_edge * t24 * t26 * t28
                            * (cos_theta * t17 + sin_theta * t103 - sin_theta * t22
                                + cos_theta * t104)
                        - 1.5 * k_wall * t94 * t95 * (t126 * t126)
                        - k_wall * t48 * t51 * (t74 - cos_theta * t37)
                        - mu * k_wall * t46 * t48 * t50 * t120
                        - thetadot * mu * k_wall * t45 * t48 * t50 * t120
                        - 1.5 * mu * k_wall * t45 * t46 * t50 * t51 * t52 * t94
                        + thetadot * mu * k_wall * t45 * t48 * t53 * t120 * t121
                        - k_edge * t55 * t65 * t68
                        - 1.5 * k_edge * t96 * t97 * (t57 * t57)
                        - mu * k_edge * t65 * t67 * t71 * t111
                        - 1.5 * mu * k_edge * t57 * t63 * t67 * t68 * t71 * t96
                        + mu * k_edge * t65 * t71 * t72 * t111 * t112
                        - mu * k_edge * t63 * t65 * t67
                            * (cos_theta * t58 + sin_theta * t109 - sin_theta * t61
                                + cos_theta * t110) - 1.5 * k_wall * t98 * t99 * (t86 * t86)
                        - k_wall * t81 * t84 * (t38 + cos_theta * t73)
                        - mu * k_wall * t79 * t81 * t83 * t123
                        - thetadot * mu * k_wall * t78 * t81 * t83 * t123
                        - 1.5 * mu * k_wall * t78 * t79 * t83 * t84 * t86 * t98
                        + thetadot * mu * k_wall * t78 * t81 * t87 * t123 * t124),
                t89 * t115,
                t89 * t125,
                t89
                    * (-(mu * k_edge * t26 * t28 * t127)
                        + mu * k_edge * t26 * t34 * t106 * t127
                        - mu * k_wall * t48 * t50 * t129
                        + mu * k_wall * t48 * t53 * t121 * t129
                        - mu * k_edge * t65 * t67 * t130
                        + mu * k_edge * t65 * t72 * t112 * t130
                        - mu * k_wall * t81 * t83 * t132
                        + mu * k_wall * t81 * t87 * t124 * t132),
                0.0,
                0.0,
                0.0,
                0.0,
                xdot * t2 + zdot * (t116 + t117),
                f1 * sin_theta + f2 * cos_theta,
                t2,
                m_2,
                0.0,
                0.0,
                -(1.5 * mu * k_edge * cos_theta * t28 * t29 * t34 * t90)
                    + 1.5 * mu * k_wall * t50 * t51 * t53 * t94
                    + 1.5 * mu * k_edge * cos_theta * t67 * t68 * t72 * t96
                    - 1.5 * mu * k_wall * t83 * t84 * t87 * t98,
                1.5 * mu * k_edge * sin_theta * t28 * t29 * t34 * t90
                    - 1.5 * mu * k_edge * sin_theta * t67 * t68 * t72 * t96,
                1.5 * mu * k_edge * t28 * t29 * t32 * t34 * t90
                    - mu * k_edge * t26 * t105 * t106 * t133
                    + mu * k_edge * t26 * t28 * t105 * t134
                    + 1.5 * mu * k_wall * t50 * t51 * t52 * t53 * t94
                    - thetadot * mu * k_wall * t48 * t120 * t121 * t135
                    + thetadot * mu * k_wall * t48 * t50 * t120 * t137
                    + 1.5 * mu * k_edge * t57 * t67 * t68 * t72 * t96
                    - mu * k_edge * t65 * t111 * t112 * t138
                    + mu * k_edge * t65 * t67 * t111 * t139
                    + 1.5 * mu * k_wall * t83 * t84 * t86 * t87 * t98
                    - thetadot * mu * k_wall * t81 * t123 * t124 * t140
                    + thetadot * mu * k_wall * t81 * t83 * t123 * t141,
                -(mu * k_edge * sin_theta * t26 * t106 * t133)
                    + mu * k_edge * sin_theta * t26 * t28 * t134
                    - mu * k_edge * sin_theta * t65 * t112 * t138
                    + mu * k_edge * sin_theta * t65 * t67 * t139,
                -(mu * k_edge * cos_theta * t26 * t106 * t133)
                    + mu * k_edge * cos_theta * t26 * t28 * t134
                    - mu * k_wall * t48 * t121 * t135 + mu * k_wall * t48 * t50 * t137
                    - mu * k_edge * cos_theta * t65 * t112 * t138
                    + mu * k_edge * cos_theta * t65 * t67 * t139
                    - mu * k_wall * t81 * t124 * t140 + mu * k_wall * t81 * t83 * t141,
                -(mu * k_edge * t26 * t33 * t106 * t133)
                    + mu * k_edge * t26 * t28 * t33 * t134
                    - mu * k_wall * t45 * t48 * t121 * t135
                    + mu * k_wall * t45 * t48 * t50 * t137
                    - mu * k_edge * t65 * t71 * t112 * t138
                    + mu * k_edge * t65 * t67 * t71 * t139
                    - mu * k_wall * t78 * t81 * t124 * t140
                    + mu * k_wall * t78 * t81 * t83 * t141,
                0.0,
                0.0,
            ],
        )
    }
    /// Per contact (edge_left, wall_right, edge_right, wall_left): normal force f (N), friction force along the tangent (N), penetration delta (m), sliding velocity (m/s), contact ellipse a, b (m) and maximum pressure p0 (Pa) ((9)-(11)).
    ///
    /// # Inputs
    /// - `y` = (`x`, `z`, `theta`, `xdot`, `zdot`, `thetadot`, `work`, `dissipation`)
    /// - `p` = (`m`, `J`, `r`, `l_c`, `D`, `rho_p`, `rho_h`, `mu`, `v_s`, `k_edge`, `k_wall`, `f1`, `f2`, `M`, `e_star`, `edge_sum`, `edge_ma`, `edge_mb`, `edge_dstar`, `wall_sum`, `wall_ma`, `wall_mb`, `wall_dstar`)
    ///
    /// # Outputs
    /// - `normal`: vector of 4
    /// - `friction`: vector of 4
    /// - `delta`: vector of 4
    /// - `slip`: vector of 4
    /// - `a`: vector of 4
    /// - `b`: vector of 4
    /// - `p0`: vector of 4
    ///
    /// # Cost
    /// 44 add/sub, 113 mul, 11 div, 4 sqrt, 17 transcendental, 4 branches; 52 `let`s.
    #[inline]
    pub fn contacts(
        y: &SVector<f64, 8>,
        p: &SVector<f64, 23>,
    ) -> (
        SVector<f64, 4>,
        SVector<f64, 4>,
        SVector<f64, 4>,
        SVector<f64, 4>,
        SVector<f64, 4>,
        SVector<f64, 4>,
        SVector<f64, 4>,
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
        let t1 = -x;
        let t2 = -rho_h + t0 + t1;
        let t3 = rho_h - z;
        let t4 = r + rho_h + cos_theta * t2 - sin_theta * t3;
        let t5 = cos_theta * t3;
        let t6 = sin_theta * t2 + t5;
        let t7 = -r;
        let t8 = sin_theta * (xdot + thetadot * (cos_theta * t6 + r * sin_theta))
            + cos_theta * (zdot + thetadot * (-(sin_theta * t6) + r * cos_theta));
        let t9 = if t4 > 0.0 || t4.is_nan() { t4 } else { 0.0 };
        let t10 = t9 * t9.sqrt();
        let t11 = v_s.hypot(t8);
        let t12 = 1.0 / e_star;
        let t13 = 1.0 / edge_sum;
        let t14 = (1.5 * k_edge * t10 * t12 * t13).powf(0.3333333333333333);
        let t15 = (1.5 * k_edge * t10).powf(0.3333333333333333);
        let t16 = (e_star * edge_sum).powf(0.6666666666666666);
        let t17 = 1.0 / edge_ma;
        let t18 = 1.0 / edge_mb;
        let t19 = -rho_p;
        let t20 = l_c + t19;
        let t21 = x + rho_p + t0 + sin_theta * t20 + cos_theta * (r + t19);
        let t22 = (0.5 * theta).sin();
        let t23 = t22 * t22;
        let t24 = zdot
            + thetadot
                * (-(sin_theta * (l_c + t19 + rho_p * sin_theta))
                    - cos_theta * (r - 2.0 * rho_p * t23));
        let t25 = if t21 > 0.0 || t21.is_nan() { t21 } else { 0.0 };
        let t26 = t25 * t25.sqrt();
        let t27 = v_s.hypot(t24);
        let t28 = 1.0 / wall_sum;
        let t29 = (1.5 * k_wall * t12 * t26 * t28).powf(0.3333333333333333);
        let t30 = (1.5 * k_wall * t26).powf(0.3333333333333333);
        let t31 = (e_star * wall_sum).powf(0.6666666666666666);
        let t32 = 1.0 / wall_ma;
        let t33 = 1.0 / wall_mb;
        let t34 = rho_h + 0.5 * d + t1;
        let t35 = r + rho_h + sin_theta * t3 - cos_theta * t34;
        let t36 = t5 + sin_theta * t34;
        let t37 = sin_theta * (xdot + thetadot * (-(r * sin_theta) + cos_theta * t36))
            + cos_theta * (zdot + thetadot * (-(r * cos_theta) - sin_theta * t36));
        let t38 = if t35 > 0.0 || t35.is_nan() { t35 } else { 0.0 };
        let t39 = t38 * t38.sqrt();
        let t40 = v_s.hypot(t37);
        let t41 = (1.5 * k_edge * t12 * t13 * t39).powf(0.3333333333333333);
        let t42 = (1.5 * k_edge * t39).powf(0.3333333333333333);
        let t43 = rho_p + t0 + t1 - sin_theta * t20 - cos_theta * (rho_p + t7);
        let t44 = zdot
            + thetadot
                * (-(sin_theta * (l_c + t19 - rho_p * sin_theta))
                    - cos_theta * (t7 + 2.0 * rho_p * t23));
        let t45 = if t43 > 0.0 || t43.is_nan() { t43 } else { 0.0 };
        let t46 = t45 * t45.sqrt();
        let t47 = v_s.hypot(t44);
        let t48 = (1.5 * k_wall * t12 * t28 * t46).powf(0.3333333333333333);
        let t49 = (1.5 * k_wall * t46).powf(0.3333333333333333);
        let normal = Vector4::new(
            k_edge * t10,
            k_wall * t26,
            k_edge * t39,
            k_wall * t46,
        );
        let friction = Vector4::new(
            -mu * k_edge * t8 * t10 / t11,
            -mu * k_wall * t24 * t26 / t27,
            -mu * k_edge * t37 * t39 / t40,
            -mu * k_wall * t44 * t46 / t47,
        );
        let delta = Vector4::new(t4, t21, t35, t43);
        let slip = Vector4::new(t8, t24, t37, t44);
        let a = Vector4::new(edge_ma * t14, wall_ma * t29, edge_ma * t41, wall_ma * t48);
        let b = Vector4::new(edge_mb * t14, wall_mb * t29, edge_mb * t41, wall_mb * t48);
        let p0 = Vector4::new(
            0.3183098861837907 * t15 * t16 * t17 * t18,
            0.3183098861837907 * t30 * t31 * t32 * t33,
            0.3183098861837907 * t16 * t17 * t18 * t42,
            0.3183098861837907 * t31 * t32 * t33 * t49,
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
    /// 28 add/sub, 26 mul, 0 div, 0 sqrt, 6 transcendental, 4 branches; 19 `let`s.
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
        let t1 = -x;
        let t2 = rho_h - z;
        let t3 = r + rho_h + cos_theta * (-rho_h + t0 + t1) - sin_theta * t2;
        let t4 = if t3 > 0.0 || t3.is_nan() { t3 } else { 0.0 };
        let t5 = t4.powf(2.5);
        let t6 = -rho_p;
        let t7 = l_c + t6;
        let t8 = x + rho_p + t0 + sin_theta * t7 + cos_theta * (r + t6);
        let t9 = if t8 > 0.0 || t8.is_nan() { t8 } else { 0.0 };
        let t10 = t9.powf(2.5);
        let t11 = r + rho_h + sin_theta * t2 - cos_theta * (rho_h + 0.5 * d + t1);
        let t12 = if t11 > 0.0 || t11.is_nan() { t11 } else { 0.0 };
        let t13 = t12.powf(2.5);
        let t14 = rho_p + t0 + t1 - sin_theta * t7 - cos_theta * (rho_p - r);
        let t15 = if t14 > 0.0 || t14.is_nan() { t14 } else { 0.0 };
        let t16 = t15.powf(2.5);
        let kinetic = 0.5 * m * (xdot * xdot + zdot * zdot)
            + 0.5 * j * (thetadot * thetadot);
        let potential = 0.4 * k_edge * t5 + 0.4 * k_wall * t10 + 0.4 * k_edge * t13
            + 0.4 * k_wall * t16;
        let depth = z + l_c * cos_theta;
        (kinetic, potential, depth)
    }
}
