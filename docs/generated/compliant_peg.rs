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
    /// 107 add/sub, 139 mul, 7 div, 4 sqrt, 6 transcendental, 16 branches; 89 `let`s.
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
        let t5 = -rho_h + t4 - x;
        let t6 = T::from_f64(0.5) * theta;
        let (t7, t8) = t6.sin_cos();
        let t9 = t7 * t7;
        let t10 = r * sin_theta;
        let t11 = r * cos_theta;
        let t12 = zdot * sin_theta;
        let t13 = t7 * t8;
        let t14 = l_c - rho_p;
        let t15 = r - rho_p;
        let t16 = sin_theta * t14;
        let t17 = -T::from_f64(2.0) * t9 * t15;
        let t18 = rho_p * sin_theta;
        let t19 = cos_theta * (r - T::from_f64(2.0) * rho_p * t9);
        let t20 = cos_theta * t14;
        let t21 = rho_h + T::from_f64(0.5) * d - x;
        let t22 = T::from_f64(1.0) - T::from_f64(2.0) * t9;
        let t23 = t19 + sin_theta * (l_c - rho_p + t18);
        let t24 = -xdot * t22;
        let slip_wall_right = zdot - thetadot * t23;
        let t25 = v_s.hypot(slip_wall_right);
        let t26 = sin_theta * (-l_c + rho_p + t18) + t19;
        let slip_wall_left = zdot + thetadot * t26;
        let t27 = v_s.hypot(slip_wall_left);
        let delta_wall_right = r + t4 + x + t16 + t17;
        let pen_wall_right = delta_wall_right.max0();
        let t28 = pen_wall_right * pen_wall_right.sqrt();
        let step_delta_wall_right = delta_wall_right.step();
        let t29 = -rho_h + z;
        let t30 = sin_theta * t29;
        let delta_edge_left = r + t4 - x + t30 - T::from_f64(2.0) * t5 * t9;
        let pen_edge_left = delta_edge_left.max0();
        let t31 = pen_edge_left * pen_edge_left.sqrt();
        let t32 = cos_theta * t29;
        let step_delta_edge_left = delta_edge_left.step();
        let t33 = t13 * t15;
        let t34 = t20 - T::from_f64(2.0) * t33;
        let delta_rate_wall_right = xdot + thetadot * t34;
        let t35 = (T::from_f64(1.0) + hc_alpha * delta_rate_wall_right).max0();
        let delta_wall_left = r + t4 - x - t16 + t17;
        let pen_wall_left = delta_wall_left.max0();
        let t36 = pen_wall_left * pen_wall_left.sqrt();
        let t37 = t20 + T::from_f64(2.0) * t33;
        let t38 = xdot + thetadot * t37;
        let t39 = (T::from_f64(1.0) - hc_alpha * t38).max0();
        let step_delta_wall_left = delta_wall_left.step();
        let t40 = T::from_f64(1.0) - t35;
        let t41 = sin_theta * t5 - t32;
        let t42 = cos_theta * t41 + t10;
        let t43 = -(sin_theta * t41) + t11;
        let slip_edge_left = sin_theta * (xdot + thetadot * t42)
            + cos_theta * (zdot + thetadot * t43);
        let t44 = t32 - T::from_f64(2.0) * t13 * t5;
        let delta_rate_edge_left = t24 + t12 + thetadot * t44;
        let t45 = (T::from_f64(1.0) + hc_alpha * delta_rate_edge_left).max0();
        let t46 = -t45 + T::from_f64(1.0);
        let t47 = v_s.hypot(slip_edge_left);
        let delta_edge_right = r + t4 + x - t30 + T::from_f64(2.0) * t9 * t21;
        let t48 = -t32 + sin_theta * t21;
        let t49 = t10 - cos_theta * t48;
        let t50 = t11 + sin_theta * t48;
        let slip_edge_right = sin_theta * (xdot - thetadot * t49)
            + cos_theta * (zdot - thetadot * t50);
        let pen_edge_right = delta_edge_right.max0();
        let t51 = pen_edge_right * pen_edge_right.sqrt();
        let t52 = t32 - T::from_f64(2.0) * t13 * t21;
        let t53 = t24 + t12 + thetadot * t52;
        let t54 = (T::from_f64(1.0) - hc_alpha * t53).max0();
        let t55 = -t54 + T::from_f64(1.0);
        let t56 = v_s.hypot(slip_edge_right);
        let step_delta_edge_right = delta_edge_right.step();
        let t57 = -t39 + T::from_f64(1.0);
        let t58 = -step_delta_edge_left + t46;
        let t59 = t45 / t47;
        let t60 = t59 * slip_edge_left;
        let t61 = t54 / t56;
        let t62 = t61 * slip_edge_right;
        let t63 = mu * (t60 * t31 + t62 * t51);
        let t64 = t35 / t25;
        let t65 = t64 * slip_wall_right;
        let t66 = t39 / t27;
        let t67 = t66 * slip_wall_left;
        let t68 = t55 - step_delta_edge_right;
        SMatrix::<
            T,
            8,
            1,
        >::from_row_slice(
            &[
                xdot,
                zdot,
                thetadot,
                (-(k_edge * (t22 * (t31 * t58 - t51 * t68) + t63 * sin_theta))
                    + k_wall
                        * (-(t28 * (-T::from_f64(1.0) + step_delta_wall_right + t35))
                            + t36 * (t39 - T::from_f64(1.0) + step_delta_wall_left)) + t0
                    + t1) / m,
                (k_edge
                    * (sin_theta
                        * (t31 * (t46 - step_delta_edge_left)
                            - t51 * (-step_delta_edge_right + t55)) - t63 * cos_theta)
                    - k_wall * (t65 * t28 + t67 * t36) * mu + t2 + t3) / m,
                -(-m_2
                    + k_edge
                        * (t31
                            * (-(t44 * t58)
                                + t60 * mu * (sin_theta * t42 + cos_theta * t43))
                            - t51
                                * (-(t52 * t68)
                                    + t62 * mu * (sin_theta * t49 + cos_theta * t50)))
                    + k_wall
                        * (-(t28
                            * (-(t34 * (step_delta_wall_right - t40)) + t65 * mu * t23))
                            + t36
                                * (-(t37 * (step_delta_wall_left - t57)) + t67 * mu * t26)))
                    / j,
                xdot * (t0 + t1) + zdot * (t2 + t3) + thetadot * m_2,
                mu
                    * (k_edge
                        * (t59 * t31 * (slip_edge_left * slip_edge_left)
                            + t61 * t51 * (slip_edge_right * slip_edge_right))
                        + k_wall
                            * (t64 * t28 * (slip_wall_right * slip_wall_right)
                                + t66 * t36 * (slip_wall_left * slip_wall_left)))
                    - k_edge * (delta_rate_edge_left * t31 * t46 - t53 * t51 * t55)
                    - k_wall * (delta_rate_wall_right * t28 * t40 - t38 * t36 * t57),
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
    /// 366 add/sub, 721 mul, 10 div, 8 sqrt, 6 transcendental, 24 branches; 290 `let`s.
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
        let t4 = -f2 * sin_theta;
        let t5 = t3 + t4;
        let t6 = -T::from_f64(0.5) * d;
        let t7 = -rho_h + t6 - x;
        let t8 = T::from_f64(0.5) * theta;
        let (t9, t10) = t8.sin_cos();
        let t11 = t9 * t9;
        let t12 = r * sin_theta;
        let t13 = r * cos_theta;
        let t14 = zdot * sin_theta;
        let t15 = t9 * t10;
        let t16 = l_c - rho_p;
        let t17 = r - rho_p;
        let t18 = sin_theta * t16;
        let t19 = -T::from_f64(2.0) * t11 * t17;
        let t20 = rho_p * sin_theta;
        let t21 = l_c - rho_p + t20;
        let t22 = r - T::from_f64(2.0) * rho_p * t11;
        let t23 = sin_theta * t22;
        let t24 = cos_theta * t22;
        let t25 = cos_theta * t16;
        let t26 = rho_h + T::from_f64(0.5) * d - x;
        let t27 = T::from_f64(1.0) - T::from_f64(2.0) * t11;
        let t28 = T::from_f64(1.0) / m;
        let t29 = T::from_f64(1.0) / j;
        let t30 = sin_theta * sin_theta;
        let t31 = t27 * t27;
        let t32 = cos_theta * cos_theta;
        let t33 = zdot * cos_theta;
        let t34 = t10 * t10;
        let t35 = t24 + sin_theta * t21;
        let t36 = -xdot * t27;
        let slip_wall_right = zdot - thetadot * t35;
        let t37 = v_s.hypot(slip_wall_right);
        let t38 = T::from_f64(1.0) / t37;
        let t39 = slip_wall_right * slip_wall_right;
        let t40 = -l_c + rho_p + t20;
        let t41 = sin_theta * t40;
        let t42 = t41 + t24;
        let slip_wall_left = zdot + thetadot * t42;
        let t43 = v_s.hypot(slip_wall_left);
        let t44 = T::from_f64(1.0) / t43;
        let t45 = slip_wall_left * slip_wall_left;
        let delta_wall_right = r + t6 + x + t18 + t19;
        let pen_wall_right = delta_wall_right.max0();
        let t46 = pen_wall_right * pen_wall_right.sqrt();
        let step_delta_wall_right = delta_wall_right.step();
        let t47 = -rho_h + z;
        let t48 = sin_theta * t47;
        let delta_edge_left = r + t6 - x + t48 - T::from_f64(2.0) * t7 * t11;
        let pen_edge_left = delta_edge_left.max0();
        let t49 = pen_edge_left * pen_edge_left.sqrt();
        let t50 = cos_theta * t47;
        let step_delta_edge_left = delta_edge_left.step();
        let t51 = t15 * t17;
        let t52 = t25 - T::from_f64(2.0) * t51;
        let delta_rate_wall_right = xdot + thetadot * t52;
        let t53 = T::from_f64(1.0) + hc_alpha * delta_rate_wall_right;
        let t54 = t53.max0();
        let delta_wall_left = r + t6 - x - t18 + t19;
        let pen_wall_left = delta_wall_left.max0();
        let t55 = pen_wall_left * pen_wall_left.sqrt();
        let t56 = t25 + T::from_f64(2.0) * t51;
        let t57 = xdot + thetadot * t56;
        let t58 = T::from_f64(1.0) - hc_alpha * t57;
        let t59 = t58.max0();
        let step_delta_wall_left = delta_wall_left.step();
        let t60 = T::from_f64(1.0) - t54;
        let t61 = sin_theta * t7 - t50;
        let t62 = cos_theta * t61;
        let t63 = t62 + t12;
        let t64 = xdot + thetadot * t63;
        let t65 = t50 - T::from_f64(2.0) * t15 * t7;
        let delta_rate_edge_left = t36 + t14 + thetadot * t65;
        let t66 = T::from_f64(1.0) + hc_alpha * delta_rate_edge_left;
        let t67 = t66.max0();
        let t68 = -t67 + T::from_f64(1.0);
        let delta_edge_right = r + t6 + x - t48 + T::from_f64(2.0) * t11 * t26;
        let t69 = -t50 + sin_theta * t26;
        let t70 = -cos_theta * t69;
        let t71 = t12 + t70;
        let t72 = xdot - thetadot * t71;
        let t73 = sin_theta * t69;
        let t74 = t13 + t73;
        let t75 = zdot - thetadot * t74;
        let slip_edge_right = sin_theta * t72 + cos_theta * t75;
        let pen_edge_right = delta_edge_right.max0();
        let t76 = pen_edge_right * pen_edge_right.sqrt();
        let t77 = t50 - T::from_f64(2.0) * t15 * t26;
        let t78 = t36 + t14 + thetadot * t77;
        let t79 = T::from_f64(1.0) - hc_alpha * t78;
        let t80 = t79.max0();
        let t81 = -t80 + T::from_f64(1.0);
        let t82 = v_s.hypot(slip_edge_right);
        let t83 = T::from_f64(1.0) / t82;
        let step_delta_edge_right = delta_edge_right.step();
        let t84 = sin_theta * t71 + cos_theta * t74;
        let t85 = slip_edge_right * slip_edge_right;
        let t86 = -t59 + T::from_f64(1.0);
        let t87 = t49 * (-step_delta_edge_left + t68);
        let t88 = T::from_f64(1.0) / (t37 * t37 * t37);
        let t89 = T::from_f64(1.0) / (t43 * t43 * t43);
        let t90 = t24 + t41;
        let sqrt_pen_wall_right = pen_wall_right.sqrt();
        let t91 = step_delta_wall_right * step_delta_wall_right;
        let sqrt_pen_edge_left = pen_edge_left.sqrt();
        let t92 = step_delta_edge_left * step_delta_edge_left;
        let t93 = -T::from_f64(1.5) * t91;
        let t94 = sqrt_pen_edge_left * t92;
        let t95 = r + cos_theta * t7 + t48;
        let t96 = r - (t48 + cos_theta * t26);
        let t97 = t17 * (-t34 + t11) + t18;
        let t98 = t11 - t34;
        let t99 = -(t7 * t98) + t48;
        let t100 = -(t17 * t98) + t18;
        let t101 = -(t26 * t98) + t48;
        let t102 = T::from_f64(2.0) * t15 * xdot;
        let t103 = t53.step();
        let t104 = t52 * t52;
        let t105 = sin_theta * t61;
        let t106 = -t105 + t13;
        let t107 = zdot + thetadot * t106;
        let slip_edge_left = sin_theta * t64 + cos_theta * t107;
        let t108 = t49 * t68;
        let t109 = v_s.hypot(slip_edge_left);
        let t110 = T::from_f64(1.0) / t109;
        let t111 = sin_theta * t63 + cos_theta * t106;
        let t112 = slip_edge_left * slip_edge_left;
        let t113 = t76 * t81;
        let t114 = slip_edge_left * t110;
        let t115 = slip_edge_right * t83;
        let t116 = t114 * t49 * t67 + t115 * t76 * t80;
        let t117 = t76 * (t81 - step_delta_edge_right);
        let sqrt_pen_wall_left = pen_wall_left.sqrt();
        let t118 = step_delta_wall_left * step_delta_wall_left;
        let t119 = t58.step();
        let t120 = t56 * t56;
        let t121 = t66.step();
        let t122 = -T::from_f64(1.5) * t67;
        let t123 = step_delta_edge_left * sqrt_pen_edge_left;
        let t124 = thetadot * hc_alpha;
        let t125 = t15 * t124;
        let t126 = t49 * t121;
        let t127 = T::from_f64(2.0) * t125 * t126;
        let t128 = t123 * (t122 + T::from_f64(1.5)) * t27 + t127;
        let sqrt_pen_edge_right = pen_edge_right.sqrt();
        let t129 = step_delta_edge_right * step_delta_edge_right;
        let t130 = t79.step();
        let t131 = -T::from_f64(1.5) * t80;
        let t132 = step_delta_edge_right * sqrt_pen_edge_right;
        let t133 = t76 * t130;
        let t134 = T::from_f64(2.0) * t125 * t133;
        let t135 = t132 * (t131 + T::from_f64(1.5)) * t27 + t134;
        let t136 = t123 * t67;
        let t137 = t132 * t80;
        let t138 = mu * (t136 * t114 - t137 * t115);
        let t139 = -T::from_f64(1.5) * t54;
        let t140 = T::from_f64(1.5) + t139;
        let t141 = sqrt_pen_wall_right * (step_delta_wall_right * t140 + t93);
        let t142 = -(T::from_f64(1.5) * t59) + T::from_f64(1.5);
        let t143 = -T::from_f64(1.5) * t118;
        let t144 = sqrt_pen_wall_left * (step_delta_wall_left * t142 + t143);
        let t145 = t124 * cos_theta;
        let t146 = sqrt_pen_edge_right * t129;
        let t147 = t94 + t146;
        let t148 = t27 * t147;
        let t149 = sin_theta * t95 + t62;
        let t150 = T::from_f64(1.0) / (t109 * t109 * t109);
        let t151 = cos_theta * t96 + t73;
        let t152 = T::from_f64(1.0) / (t82 * t82 * t82);
        let t153 = t85 * t152;
        let t154 = t55 * t119;
        let t155 = t154 * t97;
        let t156 = t112 * t150;
        let t157 = t67 * (t110 - t156);
        let t158 = t157 * t49;
        let t159 = t80 * (t83 - t153);
        let t160 = t159 * t76;
        let t161 = t158 + t160;
        let t162 = hc_alpha * (t126 + t133);
        let t163 = t103 * t46;
        let t164 = k_wall * hc_alpha;
        let t165 = hc_alpha * t121;
        let t166 = t165 * t65;
        let t167 = hc_alpha * (t126 * t114 - t133 * t115);
        let t168 = t167 * mu;
        let t169 = t168 * thetadot;
        let t170 = rho_p * (sin_theta - T::from_f64(2.0) * t15);
        let t171 = t54 * (t38 - t39 * t88);
        let t172 = t171 * t46;
        let t173 = t59 * (t44 - t45 * t89);
        let t174 = slip_wall_right * t38;
        let t175 = hc_alpha * t103;
        let t176 = t175 * t52;
        let t177 = t174 * t176;
        let t178 = hc_alpha * (t126 * t65 + t133 * t77);
        let t179 = t178 * sin_theta * k_edge;
        let t180 = step_delta_wall_left * sqrt_pen_wall_left;
        let t181 = t114 * t111;
        let t182 = sqrt_pen_edge_left
            * (t65 * t92 + t181 * mu * t67 * step_delta_edge_left);
        let t183 = t115 * t84;
        let t184 = sqrt_pen_edge_right
            * (t77 * t129 + t183 * mu * t80 * step_delta_edge_right);
        let t185 = mu * t35;
        let t186 = t174 * t54;
        let t187 = mu * t42;
        let t188 = slip_wall_left * t44;
        let t189 = t188 * t59;
        let t190 = t65 * t65;
        let t191 = step_delta_wall_right * sqrt_pen_wall_right;
        let t192 = t191 * t52;
        let t193 = t77 * t77;
        let t194 = t180 * t56;
        let t195 = t194 * t142 + t155 * t124;
        let t196 = t136 * t65;
        let t197 = t137 * t77;
        let t198 = hc_alpha * t119;
        let t199 = t198 * t97;
        let t200 = t199 * t188;
        let t201 = t159 * t84;
        let t202 = t201 * t76;
        let t203 = hc_alpha * (t181 * t126 + t183 * t133);
        let t204 = t178 * t27;
        let t205 = t158 * t111;
        let t206 = t42 * t55;
        let t207 = hc_alpha * t130;
        let t208 = t207 * t77;
        let t209 = t110 * t112;
        let t210 = t83 * t85;
        let t211 = t209 * t126 - t210 * t133;
        let t212 = t54 * t38 * t39;
        let t213 = t59 * t44 * t45;
        let t214 = t209 * t136 - t210 * t137;
        let t215 = hc_alpha * (mu * t211 + t126 * delta_rate_edge_left + t133 * t78)
            - t108 + t113;
        let t216 = t150 * (slip_edge_left * slip_edge_left * slip_edge_left);
        let t217 = t67 * (-t216 + T::from_f64(2.0) * t114) * t49;
        let t218 = t152 * (slip_edge_right * slip_edge_right * slip_edge_right);
        let t219 = t80 * (-t218 + T::from_f64(2.0) * t115) * t76;
        let t220 = t88 * (slip_wall_right * slip_wall_right * slip_wall_right);
        let t221 = t89 * (slip_wall_left * slip_wall_left * slip_wall_left);
        let t222 = t67 * t111;
        let t223 = t80 * t84;
        let t224 = t54 * t35;
        let t225 = t123 * (T::from_f64(1.5) + t122);
        let t226 = -(t225 * sin_theta) + t145 * t126;
        let t227 = t132 * (T::from_f64(1.5) + t131);
        let t228 = -(t227 * sin_theta) + t145 * t133;
        let t229 = k_edge * t28;
        let t230 = t102 + t33 - thetadot * t99;
        let t231 = t126 * t230;
        let t232 = -(t225 * t65) + t231 * hc_alpha;
        let t233 = -(cos_theta * t95) + t105;
        let t234 = cos_theta * (-t64 + thetadot * t149)
            + sin_theta * (t107 + thetadot * t233);
        let t235 = t102 + t33 - thetadot * t101;
        let t236 = t133 * t235;
        let t237 = -(t227 * t77) + t236 * hc_alpha;
        let t238 = t70 + sin_theta * t96;
        let t239 = -(cos_theta * (t72 + thetadot * t238))
            + sin_theta * (thetadot * t151 + t75);
        let t240 = t165 * t230;
        let t241 = t207 * t235;
        let t242 = t49 * (-(t157 * t234) + t240 * t114)
            - t76 * (t159 * t239 + t241 * t115)
            + T::from_f64(1.5) * (t196 * t114 - t197 * t115);
        let t243 = T::from_f64(1.5) * (t94 * t65 + t146 * t77) + t232 + t237;
        let t244 = t163 * t100;
        let t245 = sin_theta * (cos_theta * (-t158 - t160) * mu + t162 * t27);
        let t246 = t49 * (t157 * t111 + t166 * t114) - t76 * (t201 + t208 * t115);
        let t247 = t23 - cos_theta * (t170 + t21);
        let t248 = t23 - cos_theta * (t170 + t40);
        let t249 = t175 * t100;
        let t250 = t46 * (-(t171 * t247) + t249 * t174);
        let t251 = t173 * t248;
        let t252 = t198 * t56;
        let t253 = t188 * t252;
        let t254 = t124 * mu;
        let t255 = t49 * (step_delta_edge_left - t68 + t254 * t181 * t121);
        let t256 = t76 * (-step_delta_edge_right + t81 + t254 * t183 * t130);
        let t257 = t192 * (t139 + T::from_f64(1.5)) + t244 * t124;
        let t258 = t111 * t234;
        let t259 = t84 * t239;
        let t260 = thetadot * (t108 - t113);
        let t261 = t49 * t234;
        let t262 = t76 * t239;
        let t263 = t54 * t247;
        let t264 = t59 * t248;
        let t265 = t42 * t59;
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
                t28
                    * (k_edge
                        * (t27 * (T::from_f64(1.5) * t138 * sin_theta + t128 + t135)
                            - T::from_f64(1.5) * t147 * t31
                            - T::from_f64(2.0) * t169 * (t15 * sin_theta))
                        + k_wall * (t141 + t144)),
                t229
                    * (sin_theta * (T::from_f64(1.5) * t148 - t169 * cos_theta)
                        + t27 * (t226 + t228) - T::from_f64(1.5) * t138 * t30),
                t28
                    * (k_edge
                        * (-(mu * (cos_theta * t116 + sin_theta * t242)) + t27 * t243
                            + t15 * (T::from_f64(2.0) * t87 - T::from_f64(2.0) * t117))
                        + k_wall * (t141 * t52 + t144 * t56 + t124 * (t244 + t155)) + t3
                        + t4),
                -t28
                    * (k_edge * (mu * (t30 * t161 - sin_theta * t27 * t167) + t162 * t31)
                        + t164 * (t163 + t154)),
                t229 * (t245 - t168 * t30),
                -t28
                    * (k_edge * (sin_theta * t246 * mu - t204)
                        + t164 * (t163 * t52 + t154 * t56)),
                T::from_f64(0.0),
                T::from_f64(0.0),
                -t28
                    * (k_edge
                        * (sin_theta * (-(T::from_f64(1.5) * t148) + t128 + t135)
                            - cos_theta
                                * (-(t114 * (t127 - T::from_f64(1.5) * t136 * t27))
                                    + t115 * (-(T::from_f64(1.5) * t137 * t27) + t134)) * mu)
                        + T::from_f64(1.5) * (k_wall * (t186 * t191 - t189 * t180))
                            * mu),
                -t229
                    * (sin_theta * (T::from_f64(1.5) * t138 * cos_theta + t226 + t228)
                        + T::from_f64(1.5) * t147 * t30 + t169 * t32),
                -t28
                    * (-(mu
                        * (k_edge * (-(cos_theta * t242) + sin_theta * t116)
                            - k_wall
                                * (thetadot * (-t250 + t55 * (t200 - t251))
                                    + T::from_f64(1.5) * (t186 * t192 - t189 * t194))))
                        + k_edge * (-(cos_theta * (t87 - t117)) + sin_theta * t243) + t0
                        + t1),
                t28
                    * (k_edge * (t245 + cos_theta * t27 * t168)
                        - t164 * (t163 * t174 - t154 * t188) * mu),
                -t28
                    * (mu
                        * (k_edge * (t32 * t161 + sin_theta * cos_theta * t167)
                            + k_wall * (t172 + t173 * t55)) + t162 * t30 * k_edge),
                t28
                    * (mu
                        * (-(cos_theta * t246 * k_edge)
                            + k_wall
                                * (-(t46 * (-(t171 * t35) + t177))
                                    + t55 * (-(t173 * t42) + t253))) - t179),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t29
                    * (k_edge
                        * (t15 * (-(T::from_f64(2.0) * t255) - T::from_f64(2.0) * t256)
                            + t27 * (T::from_f64(1.5) * t182 + T::from_f64(1.5) * t184)
                            - t65 * t128 - t77 * t135)
                        + k_wall
                            * (sqrt_pen_wall_right
                                * (t52 * (t93 + t140 * step_delta_wall_right)
                                    + T::from_f64(1.5) * t185 * t186 * step_delta_wall_right)
                                + sqrt_pen_wall_left
                                    * (t56 * (t143 + t142 * step_delta_wall_left)
                                        + T::from_f64(1.5) * t187 * t189 * step_delta_wall_left))),
                -(k_edge
                    * (cos_theta * (t255 + t256)
                        - sin_theta
                            * (-(T::from_f64(1.5) * t182) - T::from_f64(1.5) * t184)
                        + t65 * t226 + t77 * t228)) * t29,
                -t29
                    * (mu
                        * (k_edge
                            * (t49
                                * (-(t67
                                    * (t110
                                        * (t258
                                            + slip_edge_left
                                                * (-(cos_theta * (t63 - t149)) + sin_theta * (t233 + t106)))
                                        - t156 * t258)) + t240 * t181)
                                + t76
                                    * (t80
                                        * (t83
                                            * (t259
                                                + slip_edge_right
                                                    * (-(cos_theta * (t71 - t238)) + sin_theta * (t74 - t151)))
                                            - t153 * t259) + t241 * t183)
                                + T::from_f64(1.5) * (t196 * t181 + t197 * t183))
                            + k_wall
                                * (thetadot * (t250 * t35 + t206 * (-t251 + t200))
                                    - t186 * (-(t46 * t247) + T::from_f64(1.5) * t192 * t35)
                                    - t189 * (t55 * t248 + T::from_f64(1.5) * t194 * t42)))
                        + k_edge
                            * (t87 * t99 - t117 * t101
                                + T::from_f64(1.5) * (t94 * t190 + t146 * t193) + t65 * t232
                                + t77 * t237)
                        + k_wall
                            * (-((step_delta_wall_right - t60) * t100 * t46)
                                + (step_delta_wall_left - t86) * t97 * t55
                                + T::from_f64(1.5)
                                    * (sqrt_pen_wall_right * t91 * t104
                                        + sqrt_pen_wall_left * t118 * t120) - t52 * t257
                                - t56 * t195)),
                t29
                    * (k_edge * (mu * (sin_theta * (-t205 + t202) + t203 * t27) + t204)
                        + t164
                            * (t163 * (-t52 + t185 * t174)
                                + t154 * (-t56 + t187 * t188))),
                -t29
                    * (mu
                        * (k_edge * (cos_theta * (t205 - t202) + t203 * sin_theta)
                            + k_wall * (-(t172 * t35) + t206 * t173)) + t179),
                -t29
                    * (mu
                        * (k_edge
                            * (t49 * (t157 * (t111 * t111) + t166 * t181)
                                + t76 * (t159 * (t84 * t84) + t208 * t183))
                            - k_wall
                                * (t46 * (-(t171 * (t35 * t35)) + t177 * t35)
                                    + t55 * (-(t173 * (t90 * t90)) + t253 * t42)))
                        + hc_alpha
                            * (k_edge * (t126 * t190 + t133 * t193)
                                + k_wall * (t163 * t104 + t154 * t120))),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                xdot * t5 - zdot * t2,
                t2,
                t5,
                m_2,
                T::from_f64(0.0),
                T::from_f64(0.0),
                k_edge
                    * (mu
                        * (-(T::from_f64(1.5) * t214 * t27)
                            + T::from_f64(2.0) * (t15 * t211) * t124)
                        - T::from_f64(2.0) * t260 * t15 + delta_rate_edge_left * t128
                        + t78 * t135)
                    - k_wall
                        * (-(T::from_f64(1.5) * (t212 * t191 - t213 * t180) * mu)
                            + t191 * delta_rate_wall_right * t140 + t180 * t142 * t57),
                k_edge
                    * (mu
                        * (T::from_f64(1.5) * t214 * sin_theta + cos_theta * t211 * t124)
                        - t260 * cos_theta + delta_rate_edge_left * t226 + t78 * t228),
                mu
                    * (k_edge
                        * (t67
                            * (-(t110
                                * (-(T::from_f64(1.5) * t123 * t65 * t112)
                                    + T::from_f64(2.0) * t261 * slip_edge_left)) + t261 * t216)
                            + t80
                                * (-(t83
                                    * (T::from_f64(1.5) * t132 * t77 * t85
                                        + T::from_f64(2.0) * t262 * slip_edge_right)) + t262 * t218)
                            + hc_alpha * (t231 * t209 - t236 * t210))
                        + k_wall
                            * (thetadot
                                * (-(t46
                                    * (t38
                                        * (t249 * t39 - T::from_f64(2.0) * t263 * slip_wall_right)
                                        + t263 * t220))
                                    + t55
                                        * (t44
                                            * (t199 * t45 - T::from_f64(2.0) * t264 * slip_wall_left)
                                            + t264 * t221))
                                + T::from_f64(1.5) * (t212 * t192 - t213 * t194)))
                    + k_edge
                        * (-(t108 * t230) + delta_rate_edge_left * t232 + t113 * t235
                            + t78 * t237)
                    - k_wall
                        * (thetadot * (-(t46 * t60 * t100) + t55 * t86 * t97)
                            + delta_rate_wall_right * t257 + t57 * t195),
                -(k_edge * (t27 * t215 + sin_theta * (-t217 - t219) * mu))
                    - k_wall
                        * (t46
                            * (-(t175 * (delta_rate_wall_right + mu * t38 * t39)) - t54
                                + T::from_f64(1.0))
                            + t55
                                * (t198 * (mu * t44 * t45 - t57) - T::from_f64(1.0) + t59)),
                k_edge * (sin_theta * t215 + cos_theta * (t217 + t219) * mu)
                    + k_wall
                        * (t54 * (-t220 + T::from_f64(2.0) * t174) * t46
                            + t59 * (-t221 + T::from_f64(2.0) * t188) * t55) * mu,
                -(mu
                    * (k_edge
                        * (t49
                            * (-(t110
                                * (t166 * t112 + T::from_f64(2.0) * t222 * slip_edge_left))
                                + t222 * t216)
                            - t76
                                * (-(t83
                                    * (t208 * t85 + T::from_f64(2.0) * t223 * slip_edge_right))
                                    + t223 * t218))
                        + k_wall
                            * (-(t46
                                * (t38
                                    * (t176 * t39 - T::from_f64(2.0) * t224 * slip_wall_right)
                                    + t224 * t220))
                                + t55
                                    * (t44
                                        * (t252 * t45 - T::from_f64(2.0) * t265 * slip_wall_left)
                                        + t265 * t221))))
                    + k_edge
                        * (t49 * (-t68 + t165 * delta_rate_edge_left) * t65
                            + t76 * (t81 + t207 * t78) * t77)
                    + k_wall
                        * (t46 * (-t60 + t175 * delta_rate_wall_right) * t52
                            + t55 * (t86 + t198 * t57) * t56),
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
    /// 59 add/sub, 109 mul, 8 div, 4 sqrt, 10 transcendental, 8 branches; 65 `let`s.
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
        let t1 = -rho_h + t0 - x;
        let t2 = T::from_f64(0.5) * theta;
        let (t3, t4) = t2.sin_cos();
        let t5 = t3 * t3;
        let t6 = r * sin_theta;
        let t7 = r * cos_theta;
        let t8 = zdot * sin_theta;
        let t9 = t3 * t4;
        let t10 = T::from_f64(1.0) / (e_star * edge_sum);
        let t11 = l_c - rho_p;
        let t12 = r - rho_p;
        let t13 = sin_theta * t11;
        let t14 = -T::from_f64(2.0) * t5 * t12;
        let t15 = rho_p * sin_theta;
        let t16 = cos_theta * (r - T::from_f64(2.0) * rho_p * t5);
        let t17 = cos_theta * t11;
        let t18 = T::from_f64(1.0) / (e_star * wall_sum);
        let t19 = rho_h + T::from_f64(0.5) * d - x;
        let t20 = -xdot * (T::from_f64(1.0) - T::from_f64(2.0) * t5);
        let slip_wall_right = zdot - thetadot * (t16 + sin_theta * (l_c - rho_p + t15));
        let t21 = v_s.hypot(slip_wall_right);
        let slip_wall_left = zdot + thetadot * (sin_theta * (-l_c + rho_p + t15) + t16);
        let t22 = v_s.hypot(slip_wall_left);
        let delta_wall_right = r + t0 + x + t13 + t14;
        let pen_wall_right = delta_wall_right.max0();
        let t23 = pen_wall_right * pen_wall_right.sqrt();
        let t24 = -rho_h + z;
        let t25 = sin_theta * t24;
        let delta_edge_left = r + t0 - x + t25 - T::from_f64(2.0) * t1 * t5;
        let pen_edge_left = delta_edge_left.max0();
        let t26 = pen_edge_left * pen_edge_left.sqrt();
        let t27 = cos_theta * t24;
        let t28 = t9 * t12;
        let delta_rate_wall_right = xdot + thetadot * (t17 - T::from_f64(2.0) * t28);
        let t29 = (T::from_f64(1.0) + hc_alpha * delta_rate_wall_right).max0();
        let delta_wall_left = r + t0 - x - t13 + t14;
        let pen_wall_left = delta_wall_left.max0();
        let t30 = pen_wall_left * pen_wall_left.sqrt();
        let t31 = (T::from_f64(1.0)
            - hc_alpha * (xdot + thetadot * (t17 + T::from_f64(2.0) * t28)))
            .max0();
        let t32 = sin_theta * t1 - t27;
        let slip_edge_left = sin_theta * (xdot + thetadot * (cos_theta * t32 + t6))
            + cos_theta * (zdot + thetadot * (-(sin_theta * t32) + t7));
        let delta_rate_edge_left = t20 + t8
            + thetadot * (t27 - T::from_f64(2.0) * t9 * t1);
        let t33 = (T::from_f64(1.0) + hc_alpha * delta_rate_edge_left).max0();
        let t34 = v_s.hypot(slip_edge_left);
        let delta_edge_right = r + t0 + x - t25 + T::from_f64(2.0) * t5 * t19;
        let t35 = -t27 + sin_theta * t19;
        let slip_edge_right = sin_theta * (xdot - thetadot * (t6 - cos_theta * t35))
            + cos_theta * (zdot - thetadot * (t7 + sin_theta * t35));
        let pen_edge_right = delta_edge_right.max0();
        let t36 = pen_edge_right * pen_edge_right.sqrt();
        let t37 = (T::from_f64(1.0)
            - hc_alpha * (t20 + t8 + thetadot * (t27 - T::from_f64(2.0) * t9 * t19)))
            .max0();
        let t38 = v_s.hypot(slip_edge_right);
        let normal_wall_left = k_wall * t30 * t31;
        let normal_wall_right = k_wall * t29 * t23;
        let t39 = (T::from_f64(1.5) * t18 * normal_wall_left).cbrt();
        let t40 = e_star * wall_sum * (T::from_f64(1.0) / (wall_ma * wall_mb));
        let t41 = (T::from_f64(1.5) * t18 * normal_wall_right).cbrt();
        let normal_edge_left = k_edge * t26 * t33;
        let normal_edge_right = k_edge * t36 * t37;
        let t42 = (T::from_f64(1.5) * t10 * normal_edge_left).cbrt();
        let t43 = e_star * edge_sum * (T::from_f64(1.0) / (edge_ma * edge_mb));
        let t44 = (T::from_f64(1.5) * t10 * normal_edge_right).cbrt();
        let normal = Vector4::new(
            normal_edge_left,
            normal_wall_right,
            normal_edge_right,
            normal_wall_left,
        );
        let friction = Vector4::new(
            -normal_edge_left * mu * slip_edge_left / t34,
            -normal_wall_right * mu * slip_wall_right / t21,
            -normal_edge_right * mu * slip_edge_right / t38,
            -normal_wall_left * mu * slip_wall_left / t22,
        );
        let delta = Vector4::new(
            delta_edge_left,
            delta_wall_right,
            delta_edge_right,
            delta_wall_left,
        );
        let slip = Vector4::new(
            slip_edge_left,
            slip_wall_right,
            slip_edge_right,
            slip_wall_left,
        );
        let a = Vector4::new(edge_ma * t42, wall_ma * t41, edge_ma * t44, wall_ma * t39);
        let b = Vector4::new(edge_mb * t42, wall_mb * t41, edge_mb * t44, wall_mb * t39);
        let p0 = Vector4::new(
            T::from_f64(0.3183098861837907) * t43 * t42,
            T::from_f64(0.3183098861837907) * t40 * t41,
            T::from_f64(0.3183098861837907) * t43 * t44,
            T::from_f64(0.3183098861837907) * t40 * t39,
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
    /// 29 add/sub, 23 mul, 0 div, 0 sqrt, 6 transcendental, 4 branches; 20 `let`s.
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
        let t3 = sin_theta * (l_c - rho_p);
        let t4 = -T::from_f64(2.0) * t2 * (r - rho_p);
        let delta_wall_right = r + t0 + x + t3 + t4;
        let pen_wall_right = delta_wall_right.max0();
        let t5 = sin_theta * (-rho_h + z);
        let delta_edge_left = r + t0 - x + t5
            - T::from_f64(2.0) * (-rho_h + t0 - x) * t2;
        let pen_edge_left = delta_edge_left.max0();
        let delta_wall_left = r + t0 - x - t3 + t4;
        let pen_wall_left = delta_wall_left.max0();
        let delta_edge_right = r + t0 + x - t5
            + T::from_f64(2.0) * t2 * (rho_h + T::from_f64(0.5) * d - x);
        let pen_edge_right = delta_edge_right.max0();
        let t6 = pen_wall_right.powf(T::from_f64(2.5));
        let t7 = pen_edge_left.powf(T::from_f64(2.5));
        let t8 = pen_wall_left.powf(T::from_f64(2.5));
        let t9 = pen_edge_right.powf(T::from_f64(2.5));
        let kinetic = T::from_f64(0.5)
            * (m * (xdot * xdot + zdot * zdot) + j * (thetadot * thetadot));
        let potential = T::from_f64(0.4) * (t7 + t9) * k_edge
            + T::from_f64(0.4) * (t6 + t8) * k_wall;
        let depth = z + l_c * cos_theta;
        (kinetic, potential, depth)
    }
}
