// @generated readable copy of `pegdyn::generated::compliant_peg_elastic` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generated_snapshot

/// Compliant planar peg (*Dynamic analysis for peg-in-hole assembly with contact deformation*, (31)-(51), (55)-(64)) with contacts edge_left, wall_right, edge_right, wall_left, Hertz-Mindlin friction capped by Coulomb. Inputs: state y (see STATE) and parameters p (see P_NAMES). SI units.
pub mod compliant_peg_elastic {
    use nalgebra::{SMatrix, SVector, Vector4};
    use pegdyn::scalar::Real;
    /// Symbol names of the components of `y`, in order.
    pub const Y_NAMES: [&str; 12] = [
        "x",
        "z",
        "theta",
        "xdot",
        "zdot",
        "thetadot",
        "work",
        "dissipation",
        "u_edge_left",
        "u_wall_right",
        "u_edge_right",
        "u_wall_left",
    ];
    /// Symbol names of the components of `p`, in order.
    pub const P_NAMES: [&str; 27] = [
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
        "g_star",
        "delta_floor",
        "tau_t",
    ];
    /// Right-hand side of y = (x, z, theta, xdot, zdot, thetadot, work, dissipation, u_edge_left, u_wall_right, u_edge_right, u_wall_left): M qdd = applied (50) + contact normal forces (-grad of the Hertz potential (62) and of the stored tangential energy) + Hertz-Mindlin friction capped by Coulomb; work, dissipation and utilisation rates. SI units.
    ///
    /// # Inputs
    /// - `y` = (`x`, `z`, `theta`, `xdot`, `zdot`, `thetadot`, `work`, `dissipation`, `u_edge_left`, `u_wall_right`, `u_edge_right`, `u_wall_left`)
    /// - `p` = (`m`, `J`, `r`, `l_c`, `D`, `rho_p`, `rho_h`, `mu`, `v_s`, `k_edge`, `k_wall`, `f1`, `f2`, `M`, `e_star`, `edge_sum`, `edge_ma`, `edge_mb`, `edge_dstar`, `wall_sum`, `wall_ma`, `wall_mb`, `wall_dstar`, `hc_alpha`, `g_star`, `delta_floor`, `tau_t`)
    ///
    /// # Outputs
    /// - `ydot`: vector of 12
    ///
    /// # Cost
    /// 155 add/sub, 258 mul, 15 div, 8 sqrt, 10 transcendental, 20 branches; 151 `let`s.
    #[inline]
    pub fn rhs<T: Real>(y: &SVector<T, 12>, p: &SVector<T, 27>) -> SVector<T, 12> {
        let x = y[0];
        let z = y[1];
        let theta = y[2];
        let xdot = y[3];
        let zdot = y[4];
        let thetadot = y[5];
        let u_edge_left = y[8];
        let u_wall_right = y[9];
        let u_edge_right = y[10];
        let u_wall_left = y[11];
        let m = p[0];
        let j = p[1];
        let r = p[2];
        let l_c = p[3];
        let d = p[4];
        let rho_p = p[5];
        let rho_h = p[6];
        let mu = p[7];
        let k_edge = p[9];
        let k_wall = p[10];
        let f1 = p[11];
        let f2 = p[12];
        let m_2 = p[13];
        let e_star = p[14];
        let edge_sum = p[15];
        let edge_ma = p[16];
        let edge_mb = p[17];
        let wall_sum = p[19];
        let wall_ma = p[20];
        let wall_mb = p[21];
        let hc_alpha = p[23];
        let g_star = p[24];
        let delta_floor = p[25];
        let tau_t = p[26];
        let (sin_theta, cos_theta) = theta.sin_cos();
        let t0 = f2 * cos_theta;
        let t1 = T::from_f64(0.5) * d;
        let t2 = -T::from_f64(0.5) * d;
        let t3 = -rho_h + t2 - x;
        let t4 = T::from_f64(0.5) * theta;
        let (t5, t6) = t4.sin_cos();
        let t7 = t5 * t5;
        let t8 = t3 * t7;
        let t9 = r * sin_theta;
        let t10 = r * cos_theta;
        let t11 = zdot * sin_theta;
        let t12 = t5 * t6;
        let t13 = T::from_f64(1.0) - T::from_f64(2.0) * t7;
        let t14 = edge_ma * edge_mb;
        let t15 = t14.sqrt();
        let t16 = T::from_f64(1.5) * k_edge / (e_star * edge_sum);
        let t17 = t16.cbrt();
        let t18 = T::from_f64(1.0) / t14.sqrt();
        let t19 = t16.powf(-T::from_f64(1.0 / 3.0));
        let t20 = u_edge_left * u_edge_left;
        let t21 = mu * k_edge;
        let t22 = l_c - rho_p;
        let t23 = r - rho_p;
        let t24 = sin_theta * t22;
        let t25 = rho_p * sin_theta;
        let t26 = cos_theta * (r - T::from_f64(2.0) * rho_p * t7);
        let t27 = cos_theta * t22;
        let t28 = wall_ma * wall_mb;
        let t29 = t28.sqrt();
        let t30 = T::from_f64(1.5) * k_wall / (e_star * wall_sum);
        let t31 = t30.cbrt();
        let t32 = T::from_f64(1.0) / t28.sqrt();
        let t33 = t30.powf(-T::from_f64(1.0 / 3.0));
        let t34 = u_wall_right * u_wall_right;
        let t35 = mu * k_wall;
        let t36 = rho_h + t1 - x;
        let t37 = u_edge_right * u_edge_right;
        let t38 = u_wall_left * u_wall_left;
        let t39 = -rho_h + z;
        let t40 = sin_theta * t39;
        let t41 = -xdot * t13;
        let t42 = cos_theta * t39;
        let t43 = sin_theta * (l_c - rho_p + t25) + t26;
        let t44 = thetadot * t43;
        let t45 = -rho_p + r;
        let t46 = sin_theta * (-l_c + rho_p + t25) + t26;
        let t47 = thetadot * t46;
        let slip_wall_left = zdot + t47;
        let abs_slip_wall_left = slip_wall_left.abs();
        let t48 = zdot + t47 - u_wall_left * abs_slip_wall_left;
        let delta_wall_right = r + t2 + x + t24 - T::from_f64(2.0) * t7 * t23;
        let pen_wall_right = delta_wall_right.max0();
        let t49 = pen_wall_right * pen_wall_right.sqrt();
        let t50 = delta_floor.hypot(delta_wall_right);
        let t51 = T::from_f64(1.0) / t50;
        let step_delta_wall_right = delta_wall_right.step();
        let t52 = t27 - T::from_f64(2.0) * t12 * t23;
        let delta_rate_wall_right = xdot + thetadot * t52;
        let t53 = (T::from_f64(1.0) + hc_alpha * delta_rate_wall_right).max0();
        let delta_edge_left = r + t2 - x + t40 - T::from_f64(2.0) * t8;
        let t54 = sin_theta * t3 - t42;
        let t55 = cos_theta * t54 + t9;
        let t56 = -(sin_theta * t54) + t10;
        let t57 = sin_theta * (xdot + thetadot * t55);
        let t58 = cos_theta * (zdot + thetadot * t56);
        let slip_edge_left = t57 + t58;
        let pen_edge_left = delta_edge_left.max0();
        let t59 = pen_edge_left * pen_edge_left.sqrt();
        let t60 = t42 - T::from_f64(2.0) * t12 * t3;
        let t61 = thetadot * t60;
        let delta_rate_edge_left = t41 + t11 + t61;
        let t62 = (T::from_f64(1.0) + hc_alpha * delta_rate_edge_left).max0();
        let abs_slip_edge_left = slip_edge_left.abs();
        let t63 = t57 + t58 - u_edge_left * abs_slip_edge_left;
        let t64 = g_star / mu;
        let t65 = t15 * t17;
        let t66 = t64 * (t65 / k_edge);
        let step_delta_edge_left = delta_edge_left.step();
        let slip_wall_right = zdot - t44;
        let abs_slip_wall_right = slip_wall_right.abs();
        let t67 = -zdot + t44 + u_wall_right * abs_slip_wall_right;
        let t68 = t29 * t31;
        let t69 = t64 * (t68 / k_wall);
        let t70 = -t42 + sin_theta * t36;
        let t71 = t9 - cos_theta * t70;
        let t72 = t10 + sin_theta * t70;
        let t73 = sin_theta * (xdot - thetadot * t71);
        let t74 = cos_theta * (zdot - thetadot * t72);
        let slip_edge_right = t73 + t74;
        let t75 = t42 - T::from_f64(2.0) * t12 * t36;
        let t76 = thetadot * t75;
        let t77 = t41 + t11 + t76;
        let t78 = (T::from_f64(1.0) - hc_alpha * t77).max0();
        let abs_slip_edge_right = slip_edge_right.abs();
        let t79 = t73 + t74 - u_edge_right * abs_slip_edge_right;
        let t80 = t7 * t45;
        let delta_wall_left = r + t2 - x - t24 - T::from_f64(2.0) * t80;
        let pen_wall_left = delta_wall_left.max0();
        let t81 = pen_wall_left * pen_wall_left.sqrt();
        let t82 = t27 + T::from_f64(2.0) * t12 * t45;
        let t83 = xdot + thetadot * t82;
        let t84 = (T::from_f64(1.0) - hc_alpha * t83).max0();
        let step_delta_wall_left = delta_wall_left.step();
        let t85 = delta_rate_wall_right * t51 * delta_wall_right;
        let t86 = -t62 + T::from_f64(1.0);
        let t87 = t1 - r + x - t40 + T::from_f64(2.0) * t8;
        let t88 = delta_floor.hypot(t87);
        let t89 = T::from_f64(1.0) / t88;
        let t90 = g_star * tau_t;
        let t91 = t90 * t65;
        let t92 = t63 * t89;
        let t93 = t59 * (t21 * u_edge_left + T::from_f64(8.0) * t91 * t92);
        let t94 = (t89 * (t11 + t41 + t61) * t87).max0();
        let t95 = -t53 + T::from_f64(1.0);
        let t96 = (-t85).max0();
        let delta_edge_right = r + t2 + x - t40 + T::from_f64(2.0) * t7 * t36;
        let pen_edge_right = delta_edge_right.max0();
        let t97 = pen_edge_right * pen_edge_right.sqrt();
        let t98 = -t78 + T::from_f64(1.0);
        let t99 = delta_floor.hypot(delta_edge_right);
        let t100 = T::from_f64(1.0) / t99;
        let t101 = t79 * t100;
        let t102 = t97 * (t21 * u_edge_right + T::from_f64(8.0) * t91 * t101);
        let t103 = (t100 * (t11 + t41 + t76) * delta_edge_right).max0();
        let step_delta_edge_right = delta_edge_right.step();
        let t104 = -t84 + T::from_f64(1.0);
        let t105 = t1 - r + x + t24 + T::from_f64(2.0) * t80;
        let t106 = delta_floor.hypot(t105);
        let t107 = T::from_f64(1.0) / t106;
        let t108 = t83 * t107 * t105;
        let t109 = (-t108).max0();
        let t110 = -f1 + t93 + t102;
        let t111 = t34 * t49;
        let t112 = t38 * t81;
        let t113 = t33 * (k_wall * k_wall) * t32;
        let t114 = t20 * t59;
        let t115 = t37 * t97;
        let t116 = t19 * (k_edge * k_edge) * t18;
        let t117 = mu * mu / g_star;
        let t118 = t68 * t90;
        let t119 = t67 * t51;
        let t120 = t48 * t107;
        let t121 = -step_delta_edge_right + t98;
        let t122 = t59 * (step_delta_edge_left - t86);
        let t123 = k_edge * (t122 + t97 * t121);
        let t124 = T::from_f64(0.03125) * (t116 * (t114 - t115)) * t117;
        let t125 = t119 * t49;
        let t126 = t120 * t81;
        SMatrix::<
            T,
            12,
            1,
        >::from_row_slice(
            &[
                xdot,
                zdot,
                thetadot,
                (t13 * (t123 + t124)
                    + k_wall
                        * (-(t49 * (-T::from_f64(1.0) + step_delta_wall_right + t53))
                            + t81 * (t84 - T::from_f64(1.0) + step_delta_wall_left))
                    - sin_theta * t110
                    + T::from_f64(0.03125) * (t113 * (-t111 + t112)) * t117 + t0) / m,
                -(sin_theta * (t123 + t124 + f2) + cos_theta * t110
                    + t35 * (u_wall_right * t49 + u_wall_left * t81)
                    + T::from_f64(8.0) * (t68 * (-t125 + t126)) * t90) / m,
                (m_2 + k_edge * (-(t122 * t60) - t75 * t121 * t97)
                    + t117
                        * (-(T::from_f64(0.03125) * t116 * (t114 * t60 - t115 * t75))
                            + T::from_f64(0.03125) * t113 * (-(t111 * t52) + t112 * t82))
                    + k_wall
                        * (-(t52 * (step_delta_wall_right - t95) * t49)
                            + t82 * (step_delta_wall_left - t104) * t81)
                    - t93 * (sin_theta * t55 + cos_theta * t56)
                    + t43 * t49 * (t35 * u_wall_right - T::from_f64(8.0) * t118 * t119)
                    + t102 * (sin_theta * t71 + cos_theta * t72)
                    - t46 * t81 * (t35 * u_wall_left + T::from_f64(8.0) * t118 * t120))
                    / j,
                xdot * (f1 * sin_theta + t0) + zdot * (f1 * cos_theta - f2 * sin_theta)
                    + thetadot * m_2,
                mu
                    * (k_edge * (t114 * abs_slip_edge_left + t115 * abs_slip_edge_right)
                        + k_wall
                            * (t111 * abs_slip_wall_right + t112 * abs_slip_wall_left))
                    + t117
                        * (T::from_f64(0.125) * t116
                            * (t59 * t94 * u_edge_left.powi(4)
                                + t97 * t103 * u_edge_right.powi(4))
                            + T::from_f64(0.125) * t113
                                * (t49 * t96 * u_wall_right.powi(4)
                                    + t81 * t109 * u_wall_left.powi(4)))
                    + t90
                        * (T::from_f64(8.0) * t65
                            * (t92 * slip_edge_left * t59 + t101 * slip_edge_right * t97)
                            - T::from_f64(8.0) * t68
                                * (t125 * slip_wall_right - t126 * slip_wall_left))
                    - k_edge * (delta_rate_edge_left * t59 * t86 - t77 * t97 * t98)
                    - k_wall * (delta_rate_wall_right * t49 * t95 - t83 * t81 * t104),
                -t89
                    * (-(T::from_f64(8.0) * t66 * t63)
                        + u_edge_left
                            * (-(delta_rate_edge_left * t89 * t87) + t20 * t94)),
                -t51 * (T::from_f64(8.0) * t69 * t67 + u_wall_right * (t85 + t34 * t96)),
                -t100
                    * (-(T::from_f64(8.0) * t66 * t79)
                        + u_edge_right
                            * (-(t77 * t100 * delta_edge_right) + t37 * t103)),
                -t107
                    * (-(T::from_f64(8.0) * t69 * t48)
                        + u_wall_left * (t108 + t38 * t109)),
            ],
        )
    }
    /// Exact Jacobian d(rhs)/dy, row-major 12x12.
    ///
    /// # Inputs
    /// - `y` = (`x`, `z`, `theta`, `xdot`, `zdot`, `thetadot`, `work`, `dissipation`, `u_edge_left`, `u_wall_right`, `u_edge_right`, `u_wall_left`)
    /// - `p` = (`m`, `J`, `r`, `l_c`, `D`, `rho_p`, `rho_h`, `mu`, `v_s`, `k_edge`, `k_wall`, `f1`, `f2`, `M`, `e_star`, `edge_sum`, `edge_ma`, `edge_mb`, `edge_dstar`, `wall_sum`, `wall_ma`, `wall_mb`, `wall_dstar`, `hc_alpha`, `g_star`, `delta_floor`, `tau_t`)
    ///
    /// # Outputs
    /// - `jac`: 12×12 matrix
    ///
    /// # Cost
    /// 571 add/sub, 1178 mul, 18 div, 12 sqrt, 10 transcendental, 44 branches; 470 `let`s.
    #[inline]
    pub fn jacobian<T: Real>(
        y: &SVector<T, 12>,
        p: &SVector<T, 27>,
    ) -> SMatrix<T, 12, 12> {
        let x = y[0];
        let z = y[1];
        let theta = y[2];
        let xdot = y[3];
        let zdot = y[4];
        let thetadot = y[5];
        let u_edge_left = y[8];
        let u_wall_right = y[9];
        let u_edge_right = y[10];
        let u_wall_left = y[11];
        let m = p[0];
        let j = p[1];
        let r = p[2];
        let l_c = p[3];
        let d = p[4];
        let rho_p = p[5];
        let rho_h = p[6];
        let mu = p[7];
        let k_edge = p[9];
        let k_wall = p[10];
        let f1 = p[11];
        let f2 = p[12];
        let m_2 = p[13];
        let e_star = p[14];
        let edge_sum = p[15];
        let edge_ma = p[16];
        let edge_mb = p[17];
        let wall_sum = p[19];
        let wall_ma = p[20];
        let wall_mb = p[21];
        let hc_alpha = p[23];
        let g_star = p[24];
        let delta_floor = p[25];
        let tau_t = p[26];
        let (sin_theta, cos_theta) = theta.sin_cos();
        let t0 = f1 * sin_theta + f2 * cos_theta;
        let t1 = f1 * cos_theta - f2 * sin_theta;
        let t2 = T::from_f64(0.5) * d;
        let t3 = -T::from_f64(0.5) * d;
        let t4 = -rho_h + t3 - x;
        let t5 = T::from_f64(0.5) * theta;
        let (t6, t7) = t5.sin_cos();
        let t8 = t6 * t6;
        let t9 = t4 * t8;
        let t10 = r * sin_theta;
        let t11 = r * cos_theta;
        let t12 = zdot * sin_theta;
        let t13 = t6 * t7;
        let t14 = T::from_f64(1.0) - T::from_f64(2.0) * t8;
        let t15 = edge_ma * edge_mb;
        let t16 = t15.sqrt();
        let t17 = T::from_f64(1.5) * k_edge / (e_star * edge_sum);
        let t18 = t17.cbrt();
        let t19 = T::from_f64(1.0) / t15.sqrt();
        let t20 = t17.powf(-T::from_f64(1.0 / 3.0));
        let t21 = u_edge_left * u_edge_left;
        let t22 = mu * k_edge;
        let t23 = u_edge_left.powi(4);
        let t24 = l_c - rho_p;
        let t25 = r - rho_p;
        let t26 = sin_theta * t24;
        let t27 = rho_p * sin_theta;
        let t28 = l_c - rho_p + t27;
        let t29 = r - T::from_f64(2.0) * rho_p * t8;
        let t30 = sin_theta * t29;
        let t31 = cos_theta * t29;
        let t32 = sin_theta * t28;
        let t33 = cos_theta * t24;
        let t34 = wall_ma * wall_mb;
        let t35 = t34.sqrt();
        let t36 = T::from_f64(1.5) * k_wall / (e_star * wall_sum);
        let t37 = t36.cbrt();
        let t38 = T::from_f64(1.0) / t34.sqrt();
        let t39 = t36.powf(-T::from_f64(1.0 / 3.0));
        let t40 = u_wall_right * u_wall_right;
        let t41 = mu * k_wall;
        let t42 = u_wall_right.powi(4);
        let t43 = rho_h + t2 - x;
        let t44 = xdot * t14;
        let t45 = u_edge_right * u_edge_right;
        let t46 = u_edge_right.powi(4);
        let t47 = u_wall_left * u_wall_left;
        let t48 = u_wall_left.powi(4);
        let t49 = T::from_f64(1.0) / m;
        let t50 = T::from_f64(1.0) / j;
        let t51 = sin_theta * sin_theta;
        let t52 = t14 * t14;
        let t53 = zdot * cos_theta;
        let t54 = t7 * t7;
        let t55 = -rho_h + z;
        let t56 = sin_theta * t55;
        let t57 = cos_theta * t55;
        let t58 = t32 + t31;
        let t59 = thetadot * t58;
        let t60 = -rho_p + r;
        let t61 = -l_c + rho_p + t27;
        let t62 = sin_theta * t61;
        let t63 = t62 + t31;
        let t64 = thetadot * t63;
        let slip_wall_left = zdot + t64;
        let abs_slip_wall_left = slip_wall_left.abs();
        let t65 = zdot + t64 - u_wall_left * abs_slip_wall_left;
        let delta_wall_right = r + t3 + x + t26 - T::from_f64(2.0) * t8 * t25;
        let pen_wall_right = delta_wall_right.max0();
        let t66 = pen_wall_right * pen_wall_right.sqrt();
        let t67 = delta_floor.hypot(delta_wall_right);
        let t68 = T::from_f64(1.0) / t67;
        let step_delta_wall_right = delta_wall_right.step();
        let t69 = t33 - T::from_f64(2.0) * t13 * t25;
        let delta_rate_wall_right = xdot + thetadot * t69;
        let t70 = hc_alpha * delta_rate_wall_right;
        let t71 = T::from_f64(1.0) + t70;
        let t72 = t71.max0();
        let delta_edge_left = r + t3 - x + t56 - T::from_f64(2.0) * t9;
        let t73 = sin_theta * t4 - t57;
        let t74 = cos_theta * t73;
        let t75 = t74 + t10;
        let t76 = xdot + thetadot * t75;
        let t77 = sin_theta * t76;
        let pen_edge_left = delta_edge_left.max0();
        let t78 = pen_edge_left * pen_edge_left.sqrt();
        let t79 = t57 - T::from_f64(2.0) * t13 * t4;
        let t80 = thetadot * t79;
        let t81 = g_star / mu;
        let t82 = t16 * t18;
        let t83 = t81 * (t82 / k_edge);
        let step_delta_edge_left = delta_edge_left.step();
        let t84 = sin_theta * t75;
        let slip_wall_right = zdot - t59;
        let abs_slip_wall_right = slip_wall_right.abs();
        let t85 = -zdot + t59 + u_wall_right * abs_slip_wall_right;
        let t86 = t35 * t37;
        let t87 = t81 * (t86 / k_wall);
        let t88 = -t57 + sin_theta * t43;
        let t89 = -cos_theta * t88;
        let t90 = t10 + t89;
        let t91 = xdot - thetadot * t90;
        let t92 = sin_theta * t88;
        let t93 = t11 + t92;
        let t94 = zdot - thetadot * t93;
        let t95 = sin_theta * t91;
        let t96 = cos_theta * t94;
        let slip_edge_right = t95 + t96;
        let t97 = t57 - T::from_f64(2.0) * t13 * t43;
        let t98 = thetadot * t97;
        let abs_slip_edge_right = slip_edge_right.abs();
        let t99 = t95 + t96 - u_edge_right * abs_slip_edge_right;
        let t100 = sin_theta * t90;
        let t101 = cos_theta * t93;
        let t102 = t100 + t101;
        let t103 = t8 * t60;
        let delta_wall_left = r + t3 - x - t26 - T::from_f64(2.0) * t103;
        let pen_wall_left = delta_wall_left.max0();
        let t104 = pen_wall_left * pen_wall_left.sqrt();
        let t105 = t33 + T::from_f64(2.0) * t13 * t60;
        let t106 = xdot + thetadot * t105;
        let step_delta_wall_left = delta_wall_left.step();
        let t107 = delta_rate_wall_right * t68 * delta_wall_right;
        let t108 = t2 - r + x - t56 + T::from_f64(2.0) * t9;
        let t109 = delta_floor.hypot(t108);
        let t110 = T::from_f64(1.0) / t109;
        let t111 = t22 * u_edge_left;
        let t112 = g_star * tau_t;
        let t113 = -t72 + T::from_f64(1.0);
        let t114 = (-t107).max0();
        let t115 = t40 * t114;
        let delta_edge_right = r + t3 + x - t56 + T::from_f64(2.0) * t8 * t43;
        let pen_edge_right = delta_edge_right.max0();
        let t116 = pen_edge_right * pen_edge_right.sqrt();
        let t117 = delta_floor.hypot(delta_edge_right);
        let t118 = T::from_f64(1.0) / t117;
        let t119 = t22 * u_edge_right;
        let step_delta_edge_right = delta_edge_right.step();
        let t120 = t2 - r + x + t26 + T::from_f64(2.0) * t103;
        let t121 = delta_floor.hypot(t120);
        let t122 = T::from_f64(1.0) / t121;
        let t123 = t106 * t122 * t120;
        let t124 = (-t123).max0();
        let t125 = t47 * t124;
        let t126 = t39 * (k_wall * k_wall) * t38;
        let t127 = t21 * t78;
        let t128 = t45 * t116;
        let t129 = t20 * (k_edge * k_edge) * t19;
        let t130 = mu * mu / g_star;
        let t131 = t41 * u_wall_right;
        let t132 = t41 * u_wall_left;
        let t133 = t127 - t128;
        let sign_slip_wall_left = slip_wall_left.sign();
        let sqrt_pen_wall_right = pen_wall_right.sqrt();
        let t134 = step_delta_wall_right * step_delta_wall_right;
        let t135 = T::from_f64(1.0) / (t67 * t67 * t67);
        let t136 = delta_wall_right * delta_wall_right;
        let t137 = -T::from_f64(1.5) * t134;
        let t138 = r + cos_theta * t4 + t56;
        let t139 = r - (t56 + cos_theta * t43);
        let t140 = -t54 + t8;
        let t141 = t60 * t140 + t26;
        let t142 = u_wall_left * sign_slip_wall_left;
        let t143 = t68 - t135 * t136;
        let t144 = xdot * t143;
        let t145 = zdot * t51;
        let t146 = t8 - t54;
        let t147 = -(t4 * t146) + t56;
        let t148 = -(t25 * t146) + t26;
        let t149 = -(t43 * t140) + t56;
        let t150 = -thetadot * t149;
        let t151 = -thetadot * (-(t4 * t140) + t56);
        let t152 = T::from_f64(2.0) * t13 * xdot;
        let t153 = t71.step();
        let t154 = t69 * t69;
        let t155 = sin_theta * t73;
        let t156 = -t155 + t11;
        let t157 = zdot + thetadot * t156;
        let t158 = cos_theta * t157;
        let slip_edge_left = t77 + t158;
        let delta_rate_edge_left = -t44 + t12 + t80;
        let t159 = hc_alpha * delta_rate_edge_left;
        let t160 = T::from_f64(1.0) + t159;
        let t161 = t160.max0();
        let abs_slip_edge_left = slip_edge_left.abs();
        let t162 = t77 + t158 - u_edge_left * abs_slip_edge_left;
        let t163 = cos_theta * t156;
        let t164 = t84 + t163;
        let t165 = -t44 + t12 + t98;
        let t166 = hc_alpha * t165;
        let t167 = T::from_f64(1.0) - t166;
        let t168 = t167.max0();
        let t169 = hc_alpha * t106;
        let t170 = T::from_f64(1.0) - t169;
        let t171 = t170.max0();
        let t172 = -t161 + T::from_f64(1.0);
        let t173 = t78 * t172;
        let t174 = t82 * t112;
        let t175 = t174 * t110;
        let t176 = t175 * t162;
        let t177 = t78 * (t111 + T::from_f64(8.0) * t176);
        let t178 = t108 * t110;
        let t179 = t178 * (t12 - t44 + t80);
        let t180 = t179.max0();
        let t181 = t21 * t180;
        let t182 = -t168 + T::from_f64(1.0);
        let t183 = t174 * t118;
        let t184 = t183 * t99;
        let t185 = t116 * (t119 + T::from_f64(8.0) * t184);
        let t186 = delta_edge_right * t118;
        let t187 = t186 * (t12 - t44 + t98);
        let t188 = t187.max0();
        let t189 = t45 * t188;
        let t190 = -t171 + T::from_f64(1.0);
        let t191 = t112 * t86;
        let t192 = t191 * t68;
        let t193 = t192 * t85;
        let t194 = t191 * t122;
        let t195 = t194 * t65;
        let t196 = t78 * (step_delta_edge_left - t172);
        let t197 = t116 * (-step_delta_edge_right + t182);
        let t198 = t196 + t197;
        let t199 = t129 * t130;
        let sqrt_pen_edge_left = pen_edge_left.sqrt();
        let t200 = t160.step();
        let t201 = t167.step();
        let sqrt_pen_wall_left = pen_wall_left.sqrt();
        let t202 = step_delta_wall_left * step_delta_wall_left;
        let sign_slip_edge_left = slip_edge_left.sign();
        let sign_slip_edge_right = slip_edge_right.sign();
        let t203 = t170.step();
        let t204 = u_edge_left * sign_slip_edge_left;
        let t205 = t84 + t163 - t204 * t164;
        let t206 = u_edge_right * sign_slip_edge_right;
        let t207 = t100 + t101 - t206 * t102;
        let t208 = t49 * t104;
        let t209 = t130 * t126;
        let sign_slip_wall_right = slip_wall_right.sign();
        let t210 = u_wall_right * sign_slip_wall_right;
        let t211 = T::from_f64(1.0) - t210;
        let t212 = T::from_f64(1.0) - t142;
        let t213 = t32 + t31 - t210 * t58;
        let t214 = t62 + t31 - t142 * t63;
        let t215 = t79 * t79;
        let t216 = t97 * t97;
        let t217 = t105 * t105;
        let t218 = t49 * t66;
        let t219 = -(T::from_f64(1.5) * t161) + T::from_f64(1.5);
        let t220 = step_delta_edge_left * sqrt_pen_edge_left;
        let t221 = t220 * t219;
        let t222 = thetadot * hc_alpha;
        let t223 = t13 * t222;
        let t224 = t78 * t200;
        let t225 = t221 * t14 + T::from_f64(2.0) * t223 * t224;
        let t226 = T::from_f64(1.0) / (t109 * t109 * t109);
        let t227 = t108 * t226;
        let t228 = t227 * t78;
        let t229 = t220 * (T::from_f64(1.5) * t111 + T::from_f64(12.0) * t176)
            + T::from_f64(8.0) * t228 * t174 * t162;
        let sqrt_pen_edge_right = pen_edge_right.sqrt();
        let t230 = -(T::from_f64(1.5) * t168) + T::from_f64(1.5);
        let t231 = step_delta_edge_right * sqrt_pen_edge_right;
        let t232 = t231 * t230;
        let t233 = t116 * t201;
        let t234 = t232 * t14 + T::from_f64(2.0) * t223 * t233;
        let t235 = T::from_f64(1.0) / (t117 * t117 * t117);
        let t236 = -T::from_f64(1.5) * t72;
        let t237 = sqrt_pen_wall_right
            * (step_delta_wall_right * (T::from_f64(1.5) + t236) + t137);
        let t238 = -(T::from_f64(1.5) * t171) + T::from_f64(1.5);
        let t239 = -T::from_f64(1.5) * t202;
        let t240 = sqrt_pen_wall_left * (step_delta_wall_left * t238 + t239);
        let t241 = t222 * cos_theta;
        let t242 = sqrt_pen_edge_left * (step_delta_edge_left * step_delta_edge_left);
        let t243 = sqrt_pen_edge_right * (step_delta_edge_right * step_delta_edge_right);
        let t244 = t242 + t243;
        let t245 = t220 * t21;
        let t246 = t231 * t45;
        let t247 = t245 + t246;
        let t248 = t199 * t247;
        let t249 = sin_theta * t138 + t74;
        let t250 = cos_theta * (-t76 + thetadot * t249);
        let t251 = cos_theta * t139 + t92;
        let t252 = sin_theta * (thetadot * t251 + t94);
        let t253 = t242 * t79 + t243 * t97;
        let t254 = t104 * t203;
        let t255 = t254 * t141;
        let t256 = t220 * t79;
        let t257 = t231 * t97;
        let t258 = t256 * t21 + t257 * t45;
        let t259 = t224 + t233;
        let t260 = t153 * t66;
        let t261 = hc_alpha * t259;
        let t262 = k_edge * t14;
        let t263 = t224 * t79 + t233 * t97;
        let t264 = t22 - T::from_f64(8.0) * t175 * abs_slip_edge_left;
        let t265 = t199 * u_edge_left;
        let t266 = t49 * t78;
        let t267 = t22 - T::from_f64(8.0) * t183 * abs_slip_edge_right;
        let t268 = t199 * u_edge_right;
        let t269 = t49 * t116;
        let t270 = T::from_f64(1.0) / (t121 * t121 * t121);
        let t271 = t120 * t270;
        let t272 = t271 * t104;
        let t273 = step_delta_wall_left * sqrt_pen_wall_left;
        let t274 = t65 * (T::from_f64(12.0) * t273 * t122 + T::from_f64(8.0) * t272);
        let t275 = rho_p * (sin_theta - T::from_f64(2.0) * t13);
        let t276 = t274 * t105;
        let t277 = t66 * t68;
        let t278 = t277 * t211;
        let t279 = t104 * t122;
        let t280 = t279 * t212;
        let t281 = t78 * t110;
        let t282 = t116 * t118;
        let t283 = t281 * t205 - t282 * t207;
        let t284 = t277 * t213;
        let t285 = t279 * t214;
        let t286 = sin_theta * t263 * hc_alpha * k_edge;
        let t287 = t41 - T::from_f64(8.0) * t192 * abs_slip_wall_right;
        let t288 = t41 - T::from_f64(8.0) * t194 * abs_slip_wall_left;
        let t289 = t273 * (T::from_f64(1.5) * t132 + T::from_f64(12.0) * t195)
            + T::from_f64(8.0) * t272 * t191 * t65;
        let t290 = t236 + T::from_f64(1.5);
        let t291 = step_delta_wall_right * sqrt_pen_wall_right;
        let t292 = t291 * t69;
        let t293 = t273 * t105;
        let t294 = t293 * t238 + t255 * t222;
        let t295 = t281 * t164;
        let t296 = t282 * t102;
        let t297 = u_wall_right * t69;
        let t298 = u_wall_left * t105;
        let t299 = t13 * thetadot;
        let t300 = t299 * t178;
        let t301 = t226 * (t108 * t108);
        let t302 = t110 - t301;
        let t303 = t80 * t302;
        let t304 = t179.step();
        let t305 = t69 * t143 * thetadot;
        let t306 = t144 + t305;
        let t307 = (-t107).step();
        let t308 = T::from_f64(2.0) * t186 * t299;
        let t309 = t235 * (delta_edge_right * delta_edge_right);
        let t310 = t118 - t309;
        let t311 = t98 * t310;
        let t312 = t187.step();
        let t313 = t270 * (t120 * t120);
        let t314 = t122 - t313;
        let t315 = xdot * t314;
        let t316 = t105 * t314 * thetadot;
        let t317 = t315 + t316;
        let t318 = (-t123).step();
        let t319 = slip_edge_left * t162;
        let t320 = delta_edge_right * t235;
        let t321 = t320 * t116;
        let t322 = slip_edge_right * t99;
        let t323 = t174
            * (t319 * (T::from_f64(12.0) * t220 * t110 + T::from_f64(8.0) * t228)
                + t322 * (-(T::from_f64(12.0) * t231 * t118) + T::from_f64(8.0) * t321))
            + T::from_f64(1.5) * t22
                * (t245 * abs_slip_edge_left - t246 * abs_slip_edge_right)
            + T::from_f64(0.1875) * t199 * (t220 * t180 * t23 - t231 * t188 * t46);
        let t324 = t116 * t182;
        let t325 = t173 - t324;
        let t326 = sin_theta * (t44 - t80);
        let t327 = t110 * (t326 - t145 + thetadot * cos_theta * t108);
        let t328 = sin_theta * (t44 - t98);
        let t329 = t118 * (t328 - t145 + thetadot * cos_theta * delta_edge_right);
        let t330 = -t12 + t44;
        let t331 = t79 * t330;
        let t332 = thetadot * t215;
        let t333 = xdot * t69;
        let t334 = t97 * t330;
        let t335 = thetadot * t216;
        let t336 = xdot * t105;
        let t337 = t313 * (t336 + thetadot * t217);
        let t338 = delta_wall_right * t135;
        let t339 = t338 * t66;
        let t340 = t85 * (-(T::from_f64(12.0) * t291 * t68) + T::from_f64(8.0) * t339);
        let t341 = t340 * t69;
        let t342 = -t172 + t159 * t200;
        let t343 = t182 + t166 * t201;
        let t344 = t23 * t304;
        let t345 = t344 * (t281 * t108);
        let t346 = t46 * t312;
        let t347 = t346 * (t282 * delta_edge_right);
        let t348 = k_edge * (t78 * t342 + t116 * t343)
            + T::from_f64(0.125) * t199 * (t345 + t347);
        let t349 = t42 * delta_wall_right * (t277 * t307);
        let t350 = t48 * t120 * (t279 * t318);
        let t351 = -t85 + slip_wall_right * t211;
        let t352 = t65 + slip_wall_left * t212;
        let t353 = t127 * sign_slip_edge_left + t128 * sign_slip_edge_right;
        let t354 = t40 * sign_slip_wall_right;
        let t355 = t47 * sign_slip_wall_left;
        let t356 = t70 * t153;
        let t357 = t169 * t203;
        let t358 = t52 * t302 * xdot;
        let t359 = t44 - t12;
        let t360 = t21 * t304;
        let t361 = u_edge_left * t110;
        let t362 = t361 * (t108 * (T::from_f64(1.0) - t360));
        let t363 = t338 * (T::from_f64(8.0) * t87 * t85 + u_wall_right * (t107 + t115));
        let t364 = t40 * t307;
        let t365 = t68 * (T::from_f64(1.0) - t364) * delta_wall_right;
        let t366 = u_wall_right * t68;
        let t367 = t87 * t211;
        let t368 = t45 * t312;
        let t369 = u_edge_right * t118;
        let t370 = t369 * (delta_edge_right * (T::from_f64(1.0) - t368));
        let t371 = t271
            * (-(T::from_f64(8.0) * t87 * t65) + u_wall_left * (t123 + t125));
        let t372 = t47 * t318;
        let t373 = t122 * (T::from_f64(1.0) - t372) * t120;
        let t374 = u_wall_left * t122;
        let t375 = t87 * t212;
        let t376 = -(t231 * (T::from_f64(1.5) * t119 + T::from_f64(12.0) * t184))
            + T::from_f64(8.0) * t321 * t174 * t99;
        let t377 = t291 * t40;
        let t378 = t273 * t47;
        let t379 = t229 + t376;
        let t380 = sin_theta * t379;
        let t381 = -(t221 * sin_theta) + t241 * t224;
        let t382 = -(t232 * sin_theta) + t241 * t233;
        let t383 = t152 + t53 - thetadot * t147;
        let t384 = -(t256 * t219) + t224 * hc_alpha * t383;
        let t385 = -(cos_theta * t138) + t155;
        let t386 = sin_theta * (thetadot * t385 + t157);
        let t387 = t250 + t386;
        let t388 = t250 + t386 - t204 * t387;
        let t389 = -(t79 * t229) + T::from_f64(8.0) * t281 * t174 * t388;
        let t390 = t152 + t53 + t150;
        let t391 = -(t257 * t230) + t233 * hc_alpha * t390;
        let t392 = sin_theta * t139 + t89;
        let t393 = cos_theta * (t91 + thetadot * t392);
        let t394 = -t393 + t252;
        let t395 = t393 - t252 + t206 * t394;
        let t396 = t97 * t376 + T::from_f64(8.0) * t282 * t174 * t395;
        let t397 = t13 * (-(T::from_f64(2.0) * t196) - T::from_f64(2.0) * t197);
        let t398 = t260 * t148;
        let t399 = t130
            * (t129
                * (T::from_f64(0.046875) * t258 * t14 - T::from_f64(0.0625) * t13 * t133)
                - T::from_f64(0.046875) * t126 * (t292 * t40 + t293 * t47));
        let t400 = T::from_f64(1.0) - t204;
        let t401 = T::from_f64(1.0) - t206;
        let t402 = t281 * t400 + t282 * t401;
        let t403 = t174 * t402;
        let t404 = sin_theta * t49
            * (t262 * t261 - T::from_f64(8.0) * (t403 * cos_theta));
        let t405 = hc_alpha * (-(t262 * t263) + k_wall * (t260 * t69 + t254 * t105));
        let t406 = -(cos_theta * (t275 + t28)) + t30;
        let t407 = -(cos_theta * (t275 + t61)) + t30;
        let t408 = t291 * (T::from_f64(1.5) * t131 - T::from_f64(12.0) * t193)
            + T::from_f64(8.0) * t339 * t191 * t85;
        let t409 = t164 * t229 - t102 * t376;
        let t410 = t292 * t290 + t398 * t222;
        let t411 = thetadot * t406;
        let t412 = thetadot * t407;
        let t413 = t295 * t400 - t296 * t401;
        let t414 = t14 * (t12 * t302 + t303) - t358 + T::from_f64(2.0) * t300;
        let t415 = -(t52 * t310) * xdot;
        let t416 = t14 * (t12 * t310 + t311) + t415 + t308;
        let t417 = t344 * t78;
        let t418 = t346 * t116;
        let t419 = t301 * (-t326 + t145);
        let t420 = t327 + t419;
        let t421 = t309 * (-t328 + t145);
        let t422 = t329 + t421;
        let t423 = t301 * (-t331 + t332);
        let t424 = t110 * (t108 * (t53 + t152 + t151) + t331 - t332) + t423;
        let t425 = t68 * (thetadot * (t154 - delta_wall_right * t148) + t333);
        let t426 = t136 * (t333 + thetadot * t154) * t135;
        let t427 = t425 - t426;
        let t428 = t309 * (-t334 + t335);
        let t429 = t118 * (delta_edge_right * (t53 + t152 + t150) + t334 - t335) + t428;
        let t430 = t122 * (-(thetadot * (-t217 + t120 * (t60 * t146 + t26))) + t336);
        let t431 = t430 - t337;
        let t432 = t281 * (t162 + slip_edge_left * t400);
        let t433 = t282 * (t99 + slip_edge_right * t401);
        let t434 = t227
            * (-(T::from_f64(8.0) * t83 * t162)
                + u_edge_left * (-(t178 * delta_rate_edge_left) + t181));
        let t435 = t83 * sin_theta;
        let t436 = t83 * cos_theta;
        let t437 = t320
            * (-(T::from_f64(8.0) * t83 * t99) + u_edge_right * (-(t186 * t165) + t189));
        SMatrix::<
            T,
            12,
            12,
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
                t49
                    * (k_wall * (t237 + t240)
                        + k_edge
                            * (-(T::from_f64(1.5) * t244 * t52) + t14 * (t225 + t234))
                        + t130
                            * (-(T::from_f64(0.046875) * (t52 * t247) * t129)
                                - T::from_f64(0.046875) * t126 * (t377 + t378))
                        + t380 * t14),
                t49
                    * (t14
                        * (k_edge * (T::from_f64(1.5) * t244 * sin_theta + t381 + t382)
                            + T::from_f64(0.046875) * t248 * sin_theta) - t51 * t379),
                t49
                    * (k_edge * (t14 * (T::from_f64(1.5) * t253 + t384 + t391) + t397)
                        + k_wall * (t237 * t69 + t240 * t105 + t222 * (t398 + t255))
                        + t399 - cos_theta * (-f1 + t177 + t185)
                        - sin_theta * (f2 - t389 + t396)),
                -t49
                    * (hc_alpha * (t52 * t259 * k_edge + k_wall * (t260 + t254))
                        + T::from_f64(8.0) * t403 * t51),
                t404,
                -t49 * (t405 + T::from_f64(8.0) * t174 * t283 * sin_theta),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t266 * (T::from_f64(0.0625) * t265 * t14 - sin_theta * t264),
                -T::from_f64(0.0625) * t218 * t209 * u_wall_right,
                -t269 * (T::from_f64(0.0625) * t268 * t14 + sin_theta * t267),
                T::from_f64(0.0625) * t208 * t209 * u_wall_left,
                t49
                    * (-(sin_theta
                        * (k_edge * (-(T::from_f64(1.5) * t244 * t14) + t225 + t234)
                            - T::from_f64(0.046875) * t248 * t14)) - t191 * (t340 - t274)
                        + t14 * t379 * cos_theta
                        - T::from_f64(1.5) * t41
                            * (t291 * u_wall_right - t273 * u_wall_left)),
                -t49
                    * (k_edge
                        * (T::from_f64(1.5) * t244 * t51 + sin_theta * (t381 + t382))
                        + T::from_f64(0.046875) * (t51 * t247) * t199
                        + t380 * cos_theta),
                t49
                    * (sin_theta
                        * (k_edge * (-(T::from_f64(1.5) * t253) - t384 - t391)
                            - T::from_f64(0.046875) * t199 * t258 - f1 + t177 + t185)
                        - cos_theta
                            * (k_edge * t198 + T::from_f64(0.03125) * t199 * t133 + f2
                                - t389 + t396)
                        + t191
                            * (-t341
                                + T::from_f64(8.0) * (-(t278 * t406) + t280 * t407)
                                    * thetadot + t276)
                        - T::from_f64(1.5) * t41
                            * (t292 * u_wall_right - t293 * u_wall_left)),
                t404,
                -t49
                    * (t112
                        * (T::from_f64(8.0) * (t82 * t402) * (cos_theta * cos_theta)
                            + T::from_f64(8.0) * t86 * (t278 + t280))
                        + t261 * t51 * k_edge),
                -t49
                    * (t112
                        * (T::from_f64(8.0) * (t82 * t283) * cos_theta
                            + T::from_f64(8.0) * t86 * (-t284 + t285)) + t286),
                T::from_f64(0.0),
                T::from_f64(0.0),
                -t266 * (T::from_f64(0.0625) * t265 * sin_theta + cos_theta * t264),
                -t218 * t287,
                t269 * (T::from_f64(0.0625) * t268 * sin_theta - cos_theta * t267),
                -t208 * t288,
                t50
                    * (-(k_edge
                        * (-t397 - T::from_f64(1.5) * t253 * t14 + t79 * t225
                            + t97 * t234)) + t399
                        + k_wall
                            * (sqrt_pen_wall_right
                                * (t137 + t290 * step_delta_wall_right) * t69
                                + sqrt_pen_wall_left * (t239 + t238 * step_delta_wall_left)
                                    * t105) + t14 * t409 + t58 * t408 + t63 * t289),
                -t50
                    * (k_edge
                        * (cos_theta * t198 + T::from_f64(1.5) * t253 * sin_theta
                            + t79 * t381 + t97 * t382)
                        - t199
                            * (-(T::from_f64(0.03125) * t133 * cos_theta)
                                - T::from_f64(0.046875) * t258 * sin_theta)
                        + sin_theta * t409),
                t50
                    * (-(k_edge
                        * (-(t196 * t147) - t197 * t149
                            + T::from_f64(1.5) * (t242 * t215 + t243 * t216) + t79 * t384
                            + t97 * t391))
                        - t130
                            * (-(t129
                                * (t21
                                    * (-(T::from_f64(0.046875) * t220 * t215)
                                        + T::from_f64(0.03125) * t78 * t147)
                                    - t45
                                        * (T::from_f64(0.046875) * t231 * t216
                                            + T::from_f64(0.03125) * t116 * t149)))
                                - t126
                                    * (t40
                                        * (-(T::from_f64(0.046875) * t291 * t154)
                                            + T::from_f64(0.03125) * t66 * t148)
                                        - t47
                                            * (T::from_f64(0.046875) * t273 * t217
                                                + T::from_f64(0.03125) * t104 * t141)))
                        - k_wall
                            * (-((step_delta_wall_right - t113) * t148 * t66)
                                + (step_delta_wall_left - t190) * t141 * t104
                                + T::from_f64(1.5)
                                    * (sqrt_pen_wall_right * t134 * t154
                                        + sqrt_pen_wall_left * t202 * t217) - t69 * t410
                                - t105 * t294) + t164 * t389
                        + t177
                            * (-(cos_theta * (t75 - t249)) + sin_theta * (t385 + t156))
                        - t66 * (t131 - T::from_f64(8.0) * t193) * t406
                        + t58 * (t69 * t408 + T::from_f64(8.0) * t411 * t278 * t191)
                        + t102 * t396
                        - t185
                            * (-(cos_theta * (t90 - t392)) + sin_theta * (-t251 + t93))
                        + t104 * (t132 + T::from_f64(8.0) * t195) * t407
                        + t63 * (t105 * t289 + T::from_f64(8.0) * t412 * t280 * t191)),
                -t50 * (t405 + T::from_f64(8.0) * (sin_theta * t413) * t174),
                -t50
                    * (t112
                        * (T::from_f64(8.0) * (cos_theta * t413) * t82
                            - T::from_f64(8.0) * t86 * (t278 * t58 - t280 * t63))
                        + t286),
                -t50
                    * (hc_alpha
                        * (k_edge * (t224 * t215 + t233 * t216)
                            + k_wall * (t260 * t154 + t254 * t217))
                        + t112
                            * (T::from_f64(8.0) * t82 * (t295 * t205 + t296 * t207)
                                + T::from_f64(8.0) * t86 * (t284 * t58 + t285 * t63))),
                T::from_f64(0.0),
                T::from_f64(0.0),
                -(t78 * (T::from_f64(0.0625) * t265 * t79 + t164 * t264)) * t50,
                -(t66 * (T::from_f64(0.0625) * t297 * t209 - t58 * t287)) * t50,
                t116 * (T::from_f64(0.0625) * t268 * t97 + t102 * t267) * t50,
                t104 * (T::from_f64(0.0625) * t298 * t209 - t63 * t288) * t50,
                T::from_f64(0.0),
                T::from_f64(0.0),
                xdot * t1 - zdot * t0,
                t0,
                t1,
                m_2,
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                -(t14 * t323)
                    - t130
                        * (t126
                            * (t42
                                * (-(T::from_f64(0.1875) * t291 * t114)
                                    + T::from_f64(0.125) * t66 * t306 * t307)
                                + t48
                                    * (T::from_f64(0.1875) * t273 * t124
                                        + T::from_f64(0.125) * t104 * t317 * t318))
                            - T::from_f64(0.125) * t129 * (t417 * t414 + t418 * t416))
                    + k_edge
                        * (-(T::from_f64(2.0) * t299 * t325)
                            + delta_rate_edge_left * t225 + t165 * t234)
                    - k_wall
                        * (-(T::from_f64(1.5)
                            * (t377 * abs_slip_wall_right - t378 * abs_slip_wall_left)
                            * mu) + t291 * t290 * delta_rate_wall_right
                            + t273 * t238 * t106)
                    - t191 * (-(t340 * slip_wall_right) + t274 * slip_wall_left),
                sin_theta * t323
                    + k_edge
                        * (-(cos_theta * t325 * thetadot) + delta_rate_edge_left * t381
                            + t165 * t382)
                    + T::from_f64(0.125) * t199 * (t417 * t420 + t418 * t422),
                t112
                    * (t82
                        * (t78
                            * (-(T::from_f64(8.0) * (t162 * t387 + slip_edge_left * t388)
                                * t110) + T::from_f64(8.0) * t319 * t227 * t79)
                            + t116
                                * (T::from_f64(8.0)
                                    * (-(t99 * t394) + slip_edge_right * t395) * t118
                                    + T::from_f64(8.0) * t322 * t320 * t97)
                            + T::from_f64(12.0)
                                * (t319 * t256 * t110 - t322 * t257 * t118))
                        + t86
                            * (thetadot
                                * (T::from_f64(8.0) * (t351 * t406) * t277
                                    - T::from_f64(8.0) * (t352 * t407) * t279)
                                + t341 * slip_wall_right - t276 * slip_wall_left))
                    - mu
                        * (k_edge
                            * (t21
                                * (-(T::from_f64(1.5) * t256 * abs_slip_edge_left)
                                    + t78 * t387 * sign_slip_edge_left)
                                + t45
                                    * (T::from_f64(1.5) * t257 * abs_slip_edge_right
                                        + t116 * t394 * sign_slip_edge_right))
                            - k_wall
                                * (t40
                                    * (T::from_f64(1.5) * t292 * abs_slip_wall_right
                                        + t411 * t66 * sign_slip_wall_right)
                                    - t47
                                        * (T::from_f64(1.5) * t293 * abs_slip_wall_left
                                            + t412 * t104 * sign_slip_wall_left)))
                    + t130
                        * (t129
                            * (t23
                                * (T::from_f64(0.1875) * t256 * t180
                                    + T::from_f64(0.125) * t78 * t304 * t424)
                                - t46
                                    * (T::from_f64(0.1875) * t257 * t188
                                        - T::from_f64(0.125) * t116 * t312 * t429))
                            + t126
                                * (t42
                                    * (T::from_f64(0.1875) * t292 * t114
                                        - T::from_f64(0.125) * t66 * t307 * t427)
                                    - t48
                                        * (T::from_f64(0.1875) * t293 * t124
                                            + T::from_f64(0.125) * t104 * t318 * t431)))
                    + k_edge
                        * (-(t173 * t383) + delta_rate_edge_left * t384 + t324 * t390
                            + t165 * t391)
                    - k_wall
                        * (thetadot * (-(t66 * t113 * t148) + t104 * t190 * t141)
                            + delta_rate_wall_right * t410 + t106 * t294),
                -(t14 * t348)
                    + k_wall
                        * (t66 * (t72 - T::from_f64(1.0) + t356)
                            + t104 * (T::from_f64(1.0) - t171 + t357))
                    - sin_theta
                        * (t174 * (-(T::from_f64(8.0) * t432) - T::from_f64(8.0) * t433)
                            - t22 * t353) - T::from_f64(0.125) * t209 * (t349 + t350),
                t112
                    * (t86
                        * (T::from_f64(8.0) * t277 * t351
                            + T::from_f64(8.0) * t279 * t352)
                        + t82 * (T::from_f64(8.0) * t432 + T::from_f64(8.0) * t433)
                            * cos_theta) + sin_theta * t348
                    + mu
                        * (cos_theta * t353 * k_edge
                            + k_wall * (t354 * t66 + t355 * t104)),
                t112
                    * (t82
                        * (T::from_f64(8.0) * t281
                            * (t162 * t164 + slip_edge_left * t205)
                            - T::from_f64(8.0) * t282
                                * (t99 * t102 + slip_edge_right * t207))
                        + t86
                            * (T::from_f64(8.0) * t277
                                * (t58 * t85 - slip_wall_right * t213)
                                + T::from_f64(8.0) * t279
                                    * (t63 * t65 + slip_wall_left * t214)))
                    + k_edge
                        * (t78 * (t79 * t342 + mu * t21 * t164 * sign_slip_edge_left)
                            - t116
                                * (-(t97 * t343) + mu * t45 * t102 * sign_slip_edge_right))
                    + k_wall
                        * (-(t66 * (-(t69 * (-t113 + t356)) + t354 * mu * t58))
                            + t104 * (t105 * (t190 + t357) + t355 * mu * t63))
                    + t130
                        * (T::from_f64(0.125) * t129 * (t345 * t79 + t347 * t97)
                            - T::from_f64(0.125) * t126 * (t349 * t69 + t350 * t105)),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t78
                    * (abs_slip_edge_left
                        * (T::from_f64(2.0) * t111
                            - T::from_f64(8.0) * t175 * slip_edge_left)
                        + T::from_f64(0.5) * t199 * t180
                            * (u_edge_left * u_edge_left * u_edge_left)),
                t66
                    * (abs_slip_wall_right
                        * (T::from_f64(2.0) * t131
                            - T::from_f64(8.0) * t192 * slip_wall_right)
                        + T::from_f64(0.5) * t209 * t114
                            * (u_wall_right * u_wall_right * u_wall_right)),
                t116
                    * (abs_slip_edge_right
                        * (T::from_f64(2.0) * t119
                            - T::from_f64(8.0) * t183 * slip_edge_right)
                        + T::from_f64(0.5) * t199 * t188
                            * (u_edge_right * u_edge_right * u_edge_right)),
                t104
                    * (abs_slip_wall_left
                        * (T::from_f64(2.0) * t132
                            - T::from_f64(8.0) * t194 * slip_wall_left)
                        + T::from_f64(0.5) * t209 * t124
                            * (u_wall_left * u_wall_left * u_wall_left)),
                t434 * t14
                    - t361
                        * (t14 * (-(t12 * (-t301 + t110)) - t303) + t358
                            - T::from_f64(2.0) * t300 + t360 * t414),
                -(t434 * sin_theta) + t361 * (t327 + t419 - t360 * t420),
                t110
                    * (-(T::from_f64(8.0) * t83 * t388)
                        + u_edge_left
                            * (t110 * (t108 * (t151 + t152 + t53) + t79 * t359 - t332)
                                + t423 - t360 * t424)) - t434 * t79,
                -t110 * (-(T::from_f64(8.0) * t435 * t400) + t362 * t14),
                t110 * (T::from_f64(8.0) * t436 * t400 + t362 * sin_theta),
                t110 * (T::from_f64(8.0) * t83 * t205 + t362 * t79),
                T::from_f64(0.0),
                T::from_f64(0.0),
                -t110
                    * (-t179 + T::from_f64(8.0) * t83 * abs_slip_edge_left
                        + T::from_f64(3.0) * t181),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t363 + t366 * (-t144 - t305 + t364 * t306),
                T::from_f64(0.0),
                t363 * t69
                    - t68
                        * (-(T::from_f64(8.0) * t367 * t411)
                            + u_wall_right * (t425 - t426 - t364 * t427)),
                -t366 * t365,
                T::from_f64(8.0) * t367 * t68,
                -t68 * (T::from_f64(8.0) * t87 * t213 + t297 * t365),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                -t68
                    * (t107 + T::from_f64(8.0) * t87 * abs_slip_wall_right
                        + T::from_f64(3.0) * t115),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t437 * t14
                    + t369
                        * (t14 * (t12 * (-t309 + t118) + t311) + t415 + t308
                            - t368 * t416),
                -(t437 * sin_theta) + t369 * (t329 + t421 - t368 * t422),
                t118
                    * (T::from_f64(8.0) * t83 * t395
                        + u_edge_right
                            * (t118
                                * (delta_edge_right * (t150 + t152 + t53) + t97 * t359
                                    - t335) + t428 - t368 * t429)) - t437 * t97,
                -t118 * (-(T::from_f64(8.0) * t435 * t401) + t370 * t14),
                t118 * (T::from_f64(8.0) * t436 * t401 + t370 * sin_theta),
                t118 * (-(T::from_f64(8.0) * t83 * t207) + t370 * t97),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                -t118
                    * (-t187 + T::from_f64(8.0) * t83 * abs_slip_edge_right
                        + T::from_f64(3.0) * t189),
                T::from_f64(0.0),
                t371 + t374 * (-t315 - t316 + t372 * t317),
                T::from_f64(0.0),
                t371 * t105
                    + t122
                        * (-(T::from_f64(8.0) * t375 * t412)
                            + u_wall_left * (-t430 + t337 + t372 * t431)),
                -t374 * t373,
                T::from_f64(8.0) * t375 * t122,
                -t122 * (-(T::from_f64(8.0) * t87 * t214) + t298 * t373),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                -t122
                    * (t123 + T::from_f64(8.0) * t87 * abs_slip_wall_left
                        + T::from_f64(3.0) * t125),
            ],
        )
    }
    /// Per contact (edge_left, wall_right, edge_right, wall_left): normal force f (N), friction force along the tangent (N), penetration delta (m), sliding velocity (m/s), contact ellipse a, b (m) and maximum pressure p0 (Pa) ((9)-(11)).
    ///
    /// # Inputs
    /// - `y` = (`x`, `z`, `theta`, `xdot`, `zdot`, `thetadot`, `work`, `dissipation`, `u_edge_left`, `u_wall_right`, `u_edge_right`, `u_wall_left`)
    /// - `p` = (`m`, `J`, `r`, `l_c`, `D`, `rho_p`, `rho_h`, `mu`, `v_s`, `k_edge`, `k_wall`, `f1`, `f2`, `M`, `e_star`, `edge_sum`, `edge_ma`, `edge_mb`, `edge_dstar`, `wall_sum`, `wall_ma`, `wall_mb`, `wall_dstar`, `hc_alpha`, `g_star`, `delta_floor`, `tau_t`)
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
    /// 80 add/sub, 135 mul, 10 div, 6 sqrt, 12 transcendental, 8 branches; 86 `let`s.
    #[inline]
    pub fn contacts<T: Real>(
        y: &SVector<T, 12>,
        p: &SVector<T, 27>,
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
        let u_edge_left = y[8];
        let u_wall_right = y[9];
        let u_edge_right = y[10];
        let u_wall_left = y[11];
        let r = p[2];
        let l_c = p[3];
        let d = p[4];
        let rho_p = p[5];
        let rho_h = p[6];
        let mu = p[7];
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
        let g_star = p[24];
        let delta_floor = p[25];
        let tau_t = p[26];
        let (sin_theta, cos_theta) = theta.sin_cos();
        let t0 = T::from_f64(0.5) * d;
        let t1 = -T::from_f64(0.5) * d;
        let t2 = -rho_h + t1 - x;
        let t3 = T::from_f64(0.5) * theta;
        let (t4, t5) = t3.sin_cos();
        let t6 = t4 * t4;
        let t7 = t2 * t6;
        let t8 = r * sin_theta;
        let t9 = r * cos_theta;
        let t10 = zdot * sin_theta;
        let t11 = t4 * t5;
        let t12 = (edge_ma * edge_mb).sqrt();
        let t13 = mu * k_edge;
        let t14 = l_c - rho_p;
        let t15 = r - rho_p;
        let t16 = sin_theta * t14;
        let t17 = rho_p * sin_theta;
        let t18 = cos_theta * (r - T::from_f64(2.0) * rho_p * t6);
        let t19 = cos_theta * t14;
        let t20 = (wall_ma * wall_mb).sqrt();
        let t21 = mu * k_wall;
        let t22 = rho_h + t0 - x;
        let t23 = -rho_h + z;
        let t24 = sin_theta * t23;
        let t25 = -xdot * (T::from_f64(1.0) - T::from_f64(2.0) * t6);
        let t26 = cos_theta * t23;
        let t27 = thetadot * (sin_theta * (l_c - rho_p + t17) + t18);
        let t28 = -rho_p + r;
        let t29 = thetadot * (sin_theta * (-l_c + rho_p + t17) + t18);
        let slip_wall_left = zdot + t29;
        let delta_wall_right = r + t1 + x + t16 - T::from_f64(2.0) * t6 * t15;
        let pen_wall_right = delta_wall_right.max0();
        let t30 = pen_wall_right * pen_wall_right.sqrt();
        let t31 = delta_floor.hypot(delta_wall_right);
        let delta_rate_wall_right = xdot
            + thetadot * (t19 - T::from_f64(2.0) * t11 * t15);
        let t32 = (T::from_f64(1.0) + hc_alpha * delta_rate_wall_right).max0();
        let delta_edge_left = r + t1 - x + t24 - T::from_f64(2.0) * t7;
        let t33 = sin_theta * t2 - t26;
        let t34 = sin_theta * (xdot + thetadot * (cos_theta * t33 + t8));
        let t35 = cos_theta * (zdot + thetadot * (-(sin_theta * t33) + t9));
        let slip_edge_left = t34 + t35;
        let pen_edge_left = delta_edge_left.max0();
        let t36 = pen_edge_left * pen_edge_left.sqrt();
        let delta_rate_edge_left = t25 + t10
            + thetadot * (t26 - T::from_f64(2.0) * t11 * t2);
        let t37 = (T::from_f64(1.0) + hc_alpha * delta_rate_edge_left).max0();
        let slip_wall_right = zdot - t27;
        let t38 = -t26 + sin_theta * t22;
        let t39 = sin_theta * (xdot - thetadot * (t8 - cos_theta * t38));
        let t40 = cos_theta * (zdot - thetadot * (t9 + sin_theta * t38));
        let slip_edge_right = t39 + t40;
        let t41 = (T::from_f64(1.0)
            - hc_alpha * (t25 + t10 + thetadot * (t26 - T::from_f64(2.0) * t11 * t22)))
            .max0();
        let t42 = t6 * t28;
        let delta_wall_left = r + t1 - x - t16 - T::from_f64(2.0) * t42;
        let pen_wall_left = delta_wall_left.max0();
        let t43 = pen_wall_left * pen_wall_left.sqrt();
        let t44 = (T::from_f64(1.0)
            - hc_alpha * (xdot + thetadot * (t19 + T::from_f64(2.0) * t11 * t28)))
            .max0();
        let t45 = delta_floor.hypot(t0 - r + x - t24 + T::from_f64(2.0) * t7);
        let t46 = g_star * tau_t;
        let delta_edge_right = r + t1 + x - t24 + T::from_f64(2.0) * t6 * t22;
        let pen_edge_right = delta_edge_right.max0();
        let t47 = pen_edge_right * pen_edge_right.sqrt();
        let t48 = delta_floor.hypot(delta_edge_right);
        let t49 = delta_floor.hypot(t0 - r + x + t16 + T::from_f64(2.0) * t42);
        let t50 = k_edge / e_star / edge_sum;
        let t51 = (T::from_f64(1.5) * t50).cbrt();
        let t52 = k_wall / e_star / wall_sum;
        let t53 = (T::from_f64(1.5) * t52).cbrt();
        let t54 = t36 * t37;
        let normal_edge_left = t54 * k_edge;
        let t55 = t43 * t44;
        let normal_wall_left = t55 * k_wall;
        let t56 = t32 * t30;
        let normal_wall_right = t56 * k_wall;
        let t57 = t46 * (t12 * t51);
        let t58 = t46 * (t20 * t53);
        let t59 = (T::from_f64(1.5) * t54 * t50).cbrt();
        let t60 = e_star * edge_sum * (T::from_f64(1.0) / (edge_ma * edge_mb));
        let t61 = (T::from_f64(1.5) * t55 * t52).cbrt();
        let t62 = e_star * wall_sum * (T::from_f64(1.0) / (wall_ma * wall_mb));
        let t63 = (T::from_f64(1.5) * t56 * t52).cbrt();
        let t64 = t41 * t47;
        let normal_edge_right = t64 * k_edge;
        let t65 = (T::from_f64(1.5) * t64 * t50).cbrt();
        let normal = Vector4::new(
            normal_edge_left,
            normal_wall_right,
            normal_edge_right,
            normal_wall_left,
        );
        let friction = Vector4::new(
            -(t36
                * (t13 * u_edge_left
                    + T::from_f64(8.0) * t57
                        * (t34 + t35 - u_edge_left * slip_edge_left.abs()) / t45)),
            -(t30
                * (t21 * u_wall_right
                    - T::from_f64(8.0) * t58
                        * (-zdot + t27 + u_wall_right * slip_wall_right.abs()) / t31)),
            -(t47
                * (t13 * u_edge_right
                    + T::from_f64(8.0) * t57
                        * (t39 + t40 - u_edge_right * slip_edge_right.abs()) / t48)),
            -(t43
                * (t21 * u_wall_left
                    + T::from_f64(8.0) * t58
                        * (zdot + t29 - u_wall_left * slip_wall_left.abs()) / t49)),
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
        let a = Vector4::new(edge_ma * t59, wall_ma * t63, edge_ma * t65, wall_ma * t61);
        let b = Vector4::new(edge_mb * t59, wall_mb * t63, edge_mb * t65, wall_mb * t61);
        let p0 = Vector4::new(
            T::from_f64(0.3183098861837907) * t60 * t59,
            T::from_f64(0.3183098861837907) * t62 * t63,
            T::from_f64(0.3183098861837907) * t60 * t65,
            T::from_f64(0.3183098861837907) * t62 * t61,
        );
        (normal, friction, delta, slip, a, b, p0)
    }
    /// Kinetic energy (59) (J), contact potential (63) (J), insertion depth of the bottom face (m) and stored tangential energy (J).
    ///
    /// # Inputs
    /// - `y` = (`x`, `z`, `theta`, `xdot`, `zdot`, `thetadot`, `work`, `dissipation`, `u_edge_left`, `u_wall_right`, `u_edge_right`, `u_wall_left`)
    /// - `p` = (`m`, `J`, `r`, `l_c`, `D`, `rho_p`, `rho_h`, `mu`, `v_s`, `k_edge`, `k_wall`, `f1`, `f2`, `M`, `e_star`, `edge_sum`, `edge_ma`, `edge_mb`, `edge_dstar`, `wall_sum`, `wall_ma`, `wall_mb`, `wall_dstar`, `hc_alpha`, `g_star`, `delta_floor`, `tau_t`)
    ///
    /// # Outputs
    /// - `kinetic`: scalar
    /// - `potential`: scalar
    /// - `depth`: scalar
    /// - `tangential`: scalar
    ///
    /// # Cost
    /// 33 add/sub, 51 mul, 5 div, 2 sqrt, 8 transcendental, 4 branches; 23 `let`s.
    #[inline]
    pub fn energy<T: Real>(y: &SVector<T, 12>, p: &SVector<T, 27>) -> (T, T, T, T) {
        let x = y[0];
        let z = y[1];
        let theta = y[2];
        let xdot = y[3];
        let zdot = y[4];
        let thetadot = y[5];
        let u_edge_left = y[8];
        let u_wall_right = y[9];
        let u_edge_right = y[10];
        let u_wall_left = y[11];
        let m = p[0];
        let j = p[1];
        let r = p[2];
        let l_c = p[3];
        let d = p[4];
        let rho_p = p[5];
        let rho_h = p[6];
        let mu = p[7];
        let k_edge = p[9];
        let k_wall = p[10];
        let e_star = p[14];
        let edge_sum = p[15];
        let edge_ma = p[16];
        let edge_mb = p[17];
        let wall_sum = p[19];
        let wall_ma = p[20];
        let wall_mb = p[21];
        let g_star = p[24];
        let (sin_theta, cos_theta) = theta.sin_cos();
        let t0 = -T::from_f64(0.5) * d;
        let t1 = (T::from_f64(0.5) * theta).sin();
        let t2 = t1 * t1;
        let t3 = T::from_f64(1.0) / (edge_ma * edge_mb).sqrt();
        let t4 = (T::from_f64(1.5) * k_edge / (e_star * edge_sum))
            .powf(-T::from_f64(1.0 / 3.0));
        let t5 = sin_theta * (l_c - rho_p);
        let t6 = T::from_f64(1.0) / (wall_ma * wall_mb).sqrt();
        let t7 = (T::from_f64(1.5) * k_wall / (e_star * wall_sum))
            .powf(-T::from_f64(1.0 / 3.0));
        let t8 = sin_theta * (-rho_h + z);
        let delta_edge_left = r + t0 - x + t8
            - T::from_f64(2.0) * (-rho_h + t0 - x) * t2;
        let pen_edge_left = delta_edge_left.max0();
        let delta_wall_right = r + t0 + x + t5 - T::from_f64(2.0) * t2 * (r - rho_p);
        let pen_wall_right = delta_wall_right.max0();
        let delta_edge_right = r + t0 + x - t8
            + T::from_f64(2.0) * t2 * (rho_h + T::from_f64(0.5) * d - x);
        let pen_edge_right = delta_edge_right.max0();
        let t9 = pen_edge_left.powf(T::from_f64(2.5));
        let t10 = pen_wall_right.powf(T::from_f64(2.5));
        let delta_wall_left = r + t0 - x - t5 - T::from_f64(2.0) * t2 * (-rho_p + r);
        let pen_wall_left = delta_wall_left.max0();
        let t11 = pen_wall_left.powf(T::from_f64(2.5));
        let t12 = pen_edge_right.powf(T::from_f64(2.5));
        let kinetic = T::from_f64(0.5)
            * (m * (xdot * xdot + zdot * zdot) + j * (thetadot * thetadot));
        let potential = T::from_f64(0.4) * (t9 + t12) * k_edge
            + T::from_f64(0.4) * (t10 + t11) * k_wall;
        let depth = z + l_c * cos_theta;
        let tangential = (T::from_f64(0.0625)
            * (k_edge * k_edge
                * (t9 * (u_edge_left * u_edge_left)
                    + t12 * (u_edge_right * u_edge_right)) * t4) * t3
            + T::from_f64(0.0625)
                * (k_wall * k_wall
                    * (t10 * (u_wall_right * u_wall_right)
                        + t11 * (u_wall_left * u_wall_left)) * t7) * t6) / g_star
            * (mu * mu);
        (kinetic, potential, depth, tangential)
    }
}
