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
    /// 58 add/sub, 81 mul, 5 div, 2 sqrt, 4 transcendental, 8 branches; 48 `let`s.
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
        let t3 = -rho_h + t2 - x;
        let t4 = T::from_f64(0.5) * theta;
        let (t5, t6) = t4.sin_cos();
        let t7 = t5 * t5;
        let t8 = t5 * t6;
        let t9 = l_c - rho_p;
        let t10 = r - rho_p;
        let t11 = -rho_h + z;
        let delta_edge_left = r + t2 - x + sin_theta * t11 - T::from_f64(2.0) * t3 * t7;
        let pen_edge_left = delta_edge_left.max0();
        let t12 = pen_edge_left * pen_edge_left.sqrt();
        let t13 = T::from_f64(1.0) - T::from_f64(2.0) * t7;
        let t14 = cos_theta * t11;
        let t15 = k_edge * t12;
        let step_delta_edge_left = delta_edge_left.step();
        let t16 = sin_theta * (l_c - rho_p + rho_p * sin_theta)
            + cos_theta * (r - T::from_f64(2.0) * rho_p * t7);
        let slip_wall_right = zdot - thetadot * t16;
        let t17 = v_s.hypot(slip_wall_right);
        let delta_wall_right = r + t2 + x + sin_theta * t9 - T::from_f64(2.0) * t7 * t10;
        let pen_wall_right = delta_wall_right.max0();
        let t18 = pen_wall_right * pen_wall_right.sqrt();
        let elastic_wall_right = k_wall * t18;
        let step_delta_wall_right = delta_wall_right.step();
        let t19 = cos_theta * t9 - T::from_f64(2.0) * t8 * t10;
        let delta_rate_wall_right = xdot + thetadot * t19;
        let t20 = (T::from_f64(1.0) + hc_alpha * delta_rate_wall_right).max0();
        let t21 = sin_theta * t3 - t14;
        let t22 = cos_theta * t21 + r * sin_theta;
        let t23 = -(sin_theta * t21) + r * cos_theta;
        let slip_edge_left = sin_theta * (xdot + thetadot * t22)
            + cos_theta * (zdot + thetadot * t23);
        let t24 = t14 - T::from_f64(2.0) * t8 * t3;
        let delta_rate_edge_left = -(xdot * t13) + zdot * sin_theta + thetadot * t24;
        let t25 = (T::from_f64(1.0) + hc_alpha * delta_rate_edge_left).max0();
        let t26 = v_s.hypot(slip_edge_left);
        let t27 = -t25 + T::from_f64(1.0);
        let t28 = -t20 + T::from_f64(1.0);
        let t29 = t25 / t26;
        let t30 = t29 * (mu * slip_edge_left);
        let t31 = t20 / t17;
        let t32 = elastic_wall_right * t31;
        let t33 = mu * slip_wall_right;
        let t34 = step_delta_edge_left - t27;
        SMatrix::<
            T,
            8,
            1,
        >::from_row_slice(
            &[
                xdot,
                zdot,
                thetadot,
                (-(t15 * (-(t13 * t34) + t30 * sin_theta))
                    - elastic_wall_right
                        * (-T::from_f64(1.0) + step_delta_wall_right + t20) + t0 + t1)
                    / m,
                -(sin_theta * (t15 * t34 + f2) + cos_theta * (-f1 + t30 * t15)
                    + t32 * t33) / m,
                (m_2 - t15 * (t24 * t34 + t30 * (sin_theta * t22 + cos_theta * t23))
                    + elastic_wall_right
                        * (-(t19 * (step_delta_wall_right - t28)) + t33 * t31 * t16))
                    / j,
                xdot * (t0 + t1) + zdot * (f1 * cos_theta - f2 * sin_theta)
                    + thetadot * m_2,
                mu
                    * (t29 * t15 * (slip_edge_left * slip_edge_left)
                        + t32 * (slip_wall_right * slip_wall_right))
                    - t15 * delta_rate_edge_left * t27
                    - elastic_wall_right * delta_rate_wall_right * t28,
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
    /// 199 add/sub, 442 mul, 6 div, 4 sqrt, 4 transcendental, 12 branches; 167 `let`s.
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
        let t2 = t0 + t1;
        let t3 = f1 * cos_theta;
        let t4 = f2 * sin_theta;
        let t5 = -T::from_f64(0.5) * d;
        let t6 = -rho_h + t5 - x;
        let t7 = T::from_f64(0.5) * theta;
        let (t8, t9) = t7.sin_cos();
        let t10 = t8 * t8;
        let t11 = t8 * t9;
        let t12 = l_c - rho_p;
        let t13 = r - rho_p;
        let t14 = sin_theta * t12;
        let t15 = l_c - rho_p + rho_p * sin_theta;
        let t16 = r - T::from_f64(2.0) * rho_p * t10;
        let t17 = cos_theta * t16;
        let t18 = sin_theta * t15;
        let t19 = T::from_f64(1.0) / m;
        let t20 = T::from_f64(1.0) / j;
        let t21 = sin_theta * sin_theta;
        let t22 = cos_theta * cos_theta;
        let t23 = t17 + t18;
        let t24 = -rho_h + z;
        let t25 = sin_theta * t24;
        let delta_edge_left = r + t5 - x + t25 - T::from_f64(2.0) * t6 * t10;
        let pen_edge_left = delta_edge_left.max0();
        let t26 = pen_edge_left * pen_edge_left.sqrt();
        let t27 = T::from_f64(1.0) - T::from_f64(2.0) * t10;
        let t28 = cos_theta * t24;
        let t29 = k_edge * t26;
        let step_delta_edge_left = delta_edge_left.step();
        let t30 = t18 + t17;
        let delta_wall_right = r + t5 + x + t14 - T::from_f64(2.0) * t10 * t13;
        let pen_wall_right = delta_wall_right.max0();
        let t31 = pen_wall_right * pen_wall_right.sqrt();
        let elastic_wall_right = k_wall * t31;
        let step_delta_wall_right = delta_wall_right.step();
        let t32 = cos_theta * t12 - T::from_f64(2.0) * t11 * t13;
        let delta_rate_wall_right = xdot + thetadot * t32;
        let t33 = T::from_f64(1.0) + hc_alpha * delta_rate_wall_right;
        let t34 = t33.max0();
        let t35 = sin_theta * t6 - t28;
        let t36 = cos_theta * t35;
        let t37 = t36 + r * sin_theta;
        let t38 = xdot + thetadot * t37;
        let t39 = t28 - T::from_f64(2.0) * t11 * t6;
        let delta_rate_edge_left = -(xdot * t27) + zdot * sin_theta + thetadot * t39;
        let t40 = T::from_f64(1.0) + hc_alpha * delta_rate_edge_left;
        let t41 = t40.max0();
        let t42 = -t41 + T::from_f64(1.0);
        let t43 = -t34 + T::from_f64(1.0);
        let t44 = step_delta_edge_left - t42;
        let t45 = t26 * t44;
        let sqrt_pen_edge_left = pen_edge_left.sqrt();
        let t46 = t27 * t27;
        let t47 = step_delta_edge_left * step_delta_edge_left;
        let sqrt_pen_wall_right = pen_wall_right.sqrt();
        let t48 = step_delta_wall_right * step_delta_wall_right;
        let t49 = r + cos_theta * t6 + t25;
        let t50 = -T::from_f64(1.5) * t48;
        let t51 = thetadot * t30;
        let t52 = t10 - t9 * t9;
        let t53 = -(t6 * t52) + t25;
        let t54 = -(t13 * t52) + t14;
        let t55 = t3 - t4;
        let t56 = t33.step();
        let t57 = t32 * t32;
        let t58 = sin_theta * t35;
        let t59 = -t58 + r * cos_theta;
        let t60 = zdot + thetadot * t59;
        let slip_edge_left = sin_theta * t38 + cos_theta * t60;
        let t61 = v_s.hypot(slip_edge_left);
        let t62 = T::from_f64(1.0) / t61;
        let t63 = sin_theta * t37 + cos_theta * t59;
        let t64 = slip_edge_left * slip_edge_left;
        let slip_wall_right = zdot - t51;
        let t65 = v_s.hypot(slip_wall_right);
        let t66 = T::from_f64(1.0) / t65;
        let t67 = slip_wall_right * slip_wall_right;
        let t68 = t40.step();
        let t69 = T::from_f64(1.0) / (t61 * t61 * t61);
        let t70 = T::from_f64(1.0) / (t65 * t65 * t65);
        let t71 = hc_alpha * t68;
        let t72 = t71 * t39;
        let t73 = t72 * t29 * sin_theta;
        let t74 = t39 * t39;
        let t75 = hc_alpha * t56;
        let t76 = elastic_wall_right * t75;
        let t77 = t75 * t32;
        let t78 = T::from_f64(1.5) * t34;
        let t79 = t78 - T::from_f64(1.5);
        let t80 = -(T::from_f64(1.5) * t41) + T::from_f64(1.5);
        let t81 = step_delta_edge_left * sqrt_pen_edge_left;
        let t82 = t81 * t80;
        let t83 = thetadot * t26;
        let t84 = t11 * t83;
        let t85 = T::from_f64(2.0) * t84 * t71;
        let t86 = t82 * t27 + t85;
        let t87 = slip_edge_left * t62;
        let t88 = t71 * t87;
        let t89 = t88 * t83;
        let t90 = mu * sin_theta;
        let t91 = t83 * cos_theta;
        let t92 = t91 * t71;
        let t93 = sqrt_pen_edge_left * t47;
        let t94 = T::from_f64(1.5) * t93 * t27;
        let t95 = mu * cos_theta;
        let t96 = mu * t21;
        let t97 = t87 * t41;
        let t98 = sin_theta * t49 + t36;
        let t99 = -T::from_f64(1.5) * t34;
        let t100 = t64 * t69;
        let t101 = t41 * (t62 - t100);
        let t102 = t88 * t39;
        let t103 = t101 * t63 + t102;
        let t104 = t97 * step_delta_edge_left;
        let t105 = t67 * t70;
        let t106 = t88 * t27;
        let t107 = t88 * sin_theta;
        let t108 = t34 * (t66 - t105);
        let t109 = slip_wall_right * t66;
        let t110 = mu * t63;
        let t111 = sqrt_pen_edge_left * (t39 * t47 + t104 * t110);
        let t112 = mu * t34;
        let t113 = t109 * t30;
        let t114 = step_delta_wall_right * sqrt_pen_wall_right;
        let t115 = t114 * t32;
        let t116 = t81 * t39;
        let t117 = t97 * t116;
        let t118 = t72 * t27;
        let t119 = t81 * t41;
        let t120 = -(T::from_f64(1.5) * t119 * t27) + t85;
        let t121 = t62 * t64;
        let t122 = t121 * mu;
        let t123 = t66 * t67;
        let t124 = t114 * k_wall;
        let t125 = t69 * (slip_edge_left * slip_edge_left * slip_edge_left);
        let t126 = t41 * (-t125 + T::from_f64(2.0) * t87);
        let t127 = t70 * (slip_wall_right * slip_wall_right * slip_wall_right);
        let t128 = t41 * t63;
        let t129 = t34 * t30;
        let t130 = -(t82 * sin_theta) + t92;
        let t131 = T::from_f64(2.0) * t11 * xdot + zdot * cos_theta - thetadot * t53;
        let t132 = t26 * t131;
        let t133 = t71 * t132;
        let t134 = -(t116 * t80) + t133;
        let t135 = -(cos_theta * t49) + t58;
        let t136 = cos_theta * (-t38 + thetadot * t98)
            + sin_theta * (thetadot * t135 + t60);
        let t137 = t100 * t136;
        let t138 = T::from_f64(1.5) * t93 * t39 + t134;
        let t139 = thetadot * t31;
        let t140 = t75 * t54;
        let t141 = t139 * t140;
        let t142 = -t101 * t95 + t71 * t27;
        let t143 = -(cos_theta * (rho_p * (sin_theta - T::from_f64(2.0) * t11) + t15))
            + sin_theta * t16;
        let t144 = t88 * t131;
        let t145 = t115 * t34;
        let t146 = t108 * t30;
        let t147 = t26 * (step_delta_edge_left - t42 + t110 * t88 * thetadot);
        let t148 = t115 * (t99 + T::from_f64(1.5)) + t141;
        let t149 = t26 * t136;
        let t150 = t139 * t143;
        let t151 = -t71 * (t122 + delta_rate_edge_left) + t42;
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
                -t19
                    * (k_edge
                        * (-(T::from_f64(1.5) * (-(t46 * t47) + t104 * t90 * t27)
                            * sqrt_pen_edge_left) - t27 * t86
                            + T::from_f64(2.0) * t89 * t90 * t11)
                        + sqrt_pen_wall_right
                            * (step_delta_wall_right * (-T::from_f64(1.5) + t78)
                                + T::from_f64(1.5) * t48) * k_wall),
                k_edge
                    * (sin_theta * (t94 - t89 * t95) + t27 * t130
                        - T::from_f64(1.5) * t96 * t97 * t81) * t19,
                -t19
                    * (k_edge
                        * (t26
                            * (mu
                                * (t41
                                    * (-(t62
                                        * (-(cos_theta * slip_edge_left) + sin_theta * t136))
                                        + t137 * sin_theta) + t107 * t131)
                                + T::from_f64(2.0) * t11 * t44) - t27 * t138
                            + T::from_f64(1.5) * t117 * t90)
                        - k_wall
                            * (sqrt_pen_wall_right
                                * (step_delta_wall_right * (T::from_f64(1.5) + t99) + t50)
                                * t32 + t141) - t3 + t4),
                -t19 * (-(t29 * (mu * (-(t101 * t21) + t107 * t27) - t71 * t46)) + t76),
                -(t29 * (-(sin_theta * t142) + t96 * t88)) * t19,
                -t19 * (-(t29 * (-(t90 * t103) + t118)) + t77 * elastic_wall_right),
                T::from_f64(0.0),
                T::from_f64(0.0),
                -t19
                    * (-(k_edge * (sin_theta * (t94 - t86) - t87 * t120 * t95))
                        + T::from_f64(1.5) * t124 * t112 * t109),
                -(k_edge
                    * (T::from_f64(1.5) * (t47 * t21 + t104 * t95 * sin_theta)
                        * sqrt_pen_edge_left + sin_theta * t130 + t89 * mu * t22)) * t19,
                -t19
                    * (mu
                        * (k_edge
                            * (t26
                                * (t41
                                    * (-(t62 * (sin_theta * slip_edge_left + cos_theta * t136))
                                        + t137 * cos_theta) + t144 * cos_theta)
                                + T::from_f64(1.5) * t117 * cos_theta)
                            + k_wall
                                * (-(t139 * (-(t108 * t143) + t140 * t109))
                                    + T::from_f64(1.5) * t145 * t109))
                        + k_edge * (t45 * cos_theta + sin_theta * t138) + t0 + t1),
                -t19 * (-(t29 * (sin_theta * t142 + t106 * t95)) + t76 * t109 * mu),
                -t19
                    * (mu
                        * (t29 * (t101 * t22 + t107 * cos_theta)
                            + t108 * elastic_wall_right) + t29 * t71 * t21),
                -t19
                    * (mu
                        * (cos_theta * t103 * t29
                            + elastic_wall_right * (-t146 + t77 * t109)) + t73),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t20
                    * (k_edge
                        * (-(T::from_f64(2.0) * t147 * t11)
                            + T::from_f64(1.5) * t111 * t27 - t39 * t86)
                        + sqrt_pen_wall_right
                            * (t32 * (t50 - t79 * step_delta_wall_right)
                                + T::from_f64(1.5) * t112 * t113 * step_delta_wall_right)
                            * k_wall),
                k_edge
                    * (-(t147 * cos_theta) - T::from_f64(1.5) * t111 * sin_theta
                        - t39 * t130) * t20,
                -t20
                    * (mu
                        * (k_edge
                            * (t26
                                * (-(t41
                                    * (t62
                                        * (t63 * t136
                                            + slip_edge_left
                                                * (-(cos_theta * (t37 - t98)) + sin_theta * (t135 + t59)))
                                        - t137 * t63)) + t144 * t63)
                                + T::from_f64(1.5) * t117 * t63)
                            - k_wall
                                * (-(t31
                                    * (t143 * (-(t66 * (-slip_wall_right + t51)) + t51 * t105)
                                        * t34 + t140 * t113 * thetadot))
                                    + T::from_f64(1.5) * t145 * t113))
                        + k_edge
                            * (-(t45 * t53) + T::from_f64(1.5) * t93 * t74 + t39 * t134)
                        + k_wall
                            * (-((step_delta_wall_right - t43) * t54 * t31)
                                + T::from_f64(1.5) * sqrt_pen_wall_right * t48 * t57
                                - t32 * t148)),
                t20
                    * (t29 * (t110 * (-(t101 * sin_theta) + t106) + t118)
                        + t76 * (-t32 + t113 * mu)),
                -t20
                    * (mu
                        * (t63 * (t101 * cos_theta + t107) * t29
                            - t146 * elastic_wall_right) + t73),
                -t20
                    * (mu
                        * (t29 * (t101 * (t63 * t63) + t102 * t63)
                            - elastic_wall_right * (-(t108 * (t23 * t23)) + t77 * t113))
                        + hc_alpha * (t29 * t68 * t74 + elastic_wall_right * t56 * t57)),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                xdot * t55 - zdot * t2,
                t2,
                t55,
                m_2,
                T::from_f64(0.0),
                T::from_f64(0.0),
                k_edge
                    * (t122 * t120 - T::from_f64(2.0) * t84 * t42
                        + delta_rate_edge_left * t86)
                    + t124
                        * (T::from_f64(1.5) * t123 * t112 + delta_rate_wall_right * t79),
                k_edge
                    * (t122 * (T::from_f64(1.5) * t119 * sin_theta + t92) - t91 * t42
                        + delta_rate_edge_left * t130),
                mu
                    * (k_edge
                        * (t41
                            * (-(t62
                                * (-(T::from_f64(1.5) * t116 * t64)
                                    + T::from_f64(2.0) * t149 * slip_edge_left)) + t149 * t125)
                            + t133 * t121)
                        - k_wall
                            * (t34
                                * (-(t66
                                    * (T::from_f64(1.5) * t115 * t67
                                        + T::from_f64(2.0) * t150 * slip_wall_right)) + t150 * t127)
                                + t141 * t123))
                    - k_edge * (t132 * t42 - delta_rate_edge_left * t134)
                    + k_wall * (t139 * t43 * t54 - delta_rate_wall_right * t148),
                t29 * (t27 * t151 + t126 * t90)
                    + elastic_wall_right
                        * (t75 * (t123 * mu + delta_rate_wall_right) + t34
                            - T::from_f64(1.0)),
                -(t29 * (sin_theta * t151 - t126 * t95))
                    + elastic_wall_right * (-t127 + T::from_f64(2.0) * t109) * t112,
                mu
                    * (-(t29
                        * (-(t62
                            * (t72 * t64 + T::from_f64(2.0) * t128 * slip_edge_left))
                            + t128 * t125))
                        + elastic_wall_right
                            * (t66
                                * (t77 * t67 - T::from_f64(2.0) * t129 * slip_wall_right)
                                + t129 * t127))
                    + t29 * (-t42 + t71 * delta_rate_edge_left) * t39
                    + elastic_wall_right * (-t43 + t75 * delta_rate_wall_right) * t32,
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
        let t1 = -rho_h + t0 - x;
        let t2 = T::from_f64(0.5) * theta;
        let (t3, t4) = t2.sin_cos();
        let t5 = t3 * t3;
        let t6 = t3 * t4;
        let t7 = l_c - rho_p;
        let t8 = r - rho_p;
        let t9 = -rho_h + z;
        let delta_edge_left = r + t0 - x + sin_theta * t9 - T::from_f64(2.0) * t1 * t5;
        let pen_edge_left = delta_edge_left.max0();
        let t10 = pen_edge_left * pen_edge_left.sqrt();
        let t11 = cos_theta * t9;
        let slip_wall_right = zdot
            - thetadot
                * (sin_theta * (l_c - rho_p + rho_p * sin_theta)
                    + cos_theta * (r - T::from_f64(2.0) * rho_p * t5));
        let t12 = v_s.hypot(slip_wall_right);
        let delta_wall_right = r + t0 + x + sin_theta * t7 - T::from_f64(2.0) * t5 * t8;
        let pen_wall_right = delta_wall_right.max0();
        let t13 = pen_wall_right * pen_wall_right.sqrt();
        let delta_rate_wall_right = xdot
            + thetadot * (cos_theta * t7 - T::from_f64(2.0) * t6 * t8);
        let t14 = (T::from_f64(1.0) + hc_alpha * delta_rate_wall_right).max0();
        let t15 = sin_theta * t1 - t11;
        let slip_edge_left = sin_theta
            * (xdot + thetadot * (cos_theta * t15 + r * sin_theta))
            + cos_theta * (zdot + thetadot * (-(sin_theta * t15) + r * cos_theta));
        let delta_rate_edge_left = -(xdot * (T::from_f64(1.0) - T::from_f64(2.0) * t5))
            + zdot * sin_theta + thetadot * (t11 - T::from_f64(2.0) * t6 * t1);
        let t16 = (T::from_f64(1.0) + hc_alpha * delta_rate_edge_left).max0();
        let t17 = v_s.hypot(slip_edge_left);
        let normal_edge_left = k_edge * t10 * t16;
        let normal_wall_right = k_wall * t14 * t13;
        let t18 = (T::from_f64(1.5) * normal_edge_left / (e_star * edge_sum)).cbrt();
        let t19 = (T::from_f64(1.5) * normal_wall_right / (e_star * wall_sum)).cbrt();
        let normal = Vector2::new(normal_edge_left, normal_wall_right);
        let friction = Vector2::new(
            -normal_edge_left * mu * slip_edge_left / t17,
            -normal_wall_right * mu * slip_wall_right / t12,
        );
        let delta = Vector2::new(delta_edge_left, delta_wall_right);
        let slip = Vector2::new(slip_edge_left, slip_wall_right);
        let a = Vector2::new(edge_ma * t18, wall_ma * t19);
        let b = Vector2::new(edge_mb * t18, wall_mb * t19);
        let p0 = Vector2::new(
            T::from_f64(0.3183098861837907) * e_star * edge_sum * t18
                / (edge_ma * edge_mb),
            T::from_f64(0.3183098861837907) * e_star * wall_sum * t19
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
        let t1 = (T::from_f64(0.5) * theta).sin();
        let t2 = t1 * t1;
        let delta_edge_left = r + t0 - x + sin_theta * (-rho_h + z)
            - T::from_f64(2.0) * (-rho_h + t0 - x) * t2;
        let pen_edge_left = delta_edge_left.max0();
        let delta_wall_right = r + t0 + x + sin_theta * (l_c - rho_p)
            - T::from_f64(2.0) * t2 * (r - rho_p);
        let pen_wall_right = delta_wall_right.max0();
        let t3 = pen_edge_left.powf(T::from_f64(2.5));
        let t4 = pen_wall_right.powf(T::from_f64(2.5));
        let kinetic = T::from_f64(0.5)
            * (m * (xdot * xdot + zdot * zdot) + j * (thetadot * thetadot));
        let potential = T::from_f64(0.4) * (k_edge * t3 + k_wall * t4);
        let depth = z + l_c * cos_theta;
        (kinetic, potential, depth)
    }
}
