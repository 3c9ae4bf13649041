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
    /// 110 add/sub, 151 mul, 6 div, 4 sqrt, 6 transcendental, 16 branches; 93 `let`s.
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
        let t36 = T::from_f64(1.0) / m;
        let t37 = r + t4 + x + t28 - T::from_f64(2.0) * t11 * t27;
        let t38 = t37.max0();
        let t39 = t38 * t38.sqrt();
        let t40 = t37.step();
        let t41 = r + t4 + x + t8 + T::from_f64(2.0) * t11 * t32;
        let t42 = t41.max0();
        let t43 = t42 * t42.sqrt();
        let t44 = t41.step();
        let t45 = -t40;
        let t46 = r + t4 + t5 - t8 - T::from_f64(2.0) * t6 * t11;
        let t47 = t46.max0();
        let t48 = t47 * t47.sqrt();
        let t49 = -t12 - T::from_f64(2.0) * t23 * t6;
        let t50 = xdot * t20 + t21 + thetadot * t49;
        let t51 = (T::from_f64(1.0) + hc_alpha * t50).max0();
        let t52 = t46.step();
        let t53 = -(sin_theta * (l_c + t25 + t29))
            - cos_theta * (r - T::from_f64(2.0) * t30);
        let t54 = zdot + thetadot * t53;
        let t55 = t31 - T::from_f64(2.0) * t23 * t27;
        let t56 = xdot + thetadot * t55;
        let t57 = (T::from_f64(1.0) + hc_alpha * t56).max0();
        let t58 = v_s.hypot(t54);
        let t59 = -t15 + cos_theta * t33;
        let t60 = -t17 - sin_theta * t33;
        let t61 = sin_theta * (xdot + thetadot * t59)
            + cos_theta * (zdot + thetadot * t60);
        let t62 = t12 + T::from_f64(2.0) * t23 * t32;
        let t63 = xdot * t34 - t21 + thetadot * t62;
        let t64 = (T::from_f64(1.0) + hc_alpha * t63).max0();
        let t65 = v_s.hypot(t61);
        let t66 = r + t4 + t5 - t28 + T::from_f64(2.0) * t11 * t35;
        let t67 = -(sin_theta * (l_c + t25 - t29))
            - cos_theta * (t14 + T::from_f64(2.0) * t30);
        let t68 = zdot + thetadot * t67;
        let t69 = t66.max0();
        let t70 = t69 * t69.sqrt();
        let t71 = -t31 + T::from_f64(2.0) * t23 * t35;
        let t72 = -xdot + thetadot * t71;
        let t73 = (T::from_f64(1.0) + hc_alpha * t72).max0();
        let t74 = v_s.hypot(t68);
        let t75 = t66.step();
        let t76 = t51 - T::from_f64(1.0);
        let t77 = t57 - T::from_f64(1.0);
        let t78 = t64 - T::from_f64(1.0);
        let t79 = t73 - T::from_f64(1.0);
        let t80 = -t52 - t76;
        let t81 = mu * sin_theta;
        let t82 = t51 / t24;
        let t83 = t82 * t19;
        let t84 = -t44 - t78;
        let t85 = t64 / t65;
        let t86 = t85 * t61;
        let t87 = t57 / t58;
        let t88 = t87 * t54;
        let t89 = t73 / t74;
        let t90 = t89 * t68;
        SMatrix::<
            T,
            8,
            1,
        >::from_row_slice(
            &[
                xdot,
                zdot,
                thetadot,
                (k_edge * (t48 * (t20 * t80 - t81 * t83) + t43 * (t34 * t84 - t81 * t86))
                    + k_wall
                        * (t39 * (T::from_f64(1.0) + t45 - t57)
                            + t70 * (t73 - T::from_f64(1.0) + t75)) + t0 + t1) * t36,
                (k_edge
                    * (sin_theta * (t48 * t80 + t43 * (t44 + t78))
                        + cos_theta * (-(t83 * t48) - t86 * t43) * mu)
                    + k_wall * (-(t88 * t39) - t90 * t70) * mu + t2 + t3) * t36,
                (m_2
                    + k_edge
                        * (t48
                            * (t49 * t80
                                - t83 * mu * (sin_theta * t16 + cos_theta * t18))
                            + t43
                                * (t62 * t84
                                    - t86 * mu * (sin_theta * t59 + cos_theta * t60)))
                    + k_wall
                        * (t39 * (t55 * (t45 - t77) - t88 * mu * t53)
                            + t70 * (t71 * (-t75 - t79) - t90 * mu * t67))) / j,
                xdot * (t0 + t1) + zdot * (t2 + t3) + thetadot * m_2,
                mu
                    * (k_edge * (t82 * t48 * (t19 * t19) + t85 * t43 * (t61 * t61))
                        + k_wall * (t87 * t39 * (t54 * t54) + t89 * t70 * (t68 * t68)))
                    + k_edge * (t50 * t48 * t76 + t63 * t43 * t78)
                    + k_wall * (t56 * t39 * t77 + t72 * t70 * t79),
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
    /// 400 add/sub, 777 mul, 10 div, 8 sqrt, 6 transcendental, 24 branches; 320 `let`s.
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
        let (t11, t29) = t10.sin_cos();
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
        let t24 = sin_theta * t19;
        let t25 = cos_theta * t23;
        let t26 = t24 + t25;
        let t27 = -T::from_f64(1.0) + T::from_f64(2.0) * t12;
        let t28 = zdot * sin_theta;
        let t30 = t11 * t29;
        let t31 = v_s.hypot(t26);
        let t32 = T::from_f64(1.0) / t31;
        let t33 = sin_theta * t18 + cos_theta * t22;
        let t34 = t26 * t26;
        let t35 = -rho_p;
        let t36 = l_c + t35;
        let t37 = r + t35;
        let t38 = sin_theta * t36;
        let t39 = rho_p * sin_theta;
        let t40 = l_c + t35 + t39;
        let t41 = rho_p * t12;
        let t42 = sin_theta * t40;
        let t43 = cos_theta * t36;
        let t44 = rho_h + T::from_f64(0.5) * d + t6;
        let t45 = t13 + sin_theta * t44;
        let t46 = cos_theta * t45;
        let t47 = -sin_theta * t45;
        let t48 = T::from_f64(1.0) - T::from_f64(2.0) * t12;
        let t49 = rho_p + t15;
        let t50 = T::from_f64(1.0) / m;
        let t51 = T::from_f64(1.0) / j;
        let t52 = t27 * t27;
        let t53 = sin_theta * sin_theta;
        let t54 = t48 * t48;
        let t55 = cos_theta * cos_theta;
        let t56 = zdot * cos_theta;
        let t57 = t29 * t29;
        let t58 = T::from_f64(1.0) / (t31 * t31 * t31);
        let t59 = T::from_f64(2.0) * zdot;
        let t60 = r + t5 + x + t38 - T::from_f64(2.0) * t12 * t37;
        let t61 = t60.max0();
        let t62 = t61 * t61.sqrt();
        let t63 = t60.step();
        let t64 = r + t5 + x + t9 + T::from_f64(2.0) * t12 * t44;
        let t65 = t64.max0();
        let t66 = t65 * t65.sqrt();
        let t67 = t64.step();
        let t68 = -t9;
        let t69 = r + t5 + t6 + t68 - T::from_f64(2.0) * t7 * t12;
        let t70 = t69.max0();
        let t71 = t70 * t70.sqrt();
        let t72 = -t13 - T::from_f64(2.0) * t30 * t7;
        let t73 = xdot * t27 + t28 + thetadot * t72;
        let t74 = T::from_f64(1.0) + hc_alpha * t73;
        let t75 = t74.max0();
        let t76 = t69.step();
        let t77 = r - T::from_f64(2.0) * t41;
        let t78 = t43 - T::from_f64(2.0) * t30 * t37;
        let t79 = xdot + thetadot * t78;
        let t80 = T::from_f64(1.0) + hc_alpha * t79;
        let t81 = t80.max0();
        let t82 = -t17 + t46;
        let t83 = xdot + thetadot * t82;
        let t84 = -t21 + t47;
        let t85 = zdot + thetadot * t84;
        let t86 = sin_theta * t83;
        let t87 = cos_theta * t85;
        let t88 = t86 + t87;
        let t89 = t13 + T::from_f64(2.0) * t30 * t44;
        let t90 = xdot * t48 - t28 + thetadot * t89;
        let t91 = T::from_f64(1.0) + hc_alpha * t90;
        let t92 = t91.max0();
        let t93 = v_s.hypot(t88);
        let t94 = T::from_f64(1.0) / t93;
        let t95 = sin_theta * t82 + cos_theta * t84;
        let t96 = t88 * t88;
        let t97 = -t38;
        let t98 = r + t5 + t6 + t97 + T::from_f64(2.0) * t12 * t49;
        let t99 = l_c + t35 - t39;
        let t100 = t15 + T::from_f64(2.0) * t41;
        let t101 = t98.max0();
        let t102 = t101 * t101.sqrt();
        let t103 = -t43 + T::from_f64(2.0) * t30 * t49;
        let t104 = -xdot + thetadot * t103;
        let t105 = T::from_f64(1.0) + hc_alpha * t104;
        let t106 = t105.max0();
        let t107 = t98.step();
        let t108 = t75 - T::from_f64(1.0);
        let t109 = t81 - T::from_f64(1.0);
        let t110 = t92 - T::from_f64(1.0);
        let t111 = t106 - T::from_f64(1.0);
        let t112 = -t76;
        let t113 = -t108;
        let t114 = mu * sin_theta;
        let t115 = t71 * (t112 + t113);
        let t116 = t61.sqrt();
        let t117 = t63 * t63;
        let t118 = t65.sqrt();
        let t119 = t67 * t67;
        let t120 = -T::from_f64(1.5) * t117;
        let t121 = t12 - t57;
        let t122 = t7 * t121 + t9;
        let t123 = t57 - t12;
        let t124 = t49 * t123 + t38;
        let t125 = t34 * t58;
        let t126 = T::from_f64(2.0) * t67;
        let t127 = cos_theta * t7 + t68;
        let t128 = cos_theta * t77;
        let t129 = -t42 - t128;
        let t130 = thetadot * t129;
        let t131 = zdot + t130;
        let t132 = v_s.hypot(t131);
        let t133 = T::from_f64(1.0) / t132;
        let t134 = t131 * t131;
        let t135 = t68 + cos_theta * t44;
        let t136 = sin_theta * t99;
        let t137 = cos_theta * t100;
        let t138 = -t136 - t137;
        let t139 = thetadot * t138;
        let t140 = zdot + t139;
        let t141 = v_s.hypot(t140);
        let t142 = T::from_f64(1.0) / t141;
        let t143 = t140 * t140;
        let t144 = t70.sqrt();
        let t145 = t76 * t76;
        let t146 = t74.step();
        let t147 = t91.step();
        let t148 = t101.sqrt();
        let t149 = t107 * t107;
        let t150 = t30 * xdot;
        let t151 = t80.step();
        let t152 = T::from_f64(1.0) / (t93 * t93 * t93);
        let t153 = t105.step();
        let t154 = -t0;
        let t155 = -t1;
        let t156 = T::from_f64(1.0) / (t132 * t132 * t132);
        let t157 = T::from_f64(1.0) / (t141 * t141 * t141);
        let t158 = t72 * t72;
        let t159 = t78 * t78;
        let t160 = t89 * t89;
        let t161 = t103 * t103;
        let t162 = t128 + t42;
        let t163 = t137 + t136;
        let t164 = T::from_f64(2.0) * t24 + T::from_f64(2.0) * t25;
        let t165 = t59 + T::from_f64(2.0) * t130;
        let t166 = T::from_f64(2.0) * t86 + T::from_f64(2.0) * t87;
        let t167 = t59 + T::from_f64(2.0) * t139;
        let t168 = t71 * t108;
        let t169 = t26 * t32;
        let t170 = t169 * t71 * t75;
        let t171 = t88 * t94;
        let t172 = t171 * t92 * t66;
        let t173 = t76 * t144;
        let t174 = t173 * (T::from_f64(1.5) * t75 - T::from_f64(1.5));
        let t175 = t71 * t146;
        let t176 = thetadot * hc_alpha;
        let t177 = t176 * t30;
        let t178 = t175 * t177;
        let t179 = T::from_f64(2.0) * t178;
        let t180 = t174 * t27 + t179;
        let t181 = t67 * t118;
        let t182 = t181 * (T::from_f64(1.5) * t92 - T::from_f64(1.5));
        let t183 = t147 * t66;
        let t184 = t183 * t177;
        let t185 = -T::from_f64(2.0) * t184;
        let t186 = t182 * t48 + t185;
        let t187 = t173 * t75;
        let t188 = t187 * t27;
        let t189 = t181 * t92;
        let t190 = t189 * t48;
        let t191 = t169 * (-(T::from_f64(1.5) * t188) - T::from_f64(2.0) * t178)
            + t171 * (-(T::from_f64(1.5) * t190) + T::from_f64(2.0) * t184);
        let t192 = t144 * t145;
        let t193 = t118 * t119;
        let t194 = t116 * (t63 * (T::from_f64(1.5) - T::from_f64(1.5) * t81) + t120);
        let t195 = -(T::from_f64(1.5) * t106) + T::from_f64(1.5);
        let t196 = t176 * cos_theta;
        let t197 = t174 * sin_theta + t196 * t175;
        let t198 = t181 * (-(T::from_f64(1.5) * t92) + T::from_f64(1.5)) * sin_theta
            - t196 * t183;
        let t199 = -(t169 * t175) + t183 * t171;
        let t200 = hc_alpha * t199;
        let t201 = mu * cos_theta;
        let t202 = -T::from_f64(1.5) * t192 * t27;
        let t203 = T::from_f64(1.5) * t193 * t48;
        let t204 = -(T::from_f64(1.5) * t187 * t169) + T::from_f64(1.5) * t189 * t171;
        let t205 = mu * t53;
        let t206 = k_edge * t50;
        let t207 = T::from_f64(2.0) * t150 + t56 + thetadot * t122;
        let t208 = t175 * t207;
        let t209 = t174 * t72 + t208 * hc_alpha;
        let t210 = cos_theta * (r + t127) + t20;
        let t211 = sin_theta * (t15 - t127) - t16;
        let t212 = cos_theta * (t19 + thetadot * t211)
            + sin_theta * (thetadot * t210 - t23);
        let t213 = t37 * t121 + t97;
        let t214 = t44 * t123 + t68;
        let t215 = -(T::from_f64(2.0) * t150) - t56 + thetadot * t214;
        let t216 = t183 * t215;
        let t217 = t182 * t89 + t216 * hc_alpha;
        let t218 = cos_theta * (t15 + t135) + t47;
        let t219 = sin_theta * (r - t135) - t46;
        let t220 = cos_theta * (t83 + thetadot * t219)
            + sin_theta * (thetadot * t218 - t85);
        let t221 = t75 * (-t32 + t125);
        let t222 = hc_alpha * t146;
        let t223 = t222 * t207;
        let t224 = t96 * t152;
        let t225 = t92 * (-t94 + t224);
        let t226 = hc_alpha * t147;
        let t227 = t226 * t215;
        let t228 = t187 * t72;
        let t229 = t189 * t89;
        let t230 = t71 * (t221 * t212 - t223 * t169) + t66 * (t225 * t220 - t227 * t171)
            - T::from_f64(1.5) * t228 * t169 - T::from_f64(1.5) * t229 * t171;
        let t231 = -T::from_f64(2.0) * t76;
        let t232 = -T::from_f64(2.0) * t108;
        let t233 = T::from_f64(2.0) * t110;
        let t234 = -T::from_f64(1.5) * t192 * t72;
        let t235 = -t209;
        let t236 = t193 * t89;
        let t237 = T::from_f64(1.5) * t106 - T::from_f64(1.5);
        let t238 = T::from_f64(1.5) * t149;
        let t239 = t151 * t62;
        let t240 = t239 * t213;
        let t241 = t102 * t153;
        let t242 = t241 * t124;
        let t243 = t221 * t71;
        let t244 = t243 + t225 * t66;
        let t245 = t175 * t27;
        let t246 = t183 * t48;
        let t247 = hc_alpha * (-(t245 * t169) - t246 * t171);
        let t248 = k_wall * hc_alpha;
        let t249 = sin_theta * (t201 * t244 + hc_alpha * (-t245 + t246));
        let t250 = t222 * t72;
        let t251 = t225 * t95;
        let t252 = t226 * t89;
        let t253 = t71 * (t221 * t33 - t250 * t169) + t66 * (t251 - t252 * t171);
        let t254 = hc_alpha * (-(t245 * t72) - t246 * t89);
        let t255 = t131 * t133;
        let t256 = t255 * t81;
        let t257 = t63 * t116;
        let t258 = t140 * t142;
        let t259 = t258 * t106;
        let t260 = t107 * t148;
        let t261 = t176 * mu;
        let t262 = cos_theta * (rho_p * (-sin_theta + T::from_f64(2.0) * t30) - t40)
            + sin_theta * t77;
        let t263 = cos_theta * (rho_p * (sin_theta - T::from_f64(2.0) * t30) - t99)
            + sin_theta * t100;
        let t264 = t81 * (-t133 + t134 * t156);
        let t265 = hc_alpha * t151;
        let t266 = t265 * t213;
        let t267 = t264 * t262 - t266 * t255;
        let t268 = t106 * (-t142 + t143 * t157);
        let t269 = hc_alpha * t153;
        let t270 = t269 * t124;
        let t271 = t268 * t263 - t270 * t258;
        let t272 = t257 * t78;
        let t273 = t260 * t103;
        let t274 = k_edge * hc_alpha;
        let t275 = t265 * t78;
        let t276 = t255 * t275;
        let t277 = t269 * t103;
        let t278 = t258 * t277;
        let t279 = t274 * (sin_theta * (-(t175 * t72) + t183 * t89));
        let t280 = T::from_f64(1.5) * t81 - T::from_f64(1.5);
        let t281 = t169 * t33;
        let t282 = t261 * (t281 * t146);
        let t283 = t171 * t95;
        let t284 = t261 * (t283 * t147);
        let t285 = t144
            * (-(T::from_f64(1.5) * t72 * t145)
                - T::from_f64(1.5) * t281 * mu * t75 * t76);
        let t286 = mu * t92 * (t283 * t67);
        let t287 = mu * t129;
        let t288 = mu * t138;
        let t289 = t272 * t280 + t240 * t176;
        let t290 = t273 * t237 + t242 * t176;
        let t291 = t33 * t212;
        let t292 = t95 * t220;
        let t293 = t129 * t62;
        let t294 = t138 * t102;
        let t295 = t243 * t33 + t251 * t66;
        let t296 = t32 * t34;
        let t297 = t94 * t96;
        let t298 = t66 * t110;
        let t299 = t81 * t133 * t134;
        let t300 = t106 * t142 * t143;
        let t301 = t296 * t175 - t297 * t183;
        let t302 = -t298;
        let t303 = t71 * t212;
        let t304 = t58 * (t26 * t26 * t26);
        let t305 = t66 * t220;
        let t306 = t152 * (t88 * t88 * t88);
        let t307 = t81 * t262;
        let t308 = t156 * (t131 * t131 * t131);
        let t309 = t106 * t263;
        let t310 = t157 * (t140 * t140 * t140);
        let t311 = t75 * (-t304 + t32 * t164) * t71 + t92 * (-t306 + t94 * t166) * t66;
        let t312 = t71 * (t108 + t222 * t73);
        let t313 = t66 * (t110 + t226 * t90);
        let t314 = t75 * t33;
        let t315 = t92 * t95;
        let t316 = t129 * t81;
        let t317 = t138 * t106;
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
                t50
                    * (k_edge
                        * (t114 * t191 - T::from_f64(1.5) * t192 * t52 - t27 * t180
                            - T::from_f64(1.5) * t193 * t54 - t48 * t186)
                        + k_wall
                            * (t194 + t148 * (t107 * t195 - T::from_f64(1.5) * t149))),
                t206
                    * (sin_theta * (t201 * t176 * t199 + t202 + t203) + t205 * t204
                        - t27 * t197 - t48 * t198),
                t50
                    * (k_edge
                        * (mu * (sin_theta * t230 + cos_theta * (-t170 - t172))
                            + t30 * (t71 * (t231 + t232) + t66 * (t126 + t233))
                            + t27 * (t234 + t235)
                            + t48 * (-(T::from_f64(1.5) * t236) - t217))
                        + k_wall
                            * (t194 * t78 + t148 * (t107 * t237 + t238) * t103
                                + t176 * (-t240 + t242)) + t2 + t3),
                t50
                    * (k_edge
                        * (mu * (t53 * t244 + t247 * sin_theta)
                            + hc_alpha * (-(t175 * t52) - t183 * t54))
                        + t248 * (-t239 - t241)),
                t206 * (t249 + t205 * t200),
                t50
                    * (k_edge * (t114 * t253 + t254)
                        + t248 * (-(t239 * t78) + t241 * t103)),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t50
                    * (k_edge * (sin_theta * (t202 + t203 - t180 + t186) + t201 * t191)
                        + k_wall
                            * (-(T::from_f64(1.5) * t256 * t257)
                                + T::from_f64(1.5) * t259 * t260) * mu),
                t206
                    * (sin_theta * (t201 * t204 - t197 + t198)
                        + t53 * (-(T::from_f64(1.5) * t192) - T::from_f64(1.5) * t193)
                        + t55 * t199 * t261),
                t50
                    * (mu
                        * (k_edge * (cos_theta * t230 + sin_theta * (t170 + t172))
                            + k_wall
                                * (thetadot * (t62 * t267 + t102 * t271)
                                    - T::from_f64(1.5) * t256 * t272
                                    - T::from_f64(1.5) * t259 * t273))
                        + k_edge
                            * (cos_theta * (t115 + t66 * (t67 + t110))
                                + sin_theta
                                    * (t234 + t235 + T::from_f64(1.5) * t236 + t217)) + t154
                        + t155),
                t50
                    * (k_edge * (t249 + t247 * t201)
                        + t248 * (-(t239 * t255) + t241 * t258) * mu),
                t50
                    * (mu
                        * (k_edge * (t55 * t244 + sin_theta * cos_theta * t200)
                            + k_wall * (t264 * t62 + t268 * t102))
                        + t274 * (t53 * (-t175 - t183))),
                t50
                    * (mu
                        * (cos_theta * t253 * k_edge
                            + k_wall
                                * (t62 * (t264 * t129 - t276)
                                    + t102 * (t268 * t138 - t278))) + t279),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t51
                    * (k_edge
                        * (t30
                            * (t71 * (t231 + t232 - T::from_f64(2.0) * t282)
                                + t66 * (t126 + t233 + T::from_f64(2.0) * t284))
                            + t285 * t27
                            + t118
                                * (-(T::from_f64(1.5) * t89 * t119)
                                    - T::from_f64(1.5) * t286) * t48 - t72 * t180 - t89 * t186)
                        + k_wall
                            * (t116
                                * (t78 * (t120 - t280 * t63)
                                    - T::from_f64(1.5) * t287 * t256 * t63)
                                + t148
                                    * (t103 * (t238 - t195 * t107)
                                        + T::from_f64(1.5) * t288 * t259 * t107))),
                k_edge
                    * (cos_theta
                        * (t71 * (t112 + t113 - t282) + t66 * (t67 + t110 + t284))
                        + sin_theta
                            * (t285
                                + t118
                                    * (T::from_f64(1.5) * t89 * t119 + T::from_f64(1.5) * t286))
                        - t72 * t197 - t89 * t198) * t51,
                t51
                    * (mu
                        * (k_edge
                            * (t71
                                * (t75
                                    * (t32
                                        * (-t291
                                            - t26
                                                * (cos_theta * (t18 + t211) + sin_theta * (t210 - t22)))
                                        + t125 * t291) - t223 * t281)
                                + t66
                                    * (t92
                                        * (t94
                                            * (-t292
                                                - t88
                                                    * (cos_theta * (t82 + t219) + sin_theta * (t218 - t84)))
                                            + t224 * t292) - t227 * t283)
                                - T::from_f64(1.5) * t228 * t281
                                - T::from_f64(1.5) * t229 * t283)
                            + k_wall
                                * (thetadot * (t293 * t267 + t294 * t271)
                                    + t256 * (-(t62 * t262) - T::from_f64(1.5) * t272 * t129)
                                    + t259 * (-(t102 * t263) - T::from_f64(1.5) * t273 * t138)))
                        + k_edge
                            * (t115 * t122 + (-t67 - t110) * t214 * t66
                                - T::from_f64(1.5) * t192 * t158 - t72 * t209
                                - T::from_f64(1.5) * t193 * t160 - t89 * t217)
                        + k_wall
                            * ((-t63 - t109) * t213 * t62 + (-t107 - t111) * t124 * t102
                                - T::from_f64(1.5) * t116 * t117 * t159 - t78 * t289
                                - T::from_f64(1.5) * t148 * t149 * t161 - t103 * t290)),
                t51
                    * (k_edge
                        * (mu
                            * (sin_theta * t295
                                + hc_alpha * (-(t245 * t281) - t246 * t283)) + t254)
                        + t248
                            * (t239 * (-t78 - t287 * t255)
                                + t241 * (t103 + t288 * t258))),
                t51
                    * (mu
                        * (k_edge
                            * (cos_theta * t295
                                + sin_theta * (-(t281 * t175) + t283 * t183) * hc_alpha)
                            + k_wall * (t293 * t264 + t294 * t268)) + t279),
                t51
                    * (mu
                        * (k_edge
                            * (t71 * (t221 * (t33 * t33) - t250 * t281)
                                + t66 * (t225 * (t95 * t95) - t252 * t283))
                            + k_wall
                                * (t62 * (t264 * (t162 * t162) - t276 * t129)
                                    + t102 * (t268 * (t163 * t163) - t278 * t138)))
                        + hc_alpha
                            * (k_edge * (-(t175 * t158) - t183 * t160)
                                + k_wall * (-(t239 * t159) - t241 * t161))),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                xdot * t4 + zdot * (t154 + t155),
                t0 + t1,
                t4,
                m_2,
                T::from_f64(0.0),
                T::from_f64(0.0),
                k_edge
                    * (mu
                        * (t296 * (T::from_f64(1.5) * t188 + t179)
                            + t297 * (T::from_f64(1.5) * t190 + t185))
                        + t30 * (T::from_f64(2.0) * t168 - T::from_f64(2.0) * t298)
                            * thetadot + t73 * t180 + t90 * t186)
                    + k_wall
                        * (mu
                            * (T::from_f64(1.5) * t299 * t257
                                - T::from_f64(1.5) * t300 * t260) + t257 * t280 * t79
                            + t260 * t104 * t195),
                k_edge
                    * (mu
                        * (sin_theta
                            * (T::from_f64(1.5) * t296 * t187
                                - T::from_f64(1.5) * t297 * t189) + cos_theta * t301 * t176)
                        + cos_theta * (t168 + t302) * thetadot + t73 * t197
                        + t90 * t198),
                mu
                    * (k_edge
                        * (t75
                            * (t32 * (T::from_f64(1.5) * t173 * t72 * t34 + t303 * t164)
                                - t303 * t304)
                            + t92
                                * (t94 * (T::from_f64(1.5) * t181 * t89 * t96 + t305 * t166)
                                    - t305 * t306) + hc_alpha * (t208 * t296 + t216 * t297))
                        + k_wall
                            * (thetadot
                                * (t62 * (t133 * (t266 * t134 + t307 * t165) - t307 * t308)
                                    + t102 * (t142 * (t270 * t143 + t309 * t167) - t309 * t310))
                                + T::from_f64(1.5) * t299 * t272
                                + T::from_f64(1.5) * t300 * t273))
                    + k_edge * (t168 * t207 + t73 * t209 + t298 * t215 + t90 * t217)
                    + k_wall
                        * (thetadot * (t62 * t109 * t213 + t102 * t111 * t124)
                            + t79 * t289 + t104 * t290),
                k_edge
                    * (mu * (sin_theta * t311 + hc_alpha * (t296 * t245 + t297 * t246))
                        + t312 * t27 + t313 * t48)
                    + k_wall
                        * (t62
                            * (t265 * (mu * t133 * t134 + t79) + t81 - T::from_f64(1.0))
                            + t102
                                * (t269 * (-(mu * t142 * t143) - t104) + T::from_f64(1.0)
                                    - t106)),
                k_edge
                    * (sin_theta
                        * (hc_alpha * (mu * t301 + t175 * t73 - t183 * t90) + t168
                            + t302) + t201 * t311)
                    + k_wall
                        * (t81 * (-t308 + t133 * t165) * t62
                            + t106 * (-t310 + t142 * t167) * t102) * mu,
                mu
                    * (k_edge
                        * (t71 * (t32 * (t250 * t34 + t314 * t164) - t314 * t304)
                            + t66 * (t94 * (t252 * t96 + t315 * t166) - t315 * t306))
                        + k_wall
                            * (t62 * (t133 * (t275 * t134 + t316 * t165) - t316 * t308)
                                + t102
                                    * (t142 * (t277 * t143 + t317 * t167) - t317 * t310)))
                    + k_edge * (t312 * t72 + t313 * t89)
                    + k_wall
                        * (t62 * (t109 + t265 * t79) * t78
                            + t102 * (t111 + t269 * t104) * t103),
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
    /// 62 add/sub, 114 mul, 9 div, 4 sqrt, 10 transcendental, 8 branches; 65 `let`s.
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
        let t18 = T::from_f64(1.0) / e_star;
        let t19 = t18 / edge_sum;
        let t20 = -rho_p;
        let t21 = l_c + t20;
        let t22 = r + t20;
        let t23 = sin_theta * t21;
        let t24 = rho_p * sin_theta;
        let t25 = rho_p * t7;
        let t26 = cos_theta * t21;
        let t27 = t18 / wall_sum;
        let t28 = rho_h + T::from_f64(0.5) * d + t1;
        let t29 = t8 + sin_theta * t28;
        let t30 = rho_p + t10;
        let t31 = r + t0 + x + t23 - T::from_f64(2.0) * t7 * t22;
        let t32 = t31.max0();
        let t33 = t32 * t32.sqrt();
        let t34 = r + t0 + x + t4 + T::from_f64(2.0) * t7 * t28;
        let t35 = t34.max0();
        let t36 = t35 * t35.sqrt();
        let t37 = r + t0 + t1 - t4 - T::from_f64(2.0) * t2 * t7;
        let t38 = t37.max0();
        let t39 = t38 * t38.sqrt();
        let t40 = (T::from_f64(1.0)
            + hc_alpha
                * (xdot * (-T::from_f64(1.0) + T::from_f64(2.0) * t7) + t14
                    + thetadot * (-t8 - T::from_f64(2.0) * t16 * t2)))
            .max0();
        let t41 = zdot
            + thetadot
                * (-(sin_theta * (l_c + t20 + t24))
                    - cos_theta * (r - T::from_f64(2.0) * t25));
        let t42 = (T::from_f64(1.0)
            + hc_alpha * (xdot + thetadot * (t26 - T::from_f64(2.0) * t16 * t22)))
            .max0();
        let t43 = v_s.hypot(t41);
        let t44 = sin_theta * (xdot + thetadot * (-t11 + cos_theta * t29))
            + cos_theta * (zdot + thetadot * (-t12 - sin_theta * t29));
        let t45 = (T::from_f64(1.0)
            + hc_alpha
                * (xdot * (T::from_f64(1.0) - T::from_f64(2.0) * t7) - t14
                    + thetadot * (t8 + T::from_f64(2.0) * t16 * t28)))
            .max0();
        let t46 = v_s.hypot(t44);
        let t47 = r + t0 + t1 - t23 + T::from_f64(2.0) * t7 * t30;
        let t48 = zdot
            + thetadot
                * (-(sin_theta * (l_c + t20 - t24))
                    - cos_theta * (t10 + T::from_f64(2.0) * t25));
        let t49 = t47.max0();
        let t50 = t49 * t49.sqrt();
        let t51 = (T::from_f64(1.0)
            + hc_alpha * (-xdot + thetadot * (-t26 + T::from_f64(2.0) * t16 * t30)))
            .max0();
        let t52 = v_s.hypot(t48);
        let t53 = k_edge * t39 * t40;
        let t54 = (T::from_f64(1.5) * t19 * t53).cbrt();
        let t55 = e_star * edge_sum * (T::from_f64(1.0) / (edge_ma * edge_mb));
        let t56 = k_wall * t50 * t51;
        let t57 = (T::from_f64(1.5) * t27 * t56).cbrt();
        let t58 = e_star * wall_sum * (T::from_f64(1.0) / (wall_ma * wall_mb));
        let t59 = k_wall * t42 * t33;
        let t60 = k_edge * t45 * t36;
        let t61 = (T::from_f64(1.5) * t27 * t59).cbrt();
        let t62 = (T::from_f64(1.5) * t19 * t60).cbrt();
        let normal = Vector4::new(t53, t59, t60, t56);
        let friction = Vector4::new(
            -t53 * mu * t13 / t17,
            -t59 * mu * t41 / t43,
            -t60 * mu * t44 / t46,
            -t56 * mu * t48 / t52,
        );
        let delta = Vector4::new(t37, t31, t34, t47);
        let slip = Vector4::new(t13, t41, t44, t48);
        let a = Vector4::new(edge_ma * t54, wall_ma * t61, edge_ma * t62, wall_ma * t57);
        let b = Vector4::new(edge_mb * t54, wall_mb * t61, edge_mb * t62, wall_mb * t57);
        let p0 = Vector4::new(
            T::from_f64(0.3183098861837907) * t55 * t54,
            T::from_f64(0.3183098861837907) * t58 * t61,
            T::from_f64(0.3183098861837907) * t55 * t62,
            T::from_f64(0.3183098861837907) * t58 * t57,
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
    /// 30 add/sub, 28 mul, 0 div, 0 sqrt, 6 transcendental, 4 branches; 17 `let`s.
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
        let kinetic = T::from_f64(0.5) * m * (xdot * xdot + zdot * zdot)
            + T::from_f64(0.5) * j * (thetadot * thetadot);
        let potential = k_edge * (T::from_f64(0.4) * t13 + T::from_f64(0.4) * t12)
            + k_wall * (T::from_f64(0.4) * t11 + T::from_f64(0.4) * t14);
        let depth = z + l_c * cos_theta;
        (kinetic, potential, depth)
    }
}
