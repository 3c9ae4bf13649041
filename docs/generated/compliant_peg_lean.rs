// @generated readable copy of `pegdyn::generated::compliant_peg_lean` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generator snapshot::

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
    /// The struct of `p`, shared with `compliant_peg` (same components).
    pub use super::compliant_peg::Params;
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
        let t11 = z - rho_h;
        let delta_edge_left = r + t2 - x + sin_theta * t11 - T::from_f64(2.0) * t3 * t7;
        let pen_edge_left = delta_edge_left.max0();
        let t12 = pen_edge_left * pen_edge_left.sqrt();
        let t13 = T::from_f64(1.0) - T::from_f64(2.0) * t7;
        let t14 = cos_theta * t11;
        let elastic_edge_left = k_edge * t12;
        let step_delta_edge_left = delta_edge_left.step();
        let t15 = sin_theta * (l_c - rho_p + rho_p * sin_theta)
            + cos_theta * (r - T::from_f64(2.0) * rho_p * t7);
        let slip_wall_right = zdot - thetadot * t15;
        let t16 = v_s.hypot(slip_wall_right);
        let delta_wall_right = r + t2 + x + sin_theta * t9 - T::from_f64(2.0) * t7 * t10;
        let pen_wall_right = delta_wall_right.max0();
        let t17 = pen_wall_right * pen_wall_right.sqrt();
        let elastic_wall_right = k_wall * t17;
        let step_delta_wall_right = delta_wall_right.step();
        let t18 = cos_theta * t9 - T::from_f64(2.0) * t8 * t10;
        let delta_rate_wall_right = xdot + thetadot * t18;
        let t19 = (T::from_f64(1.0) + hc_alpha * delta_rate_wall_right).max0();
        let t20 = sin_theta * t3 - t14;
        let t21 = cos_theta * t20 + r * sin_theta;
        let t22 = r * cos_theta - sin_theta * t20;
        let slip_edge_left = sin_theta * (xdot + thetadot * t21)
            + cos_theta * (zdot + thetadot * t22);
        let t23 = t14 - T::from_f64(2.0) * t8 * t3;
        let delta_rate_edge_left = -(xdot * t13) + zdot * sin_theta + thetadot * t23;
        let t24 = (T::from_f64(1.0) + hc_alpha * delta_rate_edge_left).max0();
        let t25 = v_s.hypot(slip_edge_left);
        let t26 = T::from_f64(1.0) - t24;
        let t27 = T::from_f64(1.0) - t19;
        let t28 = t24 / t25;
        let t29 = t28 * (mu * slip_edge_left);
        let t30 = t19 / t16;
        let t31 = elastic_wall_right * t30;
        let t32 = mu * slip_wall_right;
        let t33 = step_delta_edge_left - t26;
        SMatrix::<
            T,
            8,
            1,
        >::from_row_slice(
            &[
                xdot,
                zdot,
                thetadot,
                (-(elastic_edge_left * (t29 * sin_theta - t13 * t33))
                    - elastic_wall_right
                        * (-T::from_f64(1.0) + step_delta_wall_right + t19) + t0 + t1)
                    / m,
                -(sin_theta * (elastic_edge_left * t33 + f2)
                    + cos_theta * (t29 * elastic_edge_left - f1) + t31 * t32) / m,
                (m_2
                    - elastic_edge_left
                        * (t23 * t33 + t29 * (sin_theta * t21 + cos_theta * t22))
                    + elastic_wall_right
                        * (t32 * t30 * t15 - t18 * (step_delta_wall_right - t27))) / j,
                xdot * (t0 + t1) + zdot * (f1 * cos_theta - f2 * sin_theta)
                    + thetadot * m_2,
                mu
                    * (t28 * elastic_edge_left * (slip_edge_left * slip_edge_left)
                        + t31 * (slip_wall_right * slip_wall_right))
                    - elastic_edge_left * delta_rate_edge_left * t26
                    - elastic_wall_right * delta_rate_wall_right * t27,
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
    /// 196 add/sub, 439 mul, 6 div, 4 sqrt, 4 transcendental, 12 branches; 165 `let`s.
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
        let t22 = z - rho_h;
        let t23 = sin_theta * t22;
        let delta_edge_left = r + t5 - x + t23 - T::from_f64(2.0) * t6 * t10;
        let pen_edge_left = delta_edge_left.max0();
        let t24 = pen_edge_left * pen_edge_left.sqrt();
        let t25 = T::from_f64(1.0) - T::from_f64(2.0) * t10;
        let t26 = cos_theta * t22;
        let elastic_edge_left = k_edge * t24;
        let step_delta_edge_left = delta_edge_left.step();
        let delta_wall_right = r + t5 + x + t14 - T::from_f64(2.0) * t10 * t13;
        let pen_wall_right = delta_wall_right.max0();
        let t27 = pen_wall_right * pen_wall_right.sqrt();
        let elastic_wall_right = k_wall * t27;
        let step_delta_wall_right = delta_wall_right.step();
        let t28 = cos_theta * t12 - T::from_f64(2.0) * t11 * t13;
        let delta_rate_wall_right = xdot + thetadot * t28;
        let t29 = T::from_f64(1.0) + hc_alpha * delta_rate_wall_right;
        let t30 = t29.max0();
        let t31 = sin_theta * t6 - t26;
        let t32 = cos_theta * t31;
        let t33 = t32 + r * sin_theta;
        let t34 = xdot + thetadot * t33;
        let t35 = t26 - T::from_f64(2.0) * t11 * t6;
        let delta_rate_edge_left = -(xdot * t25) + zdot * sin_theta + thetadot * t35;
        let t36 = T::from_f64(1.0) + hc_alpha * delta_rate_edge_left;
        let t37 = t36.max0();
        let t38 = T::from_f64(1.0) - t37;
        let t39 = T::from_f64(1.0) - t30;
        let t40 = step_delta_edge_left - t38;
        let t41 = t24 * t40;
        let sqrt_pen_edge_left = pen_edge_left.sqrt();
        let t42 = t25 * t25;
        let t43 = step_delta_edge_left * step_delta_edge_left;
        let sqrt_pen_wall_right = pen_wall_right.sqrt();
        let t44 = step_delta_wall_right * step_delta_wall_right;
        let t45 = T::from_f64(1.5) * t44;
        let t46 = r + cos_theta * t6 + t23;
        let t47 = t10 - t9 * t9;
        let t48 = t23 - t6 * t47;
        let t49 = t14 - t13 * t47;
        let t50 = thetadot * t21;
        let t51 = t3 - t4;
        let t52 = t29.step();
        let t53 = t28 * t28;
        let t54 = sin_theta * t31;
        let t55 = r * cos_theta - t54;
        let t56 = zdot + thetadot * t55;
        let slip_edge_left = sin_theta * t34 + cos_theta * t56;
        let t57 = v_s.hypot(slip_edge_left);
        let t58 = T::from_f64(1.0) / t57;
        let t59 = sin_theta * t33 + cos_theta * t55;
        let t60 = slip_edge_left * slip_edge_left;
        let t61 = t36.step();
        let t62 = T::from_f64(1.0) / (t57 * t57 * t57);
        let t63 = hc_alpha * t61;
        let t64 = t63 * t35;
        let t65 = t64 * elastic_edge_left * sin_theta;
        let t66 = t35 * t35;
        let t67 = hc_alpha * t52;
        let t68 = elastic_wall_right * t67;
        let t69 = t67 * t28;
        let t70 = T::from_f64(1.5) * t30;
        let t71 = t70 - T::from_f64(1.5);
        let t72 = T::from_f64(1.5) - T::from_f64(1.5) * t37;
        let t73 = step_delta_edge_left * sqrt_pen_edge_left;
        let t74 = t73 * t72;
        let t75 = thetadot * t24;
        let t76 = t11 * t75;
        let t77 = T::from_f64(2.0) * t76 * t63;
        let t78 = t74 * t25 + t77;
        let t79 = slip_edge_left * t58;
        let t80 = t63 * t79;
        let t81 = t80 * t75;
        let t82 = mu * sin_theta;
        let t83 = t75 * cos_theta;
        let t84 = t83 * t63;
        let t85 = sqrt_pen_edge_left * t43;
        let t86 = T::from_f64(1.5) * t85 * t25;
        let t87 = mu * cos_theta;
        let t88 = mu * t19;
        let t89 = t79 * t37;
        let t90 = sin_theta * t46 + t32;
        let t91 = t60 * t62;
        let t92 = t37 * (t58 - t91);
        let t93 = t80 * t35;
        let t94 = t92 * t59 + t93;
        let t95 = t89 * step_delta_edge_left;
        let t96 = t80 * t25;
        let t97 = t80 * sin_theta;
        let t98 = mu * t59;
        let t99 = sqrt_pen_edge_left * (t35 * t43 + t95 * t98);
        let t100 = step_delta_wall_right * t71;
        let t101 = t73 * t35;
        let t102 = t89 * t101;
        let t103 = t64 * t25;
        let t104 = t73 * t37;
        let t105 = t77 - T::from_f64(1.5) * t104 * t25;
        let t106 = t58 * t60;
        let t107 = t106 * mu;
        let t108 = t62 * (slip_edge_left * slip_edge_left * slip_edge_left);
        let t109 = t37 * (T::from_f64(2.0) * t79 - t108);
        let t110 = t37 * t59;
        let t111 = t84 - t74 * sin_theta;
        let t112 = T::from_f64(2.0) * t11 * xdot + zdot * cos_theta - thetadot * t48;
        let t113 = t24 * t112;
        let t114 = t63 * t113;
        let t115 = t114 - t101 * t72;
        let t116 = t54 - cos_theta * t46;
        let t117 = cos_theta * (thetadot * t90 - t34)
            + sin_theta * (thetadot * t116 + t56);
        let t118 = t91 * t117;
        let t119 = T::from_f64(1.5) * t85 * t35 + t115;
        let t120 = thetadot * t27;
        let t121 = t67 * t49;
        let t122 = t120 * t121;
        let t123 = t63 * t25 - t92 * t87;
        let t124 = sin_theta * t16
            - cos_theta * (rho_p * (sin_theta - T::from_f64(2.0) * t11) + t15);
        let t125 = t80 * t112;
        let t126 = t24 * (step_delta_edge_left - t38 + t98 * t80 * thetadot);
        let t127 = t24 * t117;
        let t128 = t38 - t63 * (t107 + delta_rate_edge_left);
        let slip_wall_right = zdot - t50;
        let t129 = v_s.hypot(slip_wall_right);
        let t130 = T::from_f64(1.0) / t129;
        let t131 = slip_wall_right * slip_wall_right;
        let t132 = T::from_f64(1.0) / (t129 * t129 * t129);
        let t133 = t131 * t132;
        let t134 = t30 * (t130 - t133);
        let t135 = slip_wall_right * t130;
        let t136 = mu * t30;
        let t137 = t135 * t21;
        let t138 = step_delta_wall_right * sqrt_pen_wall_right;
        let t139 = t138 * t28;
        let t140 = t130 * t131;
        let t141 = t138 * k_wall;
        let t142 = t132 * (slip_wall_right * slip_wall_right * slip_wall_right);
        let t143 = t30 * t21;
        let t144 = t139 * t30;
        let t145 = t134 * t21;
        let t146 = t120 * t124;
        let t147 = T::from_f64(1.5) - t70;
        let t148 = t139 * t147 + t122;
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
                        * (-(T::from_f64(1.5) * (t95 * t82 * t25 - t42 * t43)
                            * sqrt_pen_edge_left) - t25 * t78
                            + T::from_f64(2.0) * t81 * t82 * t11)
                        + sqrt_pen_wall_right * (t100 + t45) * k_wall),
                k_edge
                    * (sin_theta * (t86 - t81 * t87) + t25 * t111
                        - T::from_f64(1.5) * t88 * t89 * t73) * t17,
                -t17
                    * (k_edge
                        * (t24
                            * (mu
                                * (t37
                                    * (t118 * sin_theta
                                        - t58 * (sin_theta * t117 - cos_theta * slip_edge_left))
                                    + t97 * t112) + T::from_f64(2.0) * t11 * t40) - t25 * t119
                            + T::from_f64(1.5) * t102 * t82)
                        - k_wall
                            * (sqrt_pen_wall_right * (step_delta_wall_right * t147 - t45)
                                * t28 + t122) - t3 + t4),
                -t17
                    * (t68
                        - elastic_edge_left
                            * (mu * (t97 * t25 - t92 * t19) - t63 * t42)),
                -(elastic_edge_left * (t88 * t80 - sin_theta * t123)) * t17,
                -t17
                    * (t69 * elastic_wall_right
                        - elastic_edge_left * (t103 - t82 * t94)),
                T::from_f64(0.0),
                T::from_f64(0.0),
                -t17
                    * (T::from_f64(1.5) * t141 * t136 * t135
                        - k_edge * (sin_theta * (t86 - t78) - t79 * t105 * t87)),
                -(k_edge
                    * (T::from_f64(1.5) * (t43 * t19 + t95 * t87 * sin_theta)
                        * sqrt_pen_edge_left + sin_theta * t111 + t81 * mu * t20)) * t17,
                -t17
                    * (mu
                        * (k_edge
                            * (t24
                                * (t37
                                    * (t118 * cos_theta
                                        - t58 * (sin_theta * slip_edge_left + cos_theta * t117))
                                    + t125 * cos_theta) + T::from_f64(1.5) * t102 * cos_theta)
                            + k_wall
                                * (T::from_f64(1.5) * t144 * t135
                                    - t120 * (t121 * t135 - t134 * t124)))
                        + k_edge * (t41 * cos_theta + sin_theta * t119) + t0 + t1),
                -t17
                    * (t68 * t135 * mu
                        - elastic_edge_left * (sin_theta * t123 + t96 * t87)),
                -t17
                    * (mu
                        * (elastic_edge_left * (t92 * t20 + t97 * cos_theta)
                            + t134 * elastic_wall_right)
                        + elastic_edge_left * t63 * t19),
                -t17
                    * (mu
                        * (cos_theta * t94 * elastic_edge_left
                            + elastic_wall_right * (t69 * t135 - t145)) + t65),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t18
                    * (k_edge
                        * (-(T::from_f64(2.0) * t126 * t11)
                            + T::from_f64(1.5) * t99 * t25 - t35 * t78)
                        + sqrt_pen_wall_right
                            * (t28 * (-t45 - t100)
                                + T::from_f64(1.5) * t136 * t137 * step_delta_wall_right)
                            * k_wall),
                k_edge
                    * (-(t126 * cos_theta) - T::from_f64(1.5) * t99 * sin_theta
                        - t35 * t111) * t18,
                -t18
                    * (mu
                        * (k_edge
                            * (t24
                                * (t125 * t59
                                    - t37
                                        * (t58
                                            * (t59 * t117
                                                + slip_edge_left
                                                    * (sin_theta * (t116 + t55) - cos_theta * (t33 - t90)))
                                            - t118 * t59)) + T::from_f64(1.5) * t102 * t59)
                            - k_wall
                                * (T::from_f64(1.5) * t144 * t137
                                    - t27
                                        * (t124 * (t50 * t133 - t130 * (t50 - slip_wall_right))
                                            * t30 + t121 * t137 * thetadot)))
                        + k_edge
                            * (-(t41 * t48) + T::from_f64(1.5) * t85 * t66 + t35 * t115)
                        + k_wall
                            * (-((step_delta_wall_right - t39) * t49 * t27)
                                + T::from_f64(1.5) * sqrt_pen_wall_right * t44 * t53
                                - t28 * t148)),
                t18
                    * (elastic_edge_left * (t98 * (t96 - t92 * sin_theta) + t103)
                        + t68 * (t137 * mu - t28)),
                -t18
                    * (mu
                        * (t59 * (t92 * cos_theta + t97) * elastic_edge_left
                            - t145 * elastic_wall_right) + t65),
                -t18
                    * (mu
                        * (elastic_edge_left * (t92 * (t59 * t59) + t93 * t59)
                            - elastic_wall_right * (t69 * t137 - t134 * (t21 * t21)))
                        + hc_alpha
                            * (elastic_edge_left * t61 * t66
                                + elastic_wall_right * t52 * t53)),
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
                    * (t107 * t105 - T::from_f64(2.0) * t76 * t38
                        + delta_rate_edge_left * t78)
                    + t141
                        * (T::from_f64(1.5) * t140 * t136 + delta_rate_wall_right * t71),
                k_edge
                    * (t107 * (T::from_f64(1.5) * t104 * sin_theta + t84) - t83 * t38
                        + delta_rate_edge_left * t111),
                mu
                    * (k_edge
                        * (t37
                            * (t127 * t108
                                - t58
                                    * (T::from_f64(2.0) * t127 * slip_edge_left
                                        - T::from_f64(1.5) * t101 * t60)) + t114 * t106)
                        - k_wall
                            * (t30
                                * (t146 * t142
                                    - t130
                                        * (T::from_f64(1.5) * t139 * t131
                                            + T::from_f64(2.0) * t146 * slip_wall_right))
                                + t122 * t140))
                    - k_edge * (t113 * t38 - delta_rate_edge_left * t115)
                    + k_wall * (t120 * t39 * t49 - delta_rate_wall_right * t148),
                elastic_edge_left * (t25 * t128 + t109 * t82)
                    + elastic_wall_right
                        * (t67 * (t140 * mu + delta_rate_wall_right) + t30
                            - T::from_f64(1.0)),
                elastic_wall_right * (T::from_f64(2.0) * t135 - t142) * t136
                    - elastic_edge_left * (sin_theta * t128 - t109 * t87),
                mu
                    * (elastic_wall_right
                        * (t130
                            * (t69 * t131 - T::from_f64(2.0) * t143 * slip_wall_right)
                            + t143 * t142)
                        - elastic_edge_left
                            * (t110 * t108
                                - t58
                                    * (t64 * t60 + T::from_f64(2.0) * t110 * slip_edge_left)))
                    + elastic_edge_left * (t63 * delta_rate_edge_left - t38) * t35
                    + elastic_wall_right * (t67 * delta_rate_wall_right - t39) * t28,
                T::from_f64(0.0),
                T::from_f64(0.0),
            ],
        )
    }
    /// The outputs of [`contacts`].
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct ContactsOut<T: Real> {
        /// Normal force f on the peg, N, per contact (edge_left, wall_right).
        pub normal: SVector<T, 2>,
        /// Friction force along the contact tangent, N, per contact (edge_left, wall_right).
        pub friction: SVector<T, 2>,
        /// Penetration δ (negative: gap), m, per contact (edge_left, wall_right).
        pub delta: SVector<T, 2>,
        /// Sliding velocity of the peg's material point, m/s, per contact (edge_left, wall_right).
        pub slip: SVector<T, 2>,
        /// Semi-major axis a of the Hertz ellipse (9), m, per contact (edge_left, wall_right).
        pub a: SVector<T, 2>,
        /// Semi-minor axis b of the Hertz ellipse (10), m, per contact (edge_left, wall_right).
        pub b: SVector<T, 2>,
        /// Maximum Hertz pressure p₀ (11), Pa, per contact (edge_left, wall_right).
        pub p0: SVector<T, 2>,
    }
    /// Per contact (edge_left, wall_right): normal force f (N), friction force along the tangent (N), penetration delta (m), sliding velocity (m/s), contact ellipse a, b (m) and maximum pressure p0 (Pa) ((9)-(11)).
    ///
    /// # Inputs
    /// - `y` = (`x`, `z`, `theta`, `xdot`, `zdot`, `thetadot`, `work`, `dissipation`)
    /// - `p` = (`m`, `J`, `r`, `l_c`, `D`, `rho_p`, `rho_h`, `mu`, `v_s`, `k_edge`, `k_wall`, `f1`, `f2`, `M`, `e_star`, `edge_sum`, `edge_ma`, `edge_mb`, `edge_dstar`, `wall_sum`, `wall_ma`, `wall_mb`, `wall_dstar`, `hc_alpha`)
    ///
    /// # Outputs
    /// The fields of [`ContactsOut`]:
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
    pub fn contacts<T: Real>(y: &SVector<T, 8>, p: &SVector<T, 24>) -> ContactsOut<T> {
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
        let t9 = z - rho_h;
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
            + cos_theta * (zdot + thetadot * (r * cos_theta - sin_theta * t15));
        let delta_rate_edge_left = -(xdot * (T::from_f64(1.0) - T::from_f64(2.0) * t5))
            + zdot * sin_theta + thetadot * (t11 - T::from_f64(2.0) * t6 * t1);
        let t16 = (T::from_f64(1.0) + hc_alpha * delta_rate_edge_left).max0();
        let t17 = v_s.hypot(slip_edge_left);
        let normal_edge_left = k_edge * t10 * t16;
        let normal_wall_right = k_wall * t14 * t13;
        let t18 = (T::from_f64(1.5) * normal_edge_left / (e_star * edge_sum)).cbrt();
        let t19 = (T::from_f64(1.5) * normal_wall_right / (e_star * wall_sum)).cbrt();
        ContactsOut {
            normal: Vector2::new(normal_edge_left, normal_wall_right),
            friction: Vector2::new(
                -normal_edge_left * mu * slip_edge_left / t17,
                -normal_wall_right * mu * slip_wall_right / t12,
            ),
            delta: Vector2::new(delta_edge_left, delta_wall_right),
            slip: Vector2::new(slip_edge_left, slip_wall_right),
            a: Vector2::new(edge_ma * t18, wall_ma * t19),
            b: Vector2::new(edge_mb * t18, wall_mb * t19),
            p0: Vector2::new(
                T::from_f64(0.3183098861837907) * e_star * edge_sum * t18
                    / (edge_ma * edge_mb),
                T::from_f64(0.3183098861837907) * e_star * wall_sum * t19
                    / (wall_ma * wall_mb),
            ),
        }
    }
    /// The outputs' struct, shared with `compliant_peg` (same fields).
    pub use super::compliant_peg::EnergyOut;
    /// Kinetic energy (59) (J), contact potential (63) (J) and insertion depth of the bottom face (m).
    ///
    /// # Inputs
    /// - `y` = (`x`, `z`, `theta`, `xdot`, `zdot`, `thetadot`, `work`, `dissipation`)
    /// - `p` = (`m`, `J`, `r`, `l_c`, `D`, `rho_p`, `rho_h`, `mu`, `v_s`, `k_edge`, `k_wall`, `f1`, `f2`, `M`, `e_star`, `edge_sum`, `edge_ma`, `edge_mb`, `edge_dstar`, `wall_sum`, `wall_ma`, `wall_mb`, `wall_dstar`, `hc_alpha`)
    ///
    /// # Outputs
    /// The fields of [`EnergyOut`]:
    /// - `kinetic`: scalar
    /// - `potential`: scalar
    /// - `depth`: scalar
    ///
    /// # Cost
    /// 17 add/sub, 19 mul, 0 div, 0 sqrt, 4 transcendental, 2 branches; 11 `let`s.
    #[inline]
    pub fn energy<T: Real>(y: &SVector<T, 8>, p: &SVector<T, 24>) -> EnergyOut<T> {
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
        let delta_edge_left = r + t0 - x + sin_theta * (z - rho_h)
            - T::from_f64(2.0) * (-rho_h + t0 - x) * t2;
        let pen_edge_left = delta_edge_left.max0();
        let delta_wall_right = r + t0 + x + sin_theta * (l_c - rho_p)
            - T::from_f64(2.0) * t2 * (r - rho_p);
        let pen_wall_right = delta_wall_right.max0();
        let t3 = pen_edge_left.powf(T::from_f64(2.5));
        let t4 = pen_wall_right.powf(T::from_f64(2.5));
        EnergyOut {
            kinetic: T::from_f64(0.5)
                * (m * (xdot * xdot + zdot * zdot) + j * (thetadot * thetadot)),
            potential: T::from_f64(0.4) * (k_edge * t3 + k_wall * t4),
            depth: z + l_c * cos_theta,
        }
    }
}
