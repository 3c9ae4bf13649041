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
    /// 59 add/sub, 81 mul, 5 div, 2 sqrt, 4 transcendental, 8 branches; 48 `let`s.
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
        let t11 = cos_theta * (r - T::from_f64(2.0) * rho_p * t7)
            + sin_theta * (l_c - rho_p + rho_p * sin_theta);
        let t12 = T::from_f64(1.0) - T::from_f64(2.0) * t7;
        let slip_wall_right = zdot - thetadot * t11;
        let t13 = v_s.hypot(slip_wall_right);
        let delta_wall_right = r + t2 + x + sin_theta * t9 - T::from_f64(2.0) * t7 * t10;
        let pen_wall_right = delta_wall_right.max0();
        let t14 = pen_wall_right * pen_wall_right.sqrt();
        let elastic_wall_right = k_wall * t14;
        let step_delta_wall_right = delta_wall_right.step();
        let t15 = -rho_h + z;
        let delta_edge_left = r + t2 - x + sin_theta * t15 - T::from_f64(2.0) * t3 * t7;
        let pen_edge_left = delta_edge_left.max0();
        let t16 = pen_edge_left * pen_edge_left.sqrt();
        let t17 = cos_theta * t15;
        let t18 = k_edge * t16;
        let step_delta_edge_left = delta_edge_left.step();
        let t19 = cos_theta * t9 - T::from_f64(2.0) * t8 * t10;
        let delta_rate_wall_right = xdot + thetadot * t19;
        let t20 = (T::from_f64(1.0) + hc_alpha * delta_rate_wall_right).max0();
        let t21 = T::from_f64(1.0) - t20;
        let t22 = sin_theta * t3 - t17;
        let t23 = cos_theta * t22 + r * sin_theta;
        let t24 = -(sin_theta * t22) + r * cos_theta;
        let slip_edge_left = sin_theta * (xdot + thetadot * t23)
            + cos_theta * (zdot + thetadot * t24);
        let t25 = t17 - T::from_f64(2.0) * t8 * t3;
        let delta_rate_edge_left = -(xdot * t12) + zdot * sin_theta + thetadot * t25;
        let t26 = (T::from_f64(1.0) + hc_alpha * delta_rate_edge_left).max0();
        let t27 = -t26 + T::from_f64(1.0);
        let t28 = v_s.hypot(slip_edge_left);
        let t29 = -step_delta_edge_left + t27;
        let t30 = t26 / t28;
        let t31 = t30 * (mu * slip_edge_left);
        let t32 = t20 / t13;
        let t33 = elastic_wall_right * t32;
        let t34 = mu * slip_wall_right;
        SMatrix::<
            T,
            8,
            1,
        >::from_row_slice(
            &[
                xdot,
                zdot,
                thetadot,
                (-(t18 * (t12 * t29 + t31 * sin_theta))
                    - elastic_wall_right
                        * (-T::from_f64(1.0) + step_delta_wall_right + t20) + t0 + t1)
                    / m,
                -(sin_theta * (-(t18 * (t27 - step_delta_edge_left)) + f2)
                    + cos_theta * (-f1 + t31 * t18) + t33 * t34) / m,
                (m_2 - t18 * (-(t25 * t29) + t31 * (sin_theta * t23 + cos_theta * t24))
                    + elastic_wall_right
                        * (-(t19 * (step_delta_wall_right - t21)) + t34 * t32 * t11))
                    / j,
                xdot * (t0 + t1) + zdot * (f1 * cos_theta - f2 * sin_theta)
                    + thetadot * m_2,
                mu
                    * (t30 * t18 * (slip_edge_left * slip_edge_left)
                        + t33 * (slip_wall_right * slip_wall_right))
                    - t18 * delta_rate_edge_left * t27
                    - elastic_wall_right * delta_rate_wall_right * t21,
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
    /// 203 add/sub, 443 mul, 6 div, 4 sqrt, 4 transcendental, 12 branches; 165 `let`s.
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
        let t17 = T::from_f64(1.0) / m;
        let t18 = T::from_f64(1.0) / j;
        let t19 = sin_theta * sin_theta;
        let t20 = cos_theta * cos_theta;
        let t21 = cos_theta * t16 + sin_theta * t15;
        let t22 = T::from_f64(1.0) - T::from_f64(2.0) * t10;
        let delta_wall_right = r + t5 + x + t14 - T::from_f64(2.0) * t10 * t13;
        let pen_wall_right = delta_wall_right.max0();
        let t23 = pen_wall_right * pen_wall_right.sqrt();
        let elastic_wall_right = k_wall * t23;
        let step_delta_wall_right = delta_wall_right.step();
        let t24 = -rho_h + z;
        let t25 = sin_theta * t24;
        let delta_edge_left = r + t5 - x + t25 - T::from_f64(2.0) * t6 * t10;
        let pen_edge_left = delta_edge_left.max0();
        let t26 = pen_edge_left * pen_edge_left.sqrt();
        let t27 = cos_theta * t24;
        let t28 = k_edge * t26;
        let step_delta_edge_left = delta_edge_left.step();
        let t29 = cos_theta * t12 - T::from_f64(2.0) * t11 * t13;
        let delta_rate_wall_right = xdot + thetadot * t29;
        let t30 = T::from_f64(1.0) + hc_alpha * delta_rate_wall_right;
        let t31 = t30.max0();
        let t32 = T::from_f64(1.0) - t31;
        let t33 = sin_theta * t6 - t27;
        let t34 = cos_theta * t33;
        let t35 = t34 + r * sin_theta;
        let t36 = xdot + thetadot * t35;
        let t37 = t27 - T::from_f64(2.0) * t11 * t6;
        let delta_rate_edge_left = -(xdot * t22) + zdot * sin_theta + thetadot * t37;
        let t38 = T::from_f64(1.0) + hc_alpha * delta_rate_edge_left;
        let t39 = t38.max0();
        let t40 = -t39 + T::from_f64(1.0);
        let t41 = -step_delta_edge_left + t40;
        let t42 = t22 * t22;
        let sqrt_pen_wall_right = pen_wall_right.sqrt();
        let t43 = step_delta_wall_right * step_delta_wall_right;
        let sqrt_pen_edge_left = pen_edge_left.sqrt();
        let t44 = step_delta_edge_left * step_delta_edge_left;
        let t45 = r + cos_theta * t6 + t25;
        let t46 = -T::from_f64(1.5) * t43;
        let t47 = thetadot * t21;
        let t48 = t10 - t9 * t9;
        let t49 = -(t6 * t48) + t25;
        let t50 = -(t13 * t48) + t14;
        let t51 = t3 - t4;
        let t52 = t30.step();
        let t53 = t29 * t29;
        let slip_wall_right = zdot - t47;
        let t54 = v_s.hypot(slip_wall_right);
        let t55 = T::from_f64(1.0) / t54;
        let t56 = slip_wall_right * slip_wall_right;
        let t57 = sin_theta * t33;
        let t58 = -t57 + r * cos_theta;
        let t59 = zdot + thetadot * t58;
        let slip_edge_left = sin_theta * t36 + cos_theta * t59;
        let t60 = v_s.hypot(slip_edge_left);
        let t61 = T::from_f64(1.0) / t60;
        let t62 = sin_theta * t35 + cos_theta * t58;
        let t63 = slip_edge_left * slip_edge_left;
        let t64 = T::from_f64(1.0) / (t54 * t54 * t54);
        let t65 = hc_alpha * t52;
        let t66 = elastic_wall_right * t65;
        let t67 = t65 * t29;
        let t68 = T::from_f64(1.5) * t31;
        let t69 = t68 - T::from_f64(1.5);
        let t70 = t38.step();
        let t71 = -T::from_f64(1.5) * t39;
        let t72 = step_delta_edge_left * sqrt_pen_edge_left;
        let t73 = t72 * t22;
        let t74 = thetadot * t26;
        let t75 = t11 * t74;
        let t76 = hc_alpha * t70;
        let t77 = T::from_f64(2.0) * t75 * t76;
        let t78 = t73 * (t71 + T::from_f64(1.5)) + t77;
        let t79 = slip_edge_left * t61;
        let t80 = t76 * t79;
        let t81 = t80 * t74;
        let t82 = mu * sin_theta;
        let t83 = t74 * cos_theta;
        let t84 = t83 * t76;
        let t85 = sqrt_pen_edge_left * t44;
        let t86 = T::from_f64(1.5) * t85 * t22;
        let t87 = mu * cos_theta;
        let t88 = mu * t19;
        let t89 = t79 * t39;
        let t90 = sin_theta * t45 + t34;
        let t91 = T::from_f64(1.0) / (t60 * t60 * t60);
        let t92 = -T::from_f64(1.5) * t31;
        let t93 = t63 * t91;
        let t94 = t39 * (t61 - t93);
        let t95 = t80 * t37;
        let t96 = t94 * t62 + t95;
        let t97 = t89 * step_delta_edge_left;
        let t98 = t56 * t64;
        let t99 = t26 * t41;
        let t100 = t76 * t22;
        let t101 = t80 * t22;
        let t102 = t80 * sin_theta;
        let t103 = t31 * (t55 - t98);
        let t104 = t76 * t37;
        let t105 = t104 * t28 * sin_theta;
        let t106 = slip_wall_right * t55;
        let t107 = mu * t62;
        let t108 = sqrt_pen_edge_left * (t37 * t44 + t97 * t107);
        let t109 = mu * t31;
        let t110 = t106 * t21;
        let t111 = t37 * t37;
        let t112 = step_delta_wall_right * sqrt_pen_wall_right;
        let t113 = t112 * t29;
        let t114 = t72 * t37;
        let t115 = t89 * t114;
        let t116 = t104 * t22;
        let t117 = -T::from_f64(1.5) * t73 * t39;
        let t118 = t61 * t63;
        let t119 = t118 * mu;
        let t120 = t55 * t56;
        let t121 = t112 * k_wall;
        let t122 = t72 * sin_theta;
        let t123 = t91 * (slip_edge_left * slip_edge_left * slip_edge_left);
        let t124 = t39 * (-t123 + T::from_f64(2.0) * t79);
        let t125 = t64 * (slip_wall_right * slip_wall_right * slip_wall_right);
        let t126 = t39 * t62;
        let t127 = t31 * t21;
        let t128 = T::from_f64(1.5) + t71;
        let t129 = -(t122 * t128) + t84;
        let t130 = T::from_f64(2.0) * t11 * xdot + zdot * cos_theta - thetadot * t49;
        let t131 = t26 * t130;
        let t132 = t76 * t131;
        let t133 = -(t114 * t128) + t132;
        let t134 = -(cos_theta * t45) + t57;
        let t135 = cos_theta * (-t36 + thetadot * t90)
            + sin_theta * (t59 + thetadot * t134);
        let t136 = t93 * t135;
        let t137 = T::from_f64(1.5) * t85 * t37 + t133;
        let t138 = thetadot * t23;
        let t139 = t65 * t50;
        let t140 = t138 * t139;
        let t141 = t94 * t87;
        let t142 = sin_theta * t16
            - cos_theta * (rho_p * (sin_theta - T::from_f64(2.0) * t11) + t15);
        let t143 = t80 * t130;
        let t144 = t113 * t31;
        let t145 = t103 * t21;
        let t146 = t26 * (step_delta_edge_left - t40 + t107 * t80 * thetadot);
        let t147 = t113 * (t92 + T::from_f64(1.5)) + t140;
        let t148 = t26 * t135;
        let t149 = t138 * t142;
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
                -t17
                    * (k_edge
                        * (-(T::from_f64(1.5) * (-(t42 * t44) + t97 * t82 * t22)
                            * sqrt_pen_edge_left) - t22 * t78
                            + T::from_f64(2.0) * t81 * t82 * t11)
                        + sqrt_pen_wall_right
                            * (step_delta_wall_right * (-T::from_f64(1.5) + t68)
                                + T::from_f64(1.5) * t43) * k_wall),
                k_edge
                    * (sin_theta * (t86 - t81 * t87) + t22 * t129
                        - T::from_f64(1.5) * t88 * t89 * t72) * t17,
                -t17
                    * (k_edge
                        * (t26
                            * (mu
                                * (t39
                                    * (-(t61
                                        * (-(cos_theta * slip_edge_left) + sin_theta * t135))
                                        + t136 * sin_theta) + t102 * t130)
                                - T::from_f64(2.0) * t11 * t41) - t22 * t137
                            + T::from_f64(1.5) * t115 * t82)
                        - k_wall
                            * (sqrt_pen_wall_right
                                * (step_delta_wall_right * (T::from_f64(1.5) + t92) + t46)
                                * t29 + t140) - t3 + t4),
                -t17 * (-(t28 * (mu * (-(t94 * t19) + t102 * t22) - t76 * t42)) + t66),
                -(t28 * (-(sin_theta * (t100 - t141)) + t88 * t80)) * t17,
                -t17 * (-(t28 * (t116 - t82 * t96)) + t67 * elastic_wall_right),
                T::from_f64(0.0),
                T::from_f64(0.0),
                -t17
                    * (-(k_edge * (sin_theta * (t86 - t78) - t79 * (t77 + t117) * t87))
                        + T::from_f64(1.5) * t121 * t109 * t106),
                -(k_edge
                    * (T::from_f64(1.5) * (t44 * t19 + t97 * t87 * sin_theta)
                        * sqrt_pen_edge_left + sin_theta * t129 + t81 * mu * t20)) * t17,
                -t17
                    * (mu
                        * (k_edge
                            * (t26
                                * (t39
                                    * (-(t61 * (sin_theta * slip_edge_left + cos_theta * t135))
                                        + t136 * cos_theta) + t143 * cos_theta)
                                + T::from_f64(1.5) * t115 * cos_theta)
                            + k_wall
                                * (-(t138 * (-(t103 * t142) + t139 * t106))
                                    + T::from_f64(1.5) * t144 * t106))
                        + k_edge * (-(t99 * cos_theta) + sin_theta * t137) + t0 + t1),
                -t17
                    * (-(t28 * (sin_theta * (-t141 + t100) + t101 * t87))
                        + t66 * t106 * mu),
                -t17
                    * (mu
                        * (t28 * (t94 * t20 + t102 * cos_theta)
                            + t103 * elastic_wall_right) + t28 * t76 * t19),
                -t17
                    * (mu
                        * (cos_theta * t96 * t28
                            + elastic_wall_right * (-t145 + t67 * t106)) + t105),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t18
                    * (k_edge
                        * (-(T::from_f64(2.0) * t146 * t11)
                            + T::from_f64(1.5) * t108 * t22 - t37 * t78)
                        + sqrt_pen_wall_right
                            * (t29 * (t46 - t69 * step_delta_wall_right)
                                + T::from_f64(1.5) * t109 * t110 * step_delta_wall_right)
                            * k_wall),
                k_edge
                    * (-(t146 * cos_theta) - T::from_f64(1.5) * t108 * sin_theta
                        - t37 * t129) * t18,
                -t18
                    * (mu
                        * (k_edge
                            * (t26
                                * (-(t39
                                    * (t61
                                        * (t62 * t135
                                            + slip_edge_left
                                                * (-(cos_theta * (t35 - t90)) + sin_theta * (t134 + t58)))
                                        - t136 * t62)) + t143 * t62)
                                + T::from_f64(1.5) * t115 * t62)
                            - k_wall
                                * (-(t23
                                    * (t142 * (-(t55 * (-slip_wall_right + t47)) + t47 * t98)
                                        * t31 + t139 * t110 * thetadot))
                                    + T::from_f64(1.5) * t144 * t110))
                        + k_edge
                            * (t99 * t49 + T::from_f64(1.5) * t85 * t111 + t37 * t133)
                        + k_wall
                            * (-((step_delta_wall_right - t32) * t50 * t23)
                                + T::from_f64(1.5) * sqrt_pen_wall_right * t43 * t53
                                - t29 * t147)),
                t18
                    * (t28 * (t107 * (-(t94 * sin_theta) + t101) + t116)
                        + t66 * (-t29 + t110 * mu)),
                -t18
                    * (mu
                        * (t62 * (t94 * cos_theta + t102) * t28
                            - t145 * elastic_wall_right) + t105),
                -t18
                    * (mu
                        * (t28 * (t94 * (t62 * t62) + t95 * t62)
                            - elastic_wall_right * (-(t103 * (t21 * t21)) + t67 * t110))
                        + hc_alpha
                            * (t28 * t70 * t111 + elastic_wall_right * t52 * t53)),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                xdot * t51 - zdot * t2,
                t2,
                t51,
                m_2,
                T::from_f64(0.0),
                T::from_f64(0.0),
                k_edge
                    * (t119 * (t117 + t77) - T::from_f64(2.0) * t75 * t40
                        + delta_rate_edge_left * t78)
                    + t121
                        * (T::from_f64(1.5) * t120 * t109 + delta_rate_wall_right * t69),
                k_edge
                    * (t119 * (T::from_f64(1.5) * t122 * t39 + t84) - t83 * t40
                        + delta_rate_edge_left * t129),
                mu
                    * (k_edge
                        * (t39
                            * (-(t61
                                * (-(T::from_f64(1.5) * t114 * t63)
                                    + T::from_f64(2.0) * t148 * slip_edge_left)) + t148 * t123)
                            + t132 * t118)
                        - k_wall
                            * (t31
                                * (-(t55
                                    * (T::from_f64(1.5) * t113 * t56
                                        + T::from_f64(2.0) * t149 * slip_wall_right)) + t149 * t125)
                                + t140 * t120))
                    - k_edge * (t131 * t40 - delta_rate_edge_left * t133)
                    + k_wall * (t138 * t32 * t50 - delta_rate_wall_right * t147),
                t28 * (t22 * (-(t76 * (delta_rate_edge_left + t119)) + t40) + t124 * t82)
                    + elastic_wall_right
                        * (t65 * (t120 * mu + delta_rate_wall_right) + t31
                            - T::from_f64(1.0)),
                -(t28
                    * (sin_theta * (t40 - t76 * (t119 + delta_rate_edge_left))
                        - t124 * t87))
                    + elastic_wall_right * (-t125 + T::from_f64(2.0) * t106) * t109,
                mu
                    * (-(t28
                        * (-(t61
                            * (t104 * t63 + T::from_f64(2.0) * t126 * slip_edge_left))
                            + t126 * t123))
                        + elastic_wall_right
                            * (t55
                                * (t67 * t56 - T::from_f64(2.0) * t127 * slip_wall_right)
                                + t127 * t125))
                    + t28 * (-t40 + t76 * delta_rate_edge_left) * t37
                    + elastic_wall_right * (-t32 + t65 * delta_rate_wall_right) * t29,
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
        let slip_wall_right = zdot
            - thetadot
                * (cos_theta * (r - T::from_f64(2.0) * rho_p * t5)
                    + sin_theta * (l_c - rho_p + rho_p * sin_theta));
        let t9 = v_s.hypot(slip_wall_right);
        let delta_wall_right = r + t0 + x + sin_theta * t7 - T::from_f64(2.0) * t5 * t8;
        let pen_wall_right = delta_wall_right.max0();
        let t10 = pen_wall_right * pen_wall_right.sqrt();
        let t11 = -rho_h + z;
        let delta_edge_left = r + t0 - x + sin_theta * t11 - T::from_f64(2.0) * t1 * t5;
        let pen_edge_left = delta_edge_left.max0();
        let t12 = pen_edge_left * pen_edge_left.sqrt();
        let t13 = cos_theta * t11;
        let delta_rate_wall_right = xdot
            + thetadot * (cos_theta * t7 - T::from_f64(2.0) * t6 * t8);
        let t14 = (T::from_f64(1.0) + hc_alpha * delta_rate_wall_right).max0();
        let t15 = sin_theta * t1 - t13;
        let slip_edge_left = sin_theta
            * (xdot + thetadot * (cos_theta * t15 + r * sin_theta))
            + cos_theta * (zdot + thetadot * (-(sin_theta * t15) + r * cos_theta));
        let delta_rate_edge_left = -(xdot * (T::from_f64(1.0) - T::from_f64(2.0) * t5))
            + zdot * sin_theta + thetadot * (t13 - T::from_f64(2.0) * t6 * t1);
        let t16 = (T::from_f64(1.0) + hc_alpha * delta_rate_edge_left).max0();
        let t17 = v_s.hypot(slip_edge_left);
        let normal_wall_right = k_wall * t14 * t10;
        let t18 = (T::from_f64(1.5) * normal_wall_right / (e_star * wall_sum)).cbrt();
        let normal_edge_left = k_edge * t12 * t16;
        let t19 = (T::from_f64(1.5) * normal_edge_left / (e_star * edge_sum)).cbrt();
        let normal = Vector2::new(normal_edge_left, normal_wall_right);
        let friction = Vector2::new(
            -normal_edge_left * mu * slip_edge_left / t17,
            -normal_wall_right * mu * slip_wall_right / t9,
        );
        let delta = Vector2::new(delta_edge_left, delta_wall_right);
        let slip = Vector2::new(slip_edge_left, slip_wall_right);
        let a = Vector2::new(edge_ma * t19, wall_ma * t18);
        let b = Vector2::new(edge_mb * t19, wall_mb * t18);
        let p0 = Vector2::new(
            T::from_f64(0.3183098861837907) * e_star * edge_sum * t19
                / (edge_ma * edge_mb),
            T::from_f64(0.3183098861837907) * e_star * wall_sum * t18
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
        let delta_wall_right = r + t0 + x + sin_theta * (l_c - rho_p)
            - T::from_f64(2.0) * t2 * (r - rho_p);
        let pen_wall_right = delta_wall_right.max0();
        let delta_edge_left = r + t0 - x + sin_theta * (-rho_h + z)
            - T::from_f64(2.0) * (-rho_h + t0 - x) * t2;
        let pen_edge_left = delta_edge_left.max0();
        let t3 = pen_wall_right.powf(T::from_f64(2.5));
        let t4 = pen_edge_left.powf(T::from_f64(2.5));
        let kinetic = T::from_f64(0.5)
            * (m * (xdot * xdot + zdot * zdot) + j * (thetadot * thetadot));
        let potential = T::from_f64(0.4) * (k_edge * t4 + k_wall * t3);
        let depth = z + l_c * cos_theta;
        (kinetic, potential, depth)
    }
}
