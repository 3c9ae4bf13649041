// @generated readable copy of `pegdyn::generated::compliant_peg` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generated_snapshot

/// Compliant planar peg (*Dynamic analysis for peg-in-hole assembly with contact deformation*, (31)-(51), (55)-(64)) with contacts edge_left, wall_right, edge_right, wall_left. Inputs: state y (see STATE) and parameters p (see P_NAMES). SI units.
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
    /// 104 add/sub, 137 mul, 7 div, 4 sqrt, 6 transcendental, 16 branches; 90 `let`s.
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
        let t3 = f2 * sin_theta;
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
        let t23 = z - rho_h;
        let t24 = sin_theta * t23;
        let delta_edge_left = r + t4 - x + t24 - T::from_f64(2.0) * t5 * t9;
        let pen_edge_left = delta_edge_left.max0();
        let t25 = pen_edge_left * pen_edge_left.sqrt();
        let t26 = -xdot * t22;
        let t27 = cos_theta * t23;
        let step_delta_edge_left = delta_edge_left.step();
        let t28 = sin_theta * (l_c - rho_p + t18) + t19;
        let slip_wall_right = zdot - thetadot * t28;
        let t29 = v_s.hypot(slip_wall_right);
        let t30 = sin_theta * (-l_c + rho_p + t18) + t19;
        let slip_wall_left = zdot + thetadot * t30;
        let t31 = v_s.hypot(slip_wall_left);
        let delta_wall_right = r + t4 + x + t16 + t17;
        let pen_wall_right = delta_wall_right.max0();
        let t32 = pen_wall_right * pen_wall_right.sqrt();
        let step_delta_wall_right = delta_wall_right.step();
        let t33 = t13 * t15;
        let t34 = t20 - T::from_f64(2.0) * t33;
        let delta_rate_wall_right = xdot + thetadot * t34;
        let t35 = (T::from_f64(1.0) + hc_alpha * delta_rate_wall_right).max0();
        let t36 = sin_theta * t5 - t27;
        let t37 = cos_theta * t36 + t10;
        let t38 = t11 - sin_theta * t36;
        let slip_edge_left = sin_theta * (xdot + thetadot * t37)
            + cos_theta * (zdot + thetadot * t38);
        let t39 = t27 - T::from_f64(2.0) * t13 * t5;
        let delta_rate_edge_left = t26 + t12 + thetadot * t39;
        let t40 = (T::from_f64(1.0) + hc_alpha * delta_rate_edge_left).max0();
        let t41 = v_s.hypot(slip_edge_left);
        let t42 = sin_theta * t21 - t27;
        let t43 = t10 - cos_theta * t42;
        let t44 = t11 + sin_theta * t42;
        let slip_edge_right = sin_theta * (xdot - thetadot * t43)
            + cos_theta * (zdot - thetadot * t44);
        let t45 = t27 - T::from_f64(2.0) * t13 * t21;
        let neg_delta_rate_edge_right = t26 + t12 + thetadot * t45;
        let t46 = (T::from_f64(1.0) - hc_alpha * neg_delta_rate_edge_right).max0();
        let t47 = v_s.hypot(slip_edge_right);
        let t48 = T::from_f64(1.0) - t40;
        let t49 = T::from_f64(1.0) - t35;
        let delta_edge_right = r + t4 + x - t24 + T::from_f64(2.0) * t9 * t21;
        let pen_edge_right = delta_edge_right.max0();
        let t50 = pen_edge_right * pen_edge_right.sqrt();
        let t51 = T::from_f64(1.0) - t46;
        let step_delta_edge_right = delta_edge_right.step();
        let t52 = t40 / t41;
        let t53 = t52 * slip_edge_left;
        let t54 = t46 / t47;
        let t55 = t54 * slip_edge_right;
        let t56 = step_delta_edge_left - t48;
        let t57 = t51 - step_delta_edge_right;
        let t58 = t25 * t56 + t50 * t57;
        let t59 = mu * (t53 * t25 + t55 * t50);
        let t60 = t35 / t29;
        let t61 = t60 * slip_wall_right;
        let delta_wall_left = r + t4 - x - t16 + t17;
        let pen_wall_left = delta_wall_left.max0();
        let t62 = pen_wall_left * pen_wall_left.sqrt();
        let t63 = t20 + T::from_f64(2.0) * t33;
        let neg_delta_rate_wall_left = xdot + thetadot * t63;
        let t64 = (T::from_f64(1.0) - hc_alpha * neg_delta_rate_wall_left).max0();
        let step_delta_wall_left = delta_wall_left.step();
        let t65 = T::from_f64(1.0) - t64;
        let t66 = t64 / t31;
        let t67 = t66 * slip_wall_left;
        SMatrix::<
            T,
            8,
            1,
        >::from_row_slice(
            &[
                xdot,
                zdot,
                thetadot,
                (k_edge * (t22 * t58 - t59 * sin_theta)
                    + k_wall
                        * (t62 * (t64 - T::from_f64(1.0) + step_delta_wall_left)
                            - t32 * (-T::from_f64(1.0) + step_delta_wall_right + t35))
                    + t0 + t1) / m,
                -(k_edge * (sin_theta * t58 + t59 * cos_theta)
                    + k_wall * (t61 * t32 + t67 * t62) * mu - t2 + t3) / m,
                -(-m_2
                    + k_edge
                        * (t25
                            * (t39 * t56
                                + t53 * mu * (sin_theta * t37 + cos_theta * t38))
                            - t50
                                * (t55 * mu * (sin_theta * t43 + cos_theta * t44)
                                    - t45 * t57))
                    + k_wall
                        * (t62 * (t67 * mu * t30 - t63 * (step_delta_wall_left - t65))
                            - t32
                                * (t61 * mu * t28 - t34 * (step_delta_wall_right - t49))))
                    / j,
                xdot * (t0 + t1) + zdot * (t2 - t3) + thetadot * m_2,
                mu
                    * (k_edge
                        * (t52 * t25 * (slip_edge_left * slip_edge_left)
                            + t54 * t50 * (slip_edge_right * slip_edge_right))
                        + k_wall
                            * (t60 * t32 * (slip_wall_right * slip_wall_right)
                                + t66 * t62 * (slip_wall_left * slip_wall_left)))
                    - k_edge
                        * (delta_rate_edge_left * t25 * t48
                            - neg_delta_rate_edge_right * t50 * t51)
                    - k_wall
                        * (delta_rate_wall_right * t32 * t49
                            - neg_delta_rate_wall_left * t62 * t65),
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
    /// 360 add/sub, 717 mul, 10 div, 8 sqrt, 6 transcendental, 24 branches; 285 `let`s.
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
        let t34 = t24 + sin_theta * t21;
        let t35 = z - rho_h;
        let t36 = sin_theta * t35;
        let delta_edge_left = r + t6 - x + t36 - T::from_f64(2.0) * t7 * t11;
        let pen_edge_left = delta_edge_left.max0();
        let t37 = pen_edge_left * pen_edge_left.sqrt();
        let t38 = -xdot * t27;
        let t39 = cos_theta * t35;
        let step_delta_edge_left = delta_edge_left.step();
        let t40 = -l_c + rho_p + t20;
        let t41 = sin_theta * t40 + t24;
        let slip_wall_left = zdot + thetadot * t41;
        let t42 = v_s.hypot(slip_wall_left);
        let t43 = T::from_f64(1.0) / t42;
        let t44 = slip_wall_left * slip_wall_left;
        let delta_wall_right = r + t6 + x + t18 + t19;
        let pen_wall_right = delta_wall_right.max0();
        let t45 = pen_wall_right * pen_wall_right.sqrt();
        let step_delta_wall_right = delta_wall_right.step();
        let t46 = t15 * t17;
        let t47 = t25 - T::from_f64(2.0) * t46;
        let delta_rate_wall_right = xdot + thetadot * t47;
        let t48 = T::from_f64(1.0) + hc_alpha * delta_rate_wall_right;
        let t49 = t48.max0();
        let t50 = sin_theta * t7 - t39;
        let t51 = cos_theta * t50;
        let t52 = t51 + t12;
        let t53 = xdot + thetadot * t52;
        let t54 = t39 - T::from_f64(2.0) * t15 * t7;
        let delta_rate_edge_left = t38 + t14 + thetadot * t54;
        let t55 = T::from_f64(1.0) + hc_alpha * delta_rate_edge_left;
        let t56 = t55.max0();
        let t57 = sin_theta * t26 - t39;
        let t58 = -cos_theta * t57;
        let t59 = t12 + t58;
        let t60 = xdot - thetadot * t59;
        let t61 = sin_theta * t57;
        let t62 = t13 + t61;
        let t63 = zdot - thetadot * t62;
        let slip_edge_right = sin_theta * t60 + cos_theta * t63;
        let t64 = t39 - T::from_f64(2.0) * t15 * t26;
        let neg_delta_rate_edge_right = t38 + t14 + thetadot * t64;
        let t65 = T::from_f64(1.0) - hc_alpha * neg_delta_rate_edge_right;
        let t66 = t65.max0();
        let t67 = v_s.hypot(slip_edge_right);
        let t68 = T::from_f64(1.0) / t67;
        let t69 = sin_theta * t59 + cos_theta * t62;
        let t70 = slip_edge_right * slip_edge_right;
        let t71 = T::from_f64(1.0) - t56;
        let t72 = T::from_f64(1.0) - t49;
        let delta_edge_right = r + t6 + x - t36 + T::from_f64(2.0) * t11 * t26;
        let pen_edge_right = delta_edge_right.max0();
        let t73 = pen_edge_right * pen_edge_right.sqrt();
        let t74 = T::from_f64(1.0) - t66;
        let step_delta_edge_right = delta_edge_right.step();
        let t75 = t37 * (step_delta_edge_left - t71);
        let t76 = t73 * (t74 - step_delta_edge_right);
        let delta_wall_left = r + t6 - x - t18 + t19;
        let pen_wall_left = delta_wall_left.max0();
        let t77 = pen_wall_left * pen_wall_left.sqrt();
        let t78 = t25 + T::from_f64(2.0) * t46;
        let neg_delta_rate_wall_left = xdot + thetadot * t78;
        let t79 = T::from_f64(1.0) - hc_alpha * neg_delta_rate_wall_left;
        let t80 = t79.max0();
        let step_delta_wall_left = delta_wall_left.step();
        let t81 = T::from_f64(1.0) - t80;
        let sqrt_pen_edge_left = pen_edge_left.sqrt();
        let t82 = step_delta_edge_left * step_delta_edge_left;
        let t83 = T::from_f64(1.0) / (t42 * t42 * t42);
        let sqrt_pen_wall_right = pen_wall_right.sqrt();
        let t84 = step_delta_wall_right * step_delta_wall_right;
        let t85 = -T::from_f64(1.5) * t84;
        let t86 = sqrt_pen_edge_left * t82;
        let t87 = r + cos_theta * t7 + t36;
        let t88 = r - (t36 + cos_theta * t26);
        let t89 = t11 - t10 * t10;
        let t90 = t36 - t26 * t89;
        let slip_wall_right = zdot - thetadot * t34;
        let t91 = v_s.hypot(slip_wall_right);
        let t92 = T::from_f64(1.0) / t91;
        let t93 = slip_wall_right * slip_wall_right;
        let t94 = T::from_f64(1.0) / (t91 * t91 * t91);
        let t95 = t17 * t89;
        let t96 = t95 + t18;
        let t97 = t36 - t7 * t89;
        let t98 = T::from_f64(2.0) * t15 * xdot;
        let t99 = t48.step();
        let t100 = t47 * t47;
        let t101 = sin_theta * t50;
        let t102 = t13 - t101;
        let t103 = zdot + thetadot * t102;
        let slip_edge_left = sin_theta * t53 + cos_theta * t103;
        let t104 = v_s.hypot(slip_edge_left);
        let t105 = T::from_f64(1.0) / t104;
        let t106 = sin_theta * t52 + cos_theta * t102;
        let t107 = slip_edge_left * slip_edge_left;
        let t108 = t37 * t71;
        let t109 = t73 * t74;
        let t110 = slip_edge_left * t105;
        let t111 = slip_edge_right * t68;
        let t112 = t110 * t37 * t56 + t111 * t73 * t66;
        let t113 = t55.step();
        let t114 = t65.step();
        let t115 = T::from_f64(1.0) / (t104 * t104 * t104);
        let t116 = T::from_f64(1.0) / (t67 * t67 * t67);
        let t117 = t54 * t54;
        let t118 = t64 * t64;
        let t119 = step_delta_edge_left * sqrt_pen_edge_left;
        let t120 = t119 * (T::from_f64(1.5) - T::from_f64(1.5) * t56);
        let t121 = thetadot * hc_alpha;
        let t122 = t15 * t121;
        let t123 = t37 * t113;
        let t124 = T::from_f64(2.0) * t122 * t123;
        let t125 = t120 * t27 + t124;
        let sqrt_pen_edge_right = pen_edge_right.sqrt();
        let t126 = step_delta_edge_right * step_delta_edge_right;
        let t127 = step_delta_edge_right * sqrt_pen_edge_right;
        let t128 = t127 * (T::from_f64(1.5) - T::from_f64(1.5) * t66);
        let t129 = t73 * t114;
        let t130 = T::from_f64(2.0) * t122 * t129;
        let t131 = t128 * t27 + t130;
        let t132 = t119 * t56;
        let t133 = t127 * t66;
        let t134 = mu * (t132 * t110 - t133 * t111);
        let t135 = T::from_f64(1.5) - T::from_f64(1.5) * t49;
        let t136 = sqrt_pen_wall_right * (step_delta_wall_right * t135 + t85);
        let t137 = t121 * cos_theta;
        let t138 = sqrt_pen_edge_right * t126;
        let t139 = t86 + t138;
        let t140 = t27 * t139;
        let t141 = sin_theta * t87 + t51;
        let t142 = cos_theta * t88 + t61;
        let t143 = t70 * t116;
        let t144 = t107 * t115;
        let t145 = t56 * (t105 - t144);
        let t146 = t145 * t37;
        let t147 = t66 * (t68 - t143);
        let t148 = t147 * t73;
        let t149 = t146 + t148;
        let t150 = hc_alpha * (t123 + t129);
        let t151 = t99 * t45;
        let t152 = hc_alpha * t113;
        let t153 = t152 * t54;
        let t154 = hc_alpha * (t123 * t110 - t129 * t111);
        let t155 = t154 * mu;
        let t156 = t155 * thetadot;
        let t157 = rho_p * (sin_theta - T::from_f64(2.0) * t15);
        let t158 = hc_alpha * (t123 * t54 + t129 * t64);
        let t159 = t158 * sin_theta * k_edge;
        let t160 = t110 * t106;
        let t161 = sqrt_pen_edge_left
            * (t54 * t82 + t160 * mu * t56 * step_delta_edge_left);
        let t162 = t111 * t69;
        let t163 = sqrt_pen_edge_right
            * (t64 * t126 + t162 * mu * t66 * step_delta_edge_right);
        let t164 = t132 * t54;
        let t165 = t133 * t64;
        let t166 = t147 * t69;
        let t167 = t166 * t73;
        let t168 = hc_alpha * (t160 * t123 + t162 * t129);
        let t169 = t158 * t27;
        let t170 = mu * t41;
        let t171 = slip_wall_left * t43;
        let t172 = t146 * t106;
        let t173 = hc_alpha * t114;
        let t174 = t173 * t64;
        let t175 = t105 * t107;
        let t176 = t68 * t70;
        let t177 = t175 * t123 - t176 * t129;
        let t178 = t175 * t132 - t176 * t133;
        let t179 = hc_alpha
            * (mu * t177 + t123 * delta_rate_edge_left
                + t129 * neg_delta_rate_edge_right) - t108 + t109;
        let t180 = t43 * t44;
        let t181 = t115 * (slip_edge_left * slip_edge_left * slip_edge_left);
        let t182 = t56 * (T::from_f64(2.0) * t110 - t181) * t37;
        let t183 = t116 * (slip_edge_right * slip_edge_right * slip_edge_right);
        let t184 = t66 * (T::from_f64(2.0) * t111 - t183) * t73;
        let t185 = t83 * (slip_wall_left * slip_wall_left * slip_wall_left);
        let t186 = t56 * t106;
        let t187 = t66 * t69;
        let t188 = hc_alpha * t99;
        let t189 = t137 * t123 - t120 * sin_theta;
        let t190 = t137 * t129 - t128 * sin_theta;
        let t191 = k_edge * t28;
        let t192 = t101 - cos_theta * t87;
        let t193 = cos_theta * (thetadot * t141 - t53)
            + sin_theta * (thetadot * t192 + t103);
        let t194 = t98 + t33 - thetadot * t90;
        let t195 = t129 * t194;
        let t196 = t195 * hc_alpha - t128 * t64;
        let t197 = sin_theta * t88 + t58;
        let t198 = sin_theta * (thetadot * t142 + t63)
            - cos_theta * (t60 + thetadot * t197);
        let t199 = t173 * t194;
        let t200 = sin_theta * (cos_theta * (-t146 - t148) * mu + t150 * t27);
        let t201 = t37 * (t145 * t106 + t153 * t110) - t73 * (t166 + t174 * t111);
        let t202 = t23 - cos_theta * (t157 + t21);
        let t203 = t23 - cos_theta * (t157 + t40);
        let t204 = t121 * mu;
        let t205 = t37 * (step_delta_edge_left - t71 + t204 * t160 * t113);
        let t206 = t73 * (-step_delta_edge_right + t74 + t204 * t162 * t114);
        let t207 = t106 * t193;
        let t208 = t69 * t198;
        let t209 = thetadot * (t108 - t109);
        let t210 = t37 * t193;
        let t211 = t73 * t198;
        let sqrt_pen_wall_left = pen_wall_left.sqrt();
        let t212 = step_delta_wall_left * step_delta_wall_left;
        let t213 = t79.step();
        let t214 = t78 * t78;
        let t215 = T::from_f64(1.5) - T::from_f64(1.5) * t80;
        let t216 = -T::from_f64(1.5) * t212;
        let t217 = sqrt_pen_wall_left * (step_delta_wall_left * t215 + t216);
        let t218 = t77 * t213;
        let t219 = t218 * t96;
        let t220 = k_wall * hc_alpha;
        let t221 = t49 * (t92 - t93 * t94);
        let t222 = t221 * t45;
        let t223 = t80 * (t43 - t44 * t83);
        let t224 = slip_wall_right * t92;
        let t225 = t188 * t47;
        let t226 = t224 * t225;
        let t227 = step_delta_wall_left * sqrt_pen_wall_left;
        let t228 = mu * t34;
        let t229 = t224 * t49;
        let t230 = t171 * t80;
        let t231 = step_delta_wall_right * sqrt_pen_wall_right;
        let t232 = t231 * t47;
        let t233 = t227 * t78;
        let t234 = t233 * t215 + t219 * t121;
        let t235 = hc_alpha * t213;
        let t236 = t235 * t96;
        let t237 = t41 * t77;
        let t238 = t49 * t92 * t93;
        let t239 = t180 * t80;
        let t240 = t94 * (slip_wall_right * slip_wall_right * slip_wall_right);
        let t241 = t49 * t34;
        let t242 = t98 + t33 - thetadot * t97;
        let t243 = t123 * t242;
        let t244 = t243 * hc_alpha - t120 * t54;
        let t245 = t18 - t95;
        let t246 = t152 * t242;
        let t247 = t37 * (t246 * t110 - t145 * t193) - t73 * (t147 * t198 + t199 * t111)
            + T::from_f64(1.5) * (t164 * t110 - t165 * t111);
        let t248 = T::from_f64(1.5) * (t86 * t54 + t138 * t64) + t244 + t196;
        let t249 = t151 * t245;
        let t250 = t188 * t245;
        let t251 = t45 * (t250 * t224 - t221 * t202);
        let t252 = t236 * t171 - t223 * t203;
        let t253 = t235 * t78;
        let t254 = t171 * t253;
        let t255 = t232 * t135 + t249 * t121;
        let t256 = t49 * t202;
        let t257 = t80 * t203;
        let t258 = t41 * t80;
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
                        * (t27 * (T::from_f64(1.5) * t134 * sin_theta + t125 + t131)
                            - T::from_f64(1.5) * t139 * t31
                            - T::from_f64(2.0) * t156 * (t15 * sin_theta))
                        + k_wall * (t136 + t217)),
                t191
                    * (sin_theta * (T::from_f64(1.5) * t140 - t156 * cos_theta)
                        + t27 * (t189 + t190) - T::from_f64(1.5) * t134 * t30),
                t28
                    * (k_edge
                        * (-(mu * (sin_theta * t247 + cos_theta * t112)) + t27 * t248
                            + t15 * (-(T::from_f64(2.0) * t75) - T::from_f64(2.0) * t76))
                        + k_wall * (t136 * t47 + t217 * t78 + t121 * (t249 + t219)) + t3
                        + t4),
                -t28
                    * (k_edge * (mu * (t30 * t149 - sin_theta * t27 * t154) + t150 * t31)
                        + t220 * (t151 + t218)),
                t191 * (t200 - t155 * t30),
                -t28
                    * (k_edge * (sin_theta * t201 * mu - t169)
                        + t220 * (t151 * t47 + t218 * t78)),
                T::from_f64(0.0),
                T::from_f64(0.0),
                -t28
                    * (k_edge
                        * (sin_theta * (-(T::from_f64(1.5) * t140) + t125 + t131)
                            - cos_theta
                                * (t111 * (t130 - T::from_f64(1.5) * t133 * t27)
                                    - t110 * (t124 - T::from_f64(1.5) * t132 * t27)) * mu)
                        + T::from_f64(1.5) * (k_wall * (t229 * t231 - t230 * t227))
                            * mu),
                -t191
                    * (sin_theta * (T::from_f64(1.5) * t134 * cos_theta + t189 + t190)
                        + T::from_f64(1.5) * t139 * t30 + t156 * t32),
                -t28
                    * (-(mu
                        * (k_edge * (sin_theta * t112 - cos_theta * t247)
                            - k_wall
                                * (thetadot * (t77 * t252 - t251)
                                    + T::from_f64(1.5) * (t229 * t232 - t230 * t233))))
                        + k_edge * (cos_theta * (t75 + t76) + sin_theta * t248) + t0
                        + t1),
                t28
                    * (k_edge * (t200 + cos_theta * t27 * t155)
                        - t220 * (t151 * t224 - t218 * t171) * mu),
                -t28
                    * (mu
                        * (k_edge * (t32 * t149 + sin_theta * cos_theta * t154)
                            + k_wall * (t222 + t223 * t77)) + t150 * t30 * k_edge),
                t28
                    * (mu
                        * (k_wall
                            * (t77 * (t254 - t223 * t41) - t45 * (t226 - t221 * t34))
                            - cos_theta * t201 * k_edge) - t159),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t29
                    * (k_edge
                        * (t15 * (-(T::from_f64(2.0) * t205) - T::from_f64(2.0) * t206)
                            + t27 * (T::from_f64(1.5) * t161 + T::from_f64(1.5) * t163)
                            - t54 * t125 - t64 * t131)
                        + k_wall
                            * (sqrt_pen_wall_right
                                * (t47 * (t85 + t135 * step_delta_wall_right)
                                    + T::from_f64(1.5) * t228 * t229 * step_delta_wall_right)
                                + sqrt_pen_wall_left
                                    * (t78 * (t216 + t215 * step_delta_wall_left)
                                        + T::from_f64(1.5) * t170 * t230 * step_delta_wall_left))),
                -(k_edge
                    * (cos_theta * (t205 + t206)
                        - sin_theta
                            * (-(T::from_f64(1.5) * t161) - T::from_f64(1.5) * t163)
                        + t54 * t189 + t64 * t190)) * t29,
                -t29
                    * (mu
                        * (k_edge
                            * (t37
                                * (t246 * t160
                                    - t56
                                        * (t105
                                            * (t207
                                                + slip_edge_left
                                                    * (sin_theta * (t192 + t102) - cos_theta * (t52 - t141)))
                                            - t144 * t207))
                                + t73
                                    * (t66
                                        * (t68
                                            * (t208
                                                + slip_edge_right
                                                    * (sin_theta * (t62 - t142) - cos_theta * (t59 - t197)))
                                            - t143 * t208) + t199 * t162)
                                + T::from_f64(1.5) * (t164 * t160 + t165 * t162))
                            + k_wall
                                * (thetadot * (t251 * t34 + t237 * t252)
                                    - t229 * (T::from_f64(1.5) * t232 * t34 - t45 * t202)
                                    - t230 * (t77 * t203 + T::from_f64(1.5) * t233 * t41)))
                        + k_edge
                            * (-(t75 * t97) - t76 * t90
                                + T::from_f64(1.5) * (t86 * t117 + t138 * t118) + t54 * t244
                                + t64 * t196)
                        + k_wall
                            * (-((step_delta_wall_right - t72) * t245 * t45)
                                + (step_delta_wall_left - t81) * t96 * t77
                                + T::from_f64(1.5)
                                    * (sqrt_pen_wall_right * t84 * t100
                                        + sqrt_pen_wall_left * t212 * t214) - t47 * t255
                                - t78 * t234)),
                t29
                    * (k_edge * (mu * (sin_theta * (t167 - t172) + t168 * t27) + t169)
                        + t220
                            * (t151 * (t228 * t224 - t47) + t218 * (t170 * t171 - t78))),
                -t29
                    * (mu
                        * (k_edge * (cos_theta * (t172 - t167) + t168 * sin_theta)
                            + k_wall * (t237 * t223 - t222 * t34)) + t159),
                -t29
                    * (mu
                        * (k_edge
                            * (t37 * (t145 * (t106 * t106) + t153 * t160)
                                + t73 * (t147 * (t69 * t69) + t174 * t162))
                            - k_wall
                                * (t45 * (t226 * t34 - t221 * (t34 * t34))
                                    + t77 * (t254 * t41 - t223 * (t41 * t41))))
                        + hc_alpha
                            * (k_edge * (t123 * t117 + t129 * t118)
                                + k_wall * (t151 * t100 + t218 * t214))),
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
                        * (T::from_f64(2.0) * (t15 * t177) * t121
                            - T::from_f64(1.5) * t178 * t27)
                        - T::from_f64(2.0) * t209 * t15 + delta_rate_edge_left * t125
                        + neg_delta_rate_edge_right * t131)
                    - k_wall
                        * (-(T::from_f64(1.5) * (t238 * t231 - t239 * t227) * mu)
                            + t231 * t135 * delta_rate_wall_right
                            + t227 * t215 * neg_delta_rate_wall_left),
                k_edge
                    * (mu
                        * (T::from_f64(1.5) * t178 * sin_theta + cos_theta * t177 * t121)
                        - t209 * cos_theta + delta_rate_edge_left * t189
                        + neg_delta_rate_edge_right * t190),
                mu
                    * (k_edge
                        * (t56
                            * (t210 * t181
                                - t105
                                    * (T::from_f64(2.0) * t210 * slip_edge_left
                                        - T::from_f64(1.5) * t119 * t54 * t107))
                            - t66
                                * (t68
                                    * (T::from_f64(1.5) * t127 * t64 * t70
                                        + T::from_f64(2.0) * t211 * slip_edge_right) - t211 * t183)
                            + hc_alpha * (t243 * t175 - t195 * t176))
                        + k_wall
                            * (thetadot
                                * (t77
                                    * (t43
                                        * (t236 * t44 - T::from_f64(2.0) * t257 * slip_wall_left)
                                        + t257 * t185)
                                    - t45
                                        * (t92
                                            * (t250 * t93 - T::from_f64(2.0) * t256 * slip_wall_right)
                                            + t256 * t240))
                                + T::from_f64(1.5) * (t238 * t232 - t239 * t233)))
                    + k_edge
                        * (-(t108 * t242) + delta_rate_edge_left * t244 + t109 * t194
                            + neg_delta_rate_edge_right * t196)
                    - k_wall
                        * (thetadot * (t77 * t81 * t96 - t45 * t72 * t245)
                            + delta_rate_wall_right * t255
                            + neg_delta_rate_wall_left * t234),
                -(k_edge * (t27 * t179 + sin_theta * (-t182 - t184) * mu))
                    - k_wall
                        * (t45
                            * (-(t188 * (mu * t92 * t93 + delta_rate_wall_right)) - t49
                                + T::from_f64(1.0))
                            + t77
                                * (t235 * (t180 * mu - neg_delta_rate_wall_left)
                                    - T::from_f64(1.0) + t80)),
                k_edge * (sin_theta * t179 + cos_theta * (t182 + t184) * mu)
                    + k_wall
                        * (t49 * (T::from_f64(2.0) * t224 - t240) * t45
                            + t80 * (T::from_f64(2.0) * t171 - t185) * t77) * mu,
                -(mu
                    * (k_edge
                        * (t37
                            * (t186 * t181
                                - t105
                                    * (t153 * t107 + T::from_f64(2.0) * t186 * slip_edge_left))
                            - t73
                                * (t187 * t183
                                    - t68
                                        * (t174 * t70 + T::from_f64(2.0) * t187 * slip_edge_right)))
                        + k_wall
                            * (t77
                                * (t43
                                    * (t253 * t44 - T::from_f64(2.0) * t258 * slip_wall_left)
                                    + t258 * t185)
                                - t45
                                    * (t92
                                        * (t225 * t93 - T::from_f64(2.0) * t241 * slip_wall_right)
                                        + t241 * t240))))
                    + k_edge
                        * (t37 * (t152 * delta_rate_edge_left - t71) * t54
                            + t73 * (t74 + t173 * neg_delta_rate_edge_right) * t64)
                    + k_wall
                        * (t45 * (t188 * delta_rate_wall_right - t72) * t47
                            + t77 * (t81 + t235 * neg_delta_rate_wall_left) * t78),
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
        let t20 = z - rho_h;
        let t21 = sin_theta * t20;
        let delta_edge_left = r + t0 - x + t21 - T::from_f64(2.0) * t1 * t5;
        let pen_edge_left = delta_edge_left.max0();
        let t22 = pen_edge_left * pen_edge_left.sqrt();
        let t23 = -xdot * (T::from_f64(1.0) - T::from_f64(2.0) * t5);
        let t24 = cos_theta * t20;
        let slip_wall_right = zdot - thetadot * (sin_theta * (l_c - rho_p + t15) + t16);
        let t25 = v_s.hypot(slip_wall_right);
        let slip_wall_left = zdot + thetadot * (sin_theta * (-l_c + rho_p + t15) + t16);
        let t26 = v_s.hypot(slip_wall_left);
        let delta_wall_right = r + t0 + x + t13 + t14;
        let pen_wall_right = delta_wall_right.max0();
        let t27 = pen_wall_right * pen_wall_right.sqrt();
        let t28 = t9 * t12;
        let delta_rate_wall_right = xdot + thetadot * (t17 - T::from_f64(2.0) * t28);
        let t29 = (T::from_f64(1.0) + hc_alpha * delta_rate_wall_right).max0();
        let t30 = sin_theta * t1 - t24;
        let slip_edge_left = sin_theta * (xdot + thetadot * (cos_theta * t30 + t6))
            + cos_theta * (zdot + thetadot * (t7 - sin_theta * t30));
        let delta_rate_edge_left = t23 + t8
            + thetadot * (t24 - T::from_f64(2.0) * t9 * t1);
        let t31 = (T::from_f64(1.0) + hc_alpha * delta_rate_edge_left).max0();
        let t32 = v_s.hypot(slip_edge_left);
        let t33 = sin_theta * t19 - t24;
        let slip_edge_right = sin_theta * (xdot - thetadot * (t6 - cos_theta * t33))
            + cos_theta * (zdot - thetadot * (t7 + sin_theta * t33));
        let t34 = (T::from_f64(1.0)
            - hc_alpha * (t23 + t8 + thetadot * (t24 - T::from_f64(2.0) * t9 * t19)))
            .max0();
        let t35 = v_s.hypot(slip_edge_right);
        let delta_edge_right = r + t0 + x - t21 + T::from_f64(2.0) * t5 * t19;
        let pen_edge_right = delta_edge_right.max0();
        let t36 = pen_edge_right * pen_edge_right.sqrt();
        let delta_wall_left = r + t0 - x - t13 + t14;
        let pen_wall_left = delta_wall_left.max0();
        let t37 = pen_wall_left * pen_wall_left.sqrt();
        let t38 = (T::from_f64(1.0)
            - hc_alpha * (xdot + thetadot * (t17 + T::from_f64(2.0) * t28)))
            .max0();
        let normal_edge_left = k_edge * t22 * t31;
        let normal_wall_right = k_wall * t29 * t27;
        let t39 = (T::from_f64(1.5) * t10 * normal_edge_left).cbrt();
        let t40 = e_star * edge_sum * (T::from_f64(1.0) / (edge_ma * edge_mb));
        let t41 = (T::from_f64(1.5) * t18 * normal_wall_right).cbrt();
        let t42 = e_star * wall_sum * (T::from_f64(1.0) / (wall_ma * wall_mb));
        let normal_edge_right = k_edge * t34 * t36;
        let t43 = (T::from_f64(1.5) * t10 * normal_edge_right).cbrt();
        let normal_wall_left = k_wall * t37 * t38;
        let t44 = (T::from_f64(1.5) * t18 * normal_wall_left).cbrt();
        let normal = Vector4::new(
            normal_edge_left,
            normal_wall_right,
            normal_edge_right,
            normal_wall_left,
        );
        let friction = Vector4::new(
            -normal_edge_left * mu * slip_edge_left / t32,
            -normal_wall_right * mu * slip_wall_right / t25,
            -normal_edge_right * mu * slip_edge_right / t35,
            -normal_wall_left * mu * slip_wall_left / t26,
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
        let a = Vector4::new(edge_ma * t39, wall_ma * t41, edge_ma * t43, wall_ma * t44);
        let b = Vector4::new(edge_mb * t39, wall_mb * t41, edge_mb * t43, wall_mb * t44);
        let p0 = Vector4::new(
            T::from_f64(0.3183098861837907) * t40 * t39,
            T::from_f64(0.3183098861837907) * t42 * t41,
            T::from_f64(0.3183098861837907) * t40 * t43,
            T::from_f64(0.3183098861837907) * t42 * t44,
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
        let t5 = sin_theta * (z - rho_h);
        let delta_edge_left = r + t0 - x + t5
            - T::from_f64(2.0) * (-rho_h + t0 - x) * t2;
        let pen_edge_left = delta_edge_left.max0();
        let delta_wall_right = r + t0 + x + t3 + t4;
        let pen_wall_right = delta_wall_right.max0();
        let delta_edge_right = r + t0 + x - t5
            + T::from_f64(2.0) * t2 * (rho_h + T::from_f64(0.5) * d - x);
        let pen_edge_right = delta_edge_right.max0();
        let delta_wall_left = r + t0 - x - t3 + t4;
        let pen_wall_left = delta_wall_left.max0();
        let t6 = pen_edge_left.powf(T::from_f64(2.5));
        let t7 = pen_wall_right.powf(T::from_f64(2.5));
        let t8 = pen_edge_right.powf(T::from_f64(2.5));
        let t9 = pen_wall_left.powf(T::from_f64(2.5));
        let kinetic = T::from_f64(0.5)
            * (m * (xdot * xdot + zdot * zdot) + j * (thetadot * thetadot));
        let potential = T::from_f64(0.4) * (t6 + t8) * k_edge
            + T::from_f64(0.4) * (t7 + t9) * k_wall;
        let depth = z + l_c * cos_theta;
        (kinetic, potential, depth)
    }
}
