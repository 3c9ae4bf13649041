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
    /// 108 add/sub, 215 mul, 6 div, 4 sqrt, 7 transcendental, 16 branches; 77 `let`s.
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
        let t17 = -(sin_theta * t6) - cos_theta * t7;
        let t18 = -(xdot * cos_theta) + zdot * sin_theta + thetadot * t17;
        let t19 = 1.0 + hc_alpha * t18;
        let t20 = if t19 > 0.0 || t19.is_nan() { t19 } else { 0.0 };
        let t21 = k_edge * t16 * t20 - k_edge * t16;
        let t22 = v_s.hypot(t14);
        let t23 = 1.0 / t22;
        let t24 = if t8 > 0.0 { 1.0 } else if t8.is_nan() { t8 } else { 0.0 };
        let t25 = -rho_p;
        let t26 = l_c + t25;
        let t27 = r + t25;
        let t28 = x + rho_p + t4 + sin_theta * t26 + cos_theta * t27;
        let t29 = (0.5 * theta).sin();
        let t30 = t29 * t29;
        let t31 = -(sin_theta * (l_c + t25 + rho_p * sin_theta))
            - cos_theta * (r - 2.0 * rho_p * t30);
        let t32 = zdot + thetadot * t31;
        let t33 = if t28 > 0.0 || t28.is_nan() { t28 } else { 0.0 };
        let t34 = t33 * t33.sqrt();
        let t35 = cos_theta * t26 - sin_theta * t27;
        let t36 = xdot + thetadot * t35;
        let t37 = 1.0 + hc_alpha * t36;
        let t38 = if t37 > 0.0 || t37.is_nan() { t37 } else { 0.0 };
        let t39 = k_wall * t34 * t38 - k_wall * t34;
        let t40 = v_s.hypot(t32);
        let t41 = 1.0 / t40;
        let t42 = if t28 > 0.0 { 1.0 } else if t28.is_nan() { t28 } else { 0.0 };
        let t43 = rho_h + 0.5 * d + t5;
        let t44 = r + rho_h + sin_theta * t7 - cos_theta * t43;
        let t45 = t9 + sin_theta * t43;
        let t46 = -(r * sin_theta) + cos_theta * t45;
        let t47 = -(r * cos_theta) - sin_theta * t45;
        let t48 = sin_theta * (xdot + thetadot * t46)
            + cos_theta * (zdot + thetadot * t47);
        let t49 = if t44 > 0.0 || t44.is_nan() { t44 } else { 0.0 };
        let t50 = t49 * t49.sqrt();
        let t51 = xdot * cos_theta - zdot * sin_theta + thetadot * t45;
        let t52 = 1.0 + hc_alpha * t51;
        let t53 = if t52 > 0.0 || t52.is_nan() { t52 } else { 0.0 };
        let t54 = k_edge * t50 * t53 - k_edge * t50;
        let t55 = v_s.hypot(t48);
        let t56 = 1.0 / t55;
        let t57 = if t44 > 0.0 { 1.0 } else if t44.is_nan() { t44 } else { 0.0 };
        let t58 = rho_p + t11;
        let t59 = rho_p + t4 + t5 - sin_theta * t26 - cos_theta * t58;
        let t60 = -(sin_theta * (l_c + t25 - rho_p * sin_theta))
            - cos_theta * (t11 + 2.0 * rho_p * t30);
        let t61 = zdot + thetadot * t60;
        let t62 = if t59 > 0.0 || t59.is_nan() { t59 } else { 0.0 };
        let t63 = t62 * t62.sqrt();
        let t64 = -(cos_theta * t26) + sin_theta * t58;
        let t65 = -xdot + thetadot * t64;
        let t66 = 1.0 + hc_alpha * t65;
        let t67 = if t66 > 0.0 || t66.is_nan() { t66 } else { 0.0 };
        let t68 = k_wall * t63 * t67;
        let t69 = -k_wall * t63;
        let t70 = t68 + t69;
        let t71 = v_s.hypot(t61);
        let t72 = 1.0 / t71;
        let t73 = if t59 > 0.0 { 1.0 } else if t59.is_nan() { t59 } else { 0.0 };
        let t74 = 1.0 / m;
        SMatrix::<
            f64,
            8,
            1,
        >::from_row_slice(
            &[
                xdot,
                zdot,
                thetadot,
                (t0 + t1 + k_edge * cos_theta * t16 * t24 + cos_theta * t21
                    - mu * k_edge * sin_theta * t14 * t16 * t20 * t23 + k_wall * t34
                    - k_wall * t34 * t42 - k_wall * t34 * t38
                    - k_edge * cos_theta * t50 * t57 - cos_theta * t54
                    - mu * k_edge * sin_theta * t48 * t50 * t53 * t56 + t68 + t69
                    + k_wall * t63 * t73) * t74,
                (t2 + t3 - k_edge * sin_theta * t16 * t24 - sin_theta * t21
                    - mu * k_edge * cos_theta * t14 * t16 * t20 * t23
                    - mu * k_wall * t32 * t34 * t38 * t41
                    + k_edge * sin_theta * t50 * t57 + sin_theta * t54
                    - mu * k_edge * cos_theta * t48 * t50 * t53 * t56
                    - mu * k_wall * t61 * t63 * t67 * t72) * t74,
                (m_2 - k_edge * t16 * t17 * t24 - t17 * t21
                    - mu * k_edge * t14 * t16 * t20 * t23
                        * (sin_theta * t12 + cos_theta * t13) - k_wall * t34 * t35 * t42
                    - t35 * t39 - mu * k_wall * t31 * t32 * t34 * t38 * t41
                    - k_edge * t45 * t50 * t57 - t45 * t54
                    - mu * k_edge * t48 * t50 * t53 * t56
                        * (sin_theta * t46 + cos_theta * t47) - k_wall * t63 * t64 * t73
                    - t64 * t70 - mu * k_wall * t60 * t61 * t63 * t67 * t72) / j,
                xdot * (t0 + t1) + zdot * (t2 + t3) + thetadot * m_2,
                mu * k_edge * t16 * t20 * t23 * (t14 * t14) + t18 * t21
                    + mu * k_wall * t34 * t38 * t41 * (t32 * t32) + t36 * t39
                    + mu * k_edge * t50 * t53 * t56 * (t48 * t48) + t51 * t54
                    + mu * k_wall * t63 * t67 * t72 * (t61 * t61) + t65 * t70,
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
    /// 465 add/sub, 1993 mul, 10 div, 8 sqrt, 8 transcendental, 24 branches; 217 `let`s.
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
        let t4 = -x;
        let t5 = -rho_h + t3 + t4;
        let t6 = rho_h - z;
        let t7 = cos_theta * t5;
        let t8 = -sin_theta * t6;
        let t9 = sin_theta * t6;
        let t10 = t7 + t8;
        let t11 = t9 - cos_theta * t5;
        let t12 = r + rho_h + t7 + t8;
        let t13 = cos_theta * t6;
        let t14 = sin_theta * t5 + t13;
        let t15 = -r;
        let t16 = -r * sin_theta;
        let t17 = r * sin_theta;
        let t18 = cos_theta * t14 + t17;
        let t19 = xdot + thetadot * t18;
        let t20 = -sin_theta * t14;
        let t21 = -r * cos_theta;
        let t22 = r * cos_theta;
        let t23 = t20 + t22;
        let t24 = zdot + thetadot * t23;
        let t25 = sin_theta * t19 + cos_theta * t24;
        let t26 = if t12 > 0.0 || t12.is_nan() { t12 } else { 0.0 };
        let t27 = t26 * t26.sqrt();
        let t28 = -(sin_theta * t5) - cos_theta * t6;
        let t29 = -(xdot * cos_theta) + zdot * sin_theta + thetadot * t28;
        let t30 = 1.0 + hc_alpha * t29;
        let t31 = if t30 > 0.0 || t30.is_nan() { t30 } else { 0.0 };
        let t32 = k_edge * t27 * t31 - k_edge * t27;
        let t33 = v_s.hypot(t25);
        let t34 = 1.0 / t33;
        let t35 = if t12 > 0.0 { 1.0 } else if t12.is_nan() { t12 } else { 0.0 };
        let t36 = -k_edge * cos_theta * t27 * t35;
        let t37 = -cos_theta * t32;
        let t38 = -k_edge * sin_theta * t27 * t35;
        let t39 = -sin_theta * t32;
        let t40 = sin_theta * t18 + cos_theta * t23;
        let t41 = t25 * t25;
        let t42 = -rho_p;
        let t43 = l_c + t42;
        let t44 = r + t42;
        let t45 = sin_theta * t43;
        let t46 = x + rho_p + t3 + t45 + cos_theta * t44;
        let t47 = l_c + t42 + rho_p * sin_theta;
        let t48 = 0.5 * theta;
        let t49 = t48.sin();
        let t50 = t49 * t49;
        let t51 = r - 2.0 * rho_p * t50;
        let t52 = -(sin_theta * t47) - cos_theta * t51;
        let t53 = zdot + thetadot * t52;
        let t54 = if t46 > 0.0 || t46.is_nan() { t46 } else { 0.0 };
        let t55 = t54 * t54.sqrt();
        let t56 = cos_theta * t43 - sin_theta * t44;
        let t57 = xdot + thetadot * t56;
        let t58 = 1.0 + hc_alpha * t57;
        let t59 = if t58 > 0.0 || t58.is_nan() { t58 } else { 0.0 };
        let t60 = k_wall * t55 * t59;
        let t61 = -k_wall * t55;
        let t62 = t60 + t61;
        let t63 = v_s.hypot(t53);
        let t64 = 1.0 / t63;
        let t65 = if t46 > 0.0 { 1.0 } else if t46.is_nan() { t46 } else { 0.0 };
        let t66 = t53 * t53;
        let t67 = rho_h + 0.5 * d + t4;
        let t68 = t8 + cos_theta * t67;
        let t69 = r + rho_h + t9 - cos_theta * t67;
        let t70 = t13 + sin_theta * t67;
        let t71 = t16 + cos_theta * t70;
        let t72 = xdot + thetadot * t71;
        let t73 = -sin_theta * t70;
        let t74 = t21 + t73;
        let t75 = zdot + thetadot * t74;
        let t76 = sin_theta * t72 + cos_theta * t75;
        let t77 = if t69 > 0.0 || t69.is_nan() { t69 } else { 0.0 };
        let t78 = t77 * t77.sqrt();
        let t79 = xdot * cos_theta - zdot * sin_theta + thetadot * t70;
        let t80 = 1.0 + hc_alpha * t79;
        let t81 = if t80 > 0.0 || t80.is_nan() { t80 } else { 0.0 };
        let t82 = k_edge * t78 * t81 - k_edge * t78;
        let t83 = v_s.hypot(t76);
        let t84 = 1.0 / t83;
        let t85 = if t69 > 0.0 { 1.0 } else if t69.is_nan() { t69 } else { 0.0 };
        let t86 = k_edge * cos_theta * t78 * t85;
        let t87 = cos_theta * t82;
        let t88 = k_edge * sin_theta * t78 * t85;
        let t89 = sin_theta * t82;
        let t90 = sin_theta * t71 + cos_theta * t74;
        let t91 = t76 * t76;
        let t92 = rho_p + t15;
        let t93 = -sin_theta * t43;
        let t94 = rho_p + t3 + t4 + t93 - cos_theta * t92;
        let t95 = l_c + t42 - rho_p * sin_theta;
        let t96 = t15 + 2.0 * rho_p * t50;
        let t97 = -(sin_theta * t95) - cos_theta * t96;
        let t98 = zdot + thetadot * t97;
        let t99 = if t94 > 0.0 || t94.is_nan() { t94 } else { 0.0 };
        let t100 = t99 * t99.sqrt();
        let t101 = -cos_theta * t43;
        let t102 = t101 + sin_theta * t92;
        let t103 = -xdot + thetadot * t102;
        let t104 = 1.0 + hc_alpha * t103;
        let t105 = if t104 > 0.0 || t104.is_nan() { t104 } else { 0.0 };
        let t106 = k_wall * t100 * t105 - k_wall * t100;
        let t107 = v_s.hypot(t98);
        let t108 = 1.0 / t107;
        let t109 = if t94 > 0.0 { 1.0 } else if t94.is_nan() { t94 } else { 0.0 };
        let t110 = t98 * t98;
        let t111 = 1.0 / m;
        let t112 = 1.0 / j;
        let t113 = t26.sqrt();
        let t114 = cos_theta * cos_theta;
        let t115 = t35 * t35;
        let t116 = if t30 > 0.0 { 1.0 } else if t30.is_nan() { t30 } else { 0.0 };
        let t117 = -(1.5 * k_edge * cos_theta * t31 * t35 * t113)
            + thetadot * k_edge * hc_alpha * sin_theta * t27 * t116
            + 1.5 * k_edge * cos_theta * t35 * t113;
        let t118 = sin_theta * sin_theta;
        let t119 = t54.sqrt();
        let t120 = t65 * t65;
        let t121 = t77.sqrt();
        let t122 = t85 * t85;
        let t123 = if t80 > 0.0 { 1.0 } else if t80.is_nan() { t80 } else { 0.0 };
        let t124 = 1.5 * k_edge * cos_theta * t81 * t85 * t121
            - thetadot * k_edge * hc_alpha * sin_theta * t78 * t123
            - 1.5 * k_edge * cos_theta * t85 * t121;
        let t125 = t99.sqrt();
        let t126 = -1.5 * k_wall * t105 * t109 * t125;
        let t127 = 1.5 * k_wall * t109 * t125;
        let t128 = t109 * t109;
        let t129 = 1.5 * k_edge * sin_theta * cos_theta * t113 * t115;
        let t130 = 1.5 * k_edge * sin_theta * t31 * t35 * t113
            + thetadot * k_edge * hc_alpha * cos_theta * t27 * t116
            - 1.5 * k_edge * sin_theta * t35 * t113;
        let t131 = -thetadot * mu * k_edge * hc_alpha * sin_theta * cos_theta * t25 * t27
            * t34 * t116;
        let t132 = 1.5 * k_edge * sin_theta * cos_theta * t121 * t122;
        let t133 = -(1.5 * k_edge * sin_theta * t81 * t85 * t121)
            - thetadot * k_edge * hc_alpha * cos_theta * t78 * t123
            + 1.5 * k_edge * sin_theta * t85 * t121;
        let t134 = thetadot * mu * k_edge * hc_alpha * sin_theta * cos_theta * t76 * t78
            * t84 * t123;
        let t135 = 1.5 * k_edge * cos_theta * t28 * t113 * t115;
        let t136 = xdot * sin_theta + zdot * cos_theta + thetadot * t11;
        let t137 = 1.5 * k_edge * t28 * t31 * t35 * t113
            + k_edge * hc_alpha * t27 * t116 * t136 - 1.5 * k_edge * t28 * t35 * t113;
        let t138 = t20 + t22 + cos_theta * t10;
        let t139 = t16 - cos_theta * t14 - sin_theta * t10;
        let t140 = cos_theta * t19 + thetadot * sin_theta * t138 - sin_theta * t24
            + thetadot * cos_theta * t139;
        let t141 = 1.0 / (t33 * t33 * t33);
        let t142 = -1.5 * k_wall * t56 * t119 * t120;
        let t143 = t93 - cos_theta * t44;
        let t144 = if t58 > 0.0 { 1.0 } else if t58.is_nan() { t58 } else { 0.0 };
        let t145 = -1.5 * k_edge * cos_theta * t70 * t121 * t122;
        let t146 = -(xdot * sin_theta) - zdot * cos_theta + thetadot * t68;
        let t147 = 1.5 * k_edge * t70 * t81 * t85 * t121
            + k_edge * hc_alpha * t78 * t123 * t146 - 1.5 * k_edge * t70 * t85 * t121;
        let t148 = t21 + t73 + cos_theta * t68;
        let t149 = t17 - cos_theta * t70 - sin_theta * t68;
        let t150 = cos_theta * t72 + thetadot * sin_theta * t148 - sin_theta * t75
            + thetadot * cos_theta * t149;
        let t151 = 1.0 / (t83 * t83 * t83);
        let t152 = 1.5 * k_wall * t102 * t105 * t109 * t125;
        let t153 = t45 + cos_theta * t92;
        let t154 = if t104 > 0.0 { 1.0 } else if t104.is_nan() { t104 } else { 0.0 };
        let t155 = thetadot * k_wall * hc_alpha * t100 * t153 * t154;
        let t156 = -1.5 * k_wall * t102 * t109 * t125;
        let t157 = 1.5 * k_wall * t102 * t125 * t128;
        let t158 = k_edge * hc_alpha * sin_theta * cos_theta * t27 * t116;
        let t159 = -mu * k_edge * sin_theta * cos_theta * t27 * t31 * t34;
        let t160 = mu * k_edge * sin_theta * cos_theta * t27 * t31 * t41 * t141;
        let t161 = k_edge * hc_alpha * sin_theta * cos_theta * t78 * t123;
        let t162 = -mu * k_edge * sin_theta * cos_theta * t78 * t81 * t84;
        let t163 = mu * k_edge * sin_theta * cos_theta * t78 * t81 * t91 * t151;
        let t164 = k_edge * hc_alpha * cos_theta * t27 * t28 * t116;
        let t165 = -mu * k_edge * sin_theta * t27 * t31 * t34 * t40;
        let t166 = mu * k_edge * sin_theta * t27 * t31 * t40 * t41 * t141;
        let t167 = -k_wall * hc_alpha * t55 * t56 * t144;
        let t168 = -k_edge * hc_alpha * cos_theta * t70 * t78 * t123;
        let t169 = -mu * k_edge * sin_theta * t78 * t81 * t84 * t90;
        let t170 = mu * k_edge * sin_theta * t78 * t81 * t90 * t91 * t151;
        let t171 = k_wall * hc_alpha * t100 * t102 * t154;
        let t172 = -f1 * sin_theta;
        let t173 = -f2 * cos_theta;
        let t174 = -1.5 * k_edge * sin_theta * t28 * t113 * t115;
        let t175 = t48.cos();
        let t176 = sin_theta * t51 - cos_theta * t47 - rho_p * sin_theta * cos_theta
            + 2.0 * rho_p * cos_theta * t49 * t175;
        let t177 = 1.0 / (t63 * t63 * t63);
        let t178 = 1.5 * k_edge * sin_theta * t70 * t121 * t122;
        let t179 = sin_theta * t96 + rho_p * sin_theta * cos_theta - cos_theta * t95
            - 2.0 * rho_p * cos_theta * t49 * t175;
        let t180 = 1.0 / (t107 * t107 * t107);
        let t181 = -k_edge * hc_alpha * sin_theta * t27 * t28 * t116;
        let t182 = -mu * k_edge * cos_theta * t27 * t31 * t34 * t40;
        let t183 = mu * k_edge * cos_theta * t27 * t31 * t40 * t41 * t141;
        let t184 = -mu * k_wall * t52 * t55 * t59 * t64;
        let t185 = mu * k_wall * t52 * t55 * t59 * t66 * t177;
        let t186 = k_edge * hc_alpha * sin_theta * t70 * t78 * t123;
        let t187 = -mu * k_edge * cos_theta * t78 * t81 * t84 * t90;
        let t188 = mu * k_edge * cos_theta * t78 * t81 * t90 * t91 * t151;
        let t189 = -mu * k_wall * t97 * t100 * t105 * t108;
        let t190 = mu * k_wall * t97 * t100 * t105 * t110 * t180;
        let t191 = 1.5 * k_wall * t59 * t65 * t119 - 1.5 * k_wall * t65 * t119;
        let t192 = t126 + t127;
        let t193 = t14 * t14;
        let t194 = sin_theta * t44 + t101;
        let t195 = t194 * t194;
        let t196 = thetadot * k_wall * hc_alpha * t55 * t143 * t144
            + 1.5 * k_wall * t56 * t59 * t65 * t119 - 1.5 * k_wall * t56 * t65 * t119;
        let t197 = t70 * t70;
        let t198 = t102 * t102;
        let t199 = t152 + t155 + t156;
        let t200 = t40 * t40;
        let t201 = cos_theta * t51 + sin_theta * t47;
        let t202 = t201 * t201;
        let t203 = t90 * t90;
        let t204 = cos_theta * t96 + sin_theta * t95;
        let t205 = t204 * t204;
        let t206 = t25 * t25 * t25;
        let t207 = 2.0 * sin_theta * t19 + 2.0 * cos_theta * t24;
        let t208 = t53 * t53 * t53;
        let t209 = 2.0 * zdot;
        let t210 = t209 + 2.0 * thetadot * t52;
        let t211 = t76 * t76 * t76;
        let t212 = 2.0 * sin_theta * t72 + 2.0 * cos_theta * t75;
        let t213 = t98 * t98 * t98;
        let t214 = t209 + 2.0 * thetadot * t97;
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
                t111
                    * (-(1.5 * k_edge * t113 * t114 * t115) + cos_theta * t117
                        + 1.5 * mu * k_edge * sin_theta * cos_theta * t25 * t31 * t34
                            * t35 * t113
                        - thetadot * mu * k_edge * hc_alpha * t25 * t27 * t34 * t116
                            * t118 + 1.5 * k_wall * t65 * t119
                        - 1.5 * k_wall * t119 * t120 - 1.5 * k_wall * t59 * t65 * t119
                        - 1.5 * k_edge * t114 * t121 * t122 - cos_theta * t124
                        - 1.5 * mu * k_edge * sin_theta * cos_theta * t76 * t81 * t84
                            * t85 * t121
                        + thetadot * mu * k_edge * hc_alpha * t76 * t78 * t84 * t118
                            * t123 + t126 + t127 - 1.5 * k_wall * t125 * t128),
                t111
                    * (t129 + cos_theta * t130
                        - 1.5 * mu * k_edge * t25 * t31 * t34 * t35 * t113 * t118 + t131
                        + t132 - cos_theta * t133
                        + 1.5 * mu * k_edge * t76 * t81 * t84 * t85 * t118 * t121
                        + t134),
                t111
                    * (t0 + t1 + t38 + t39
                        - mu * k_edge * cos_theta * t25 * t27 * t31 * t34 + t88 + t89
                        - mu * k_edge * cos_theta * t76 * t78 * t81 * t84 + t135
                        + cos_theta * t137
                        - mu * k_edge * sin_theta * t27 * t31 * t34 * t140
                        - 1.5 * mu * k_edge * sin_theta * t25 * t28 * t31 * t34 * t35
                            * t113
                        - mu * k_edge * hc_alpha * sin_theta * t25 * t27 * t34 * t116
                            * t136
                        + mu * k_edge * sin_theta * t27 * t31 * t41 * t140 * t141
                        + 1.5 * k_wall * t56 * t65 * t119 + t142
                        - 1.5 * k_wall * t56 * t59 * t65 * t119
                        - thetadot * k_wall * hc_alpha * t55 * t143 * t144 + t145
                        - cos_theta * t147
                        - mu * k_edge * sin_theta * t78 * t81 * t84 * t150
                        - 1.5 * mu * k_edge * sin_theta * t70 * t76 * t81 * t84 * t85
                            * t121
                        - mu * k_edge * hc_alpha * sin_theta * t76 * t78 * t84 * t123
                            * t146
                        + mu * k_edge * sin_theta * t78 * t81 * t91 * t150 * t151 + t152
                        + t155 + t156 + t157),
                t111
                    * (-(k_edge * hc_alpha * t27 * t114 * t116)
                        - mu * k_edge * t27 * t31 * t34 * t118
                        + mu * k_edge * hc_alpha * sin_theta * cos_theta * t25 * t27
                            * t34 * t116 + mu * k_edge * t27 * t31 * t41 * t118 * t141
                        - k_wall * hc_alpha * t55 * t144
                        - k_edge * hc_alpha * t78 * t114 * t123
                        - mu * k_edge * t78 * t81 * t84 * t118
                        - mu * k_edge * hc_alpha * sin_theta * cos_theta * t76 * t78
                            * t84 * t123 + mu * k_edge * t78 * t81 * t91 * t118 * t151
                        - k_wall * hc_alpha * t100 * t154),
                t111
                    * (t158 + t159
                        - mu * k_edge * hc_alpha * t25 * t27 * t34 * t116 * t118 + t160
                        + t161 + t162
                        + mu * k_edge * hc_alpha * t76 * t78 * t84 * t118 * t123 + t163),
                t111
                    * (t164 + t165
                        - mu * k_edge * hc_alpha * sin_theta * t25 * t27 * t28 * t34
                            * t116 + t166 + t167 + t168 + t169
                        - mu * k_edge * hc_alpha * sin_theta * t70 * t76 * t78 * t84
                            * t123 + t170 + t171),
                0.0,
                0.0,
                t111
                    * (t129 + t131 + t132 + t134 - sin_theta * t117
                        + 1.5 * mu * k_edge * t25 * t31 * t34 * t35 * t113 * t114
                        - 1.5 * mu * k_wall * t53 * t59 * t64 * t65 * t119
                        + sin_theta * t124
                        - 1.5 * mu * k_edge * t76 * t81 * t84 * t85 * t114 * t121
                        + 1.5 * mu * k_wall * t98 * t105 * t108 * t109 * t125),
                t111
                    * (-(1.5 * k_edge * t113 * t115 * t118) - sin_theta * t130
                        - 1.5 * mu * k_edge * sin_theta * cos_theta * t25 * t31 * t34
                            * t35 * t113
                        - thetadot * mu * k_edge * hc_alpha * t25 * t27 * t34 * t114
                            * t116 - 1.5 * k_edge * t118 * t121 * t122 + sin_theta * t133
                        + 1.5 * mu * k_edge * sin_theta * cos_theta * t76 * t81 * t84
                            * t85 * t121
                        + thetadot * mu * k_edge * hc_alpha * t76 * t78 * t84 * t114
                            * t123),
                t111
                    * (t36 + t37 + mu * k_edge * sin_theta * t25 * t27 * t31 * t34 + t86
                        + t87 + mu * k_edge * sin_theta * t76 * t78 * t81 * t84 + t172
                        + t173 + t174 - sin_theta * t137
                        - mu * k_edge * cos_theta * t27 * t31 * t34 * t140
                        - 1.5 * mu * k_edge * cos_theta * t25 * t28 * t31 * t34 * t35
                            * t113
                        - mu * k_edge * hc_alpha * cos_theta * t25 * t27 * t34 * t116
                            * t136
                        + mu * k_edge * cos_theta * t27 * t31 * t41 * t140 * t141
                        - thetadot * mu * k_wall * t55 * t59 * t64 * t176
                        - 1.5 * mu * k_wall * t53 * t56 * t59 * t64 * t65 * t119
                        - thetadot * mu * k_wall * hc_alpha * t53 * t55 * t64 * t143
                            * t144
                        + thetadot * mu * k_wall * t55 * t59 * t66 * t176 * t177 + t178
                        + sin_theta * t147
                        - mu * k_edge * cos_theta * t78 * t81 * t84 * t150
                        - 1.5 * mu * k_edge * cos_theta * t70 * t76 * t81 * t84 * t85
                            * t121
                        - mu * k_edge * hc_alpha * cos_theta * t76 * t78 * t84 * t123
                            * t146
                        + mu * k_edge * cos_theta * t78 * t81 * t91 * t150 * t151
                        - thetadot * mu * k_wall * t100 * t105 * t108 * t179
                        - 1.5 * mu * k_wall * t98 * t102 * t105 * t108 * t109 * t125
                        - thetadot * mu * k_wall * hc_alpha * t98 * t100 * t108 * t153
                            * t154
                        + thetadot * mu * k_wall * t100 * t105 * t110 * t179 * t180),
                t111
                    * (t158 + t159 + t160 + t161 + t162 + t163
                        + mu * k_edge * hc_alpha * t25 * t27 * t34 * t114 * t116
                        - mu * k_wall * hc_alpha * t53 * t55 * t64 * t144
                        - mu * k_edge * hc_alpha * t76 * t78 * t84 * t114 * t123
                        + mu * k_wall * hc_alpha * t98 * t100 * t108 * t154),
                t111
                    * (mu * k_edge * hc_alpha * sin_theta * cos_theta * t76 * t78 * t84
                        * t123 - k_edge * hc_alpha * t27 * t116 * t118
                        - mu * k_edge * t27 * t31 * t34 * t114
                        - mu * k_edge * hc_alpha * sin_theta * cos_theta * t25 * t27
                            * t34 * t116 + mu * k_edge * t27 * t31 * t41 * t114 * t141
                        - mu * k_wall * t55 * t59 * t64
                        + mu * k_wall * t55 * t59 * t66 * t177
                        - k_edge * hc_alpha * t78 * t118 * t123
                        - mu * k_edge * t78 * t81 * t84 * t114
                        + mu * k_edge * t78 * t81 * t91 * t114 * t151
                        - mu * k_wall * t100 * t105 * t108
                        + mu * k_wall * t100 * t105 * t110 * t180),
                t111
                    * (t181 + t182
                        - mu * k_edge * hc_alpha * cos_theta * t25 * t27 * t28 * t34
                            * t116 + t183 + t184
                        - mu * k_wall * hc_alpha * t53 * t55 * t56 * t64 * t144 + t185
                        + t186 + t187
                        - mu * k_edge * hc_alpha * cos_theta * t70 * t76 * t78 * t84
                            * t123 + t188 + t189
                        - mu * k_wall * hc_alpha * t98 * t100 * t102 * t108 * t154
                        + t190),
                0.0,
                0.0,
                t112
                    * (t38 + t39 + t88 + t89 + t135 + t142 + t145 + t157 - t28 * t117
                        + 1.5 * mu * k_edge * cos_theta * t25 * t31 * t34 * t35 * t40
                            * t113
                        - thetadot * mu * k_edge * hc_alpha * sin_theta * t25 * t27 * t34
                            * t40 * t116 - t56 * t191
                        - 1.5 * mu * k_wall * t52 * t53 * t59 * t64 * t65 * t119
                        - t70 * t124
                        - 1.5 * mu * k_edge * cos_theta * t76 * t81 * t84 * t85 * t90
                            * t121
                        + thetadot * mu * k_edge * hc_alpha * sin_theta * t76 * t78 * t84
                            * t90 * t123 - t102 * t192
                        + 1.5 * mu * k_wall * t97 * t98 * t105 * t108 * t109 * t125),
                t112
                    * (t36 + t37 + t86 + t87 + t174 + t178 - t28 * t130
                        - 1.5 * mu * k_edge * sin_theta * t25 * t31 * t34 * t35 * t40
                            * t113
                        - thetadot * mu * k_edge * hc_alpha * cos_theta * t25 * t27 * t34
                            * t40 * t116 - t70 * t133
                        + 1.5 * mu * k_edge * sin_theta * t76 * t81 * t84 * t85 * t90
                            * t121
                        + thetadot * mu * k_edge * hc_alpha * cos_theta * t76 * t78 * t84
                            * t90 * t123),
                t112
                    * (-(1.5 * k_edge * t113 * t115 * t193) - k_edge * t11 * t27 * t35
                        - t11 * t32 - t28 * t137
                        - mu * k_edge * t27 * t31 * t34 * t40 * t140
                        - 1.5 * mu * k_edge * t25 * t28 * t31 * t34 * t35 * t40 * t113
                        - mu * k_edge * hc_alpha * t25 * t27 * t34 * t40 * t116 * t136
                        + mu * k_edge * t27 * t31 * t40 * t41 * t140 * t141
                        - mu * k_edge * t25 * t27 * t31 * t34
                            * (cos_theta * t18 + sin_theta * t138 - sin_theta * t23
                                + cos_theta * t139) - 1.5 * k_wall * t119 * t120 * t195
                        - k_wall * t55 * t65 * t143 - t62 * t143 - t56 * t196
                        - mu * k_wall * t53 * t55 * t59 * t64 * t176
                        - thetadot * mu * k_wall * t52 * t55 * t59 * t64 * t176
                        - 1.5 * mu * k_wall * t52 * t53 * t56 * t59 * t64 * t65 * t119
                        - thetadot * mu * k_wall * hc_alpha * t52 * t53 * t55 * t64
                            * t143 * t144
                        + thetadot * mu * k_wall * t52 * t55 * t59 * t66 * t176 * t177
                        - k_edge * t68 * t78 * t85 - 1.5 * k_edge * t121 * t122 * t197
                        - t68 * t82 - t70 * t147
                        - mu * k_edge * t78 * t81 * t84 * t90 * t150
                        - 1.5 * mu * k_edge * t70 * t76 * t81 * t84 * t85 * t90 * t121
                        - mu * k_edge * hc_alpha * t76 * t78 * t84 * t90 * t123 * t146
                        + mu * k_edge * t78 * t81 * t90 * t91 * t150 * t151
                        - mu * k_edge * t76 * t78 * t81 * t84
                            * (cos_theta * t71 + sin_theta * t148 - sin_theta * t74
                                + cos_theta * t149) - 1.5 * k_wall * t125 * t128 * t198
                        - k_wall * t100 * t109 * t153 - t106 * t153 - t102 * t199
                        - mu * k_wall * t98 * t100 * t105 * t108 * t179
                        - thetadot * mu * k_wall * t97 * t100 * t105 * t108 * t179
                        - 1.5 * mu * k_wall * t97 * t98 * t102 * t105 * t108 * t109
                            * t125
                        - thetadot * mu * k_wall * hc_alpha * t97 * t98 * t100 * t108
                            * t153 * t154
                        + thetadot * mu * k_wall * t97 * t100 * t105 * t110 * t179
                            * t180),
                t112
                    * (t164 + t165 + t166 + t167 + t168 + t169 + t170 + t171
                        + mu * k_edge * hc_alpha * cos_theta * t25 * t27 * t34 * t40
                            * t116
                        - mu * k_wall * hc_alpha * t52 * t53 * t55 * t64 * t144
                        - mu * k_edge * hc_alpha * cos_theta * t76 * t78 * t84 * t90
                            * t123
                        + mu * k_wall * hc_alpha * t97 * t98 * t100 * t108 * t154),
                t112
                    * (t181 + t182 + t183 + t184 + t185 + t186 + t187 + t188 + t189
                        + t190
                        - mu * k_edge * hc_alpha * sin_theta * t25 * t27 * t34 * t40
                            * t116
                        + mu * k_edge * hc_alpha * sin_theta * t76 * t78 * t84 * t90
                            * t123),
                t112
                    * (-(k_edge * hc_alpha * t27 * t116 * t193)
                        - mu * k_edge * t27 * t31 * t34 * t200
                        - mu * k_edge * hc_alpha * t25 * t27 * t28 * t34 * t40 * t116
                        + mu * k_edge * t27 * t31 * t41 * t141 * t200
                        - k_wall * hc_alpha * t55 * t144 * t195
                        - mu * k_wall * t55 * t59 * t64 * t202
                        - mu * k_wall * hc_alpha * t52 * t53 * t55 * t56 * t64 * t144
                        + mu * k_wall * t55 * t59 * t66 * t177 * t202
                        - k_edge * hc_alpha * t78 * t123 * t197
                        - mu * k_edge * t78 * t81 * t84 * t203
                        - mu * k_edge * hc_alpha * t70 * t76 * t78 * t84 * t90 * t123
                        + mu * k_edge * t78 * t81 * t91 * t151 * t203
                        - k_wall * hc_alpha * t100 * t154 * t198
                        - mu * k_wall * t100 * t105 * t108 * t205
                        - mu * k_wall * hc_alpha * t97 * t98 * t100 * t102 * t108 * t154
                        + mu * k_wall * t100 * t105 * t110 * t180 * t205),
                0.0,
                0.0,
                0.0,
                0.0,
                xdot * t2 + zdot * (t172 + t173),
                f1 * sin_theta + f2 * cos_theta,
                t2,
                m_2,
                0.0,
                0.0,
                -(1.5 * mu * k_edge * cos_theta * t31 * t34 * t35 * t41 * t113)
                    + thetadot * mu * k_edge * hc_alpha * sin_theta * t27 * t34 * t41
                        * t116 + thetadot * sin_theta * t32 + t29 * t117
                    + 1.5 * mu * k_wall * t59 * t64 * t65 * t66 * t119 + t57 * t191
                    + 1.5 * mu * k_edge * cos_theta * t81 * t84 * t85 * t91 * t121
                    - thetadot * mu * k_edge * hc_alpha * sin_theta * t78 * t84 * t91
                        * t123 - thetadot * sin_theta * t82 + t79 * t124
                    - 1.5 * mu * k_wall * t105 * t108 * t109 * t110 * t125 + t103 * t192,
                1.5 * mu * k_edge * sin_theta * t31 * t34 * t35 * t41 * t113
                    + thetadot * mu * k_edge * hc_alpha * cos_theta * t27 * t34 * t41
                        * t116 + thetadot * cos_theta * t32 + t29 * t130
                    - 1.5 * mu * k_edge * sin_theta * t81 * t84 * t85 * t91 * t121
                    - thetadot * mu * k_edge * hc_alpha * cos_theta * t78 * t84 * t91
                        * t123 - thetadot * cos_theta * t82 + t79 * t133,
                1.5 * mu * k_edge * t28 * t31 * t34 * t35 * t41 * t113
                    + mu * k_edge * hc_alpha * t27 * t34 * t41 * t116 * t136
                    - mu * k_edge * t27 * t31 * t140 * t141 * t206
                    + mu * k_edge * t27 * t31 * t34 * t140 * t207 + t32 * t136
                    + t29 * t137 + 1.5 * mu * k_wall * t56 * t59 * t64 * t65 * t66 * t119
                    + thetadot * mu * k_wall * hc_alpha * t55 * t64 * t66 * t143 * t144
                    - thetadot * mu * k_wall * t55 * t59 * t176 * t177 * t208
                    + thetadot * mu * k_wall * t55 * t59 * t64 * t176 * t210
                    + thetadot * t62 * t143 + t57 * t196
                    + 1.5 * mu * k_edge * t70 * t81 * t84 * t85 * t91 * t121
                    + mu * k_edge * hc_alpha * t78 * t84 * t91 * t123 * t146
                    - mu * k_edge * t78 * t81 * t150 * t151 * t211
                    + mu * k_edge * t78 * t81 * t84 * t150 * t212 + t82 * t146
                    + t79 * t147
                    + 1.5 * mu * k_wall * t102 * t105 * t108 * t109 * t110 * t125
                    + thetadot * mu * k_wall * hc_alpha * t100 * t108 * t110 * t153
                        * t154
                    - thetadot * mu * k_wall * t100 * t105 * t179 * t180 * t213
                    + thetadot * mu * k_wall * t100 * t105 * t108 * t179 * t214
                    + thetadot * t106 * t153 + t103 * t199,
                t37 + t60 + t61 + t87 + k_wall * t100 - k_wall * t100 * t105
                    - mu * k_edge * hc_alpha * cos_theta * t27 * t34 * t41 * t116
                    - mu * k_edge * sin_theta * t27 * t31 * t141 * t206
                    + mu * k_edge * sin_theta * t27 * t31 * t34 * t207
                    - k_edge * hc_alpha * cos_theta * t27 * t29 * t116
                    + mu * k_wall * hc_alpha * t55 * t64 * t66 * t144
                    + k_wall * hc_alpha * t55 * t57 * t144
                    + mu * k_edge * hc_alpha * cos_theta * t78 * t84 * t91 * t123
                    - mu * k_edge * sin_theta * t78 * t81 * t151 * t211
                    + mu * k_edge * sin_theta * t78 * t81 * t84 * t212
                    + k_edge * hc_alpha * cos_theta * t78 * t79 * t123
                    - mu * k_wall * hc_alpha * t100 * t108 * t110 * t154
                    - k_wall * hc_alpha * t100 * t103 * t154,
                sin_theta * t32 - sin_theta * t82
                    + mu * k_edge * hc_alpha * sin_theta * t27 * t34 * t41 * t116
                    - mu * k_edge * cos_theta * t27 * t31 * t141 * t206
                    + mu * k_edge * cos_theta * t27 * t31 * t34 * t207
                    + k_edge * hc_alpha * sin_theta * t27 * t29 * t116
                    - mu * k_wall * t55 * t59 * t177 * t208
                    + mu * k_wall * t55 * t59 * t64 * t210
                    - mu * k_edge * hc_alpha * sin_theta * t78 * t84 * t91 * t123
                    - mu * k_edge * cos_theta * t78 * t81 * t151 * t211
                    + mu * k_edge * cos_theta * t78 * t81 * t84 * t212
                    - k_edge * hc_alpha * sin_theta * t78 * t79 * t123
                    - mu * k_wall * t100 * t105 * t180 * t213
                    + mu * k_wall * t100 * t105 * t108 * t214,
                t28 * t32 + t56 * t62 + t70 * t82 + t102 * t106
                    + mu * k_edge * hc_alpha * t27 * t28 * t34 * t41 * t116
                    - mu * k_edge * t27 * t31 * t40 * t141 * t206
                    + mu * k_edge * t27 * t31 * t34 * t40 * t207
                    + k_edge * hc_alpha * t27 * t28 * t29 * t116
                    + mu * k_wall * hc_alpha * t55 * t56 * t64 * t66 * t144
                    - mu * k_wall * t52 * t55 * t59 * t177 * t208
                    + mu * k_wall * t52 * t55 * t59 * t64 * t210
                    + k_wall * hc_alpha * t55 * t56 * t57 * t144
                    + mu * k_edge * hc_alpha * t70 * t78 * t84 * t91 * t123
                    - mu * k_edge * t78 * t81 * t90 * t151 * t211
                    + mu * k_edge * t78 * t81 * t84 * t90 * t212
                    + k_edge * hc_alpha * t70 * t78 * t79 * t123
                    + mu * k_wall * hc_alpha * t100 * t102 * t108 * t110 * t154
                    - mu * k_wall * t97 * t100 * t105 * t180 * t213
                    + mu * k_wall * t97 * t100 * t105 * t108 * t214
                    + k_wall * hc_alpha * t100 * t102 * t103 * t154,
                0.0,
                0.0,
            ],
        )
    }
    /// Per contact (edge_left, wall_right, edge_right, wall_left): normal force f (N), friction force along the tangent (N), penetration delta (m), sliding velocity (m/s), contact ellipse a, b (m) and maximum pressure p0 (Pa) ((9)-(11)).
    ///
    /// # Inputs
    /// - `y` = (`x`, `z`, `theta`, `xdot`, `zdot`, `thetadot`, `work`, `dissipation`)
    /// - `p` = (`m`, `J`, `r`, `l_c`, `D`, `rho_p`, `rho_h`, `mu`, `v_s`, `k_edge`, `k_wall`, `f1`, `f2`, `M`, `e_star`, `edge_sum`, `edge_ma`, `edge_mb`, `edge_dstar`, `wall_sum`, `wall_ma`, `wall_mb`, `wall_dstar`, `hc_alpha`)
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
    /// 57 add/sub, 147 mul, 11 div, 4 sqrt, 17 transcendental, 8 branches; 62 `let`s.
    #[inline]
    pub fn contacts(
        y: &SVector<f64, 8>,
        p: &SVector<f64, 24>,
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
        let hc_alpha = p[23];
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
        let t11 = 1.0
            + hc_alpha
                * (-(xdot * cos_theta) + zdot * sin_theta
                    + thetadot * (-(sin_theta * t2) - cos_theta * t3));
        let t12 = if t11 > 0.0 || t11.is_nan() { t11 } else { 0.0 };
        let t13 = v_s.hypot(t8);
        let t14 = 1.0 / e_star;
        let t15 = 1.0 / edge_sum;
        let t16 = (1.5 * k_edge * t10 * t12 * t14 * t15).powf(0.3333333333333333);
        let t17 = (1.5 * k_edge * t10 * t12).powf(0.3333333333333333);
        let t18 = (e_star * edge_sum).powf(0.6666666666666666);
        let t19 = 1.0 / edge_ma;
        let t20 = 1.0 / edge_mb;
        let t21 = -rho_p;
        let t22 = l_c + t21;
        let t23 = r + t21;
        let t24 = x + rho_p + t0 + sin_theta * t22 + cos_theta * t23;
        let t25 = (0.5 * theta).sin();
        let t26 = t25 * t25;
        let t27 = zdot
            + thetadot
                * (-(sin_theta * (l_c + t21 + rho_p * sin_theta))
                    - cos_theta * (r - 2.0 * rho_p * t26));
        let t28 = if t24 > 0.0 || t24.is_nan() { t24 } else { 0.0 };
        let t29 = t28 * t28.sqrt();
        let t30 = 1.0
            + hc_alpha * (xdot + thetadot * (cos_theta * t22 - sin_theta * t23));
        let t31 = if t30 > 0.0 || t30.is_nan() { t30 } else { 0.0 };
        let t32 = v_s.hypot(t27);
        let t33 = 1.0 / wall_sum;
        let t34 = (1.5 * k_wall * t14 * t29 * t31 * t33).powf(0.3333333333333333);
        let t35 = (1.5 * k_wall * t29 * t31).powf(0.3333333333333333);
        let t36 = (e_star * wall_sum).powf(0.6666666666666666);
        let t37 = 1.0 / wall_ma;
        let t38 = 1.0 / wall_mb;
        let t39 = rho_h + 0.5 * d + t1;
        let t40 = r + rho_h + sin_theta * t3 - cos_theta * t39;
        let t41 = t5 + sin_theta * t39;
        let t42 = sin_theta * (xdot + thetadot * (-(r * sin_theta) + cos_theta * t41))
            + cos_theta * (zdot + thetadot * (-(r * cos_theta) - sin_theta * t41));
        let t43 = if t40 > 0.0 || t40.is_nan() { t40 } else { 0.0 };
        let t44 = t43 * t43.sqrt();
        let t45 = 1.0
            + hc_alpha * (xdot * cos_theta - zdot * sin_theta + thetadot * t41);
        let t46 = if t45 > 0.0 || t45.is_nan() { t45 } else { 0.0 };
        let t47 = v_s.hypot(t42);
        let t48 = (1.5 * k_edge * t14 * t15 * t44 * t46).powf(0.3333333333333333);
        let t49 = (1.5 * k_edge * t44 * t46).powf(0.3333333333333333);
        let t50 = rho_p + t7;
        let t51 = rho_p + t0 + t1 - sin_theta * t22 - cos_theta * t50;
        let t52 = zdot
            + thetadot
                * (-(sin_theta * (l_c + t21 - rho_p * sin_theta))
                    - cos_theta * (t7 + 2.0 * rho_p * t26));
        let t53 = if t51 > 0.0 || t51.is_nan() { t51 } else { 0.0 };
        let t54 = t53 * t53.sqrt();
        let t55 = 1.0
            + hc_alpha * (-xdot + thetadot * (-(cos_theta * t22) + sin_theta * t50));
        let t56 = if t55 > 0.0 || t55.is_nan() { t55 } else { 0.0 };
        let t57 = v_s.hypot(t52);
        let t58 = (1.5 * k_wall * t14 * t33 * t54 * t56).powf(0.3333333333333333);
        let t59 = (1.5 * k_wall * t54 * t56).powf(0.3333333333333333);
        let normal = Vector4::new(
            k_edge * t10 * t12,
            k_wall * t29 * t31,
            k_edge * t44 * t46,
            k_wall * t54 * t56,
        );
        let friction = Vector4::new(
            -mu * k_edge * t8 * t10 * t12 / t13,
            -mu * k_wall * t27 * t29 * t31 / t32,
            -mu * k_edge * t42 * t44 * t46 / t47,
            -mu * k_wall * t52 * t54 * t56 / t57,
        );
        let delta = Vector4::new(t4, t24, t40, t51);
        let slip = Vector4::new(t8, t27, t42, t52);
        let a = Vector4::new(edge_ma * t16, wall_ma * t34, edge_ma * t48, wall_ma * t58);
        let b = Vector4::new(edge_mb * t16, wall_mb * t34, edge_mb * t48, wall_mb * t58);
        let p0 = Vector4::new(
            0.3183098861837907 * t17 * t18 * t19 * t20,
            0.3183098861837907 * t35 * t36 * t37 * t38,
            0.3183098861837907 * t18 * t19 * t20 * t49,
            0.3183098861837907 * t36 * t37 * t38 * t59,
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
    /// 28 add/sub, 26 mul, 0 div, 0 sqrt, 6 transcendental, 4 branches; 19 `let`s.
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
