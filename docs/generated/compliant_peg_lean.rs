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
    /// 60 add/sub, 121 mul, 4 div, 2 sqrt, 4 transcendental, 8 branches; 45 `let`s.
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
        let t8 = T::from_f64(0.5) * theta;
        let (t9, t19) = t8.sin_cos();
        let t10 = t9 * t9;
        let t11 = r + t4 + t5 - sin_theta * t7 - T::from_f64(2.0) * t6 * t10;
        let t12 = sin_theta * t6 + cos_theta * t7;
        let t13 = cos_theta * t12 + r * sin_theta;
        let t14 = -(sin_theta * t12) + r * cos_theta;
        let t15 = sin_theta * (xdot + thetadot * t13)
            + cos_theta * (zdot + thetadot * t14);
        let t16 = t11.max0();
        let t17 = t16 * t16.sqrt();
        let t18 = -T::from_f64(1.0) + T::from_f64(2.0) * t10;
        let t20 = -(cos_theta * t7) - T::from_f64(2.0) * t6 * t9 * t19;
        let t21 = xdot * t18 + zdot * sin_theta + thetadot * t20;
        let t22 = (T::from_f64(1.0) + hc_alpha * t21).max0();
        let t23 = k_edge * t17 * (t22 - T::from_f64(1.0));
        let t24 = v_s.hypot(t15);
        let t25 = T::from_f64(1.0) / t24;
        let t26 = t11.step();
        let t27 = -rho_p;
        let t28 = l_c + t27;
        let t29 = r + t27;
        let t30 = r + t4 + x + sin_theta * t28 - T::from_f64(2.0) * t10 * t29;
        let t31 = -(sin_theta * (l_c + t27 + rho_p * sin_theta))
            - cos_theta * (r - T::from_f64(2.0) * rho_p * t10);
        let t32 = zdot + thetadot * t31;
        let t33 = t30.max0();
        let t34 = t33 * t33.sqrt();
        let t35 = cos_theta * t28 - T::from_f64(2.0) * t9 * t19 * t29;
        let t36 = xdot + thetadot * t35;
        let t37 = (T::from_f64(1.0) + hc_alpha * t36).max0();
        let t38 = k_wall * t34 * (t37 - T::from_f64(1.0));
        let t39 = v_s.hypot(t32);
        let t40 = T::from_f64(1.0) / t39;
        let t41 = t30.step();
        let t42 = T::from_f64(1.0) / m;
        SMatrix::<
            T,
            8,
            1,
        >::from_row_slice(
            &[
                xdot,
                zdot,
                thetadot,
                (t0 + t1 - k_edge * t17 * t18 * t26 - t18 * t23
                    - mu * k_edge * sin_theta * t15 * t17 * t22 * t25 + k_wall * t34
                    - k_wall * t34 * t41 - k_wall * t34 * t37) * t42,
                (t2 + t3 - k_edge * sin_theta * t17 * t26 - sin_theta * t23
                    - mu * k_edge * cos_theta * t15 * t17 * t22 * t25
                    - mu * k_wall * t32 * t34 * t37 * t40) * t42,
                (m_2 - k_edge * t17 * t20 * t26 - t20 * t23
                    - mu * k_edge * t15 * t17 * t22 * t25
                        * (sin_theta * t13 + cos_theta * t14) - k_wall * t34 * t35 * t41
                    - t35 * t38 - mu * k_wall * t31 * t32 * t34 * t37 * t40) / j,
                xdot * (t0 + t1) + zdot * (t2 + t3) + thetadot * m_2,
                mu * k_edge * t17 * t22 * t25 * (t15 * t15) + t21 * t23
                    + mu * k_wall * t34 * t37 * t40 * (t32 * t32) + t36 * t38,
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
    /// 230 add/sub, 1056 mul, 6 div, 4 sqrt, 4 transcendental, 12 branches; 115 `let`s.
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
        let t0 = f1 * cos_theta;
        let t1 = -f2 * sin_theta;
        let t2 = t0 + t1;
        let t3 = -T::from_f64(0.5) * d;
        let t4 = -x;
        let t5 = -rho_h + t3 + t4;
        let t6 = rho_h - z;
        let t7 = -sin_theta * t6;
        let t8 = cos_theta * t5 + t7;
        let t9 = T::from_f64(0.5) * theta;
        let (t10, t24) = t9.sin_cos();
        let t11 = t10 * t10;
        let t12 = r + t3 + t4 + t7 - T::from_f64(2.0) * t5 * t11;
        let t13 = sin_theta * t5 + cos_theta * t6;
        let t14 = cos_theta * t13 + r * sin_theta;
        let t15 = xdot + thetadot * t14;
        let t16 = -sin_theta * t13;
        let t17 = r * cos_theta;
        let t18 = t16 + t17;
        let t19 = zdot + thetadot * t18;
        let t20 = sin_theta * t15 + cos_theta * t19;
        let t21 = t12.max0();
        let t22 = t21 * t21.sqrt();
        let t23 = -T::from_f64(1.0) + T::from_f64(2.0) * t11;
        let t25 = -(cos_theta * t6) - T::from_f64(2.0) * t5 * t10 * t24;
        let t26 = xdot * t23 + zdot * sin_theta + thetadot * t25;
        let t27 = T::from_f64(1.0) + hc_alpha * t26;
        let t28 = t27.max0();
        let t29 = k_edge * t22 * (t28 - T::from_f64(1.0));
        let t30 = v_s.hypot(t20);
        let t31 = T::from_f64(1.0) / t30;
        let t32 = t12.step();
        let t33 = sin_theta * t14 + cos_theta * t18;
        let t34 = t20 * t20;
        let t35 = -rho_p;
        let t36 = l_c + t35;
        let t37 = r + t35;
        let t38 = r + t3 + x + sin_theta * t36 - T::from_f64(2.0) * t11 * t37;
        let t39 = l_c + t35 + rho_p * sin_theta;
        let t40 = r - T::from_f64(2.0) * rho_p * t11;
        let t41 = -(sin_theta * t39) - cos_theta * t40;
        let t42 = zdot + thetadot * t41;
        let t43 = t38.max0();
        let t44 = t43 * t43.sqrt();
        let t45 = cos_theta * t36 - T::from_f64(2.0) * t10 * t24 * t37;
        let t46 = xdot + thetadot * t45;
        let t47 = T::from_f64(1.0) + hc_alpha * t46;
        let t48 = t47.max0();
        let t49 = k_wall * t44 * t48;
        let t50 = -k_wall * t44;
        let t51 = t49 + t50;
        let t52 = v_s.hypot(t42);
        let t53 = T::from_f64(1.0) / t52;
        let t54 = t38.step();
        let t55 = t42 * t42;
        let t56 = T::from_f64(1.0) / m;
        let t57 = T::from_f64(1.0) / j;
        let t58 = t21.sqrt();
        let t59 = t23 * t23;
        let t60 = t32 * t32;
        let t61 = t27.step();
        let t62 = k_edge
            * (T::from_f64(1.5) * t23 * t28 * t32 * t58
                + T::from_f64(2.0) * thetadot * hc_alpha * t10 * t22 * t24 * t61
                - T::from_f64(1.5) * t23 * t32 * t58);
        let t63 = sin_theta * sin_theta;
        let t64 = t43.sqrt();
        let t65 = t54 * t54;
        let t66 = -T::from_f64(1.5) * k_edge * sin_theta * t23 * t58 * t60;
        let t67 = k_edge
            * (T::from_f64(1.5) * sin_theta * t28 * t32 * t58
                + thetadot * hc_alpha * cos_theta * t22 * t61
                - T::from_f64(1.5) * sin_theta * t32 * t58);
        let t68 = cos_theta * cos_theta;
        let t69 = -T::from_f64(1.5) * k_edge * t23 * t25 * t58 * t60;
        let t70 = -T::from_f64(2.0) * k_edge * t10 * t22 * t24 * t32;
        let t71 = -T::from_f64(2.0) * t10 * t24 * t29;
        let t72 = t24 * t24;
        let t73 = sin_theta * t6 + t5 * t11 - t5 * t72;
        let t74 = T::from_f64(2.0) * xdot * t10 * t24 + zdot * cos_theta
            + thetadot * t73;
        let t75 = k_edge
            * (T::from_f64(1.5) * t25 * t28 * t32 * t58 + hc_alpha * t22 * t61 * t74
                - T::from_f64(1.5) * t25 * t32 * t58);
        let t76 = t16 + t17 + cos_theta * t8;
        let t77 = -(r * sin_theta) - cos_theta * t13 - sin_theta * t8;
        let t78 = cos_theta * t15 + thetadot * sin_theta * t76 - sin_theta * t19
            + thetadot * cos_theta * t77;
        let t79 = T::from_f64(1.0) / (t30 * t30 * t30);
        let t80 = -T::from_f64(1.5) * k_wall * t45 * t64 * t65;
        let t81 = t11 * t37 - sin_theta * t36 - t37 * t72;
        let t82 = t47.step();
        let t83 = -k_edge * hc_alpha * sin_theta * t22 * t23 * t61;
        let t84 = -mu * k_edge * sin_theta * cos_theta * t22 * t28 * t31;
        let t85 = mu * k_edge * sin_theta * cos_theta * t22 * t28 * t34 * t79;
        let t86 = -k_edge * hc_alpha * t22 * t23 * t25 * t61;
        let t87 = -mu * k_edge * sin_theta * t22 * t28 * t31 * t33;
        let t88 = mu * k_edge * sin_theta * t22 * t28 * t33 * t34 * t79;
        let t89 = -k_wall * hc_alpha * t44 * t45 * t82;
        let t90 = -f1 * sin_theta;
        let t91 = -f2 * cos_theta;
        let t92 = -k_edge * cos_theta * t22 * t32;
        let t93 = -T::from_f64(1.5) * k_edge * sin_theta * t25 * t58 * t60;
        let t94 = -cos_theta * t29;
        let t95 = sin_theta * t40 - cos_theta * t39 - rho_p * sin_theta * cos_theta
            + T::from_f64(2.0) * rho_p * cos_theta * t10 * t24;
        let t96 = T::from_f64(1.0) / (t52 * t52 * t52);
        let t97 = -k_edge * hc_alpha * sin_theta * t22 * t25 * t61;
        let t98 = -mu * k_edge * cos_theta * t22 * t28 * t31 * t33;
        let t99 = mu * k_edge * cos_theta * t22 * t28 * t33 * t34 * t79;
        let t100 = -mu * k_wall * t41 * t44 * t48 * t53;
        let t101 = mu * k_wall * t41 * t44 * t48 * t55 * t96;
        let t102 = k_wall * t54 * t64 * (T::from_f64(1.5) * t48 - T::from_f64(1.5));
        let t103 = t25 * t25;
        let t104 = t45 * t45;
        let t105 = k_wall
            * (thetadot * hc_alpha * t44 * t81 * t82
                + T::from_f64(1.5) * t45 * t48 * t54 * t64
                - T::from_f64(1.5) * t45 * t54 * t64);
        let t106 = t33 * t33;
        let t107 = cos_theta * t40 + sin_theta * t39;
        let t108 = t107 * t107;
        let t109 = t20 * t20 * t20;
        let t110 = T::from_f64(2.0) * sin_theta * t15
            + T::from_f64(2.0) * cos_theta * t19;
        let t111 = t42 * t42 * t42;
        let t112 = T::from_f64(2.0) * zdot + T::from_f64(2.0) * thetadot * t41;
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
                t56
                    * (-(T::from_f64(1.5) * k_edge * t58 * t59 * t60) - t23 * t62
                        - T::from_f64(1.5) * mu * k_edge * sin_theta * t20 * t23 * t28
                            * t31 * t32 * t58
                        - T::from_f64(2.0) * thetadot * mu * k_edge * hc_alpha
                            * sin_theta * t10 * t20 * t22 * t24 * t31 * t61
                        + T::from_f64(1.5) * k_wall * t54 * t64
                        - T::from_f64(1.5) * k_wall * t64 * t65
                        - T::from_f64(1.5) * k_wall * t48 * t54 * t64),
                t56
                    * (t66 - t23 * t67
                        - T::from_f64(1.5) * mu * k_edge * t20 * t28 * t31 * t32 * t58
                            * t63
                        - thetadot * mu * k_edge * hc_alpha * sin_theta * cos_theta * t20
                            * t22 * t31 * t61),
                t56
                    * (t0 + t1 - mu * k_edge * cos_theta * t20 * t22 * t28 * t31 + t69
                        + t70 + t71 - t23 * t75
                        - mu * k_edge * sin_theta * t22 * t28 * t31 * t78
                        - T::from_f64(1.5) * mu * k_edge * sin_theta * t20 * t25 * t28
                            * t31 * t32 * t58
                        - mu * k_edge * hc_alpha * sin_theta * t20 * t22 * t31 * t61
                            * t74 + mu * k_edge * sin_theta * t22 * t28 * t34 * t78 * t79
                        + T::from_f64(1.5) * k_wall * t45 * t54 * t64 + t80
                        - T::from_f64(1.5) * k_wall * t45 * t48 * t54 * t64
                        - thetadot * k_wall * hc_alpha * t44 * t81 * t82),
                t56
                    * (-(k_edge * hc_alpha * t22 * t59 * t61)
                        - mu * k_edge * t22 * t28 * t31 * t63
                        - mu * k_edge * hc_alpha * sin_theta * t20 * t22 * t23 * t31
                            * t61 + mu * k_edge * t22 * t28 * t34 * t63 * t79
                        - k_wall * hc_alpha * t44 * t82),
                t56
                    * (t83 + t84 - mu * k_edge * hc_alpha * t20 * t22 * t31 * t61 * t63
                        + t85),
                t56
                    * (t86 + t87
                        - mu * k_edge * hc_alpha * sin_theta * t20 * t22 * t25 * t31
                            * t61 + t88 + t89),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t56
                    * (t66 - sin_theta * t62
                        - T::from_f64(1.5) * mu * k_edge * cos_theta * t20 * t23 * t28
                            * t31 * t32 * t58
                        - T::from_f64(2.0) * thetadot * mu * k_edge * hc_alpha
                            * cos_theta * t10 * t20 * t22 * t24 * t31 * t61
                        - T::from_f64(1.5) * mu * k_wall * t42 * t48 * t53 * t54 * t64),
                t56
                    * (-(T::from_f64(1.5) * k_edge * t58 * t60 * t63) - sin_theta * t67
                        - T::from_f64(1.5) * mu * k_edge * sin_theta * cos_theta * t20
                            * t28 * t31 * t32 * t58
                        - thetadot * mu * k_edge * hc_alpha * t20 * t22 * t31 * t61
                            * t68),
                t56
                    * (mu * k_edge * sin_theta * t20 * t22 * t28 * t31 + t90 + t91 + t92
                        + t93 + t94 - sin_theta * t75
                        - mu * k_edge * cos_theta * t22 * t28 * t31 * t78
                        - T::from_f64(1.5) * mu * k_edge * cos_theta * t20 * t25 * t28
                            * t31 * t32 * t58
                        - mu * k_edge * hc_alpha * cos_theta * t20 * t22 * t31 * t61
                            * t74 + mu * k_edge * cos_theta * t22 * t28 * t34 * t78 * t79
                        - thetadot * mu * k_wall * t44 * t48 * t53 * t95
                        - T::from_f64(1.5) * mu * k_wall * t42 * t45 * t48 * t53 * t54
                            * t64
                        - thetadot * mu * k_wall * hc_alpha * t42 * t44 * t53 * t81 * t82
                        + thetadot * mu * k_wall * t44 * t48 * t55 * t95 * t96),
                t56
                    * (t83 + t84 + t85
                        - mu * k_edge * hc_alpha * cos_theta * t20 * t22 * t23 * t31
                            * t61 - mu * k_wall * hc_alpha * t42 * t44 * t53 * t82),
                t56
                    * (-(k_edge * hc_alpha * t22 * t61 * t63)
                        - mu * k_edge * t22 * t28 * t31 * t68
                        - mu * k_edge * hc_alpha * sin_theta * cos_theta * t20 * t22
                            * t31 * t61 + mu * k_edge * t22 * t28 * t34 * t68 * t79
                        - mu * k_wall * t44 * t48 * t53
                        + mu * k_wall * t44 * t48 * t55 * t96),
                t56
                    * (t97 + t98
                        - mu * k_edge * hc_alpha * cos_theta * t20 * t22 * t25 * t31
                            * t61 + t99 + t100
                        - mu * k_wall * hc_alpha * t42 * t44 * t45 * t53 * t82 + t101),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t57
                    * (t69 + t70 + t71 + t80 - t25 * t62
                        - T::from_f64(1.5) * mu * k_edge * t20 * t23 * t28 * t31 * t32
                            * t33 * t58
                        - T::from_f64(2.0) * thetadot * mu * k_edge * hc_alpha * t10
                            * t20 * t22 * t24 * t31 * t33 * t61 - t45 * t102
                        - T::from_f64(1.5) * mu * k_wall * t41 * t42 * t48 * t53 * t54
                            * t64),
                t57
                    * (t92 + t93 + t94 - t25 * t67
                        - T::from_f64(1.5) * mu * k_edge * sin_theta * t20 * t28 * t31
                            * t32 * t33 * t58
                        - thetadot * mu * k_edge * hc_alpha * cos_theta * t20 * t22 * t31
                            * t33 * t61),
                t57
                    * (-(T::from_f64(1.5) * k_edge * t58 * t60 * t103)
                        - k_edge * t22 * t32 * t73 - t29 * t73 - t25 * t75
                        - mu * k_edge * t22 * t28 * t31 * t33 * t78
                        - T::from_f64(1.5) * mu * k_edge * t20 * t25 * t28 * t31 * t32
                            * t33 * t58
                        - mu * k_edge * hc_alpha * t20 * t22 * t31 * t33 * t61 * t74
                        + mu * k_edge * t22 * t28 * t33 * t34 * t78 * t79
                        - mu * k_edge * t20 * t22 * t28 * t31
                            * (cos_theta * t14 + sin_theta * t76 - sin_theta * t18
                                + cos_theta * t77)
                        - T::from_f64(1.5) * k_wall * t64 * t65 * t104
                        - k_wall * t44 * t54 * t81 - t51 * t81 - t45 * t105
                        - mu * k_wall * t42 * t44 * t48 * t53 * t95
                        - thetadot * mu * k_wall * t41 * t44 * t48 * t53 * t95
                        - T::from_f64(1.5) * mu * k_wall * t41 * t42 * t45 * t48 * t53
                            * t54 * t64
                        - thetadot * mu * k_wall * hc_alpha * t41 * t42 * t44 * t53 * t81
                            * t82
                        + thetadot * mu * k_wall * t41 * t44 * t48 * t55 * t95 * t96),
                t57
                    * (t86 + t87 + t88 + t89
                        - mu * k_edge * hc_alpha * t20 * t22 * t23 * t31 * t33 * t61
                        - mu * k_wall * hc_alpha * t41 * t42 * t44 * t53 * t82),
                t57
                    * (t97 + t98 + t99 + t100 + t101
                        - mu * k_edge * hc_alpha * sin_theta * t20 * t22 * t31 * t33
                            * t61),
                t57
                    * (-(k_edge * hc_alpha * t22 * t61 * t103)
                        - mu * k_edge * t22 * t28 * t31 * t106
                        - mu * k_edge * hc_alpha * t20 * t22 * t25 * t31 * t33 * t61
                        + mu * k_edge * t22 * t28 * t34 * t79 * t106
                        - k_wall * hc_alpha * t44 * t82 * t104
                        - mu * k_wall * t44 * t48 * t53 * t108
                        - mu * k_wall * hc_alpha * t41 * t42 * t44 * t45 * t53 * t82
                        + mu * k_wall * t44 * t48 * t55 * t96 * t108),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                xdot * t2 + zdot * (t90 + t91),
                f1 * sin_theta + f2 * cos_theta,
                t2,
                m_2,
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(1.5) * mu * k_edge * t23 * t28 * t31 * t32 * t34 * t58
                    + T::from_f64(2.0) * thetadot * mu * k_edge * hc_alpha * t10 * t22
                        * t24 * t31 * t34 * t61
                    + T::from_f64(2.0) * thetadot * t10 * t24 * t29 + t26 * t62
                    + T::from_f64(1.5) * mu * k_wall * t48 * t53 * t54 * t55 * t64
                    + t46 * t102,
                T::from_f64(1.5) * mu * k_edge * sin_theta * t28 * t31 * t32 * t34 * t58
                    + thetadot * mu * k_edge * hc_alpha * cos_theta * t22 * t31 * t34
                        * t61 + thetadot * cos_theta * t29 + t26 * t67,
                T::from_f64(1.5) * mu * k_edge * t25 * t28 * t31 * t32 * t34 * t58
                    + mu * k_edge * hc_alpha * t22 * t31 * t34 * t61 * t74
                    - mu * k_edge * t22 * t28 * t78 * t79 * t109
                    + mu * k_edge * t22 * t28 * t31 * t78 * t110 + t29 * t74 + t26 * t75
                    + T::from_f64(1.5) * mu * k_wall * t45 * t48 * t53 * t54 * t55 * t64
                    + thetadot * mu * k_wall * hc_alpha * t44 * t53 * t55 * t81 * t82
                    - thetadot * mu * k_wall * t44 * t48 * t95 * t96 * t111
                    + thetadot * mu * k_wall * t44 * t48 * t53 * t95 * t112
                    + thetadot * t51 * t81 + t46 * t105,
                t23 * t29 + t49 + t50
                    + mu * k_edge * hc_alpha * t22 * t23 * t31 * t34 * t61
                    - mu * k_edge * sin_theta * t22 * t28 * t79 * t109
                    + mu * k_edge * sin_theta * t22 * t28 * t31 * t110
                    + k_edge * hc_alpha * t22 * t23 * t26 * t61
                    + mu * k_wall * hc_alpha * t44 * t53 * t55 * t82
                    + k_wall * hc_alpha * t44 * t46 * t82,
                sin_theta * t29
                    + mu * k_edge * hc_alpha * sin_theta * t22 * t31 * t34 * t61
                    - mu * k_edge * cos_theta * t22 * t28 * t79 * t109
                    + mu * k_edge * cos_theta * t22 * t28 * t31 * t110
                    + k_edge * hc_alpha * sin_theta * t22 * t26 * t61
                    - mu * k_wall * t44 * t48 * t96 * t111
                    + mu * k_wall * t44 * t48 * t53 * t112,
                t25 * t29 + t45 * t51
                    + mu * k_edge * hc_alpha * t22 * t25 * t31 * t34 * t61
                    - mu * k_edge * t22 * t28 * t33 * t79 * t109
                    + mu * k_edge * t22 * t28 * t31 * t33 * t110
                    + k_edge * hc_alpha * t22 * t25 * t26 * t61
                    + mu * k_wall * hc_alpha * t44 * t45 * t53 * t55 * t82
                    - mu * k_wall * t41 * t44 * t48 * t96 * t111
                    + mu * k_wall * t41 * t44 * t48 * t53 * t112
                    + k_wall * hc_alpha * t44 * t45 * t46 * t82,
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
    /// 32 add/sub, 74 mul, 7 div, 2 sqrt, 6 transcendental, 4 branches; 29 `let`s.
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
        let (t5, t12) = t4.sin_cos();
        let t6 = t5 * t5;
        let t7 = r + t0 + t1 - sin_theta * t3 - T::from_f64(2.0) * t2 * t6;
        let t8 = sin_theta * t2 + cos_theta * t3;
        let t9 = sin_theta * (xdot + thetadot * (cos_theta * t8 + r * sin_theta))
            + cos_theta * (zdot + thetadot * (-(sin_theta * t8) + r * cos_theta));
        let t10 = t7.max0();
        let t11 = t10 * t10.sqrt();
        let t13 = (T::from_f64(1.0)
            + hc_alpha
                * (xdot * (-T::from_f64(1.0) + T::from_f64(2.0) * t6) + zdot * sin_theta
                    + thetadot * (-(cos_theta * t3) - T::from_f64(2.0) * t2 * t5 * t12)))
            .max0();
        let t14 = v_s.hypot(t9);
        let t15 = T::from_f64(1.0) / e_star;
        let t16 = (T::from_f64(1.5) * k_edge * t11 * t13 * t15 / edge_sum).cbrt();
        let t17 = -rho_p;
        let t18 = l_c + t17;
        let t19 = r + t17;
        let t20 = r + t0 + x + sin_theta * t18 - T::from_f64(2.0) * t6 * t19;
        let t21 = zdot
            + thetadot
                * (-(sin_theta * (l_c + t17 + rho_p * sin_theta))
                    - cos_theta * (r - T::from_f64(2.0) * rho_p * t6));
        let t22 = t20.max0();
        let t23 = t22 * t22.sqrt();
        let t24 = (T::from_f64(1.0)
            + hc_alpha
                * (xdot
                    + thetadot * (cos_theta * t18 - T::from_f64(2.0) * t5 * t12 * t19)))
            .max0();
        let t25 = v_s.hypot(t21);
        let t26 = (T::from_f64(1.5) * k_wall * t15 * t23 * t24 / wall_sum).cbrt();
        let normal = Vector2::new(k_edge * t11 * t13, k_wall * t23 * t24);
        let friction = Vector2::new(
            -mu * k_edge * t9 * t11 * t13 / t14,
            -mu * k_wall * t21 * t23 * t24 / t25,
        );
        let delta = Vector2::new(t7, t20);
        let slip = Vector2::new(t9, t21);
        let a = Vector2::new(edge_ma * t16, wall_ma * t26);
        let b = Vector2::new(edge_mb * t16, wall_mb * t26);
        let p0 = Vector2::new(
            T::from_f64(0.3183098861837907) * e_star * edge_sum * t16
                / (edge_ma * edge_mb),
            T::from_f64(0.3183098861837907) * e_star * wall_sum * t26
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
    /// 17 add/sub, 21 mul, 0 div, 0 sqrt, 4 transcendental, 2 branches; 11 `let`s.
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
        let kinetic = T::from_f64(0.5) * m * (xdot * xdot + zdot * zdot)
            + T::from_f64(0.5) * j * (thetadot * thetadot);
        let potential = T::from_f64(0.4) * k_edge * t5 + T::from_f64(0.4) * k_wall * t8;
        let depth = z + l_c * cos_theta;
        (kinetic, potential, depth)
    }
}
