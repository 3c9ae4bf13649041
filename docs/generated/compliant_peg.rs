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
    /// 105 add/sub, 140 mul, 7 div, 4 sqrt, 6 transcendental, 16 branches; 89 `let`s.
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
        let t17 = rho_p * sin_theta;
        let t18 = cos_theta * (r - T::from_f64(2.0) * rho_p * t9);
        let t19 = cos_theta * t14;
        let t20 = rho_h + T::from_f64(0.5) * d - x;
        let t21 = T::from_f64(1.0) - T::from_f64(2.0) * t9;
        let t22 = -rho_h + z;
        let t23 = sin_theta * t22;
        let delta_edge_left = r + t4 - x + t23 - T::from_f64(2.0) * t5 * t9;
        let pen_edge_left = delta_edge_left.max0();
        let t24 = pen_edge_left * pen_edge_left.sqrt();
        let t25 = -xdot * t21;
        let t26 = cos_theta * t22;
        let step_delta_edge_left = delta_edge_left.step();
        let t27 = sin_theta * (l_c - rho_p + t17) + t18;
        let slip_wall_right = zdot - thetadot * t27;
        let t28 = v_s.hypot(slip_wall_right);
        let t29 = -rho_p + r;
        let t30 = sin_theta * (-l_c + rho_p + t17) + t18;
        let slip_wall_left = zdot + thetadot * t30;
        let t31 = v_s.hypot(slip_wall_left);
        let delta_wall_right = r + t4 + x + t16 - T::from_f64(2.0) * t9 * t15;
        let pen_wall_right = delta_wall_right.max0();
        let t32 = pen_wall_right * pen_wall_right.sqrt();
        let step_delta_wall_right = delta_wall_right.step();
        let t33 = t19 - T::from_f64(2.0) * t13 * t15;
        let delta_rate_wall_right = xdot + thetadot * t33;
        let t34 = (T::from_f64(1.0) + hc_alpha * delta_rate_wall_right).max0();
        let t35 = sin_theta * t5 - t26;
        let t36 = cos_theta * t35 + t10;
        let t37 = -(sin_theta * t35) + t11;
        let slip_edge_left = sin_theta * (xdot + thetadot * t36)
            + cos_theta * (zdot + thetadot * t37);
        let t38 = t26 - T::from_f64(2.0) * t13 * t5;
        let delta_rate_edge_left = t25 + t12 + thetadot * t38;
        let t39 = (T::from_f64(1.0) + hc_alpha * delta_rate_edge_left).max0();
        let t40 = v_s.hypot(slip_edge_left);
        let t41 = -t26 + sin_theta * t20;
        let t42 = t10 - cos_theta * t41;
        let t43 = t11 + sin_theta * t41;
        let slip_edge_right = sin_theta * (xdot - thetadot * t42)
            + cos_theta * (zdot - thetadot * t43);
        let t44 = t26 - T::from_f64(2.0) * t13 * t20;
        let t45 = t25 + t12 + thetadot * t44;
        let t46 = (T::from_f64(1.0) - hc_alpha * t45).max0();
        let t47 = v_s.hypot(slip_edge_right);
        let delta_wall_left = r + t4 - x - t16 - T::from_f64(2.0) * t9 * t29;
        let pen_wall_left = delta_wall_left.max0();
        let t48 = pen_wall_left * pen_wall_left.sqrt();
        let t49 = t19 + T::from_f64(2.0) * t13 * t29;
        let t50 = xdot + thetadot * t49;
        let t51 = (T::from_f64(1.0) - hc_alpha * t50).max0();
        let step_delta_wall_left = delta_wall_left.step();
        let t52 = -t39 + T::from_f64(1.0);
        let t53 = -t34 + T::from_f64(1.0);
        let delta_edge_right = r + t4 + x - t23 + T::from_f64(2.0) * t9 * t20;
        let pen_edge_right = delta_edge_right.max0();
        let t54 = pen_edge_right * pen_edge_right.sqrt();
        let t55 = -t46 + T::from_f64(1.0);
        let step_delta_edge_right = delta_edge_right.step();
        let t56 = -t51 + T::from_f64(1.0);
        let t57 = t39 / t40;
        let t58 = t57 * slip_edge_left;
        let t59 = t46 / t47;
        let t60 = t59 * slip_edge_right;
        let t61 = step_delta_edge_left - t52;
        let t62 = -step_delta_edge_right + t55;
        let t63 = t24 * t61 + t54 * t62;
        let t64 = mu * (t58 * t24 + t60 * t54);
        let t65 = t34 / t28;
        let t66 = t65 * slip_wall_right;
        let t67 = t51 / t31;
        let t68 = t67 * slip_wall_left;
        SMatrix::<
            T,
            8,
            1,
        >::from_row_slice(
            &[
                xdot,
                zdot,
                thetadot,
                (k_edge * (t21 * t63 - t64 * sin_theta)
                    + k_wall
                        * (-(t32 * (-T::from_f64(1.0) + step_delta_wall_right + t34))
                            + t48 * (t51 - T::from_f64(1.0) + step_delta_wall_left)) + t0
                    + t1) / m,
                -(k_edge * (sin_theta * t63 + t64 * cos_theta)
                    + k_wall * (t66 * t32 + t68 * t48) * mu - t2 + t3) / m,
                -(-m_2
                    + k_edge
                        * (t24
                            * (t38 * t61
                                + t58 * mu * (sin_theta * t36 + cos_theta * t37))
                            - t54
                                * (-(t44 * t62)
                                    + t60 * mu * (sin_theta * t42 + cos_theta * t43)))
                    + k_wall
                        * (-(t32
                            * (-(t33 * (step_delta_wall_right - t53)) + t66 * mu * t27))
                            + t48
                                * (-(t49 * (step_delta_wall_left - t56)) + t68 * mu * t30)))
                    / j,
                xdot * (t0 + t1) + zdot * (t2 - t3) + thetadot * m_2,
                mu
                    * (k_edge
                        * (t57 * t24 * (slip_edge_left * slip_edge_left)
                            + t59 * t54 * (slip_edge_right * slip_edge_right))
                        + k_wall
                            * (t65 * t32 * (slip_wall_right * slip_wall_right)
                                + t67 * t48 * (slip_wall_left * slip_wall_left)))
                    - k_edge * (delta_rate_edge_left * t24 * t52 - t45 * t54 * t55)
                    - k_wall * (delta_rate_wall_right * t32 * t53 - t50 * t48 * t56),
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
    /// 365 add/sub, 722 mul, 10 div, 8 sqrt, 6 transcendental, 24 branches; 289 `let`s.
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
        let t19 = rho_p * sin_theta;
        let t20 = l_c - rho_p + t19;
        let t21 = r - T::from_f64(2.0) * rho_p * t11;
        let t22 = sin_theta * t21;
        let t23 = cos_theta * t21;
        let t24 = sin_theta * t20;
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
        let t35 = t23 + t24;
        let t36 = -rho_h + z;
        let t37 = sin_theta * t36;
        let delta_edge_left = r + t6 - x + t37 - T::from_f64(2.0) * t7 * t11;
        let pen_edge_left = delta_edge_left.max0();
        let t38 = pen_edge_left * pen_edge_left.sqrt();
        let t39 = -xdot * t27;
        let t40 = cos_theta * t36;
        let step_delta_edge_left = delta_edge_left.step();
        let t41 = t24 + t23;
        let slip_wall_right = zdot - thetadot * t41;
        let t42 = v_s.hypot(slip_wall_right);
        let t43 = T::from_f64(1.0) / t42;
        let t44 = slip_wall_right * slip_wall_right;
        let t45 = -rho_p + r;
        let t46 = -l_c + rho_p + t19;
        let t47 = sin_theta * t46;
        let t48 = t47 + t23;
        let slip_wall_left = zdot + thetadot * t48;
        let t49 = v_s.hypot(slip_wall_left);
        let t50 = T::from_f64(1.0) / t49;
        let t51 = slip_wall_left * slip_wall_left;
        let delta_wall_right = r + t6 + x + t18 - T::from_f64(2.0) * t11 * t17;
        let pen_wall_right = delta_wall_right.max0();
        let t52 = pen_wall_right * pen_wall_right.sqrt();
        let step_delta_wall_right = delta_wall_right.step();
        let t53 = t25 - T::from_f64(2.0) * t15 * t17;
        let delta_rate_wall_right = xdot + thetadot * t53;
        let t54 = T::from_f64(1.0) + hc_alpha * delta_rate_wall_right;
        let t55 = t54.max0();
        let t56 = sin_theta * t7 - t40;
        let t57 = cos_theta * t56;
        let t58 = t57 + t12;
        let t59 = xdot + thetadot * t58;
        let t60 = t40 - T::from_f64(2.0) * t15 * t7;
        let delta_rate_edge_left = t39 + t14 + thetadot * t60;
        let t61 = T::from_f64(1.0) + hc_alpha * delta_rate_edge_left;
        let t62 = t61.max0();
        let t63 = -t40 + sin_theta * t26;
        let t64 = -cos_theta * t63;
        let t65 = t12 + t64;
        let t66 = xdot - thetadot * t65;
        let t67 = sin_theta * t63;
        let t68 = t13 + t67;
        let t69 = zdot - thetadot * t68;
        let slip_edge_right = sin_theta * t66 + cos_theta * t69;
        let t70 = t40 - T::from_f64(2.0) * t15 * t26;
        let t71 = t39 + t14 + thetadot * t70;
        let t72 = T::from_f64(1.0) - hc_alpha * t71;
        let t73 = t72.max0();
        let t74 = v_s.hypot(slip_edge_right);
        let t75 = T::from_f64(1.0) / t74;
        let t76 = sin_theta * t65 + cos_theta * t68;
        let t77 = slip_edge_right * slip_edge_right;
        let delta_wall_left = r + t6 - x - t18 - T::from_f64(2.0) * t11 * t45;
        let pen_wall_left = delta_wall_left.max0();
        let t78 = pen_wall_left * pen_wall_left.sqrt();
        let t79 = t25 + T::from_f64(2.0) * t15 * t45;
        let t80 = xdot + thetadot * t79;
        let t81 = T::from_f64(1.0) - hc_alpha * t80;
        let t82 = t81.max0();
        let step_delta_wall_left = delta_wall_left.step();
        let t83 = -t62 + T::from_f64(1.0);
        let t84 = -t55 + T::from_f64(1.0);
        let delta_edge_right = r + t6 + x - t37 + T::from_f64(2.0) * t11 * t26;
        let pen_edge_right = delta_edge_right.max0();
        let t85 = pen_edge_right * pen_edge_right.sqrt();
        let t86 = -t73 + T::from_f64(1.0);
        let step_delta_edge_right = delta_edge_right.step();
        let t87 = -t82 + T::from_f64(1.0);
        let t88 = t38 * (step_delta_edge_left - t83);
        let t89 = t85 * (-step_delta_edge_right + t86);
        let sqrt_pen_edge_left = pen_edge_left.sqrt();
        let t90 = step_delta_edge_left * step_delta_edge_left;
        let t91 = T::from_f64(1.0) / (t42 * t42 * t42);
        let t92 = T::from_f64(1.0) / (t49 * t49 * t49);
        let t93 = t23 + t47;
        let sqrt_pen_wall_right = pen_wall_right.sqrt();
        let t94 = step_delta_wall_right * step_delta_wall_right;
        let t95 = -T::from_f64(1.5) * t94;
        let t96 = sqrt_pen_edge_left * t90;
        let t97 = r + cos_theta * t7 + t37;
        let t98 = r - (t37 + cos_theta * t26);
        let t99 = -t34 + t11;
        let t100 = t45 * t99 + t18;
        let t101 = t11 - t34;
        let t102 = -(t7 * t101) + t37;
        let t103 = -(t17 * t101) + t18;
        let t104 = -(t26 * t99) + t37;
        let t105 = T::from_f64(2.0) * t15 * xdot;
        let t106 = t54.step();
        let t107 = t53 * t53;
        let t108 = sin_theta * t56;
        let t109 = -t108 + t13;
        let t110 = zdot + thetadot * t109;
        let slip_edge_left = sin_theta * t59 + cos_theta * t110;
        let t111 = v_s.hypot(slip_edge_left);
        let t112 = T::from_f64(1.0) / t111;
        let t113 = sin_theta * t58 + cos_theta * t109;
        let t114 = slip_edge_left * slip_edge_left;
        let t115 = t38 * t83;
        let t116 = t85 * t86;
        let t117 = slip_edge_left * t112;
        let t118 = slip_edge_right * t75;
        let t119 = t117 * t38 * t62 + t118 * t85 * t73;
        let t120 = t61.step();
        let t121 = t72.step();
        let sqrt_pen_wall_left = pen_wall_left.sqrt();
        let t122 = step_delta_wall_left * step_delta_wall_left;
        let t123 = T::from_f64(1.0) / (t111 * t111 * t111);
        let t124 = T::from_f64(1.0) / (t74 * t74 * t74);
        let t125 = t81.step();
        let t126 = t60 * t60;
        let t127 = t70 * t70;
        let t128 = t79 * t79;
        let t129 = step_delta_edge_left * sqrt_pen_edge_left;
        let t130 = t129 * (-(T::from_f64(1.5) * t62) + T::from_f64(1.5));
        let t131 = thetadot * hc_alpha;
        let t132 = t15 * t131;
        let t133 = t38 * t120;
        let t134 = T::from_f64(2.0) * t132 * t133;
        let t135 = t130 * t27 + t134;
        let sqrt_pen_edge_right = pen_edge_right.sqrt();
        let t136 = step_delta_edge_right * step_delta_edge_right;
        let t137 = step_delta_edge_right * sqrt_pen_edge_right;
        let t138 = t137 * (-(T::from_f64(1.5) * t73) + T::from_f64(1.5));
        let t139 = t85 * t121;
        let t140 = T::from_f64(2.0) * t132 * t139;
        let t141 = t138 * t27 + t140;
        let t142 = t129 * t62;
        let t143 = t137 * t73;
        let t144 = mu * (t142 * t117 - t143 * t118);
        let t145 = -T::from_f64(1.5) * t55;
        let t146 = sqrt_pen_wall_right
            * (step_delta_wall_right * (T::from_f64(1.5) + t145) + t95);
        let t147 = -(T::from_f64(1.5) * t82) + T::from_f64(1.5);
        let t148 = -T::from_f64(1.5) * t122;
        let t149 = sqrt_pen_wall_left * (step_delta_wall_left * t147 + t148);
        let t150 = t131 * cos_theta;
        let t151 = sqrt_pen_edge_right * t136;
        let t152 = t96 + t151;
        let t153 = t27 * t152;
        let t154 = sin_theta * t97 + t57;
        let t155 = cos_theta * t98 + t67;
        let t156 = t77 * t124;
        let t157 = t78 * t125;
        let t158 = t157 * t100;
        let t159 = t114 * t123;
        let t160 = t62 * (t112 - t159);
        let t161 = t160 * t38;
        let t162 = t73 * (t75 - t156);
        let t163 = t162 * t85;
        let t164 = t161 + t163;
        let t165 = hc_alpha * (t133 + t139);
        let t166 = t106 * t52;
        let t167 = k_wall * hc_alpha;
        let t168 = hc_alpha * t120;
        let t169 = t168 * t60;
        let t170 = hc_alpha * (t133 * t117 - t139 * t118);
        let t171 = t170 * mu;
        let t172 = t171 * thetadot;
        let t173 = rho_p * (sin_theta - T::from_f64(2.0) * t15);
        let t174 = t55 * (t43 - t44 * t91);
        let t175 = t174 * t52;
        let t176 = t82 * (t50 - t51 * t92);
        let t177 = slip_wall_right * t43;
        let t178 = hc_alpha * t106;
        let t179 = t178 * t53;
        let t180 = t177 * t179;
        let t181 = hc_alpha * (t133 * t60 + t139 * t70);
        let t182 = t181 * sin_theta * k_edge;
        let t183 = step_delta_wall_left * sqrt_pen_wall_left;
        let t184 = t117 * t113;
        let t185 = sqrt_pen_edge_left
            * (t60 * t90 + t184 * mu * t62 * step_delta_edge_left);
        let t186 = t118 * t76;
        let t187 = sqrt_pen_edge_right
            * (t70 * t136 + t186 * mu * t73 * step_delta_edge_right);
        let t188 = mu * t41;
        let t189 = t177 * t55;
        let t190 = mu * t48;
        let t191 = slip_wall_left * t50;
        let t192 = t191 * t82;
        let t193 = t145 + T::from_f64(1.5);
        let t194 = step_delta_wall_right * sqrt_pen_wall_right;
        let t195 = t194 * t53;
        let t196 = t183 * t79;
        let t197 = t196 * t147 + t158 * t131;
        let t198 = t142 * t60;
        let t199 = t143 * t70;
        let t200 = hc_alpha * t125;
        let t201 = t200 * t100;
        let t202 = t162 * t76;
        let t203 = t202 * t85;
        let t204 = hc_alpha * (t184 * t133 + t186 * t139);
        let t205 = t181 * t27;
        let t206 = t161 * t113;
        let t207 = t48 * t78;
        let t208 = hc_alpha * t121;
        let t209 = t208 * t70;
        let t210 = t112 * t114;
        let t211 = t75 * t77;
        let t212 = t210 * t133 - t211 * t139;
        let t213 = t55 * t43 * t44;
        let t214 = t82 * t50 * t51;
        let t215 = t210 * t142 - t211 * t143;
        let t216 = hc_alpha * (mu * t212 + t133 * delta_rate_edge_left + t139 * t71)
            - t115 + t116;
        let t217 = t123 * (slip_edge_left * slip_edge_left * slip_edge_left);
        let t218 = t62 * (-t217 + T::from_f64(2.0) * t117) * t38;
        let t219 = t124 * (slip_edge_right * slip_edge_right * slip_edge_right);
        let t220 = t73 * (-t219 + T::from_f64(2.0) * t118) * t85;
        let t221 = t91 * (slip_wall_right * slip_wall_right * slip_wall_right);
        let t222 = t92 * (slip_wall_left * slip_wall_left * slip_wall_left);
        let t223 = t62 * t113;
        let t224 = t73 * t76;
        let t225 = t55 * t41;
        let t226 = -(t130 * sin_theta) + t150 * t133;
        let t227 = -(t138 * sin_theta) + t150 * t139;
        let t228 = k_edge * t28;
        let t229 = t105 + t33 - thetadot * t102;
        let t230 = t133 * t229;
        let t231 = -(t130 * t60) + t230 * hc_alpha;
        let t232 = -(cos_theta * t97) + t108;
        let t233 = cos_theta * (-t59 + thetadot * t154)
            + sin_theta * (thetadot * t232 + t110);
        let t234 = t105 + t33 - thetadot * t104;
        let t235 = t139 * t234;
        let t236 = -(t138 * t70) + t235 * hc_alpha;
        let t237 = sin_theta * t98 + t64;
        let t238 = -(cos_theta * (t66 + thetadot * t237))
            + sin_theta * (thetadot * t155 + t69);
        let t239 = t168 * t229;
        let t240 = t208 * t234;
        let t241 = t38 * (-(t160 * t233) + t239 * t117)
            - t85 * (t162 * t238 + t240 * t118)
            + T::from_f64(1.5) * (t198 * t117 - t199 * t118);
        let t242 = T::from_f64(1.5) * (t96 * t60 + t151 * t70) + t231 + t236;
        let t243 = t166 * t103;
        let t244 = sin_theta * (cos_theta * (-t161 - t163) * mu + t165 * t27);
        let t245 = t38 * (t160 * t113 + t169 * t117) - t85 * (t202 + t209 * t118);
        let t246 = -(cos_theta * (t173 + t20)) + t22;
        let t247 = -(cos_theta * (t173 + t46)) + t22;
        let t248 = t178 * t103;
        let t249 = t52 * (-(t174 * t246) + t248 * t177);
        let t250 = -t176 * t247 + t201 * t191;
        let t251 = t200 * t79;
        let t252 = t191 * t251;
        let t253 = t131 * mu;
        let t254 = t38 * (step_delta_edge_left - t83 + t253 * t184 * t120);
        let t255 = t85 * (-step_delta_edge_right + t86 + t253 * t186 * t121);
        let t256 = t195 * t193 + t243 * t131;
        let t257 = t113 * t233;
        let t258 = t76 * t238;
        let t259 = thetadot * (t115 - t116);
        let t260 = t38 * t233;
        let t261 = t85 * t238;
        let t262 = t55 * t246;
        let t263 = t82 * t247;
        let t264 = t48 * t82;
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
                        * (t27 * (T::from_f64(1.5) * t144 * sin_theta + t135 + t141)
                            - T::from_f64(1.5) * t152 * t31
                            - T::from_f64(2.0) * t172 * (t15 * sin_theta))
                        + k_wall * (t146 + t149)),
                t228
                    * (sin_theta * (T::from_f64(1.5) * t153 - t172 * cos_theta)
                        + t27 * (t226 + t227) - T::from_f64(1.5) * t144 * t30),
                t28
                    * (k_edge
                        * (-(mu * (sin_theta * t241 + cos_theta * t119)) + t27 * t242
                            + t15 * (-(T::from_f64(2.0) * t88) - T::from_f64(2.0) * t89))
                        + k_wall * (t146 * t53 + t149 * t79 + t131 * (t243 + t158)) + t3
                        + t4),
                -t28
                    * (k_edge * (mu * (t30 * t164 - sin_theta * t27 * t170) + t165 * t31)
                        + t167 * (t166 + t157)),
                t228 * (t244 - t171 * t30),
                -t28
                    * (k_edge * (sin_theta * t245 * mu - t205)
                        + t167 * (t166 * t53 + t157 * t79)),
                T::from_f64(0.0),
                T::from_f64(0.0),
                -t28
                    * (k_edge
                        * (sin_theta * (-(T::from_f64(1.5) * t153) + t135 + t141)
                            - cos_theta
                                * (-(t117 * (-(T::from_f64(1.5) * t142 * t27) + t134))
                                    + t118 * (-(T::from_f64(1.5) * t143 * t27) + t140)) * mu)
                        + T::from_f64(1.5) * (k_wall * (t189 * t194 - t192 * t183))
                            * mu),
                -t228
                    * (sin_theta * (T::from_f64(1.5) * t144 * cos_theta + t226 + t227)
                        + T::from_f64(1.5) * t152 * t30 + t172 * t32),
                -t28
                    * (-(mu
                        * (k_edge * (-(cos_theta * t241) + sin_theta * t119)
                            - k_wall
                                * (thetadot * (-t249 + t78 * t250)
                                    + T::from_f64(1.5) * (t189 * t195 - t192 * t196))))
                        + k_edge * (cos_theta * (t88 + t89) + sin_theta * t242) + t0
                        + t1),
                t28
                    * (k_edge * (t244 + cos_theta * t27 * t171)
                        - t167 * (t166 * t177 - t157 * t191) * mu),
                -t28
                    * (mu
                        * (k_edge * (t32 * t164 + sin_theta * cos_theta * t170)
                            + k_wall * (t175 + t176 * t78)) + t165 * t30 * k_edge),
                t28
                    * (mu
                        * (-(cos_theta * t245 * k_edge)
                            + k_wall
                                * (-(t52 * (-(t174 * t41) + t180))
                                    + t78 * (-(t176 * t48) + t252))) - t182),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t29
                    * (k_edge
                        * (t15 * (-(T::from_f64(2.0) * t254) - T::from_f64(2.0) * t255)
                            + t27 * (T::from_f64(1.5) * t185 + T::from_f64(1.5) * t187)
                            - t60 * t135 - t70 * t141)
                        + k_wall
                            * (sqrt_pen_wall_right
                                * (t53 * (t95 + t193 * step_delta_wall_right)
                                    + T::from_f64(1.5) * t188 * t189 * step_delta_wall_right)
                                + sqrt_pen_wall_left
                                    * (t79 * (t148 + t147 * step_delta_wall_left)
                                        + T::from_f64(1.5) * t190 * t192 * step_delta_wall_left))),
                -(k_edge
                    * (cos_theta * (t254 + t255)
                        - sin_theta
                            * (-(T::from_f64(1.5) * t185) - T::from_f64(1.5) * t187)
                        + t60 * t226 + t70 * t227)) * t29,
                -t29
                    * (mu
                        * (k_edge
                            * (t38
                                * (-(t62
                                    * (t112
                                        * (t257
                                            + slip_edge_left
                                                * (-(cos_theta * (t58 - t154)) + sin_theta * (t232 + t109)))
                                        - t159 * t257)) + t239 * t184)
                                + t85
                                    * (t73
                                        * (t75
                                            * (t258
                                                + slip_edge_right
                                                    * (-(cos_theta * (t65 - t237)) + sin_theta * (-t155 + t68)))
                                            - t156 * t258) + t240 * t186)
                                + T::from_f64(1.5) * (t198 * t184 + t199 * t186))
                            + k_wall
                                * (thetadot * (t249 * t41 + t207 * t250)
                                    - t189 * (-(t52 * t246) + T::from_f64(1.5) * t195 * t41)
                                    - t192 * (t78 * t247 + T::from_f64(1.5) * t196 * t48)))
                        + k_edge
                            * (-(t88 * t102) - t89 * t104
                                + T::from_f64(1.5) * (t96 * t126 + t151 * t127) + t60 * t231
                                + t70 * t236)
                        + k_wall
                            * (-((step_delta_wall_right - t84) * t103 * t52)
                                + (step_delta_wall_left - t87) * t100 * t78
                                + T::from_f64(1.5)
                                    * (sqrt_pen_wall_right * t94 * t107
                                        + sqrt_pen_wall_left * t122 * t128) - t53 * t256
                                - t79 * t197)),
                t29
                    * (k_edge * (mu * (sin_theta * (-t206 + t203) + t204 * t27) + t205)
                        + t167
                            * (t166 * (-t53 + t188 * t177)
                                + t157 * (-t79 + t190 * t191))),
                -t29
                    * (mu
                        * (k_edge * (cos_theta * (t206 - t203) + t204 * sin_theta)
                            + k_wall * (-(t175 * t41) + t207 * t176)) + t182),
                -t29
                    * (mu
                        * (k_edge
                            * (t38 * (t160 * (t113 * t113) + t169 * t184)
                                + t85 * (t162 * (t76 * t76) + t209 * t186))
                            - k_wall
                                * (t52 * (-(t174 * (t35 * t35)) + t180 * t41)
                                    + t78 * (-(t176 * (t93 * t93)) + t252 * t48)))
                        + hc_alpha
                            * (k_edge * (t133 * t126 + t139 * t127)
                                + k_wall * (t166 * t107 + t157 * t128))),
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
                        * (-(T::from_f64(1.5) * t215 * t27)
                            + T::from_f64(2.0) * (t15 * t212) * t131)
                        - T::from_f64(2.0) * t259 * t15 + delta_rate_edge_left * t135
                        + t71 * t141)
                    - k_wall
                        * (-(T::from_f64(1.5) * (t213 * t194 - t214 * t183) * mu)
                            + t194 * t193 * delta_rate_wall_right + t183 * t147 * t80),
                k_edge
                    * (mu
                        * (T::from_f64(1.5) * t215 * sin_theta + cos_theta * t212 * t131)
                        - t259 * cos_theta + delta_rate_edge_left * t226 + t71 * t227),
                mu
                    * (k_edge
                        * (t62
                            * (-(t112
                                * (-(T::from_f64(1.5) * t129 * t60 * t114)
                                    + T::from_f64(2.0) * t260 * slip_edge_left)) + t260 * t217)
                            - t73
                                * (t75
                                    * (T::from_f64(1.5) * t137 * t70 * t77
                                        + T::from_f64(2.0) * t261 * slip_edge_right) - t261 * t219)
                            + hc_alpha * (t230 * t210 - t235 * t211))
                        + k_wall
                            * (thetadot
                                * (-(t52
                                    * (t43
                                        * (t248 * t44 - T::from_f64(2.0) * t262 * slip_wall_right)
                                        + t262 * t221))
                                    + t78
                                        * (t50
                                            * (t201 * t51 - T::from_f64(2.0) * t263 * slip_wall_left)
                                            + t263 * t222))
                                + T::from_f64(1.5) * (t213 * t195 - t214 * t196)))
                    + k_edge
                        * (-(t115 * t229) + delta_rate_edge_left * t231 + t116 * t234
                            + t71 * t236)
                    - k_wall
                        * (thetadot * (-(t52 * t84 * t103) + t78 * t87 * t100)
                            + delta_rate_wall_right * t256 + t80 * t197),
                -(k_edge * (t27 * t216 + sin_theta * (-t218 - t220) * mu))
                    - k_wall
                        * (t52
                            * (-(t178 * (mu * t43 * t44 + delta_rate_wall_right)) - t55
                                + T::from_f64(1.0))
                            + t78
                                * (t200 * (mu * t50 * t51 - t80) - T::from_f64(1.0) + t82)),
                k_edge * (sin_theta * t216 + cos_theta * (t218 + t220) * mu)
                    + k_wall
                        * (t55 * (-t221 + T::from_f64(2.0) * t177) * t52
                            + t82 * (-t222 + T::from_f64(2.0) * t191) * t78) * mu,
                -(mu
                    * (k_edge
                        * (t38
                            * (-(t112
                                * (t169 * t114 + T::from_f64(2.0) * t223 * slip_edge_left))
                                + t223 * t217)
                            - t85
                                * (-(t75
                                    * (t209 * t77 + T::from_f64(2.0) * t224 * slip_edge_right))
                                    + t224 * t219))
                        + k_wall
                            * (-(t52
                                * (t43
                                    * (t179 * t44 - T::from_f64(2.0) * t225 * slip_wall_right)
                                    + t225 * t221))
                                + t78
                                    * (t50
                                        * (t251 * t51 - T::from_f64(2.0) * t264 * slip_wall_left)
                                        + t264 * t222))))
                    + k_edge
                        * (t38 * (-t83 + t168 * delta_rate_edge_left) * t60
                            + t85 * (t86 + t208 * t71) * t70)
                    + k_wall
                        * (t52 * (-t84 + t178 * delta_rate_wall_right) * t53
                            + t78 * (t87 + t200 * t80) * t79),
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
    /// 60 add/sub, 112 mul, 8 div, 4 sqrt, 10 transcendental, 8 branches; 64 `let`s.
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
        let t14 = rho_p * sin_theta;
        let t15 = cos_theta * (r - T::from_f64(2.0) * rho_p * t5);
        let t16 = cos_theta * t11;
        let t17 = T::from_f64(1.0) / (e_star * wall_sum);
        let t18 = rho_h + T::from_f64(0.5) * d - x;
        let t19 = -rho_h + z;
        let t20 = sin_theta * t19;
        let delta_edge_left = r + t0 - x + t20 - T::from_f64(2.0) * t1 * t5;
        let pen_edge_left = delta_edge_left.max0();
        let t21 = pen_edge_left * pen_edge_left.sqrt();
        let t22 = -xdot * (T::from_f64(1.0) - T::from_f64(2.0) * t5);
        let t23 = cos_theta * t19;
        let slip_wall_right = zdot - thetadot * (sin_theta * (l_c - rho_p + t14) + t15);
        let t24 = v_s.hypot(slip_wall_right);
        let t25 = -rho_p + r;
        let slip_wall_left = zdot + thetadot * (sin_theta * (-l_c + rho_p + t14) + t15);
        let t26 = v_s.hypot(slip_wall_left);
        let delta_wall_right = r + t0 + x + t13 - T::from_f64(2.0) * t5 * t12;
        let pen_wall_right = delta_wall_right.max0();
        let t27 = pen_wall_right * pen_wall_right.sqrt();
        let delta_rate_wall_right = xdot
            + thetadot * (t16 - T::from_f64(2.0) * t9 * t12);
        let t28 = (T::from_f64(1.0) + hc_alpha * delta_rate_wall_right).max0();
        let t29 = sin_theta * t1 - t23;
        let slip_edge_left = sin_theta * (xdot + thetadot * (cos_theta * t29 + t6))
            + cos_theta * (zdot + thetadot * (-(sin_theta * t29) + t7));
        let delta_rate_edge_left = t22 + t8
            + thetadot * (t23 - T::from_f64(2.0) * t9 * t1);
        let t30 = (T::from_f64(1.0) + hc_alpha * delta_rate_edge_left).max0();
        let t31 = v_s.hypot(slip_edge_left);
        let t32 = -t23 + sin_theta * t18;
        let slip_edge_right = sin_theta * (xdot - thetadot * (t6 - cos_theta * t32))
            + cos_theta * (zdot - thetadot * (t7 + sin_theta * t32));
        let t33 = (T::from_f64(1.0)
            - hc_alpha * (t22 + t8 + thetadot * (t23 - T::from_f64(2.0) * t9 * t18)))
            .max0();
        let t34 = v_s.hypot(slip_edge_right);
        let delta_wall_left = r + t0 - x - t13 - T::from_f64(2.0) * t5 * t25;
        let pen_wall_left = delta_wall_left.max0();
        let t35 = pen_wall_left * pen_wall_left.sqrt();
        let t36 = (T::from_f64(1.0)
            - hc_alpha * (xdot + thetadot * (t16 + T::from_f64(2.0) * t9 * t25)))
            .max0();
        let delta_edge_right = r + t0 + x - t20 + T::from_f64(2.0) * t5 * t18;
        let pen_edge_right = delta_edge_right.max0();
        let t37 = pen_edge_right * pen_edge_right.sqrt();
        let normal_edge_left = k_edge * t21 * t30;
        let normal_wall_left = k_wall * t35 * t36;
        let normal_wall_right = k_wall * t28 * t27;
        let t38 = (T::from_f64(1.5) * t10 * normal_edge_left).cbrt();
        let t39 = e_star * edge_sum * (T::from_f64(1.0) / (edge_ma * edge_mb));
        let t40 = (T::from_f64(1.5) * t17 * normal_wall_left).cbrt();
        let t41 = e_star * wall_sum * (T::from_f64(1.0) / (wall_ma * wall_mb));
        let t42 = (T::from_f64(1.5) * t17 * normal_wall_right).cbrt();
        let normal_edge_right = k_edge * t33 * t37;
        let t43 = (T::from_f64(1.5) * t10 * normal_edge_right).cbrt();
        let normal = Vector4::new(
            normal_edge_left,
            normal_wall_right,
            normal_edge_right,
            normal_wall_left,
        );
        let friction = Vector4::new(
            -normal_edge_left * mu * slip_edge_left / t31,
            -normal_wall_right * mu * slip_wall_right / t24,
            -normal_edge_right * mu * slip_edge_right / t34,
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
        let a = Vector4::new(edge_ma * t38, wall_ma * t42, edge_ma * t43, wall_ma * t40);
        let b = Vector4::new(edge_mb * t38, wall_mb * t42, edge_mb * t43, wall_mb * t40);
        let p0 = Vector4::new(
            T::from_f64(0.3183098861837907) * t39 * t38,
            T::from_f64(0.3183098861837907) * t41 * t42,
            T::from_f64(0.3183098861837907) * t39 * t43,
            T::from_f64(0.3183098861837907) * t41 * t40,
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
    /// 30 add/sub, 25 mul, 0 div, 0 sqrt, 6 transcendental, 4 branches; 19 `let`s.
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
        let t4 = sin_theta * (-rho_h + z);
        let delta_edge_left = r + t0 - x + t4
            - T::from_f64(2.0) * (-rho_h + t0 - x) * t2;
        let pen_edge_left = delta_edge_left.max0();
        let delta_wall_right = r + t0 + x + t3 - T::from_f64(2.0) * t2 * (r - rho_p);
        let pen_wall_right = delta_wall_right.max0();
        let delta_wall_left = r + t0 - x - t3 - T::from_f64(2.0) * t2 * (-rho_p + r);
        let pen_wall_left = delta_wall_left.max0();
        let delta_edge_right = r + t0 + x - t4
            + T::from_f64(2.0) * t2 * (rho_h + T::from_f64(0.5) * d - x);
        let pen_edge_right = delta_edge_right.max0();
        let t5 = pen_edge_left.powf(T::from_f64(2.5));
        let t6 = pen_wall_right.powf(T::from_f64(2.5));
        let t7 = pen_wall_left.powf(T::from_f64(2.5));
        let t8 = pen_edge_right.powf(T::from_f64(2.5));
        let kinetic = T::from_f64(0.5)
            * (m * (xdot * xdot + zdot * zdot) + j * (thetadot * thetadot));
        let potential = T::from_f64(0.4) * (t5 + t8) * k_edge
            + T::from_f64(0.4) * (t6 + t7) * k_wall;
        let depth = z + l_c * cos_theta;
        (kinetic, potential, depth)
    }
}
