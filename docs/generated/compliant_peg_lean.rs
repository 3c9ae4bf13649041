// @generated readable copy of `pegdyn::generated::compliant_peg_lean` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generated_snapshot

/// Compliant planar peg (*Dynamic analysis for peg-in-hole assembly with contact deformation*, (31)-(51), (55)-(64)) with contacts edge_left, wall_right. Inputs: state y (see STATE) and parameters p (see P_NAMES). SI units.
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
    /// 58 add/sub, 81 mul, 5 div, 2 sqrt, 4 transcendental, 8 branches; 51 `let`s.
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
        let t29 = r + t2 + x + sin_theta * t24 - T::from_f64(2.0) * t8 * t25;
        let t30 = t29.max0();
        let t31 = t30 * t30.sqrt();
        let t32 = k_wall * t31;
        let t33 = t29.step();
        let t34 = -t33;
        let t35 = -t10 - T::from_f64(2.0) * t20 * t4;
        let t36 = xdot * t18 + zdot * sin_theta + thetadot * t35;
        let t37 = (T::from_f64(1.0) + hc_alpha * t36).max0();
        let t38 = t37 / t21;
        let t39 = t38 * (mu * t14);
        let t40 = cos_theta * t24 - T::from_f64(2.0) * t20 * t25;
        let t41 = xdot + thetadot * t40;
        let t42 = (T::from_f64(1.0) + hc_alpha * t41).max0();
        let t43 = t37 - T::from_f64(1.0);
        let t44 = t42 - T::from_f64(1.0);
        let t45 = t42 / t28;
        let t46 = t32 * t45;
        let t47 = mu * t27;
        let t48 = -t22 - t43;
        SMatrix::<
            T,
            8,
            1,
        >::from_row_slice(
            &[
                xdot,
                zdot,
                thetadot,
                (t17 * (t18 * t48 - t39 * sin_theta)
                    + t32 * (T::from_f64(1.0) + t34 - t42) + t0 + t1) / m,
                (sin_theta * (t17 * t48 - f2) + cos_theta * (f1 - t39 * t17) - t46 * t47)
                    / m,
                (m_2 + t17 * (t35 * t48 - t39 * (sin_theta * t12 + cos_theta * t13))
                    + t32 * (t40 * (t34 - t44) - t47 * t45 * t26)) / j,
                xdot * (t0 + t1) + zdot * (f1 * cos_theta - f2 * sin_theta)
                    + thetadot * m_2,
                mu * (t38 * t17 * (t14 * t14) + t46 * (t27 * t27)) + t17 * t36 * t43
                    + t32 * t41 * t44,
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
    /// 199 add/sub, 446 mul, 6 div, 4 sqrt, 4 transcendental, 12 branches; 172 `let`s.
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
        let (t11, t23) = t10.sin_cos();
        let t12 = t11 * t11;
        let t13 = cos_theta * t8;
        let t14 = sin_theta * t7 + t13;
        let t15 = cos_theta * t14;
        let t16 = t15 + r * sin_theta;
        let t17 = xdot + thetadot * t16;
        let t18 = -sin_theta * t14;
        let t19 = t18 + r * cos_theta;
        let t20 = zdot + thetadot * t19;
        let t21 = sin_theta * t17 + cos_theta * t20;
        let t22 = -T::from_f64(1.0) + T::from_f64(2.0) * t12;
        let t24 = t11 * t23;
        let t25 = v_s.hypot(t21);
        let t26 = T::from_f64(1.0) / t25;
        let t27 = sin_theta * t16 + cos_theta * t19;
        let t28 = t21 * t21;
        let t29 = -rho_p;
        let t30 = l_c + t29;
        let t31 = r + t29;
        let t32 = sin_theta * t30;
        let t33 = l_c + t29 + rho_p * sin_theta;
        let t34 = r - T::from_f64(2.0) * rho_p * t12;
        let t35 = cos_theta * t34;
        let t36 = sin_theta * t33;
        let t37 = T::from_f64(1.0) / m;
        let t38 = T::from_f64(1.0) / j;
        let t39 = t22 * t22;
        let t40 = sin_theta * sin_theta;
        let t41 = cos_theta * cos_theta;
        let t42 = T::from_f64(1.0) / (t25 * t25 * t25);
        let t43 = t35 + t36;
        let t44 = r + t5 + x + t32 - T::from_f64(2.0) * t12 * t31;
        let t45 = t44.max0();
        let t46 = t45 * t45.sqrt();
        let t47 = k_wall * t46;
        let t48 = t44.step();
        let t49 = -t13 - T::from_f64(2.0) * t24 * t7;
        let t50 = xdot * t22 + zdot * sin_theta + thetadot * t49;
        let t51 = T::from_f64(1.0) + hc_alpha * t50;
        let t52 = t51.max0();
        let t53 = cos_theta * t30 - T::from_f64(2.0) * t24 * t31;
        let t54 = xdot + thetadot * t53;
        let t55 = T::from_f64(1.0) + hc_alpha * t54;
        let t56 = t55.max0();
        let t57 = t52 - T::from_f64(1.0);
        let t58 = t56 - T::from_f64(1.0);
        let t59 = -t57;
        let t60 = t45.sqrt();
        let t61 = t48 * t48;
        let t62 = -T::from_f64(1.5) * t61;
        let t63 = t12 - t23 * t23;
        let t64 = t7 * t63 + t9;
        let t65 = t28 * t42;
        let t66 = -t26 + t65;
        let t67 = -t9;
        let t68 = cos_theta * t7 + t67;
        let t69 = r + t5 + t6 + t67 - T::from_f64(2.0) * t7 * t12;
        let t70 = t69.max0();
        let t71 = t70 * t70.sqrt();
        let t72 = t69.step();
        let t73 = -t36 - t35;
        let t74 = thetadot * t73;
        let t75 = zdot + t74;
        let t76 = v_s.hypot(t75);
        let t77 = T::from_f64(1.0) / t76;
        let t78 = t75 * t75;
        let t79 = t70.sqrt();
        let t80 = t72 * t72;
        let t81 = t51.step();
        let t82 = t55.step();
        let t83 = -t0;
        let t84 = -t1;
        let t85 = T::from_f64(1.0) / (t76 * t76 * t76);
        let t86 = k_edge * t71;
        let t87 = hc_alpha * t81;
        let t88 = t87 * t49;
        let t89 = -t88 * t86 * sin_theta;
        let t90 = t49 * t49;
        let t91 = t53 * t53;
        let t92 = -t72;
        let t93 = t92 + t59;
        let t94 = t71 * t93;
        let t95 = T::from_f64(1.5) * t52 - T::from_f64(1.5);
        let t96 = t72 * t79;
        let t97 = t96 * t22;
        let t98 = thetadot * t71;
        let t99 = t24 * t98;
        let t100 = t87 * t99;
        let t101 = T::from_f64(2.0) * t100;
        let t102 = t97 * t95 + t101;
        let t103 = t21 * t26;
        let t104 = mu * t52;
        let t105 = t103 * t104;
        let t106 = t105 * sin_theta;
        let t107 = t106 * t72;
        let t108 = t87 * t103;
        let t109 = t108 * mu;
        let t110 = t60 * (t48 * (T::from_f64(1.5) - T::from_f64(1.5) * t56) + t62);
        let t111 = t96 * sin_theta;
        let t112 = t98 * cos_theta;
        let t113 = t112 * t87;
        let t114 = t111 * t95 + t113;
        let t115 = t79 * t80;
        let t116 = -T::from_f64(1.5) * t115 * t22;
        let t117 = T::from_f64(2.0) * t24 * xdot + zdot * cos_theta + thetadot * t64;
        let t118 = t96 * t49;
        let t119 = t71 * t117;
        let t120 = t87 * t119;
        let t121 = t118 * t95 + t120;
        let t122 = cos_theta * (r + t68) + t18;
        let t123 = sin_theta * (-r - t68) - t15;
        let t124 = cos_theta * (t17 + thetadot * t123)
            + sin_theta * (thetadot * t122 - t20);
        let t125 = t31 * t63 - t32;
        let t126 = t65 * t124;
        let t127 = t108 * sin_theta;
        let t128 = -(T::from_f64(1.5) * t115 * t49) - t121;
        let t129 = thetadot * t46;
        let t130 = hc_alpha * t82;
        let t131 = t130 * t125;
        let t132 = t129 * t131;
        let t133 = t47 * t130;
        let t134 = cos_theta * t52;
        let t135 = t104 * cos_theta;
        let t136 = sin_theta * (t135 * t66 - t87 * t22);
        let t137 = t130 * t53;
        let t138 = t52 * t27;
        let t139 = t108 * t49;
        let t140 = t138 * t66 - t139;
        let t141 = -t88 * t22;
        let t142 = t48 * t60;
        let t143 = t142 * k_wall;
        let t144 = mu * t56;
        let t145 = t75 * t77;
        let t146 = t97 * t52;
        let t147 = cos_theta * (rho_p * (-sin_theta + T::from_f64(2.0) * t24) - t33)
            + sin_theta * t34;
        let t148 = t108 * t117;
        let t149 = t103 * t118;
        let t150 = t78 * t85;
        let t151 = t56 * (-t77 + t150);
        let t152 = t142 * t53;
        let t153 = t152 * t56;
        let t154 = t151 * t73;
        let t155 = T::from_f64(1.5) * t56 - T::from_f64(1.5);
        let t156 = t71 * (t92 + t59 - t109 * thetadot * t27);
        let t157 = t79 * (-(t49 * t80) - t105 * t72 * t27);
        let t158 = t145 * t73;
        let t159 = t152 * t155 + t132;
        let t160 = t26 * t28;
        let t161 = t160 * mu;
        let t162 = t77 * t78;
        let t163 = t71 * t124;
        let t164 = t42 * (t21 * t21 * t21);
        let t165 = t129 * t147;
        let t166 = t85 * (t75 * t75 * t75);
        let t167 = t87 * (t161 + t50) + t57;
        let t168 = -t164 + T::from_f64(2.0) * t103;
        let t169 = t73 * t56;
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
                t37
                    * (k_edge
                        * (T::from_f64(1.5) * (-(t39 * t80) - t107 * t22) * t79
                            - t22 * t102 - T::from_f64(2.0) * t99 * t109 * sin_theta)
                        + t110 * k_wall),
                k_edge
                    * (sin_theta * (t116 - t112 * t109) - t22 * t114
                        - T::from_f64(1.5) * t105 * t96 * t40) * t37,
                t37
                    * (k_edge
                        * (t71
                            * (mu
                                * (t52
                                    * (t26 * (-(cos_theta * t21) - sin_theta * t124)
                                        + t126 * sin_theta) - t127 * t117)
                                + T::from_f64(2.0) * t24 * t93) + t22 * t128
                            - T::from_f64(1.5) * t106 * t118)
                        + k_wall * (t110 * t53 - t132) + t2 + t3),
                t37 * (t86 * (mu * (t40 * t66 * t52 - t127 * t22) - t87 * t39) - t133),
                t86 * (t136 - t109 * t40) * t37,
                t37 * (t86 * (sin_theta * t140 * mu + t141) - t137 * t47),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t37
                    * (k_edge
                        * (sin_theta * (t116 - t102)
                            + t103
                                * (-(T::from_f64(1.5) * t146) - T::from_f64(2.0) * t100)
                                * cos_theta * mu) - T::from_f64(1.5) * t143 * t144 * t145),
                k_edge
                    * (T::from_f64(1.5) * (-(t80 * t40) - t107 * cos_theta) * t79
                        - sin_theta * t114 - t109 * t98 * t41) * t37,
                t37
                    * (mu
                        * (k_edge
                            * (t71
                                * (t52
                                    * (t26 * (sin_theta * t21 - cos_theta * t124)
                                        + t126 * cos_theta) - t148 * cos_theta)
                                - T::from_f64(1.5) * t149 * t134)
                            + k_wall
                                * (t129 * (t151 * t147 - t131 * t145)
                                    - T::from_f64(1.5) * t153 * t145))
                        + k_edge * (t94 * cos_theta + sin_theta * t128) + t83 + t84),
                t37 * (t86 * (t136 - t109 * cos_theta * t22) - t133 * t145 * mu),
                t37
                    * (mu * (t86 * (t41 * t66 * t52 - t127 * cos_theta) + t151 * t47)
                        - t86 * t87 * t40),
                t37 * (mu * (cos_theta * t140 * t86 + t47 * (t154 - t137 * t145)) + t89),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t38
                    * (k_edge
                        * (T::from_f64(2.0) * t156 * t24 + T::from_f64(1.5) * t157 * t22
                            - t49 * t102)
                        + t60
                            * (t53 * (t62 - t155 * t48)
                                - T::from_f64(1.5) * t144 * t158 * t48) * k_wall),
                k_edge
                    * (t156 * cos_theta + T::from_f64(1.5) * t157 * sin_theta
                        - t49 * t114) * t38,
                t38
                    * (mu
                        * (k_edge
                            * (t71
                                * (t52
                                    * (t26
                                        * (-(t27 * t124)
                                            - t21
                                                * (cos_theta * (t16 + t123) + sin_theta * (t122 - t19)))
                                        + t126 * t27) - t148 * t27)
                                - T::from_f64(1.5) * t149 * t138)
                            + k_wall
                                * (t46
                                    * (t147 * (t77 * (-t75 - t74) + t74 * t150) * t56
                                        - t131 * t158 * thetadot) - T::from_f64(1.5) * t153 * t158))
                        + k_edge
                            * (t94 * t64 - T::from_f64(1.5) * t115 * t90 - t49 * t121)
                        + k_wall
                            * ((-t48 - t58) * t125 * t46
                                - T::from_f64(1.5) * t60 * t61 * t91 - t53 * t159)),
                t38
                    * (t86 * (t27 * (t52 * t66 * sin_theta - t108 * t22) * mu + t141)
                        + t133 * (-t53 - t158 * mu)),
                t38 * (mu * (t27 * (t134 * t66 - t127) * t86 + t154 * t47) + t89),
                t38
                    * (mu
                        * (t86 * (t27 * t27 * t66 * t52 - t139 * t27)
                            + t47 * (t151 * (t43 * t43) - t137 * t158))
                        + hc_alpha * (-(t86 * t81 * t90) - t47 * t82 * t91)),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                xdot * t4 + zdot * (t83 + t84),
                t0 + t1,
                t4,
                m_2,
                T::from_f64(0.0),
                T::from_f64(0.0),
                k_edge
                    * (t161 * (T::from_f64(1.5) * t146 + t101)
                        + T::from_f64(2.0) * t99 * t57 + t50 * t102)
                    + t143 * (T::from_f64(1.5) * t162 * t144 + t54 * t155),
                k_edge
                    * (t161 * (T::from_f64(1.5) * t111 * t52 + t113) + t112 * t57
                        + t50 * t114),
                mu
                    * (k_edge
                        * (t52
                            * (t26
                                * (T::from_f64(1.5) * t118 * t28
                                    + T::from_f64(2.0) * t163 * t21) - t163 * t164)
                            + t120 * t160)
                        + k_wall
                            * (t56
                                * (t77
                                    * (T::from_f64(1.5) * t152 * t78
                                        + T::from_f64(2.0) * t165 * t75) - t165 * t166)
                                + t132 * t162)) + k_edge * (t119 * t57 + t50 * t121)
                    + k_wall * (t129 * t58 * t125 + t54 * t159),
                t86 * (t22 * t167 + sin_theta * t168 * t104)
                    + t47 * (t130 * (t162 * mu + t54) + t56 - T::from_f64(1.0)),
                t86 * (sin_theta * t167 + t135 * t168)
                    + t47 * (-t166 + T::from_f64(2.0) * t145) * t144,
                mu
                    * (t86
                        * (t26 * (t88 * t28 + T::from_f64(2.0) * t138 * t21)
                            - t164 * t138)
                        + t47
                            * (t77 * (t137 * t78 + T::from_f64(2.0) * t169 * t75)
                                - t169 * t166)) + t86 * (t57 + t87 * t50) * t49
                    + t47 * (t58 + t130 * t54) * t53,
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
    /// 32 add/sub, 64 mul, 6 div, 2 sqrt, 6 transcendental, 4 branches; 32 `let`s.
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
        let t16 = -rho_p;
        let t17 = l_c + t16;
        let t18 = r + t16;
        let t19 = zdot
            + thetadot
                * (-(sin_theta * (l_c + t16 + rho_p * sin_theta))
                    - cos_theta * (r - T::from_f64(2.0) * rho_p * t6));
        let t20 = v_s.hypot(t19);
        let t21 = r + t0 + x + sin_theta * t17 - T::from_f64(2.0) * t6 * t18;
        let t22 = t21.max0();
        let t23 = t22 * t22.sqrt();
        let t24 = (T::from_f64(1.0)
            + hc_alpha
                * (xdot * (-T::from_f64(1.0) + T::from_f64(2.0) * t6) + zdot * sin_theta
                    + thetadot * (-t8 - T::from_f64(2.0) * t14 * t2)))
            .max0();
        let t25 = (T::from_f64(1.0)
            + hc_alpha
                * (xdot + thetadot * (cos_theta * t17 - T::from_f64(2.0) * t14 * t18)))
            .max0();
        let t26 = k_edge * t12 * t24;
        let t27 = (T::from_f64(1.5) * t26 / (e_star * edge_sum)).cbrt();
        let t28 = k_wall * t25 * t23;
        let t29 = (T::from_f64(1.5) * t28 / (e_star * wall_sum)).cbrt();
        let normal = Vector2::new(t26, t28);
        let friction = Vector2::new(-t26 * mu * t10 / t15, -t28 * mu * t19 / t20);
        let delta = Vector2::new(t7, t21);
        let slip = Vector2::new(t10, t19);
        let a = Vector2::new(edge_ma * t27, wall_ma * t29);
        let b = Vector2::new(edge_mb * t27, wall_mb * t29);
        let p0 = Vector2::new(
            T::from_f64(0.3183098861837907) * e_star * edge_sum * t27
                / (edge_ma * edge_mb),
            T::from_f64(0.3183098861837907) * e_star * wall_sum * t29
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
    /// 17 add/sub, 19 mul, 0 div, 0 sqrt, 4 transcendental, 2 branches; 11 `let`s.
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
        let kinetic = T::from_f64(0.5)
            * (m * (xdot * xdot + zdot * zdot) + j * (thetadot * thetadot));
        let potential = T::from_f64(0.4) * (k_edge * t5 + k_wall * t8);
        let depth = z + l_c * cos_theta;
        (kinetic, potential, depth)
    }
}
