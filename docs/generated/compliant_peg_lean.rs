// @generated readable copy of `pegdyn::generated::compliant_peg_lean` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generated_snapshot

/// Planar compliant peg-in-hole (paper 001, (31)-(51), (55)-(64)) with contacts edge_left, wall_right. Inputs: state y (see STATE) and parameters p (see P_NAMES). SI units.
pub mod compliant_peg_lean {
    use nalgebra::{SMatrix, SVector, Vector2};
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
    /// 58 add/sub, 83 mul, 4 div, 2 sqrt, 4 transcendental, 8 branches; 52 `let`s.
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
        let t2 = -T::from_f64(0.5) * d;
        let t3 = -x;
        let t4 = -rho_h + t2 + t3;
        let t5 = rho_h - z;
        let t6 = T::from_f64(0.5) * theta;
        let (t7, t19) = t6.sin_cos();
        let t8 = t7 * t7;
        let t9 = r + t2 + t3 - sin_theta * t5 - T::from_f64(2.0) * t4 * t8;
        let t10 = cos_theta * t5;
        let t11 = sin_theta * t4 + t10;
        let t12 = cos_theta * t11 + r * sin_theta;
        let t13 = -(sin_theta * t11) + r * cos_theta;
        let t14 = sin_theta * (xdot + thetadot * t12)
            + cos_theta * (zdot + thetadot * t13);
        let t15 = t9.max0();
        let t16 = t15 * t15.sqrt();
        let t17 = k_edge * t16;
        let t18 = -T::from_f64(1.0) + T::from_f64(2.0) * t8;
        let t20 = t7 * t19;
        let t21 = v_s.hypot(t14);
        let t22 = t9.step();
        let t23 = -rho_p;
        let t24 = l_c + t23;
        let t25 = r + t23;
        let t26 = -(sin_theta * (l_c + t23 + rho_p * sin_theta))
            - cos_theta * (r - T::from_f64(2.0) * rho_p * t8);
        let t27 = zdot + thetadot * t26;
        let t28 = v_s.hypot(t27);
        let t29 = T::from_f64(1.0) / m;
        let t30 = r + t2 + x + sin_theta * t24 - T::from_f64(2.0) * t8 * t25;
        let t31 = t30.max0();
        let t32 = t31 * t31.sqrt();
        let t33 = k_wall * t32;
        let t34 = t30.step();
        let t35 = -t34;
        let t36 = -t10 - T::from_f64(2.0) * t20 * t4;
        let t37 = xdot * t18 + zdot * sin_theta + thetadot * t36;
        let t38 = (T::from_f64(1.0) + hc_alpha * t37).max0();
        let t39 = t38 / t21;
        let t40 = t39 * (mu * t14);
        let t41 = cos_theta * t24 - T::from_f64(2.0) * t20 * t25;
        let t42 = xdot + thetadot * t41;
        let t43 = (T::from_f64(1.0) + hc_alpha * t42).max0();
        let t44 = t38 - T::from_f64(1.0);
        let t45 = t43 - T::from_f64(1.0);
        let t46 = t43 / t28;
        let t47 = t33 * t46;
        let t48 = mu * t27;
        let t49 = -t22 - t44;
        SMatrix::<
            T,
            8,
            1,
        >::from_row_slice(
            &[
                xdot,
                zdot,
                thetadot,
                (t17 * (t18 * t49 - t40 * sin_theta)
                    + t33 * (T::from_f64(1.0) + t35 - t43) + t0 + t1) * t29,
                (sin_theta * (t17 * t49 - f2) + cos_theta * (f1 - t40 * t17) - t47 * t48)
                    * t29,
                (m_2 + t17 * (t36 * t49 - t40 * (sin_theta * t12 + cos_theta * t13))
                    + t33 * (t41 * (t35 - t45) - t48 * t46 * t26)) / j,
                xdot * (t0 + t1) + zdot * (f1 * cos_theta - f2 * sin_theta)
                    + thetadot * m_2,
                mu * (t39 * t17 * (t14 * t14) + t47 * (t27 * t27)) + t17 * t37 * t44
                    + t33 * t42 * t45,
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
    /// 204 add/sub, 449 mul, 6 div, 4 sqrt, 4 transcendental, 12 branches; 178 `let`s.
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
        let t0 = f1 * sin_theta;
        let t1 = f2 * cos_theta;
        let t2 = f1 * cos_theta;
        let t3 = -f2 * sin_theta;
        let t4 = t2 + t3;
        let t5 = -T::from_f64(0.5) * d;
        let t6 = -x;
        let t7 = -rho_h + t5 + t6;
        let t8 = rho_h - z;
        let t9 = sin_theta * t8;
        let t10 = T::from_f64(0.5) * theta;
        let (t11, t25) = t10.sin_cos();
        let t12 = t11 * t11;
        let t13 = cos_theta * t8;
        let t14 = sin_theta * t7 + t13;
        let t15 = cos_theta * t14;
        let t16 = t15 + r * sin_theta;
        let t17 = xdot + thetadot * t16;
        let t18 = -sin_theta * t14;
        let t19 = t18 + r * cos_theta;
        let t20 = zdot + thetadot * t19;
        let t21 = sin_theta * t17;
        let t22 = cos_theta * t20;
        let t23 = t21 + t22;
        let t24 = -T::from_f64(1.0) + T::from_f64(2.0) * t12;
        let t26 = t11 * t25;
        let t27 = v_s.hypot(t23);
        let t28 = T::from_f64(1.0) / t27;
        let t29 = sin_theta * t16 + cos_theta * t19;
        let t30 = t23 * t23;
        let t31 = -rho_p;
        let t32 = l_c + t31;
        let t33 = r + t31;
        let t34 = sin_theta * t32;
        let t35 = l_c + t31 + rho_p * sin_theta;
        let t36 = r - T::from_f64(2.0) * rho_p * t12;
        let t37 = cos_theta * t36;
        let t38 = sin_theta * t35;
        let t39 = T::from_f64(1.0) / m;
        let t40 = T::from_f64(1.0) / j;
        let t41 = t24 * t24;
        let t42 = sin_theta * sin_theta;
        let t43 = cos_theta * cos_theta;
        let t44 = T::from_f64(1.0) / (t27 * t27 * t27);
        let t45 = t37 + t38;
        let t46 = r + t5 + x + t34 - T::from_f64(2.0) * t12 * t33;
        let t47 = t46.max0();
        let t48 = t47 * t47.sqrt();
        let t49 = k_wall * t48;
        let t50 = t46.step();
        let t51 = -t13 - T::from_f64(2.0) * t26 * t7;
        let t52 = xdot * t24 + zdot * sin_theta + thetadot * t51;
        let t53 = T::from_f64(1.0) + hc_alpha * t52;
        let t54 = t53.max0();
        let t55 = cos_theta * t32 - T::from_f64(2.0) * t26 * t33;
        let t56 = xdot + thetadot * t55;
        let t57 = T::from_f64(1.0) + hc_alpha * t56;
        let t58 = t57.max0();
        let t59 = t54 - T::from_f64(1.0);
        let t60 = t58 - T::from_f64(1.0);
        let t61 = -t59;
        let t62 = t47.sqrt();
        let t63 = t50 * t50;
        let t64 = -T::from_f64(1.5) * t63;
        let t65 = t12 - t25 * t25;
        let t66 = t7 * t65 + t9;
        let t67 = t30 * t44;
        let t68 = -t28 + t67;
        let t69 = -t9;
        let t70 = cos_theta * t7 + t69;
        let t71 = r + t5 + t6 + t69 - T::from_f64(2.0) * t7 * t12;
        let t72 = t71.max0();
        let t73 = t72 * t72.sqrt();
        let t74 = t71.step();
        let t75 = -t38 - t37;
        let t76 = thetadot * t75;
        let t77 = zdot + t76;
        let t78 = v_s.hypot(t77);
        let t79 = T::from_f64(1.0) / t78;
        let t80 = t77 * t77;
        let t81 = t72.sqrt();
        let t82 = t74 * t74;
        let t83 = t53.step();
        let t84 = t57.step();
        let t85 = -t0;
        let t86 = -t1;
        let t87 = T::from_f64(1.0) / (t78 * t78 * t78);
        let t88 = k_edge * t73;
        let t89 = hc_alpha * t83;
        let t90 = t89 * t51;
        let t91 = -t90 * t88 * sin_theta;
        let t92 = t51 * t51;
        let t93 = t55 * t55;
        let t94 = T::from_f64(2.0) * t21 + T::from_f64(2.0) * t22;
        let t95 = T::from_f64(2.0) * zdot + T::from_f64(2.0) * t76;
        let t96 = -t74;
        let t97 = t73 * (t96 + t61);
        let t98 = T::from_f64(1.5) * t54 - T::from_f64(1.5);
        let t99 = t74 * t81;
        let t100 = t99 * t24;
        let t101 = thetadot * t73;
        let t102 = t26 * t101;
        let t103 = t89 * t102;
        let t104 = T::from_f64(2.0) * t103;
        let t105 = t100 * t98 + t104;
        let t106 = t23 * t28;
        let t107 = mu * t54;
        let t108 = t106 * t107;
        let t109 = t108 * sin_theta;
        let t110 = t109 * t74;
        let t111 = t89 * t106;
        let t112 = t111 * mu;
        let t113 = t62 * (t50 * (T::from_f64(1.5) - T::from_f64(1.5) * t58) + t64);
        let t114 = t99 * sin_theta;
        let t115 = t101 * cos_theta;
        let t116 = t115 * t89;
        let t117 = t114 * t98 + t116;
        let t118 = t81 * t82;
        let t119 = -T::from_f64(1.5) * t118 * t24;
        let t120 = T::from_f64(2.0) * t26 * xdot + zdot * cos_theta + thetadot * t66;
        let t121 = t99 * t51;
        let t122 = t73 * t120;
        let t123 = t89 * t122;
        let t124 = t121 * t98 + t123;
        let t125 = cos_theta * (r + t70) + t18;
        let t126 = sin_theta * (-r - t70) - t15;
        let t127 = cos_theta * (t17 + thetadot * t126)
            + sin_theta * (thetadot * t125 - t20);
        let t128 = t33 * t65 - t34;
        let t129 = t67 * t127;
        let t130 = t111 * sin_theta;
        let t131 = -T::from_f64(2.0) * t74;
        let t132 = -T::from_f64(2.0) * t59;
        let t133 = -(T::from_f64(1.5) * t118 * t51) - t124;
        let t134 = thetadot * t48;
        let t135 = hc_alpha * t84;
        let t136 = t135 * t128;
        let t137 = t134 * t136;
        let t138 = t49 * t135;
        let t139 = cos_theta * t54;
        let t140 = t107 * cos_theta;
        let t141 = sin_theta * (t140 * t68 - t89 * t24);
        let t142 = t135 * t55;
        let t143 = t54 * t29;
        let t144 = t111 * t51;
        let t145 = t143 * t68 - t144;
        let t146 = -t90 * t24;
        let t147 = t50 * t62;
        let t148 = t147 * k_wall;
        let t149 = mu * t58;
        let t150 = t77 * t79;
        let t151 = t100 * t54;
        let t152 = cos_theta * (rho_p * (-sin_theta + T::from_f64(2.0) * t26) - t35)
            + sin_theta * t36;
        let t153 = t111 * t120;
        let t154 = t106 * t121;
        let t155 = t80 * t87;
        let t156 = t58 * (-t79 + t155);
        let t157 = t150 * t136;
        let t158 = t147 * t55;
        let t159 = t158 * t58;
        let t160 = t156 * t75;
        let t161 = T::from_f64(1.5) * t58 - T::from_f64(1.5);
        let t162 = t112 * (thetadot * t29);
        let t163 = t81
            * (-(T::from_f64(1.5) * t51 * t82) - T::from_f64(1.5) * t108 * t74 * t29);
        let t164 = t150 * t75;
        let t165 = t158 * t161 + t137;
        let t166 = t28 * t30;
        let t167 = t166 * mu;
        let t168 = t79 * t80;
        let t169 = t73 * t127;
        let t170 = t44 * (t23 * t23 * t23);
        let t171 = t134 * t152;
        let t172 = t87 * (t77 * t77 * t77);
        let t173 = t89 * (t167 + t52) + t59;
        let t174 = -t170 + t28 * t94;
        let t175 = t75 * t58;
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
                t39
                    * (k_edge
                        * (t81
                            * (-(T::from_f64(1.5) * t41 * t82)
                                - T::from_f64(1.5) * t110 * t24) - t24 * t105
                            - T::from_f64(2.0) * t102 * t112 * sin_theta)
                        + t113 * k_wall),
                k_edge
                    * (sin_theta * (t119 - t115 * t112) - t24 * t117
                        - T::from_f64(1.5) * t108 * t99 * t42) * t39,
                t39
                    * (k_edge
                        * (t73
                            * (mu
                                * (t54
                                    * (t28 * (-(cos_theta * t23) - sin_theta * t127)
                                        + t129 * sin_theta) - t130 * t120) + t26 * (t131 + t132))
                            + t24 * t133 - T::from_f64(1.5) * t109 * t121)
                        + k_wall * (t113 * t55 - t137) + t2 + t3),
                t39 * (t88 * (mu * (t42 * t68 * t54 - t130 * t24) - t89 * t41) - t138),
                t88 * (t141 - t112 * t42) * t39,
                t39 * (t88 * (sin_theta * t145 * mu + t146) - t142 * t49),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t39
                    * (k_edge
                        * (sin_theta * (t119 - t105)
                            + t106
                                * (-(T::from_f64(1.5) * t151) - T::from_f64(2.0) * t103)
                                * cos_theta * mu) - T::from_f64(1.5) * t148 * t149 * t150),
                k_edge
                    * (t81
                        * (-(T::from_f64(1.5) * t82 * t42)
                            - T::from_f64(1.5) * t110 * cos_theta) - sin_theta * t117
                        - t112 * t101 * t43) * t39,
                t39
                    * (mu
                        * (k_edge
                            * (t73
                                * (t54
                                    * (t28 * (sin_theta * t23 - cos_theta * t127)
                                        + t129 * cos_theta) - t153 * cos_theta)
                                - T::from_f64(1.5) * t154 * t139)
                            + k_wall
                                * (t134 * (t156 * t152 - t157)
                                    - T::from_f64(1.5) * t159 * t150))
                        + k_edge * (t97 * cos_theta + sin_theta * t133) + t85 + t86),
                t39 * (t88 * (t141 - t112 * cos_theta * t24) - t138 * t150 * mu),
                t39
                    * (mu * (t88 * (t43 * t68 * t54 - t130 * cos_theta) + t156 * t49)
                        - t88 * t89 * t42),
                t39 * (mu * (cos_theta * t145 * t88 + t49 * (t160 - t142 * t150)) + t91),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t40
                    * (k_edge
                        * (t73 * (t131 + t132 - T::from_f64(2.0) * t162) * t26
                            + t163 * t24 - t51 * t105)
                        + t62
                            * (t55 * (t64 - t161 * t50)
                                - T::from_f64(1.5) * t164 * t149 * t50) * k_wall),
                k_edge
                    * (t73 * (t96 + t61 - t162) * cos_theta + t163 * sin_theta
                        - t51 * t117) * t40,
                t40
                    * (mu
                        * (k_edge
                            * (t73
                                * (t54
                                    * (t28
                                        * (-(t29 * t127)
                                            - t23
                                                * (cos_theta * (t16 + t126) + sin_theta * (t125 - t19)))
                                        + t129 * t29) - t153 * t29)
                                - T::from_f64(1.5) * t154 * t143)
                            + k_wall
                                * (t48
                                    * (t152 * (t79 * (-t77 - t76) + t155 * t76) * t58
                                        - t157 * t76) - T::from_f64(1.5) * t159 * t164))
                        + k_edge
                            * (t97 * t66 - T::from_f64(1.5) * t118 * t92 - t51 * t124)
                        + k_wall
                            * ((-t50 - t60) * t128 * t48
                                - T::from_f64(1.5) * t62 * t63 * t93 - t55 * t165)),
                t40
                    * (t88 * (t29 * (t54 * t68 * sin_theta - t111 * t24) * mu + t146)
                        + t138 * (-t55 - t164 * mu)),
                t40 * (mu * (t29 * (t139 * t68 - t130) * t88 + t160 * t49) + t91),
                t40
                    * (mu
                        * (t88 * (t29 * t29 * t68 * t54 - t144 * t29)
                            + t49 * (t156 * (t45 * t45) - t142 * t164))
                        + hc_alpha * (-(t88 * t83 * t92) - t49 * t84 * t93)),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                xdot * t4 + zdot * (t85 + t86),
                t0 + t1,
                t4,
                m_2,
                T::from_f64(0.0),
                T::from_f64(0.0),
                k_edge
                    * (t167 * (T::from_f64(1.5) * t151 + t104)
                        + T::from_f64(2.0) * t102 * t59 + t52 * t105)
                    + t148 * (T::from_f64(1.5) * t168 * t149 + t56 * t161),
                k_edge
                    * (t167 * (T::from_f64(1.5) * t114 * t54 + t116) + t115 * t59
                        + t52 * t117),
                mu
                    * (k_edge
                        * (t54
                            * (t28 * (T::from_f64(1.5) * t121 * t30 + t169 * t94)
                                - t169 * t170) + t123 * t166)
                        + k_wall
                            * (t58
                                * (t79 * (T::from_f64(1.5) * t158 * t80 + t171 * t95)
                                    - t171 * t172) + t137 * t168))
                    + k_edge * (t122 * t59 + t52 * t124)
                    + k_wall * (t134 * t60 * t128 + t56 * t165),
                t88 * (t24 * t173 + sin_theta * t174 * t107)
                    + t49 * (t135 * (t168 * mu + t56) + t58 - T::from_f64(1.0)),
                t88 * (sin_theta * t173 + t140 * t174)
                    + t49 * (-t172 + t79 * t95) * t149,
                mu
                    * (t88 * (t28 * (t90 * t30 + t143 * t94) - t170 * t143)
                        + t49 * (t79 * (t142 * t80 + t175 * t95) - t175 * t172))
                    + t88 * (t59 + t89 * t52) * t51 + t49 * (t60 + t135 * t56) * t55,
                T::from_f64(0.0),
                T::from_f64(0.0),
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
    /// 32 add/sub, 64 mul, 7 div, 2 sqrt, 6 transcendental, 4 branches; 33 `let`s.
    #[inline]
    pub fn contacts<T: Real>(
        y: &SVector<T, 8>,
        p: &SVector<T, 24>,
    ) -> (
        SVector<T, 2>,
        SVector<T, 2>,
        SVector<T, 2>,
        SVector<T, 2>,
        SVector<T, 2>,
        SVector<T, 2>,
        SVector<T, 2>,
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
        let (t5, t13) = t4.sin_cos();
        let t6 = t5 * t5;
        let t7 = r + t0 + t1 - sin_theta * t3 - T::from_f64(2.0) * t2 * t6;
        let t8 = cos_theta * t3;
        let t9 = sin_theta * t2 + t8;
        let t10 = sin_theta * (xdot + thetadot * (cos_theta * t9 + r * sin_theta))
            + cos_theta * (zdot + thetadot * (-(sin_theta * t9) + r * cos_theta));
        let t11 = t7.max0();
        let t12 = t11 * t11.sqrt();
        let t14 = t5 * t13;
        let t15 = v_s.hypot(t10);
        let t16 = T::from_f64(1.0) / e_star;
        let t17 = -rho_p;
        let t18 = l_c + t17;
        let t19 = r + t17;
        let t20 = zdot
            + thetadot
                * (-(sin_theta * (l_c + t17 + rho_p * sin_theta))
                    - cos_theta * (r - T::from_f64(2.0) * rho_p * t6));
        let t21 = v_s.hypot(t20);
        let t22 = r + t0 + x + sin_theta * t18 - T::from_f64(2.0) * t6 * t19;
        let t23 = t22.max0();
        let t24 = t23 * t23.sqrt();
        let t25 = (T::from_f64(1.0)
            + hc_alpha
                * (xdot * (-T::from_f64(1.0) + T::from_f64(2.0) * t6) + zdot * sin_theta
                    + thetadot * (-t8 - T::from_f64(2.0) * t14 * t2)))
            .max0();
        let t26 = (T::from_f64(1.0)
            + hc_alpha
                * (xdot + thetadot * (cos_theta * t18 - T::from_f64(2.0) * t14 * t19)))
            .max0();
        let t27 = k_edge * t12 * t25;
        let t28 = (T::from_f64(1.5) * t27 * t16 / edge_sum).cbrt();
        let t29 = k_wall * t26 * t24;
        let t30 = (T::from_f64(1.5) * t29 * t16 / wall_sum).cbrt();
        let normal = Vector2::new(t27, t29);
        let friction = Vector2::new(-t27 * mu * t10 / t15, -t29 * mu * t20 / t21);
        let delta = Vector2::new(t7, t22);
        let slip = Vector2::new(t10, t20);
        let a = Vector2::new(edge_ma * t28, wall_ma * t30);
        let b = Vector2::new(edge_mb * t28, wall_mb * t30);
        let p0 = Vector2::new(
            T::from_f64(0.3183098861837907) * e_star * edge_sum * t28
                / (edge_ma * edge_mb),
            T::from_f64(0.3183098861837907) * e_star * wall_sum * t30
                / (wall_ma * wall_mb),
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
    /// 17 add/sub, 21 mul, 0 div, 0 sqrt, 4 transcendental, 2 branches; 11 `let`s.
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
        let t2 = (T::from_f64(0.5) * theta).sin();
        let t3 = t2 * t2;
        let t4 = (r + t0 + t1 - sin_theta * (rho_h - z)
            - T::from_f64(2.0) * (-rho_h + t0 + t1) * t3)
            .max0();
        let t5 = t4.powf(T::from_f64(2.5));
        let t6 = -rho_p;
        let t7 = (r + t0 + x + sin_theta * (l_c + t6) - T::from_f64(2.0) * t3 * (r + t6))
            .max0();
        let t8 = t7.powf(T::from_f64(2.5));
        let kinetic = T::from_f64(0.5) * m * (xdot * xdot + zdot * zdot)
            + T::from_f64(0.5) * j * (thetadot * thetadot);
        let potential = T::from_f64(0.4) * k_edge * t5 + T::from_f64(0.4) * k_wall * t8;
        let depth = z + l_c * cos_theta;
        (kinetic, potential, depth)
    }
}
