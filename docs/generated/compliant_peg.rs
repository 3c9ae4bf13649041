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
    /// 110 add/sub, 149 mul, 7 div, 4 sqrt, 6 transcendental, 16 branches; 92 `let`s.
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
        let t8 = sin_theta * t7;
        let t9 = T::from_f64(0.5) * theta;
        let (t10, t22) = t9.sin_cos();
        let t11 = t10 * t10;
        let t12 = cos_theta * t7;
        let t13 = sin_theta * t6 + t12;
        let t14 = -r;
        let t15 = r * sin_theta;
        let t16 = cos_theta * t13 + t15;
        let t17 = r * cos_theta;
        let t18 = -(sin_theta * t13) + t17;
        let t19 = sin_theta * (xdot + thetadot * t16)
            + cos_theta * (zdot + thetadot * t18);
        let t20 = -T::from_f64(1.0) + T::from_f64(2.0) * t11;
        let t21 = zdot * sin_theta;
        let t23 = t10 * t22;
        let t24 = v_s.hypot(t19);
        let t25 = -rho_p;
        let t26 = l_c + t25;
        let t27 = r + t25;
        let t28 = sin_theta * t26;
        let t29 = rho_p * sin_theta;
        let t30 = rho_p * t11;
        let t31 = cos_theta * t26;
        let t32 = rho_h + T::from_f64(0.5) * d + t5;
        let t33 = t12 + sin_theta * t32;
        let t34 = T::from_f64(1.0) - T::from_f64(2.0) * t11;
        let t35 = rho_p + t14;
        let t36 = r + t4 + x + t28 - T::from_f64(2.0) * t11 * t27;
        let t37 = t36.max0();
        let t38 = t37 * t37.sqrt();
        let t39 = t36.step();
        let t40 = r + t4 + x + t8 + T::from_f64(2.0) * t11 * t32;
        let t41 = t40.max0();
        let t42 = t41 * t41.sqrt();
        let t43 = t40.step();
        let t44 = -t39;
        let t45 = r + t4 + t5 - t8 - T::from_f64(2.0) * t6 * t11;
        let t46 = t45.max0();
        let t47 = t46 * t46.sqrt();
        let t48 = -t12 - T::from_f64(2.0) * t23 * t6;
        let t49 = xdot * t20 + t21 + thetadot * t48;
        let t50 = (T::from_f64(1.0) + hc_alpha * t49).max0();
        let t51 = t45.step();
        let t52 = -(sin_theta * (l_c + t25 + t29))
            - cos_theta * (r - T::from_f64(2.0) * t30);
        let t53 = zdot + thetadot * t52;
        let t54 = t31 - T::from_f64(2.0) * t23 * t27;
        let t55 = xdot + thetadot * t54;
        let t56 = (T::from_f64(1.0) + hc_alpha * t55).max0();
        let t57 = v_s.hypot(t53);
        let t58 = -t15 + cos_theta * t33;
        let t59 = -t17 - sin_theta * t33;
        let t60 = sin_theta * (xdot + thetadot * t58)
            + cos_theta * (zdot + thetadot * t59);
        let t61 = t12 + T::from_f64(2.0) * t23 * t32;
        let t62 = xdot * t34 - t21 + thetadot * t61;
        let t63 = (T::from_f64(1.0) + hc_alpha * t62).max0();
        let t64 = v_s.hypot(t60);
        let t65 = r + t4 + t5 - t28 + T::from_f64(2.0) * t11 * t35;
        let t66 = -(sin_theta * (l_c + t25 - t29))
            - cos_theta * (t14 + T::from_f64(2.0) * t30);
        let t67 = zdot + thetadot * t66;
        let t68 = t65.max0();
        let t69 = t68 * t68.sqrt();
        let t70 = -t31 + T::from_f64(2.0) * t23 * t35;
        let t71 = -xdot + thetadot * t70;
        let t72 = (T::from_f64(1.0) + hc_alpha * t71).max0();
        let t73 = v_s.hypot(t67);
        let t74 = t65.step();
        let t75 = t50 - T::from_f64(1.0);
        let t76 = t56 - T::from_f64(1.0);
        let t77 = t63 - T::from_f64(1.0);
        let t78 = t72 - T::from_f64(1.0);
        let t79 = -t51 - t75;
        let t80 = mu * sin_theta;
        let t81 = t50 / t24;
        let t82 = t81 * t19;
        let t83 = -t43 - t77;
        let t84 = t63 / t64;
        let t85 = t84 * t60;
        let t86 = t56 / t57;
        let t87 = t86 * t53;
        let t88 = t72 / t73;
        let t89 = t88 * t67;
        SMatrix::<
            T,
            8,
            1,
        >::from_row_slice(
            &[
                xdot,
                zdot,
                thetadot,
                (k_edge * (t47 * (t20 * t79 - t80 * t82) + t42 * (t34 * t83 - t80 * t85))
                    + k_wall
                        * (t38 * (T::from_f64(1.0) + t44 - t56)
                            + t69 * (t72 - T::from_f64(1.0) + t74)) + t0 + t1) / m,
                (k_edge
                    * (sin_theta * (t47 * t79 + t42 * (t43 + t77))
                        + cos_theta * (-(t82 * t47) - t85 * t42) * mu)
                    + k_wall * (-(t87 * t38) - t89 * t69) * mu + t2 + t3) / m,
                (m_2
                    + k_edge
                        * (t47
                            * (t48 * t79
                                - t82 * mu * (sin_theta * t16 + cos_theta * t18))
                            + t42
                                * (t61 * t83
                                    - t85 * mu * (sin_theta * t58 + cos_theta * t59)))
                    + k_wall
                        * (t38 * (t54 * (t44 - t76) - t87 * mu * t52)
                            + t69 * (t70 * (-t74 - t78) - t89 * mu * t66))) / j,
                xdot * (t0 + t1) + zdot * (t2 + t3) + thetadot * m_2,
                mu
                    * (k_edge * (t81 * t47 * (t19 * t19) + t84 * t42 * (t60 * t60))
                        + k_wall * (t86 * t38 * (t53 * t53) + t88 * t69 * (t67 * t67)))
                    + k_edge * (t49 * t47 * t75 + t62 * t42 * t77)
                    + k_wall * (t55 * t38 * t76 + t71 * t69 * t78),
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
    /// 388 add/sub, 756 mul, 10 div, 8 sqrt, 6 transcendental, 24 branches; 306 `let`s.
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
        let (t11, t27) = t10.sin_cos();
        let t12 = t11 * t11;
        let t13 = cos_theta * t8;
        let t14 = sin_theta * t7 + t13;
        let t15 = -r;
        let t16 = cos_theta * t14;
        let t17 = r * sin_theta;
        let t18 = t16 + t17;
        let t19 = xdot + thetadot * t18;
        let t20 = -sin_theta * t14;
        let t21 = r * cos_theta;
        let t22 = t20 + t21;
        let t23 = zdot + thetadot * t22;
        let t24 = sin_theta * t19 + cos_theta * t23;
        let t25 = -T::from_f64(1.0) + T::from_f64(2.0) * t12;
        let t26 = zdot * sin_theta;
        let t28 = t11 * t27;
        let t29 = v_s.hypot(t24);
        let t30 = T::from_f64(1.0) / t29;
        let t31 = sin_theta * t18 + cos_theta * t22;
        let t32 = t24 * t24;
        let t33 = -rho_p;
        let t34 = l_c + t33;
        let t35 = r + t33;
        let t36 = sin_theta * t34;
        let t37 = rho_p * sin_theta;
        let t38 = l_c + t33 + t37;
        let t39 = rho_p * t12;
        let t40 = sin_theta * t38;
        let t41 = cos_theta * t34;
        let t42 = rho_h + T::from_f64(0.5) * d + t6;
        let t43 = t13 + sin_theta * t42;
        let t44 = cos_theta * t43;
        let t45 = -sin_theta * t43;
        let t46 = T::from_f64(1.0) - T::from_f64(2.0) * t12;
        let t47 = rho_p + t15;
        let t48 = T::from_f64(1.0) / m;
        let t49 = T::from_f64(1.0) / j;
        let t50 = t25 * t25;
        let t51 = sin_theta * sin_theta;
        let t52 = t46 * t46;
        let t53 = cos_theta * cos_theta;
        let t54 = zdot * cos_theta;
        let t55 = t27 * t27;
        let t56 = T::from_f64(1.0) / (t29 * t29 * t29);
        let t57 = r + t5 + x + t36 - T::from_f64(2.0) * t12 * t35;
        let t58 = t57.max0();
        let t59 = t58 * t58.sqrt();
        let t60 = t57.step();
        let t61 = r + t5 + x + t9 + T::from_f64(2.0) * t12 * t42;
        let t62 = t61.max0();
        let t63 = t62 * t62.sqrt();
        let t64 = t61.step();
        let t65 = -t9;
        let t66 = r + t5 + t6 + t65 - T::from_f64(2.0) * t7 * t12;
        let t67 = t66.max0();
        let t68 = t67 * t67.sqrt();
        let t69 = -t13 - T::from_f64(2.0) * t28 * t7;
        let t70 = xdot * t25 + t26 + thetadot * t69;
        let t71 = T::from_f64(1.0) + hc_alpha * t70;
        let t72 = t71.max0();
        let t73 = t66.step();
        let t74 = r - T::from_f64(2.0) * t39;
        let t75 = t41 - T::from_f64(2.0) * t28 * t35;
        let t76 = xdot + thetadot * t75;
        let t77 = T::from_f64(1.0) + hc_alpha * t76;
        let t78 = t77.max0();
        let t79 = -t17 + t44;
        let t80 = xdot + thetadot * t79;
        let t81 = -t21 + t45;
        let t82 = zdot + thetadot * t81;
        let t83 = sin_theta * t80 + cos_theta * t82;
        let t84 = t13 + T::from_f64(2.0) * t28 * t42;
        let t85 = xdot * t46 - t26 + thetadot * t84;
        let t86 = T::from_f64(1.0) + hc_alpha * t85;
        let t87 = t86.max0();
        let t88 = v_s.hypot(t83);
        let t89 = T::from_f64(1.0) / t88;
        let t90 = sin_theta * t79 + cos_theta * t81;
        let t91 = t83 * t83;
        let t92 = -t36;
        let t93 = r + t5 + t6 + t92 + T::from_f64(2.0) * t12 * t47;
        let t94 = l_c + t33 - t37;
        let t95 = t15 + T::from_f64(2.0) * t39;
        let t96 = t93.max0();
        let t97 = t96 * t96.sqrt();
        let t98 = -t41 + T::from_f64(2.0) * t28 * t47;
        let t99 = -xdot + thetadot * t98;
        let t100 = T::from_f64(1.0) + hc_alpha * t99;
        let t101 = t100.max0();
        let t102 = t93.step();
        let t103 = t72 - T::from_f64(1.0);
        let t104 = t78 - T::from_f64(1.0);
        let t105 = t87 - T::from_f64(1.0);
        let t106 = t101 - T::from_f64(1.0);
        let t107 = -t73;
        let t108 = -t103;
        let t109 = mu * sin_theta;
        let t110 = t68 * (t107 + t108);
        let t111 = t63 * (t64 + t105);
        let t112 = t58.sqrt();
        let t113 = t60 * t60;
        let t114 = t62.sqrt();
        let t115 = t64 * t64;
        let t116 = -T::from_f64(1.5) * t113;
        let t117 = t12 - t55;
        let t118 = t7 * t117 + t9;
        let t119 = t55 - t12;
        let t120 = t47 * t119 + t36;
        let t121 = t32 * t56;
        let t122 = cos_theta * t7 + t65;
        let t123 = cos_theta * t74;
        let t124 = -t40 - t123;
        let t125 = zdot + thetadot * t124;
        let t126 = v_s.hypot(t125);
        let t127 = T::from_f64(1.0) / t126;
        let t128 = t125 * t125;
        let t129 = t65 + cos_theta * t42;
        let t130 = sin_theta * t94;
        let t131 = cos_theta * t95;
        let t132 = -t130 - t131;
        let t133 = zdot + thetadot * t132;
        let t134 = v_s.hypot(t133);
        let t135 = T::from_f64(1.0) / t134;
        let t136 = t133 * t133;
        let t137 = t67.sqrt();
        let t138 = t73 * t73;
        let t139 = t71.step();
        let t140 = t86.step();
        let t141 = t96.sqrt();
        let t142 = t102 * t102;
        let t143 = t28 * xdot;
        let t144 = t77.step();
        let t145 = T::from_f64(1.0) / (t88 * t88 * t88);
        let t146 = t100.step();
        let t147 = -t0;
        let t148 = -t1;
        let t149 = T::from_f64(1.0) / (t126 * t126 * t126);
        let t150 = T::from_f64(1.0) / (t134 * t134 * t134);
        let t151 = t69 * t69;
        let t152 = t75 * t75;
        let t153 = t84 * t84;
        let t154 = t98 * t98;
        let t155 = t123 + t40;
        let t156 = t131 + t130;
        let t157 = t68 * t103;
        let t158 = t24 * t30;
        let t159 = t158 * t68 * t72;
        let t160 = t83 * t89;
        let t161 = t160 * t87 * t63;
        let t162 = t73 * t137;
        let t163 = t162 * (T::from_f64(1.5) * t72 - T::from_f64(1.5));
        let t164 = t68 * t139;
        let t165 = thetadot * hc_alpha;
        let t166 = t28 * t165;
        let t167 = t164 * t166;
        let t168 = T::from_f64(2.0) * t167;
        let t169 = t163 * t25 + t168;
        let t170 = t64 * t114;
        let t171 = t170 * (T::from_f64(1.5) * t87 - T::from_f64(1.5));
        let t172 = t140 * t63;
        let t173 = t172 * t166;
        let t174 = -T::from_f64(2.0) * t173;
        let t175 = t171 * t46 + t174;
        let t176 = t162 * t72;
        let t177 = t176 * t25;
        let t178 = t170 * t87;
        let t179 = t178 * t46;
        let t180 = t158 * (-(T::from_f64(1.5) * t177) - T::from_f64(2.0) * t167)
            + t160 * (-(T::from_f64(1.5) * t179) + T::from_f64(2.0) * t173);
        let t181 = t137 * t138;
        let t182 = t114 * t115;
        let t183 = t112 * (t60 * (T::from_f64(1.5) - T::from_f64(1.5) * t78) + t116);
        let t184 = -(T::from_f64(1.5) * t101) + T::from_f64(1.5);
        let t185 = t165 * cos_theta;
        let t186 = t163 * sin_theta + t185 * t164;
        let t187 = t170 * (-(T::from_f64(1.5) * t87) + T::from_f64(1.5)) * sin_theta
            - t185 * t172;
        let t188 = -(t158 * t164) + t172 * t160;
        let t189 = hc_alpha * t188;
        let t190 = mu * cos_theta;
        let t191 = T::from_f64(1.5) * (-(t181 * t25) + t182 * t46);
        let t192 = -(t176 * t158) + t178 * t160;
        let t193 = mu * t51;
        let t194 = k_edge * t48;
        let t195 = T::from_f64(2.0) * t143 + t54 + thetadot * t118;
        let t196 = t164 * t195;
        let t197 = t163 * t69 + t196 * hc_alpha;
        let t198 = cos_theta * (r + t122) + t20;
        let t199 = sin_theta * (t15 - t122) - t16;
        let t200 = cos_theta * (t19 + thetadot * t199)
            + sin_theta * (thetadot * t198 - t23);
        let t201 = t35 * t117 + t92;
        let t202 = t42 * t119 + t65;
        let t203 = -(T::from_f64(2.0) * t143) - t54 + thetadot * t202;
        let t204 = t172 * t203;
        let t205 = t171 * t84 + t204 * hc_alpha;
        let t206 = cos_theta * (t15 + t129) + t45;
        let t207 = sin_theta * (r - t129) - t44;
        let t208 = cos_theta * (t80 + thetadot * t207)
            + sin_theta * (thetadot * t206 - t82);
        let t209 = t72 * (-t30 + t121);
        let t210 = hc_alpha * t139;
        let t211 = t210 * t195;
        let t212 = t91 * t145;
        let t213 = t87 * (-t89 + t212);
        let t214 = hc_alpha * t140;
        let t215 = t214 * t203;
        let t216 = t176 * t69;
        let t217 = t178 * t84;
        let t218 = t68 * (t209 * t200 - t211 * t158) + t63 * (t213 * t208 - t215 * t160)
            + T::from_f64(1.5) * (-(t216 * t158) - t217 * t160);
        let t219 = t181 * t69;
        let t220 = -t197;
        let t221 = t182 * t84;
        let t222 = T::from_f64(1.5) * t101 - T::from_f64(1.5);
        let t223 = T::from_f64(1.5) * t142;
        let t224 = t144 * t59;
        let t225 = t224 * t201;
        let t226 = t97 * t146;
        let t227 = t226 * t120;
        let t228 = t209 * t68;
        let t229 = t228 + t213 * t63;
        let t230 = t164 * t25;
        let t231 = t172 * t46;
        let t232 = hc_alpha * (-(t230 * t158) - t231 * t160);
        let t233 = k_wall * hc_alpha;
        let t234 = sin_theta * (t190 * t229 + hc_alpha * (-t230 + t231));
        let t235 = t210 * t69;
        let t236 = t213 * t90;
        let t237 = t214 * t84;
        let t238 = t68 * (t209 * t31 - t235 * t158) + t63 * (t236 - t237 * t160);
        let t239 = hc_alpha * (-(t230 * t69) - t231 * t84);
        let t240 = t125 * t127;
        let t241 = t240 * t78;
        let t242 = t60 * t112;
        let t243 = t133 * t135;
        let t244 = t243 * t101;
        let t245 = t102 * t141;
        let t246 = t165 * mu;
        let t247 = cos_theta * (rho_p * (-sin_theta + T::from_f64(2.0) * t28) - t38)
            + sin_theta * t74;
        let t248 = cos_theta * (rho_p * (sin_theta - T::from_f64(2.0) * t28) - t94)
            + sin_theta * t95;
        let t249 = t78 * (-t127 + t128 * t149);
        let t250 = hc_alpha * t144;
        let t251 = t250 * t201;
        let t252 = t249 * t247 - t251 * t240;
        let t253 = t101 * (-t135 + t136 * t150);
        let t254 = hc_alpha * t146;
        let t255 = t254 * t120;
        let t256 = t253 * t248 - t255 * t243;
        let t257 = t242 * t75;
        let t258 = t245 * t98;
        let t259 = k_edge * hc_alpha;
        let t260 = t250 * t75;
        let t261 = t240 * t260;
        let t262 = t254 * t98;
        let t263 = t243 * t262;
        let t264 = t259 * (sin_theta * (-(t164 * t69) + t172 * t84));
        let t265 = T::from_f64(1.5) * t78 - T::from_f64(1.5);
        let t266 = t158 * t31;
        let t267 = t68 * (t107 + t108 - t246 * t266 * t139);
        let t268 = t160 * t90;
        let t269 = t63 * (t64 + t105 + t246 * t268 * t140);
        let t270 = t137 * (-(t69 * t138) - t266 * mu * t72 * t73);
        let t271 = mu * t87 * (t268 * t64);
        let t272 = mu * t124;
        let t273 = mu * t132;
        let t274 = t257 * t265 + t225 * t165;
        let t275 = t258 * t222 + t227 * t165;
        let t276 = t31 * t200;
        let t277 = t90 * t208;
        let t278 = t124 * t59;
        let t279 = t132 * t97;
        let t280 = t228 * t31 + t236 * t63;
        let t281 = t30 * t32;
        let t282 = t89 * t91;
        let t283 = t63 * t105;
        let t284 = -t283;
        let t285 = thetadot * (t157 + t284);
        let t286 = t78 * t127 * t128;
        let t287 = t101 * t135 * t136;
        let t288 = t281 * t164 - t282 * t172;
        let t289 = t68 * t200;
        let t290 = t56 * (t24 * t24 * t24);
        let t291 = t63 * t208;
        let t292 = t145 * (t83 * t83 * t83);
        let t293 = t78 * t247;
        let t294 = t149 * (t125 * t125 * t125);
        let t295 = t101 * t248;
        let t296 = t150 * (t133 * t133 * t133);
        let t297 = t72 * (-t290 + T::from_f64(2.0) * t158) * t68
            + t87 * (-t292 + T::from_f64(2.0) * t160) * t63;
        let t298 = t68 * (t103 + t210 * t70);
        let t299 = t63 * (t105 + t214 * t85);
        let t300 = t72 * t31;
        let t301 = t87 * t90;
        let t302 = t124 * t78;
        let t303 = t132 * t101;
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
                t48
                    * (k_edge
                        * (t109 * t180 + T::from_f64(1.5) * (-(t181 * t50) - t182 * t52)
                            - t25 * t169 - t46 * t175)
                        + k_wall
                            * (t183 + t141 * (t102 * t184 - T::from_f64(1.5) * t142))),
                t194
                    * (sin_theta * (t190 * t165 * t188 + t191)
                        + T::from_f64(1.5) * t193 * t192 - t25 * t186 - t46 * t187),
                t48
                    * (k_edge
                        * (mu * (sin_theta * t218 + cos_theta * (-t159 - t161))
                            + t28 * (T::from_f64(2.0) * t110 + T::from_f64(2.0) * t111)
                            + t25 * (-(T::from_f64(1.5) * t219) + t220)
                            + t46 * (-(T::from_f64(1.5) * t221) - t205))
                        + k_wall
                            * (t183 * t75 + t141 * (t102 * t222 + t223) * t98
                                + t165 * (-t225 + t227)) + t2 + t3),
                t48
                    * (k_edge
                        * (mu * (t51 * t229 + t232 * sin_theta)
                            + hc_alpha * (-(t164 * t50) - t172 * t52))
                        + t233 * (-t224 - t226)),
                t194 * (t234 + t193 * t189),
                t48
                    * (k_edge * (t109 * t238 + t239)
                        + t233 * (-(t224 * t75) + t226 * t98)),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t48
                    * (k_edge * (sin_theta * (t191 - t169 + t175) + t190 * t180)
                        + T::from_f64(1.5) * (k_wall * (-(t241 * t242) + t244 * t245))
                            * mu),
                t194
                    * (sin_theta * (T::from_f64(1.5) * t190 * t192 - t186 + t187)
                        + T::from_f64(1.5) * (-t181 - t182) * t51 + t53 * t188 * t246),
                t48
                    * (mu
                        * (k_edge * (cos_theta * t218 + sin_theta * (t159 + t161))
                            + k_wall
                                * (thetadot * (t59 * t252 + t97 * t256)
                                    + T::from_f64(1.5) * (-(t241 * t257) - t244 * t258)))
                        + k_edge
                            * (cos_theta * (t110 + t111)
                                + sin_theta
                                    * (T::from_f64(1.5) * (-t219 + t221) + t220 + t205)) + t147
                        + t148),
                t48
                    * (k_edge * (t234 + t232 * t190)
                        + t233 * (-(t224 * t240) + t226 * t243) * mu),
                t48
                    * (mu
                        * (k_edge * (t53 * t229 + sin_theta * cos_theta * t189)
                            + k_wall * (t249 * t59 + t253 * t97))
                        + t259 * (t51 * (-t164 - t172))),
                t48
                    * (mu
                        * (cos_theta * t238 * k_edge
                            + k_wall
                                * (t59 * (t249 * t124 - t261) + t97 * (t253 * t132 - t263)))
                        + t264),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t49
                    * (k_edge
                        * (t28 * (T::from_f64(2.0) * t267 + T::from_f64(2.0) * t269)
                            + T::from_f64(1.5) * t270 * t25
                            + T::from_f64(1.5) * (t114 * (-(t84 * t115) - t271)) * t46
                            - t69 * t169 - t84 * t175)
                        + k_wall
                            * (t112
                                * (t75 * (t116 - t265 * t60)
                                    - T::from_f64(1.5) * t272 * t241 * t60)
                                + t141
                                    * (t98 * (t223 - t184 * t102)
                                        + T::from_f64(1.5) * t273 * t244 * t102))),
                k_edge
                    * (cos_theta * (t267 + t269)
                        + sin_theta
                            * (T::from_f64(1.5) * t270
                                + T::from_f64(1.5) * (t84 * t115 + t271) * t114)
                        - t69 * t186 - t84 * t187) * t49,
                t49
                    * (mu
                        * (k_edge
                            * (t68
                                * (t72
                                    * (t30
                                        * (-t276
                                            - t24
                                                * (cos_theta * (t18 + t199) + sin_theta * (t198 - t22)))
                                        + t121 * t276) - t211 * t266)
                                + t63
                                    * (t87
                                        * (t89
                                            * (-t277
                                                - t83
                                                    * (cos_theta * (t79 + t207) + sin_theta * (t206 - t81)))
                                            + t212 * t277) - t215 * t268)
                                + T::from_f64(1.5) * (-(t216 * t266) - t217 * t268))
                            + k_wall
                                * (thetadot * (t278 * t252 + t279 * t256)
                                    + t241 * (-(t59 * t247) - T::from_f64(1.5) * t257 * t124)
                                    + t244 * (-(t97 * t248) - T::from_f64(1.5) * t258 * t132)))
                        + k_edge
                            * (t110 * t118 + (-t64 - t105) * t202 * t63
                                + T::from_f64(1.5) * (-(t181 * t151) - t182 * t153)
                                - t69 * t197 - t84 * t205)
                        + k_wall
                            * ((-t60 - t104) * t201 * t59 + (-t102 - t106) * t120 * t97
                                + T::from_f64(1.5)
                                    * (-(t112 * t113 * t152) - t141 * t142 * t154) - t75 * t274
                                - t98 * t275)),
                t49
                    * (k_edge
                        * (mu
                            * (sin_theta * t280
                                + hc_alpha * (-(t230 * t266) - t231 * t268)) + t239)
                        + t233
                            * (t224 * (-t75 - t272 * t240)
                                + t226 * (t98 + t273 * t243))),
                t49
                    * (mu
                        * (k_edge
                            * (cos_theta * t280
                                + sin_theta * (-(t266 * t164) + t268 * t172) * hc_alpha)
                            + k_wall * (t278 * t249 + t279 * t253)) + t264),
                t49
                    * (mu
                        * (k_edge
                            * (t68 * (t209 * (t31 * t31) - t235 * t266)
                                + t63 * (t213 * (t90 * t90) - t237 * t268))
                            + k_wall
                                * (t59 * (t249 * (t155 * t155) - t261 * t124)
                                    + t97 * (t253 * (t156 * t156) - t263 * t132)))
                        + hc_alpha
                            * (k_edge * (-(t164 * t151) - t172 * t153)
                                + k_wall * (-(t224 * t152) - t226 * t154))),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                xdot * t4 + zdot * (t147 + t148),
                t0 + t1,
                t4,
                m_2,
                T::from_f64(0.0),
                T::from_f64(0.0),
                k_edge
                    * (mu
                        * (t281 * (T::from_f64(1.5) * t177 + t168)
                            + t282 * (T::from_f64(1.5) * t179 + t174))
                        + T::from_f64(2.0) * t285 * t28 + t70 * t169 + t85 * t175)
                    + k_wall
                        * (T::from_f64(1.5) * (t286 * t242 - t287 * t245) * mu
                            + t242 * t265 * t76 + t245 * t99 * t184),
                k_edge
                    * (mu
                        * (T::from_f64(1.5) * (t281 * t176 - t282 * t178) * sin_theta
                            + cos_theta * t288 * t165) + t285 * cos_theta + t70 * t186
                        + t85 * t187),
                mu
                    * (k_edge
                        * (t72
                            * (t30
                                * (T::from_f64(1.5) * t162 * t69 * t32
                                    + T::from_f64(2.0) * t289 * t24) - t289 * t290)
                            + t87
                                * (t89
                                    * (T::from_f64(1.5) * t170 * t84 * t91
                                        + T::from_f64(2.0) * t291 * t83) - t291 * t292)
                            + hc_alpha * (t196 * t281 + t204 * t282))
                        + k_wall
                            * (thetadot
                                * (t59
                                    * (t127 * (t251 * t128 + T::from_f64(2.0) * t293 * t125)
                                        - t293 * t294)
                                    + t97
                                        * (t135 * (t255 * t136 + T::from_f64(2.0) * t295 * t133)
                                            - t295 * t296))
                                + T::from_f64(1.5) * (t286 * t257 + t287 * t258)))
                    + k_edge * (t157 * t195 + t70 * t197 + t283 * t203 + t85 * t205)
                    + k_wall
                        * (thetadot * (t59 * t104 * t201 + t97 * t106 * t120)
                            + t76 * t274 + t99 * t275),
                k_edge
                    * (mu * (sin_theta * t297 + hc_alpha * (t281 * t230 + t282 * t231))
                        + t298 * t25 + t299 * t46)
                    + k_wall
                        * (t59
                            * (t250 * (mu * t127 * t128 + t76) + t78 - T::from_f64(1.0))
                            + t97
                                * (t254 * (-(mu * t135 * t136) - t99) + T::from_f64(1.0)
                                    - t101)),
                k_edge
                    * (sin_theta
                        * (hc_alpha * (mu * t288 + t164 * t70 - t172 * t85) + t157
                            + t284) + t190 * t297)
                    + k_wall
                        * (t78 * (-t294 + T::from_f64(2.0) * t240) * t59
                            + t101 * (-t296 + T::from_f64(2.0) * t243) * t97) * mu,
                mu
                    * (k_edge
                        * (t68
                            * (t30 * (t235 * t32 + T::from_f64(2.0) * t300 * t24)
                                - t300 * t290)
                            + t63
                                * (t89 * (t237 * t91 + T::from_f64(2.0) * t301 * t83)
                                    - t301 * t292))
                        + k_wall
                            * (t59
                                * (t127 * (t260 * t128 + T::from_f64(2.0) * t302 * t125)
                                    - t302 * t294)
                                + t97
                                    * (t135 * (t262 * t136 + T::from_f64(2.0) * t303 * t133)
                                        - t303 * t296))) + k_edge * (t298 * t69 + t299 * t84)
                    + k_wall
                        * (t59 * (t104 + t250 * t76) * t75
                            + t97 * (t106 + t254 * t99) * t98),
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
    /// 62 add/sub, 116 mul, 8 div, 4 sqrt, 10 transcendental, 8 branches; 64 `let`s.
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
        let t4 = sin_theta * t3;
        let t5 = T::from_f64(0.5) * theta;
        let (t6, t15) = t5.sin_cos();
        let t7 = t6 * t6;
        let t8 = cos_theta * t3;
        let t9 = sin_theta * t2 + t8;
        let t10 = -r;
        let t11 = r * sin_theta;
        let t12 = r * cos_theta;
        let t13 = sin_theta * (xdot + thetadot * (cos_theta * t9 + t11))
            + cos_theta * (zdot + thetadot * (-(sin_theta * t9) + t12));
        let t14 = zdot * sin_theta;
        let t16 = t6 * t15;
        let t17 = v_s.hypot(t13);
        let t18 = T::from_f64(1.0) / (e_star * edge_sum);
        let t19 = -rho_p;
        let t20 = l_c + t19;
        let t21 = r + t19;
        let t22 = sin_theta * t20;
        let t23 = rho_p * sin_theta;
        let t24 = rho_p * t7;
        let t25 = cos_theta * t20;
        let t26 = T::from_f64(1.0) / (e_star * wall_sum);
        let t27 = rho_h + T::from_f64(0.5) * d + t1;
        let t28 = t8 + sin_theta * t27;
        let t29 = rho_p + t10;
        let t30 = r + t0 + x + t22 - T::from_f64(2.0) * t7 * t21;
        let t31 = t30.max0();
        let t32 = t31 * t31.sqrt();
        let t33 = r + t0 + x + t4 + T::from_f64(2.0) * t7 * t27;
        let t34 = t33.max0();
        let t35 = t34 * t34.sqrt();
        let t36 = r + t0 + t1 - t4 - T::from_f64(2.0) * t2 * t7;
        let t37 = t36.max0();
        let t38 = t37 * t37.sqrt();
        let t39 = (T::from_f64(1.0)
            + hc_alpha
                * (xdot * (-T::from_f64(1.0) + T::from_f64(2.0) * t7) + t14
                    + thetadot * (-t8 - T::from_f64(2.0) * t16 * t2)))
            .max0();
        let t40 = zdot
            + thetadot
                * (-(sin_theta * (l_c + t19 + t23))
                    - cos_theta * (r - T::from_f64(2.0) * t24));
        let t41 = (T::from_f64(1.0)
            + hc_alpha * (xdot + thetadot * (t25 - T::from_f64(2.0) * t16 * t21)))
            .max0();
        let t42 = v_s.hypot(t40);
        let t43 = sin_theta * (xdot + thetadot * (-t11 + cos_theta * t28))
            + cos_theta * (zdot + thetadot * (-t12 - sin_theta * t28));
        let t44 = (T::from_f64(1.0)
            + hc_alpha
                * (xdot * (T::from_f64(1.0) - T::from_f64(2.0) * t7) - t14
                    + thetadot * (t8 + T::from_f64(2.0) * t16 * t27)))
            .max0();
        let t45 = v_s.hypot(t43);
        let t46 = r + t0 + t1 - t22 + T::from_f64(2.0) * t7 * t29;
        let t47 = zdot
            + thetadot
                * (-(sin_theta * (l_c + t19 - t23))
                    - cos_theta * (t10 + T::from_f64(2.0) * t24));
        let t48 = t46.max0();
        let t49 = t48 * t48.sqrt();
        let t50 = (T::from_f64(1.0)
            + hc_alpha * (-xdot + thetadot * (-t25 + T::from_f64(2.0) * t16 * t29)))
            .max0();
        let t51 = v_s.hypot(t47);
        let t52 = k_edge * t38 * t39;
        let t53 = (T::from_f64(1.5) * t18 * t52).cbrt();
        let t54 = e_star * edge_sum * (T::from_f64(1.0) / (edge_ma * edge_mb));
        let t55 = k_wall * t49 * t50;
        let t56 = (T::from_f64(1.5) * t26 * t55).cbrt();
        let t57 = e_star * wall_sum * (T::from_f64(1.0) / (wall_ma * wall_mb));
        let t58 = k_wall * t41 * t32;
        let t59 = k_edge * t44 * t35;
        let t60 = (T::from_f64(1.5) * t26 * t58).cbrt();
        let t61 = (T::from_f64(1.5) * t18 * t59).cbrt();
        let normal = Vector4::new(t52, t58, t59, t55);
        let friction = Vector4::new(
            -t52 * mu * t13 / t17,
            -t58 * mu * t40 / t42,
            -t59 * mu * t43 / t45,
            -t55 * mu * t47 / t51,
        );
        let delta = Vector4::new(t36, t30, t33, t46);
        let slip = Vector4::new(t13, t40, t43, t47);
        let a = Vector4::new(edge_ma * t53, wall_ma * t60, edge_ma * t61, wall_ma * t56);
        let b = Vector4::new(edge_mb * t53, wall_mb * t60, edge_mb * t61, wall_mb * t56);
        let p0 = Vector4::new(
            T::from_f64(0.3183098861837907) * t54 * t53,
            T::from_f64(0.3183098861837907) * t57 * t60,
            T::from_f64(0.3183098861837907) * t54 * t61,
            T::from_f64(0.3183098861837907) * t57 * t56,
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
    /// 30 add/sub, 25 mul, 0 div, 0 sqrt, 6 transcendental, 4 branches; 17 `let`s.
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
        let t2 = sin_theta * (rho_h - z);
        let t3 = (T::from_f64(0.5) * theta).sin();
        let t4 = t3 * t3;
        let t5 = -rho_p;
        let t6 = sin_theta * (l_c + t5);
        let t7 = (r + t0 + x + t6 - T::from_f64(2.0) * t4 * (r + t5)).max0();
        let t8 = (r + t0 + x + t2
            + T::from_f64(2.0) * t4 * (rho_h + T::from_f64(0.5) * d + t1))
            .max0();
        let t9 = (r + t0 + t1 - t2 - T::from_f64(2.0) * (-rho_h + t0 + t1) * t4).max0();
        let t10 = (r + t0 + t1 - t6 + T::from_f64(2.0) * t4 * (rho_p - r)).max0();
        let t11 = t7.powf(T::from_f64(2.5));
        let t12 = t8.powf(T::from_f64(2.5));
        let t13 = t9.powf(T::from_f64(2.5));
        let t14 = t10.powf(T::from_f64(2.5));
        let kinetic = T::from_f64(0.5)
            * (m * (xdot * xdot + zdot * zdot) + j * (thetadot * thetadot));
        let potential = T::from_f64(0.4) * (t13 + t12) * k_edge
            + T::from_f64(0.4) * (t11 + t14) * k_wall;
        let depth = z + l_c * cos_theta;
        (kinetic, potential, depth)
    }
}
