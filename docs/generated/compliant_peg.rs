// @generated readable copy of `pegdyn::generated::compliant_peg` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generated_snapshot

/// Planar compliant peg-in-hole (paper 001, (31)-(51), (55)-(64)) with contacts edge_left, wall_right, edge_right, wall_left. Inputs: state y (see STATE) and parameters p (see P_NAMES). SI units.
pub mod compliant_peg {
    use nalgebra::{SMatrix, SVector, Vector4};
    use pegdyn::scalar::Real;
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
    /// 113 add/sub, 227 mul, 6 div, 4 sqrt, 6 transcendental, 16 branches; 78 `let`s.
    #[inline]
    pub fn rhs<T: Real>(y: &SVector<T, 8>, p: &SVector<T, 24>) -> SVector<T, 8> {
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
        let (sin_theta, cos_theta) = theta.sin_cos();
        let t0 = f1 * sin_theta;
        let t1 = f2 * cos_theta;
        let t2 = f1 * cos_theta;
        let t3 = -f2 * sin_theta;
        let t4 = -T::from_f64(0.5) * d;
        let t5 = -x;
        let t6 = -rho_h + t4 + t5;
        let t7 = rho_h - z;
        let t8 = T::from_f64(0.5) * theta;
        let (t9, t21) = t8.sin_cos();
        let t10 = t9 * t9;
        let t11 = r + t4 + t5 - sin_theta * t7 - T::from_f64(2.0) * t6 * t10;
        let t12 = cos_theta * t7;
        let t13 = sin_theta * t6 + t12;
        let t14 = -r;
        let t15 = cos_theta * t13 + r * sin_theta;
        let t16 = -(sin_theta * t13) + r * cos_theta;
        let t17 = sin_theta * (xdot + thetadot * t15)
            + cos_theta * (zdot + thetadot * t16);
        let t18 = t11.max0();
        let t19 = t18 * t18.sqrt();
        let t20 = -T::from_f64(1.0) + T::from_f64(2.0) * t10;
        let t22 = -(cos_theta * t7) - T::from_f64(2.0) * t6 * t9 * t21;
        let t23 = xdot * t20 + zdot * sin_theta + thetadot * t22;
        let t24 = (T::from_f64(1.0) + hc_alpha * t23).max0();
        let t25 = k_edge * t19 * (t24 - T::from_f64(1.0));
        let t26 = v_s.hypot(t17);
        let t27 = T::from_f64(1.0) / t26;
        let t28 = t11.step();
        let t29 = -rho_p;
        let t30 = l_c + t29;
        let t31 = r + t29;
        let t32 = r + t4 + x + sin_theta * t30 - T::from_f64(2.0) * t10 * t31;
        let t33 = -(sin_theta * (l_c + t29 + rho_p * sin_theta))
            - cos_theta * (r - T::from_f64(2.0) * rho_p * t10);
        let t34 = zdot + thetadot * t33;
        let t35 = t32.max0();
        let t36 = t35 * t35.sqrt();
        let t37 = cos_theta * t30 - T::from_f64(2.0) * t9 * t21 * t31;
        let t38 = xdot + thetadot * t37;
        let t39 = (T::from_f64(1.0) + hc_alpha * t38).max0();
        let t40 = k_wall * t36 * (t39 - T::from_f64(1.0));
        let t41 = v_s.hypot(t34);
        let t42 = T::from_f64(1.0) / t41;
        let t43 = t32.step();
        let t44 = rho_h + T::from_f64(0.5) * d + t5;
        let t45 = r + t4 + x + sin_theta * t7 + T::from_f64(2.0) * t10 * t44;
        let t46 = t12 + sin_theta * t44;
        let t47 = -(r * sin_theta) + cos_theta * t46;
        let t48 = -(r * cos_theta) - sin_theta * t46;
        let t49 = sin_theta * (xdot + thetadot * t47)
            + cos_theta * (zdot + thetadot * t48);
        let t50 = t45.max0();
        let t51 = t50 * t50.sqrt();
        let t52 = T::from_f64(1.0) - T::from_f64(2.0) * t10;
        let t53 = t12 + T::from_f64(2.0) * t9 * t21 * t44;
        let t54 = xdot * t52 - zdot * sin_theta + thetadot * t53;
        let t55 = (T::from_f64(1.0) + hc_alpha * t54).max0();
        let t56 = k_edge * t51 * (t55 - T::from_f64(1.0));
        let t57 = v_s.hypot(t49);
        let t58 = T::from_f64(1.0) / t57;
        let t59 = t45.step();
        let t60 = rho_p + t14;
        let t61 = r + t4 + t5 - sin_theta * t30 + T::from_f64(2.0) * t10 * t60;
        let t62 = -(sin_theta * (l_c + t29 - rho_p * sin_theta))
            - cos_theta * (t14 + T::from_f64(2.0) * rho_p * t10);
        let t63 = zdot + thetadot * t62;
        let t64 = t61.max0();
        let t65 = t64 * t64.sqrt();
        let t66 = -(cos_theta * t30) + T::from_f64(2.0) * t9 * t21 * t60;
        let t67 = -xdot + thetadot * t66;
        let t68 = (T::from_f64(1.0) + hc_alpha * t67).max0();
        let t69 = k_wall * t65 * t68;
        let t70 = -k_wall * t65;
        let t71 = t69 + t70;
        let t72 = v_s.hypot(t63);
        let t73 = T::from_f64(1.0) / t72;
        let t74 = t61.step();
        let t75 = T::from_f64(1.0) / m;
        SMatrix::<
            T,
            8,
            1,
        >::from_row_slice(
            &[
                xdot,
                zdot,
                thetadot,
                (t0 + t1 - k_edge * t19 * t20 * t28 - t20 * t25
                    - mu * k_edge * sin_theta * t17 * t19 * t24 * t27 + k_wall * t36
                    - k_wall * t36 * t43 - k_wall * t36 * t39 - k_edge * t51 * t52 * t59
                    - t52 * t56 - mu * k_edge * sin_theta * t49 * t51 * t55 * t58 + t69
                    + t70 + k_wall * t65 * t74) * t75,
                (t2 + t3 - k_edge * sin_theta * t19 * t28 - sin_theta * t25
                    - mu * k_edge * cos_theta * t17 * t19 * t24 * t27
                    - mu * k_wall * t34 * t36 * t39 * t42
                    + k_edge * sin_theta * t51 * t59 + sin_theta * t56
                    - mu * k_edge * cos_theta * t49 * t51 * t55 * t58
                    - mu * k_wall * t63 * t65 * t68 * t73) * t75,
                (m_2 - k_edge * t19 * t22 * t28 - t22 * t25
                    - mu * k_edge * t17 * t19 * t24 * t27
                        * (sin_theta * t15 + cos_theta * t16) - k_wall * t36 * t37 * t43
                    - t37 * t40 - mu * k_wall * t33 * t34 * t36 * t39 * t42
                    - k_edge * t51 * t53 * t59 - t53 * t56
                    - mu * k_edge * t49 * t51 * t55 * t58
                        * (sin_theta * t47 + cos_theta * t48) - k_wall * t65 * t66 * t74
                    - t66 * t71 - mu * k_wall * t62 * t63 * t65 * t68 * t73) / j,
                xdot * (t0 + t1) + zdot * (t2 + t3) + thetadot * m_2,
                mu * k_edge * t19 * t24 * t27 * (t17 * t17) + t23 * t25
                    + mu * k_wall * t36 * t39 * t42 * (t34 * t34) + t38 * t40
                    + mu * k_edge * t51 * t55 * t58 * (t49 * t49) + t54 * t56
                    + mu * k_wall * t65 * t68 * t73 * (t63 * t63) + t67 * t71,
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
    /// 474 add/sub, 2058 mul, 10 div, 8 sqrt, 6 transcendental, 24 branches; 219 `let`s.
    #[inline]
    pub fn jacobian<T: Real>(y: &SVector<T, 8>, p: &SVector<T, 24>) -> SMatrix<T, 8, 8> {
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
        let (sin_theta, cos_theta) = theta.sin_cos();
        let t0 = f1 * cos_theta;
        let t1 = -f2 * sin_theta;
        let t2 = t0 + t1;
        let t3 = -T::from_f64(0.5) * d;
        let t4 = -x;
        let t5 = -rho_h + t3 + t4;
        let t6 = rho_h - z;
        let t7 = -sin_theta * t6;
        let t8 = sin_theta * t6;
        let t9 = cos_theta * t5 + t7;
        let t10 = T::from_f64(0.5) * theta;
        let (t11, t30) = t10.sin_cos();
        let t12 = t11 * t11;
        let t13 = r + t3 + t4 + t7 - T::from_f64(2.0) * t5 * t12;
        let t14 = cos_theta * t6;
        let t15 = sin_theta * t5 + t14;
        let t16 = -r;
        let t17 = -r * sin_theta;
        let t18 = r * sin_theta;
        let t19 = cos_theta * t15 + t18;
        let t20 = xdot + thetadot * t19;
        let t21 = -sin_theta * t15;
        let t22 = -r * cos_theta;
        let t23 = r * cos_theta;
        let t24 = t21 + t23;
        let t25 = zdot + thetadot * t24;
        let t26 = sin_theta * t20 + cos_theta * t25;
        let t27 = t13.max0();
        let t28 = t27 * t27.sqrt();
        let t29 = -T::from_f64(1.0) + T::from_f64(2.0) * t12;
        let t31 = -(cos_theta * t6) - T::from_f64(2.0) * t5 * t11 * t30;
        let t32 = xdot * t29 + zdot * sin_theta + thetadot * t31;
        let t33 = T::from_f64(1.0) + hc_alpha * t32;
        let t34 = t33.max0();
        let t35 = k_edge * t28 * (t34 - T::from_f64(1.0));
        let t36 = v_s.hypot(t26);
        let t37 = T::from_f64(1.0) / t36;
        let t38 = t13.step();
        let t39 = sin_theta * t19 + cos_theta * t24;
        let t40 = t26 * t26;
        let t41 = -rho_p;
        let t42 = l_c + t41;
        let t43 = r + t41;
        let t44 = sin_theta * t42;
        let t45 = r + t3 + x + t44 - T::from_f64(2.0) * t12 * t43;
        let t46 = l_c + t41 + rho_p * sin_theta;
        let t47 = r - T::from_f64(2.0) * rho_p * t12;
        let t48 = -(sin_theta * t46) - cos_theta * t47;
        let t49 = zdot + thetadot * t48;
        let t50 = t45.max0();
        let t51 = t50 * t50.sqrt();
        let t52 = cos_theta * t42 - T::from_f64(2.0) * t11 * t30 * t43;
        let t53 = xdot + thetadot * t52;
        let t54 = T::from_f64(1.0) + hc_alpha * t53;
        let t55 = t54.max0();
        let t56 = k_wall * t51 * t55;
        let t57 = -k_wall * t51;
        let t58 = t56 + t57;
        let t59 = v_s.hypot(t49);
        let t60 = T::from_f64(1.0) / t59;
        let t61 = t45.step();
        let t62 = t49 * t49;
        let t63 = rho_h + T::from_f64(0.5) * d + t4;
        let t64 = t7 + cos_theta * t63;
        let t65 = r + t3 + x + t8 + T::from_f64(2.0) * t12 * t63;
        let t66 = t14 + sin_theta * t63;
        let t67 = t17 + cos_theta * t66;
        let t68 = xdot + thetadot * t67;
        let t69 = -sin_theta * t66;
        let t70 = t22 + t69;
        let t71 = zdot + thetadot * t70;
        let t72 = sin_theta * t68 + cos_theta * t71;
        let t73 = t65.max0();
        let t74 = t73 * t73.sqrt();
        let t75 = T::from_f64(1.0) - T::from_f64(2.0) * t12;
        let t76 = t14 + T::from_f64(2.0) * t11 * t30 * t63;
        let t77 = xdot * t75 - zdot * sin_theta + thetadot * t76;
        let t78 = T::from_f64(1.0) + hc_alpha * t77;
        let t79 = t78.max0();
        let t80 = k_edge * t74 * (t79 - T::from_f64(1.0));
        let t81 = v_s.hypot(t72);
        let t82 = T::from_f64(1.0) / t81;
        let t83 = t65.step();
        let t84 = sin_theta * t67 + cos_theta * t70;
        let t85 = t72 * t72;
        let t86 = rho_p + t16;
        let t87 = -sin_theta * t42;
        let t88 = r + t3 + t4 + t87 + T::from_f64(2.0) * t12 * t86;
        let t89 = l_c + t41 - rho_p * sin_theta;
        let t90 = t16 + T::from_f64(2.0) * rho_p * t12;
        let t91 = -(sin_theta * t89) - cos_theta * t90;
        let t92 = zdot + thetadot * t91;
        let t93 = t88.max0();
        let t94 = t93 * t93.sqrt();
        let t95 = -(cos_theta * t42) + T::from_f64(2.0) * t11 * t30 * t86;
        let t96 = -xdot + thetadot * t95;
        let t97 = T::from_f64(1.0) + hc_alpha * t96;
        let t98 = t97.max0();
        let t99 = k_wall * t94 * (t98 - T::from_f64(1.0));
        let t100 = v_s.hypot(t92);
        let t101 = T::from_f64(1.0) / t100;
        let t102 = t88.step();
        let t103 = t92 * t92;
        let t104 = T::from_f64(1.0) / m;
        let t105 = T::from_f64(1.0) / j;
        let t106 = t27.sqrt();
        let t107 = t29 * t29;
        let t108 = t38 * t38;
        let t109 = t33.step();
        let t110 = k_edge
            * (T::from_f64(1.5) * t29 * t34 * t38 * t106
                + T::from_f64(2.0) * thetadot * hc_alpha * t11 * t28 * t30 * t109
                - T::from_f64(1.5) * t29 * t38 * t106);
        let t111 = sin_theta * sin_theta;
        let t112 = t50.sqrt();
        let t113 = t61 * t61;
        let t114 = t73.sqrt();
        let t115 = t75 * t75;
        let t116 = t83 * t83;
        let t117 = t78.step();
        let t118 = k_edge
            * (T::from_f64(1.5) * t75 * t79 * t83 * t114
                - T::from_f64(2.0) * thetadot * hc_alpha * t11 * t30 * t74 * t117
                - T::from_f64(1.5) * t75 * t83 * t114);
        let t119 = t93.sqrt();
        let t120 = -T::from_f64(1.5) * k_wall * t98 * t102 * t119;
        let t121 = T::from_f64(1.5) * k_wall * t102 * t119;
        let t122 = t102 * t102;
        let t123 = -T::from_f64(1.5) * k_edge * sin_theta * t29 * t106 * t108;
        let t124 = k_edge
            * (T::from_f64(1.5) * sin_theta * t34 * t38 * t106
                + thetadot * hc_alpha * cos_theta * t28 * t109
                - T::from_f64(1.5) * sin_theta * t38 * t106);
        let t125 = cos_theta * cos_theta;
        let t126 = T::from_f64(1.5) * k_edge * sin_theta * t75 * t114 * t116;
        let t127 = k_edge
            * (-(T::from_f64(1.5) * sin_theta * t79 * t83 * t114)
                - thetadot * hc_alpha * cos_theta * t74 * t117
                + T::from_f64(1.5) * sin_theta * t83 * t114);
        let t128 = -T::from_f64(1.5) * k_edge * t29 * t31 * t106 * t108;
        let t129 = -T::from_f64(2.0) * k_edge * t11 * t28 * t30 * t38;
        let t130 = -T::from_f64(2.0) * t11 * t30 * t35;
        let t131 = t30 * t30;
        let t132 = t8 + t5 * t12 - t5 * t131;
        let t133 = T::from_f64(2.0) * xdot * t11 * t30 + zdot * cos_theta
            + thetadot * t132;
        let t134 = k_edge
            * (T::from_f64(1.5) * t31 * t34 * t38 * t106 + hc_alpha * t28 * t109 * t133
                - T::from_f64(1.5) * t31 * t38 * t106);
        let t135 = t21 + t23 + cos_theta * t9;
        let t136 = t17 - cos_theta * t15 - sin_theta * t9;
        let t137 = cos_theta * t20 + thetadot * sin_theta * t135 - sin_theta * t25
            + thetadot * cos_theta * t136;
        let t138 = T::from_f64(1.0) / (t36 * t36 * t36);
        let t139 = -T::from_f64(1.5) * k_wall * t52 * t112 * t113;
        let t140 = t12 * t43 + t87 - t43 * t131;
        let t141 = t54.step();
        let t142 = -T::from_f64(1.5) * k_edge * t75 * t76 * t114 * t116;
        let t143 = T::from_f64(2.0) * k_edge * t11 * t30 * t74 * t83;
        let t144 = T::from_f64(2.0) * t11 * t30 * t80;
        let t145 = t7 + t63 * t131 - t12 * t63;
        let t146 = -(T::from_f64(2.0) * xdot * t11 * t30) - zdot * cos_theta
            + thetadot * t145;
        let t147 = k_edge
            * (T::from_f64(1.5) * t76 * t79 * t83 * t114 + hc_alpha * t74 * t117 * t146
                - T::from_f64(1.5) * t76 * t83 * t114);
        let t148 = t22 + t69 + cos_theta * t64;
        let t149 = t18 - cos_theta * t66 - sin_theta * t64;
        let t150 = cos_theta * t68 + thetadot * sin_theta * t148 - sin_theta * t71
            + thetadot * cos_theta * t149;
        let t151 = T::from_f64(1.0) / (t81 * t81 * t81);
        let t152 = T::from_f64(1.5) * k_wall * t95 * t98 * t102 * t119;
        let t153 = t44 + t86 * t131 - t12 * t86;
        let t154 = t97.step();
        let t155 = thetadot * k_wall * hc_alpha * t94 * t153 * t154;
        let t156 = -T::from_f64(1.5) * k_wall * t95 * t102 * t119;
        let t157 = T::from_f64(1.5) * k_wall * t95 * t119 * t122;
        let t158 = -k_edge * hc_alpha * sin_theta * t28 * t29 * t109;
        let t159 = -mu * k_edge * sin_theta * cos_theta * t28 * t34 * t37;
        let t160 = mu * k_edge * sin_theta * cos_theta * t28 * t34 * t40 * t138;
        let t161 = k_edge * hc_alpha * sin_theta * t74 * t75 * t117;
        let t162 = -mu * k_edge * sin_theta * cos_theta * t74 * t79 * t82;
        let t163 = mu * k_edge * sin_theta * cos_theta * t74 * t79 * t85 * t151;
        let t164 = -k_edge * hc_alpha * t28 * t29 * t31 * t109;
        let t165 = -mu * k_edge * sin_theta * t28 * t34 * t37 * t39;
        let t166 = mu * k_edge * sin_theta * t28 * t34 * t39 * t40 * t138;
        let t167 = -k_wall * hc_alpha * t51 * t52 * t141;
        let t168 = -k_edge * hc_alpha * t74 * t75 * t76 * t117;
        let t169 = -mu * k_edge * sin_theta * t74 * t79 * t82 * t84;
        let t170 = mu * k_edge * sin_theta * t74 * t79 * t84 * t85 * t151;
        let t171 = k_wall * hc_alpha * t94 * t95 * t154;
        let t172 = -f1 * sin_theta;
        let t173 = -f2 * cos_theta;
        let t174 = -k_edge * cos_theta * t28 * t38;
        let t175 = -T::from_f64(1.5) * k_edge * sin_theta * t31 * t106 * t108;
        let t176 = -cos_theta * t35;
        let t177 = sin_theta * t47 - cos_theta * t46 - rho_p * sin_theta * cos_theta
            + T::from_f64(2.0) * rho_p * cos_theta * t11 * t30;
        let t178 = T::from_f64(1.0) / (t59 * t59 * t59);
        let t179 = k_edge * cos_theta * t74 * t83;
        let t180 = T::from_f64(1.5) * k_edge * sin_theta * t76 * t114 * t116;
        let t181 = cos_theta * t80;
        let t182 = sin_theta * t90 + rho_p * sin_theta * cos_theta - cos_theta * t89
            - T::from_f64(2.0) * rho_p * cos_theta * t11 * t30;
        let t183 = T::from_f64(1.0) / (t100 * t100 * t100);
        let t184 = -k_edge * hc_alpha * sin_theta * t28 * t31 * t109;
        let t185 = -mu * k_edge * cos_theta * t28 * t34 * t37 * t39;
        let t186 = mu * k_edge * cos_theta * t28 * t34 * t39 * t40 * t138;
        let t187 = -mu * k_wall * t48 * t51 * t55 * t60;
        let t188 = mu * k_wall * t48 * t51 * t55 * t62 * t178;
        let t189 = k_edge * hc_alpha * sin_theta * t74 * t76 * t117;
        let t190 = -mu * k_edge * cos_theta * t74 * t79 * t82 * t84;
        let t191 = mu * k_edge * cos_theta * t74 * t79 * t84 * t85 * t151;
        let t192 = -mu * k_wall * t91 * t94 * t98 * t101;
        let t193 = mu * k_wall * t91 * t94 * t98 * t103 * t183;
        let t194 = k_wall * t61 * t112 * (T::from_f64(1.5) * t55 - T::from_f64(1.5));
        let t195 = t120 + t121;
        let t196 = t31 * t31;
        let t197 = t52 * t52;
        let t198 = k_wall
            * (thetadot * hc_alpha * t51 * t140 * t141
                + T::from_f64(1.5) * t52 * t55 * t61 * t112
                - T::from_f64(1.5) * t52 * t61 * t112);
        let t199 = t76 * t76;
        let t200 = t95 * t95;
        let t201 = t152 + t155 + t156;
        let t202 = t39 * t39;
        let t203 = cos_theta * t47 + sin_theta * t46;
        let t204 = t203 * t203;
        let t205 = t84 * t84;
        let t206 = cos_theta * t90 + sin_theta * t89;
        let t207 = t206 * t206;
        let t208 = t26 * t26 * t26;
        let t209 = T::from_f64(2.0) * sin_theta * t20
            + T::from_f64(2.0) * cos_theta * t25;
        let t210 = t49 * t49 * t49;
        let t211 = T::from_f64(2.0) * zdot;
        let t212 = t211 + T::from_f64(2.0) * thetadot * t48;
        let t213 = t72 * t72 * t72;
        let t214 = T::from_f64(2.0) * sin_theta * t68
            + T::from_f64(2.0) * cos_theta * t71;
        let t215 = t92 * t92 * t92;
        let t216 = t211 + T::from_f64(2.0) * thetadot * t91;
        SMatrix::<
            T,
            8,
            8,
        >::from_row_slice(
            &[
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(1.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(1.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(1.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t104
                    * (-(T::from_f64(1.5) * k_edge * t106 * t107 * t108) - t29 * t110
                        - T::from_f64(1.5) * mu * k_edge * sin_theta * t26 * t29 * t34
                            * t37 * t38 * t106
                        - T::from_f64(2.0) * thetadot * mu * k_edge * hc_alpha
                            * sin_theta * t11 * t26 * t28 * t30 * t37 * t109
                        + T::from_f64(1.5) * k_wall * t61 * t112
                        - T::from_f64(1.5) * k_wall * t112 * t113
                        - T::from_f64(1.5) * k_wall * t55 * t61 * t112
                        - T::from_f64(1.5) * k_edge * t114 * t115 * t116 - t75 * t118
                        - T::from_f64(1.5) * mu * k_edge * sin_theta * t72 * t75 * t79
                            * t82 * t83 * t114
                        + T::from_f64(2.0) * thetadot * mu * k_edge * hc_alpha
                            * sin_theta * t11 * t30 * t72 * t74 * t82 * t117 + t120
                        + t121 - T::from_f64(1.5) * k_wall * t119 * t122),
                t104
                    * (t123 - t29 * t124
                        - T::from_f64(1.5) * mu * k_edge * t26 * t34 * t37 * t38 * t106
                            * t111
                        - thetadot * mu * k_edge * hc_alpha * sin_theta * cos_theta * t26
                            * t28 * t37 * t109 + t126 - t75 * t127
                        + T::from_f64(1.5) * mu * k_edge * t72 * t79 * t82 * t83 * t111
                            * t114
                        + thetadot * mu * k_edge * hc_alpha * sin_theta * cos_theta * t72
                            * t74 * t82 * t117),
                t104
                    * (t0 + t1 - mu * k_edge * cos_theta * t26 * t28 * t34 * t37
                        - mu * k_edge * cos_theta * t72 * t74 * t79 * t82 + t128 + t129
                        + t130 - t29 * t134
                        - mu * k_edge * sin_theta * t28 * t34 * t37 * t137
                        - T::from_f64(1.5) * mu * k_edge * sin_theta * t26 * t31 * t34
                            * t37 * t38 * t106
                        - mu * k_edge * hc_alpha * sin_theta * t26 * t28 * t37 * t109
                            * t133
                        + mu * k_edge * sin_theta * t28 * t34 * t40 * t137 * t138
                        + T::from_f64(1.5) * k_wall * t52 * t61 * t112 + t139
                        - T::from_f64(1.5) * k_wall * t52 * t55 * t61 * t112
                        - thetadot * k_wall * hc_alpha * t51 * t140 * t141 + t142 + t143
                        + t144 - t75 * t147
                        - mu * k_edge * sin_theta * t74 * t79 * t82 * t150
                        - T::from_f64(1.5) * mu * k_edge * sin_theta * t72 * t76 * t79
                            * t82 * t83 * t114
                        - mu * k_edge * hc_alpha * sin_theta * t72 * t74 * t82 * t117
                            * t146
                        + mu * k_edge * sin_theta * t74 * t79 * t85 * t150 * t151 + t152
                        + t155 + t156 + t157),
                t104
                    * (-(k_edge * hc_alpha * t28 * t107 * t109)
                        - mu * k_edge * t28 * t34 * t37 * t111
                        - mu * k_edge * hc_alpha * sin_theta * t26 * t28 * t29 * t37
                            * t109 + mu * k_edge * t28 * t34 * t40 * t111 * t138
                        - k_wall * hc_alpha * t51 * t141
                        - k_edge * hc_alpha * t74 * t115 * t117
                        - mu * k_edge * t74 * t79 * t82 * t111
                        - mu * k_edge * hc_alpha * sin_theta * t72 * t74 * t75 * t82
                            * t117 + mu * k_edge * t74 * t79 * t85 * t111 * t151
                        - k_wall * hc_alpha * t94 * t154),
                t104
                    * (t158 + t159
                        - mu * k_edge * hc_alpha * t26 * t28 * t37 * t109 * t111 + t160
                        + t161 + t162
                        + mu * k_edge * hc_alpha * t72 * t74 * t82 * t111 * t117 + t163),
                t104
                    * (t164 + t165
                        - mu * k_edge * hc_alpha * sin_theta * t26 * t28 * t31 * t37
                            * t109 + t166 + t167 + t168 + t169
                        - mu * k_edge * hc_alpha * sin_theta * t72 * t74 * t76 * t82
                            * t117 + t170 + t171),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t104
                    * (t123 + t126 - sin_theta * t110
                        - T::from_f64(1.5) * mu * k_edge * cos_theta * t26 * t29 * t34
                            * t37 * t38 * t106
                        - T::from_f64(2.0) * thetadot * mu * k_edge * hc_alpha
                            * cos_theta * t11 * t26 * t28 * t30 * t37 * t109
                        - T::from_f64(1.5) * mu * k_wall * t49 * t55 * t60 * t61 * t112
                        + sin_theta * t118
                        - T::from_f64(1.5) * mu * k_edge * cos_theta * t72 * t75 * t79
                            * t82 * t83 * t114
                        + T::from_f64(2.0) * thetadot * mu * k_edge * hc_alpha
                            * cos_theta * t11 * t30 * t72 * t74 * t82 * t117
                        + T::from_f64(1.5) * mu * k_wall * t92 * t98 * t101 * t102
                            * t119),
                t104
                    * (-(T::from_f64(1.5) * k_edge * t106 * t108 * t111)
                        - sin_theta * t124
                        - T::from_f64(1.5) * mu * k_edge * sin_theta * cos_theta * t26
                            * t34 * t37 * t38 * t106
                        - thetadot * mu * k_edge * hc_alpha * t26 * t28 * t37 * t109
                            * t125 - T::from_f64(1.5) * k_edge * t111 * t114 * t116
                        + sin_theta * t127
                        + T::from_f64(1.5) * mu * k_edge * sin_theta * cos_theta * t72
                            * t79 * t82 * t83 * t114
                        + thetadot * mu * k_edge * hc_alpha * t72 * t74 * t82 * t117
                            * t125),
                t104
                    * (mu * k_edge * sin_theta * t26 * t28 * t34 * t37
                        + mu * k_edge * sin_theta * t72 * t74 * t79 * t82 + t172 + t173
                        + t174 + t175 + t176 - sin_theta * t134
                        - mu * k_edge * cos_theta * t28 * t34 * t37 * t137
                        - T::from_f64(1.5) * mu * k_edge * cos_theta * t26 * t31 * t34
                            * t37 * t38 * t106
                        - mu * k_edge * hc_alpha * cos_theta * t26 * t28 * t37 * t109
                            * t133
                        + mu * k_edge * cos_theta * t28 * t34 * t40 * t137 * t138
                        - thetadot * mu * k_wall * t51 * t55 * t60 * t177
                        - T::from_f64(1.5) * mu * k_wall * t49 * t52 * t55 * t60 * t61
                            * t112
                        - thetadot * mu * k_wall * hc_alpha * t49 * t51 * t60 * t140
                            * t141
                        + thetadot * mu * k_wall * t51 * t55 * t62 * t177 * t178 + t179
                        + t180 + t181 + sin_theta * t147
                        - mu * k_edge * cos_theta * t74 * t79 * t82 * t150
                        - T::from_f64(1.5) * mu * k_edge * cos_theta * t72 * t76 * t79
                            * t82 * t83 * t114
                        - mu * k_edge * hc_alpha * cos_theta * t72 * t74 * t82 * t117
                            * t146
                        + mu * k_edge * cos_theta * t74 * t79 * t85 * t150 * t151
                        - thetadot * mu * k_wall * t94 * t98 * t101 * t182
                        - T::from_f64(1.5) * mu * k_wall * t92 * t95 * t98 * t101 * t102
                            * t119
                        - thetadot * mu * k_wall * hc_alpha * t92 * t94 * t101 * t153
                            * t154
                        + thetadot * mu * k_wall * t94 * t98 * t103 * t182 * t183),
                t104
                    * (t158 + t159 + t160 + t161 + t162 + t163
                        - mu * k_edge * hc_alpha * cos_theta * t26 * t28 * t29 * t37
                            * t109 - mu * k_wall * hc_alpha * t49 * t51 * t60 * t141
                        - mu * k_edge * hc_alpha * cos_theta * t72 * t74 * t75 * t82
                            * t117 + mu * k_wall * hc_alpha * t92 * t94 * t101 * t154),
                t104
                    * (-(k_edge * hc_alpha * t28 * t109 * t111)
                        - mu * k_edge * t28 * t34 * t37 * t125
                        - mu * k_edge * hc_alpha * sin_theta * cos_theta * t26 * t28
                            * t37 * t109 + mu * k_edge * t28 * t34 * t40 * t125 * t138
                        - mu * k_wall * t51 * t55 * t60
                        + mu * k_wall * t51 * t55 * t62 * t178
                        - k_edge * hc_alpha * t74 * t111 * t117
                        - mu * k_edge * t74 * t79 * t82 * t125
                        + mu * k_edge * hc_alpha * sin_theta * cos_theta * t72 * t74
                            * t82 * t117 + mu * k_edge * t74 * t79 * t85 * t125 * t151
                        - mu * k_wall * t94 * t98 * t101
                        + mu * k_wall * t94 * t98 * t103 * t183),
                t104
                    * (t184 + t185
                        - mu * k_edge * hc_alpha * cos_theta * t26 * t28 * t31 * t37
                            * t109 + t186 + t187
                        - mu * k_wall * hc_alpha * t49 * t51 * t52 * t60 * t141 + t188
                        + t189 + t190
                        - mu * k_edge * hc_alpha * cos_theta * t72 * t74 * t76 * t82
                            * t117 + t191 + t192
                        - mu * k_wall * hc_alpha * t92 * t94 * t95 * t101 * t154 + t193),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t105
                    * (t128 + t129 + t130 + t139 + t142 + t143 + t144 + t157 - t31 * t110
                        - T::from_f64(1.5) * mu * k_edge * t26 * t29 * t34 * t37 * t38
                            * t39 * t106
                        - T::from_f64(2.0) * thetadot * mu * k_edge * hc_alpha * t11
                            * t26 * t28 * t30 * t37 * t39 * t109 - t52 * t194
                        - T::from_f64(1.5) * mu * k_wall * t48 * t49 * t55 * t60 * t61
                            * t112 - t76 * t118
                        - T::from_f64(1.5) * mu * k_edge * t72 * t75 * t79 * t82 * t83
                            * t84 * t114
                        + T::from_f64(2.0) * thetadot * mu * k_edge * hc_alpha * t11
                            * t30 * t72 * t74 * t82 * t84 * t117 - t95 * t195
                        + T::from_f64(1.5) * mu * k_wall * t91 * t92 * t98 * t101 * t102
                            * t119),
                t105
                    * (t174 + t175 + t176 + t179 + t180 + t181 - t31 * t124
                        - T::from_f64(1.5) * mu * k_edge * sin_theta * t26 * t34 * t37
                            * t38 * t39 * t106
                        - thetadot * mu * k_edge * hc_alpha * cos_theta * t26 * t28 * t37
                            * t39 * t109 - t76 * t127
                        + T::from_f64(1.5) * mu * k_edge * sin_theta * t72 * t79 * t82
                            * t83 * t84 * t114
                        + thetadot * mu * k_edge * hc_alpha * cos_theta * t72 * t74 * t82
                            * t84 * t117),
                t105
                    * (-(T::from_f64(1.5) * k_edge * t106 * t108 * t196)
                        - k_edge * t28 * t38 * t132 - t35 * t132 - t31 * t134
                        - mu * k_edge * t28 * t34 * t37 * t39 * t137
                        - T::from_f64(1.5) * mu * k_edge * t26 * t31 * t34 * t37 * t38
                            * t39 * t106
                        - mu * k_edge * hc_alpha * t26 * t28 * t37 * t39 * t109 * t133
                        + mu * k_edge * t28 * t34 * t39 * t40 * t137 * t138
                        - mu * k_edge * t26 * t28 * t34 * t37
                            * (cos_theta * t19 + sin_theta * t135 - sin_theta * t24
                                + cos_theta * t136)
                        - T::from_f64(1.5) * k_wall * t112 * t113 * t197
                        - k_wall * t51 * t61 * t140 - t58 * t140 - t52 * t198
                        - mu * k_wall * t49 * t51 * t55 * t60 * t177
                        - thetadot * mu * k_wall * t48 * t51 * t55 * t60 * t177
                        - T::from_f64(1.5) * mu * k_wall * t48 * t49 * t52 * t55 * t60
                            * t61 * t112
                        - thetadot * mu * k_wall * hc_alpha * t48 * t49 * t51 * t60
                            * t140 * t141
                        + thetadot * mu * k_wall * t48 * t51 * t55 * t62 * t177 * t178
                        - T::from_f64(1.5) * k_edge * t114 * t116 * t199
                        - k_edge * t74 * t83 * t145 - t80 * t145 - t76 * t147
                        - mu * k_edge * t74 * t79 * t82 * t84 * t150
                        - T::from_f64(1.5) * mu * k_edge * t72 * t76 * t79 * t82 * t83
                            * t84 * t114
                        - mu * k_edge * hc_alpha * t72 * t74 * t82 * t84 * t117 * t146
                        + mu * k_edge * t74 * t79 * t84 * t85 * t150 * t151
                        - mu * k_edge * t72 * t74 * t79 * t82
                            * (cos_theta * t67 + sin_theta * t148 - sin_theta * t70
                                + cos_theta * t149)
                        - T::from_f64(1.5) * k_wall * t119 * t122 * t200
                        - k_wall * t94 * t102 * t153 - t99 * t153 - t95 * t201
                        - mu * k_wall * t92 * t94 * t98 * t101 * t182
                        - thetadot * mu * k_wall * t91 * t94 * t98 * t101 * t182
                        - T::from_f64(1.5) * mu * k_wall * t91 * t92 * t95 * t98 * t101
                            * t102 * t119
                        - thetadot * mu * k_wall * hc_alpha * t91 * t92 * t94 * t101
                            * t153 * t154
                        + thetadot * mu * k_wall * t91 * t94 * t98 * t103 * t182 * t183),
                t105
                    * (t164 + t165 + t166 + t167 + t168 + t169 + t170 + t171
                        - mu * k_edge * hc_alpha * t26 * t28 * t29 * t37 * t39 * t109
                        - mu * k_wall * hc_alpha * t48 * t49 * t51 * t60 * t141
                        - mu * k_edge * hc_alpha * t72 * t74 * t75 * t82 * t84 * t117
                        + mu * k_wall * hc_alpha * t91 * t92 * t94 * t101 * t154),
                t105
                    * (t184 + t185 + t186 + t187 + t188 + t189 + t190 + t191 + t192
                        + t193
                        - mu * k_edge * hc_alpha * sin_theta * t26 * t28 * t37 * t39
                            * t109
                        + mu * k_edge * hc_alpha * sin_theta * t72 * t74 * t82 * t84
                            * t117),
                t105
                    * (-(k_edge * hc_alpha * t28 * t109 * t196)
                        - mu * k_edge * t28 * t34 * t37 * t202
                        - mu * k_edge * hc_alpha * t26 * t28 * t31 * t37 * t39 * t109
                        + mu * k_edge * t28 * t34 * t40 * t138 * t202
                        - k_wall * hc_alpha * t51 * t141 * t197
                        - mu * k_wall * t51 * t55 * t60 * t204
                        - mu * k_wall * hc_alpha * t48 * t49 * t51 * t52 * t60 * t141
                        + mu * k_wall * t51 * t55 * t62 * t178 * t204
                        - k_edge * hc_alpha * t74 * t117 * t199
                        - mu * k_edge * t74 * t79 * t82 * t205
                        - mu * k_edge * hc_alpha * t72 * t74 * t76 * t82 * t84 * t117
                        + mu * k_edge * t74 * t79 * t85 * t151 * t205
                        - k_wall * hc_alpha * t94 * t154 * t200
                        - mu * k_wall * t94 * t98 * t101 * t207
                        - mu * k_wall * hc_alpha * t91 * t92 * t94 * t95 * t101 * t154
                        + mu * k_wall * t94 * t98 * t103 * t183 * t207),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                xdot * t2 + zdot * (t172 + t173),
                f1 * sin_theta + f2 * cos_theta,
                t2,
                m_2,
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(1.5) * mu * k_edge * t29 * t34 * t37 * t38 * t40 * t106
                    + T::from_f64(2.0) * thetadot * mu * k_edge * hc_alpha * t11 * t28
                        * t30 * t37 * t40 * t109
                    + T::from_f64(2.0) * thetadot * t11 * t30 * t35 + t32 * t110
                    + T::from_f64(1.5) * mu * k_wall * t55 * t60 * t61 * t62 * t112
                    + t53 * t194
                    + T::from_f64(1.5) * mu * k_edge * t75 * t79 * t82 * t83 * t85 * t114
                    - T::from_f64(2.0) * thetadot * mu * k_edge * hc_alpha * t11 * t30
                        * t74 * t82 * t85 * t117
                    - T::from_f64(2.0) * thetadot * t11 * t30 * t80 + t77 * t118
                    - T::from_f64(1.5) * mu * k_wall * t98 * t101 * t102 * t103 * t119
                    + t96 * t195,
                T::from_f64(1.5) * mu * k_edge * sin_theta * t34 * t37 * t38 * t40 * t106
                    + thetadot * mu * k_edge * hc_alpha * cos_theta * t28 * t37 * t40
                        * t109 + thetadot * cos_theta * t35 + t32 * t124
                    - T::from_f64(1.5) * mu * k_edge * sin_theta * t79 * t82 * t83 * t85
                        * t114
                    - thetadot * mu * k_edge * hc_alpha * cos_theta * t74 * t82 * t85
                        * t117 - thetadot * cos_theta * t80 + t77 * t127,
                T::from_f64(1.5) * mu * k_edge * t31 * t34 * t37 * t38 * t40 * t106
                    + mu * k_edge * hc_alpha * t28 * t37 * t40 * t109 * t133
                    - mu * k_edge * t28 * t34 * t137 * t138 * t208
                    + mu * k_edge * t28 * t34 * t37 * t137 * t209 + t35 * t133
                    + t32 * t134
                    + T::from_f64(1.5) * mu * k_wall * t52 * t55 * t60 * t61 * t62 * t112
                    + thetadot * mu * k_wall * hc_alpha * t51 * t60 * t62 * t140 * t141
                    - thetadot * mu * k_wall * t51 * t55 * t177 * t178 * t210
                    + thetadot * mu * k_wall * t51 * t55 * t60 * t177 * t212
                    + thetadot * t58 * t140 + t53 * t198
                    + T::from_f64(1.5) * mu * k_edge * t76 * t79 * t82 * t83 * t85 * t114
                    + mu * k_edge * hc_alpha * t74 * t82 * t85 * t117 * t146
                    - mu * k_edge * t74 * t79 * t150 * t151 * t213
                    + mu * k_edge * t74 * t79 * t82 * t150 * t214 + t80 * t146
                    + t77 * t147
                    + T::from_f64(1.5) * mu * k_wall * t95 * t98 * t101 * t102 * t103
                        * t119
                    + thetadot * mu * k_wall * hc_alpha * t94 * t101 * t103 * t153 * t154
                    - thetadot * mu * k_wall * t94 * t98 * t182 * t183 * t215
                    + thetadot * mu * k_wall * t94 * t98 * t101 * t182 * t216
                    + thetadot * t99 * t153 + t96 * t201,
                t29 * t35 + t56 + t57 + t75 * t80 + k_wall * t94 - k_wall * t94 * t98
                    + mu * k_edge * hc_alpha * t28 * t29 * t37 * t40 * t109
                    - mu * k_edge * sin_theta * t28 * t34 * t138 * t208
                    + mu * k_edge * sin_theta * t28 * t34 * t37 * t209
                    + k_edge * hc_alpha * t28 * t29 * t32 * t109
                    + mu * k_wall * hc_alpha * t51 * t60 * t62 * t141
                    + k_wall * hc_alpha * t51 * t53 * t141
                    + mu * k_edge * hc_alpha * t74 * t75 * t82 * t85 * t117
                    - mu * k_edge * sin_theta * t74 * t79 * t151 * t213
                    + mu * k_edge * sin_theta * t74 * t79 * t82 * t214
                    + k_edge * hc_alpha * t74 * t75 * t77 * t117
                    - mu * k_wall * hc_alpha * t94 * t101 * t103 * t154
                    - k_wall * hc_alpha * t94 * t96 * t154,
                sin_theta * t35 - sin_theta * t80
                    + mu * k_edge * hc_alpha * sin_theta * t28 * t37 * t40 * t109
                    - mu * k_edge * cos_theta * t28 * t34 * t138 * t208
                    + mu * k_edge * cos_theta * t28 * t34 * t37 * t209
                    + k_edge * hc_alpha * sin_theta * t28 * t32 * t109
                    - mu * k_wall * t51 * t55 * t178 * t210
                    + mu * k_wall * t51 * t55 * t60 * t212
                    - mu * k_edge * hc_alpha * sin_theta * t74 * t82 * t85 * t117
                    - mu * k_edge * cos_theta * t74 * t79 * t151 * t213
                    + mu * k_edge * cos_theta * t74 * t79 * t82 * t214
                    - k_edge * hc_alpha * sin_theta * t74 * t77 * t117
                    - mu * k_wall * t94 * t98 * t183 * t215
                    + mu * k_wall * t94 * t98 * t101 * t216,
                t31 * t35 + t52 * t58 + t76 * t80 + t95 * t99
                    + mu * k_edge * hc_alpha * t28 * t31 * t37 * t40 * t109
                    - mu * k_edge * t28 * t34 * t39 * t138 * t208
                    + mu * k_edge * t28 * t34 * t37 * t39 * t209
                    + k_edge * hc_alpha * t28 * t31 * t32 * t109
                    + mu * k_wall * hc_alpha * t51 * t52 * t60 * t62 * t141
                    - mu * k_wall * t48 * t51 * t55 * t178 * t210
                    + mu * k_wall * t48 * t51 * t55 * t60 * t212
                    + k_wall * hc_alpha * t51 * t52 * t53 * t141
                    + mu * k_edge * hc_alpha * t74 * t76 * t82 * t85 * t117
                    - mu * k_edge * t74 * t79 * t84 * t151 * t213
                    + mu * k_edge * t74 * t79 * t82 * t84 * t214
                    + k_edge * hc_alpha * t74 * t76 * t77 * t117
                    + mu * k_wall * hc_alpha * t94 * t95 * t101 * t103 * t154
                    - mu * k_wall * t91 * t94 * t98 * t183 * t215
                    + mu * k_wall * t91 * t94 * t98 * t101 * t216
                    + k_wall * hc_alpha * t94 * t95 * t96 * t154,
                T::from_f64(0.0),
                T::from_f64(0.0),
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
    /// 62 add/sub, 152 mul, 11 div, 4 sqrt, 10 transcendental, 8 branches; 54 `let`s.
    #[inline]
    pub fn contacts<T: Real>(
        y: &SVector<T, 8>,
        p: &SVector<T, 24>,
    ) -> (
        SVector<T, 4>,
        SVector<T, 4>,
        SVector<T, 4>,
        SVector<T, 4>,
        SVector<T, 4>,
        SVector<T, 4>,
        SVector<T, 4>,
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
        let (sin_theta, cos_theta) = theta.sin_cos();
        let t0 = -T::from_f64(0.5) * d;
        let t1 = -x;
        let t2 = -rho_h + t0 + t1;
        let t3 = rho_h - z;
        let t4 = T::from_f64(0.5) * theta;
        let (t5, t14) = t4.sin_cos();
        let t6 = t5 * t5;
        let t7 = r + t0 + t1 - sin_theta * t3 - T::from_f64(2.0) * t2 * t6;
        let t8 = cos_theta * t3;
        let t9 = sin_theta * t2 + t8;
        let t10 = -r;
        let t11 = sin_theta * (xdot + thetadot * (cos_theta * t9 + r * sin_theta))
            + cos_theta * (zdot + thetadot * (-(sin_theta * t9) + r * cos_theta));
        let t12 = t7.max0();
        let t13 = t12 * t12.sqrt();
        let t15 = (T::from_f64(1.0)
            + hc_alpha
                * (xdot * (-T::from_f64(1.0) + T::from_f64(2.0) * t6) + zdot * sin_theta
                    + thetadot * (-(cos_theta * t3) - T::from_f64(2.0) * t2 * t5 * t14)))
            .max0();
        let t16 = v_s.hypot(t11);
        let t17 = T::from_f64(1.0) / e_star;
        let t18 = T::from_f64(1.0) / edge_sum;
        let t19 = (T::from_f64(1.5) * k_edge * t13 * t15 * t17 * t18).cbrt();
        let t20 = T::from_f64(1.0) / edge_ma;
        let t21 = T::from_f64(1.0) / edge_mb;
        let t22 = -rho_p;
        let t23 = l_c + t22;
        let t24 = r + t22;
        let t25 = r + t0 + x + sin_theta * t23 - T::from_f64(2.0) * t6 * t24;
        let t26 = zdot
            + thetadot
                * (-(sin_theta * (l_c + t22 + rho_p * sin_theta))
                    - cos_theta * (r - T::from_f64(2.0) * rho_p * t6));
        let t27 = t25.max0();
        let t28 = t27 * t27.sqrt();
        let t29 = (T::from_f64(1.0)
            + hc_alpha
                * (xdot
                    + thetadot * (cos_theta * t23 - T::from_f64(2.0) * t5 * t14 * t24)))
            .max0();
        let t30 = v_s.hypot(t26);
        let t31 = T::from_f64(1.0) / wall_sum;
        let t32 = (T::from_f64(1.5) * k_wall * t17 * t28 * t29 * t31).cbrt();
        let t33 = T::from_f64(1.0) / wall_ma;
        let t34 = T::from_f64(1.0) / wall_mb;
        let t35 = rho_h + T::from_f64(0.5) * d + t1;
        let t36 = r + t0 + x + sin_theta * t3 + T::from_f64(2.0) * t6 * t35;
        let t37 = t8 + sin_theta * t35;
        let t38 = sin_theta * (xdot + thetadot * (-(r * sin_theta) + cos_theta * t37))
            + cos_theta * (zdot + thetadot * (-(r * cos_theta) - sin_theta * t37));
        let t39 = t36.max0();
        let t40 = t39 * t39.sqrt();
        let t41 = (T::from_f64(1.0)
            + hc_alpha
                * (xdot * (T::from_f64(1.0) - T::from_f64(2.0) * t6) - zdot * sin_theta
                    + thetadot * (t8 + T::from_f64(2.0) * t5 * t14 * t35)))
            .max0();
        let t42 = v_s.hypot(t38);
        let t43 = (T::from_f64(1.5) * k_edge * t17 * t18 * t40 * t41).cbrt();
        let t44 = rho_p + t10;
        let t45 = r + t0 + t1 - sin_theta * t23 + T::from_f64(2.0) * t6 * t44;
        let t46 = zdot
            + thetadot
                * (-(sin_theta * (l_c + t22 - rho_p * sin_theta))
                    - cos_theta * (t10 + T::from_f64(2.0) * rho_p * t6));
        let t47 = t45.max0();
        let t48 = t47 * t47.sqrt();
        let t49 = (T::from_f64(1.0)
            + hc_alpha
                * (-xdot
                    + thetadot
                        * (-(cos_theta * t23) + T::from_f64(2.0) * t5 * t14 * t44)))
            .max0();
        let t50 = v_s.hypot(t46);
        let t51 = (T::from_f64(1.5) * k_wall * t17 * t31 * t48 * t49).cbrt();
        let normal = Vector4::new(
            k_edge * t13 * t15,
            k_wall * t28 * t29,
            k_edge * t40 * t41,
            k_wall * t48 * t49,
        );
        let friction = Vector4::new(
            -mu * k_edge * t11 * t13 * t15 / t16,
            -mu * k_wall * t26 * t28 * t29 / t30,
            -mu * k_edge * t38 * t40 * t41 / t42,
            -mu * k_wall * t46 * t48 * t49 / t50,
        );
        let delta = Vector4::new(t7, t25, t36, t45);
        let slip = Vector4::new(t11, t26, t38, t46);
        let a = Vector4::new(edge_ma * t19, wall_ma * t32, edge_ma * t43, wall_ma * t51);
        let b = Vector4::new(edge_mb * t19, wall_mb * t32, edge_mb * t43, wall_mb * t51);
        let p0 = Vector4::new(
            T::from_f64(0.3183098861837907) * e_star * edge_sum * t19 * t20 * t21,
            T::from_f64(0.3183098861837907) * e_star * wall_sum * t32 * t33 * t34,
            T::from_f64(0.3183098861837907) * e_star * edge_sum * t20 * t21 * t43,
            T::from_f64(0.3183098861837907) * e_star * wall_sum * t33 * t34 * t51,
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
    /// 30 add/sub, 32 mul, 0 div, 0 sqrt, 6 transcendental, 4 branches; 17 `let`s.
    #[inline]
    pub fn energy<T: Real>(y: &SVector<T, 8>, p: &SVector<T, 24>) -> (T, T, T) {
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
        let (sin_theta, cos_theta) = theta.sin_cos();
        let t0 = -T::from_f64(0.5) * d;
        let t1 = -x;
        let t2 = rho_h - z;
        let t3 = (T::from_f64(0.5) * theta).sin();
        let t4 = t3 * t3;
        let t5 = (r + t0 + t1 - sin_theta * t2
            - T::from_f64(2.0) * (-rho_h + t0 + t1) * t4)
            .max0();
        let t6 = t5.powf(T::from_f64(2.5));
        let t7 = -rho_p;
        let t8 = l_c + t7;
        let t9 = (r + t0 + x + sin_theta * t8 - T::from_f64(2.0) * t4 * (r + t7)).max0();
        let t10 = t9.powf(T::from_f64(2.5));
        let t11 = (r + t0 + x + sin_theta * t2
            + T::from_f64(2.0) * t4 * (rho_h + T::from_f64(0.5) * d + t1))
            .max0();
        let t12 = t11.powf(T::from_f64(2.5));
        let t13 = (r + t0 + t1 - sin_theta * t8 + T::from_f64(2.0) * t4 * (rho_p - r))
            .max0();
        let t14 = t13.powf(T::from_f64(2.5));
        let kinetic = T::from_f64(0.5) * m * (xdot * xdot + zdot * zdot)
            + T::from_f64(0.5) * j * (thetadot * thetadot);
        let potential = T::from_f64(0.4) * k_edge * t6 + T::from_f64(0.4) * k_wall * t10
            + T::from_f64(0.4) * k_edge * t12 + T::from_f64(0.4) * k_wall * t14;
        let depth = z + l_c * cos_theta;
        (kinetic, potential, depth)
    }
}
