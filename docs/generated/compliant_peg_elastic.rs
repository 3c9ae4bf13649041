// @generated readable copy of `pegdyn::generated::compliant_peg_elastic` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generator snapshot::

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
    /// The parameters of `compliant_peg_elastic`: the input `p` of its functions as a struct, one field per component in vector order (`From`/`Into` convert both ways).
    #[derive(Clone, Copy, Debug, PartialEq)]
    #[allow(non_snake_case)]
    pub struct Params<T> {
        /// Mass m of the peg, kg.
        pub m: T,
        /// Moment of inertia J about the centre of mass, kg·m².
        pub J: T,
        /// Peg radius r, m.
        pub r: T,
        /// Distance l_c from the centre of mass to the bottom face, m.
        pub l_c: T,
        /// Hole diameter D, m.
        pub D: T,
        /// Fillet radius ρ_p of the peg's bottom corners, m.
        pub rho_p: T,
        /// Fillet radius ρ_h of the hole's top edges, m.
        pub rho_h: T,
        /// Coulomb friction coefficient μ, dimensionless.
        pub mu: T,
        /// Velocity scale v_s of the regularized friction law, m/s.
        pub v_s: T,
        /// Hertz stiffness of the edge contacts, N/m^1.5.
        pub k_edge: T,
        /// Hertz stiffness of the wall contacts, N/m^1.5.
        pub k_wall: T,
        /// Applied axial force f₁ (along e_a, pushing the peg into the hole), N.
        pub f1: T,
        /// Applied radial force f₂ (along e_r), N.
        pub f2: T,
        /// Applied torque M about the centre of mass, positive increasing θ, N·m.
        pub M: T,
        /// Contact modulus E* of the peg and hole materials, Pa.
        pub e_star: T,
        /// Sum of the principal curvatures Σρ of the edge contacts, 1/m.
        pub edge_sum: T,
        /// Hertz ellipse coefficient m_a of the edge contacts (9), dimensionless.
        pub edge_ma: T,
        /// Hertz ellipse coefficient m_b of the edge contacts (10), dimensionless.
        pub edge_mb: T,
        /// Hertz approach coefficient δ* of the edge contacts (13), dimensionless.
        pub edge_dstar: T,
        /// Sum of the principal curvatures Σρ of the wall contacts, 1/m.
        pub wall_sum: T,
        /// Hertz ellipse coefficient m_a of the wall contacts (9), dimensionless.
        pub wall_ma: T,
        /// Hertz ellipse coefficient m_b of the wall contacts (10), dimensionless.
        pub wall_mb: T,
        /// Hertz approach coefficient δ* of the wall contacts (13), dimensionless.
        pub wall_dstar: T,
        /// Hunt–Crossley damping coefficient α (0 for elastic contacts), s/m.
        pub hc_alpha: T,
        /// Effective shear modulus G* of Mindlin's tangential stiffness, Pa.
        pub g_star: T,
        /// Penetration floor δ_0 of the utilisation rate, m.
        pub delta_floor: T,
        /// Damping time τ_t of the tangential springs, s.
        pub tau_t: T,
    }
    impl<T> Params<T> {
        /// The field names in vector order: the symbol names of `p` ([`P_NAMES`]).
        pub const NAMES: [&'static str; 27] = P_NAMES;
    }
    impl<T: Real> From<Params<T>> for SVector<T, 27> {
        /// The `p` vector of these values, in field order.
        fn from(v: Params<T>) -> SVector<T, 27> {
            SVector::from([
                v.m,
                v.J,
                v.r,
                v.l_c,
                v.D,
                v.rho_p,
                v.rho_h,
                v.mu,
                v.v_s,
                v.k_edge,
                v.k_wall,
                v.f1,
                v.f2,
                v.M,
                v.e_star,
                v.edge_sum,
                v.edge_ma,
                v.edge_mb,
                v.edge_dstar,
                v.wall_sum,
                v.wall_ma,
                v.wall_mb,
                v.wall_dstar,
                v.hc_alpha,
                v.g_star,
                v.delta_floor,
                v.tau_t,
            ])
        }
    }
    impl<T: Real> From<&SVector<T, 27>> for Params<T> {
        /// The fields of a `p` vector, in field order.
        fn from(v: &SVector<T, 27>) -> Params<T> {
            Params {
                m: v[0],
                J: v[1],
                r: v[2],
                l_c: v[3],
                D: v[4],
                rho_p: v[5],
                rho_h: v[6],
                mu: v[7],
                v_s: v[8],
                k_edge: v[9],
                k_wall: v[10],
                f1: v[11],
                f2: v[12],
                M: v[13],
                e_star: v[14],
                edge_sum: v[15],
                edge_ma: v[16],
                edge_mb: v[17],
                edge_dstar: v[18],
                wall_sum: v[19],
                wall_ma: v[20],
                wall_mb: v[21],
                wall_dstar: v[22],
                hc_alpha: v[23],
                g_star: v[24],
                delta_floor: v[25],
                tau_t: v[26],
            }
        }
    }
    impl<T: Real> From<SVector<T, 27>> for Params<T> {
        /// The fields of a `p` vector, in field order.
        fn from(v: SVector<T, 27>) -> Params<T> {
            Params::from(&v)
        }
    }
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
    /// 150 add/sub, 248 mul, 15 div, 8 sqrt, 10 transcendental, 20 branches; 150 `let`s.
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
        let t2 = T::from_f64(0.5) * theta;
        let (t3, t4) = t2.sin_cos();
        let t5 = t3 * t3;
        let t6 = r * sin_theta;
        let t7 = r * cos_theta;
        let t8 = zdot * sin_theta;
        let t9 = t3 * t4;
        let t10 = T::from_f64(1.0) - T::from_f64(2.0) * t5;
        let t11 = edge_ma * edge_mb;
        let t12 = t11.sqrt();
        let t13 = T::from_f64(1.5) * k_edge / (e_star * edge_sum);
        let t14 = t13.cbrt();
        let t15 = T::from_f64(1.0) / t11.sqrt();
        let t16 = t13.powf(-T::from_f64(1.0 / 3.0));
        let t17 = u_edge_left * u_edge_left;
        let t18 = mu * k_edge;
        let t19 = l_c - rho_p;
        let t20 = r - rho_p;
        let t21 = sin_theta * t19;
        let t22 = rho_p * sin_theta;
        let t23 = cos_theta * (r - T::from_f64(2.0) * rho_p * t5);
        let t24 = cos_theta * t19;
        let t25 = wall_ma * wall_mb;
        let t26 = t25.sqrt();
        let t27 = T::from_f64(1.5) * k_wall / (e_star * wall_sum);
        let t28 = t27.cbrt();
        let t29 = T::from_f64(1.0) / t25.sqrt();
        let t30 = t27.powf(-T::from_f64(1.0 / 3.0));
        let t31 = u_wall_right * u_wall_right;
        let t32 = mu * k_wall;
        let t33 = rho_h + t1 - x;
        let t34 = u_edge_right * u_edge_right;
        let t35 = u_wall_left * u_wall_left;
        let t36 = z - rho_h;
        let t37 = sin_theta * t36;
        let t38 = -xdot * t10;
        let t39 = cos_theta * t36;
        let t40 = sin_theta * (l_c - rho_p + t22) + t23;
        let t41 = thetadot * t40;
        let t42 = sin_theta * (-l_c + rho_p + t22) + t23;
        let t43 = thetadot * t42;
        let slip_wall_left = zdot + t43;
        let slip_wall_left_2 = slip_wall_left.abs();
        let t44 = zdot + t43 - u_wall_left * slip_wall_left_2;
        let t45 = g_star / mu;
        let t46 = t12 * t14;
        let t47 = t45 * (t46 / k_edge);
        let slip_wall_right = zdot - t41;
        let abs_slip_wall_right = slip_wall_right.abs();
        let t48 = -zdot + t41 + u_wall_right * abs_slip_wall_right;
        let t49 = t26 * t28;
        let t50 = t45 * (t49 / k_wall);
        let t51 = sin_theta * t33 - t39;
        let t52 = t6 - cos_theta * t51;
        let t53 = t7 + sin_theta * t51;
        let t54 = sin_theta * (xdot - thetadot * t52);
        let t55 = cos_theta * (zdot - thetadot * t53);
        let slip_edge_right = t54 + t55;
        let t56 = t39 - T::from_f64(2.0) * t9 * t33;
        let neg_delta_rate_edge_right = t38 + t8 + thetadot * t56;
        let t57 = (T::from_f64(1.0) - hc_alpha * neg_delta_rate_edge_right).max0();
        let slip_edge_right_2 = slip_edge_right.abs();
        let t58 = t54 + t55 - u_edge_right * slip_edge_right_2;
        let t59 = g_star * tau_t;
        let t60 = t59 * t46;
        let t61 = T::from_f64(1.0) - t57;
        let t62 = t49 * t59;
        let t63 = t16 * (k_edge * k_edge) * t15;
        let t64 = mu * mu / g_star;
        let t65 = T::from_f64(2.0) * (t9 * t20);
        let t66 = t24 + t65;
        let neg_delta_rate_wall_left = xdot + thetadot * t66;
        let t67 = (T::from_f64(1.0) - hc_alpha * neg_delta_rate_wall_left).max0();
        let t68 = T::from_f64(2.0) * (t5 * t20);
        let t69 = T::from_f64(1.0) - t67;
        let neg_delta_wall_left = t1 - r + x + t21 + t68;
        let t70 = delta_floor.hypot(neg_delta_wall_left);
        let t71 = T::from_f64(1.0) / t70;
        let t72 = neg_delta_rate_wall_left * t71 * neg_delta_wall_left;
        let t73 = (-t72).max0();
        let t74 = t30 * (k_wall * k_wall) * t29;
        let t75 = t44 * t71;
        let t76 = -rho_h - t1 - x;
        let t77 = t76 * t5;
        let t78 = t24 - t65;
        let delta_rate_wall_right = xdot + thetadot * t78;
        let t79 = (T::from_f64(1.0) + hc_alpha * delta_rate_wall_right).max0();
        let delta_edge_left = r - t1 - x + t37 - T::from_f64(2.0) * t77;
        let t80 = sin_theta * t76 - t39;
        let t81 = cos_theta * t80 + t6;
        let t82 = t7 - sin_theta * t80;
        let t83 = sin_theta * (xdot + thetadot * t81);
        let t84 = cos_theta * (zdot + thetadot * t82);
        let slip_edge_left = t83 + t84;
        let pen_edge_left = delta_edge_left.max0();
        let t85 = pen_edge_left * pen_edge_left.sqrt();
        let t86 = t39 - T::from_f64(2.0) * t9 * t76;
        let delta_rate_edge_left = t38 + t8 + thetadot * t86;
        let t87 = (T::from_f64(1.0) + hc_alpha * delta_rate_edge_left).max0();
        let slip_edge_left_2 = slip_edge_left.abs();
        let t88 = t83 + t84 - u_edge_left * slip_edge_left_2;
        let step_delta_edge_left = delta_edge_left.step();
        let delta_wall_right = r - t1 + x + t21 - t68;
        let pen_wall_right = delta_wall_right.max0();
        let t89 = pen_wall_right * pen_wall_right.sqrt();
        let t90 = delta_floor.hypot(delta_wall_right);
        let t91 = T::from_f64(1.0) / t90;
        let t92 = delta_rate_wall_right * t91 * delta_wall_right;
        let step_delta_wall_right = delta_wall_right.step();
        let t93 = T::from_f64(1.0) - t87;
        let neg_delta_edge_left = t1 - r + x - t37 + T::from_f64(2.0) * t77;
        let t94 = delta_floor.hypot(neg_delta_edge_left);
        let t95 = T::from_f64(1.0) / t94;
        let t96 = t88 * t95;
        let t97 = t85 * (t18 * u_edge_left + T::from_f64(8.0) * t60 * t96);
        let t98 = T::from_f64(1.0) - t79;
        let t99 = (-t92).max0();
        let delta_edge_right = r - t1 + x - t37 + T::from_f64(2.0) * t5 * t33;
        let pen_edge_right = delta_edge_right.max0();
        let t100 = pen_edge_right * pen_edge_right.sqrt();
        let t101 = delta_floor.hypot(delta_edge_right);
        let t102 = T::from_f64(1.0) / t101;
        let t103 = t58 * t102;
        let t104 = t100 * (t18 * u_edge_right + T::from_f64(8.0) * t60 * t103);
        let step_delta_edge_right = delta_edge_right.step();
        let t105 = -f1 + t97 + t104;
        let t106 = t31 * t89;
        let t107 = t17 * t85;
        let t108 = t34 * t100;
        let t109 = delta_rate_edge_left * t95 * neg_delta_edge_left;
        let t110 = t48 * t91;
        let t111 = neg_delta_rate_edge_right * t102 * delta_edge_right;
        let t112 = t61 - step_delta_edge_right;
        let t113 = t85 * (step_delta_edge_left - t93);
        let t114 = k_edge * (t113 + t100 * t112);
        let t115 = T::from_f64(0.03125) * (t63 * (t107 - t108)) * t64;
        let t116 = t110 * t89;
        let delta_wall_left = r - t1 - x - t21 - t68;
        let pen_wall_left = delta_wall_left.max0();
        let t117 = pen_wall_left * pen_wall_left.sqrt();
        let step_delta_wall_left = delta_wall_left.step();
        let t118 = t109.max0();
        let t119 = t111.max0();
        let t120 = t35 * t117;
        let t121 = t75 * t117;
        SMatrix::<
            T,
            12,
            1,
        >::from_row_slice(
            &[
                xdot,
                zdot,
                thetadot,
                (t10 * (t114 + t115)
                    + k_wall
                        * (t117 * (t67 - T::from_f64(1.0) + step_delta_wall_left)
                            - t89 * (-T::from_f64(1.0) + step_delta_wall_right + t79))
                    - sin_theta * t105
                    + T::from_f64(0.03125) * (t74 * (t120 - t106)) * t64 + t0) / m,
                -(sin_theta * (t114 + t115 + f2) + cos_theta * t105
                    + t32 * (u_wall_right * t89 + u_wall_left * t117)
                    + T::from_f64(8.0) * (t49 * (t121 - t116)) * t59) / m,
                (m_2 + k_edge * (-(t113 * t86) - t56 * t112 * t100)
                    + t64
                        * (T::from_f64(0.03125) * t74 * (t120 * t66 - t106 * t78)
                            - T::from_f64(0.03125) * t63 * (t107 * t86 - t108 * t56))
                    + k_wall
                        * (t66 * (step_delta_wall_left - t69) * t117
                            - t78 * (step_delta_wall_right - t98) * t89)
                    - t97 * (sin_theta * t81 + cos_theta * t82)
                    + t40 * t89 * (t32 * u_wall_right - T::from_f64(8.0) * t62 * t110)
                    + t104 * (sin_theta * t52 + cos_theta * t53)
                    - t42 * t117 * (t32 * u_wall_left + T::from_f64(8.0) * t62 * t75))
                    / j,
                xdot * (f1 * sin_theta + t0) + zdot * (f1 * cos_theta - f2 * sin_theta)
                    + thetadot * m_2,
                mu
                    * (k_edge * (t107 * slip_edge_left_2 + t108 * slip_edge_right_2)
                        + k_wall
                            * (t106 * abs_slip_wall_right + t120 * slip_wall_left_2))
                    + t64
                        * (T::from_f64(0.125) * t63
                            * (t85 * t118 * u_edge_left.powi(4)
                                + t100 * t119 * u_edge_right.powi(4))
                            + T::from_f64(0.125) * t74
                                * (t89 * t99 * u_wall_right.powi(4)
                                    + t117 * t73 * u_wall_left.powi(4)))
                    + t59
                        * (T::from_f64(8.0) * t46
                            * (t96 * slip_edge_left * t85
                                + t103 * slip_edge_right * t100)
                            - T::from_f64(8.0) * t49
                                * (t116 * slip_wall_right - t121 * slip_wall_left))
                    - k_edge
                        * (delta_rate_edge_left * t85 * t93
                            - neg_delta_rate_edge_right * t100 * t61)
                    - k_wall
                        * (delta_rate_wall_right * t89 * t98
                            - neg_delta_rate_wall_left * t117 * t69),
                -t95
                    * (u_edge_left * (t17 * t118 - t109) - T::from_f64(8.0) * t47 * t88),
                -t91 * (T::from_f64(8.0) * t50 * t48 + u_wall_right * (t92 + t31 * t99)),
                -t102
                    * (u_edge_right * (t34 * t119 - t111)
                        - T::from_f64(8.0) * t47 * t58),
                -t71 * (u_wall_left * (t72 + t35 * t73) - T::from_f64(8.0) * t50 * t44),
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
    /// 546 add/sub, 1158 mul, 18 div, 12 sqrt, 10 transcendental, 44 branches; 465 `let`s.
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
        let t3 = T::from_f64(0.5) * theta;
        let (t4, t5) = t3.sin_cos();
        let t6 = t4 * t4;
        let t7 = r * sin_theta;
        let t8 = r * cos_theta;
        let t9 = zdot * sin_theta;
        let t10 = t4 * t5;
        let t11 = T::from_f64(1.0) - T::from_f64(2.0) * t6;
        let t12 = edge_ma * edge_mb;
        let t13 = t12.sqrt();
        let t14 = T::from_f64(1.5) * k_edge / (e_star * edge_sum);
        let t15 = t14.cbrt();
        let t16 = T::from_f64(1.0) / t12.sqrt();
        let t17 = t14.powf(-T::from_f64(1.0 / 3.0));
        let t18 = u_edge_left * u_edge_left;
        let t19 = mu * k_edge;
        let t20 = u_edge_left.powi(4);
        let t21 = l_c - rho_p;
        let t22 = r - rho_p;
        let t23 = sin_theta * t21;
        let t24 = rho_p * sin_theta;
        let t25 = l_c - rho_p + t24;
        let t26 = r - T::from_f64(2.0) * rho_p * t6;
        let t27 = sin_theta * t26;
        let t28 = cos_theta * t26;
        let t29 = sin_theta * t25;
        let t30 = cos_theta * t21;
        let t31 = wall_ma * wall_mb;
        let t32 = t31.sqrt();
        let t33 = T::from_f64(1.5) * k_wall / (e_star * wall_sum);
        let t34 = t33.cbrt();
        let t35 = T::from_f64(1.0) / t31.sqrt();
        let t36 = t33.powf(-T::from_f64(1.0 / 3.0));
        let t37 = u_wall_right * u_wall_right;
        let t38 = mu * k_wall;
        let t39 = u_wall_right.powi(4);
        let t40 = rho_h + t2 - x;
        let t41 = xdot * t11;
        let t42 = u_edge_right * u_edge_right;
        let t43 = u_edge_right.powi(4);
        let t44 = u_wall_left * u_wall_left;
        let t45 = u_wall_left.powi(4);
        let t46 = T::from_f64(1.0) / m;
        let t47 = T::from_f64(1.0) / j;
        let t48 = sin_theta * sin_theta;
        let t49 = t11 * t11;
        let t50 = zdot * cos_theta;
        let t51 = z - rho_h;
        let t52 = sin_theta * t51;
        let t53 = cos_theta * t51;
        let t54 = t29 + t28;
        let t55 = thetadot * t54;
        let t56 = -l_c + rho_p + t24;
        let t57 = sin_theta * t56;
        let t58 = t57 + t28;
        let t59 = thetadot * t58;
        let slip_wall_left = zdot + t59;
        let slip_wall_left_2 = slip_wall_left.abs();
        let t60 = zdot + t59 - u_wall_left * slip_wall_left_2;
        let t61 = g_star / mu;
        let t62 = t13 * t15;
        let t63 = t61 * (t62 / k_edge);
        let slip_wall_right = zdot - t55;
        let abs_slip_wall_right = slip_wall_right.abs();
        let t64 = -zdot + t55 + u_wall_right * abs_slip_wall_right;
        let t65 = t32 * t34;
        let t66 = t61 * (t65 / k_wall);
        let t67 = sin_theta * t40 - t53;
        let t68 = -cos_theta * t67;
        let t69 = t7 + t68;
        let t70 = xdot - thetadot * t69;
        let t71 = sin_theta * t67;
        let t72 = t8 + t71;
        let t73 = zdot - thetadot * t72;
        let t74 = sin_theta * t70;
        let t75 = cos_theta * t73;
        let slip_edge_right = t74 + t75;
        let t76 = t53 - T::from_f64(2.0) * t10 * t40;
        let t77 = thetadot * t76;
        let slip_edge_right_2 = slip_edge_right.abs();
        let t78 = t74 + t75 - u_edge_right * slip_edge_right_2;
        let t79 = sin_theta * t69;
        let t80 = cos_theta * t72;
        let t81 = t79 + t80;
        let t82 = t19 * u_edge_left;
        let t83 = g_star * tau_t;
        let t84 = t19 * u_edge_right;
        let t85 = t38 * u_wall_right;
        let t86 = t38 * u_wall_left;
        let t87 = t17 * (k_edge * k_edge) * t16;
        let t88 = mu * mu / g_star;
        let t89 = T::from_f64(2.0) * (t10 * t22);
        let t90 = t30 + t89;
        let neg_delta_rate_wall_left = xdot + thetadot * t90;
        let t91 = T::from_f64(2.0) * (t6 * t22);
        let neg_delta_wall_left = t2 - r + x + t23 + t91;
        let t92 = delta_floor.hypot(neg_delta_wall_left);
        let t93 = T::from_f64(1.0) / t92;
        let t94 = neg_delta_rate_wall_left * t93 * neg_delta_wall_left;
        let t95 = (-t94).max0();
        let t96 = t44 * t95;
        let t97 = t36 * (k_wall * k_wall) * t35;
        let t98 = -rho_h - t2 - x;
        let t99 = t98 * t6;
        let t100 = t30 - t89;
        let delta_rate_wall_right = xdot + thetadot * t100;
        let t101 = hc_alpha * delta_rate_wall_right;
        let t102 = T::from_f64(1.0) + t101;
        let t103 = t102.max0();
        let delta_edge_left = r - t2 - x + t52 - T::from_f64(2.0) * t99;
        let t104 = sin_theta * t98 - t53;
        let t105 = cos_theta * t104;
        let t106 = t105 + t7;
        let t107 = xdot + thetadot * t106;
        let t108 = sin_theta * t107;
        let pen_edge_left = delta_edge_left.max0();
        let t109 = pen_edge_left * pen_edge_left.sqrt();
        let t110 = t53 - T::from_f64(2.0) * t10 * t98;
        let t111 = thetadot * t110;
        let step_delta_edge_left = delta_edge_left.step();
        let t112 = sin_theta * t106;
        let delta_wall_right = r - t2 + x + t23 - t91;
        let pen_wall_right = delta_wall_right.max0();
        let t113 = pen_wall_right * pen_wall_right.sqrt();
        let t114 = delta_floor.hypot(delta_wall_right);
        let t115 = T::from_f64(1.0) / t114;
        let t116 = delta_rate_wall_right * t115 * delta_wall_right;
        let step_delta_wall_right = delta_wall_right.step();
        let neg_delta_edge_left = t2 - r + x - t52 + T::from_f64(2.0) * t99;
        let t117 = delta_floor.hypot(neg_delta_edge_left);
        let t118 = T::from_f64(1.0) / t117;
        let t119 = T::from_f64(1.0) - t103;
        let t120 = (-t116).max0();
        let t121 = t37 * t120;
        let delta_edge_right = r - t2 + x - t52 + T::from_f64(2.0) * t6 * t40;
        let pen_edge_right = delta_edge_right.max0();
        let t122 = pen_edge_right * pen_edge_right.sqrt();
        let t123 = delta_floor.hypot(delta_edge_right);
        let t124 = T::from_f64(1.0) / t123;
        let step_delta_edge_right = delta_edge_right.step();
        let t125 = t18 * t109;
        let t126 = t42 * t122;
        let t127 = t125 - t126;
        let delta_wall_left = r - t2 - x - t23 - t91;
        let pen_wall_left = delta_wall_left.max0();
        let t128 = pen_wall_left * pen_wall_left.sqrt();
        let step_delta_wall_left = delta_wall_left.step();
        let sign_slip_wall_left = slip_wall_left.sign();
        let t129 = r - (t52 + cos_theta * t40);
        let t130 = t6 - t5 * t5;
        let t131 = u_wall_left * sign_slip_wall_left;
        let t132 = zdot * t48;
        let t133 = t52 - t40 * t130;
        let t134 = t22 * t130;
        let t135 = t134 + t23;
        let t136 = T::from_f64(2.0) * t10 * xdot;
        let neg_delta_rate_edge_right = -t41 + t9 + t77;
        let t137 = hc_alpha * neg_delta_rate_edge_right;
        let t138 = T::from_f64(1.0) - t137;
        let t139 = t138.max0();
        let t140 = t62 * t83;
        let t141 = T::from_f64(1.0) - t139;
        let t142 = t83 * t65;
        let t143 = t87 * t88;
        let t144 = hc_alpha * neg_delta_rate_wall_left;
        let t145 = T::from_f64(1.0) - t144;
        let t146 = t145.max0();
        let t147 = T::from_f64(1.0) - t146;
        let t148 = t142 * t93;
        let t149 = t148 * t60;
        let t150 = t138.step();
        let sign_slip_edge_right = slip_edge_right.sign();
        let t151 = u_edge_right * sign_slip_edge_right;
        let t152 = t79 + t80 - t151 * t81;
        let sign_slip_wall_right = slip_wall_right.sign();
        let t153 = u_wall_right * sign_slip_wall_right;
        let t154 = T::from_f64(1.0) - t153;
        let t155 = T::from_f64(1.0) - t131;
        let t156 = t29 + t28 - t153 * t54;
        let t157 = t57 + t28 - t131 * t58;
        let t158 = t76 * t76;
        let t159 = t88 * t97;
        let t160 = thetadot * hc_alpha;
        let t161 = t10 * t160;
        let t162 = T::from_f64(1.5) - T::from_f64(1.5) * t139;
        let t163 = t160 * cos_theta;
        let t164 = cos_theta * t129 + t71;
        let t165 = sin_theta * (thetadot * t164 + t73);
        let t166 = k_edge * t11;
        let t167 = t143 * u_edge_left;
        let t168 = t143 * u_edge_right;
        let t169 = rho_p * (sin_theta - T::from_f64(2.0) * t10);
        let t170 = t10 * thetadot;
        let t171 = slip_edge_right * t78;
        let t172 = sin_theta * (t41 - t77);
        let t173 = t41 - t9;
        let t174 = t76 * t173;
        let t175 = thetadot * t158;
        let t176 = t141 + t137 * t150;
        let t177 = slip_wall_right * t154 - t64;
        let t178 = t60 + slip_wall_left * t155;
        let t179 = t37 * sign_slip_wall_right;
        let t180 = t44 * sign_slip_wall_left;
        let t181 = t66 * t154;
        let t182 = t136 + t50 - thetadot * t133;
        let t183 = sin_theta * t129 + t68;
        let t184 = cos_theta * (t70 + thetadot * t183);
        let t185 = t165 - t184;
        let t186 = t184 - t165 + t151 * t185;
        let t187 = T::from_f64(1.0) - t151;
        let t188 = t27 - cos_theta * (t169 + t25);
        let t189 = t27 - cos_theta * (t169 + t56);
        let t190 = thetadot * t188;
        let t191 = t63 * sin_theta;
        let t192 = t63 * cos_theta;
        let t193 = t66 * t155;
        let t194 = thetadot * t189;
        let t195 = t145.step();
        let t196 = t90 * t90;
        let t197 = T::from_f64(1.5) - T::from_f64(1.5) * t146;
        let t198 = T::from_f64(1.0) / (t92 * t92 * t92);
        let t199 = neg_delta_wall_left * t198;
        let t200 = t38 - T::from_f64(8.0) * t148 * slip_wall_left_2;
        let t201 = u_wall_left * t90;
        let t202 = t198 * (neg_delta_wall_left * neg_delta_wall_left);
        let t203 = t93 - t202;
        let t204 = xdot * t203;
        let t205 = t90 * t203 * thetadot;
        let t206 = t204 + t205;
        let t207 = (-t94).step();
        let t208 = xdot * t90;
        let t209 = t202 * (t208 + thetadot * t196);
        let t210 = t144 * t195;
        let t211 = t199 * (u_wall_left * (t94 + t96) - T::from_f64(8.0) * t66 * t60);
        let t212 = t44 * t207;
        let t213 = t93 * (T::from_f64(1.0) - t212) * neg_delta_wall_left;
        let t214 = u_wall_left * t93;
        let t215 = t23 - t134;
        let t216 = t93 * (t208 - thetadot * (neg_delta_wall_left * t135 - t196));
        let t217 = t216 - t209;
        let t218 = r + cos_theta * t98 + t52;
        let t219 = t52 - t98 * t130;
        let t220 = t102.step();
        let t221 = t100 * t100;
        let t222 = sin_theta * t104;
        let t223 = t8 - t222;
        let t224 = zdot + thetadot * t223;
        let t225 = cos_theta * t224;
        let slip_edge_left = t108 + t225;
        let delta_rate_edge_left = -t41 + t9 + t111;
        let t226 = hc_alpha * delta_rate_edge_left;
        let t227 = T::from_f64(1.0) + t226;
        let t228 = t227.max0();
        let slip_edge_left_2 = slip_edge_left.abs();
        let t229 = t108 + t225 - u_edge_left * slip_edge_left_2;
        let t230 = cos_theta * t223;
        let t231 = t112 + t230;
        let t232 = T::from_f64(1.0) - t228;
        let t233 = t109 * t232;
        let t234 = t140 * t118;
        let t235 = t234 * t229;
        let t236 = t109 * (t82 + T::from_f64(8.0) * t235);
        let t237 = t140 * t124;
        let t238 = t237 * t78;
        let t239 = t122 * (t84 + T::from_f64(8.0) * t238);
        let t240 = delta_rate_edge_left * t118 * neg_delta_edge_left;
        let t241 = t142 * t115;
        let t242 = t241 * t64;
        let t243 = neg_delta_rate_edge_right * t124 * delta_edge_right;
        let t244 = t109 * (step_delta_edge_left - t232);
        let t245 = t122 * (t141 - step_delta_edge_right);
        let t246 = t244 + t245;
        let t247 = t240.max0();
        let t248 = t18 * t247;
        let t249 = t243.max0();
        let t250 = t42 * t249;
        let sqrt_pen_edge_left = pen_edge_left.sqrt();
        let t251 = t227.step();
        let sign_slip_edge_left = slip_edge_left.sign();
        let t252 = u_edge_left * sign_slip_edge_left;
        let t253 = t112 + t230 - t252 * t231;
        let t254 = t110 * t110;
        let sqrt_pen_wall_right = pen_wall_right.sqrt();
        let t255 = step_delta_wall_right * step_delta_wall_right;
        let t256 = t46 * t113;
        let t257 = T::from_f64(1.0) / (t114 * t114 * t114);
        let t258 = delta_wall_right * delta_wall_right;
        let t259 = T::from_f64(1.5) - T::from_f64(1.5) * t228;
        let t260 = step_delta_edge_left * sqrt_pen_edge_left;
        let t261 = t260 * t259;
        let t262 = t109 * t251;
        let t263 = t261 * t11 + T::from_f64(2.0) * t161 * t262;
        let t264 = T::from_f64(1.0) / (t117 * t117 * t117);
        let t265 = neg_delta_edge_left * t264;
        let t266 = t265 * t109;
        let t267 = t260 * (T::from_f64(1.5) * t82 + T::from_f64(12.0) * t235)
            + T::from_f64(8.0) * t266 * t140 * t229;
        let sqrt_pen_edge_right = pen_edge_right.sqrt();
        let t268 = step_delta_edge_right * sqrt_pen_edge_right;
        let t269 = t268 * t162;
        let t270 = t122 * t150;
        let t271 = t269 * t11 + T::from_f64(2.0) * t161 * t270;
        let t272 = T::from_f64(1.0) / (t123 * t123 * t123);
        let t273 = T::from_f64(1.5) - T::from_f64(1.5) * t103;
        let t274 = -T::from_f64(1.5) * t255;
        let t275 = sqrt_pen_wall_right * (step_delta_wall_right * t273 + t274);
        let t276 = sqrt_pen_edge_left * (step_delta_edge_left * step_delta_edge_left);
        let t277 = sqrt_pen_edge_right * (step_delta_edge_right * step_delta_edge_right);
        let t278 = t276 + t277;
        let t279 = t260 * t18;
        let t280 = t268 * t42;
        let t281 = t279 + t280;
        let t282 = t143 * t281;
        let t283 = sin_theta * t218 + t105;
        let t284 = cos_theta * (thetadot * t283 - t107);
        let t285 = t276 * t110 + t277 * t76;
        let t286 = t260 * t110;
        let t287 = t268 * t76;
        let t288 = t286 * t18 + t287 * t42;
        let t289 = t262 + t270;
        let t290 = t220 * t113;
        let t291 = hc_alpha * t289;
        let t292 = t262 * t110 + t270 * t76;
        let t293 = t19 - T::from_f64(8.0) * t234 * slip_edge_left_2;
        let t294 = t46 * t109;
        let t295 = t19 - T::from_f64(8.0) * t237 * slip_edge_right_2;
        let t296 = t46 * t122;
        let t297 = t113 * t115;
        let t298 = t297 * t154;
        let t299 = t109 * t118;
        let t300 = t122 * t124;
        let t301 = t299 * t253 - t300 * t152;
        let t302 = t297 * t156;
        let t303 = sin_theta * t292 * hc_alpha * k_edge;
        let t304 = t38 - T::from_f64(8.0) * t241 * abs_slip_wall_right;
        let t305 = t299 * t231;
        let t306 = t300 * t81;
        let t307 = u_wall_right * t100;
        let t308 = t170 * neg_delta_edge_left * t118;
        let t309 = t264 * (neg_delta_edge_left * neg_delta_edge_left);
        let t310 = t118 - t309;
        let t311 = t9 * t310;
        let t312 = t111 * t310;
        let t313 = t115 - t257 * t258;
        let t314 = xdot * t313;
        let t315 = t100 * t313 * thetadot;
        let t316 = t314 + t315;
        let t317 = (-t116).step();
        let t318 = T::from_f64(2.0) * t170 * delta_edge_right * t124;
        let t319 = t272 * (delta_edge_right * delta_edge_right);
        let t320 = t124 - t319;
        let t321 = t11 * (t320 * (t9 + t77));
        let t322 = slip_edge_left * t229;
        let t323 = delta_edge_right * t272;
        let t324 = t323 * t122;
        let t325 = step_delta_wall_right * sqrt_pen_wall_right;
        let t326 = t122 * t141;
        let t327 = t233 - t326;
        let t328 = sin_theta * (t41 - t111);
        let t329 = t118 * (t328 - t132 + thetadot * cos_theta * neg_delta_edge_left);
        let t330 = t124 * (t172 - t132 + thetadot * cos_theta * delta_edge_right);
        let t331 = t110 * t173;
        let t332 = thetadot * t254;
        let t333 = xdot * t100;
        let t334 = delta_wall_right * t257;
        let t335 = t334 * t113;
        let t336 = t64 * (T::from_f64(8.0) * t335 - T::from_f64(12.0) * t325 * t115);
        let t337 = t336 * t100;
        let t338 = t325 * t100;
        let t339 = t226 * t251 - t232;
        let t340 = t39 * delta_wall_right * (t297 * t317);
        let t341 = t125 * sign_slip_edge_left + t126 * sign_slip_edge_right;
        let t342 = t101 * t220;
        let t343 = t49 * t310 * xdot;
        let t344 = t334 * (T::from_f64(8.0) * t66 * t64 + u_wall_right * (t116 + t121));
        let t345 = t37 * t317;
        let t346 = t115 * (T::from_f64(1.0) - t345) * delta_wall_right;
        let t347 = u_wall_right * t115;
        let t348 = T::from_f64(8.0) * t324 * t140 * t78
            - t268 * (T::from_f64(1.5) * t84 + T::from_f64(12.0) * t238);
        let t349 = t325 * t37;
        let t350 = t267 + t348;
        let t351 = sin_theta * t350;
        let t352 = t163 * t262 - t261 * sin_theta;
        let t353 = t163 * t270 - t269 * sin_theta;
        let t354 = t222 - cos_theta * t218;
        let t355 = sin_theta * (thetadot * t354 + t224);
        let t356 = t284 + t355;
        let t357 = t284 + t355 - t252 * t356;
        let t358 = T::from_f64(8.0) * t299 * t140 * t357 - t110 * t267;
        let t359 = t270 * hc_alpha * t182 - t287 * t162;
        let t360 = t76 * t348 + T::from_f64(8.0) * t300 * t140 * t186;
        let t361 = t10 * (-(T::from_f64(2.0) * t244) - T::from_f64(2.0) * t245);
        let t362 = T::from_f64(1.0) - t252;
        let t363 = t299 * t362 + t300 * t187;
        let t364 = t140 * t363;
        let t365 = sin_theta * t46
            * (t166 * t291 - T::from_f64(8.0) * (t364 * cos_theta));
        let t366 = t325 * (T::from_f64(1.5) * t85 - T::from_f64(12.0) * t242)
            + T::from_f64(8.0) * t335 * t142 * t64;
        let t367 = t231 * t267 - t81 * t348;
        let t368 = t305 * t362 - t306 * t187;
        let t369 = t11 * (t311 + t312) - t343 + T::from_f64(2.0) * t308;
        let t370 = -(t49 * t320) * xdot;
        let t371 = t321 + t370 + t318;
        let t372 = t309 * (t132 - t328);
        let t373 = t329 + t372;
        let t374 = t319 * (t132 - t172);
        let t375 = t330 + t374;
        let t376 = t309 * (t332 - t331);
        let t377 = t258 * (t333 + thetadot * t221) * t257;
        let t378 = t319 * (t175 - t174);
        let t379 = t299 * (t229 + slip_edge_left * t362);
        let t380 = t300 * (t78 + slip_edge_right * t187);
        let sqrt_pen_wall_left = pen_wall_left.sqrt();
        let t381 = step_delta_wall_left * step_delta_wall_left;
        let t382 = t46 * t128;
        let t383 = -T::from_f64(1.5) * t381;
        let t384 = sqrt_pen_wall_left * (step_delta_wall_left * t197 + t383);
        let t385 = t128 * t195;
        let t386 = t385 * t135;
        let t387 = t199 * t128;
        let t388 = step_delta_wall_left * sqrt_pen_wall_left;
        let t389 = t60 * (T::from_f64(12.0) * t388 * t93 + T::from_f64(8.0) * t387);
        let t390 = t389 * t90;
        let t391 = t128 * t93;
        let t392 = t391 * t155;
        let t393 = t391 * t157;
        let t394 = t388 * (T::from_f64(1.5) * t86 + T::from_f64(12.0) * t149)
            + T::from_f64(8.0) * t387 * t142 * t60;
        let t395 = t388 * t90;
        let t396 = t395 * t197 + t386 * t160;
        let t397 = t240.step();
        let t398 = t243.step();
        let t399 = t140
            * (t322 * (T::from_f64(12.0) * t260 * t118 + T::from_f64(8.0) * t266)
                + t171 * (T::from_f64(8.0) * t324 - T::from_f64(12.0) * t268 * t124))
            + T::from_f64(1.5) * t19
                * (t279 * slip_edge_left_2 - t280 * slip_edge_right_2)
            + T::from_f64(0.1875) * t143 * (t260 * t247 * t20 - t268 * t249 * t43);
        let t400 = t20 * t397;
        let t401 = t400 * (t299 * neg_delta_edge_left);
        let t402 = t43 * t398;
        let t403 = t402 * (t300 * delta_edge_right);
        let t404 = k_edge * (t109 * t339 + t122 * t176)
            + T::from_f64(0.125) * t143 * (t401 + t403);
        let t405 = t45 * neg_delta_wall_left * (t391 * t207);
        let t406 = t18 * t397;
        let t407 = u_edge_left * t118;
        let t408 = t407 * (neg_delta_edge_left * (T::from_f64(1.0) - t406));
        let t409 = t42 * t398;
        let t410 = u_edge_right * t124;
        let t411 = t410 * (delta_edge_right * (T::from_f64(1.0) - t409));
        let t412 = t388 * t44;
        let t413 = t136 + t50 - thetadot * t219;
        let t414 = t262 * hc_alpha * t413 - t286 * t259;
        let t415 = t290 * t215;
        let t416 = t88
            * (t87
                * (T::from_f64(0.046875) * t288 * t11 - T::from_f64(0.0625) * t10 * t127)
                - T::from_f64(0.046875) * t97 * (t338 * t37 + t395 * t44));
        let t417 = hc_alpha * (k_wall * (t290 * t100 + t385 * t90) - t166 * t292);
        let t418 = t338 * t273 + t415 * t160;
        let t419 = t400 * t109;
        let t420 = t402 * t122;
        let t421 = t118 * (neg_delta_edge_left * t413 + t331 - t332);
        let t422 = t421 + t376;
        let t423 = t115 * (thetadot * (t221 - delta_wall_right * t215) + t333);
        let t424 = t423 - t377;
        let t425 = t124 * (delta_edge_right * t182 + t174 - t175);
        let t426 = t425 + t378;
        let t427 = t265 * (u_edge_left * (t248 - t240) - T::from_f64(8.0) * t63 * t229);
        let t428 = t323 * (u_edge_right * (t250 - t243) - T::from_f64(8.0) * t63 * t78);
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
                t46
                    * (k_wall * (t275 + t384)
                        + k_edge * (t11 * (t263 + t271) - T::from_f64(1.5) * t278 * t49)
                        + t88
                            * (-(T::from_f64(0.046875) * (t49 * t281) * t87)
                                - T::from_f64(0.046875) * t97 * (t349 + t412))
                        + t351 * t11),
                t46
                    * (t11
                        * (k_edge * (T::from_f64(1.5) * t278 * sin_theta + t352 + t353)
                            + T::from_f64(0.046875) * t282 * sin_theta) - t48 * t350),
                t46
                    * (k_edge * (t11 * (T::from_f64(1.5) * t285 + t414 + t359) + t361)
                        + k_wall * (t275 * t100 + t384 * t90 + t160 * (t415 + t386))
                        + t416 - cos_theta * (-f1 + t236 + t239)
                        - sin_theta * (f2 - t358 + t360)),
                -t46
                    * (hc_alpha * (t49 * t289 * k_edge + k_wall * (t290 + t385))
                        + T::from_f64(8.0) * t364 * t48),
                t365,
                -t46 * (t417 + T::from_f64(8.0) * t140 * t301 * sin_theta),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t294 * (T::from_f64(0.0625) * t167 * t11 - sin_theta * t293),
                -T::from_f64(0.0625) * t256 * t159 * u_wall_right,
                -t296 * (T::from_f64(0.0625) * t168 * t11 + sin_theta * t295),
                T::from_f64(0.0625) * t382 * t159 * u_wall_left,
                t46
                    * (-(sin_theta
                        * (k_edge * (-(T::from_f64(1.5) * t278 * t11) + t263 + t271)
                            - T::from_f64(0.046875) * t282 * t11)) - t142 * (t336 - t389)
                        + t11 * t350 * cos_theta
                        - T::from_f64(1.5) * t38
                            * (t325 * u_wall_right - t388 * u_wall_left)),
                -t46
                    * (k_edge
                        * (T::from_f64(1.5) * t278 * t48 + sin_theta * (t352 + t353))
                        + T::from_f64(0.046875) * (t48 * t281) * t143
                        + t351 * cos_theta),
                t46
                    * (sin_theta
                        * (k_edge * (-(T::from_f64(1.5) * t285) - t414 - t359)
                            - T::from_f64(0.046875) * t143 * t288 - f1 + t236 + t239)
                        - cos_theta
                            * (k_edge * t246 + T::from_f64(0.03125) * t143 * t127 + f2
                                - t358 + t360)
                        + t142
                            * (-t337
                                + T::from_f64(8.0) * (t392 * t189 - t298 * t188) * thetadot
                                + t390)
                        - T::from_f64(1.5) * t38
                            * (t338 * u_wall_right - t395 * u_wall_left)),
                t365,
                -t46
                    * (t83
                        * (T::from_f64(8.0) * (t62 * t363) * (cos_theta * cos_theta)
                            + T::from_f64(8.0) * t65 * (t298 + t392))
                        + t291 * t48 * k_edge),
                -t46
                    * (t83
                        * (T::from_f64(8.0) * (t62 * t301) * cos_theta
                            + T::from_f64(8.0) * t65 * (t393 - t302)) + t303),
                T::from_f64(0.0),
                T::from_f64(0.0),
                -t294 * (T::from_f64(0.0625) * t167 * sin_theta + cos_theta * t293),
                -t256 * t304,
                t296 * (T::from_f64(0.0625) * t168 * sin_theta - cos_theta * t295),
                -t382 * t200,
                t47
                    * (-(k_edge
                        * (-t361 - T::from_f64(1.5) * t285 * t11 + t110 * t263
                            + t76 * t271)) + t416
                        + k_wall
                            * (sqrt_pen_wall_right
                                * (t274 + t273 * step_delta_wall_right) * t100
                                + sqrt_pen_wall_left * (t383 + t197 * step_delta_wall_left)
                                    * t90) + t11 * t367 + t54 * t366 + t58 * t394),
                -t47
                    * (k_edge
                        * (cos_theta * t246 + T::from_f64(1.5) * t285 * sin_theta
                            + t110 * t352 + t76 * t353)
                        - t143
                            * (-(T::from_f64(0.03125) * t127 * cos_theta)
                                - T::from_f64(0.046875) * t288 * sin_theta)
                        + sin_theta * t367),
                t47
                    * (-(k_edge
                        * (-(t244 * t219) - t245 * t133
                            + T::from_f64(1.5) * (t276 * t254 + t277 * t158)
                            + t110 * t414 + t76 * t359))
                        - t88
                            * (-(t87
                                * (t18
                                    * (T::from_f64(0.03125) * t109 * t219
                                        - T::from_f64(0.046875) * t260 * t254)
                                    - t42
                                        * (T::from_f64(0.046875) * t268 * t158
                                            + T::from_f64(0.03125) * t122 * t133)))
                                - t97
                                    * (t37
                                        * (T::from_f64(0.03125) * t113 * t215
                                            - T::from_f64(0.046875) * t325 * t221)
                                        - t44
                                            * (T::from_f64(0.046875) * t388 * t196
                                                + T::from_f64(0.03125) * t128 * t135)))
                        - k_wall
                            * (-((step_delta_wall_right - t119) * t215 * t113)
                                + (step_delta_wall_left - t147) * t135 * t128
                                + T::from_f64(1.5)
                                    * (sqrt_pen_wall_right * t255 * t221
                                        + sqrt_pen_wall_left * t381 * t196) - t100 * t418
                                - t90 * t396) + t231 * t358
                        + t236 * (sin_theta * (t354 + t223) - cos_theta * (t106 - t283))
                        - t113 * (t85 - T::from_f64(8.0) * t242) * t188
                        + t54 * (t100 * t366 + T::from_f64(8.0) * t190 * t298 * t142)
                        + t81 * t360
                        - t239 * (sin_theta * (t72 - t164) - cos_theta * (t69 - t183))
                        + t128 * (t86 + T::from_f64(8.0) * t149) * t189
                        + t58 * (t90 * t394 + T::from_f64(8.0) * t194 * t392 * t142)),
                -t47 * (t417 + T::from_f64(8.0) * (sin_theta * t368) * t140),
                -t47
                    * (t83
                        * (T::from_f64(8.0) * (cos_theta * t368) * t62
                            - T::from_f64(8.0) * t65 * (t298 * t54 - t392 * t58))
                        + t303),
                -t47
                    * (hc_alpha
                        * (k_edge * (t262 * t254 + t270 * t158)
                            + k_wall * (t290 * t221 + t385 * t196))
                        + t83
                            * (T::from_f64(8.0) * t62 * (t305 * t253 + t306 * t152)
                                + T::from_f64(8.0) * t65 * (t302 * t54 + t393 * t58))),
                T::from_f64(0.0),
                T::from_f64(0.0),
                -(t109 * (T::from_f64(0.0625) * t167 * t110 + t231 * t293)) * t47,
                -(t113 * (T::from_f64(0.0625) * t307 * t159 - t54 * t304)) * t47,
                t122 * (T::from_f64(0.0625) * t168 * t76 + t81 * t295) * t47,
                t128 * (T::from_f64(0.0625) * t201 * t159 - t58 * t200) * t47,
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
                -(t11 * t399)
                    - t88
                        * (t97
                            * (t39
                                * (T::from_f64(0.125) * t113 * t316 * t317
                                    - T::from_f64(0.1875) * t325 * t120)
                                + t45
                                    * (T::from_f64(0.1875) * t388 * t95
                                        + T::from_f64(0.125) * t128 * t206 * t207))
                            - T::from_f64(0.125) * t87 * (t419 * t369 + t420 * t371))
                    + k_edge
                        * (-(T::from_f64(2.0) * t170 * t327)
                            + delta_rate_edge_left * t263
                            + neg_delta_rate_edge_right * t271)
                    - k_wall
                        * (-(T::from_f64(1.5)
                            * (t349 * abs_slip_wall_right - t412 * slip_wall_left_2)
                            * mu) + t325 * t273 * delta_rate_wall_right
                            + t388 * t197 * neg_delta_rate_wall_left)
                    - t142 * (t389 * slip_wall_left - t336 * slip_wall_right),
                sin_theta * t399
                    + k_edge
                        * (-(cos_theta * t327 * thetadot) + delta_rate_edge_left * t352
                            + neg_delta_rate_edge_right * t353)
                    + T::from_f64(0.125) * t143 * (t419 * t373 + t420 * t375),
                t83
                    * (t62
                        * (t109
                            * (T::from_f64(8.0) * t322 * t265 * t110
                                - T::from_f64(8.0) * (t229 * t356 + slip_edge_left * t357)
                                    * t118)
                            + t122
                                * (T::from_f64(8.0) * (slip_edge_right * t186 - t78 * t185)
                                    * t124 + T::from_f64(8.0) * t171 * t323 * t76)
                            + T::from_f64(12.0)
                                * (t322 * t286 * t118 - t171 * t287 * t124))
                        + t65
                            * (thetadot
                                * (T::from_f64(8.0) * (t177 * t188) * t297
                                    - T::from_f64(8.0) * (t178 * t189) * t391)
                                + t337 * slip_wall_right - t390 * slip_wall_left))
                    - mu
                        * (k_edge
                            * (t18
                                * (t109 * t356 * sign_slip_edge_left
                                    - T::from_f64(1.5) * t286 * slip_edge_left_2)
                                + t42
                                    * (T::from_f64(1.5) * t287 * slip_edge_right_2
                                        + t122 * t185 * sign_slip_edge_right))
                            - k_wall
                                * (t37
                                    * (T::from_f64(1.5) * t338 * abs_slip_wall_right
                                        + t190 * t113 * sign_slip_wall_right)
                                    - t44
                                        * (T::from_f64(1.5) * t395 * slip_wall_left_2
                                            + t194 * t128 * sign_slip_wall_left)))
                    + t88
                        * (t87
                            * (t20
                                * (T::from_f64(0.1875) * t286 * t247
                                    + T::from_f64(0.125) * t109 * t397 * t422)
                                - t43
                                    * (T::from_f64(0.1875) * t287 * t249
                                        - T::from_f64(0.125) * t122 * t398 * t426))
                            + t97
                                * (t39
                                    * (T::from_f64(0.1875) * t338 * t120
                                        - T::from_f64(0.125) * t113 * t317 * t424)
                                    - t45
                                        * (T::from_f64(0.1875) * t395 * t95
                                            + T::from_f64(0.125) * t128 * t207 * t217)))
                    + k_edge
                        * (-(t233 * t413) + delta_rate_edge_left * t414 + t326 * t182
                            + neg_delta_rate_edge_right * t359)
                    - k_wall
                        * (thetadot * (t128 * t147 * t135 - t113 * t119 * t215)
                            + delta_rate_wall_right * t418
                            + neg_delta_rate_wall_left * t396),
                -(t11 * t404)
                    + k_wall
                        * (t113 * (t103 - T::from_f64(1.0) + t342)
                            + t128 * (T::from_f64(1.0) - t146 + t210))
                    - sin_theta
                        * (t140 * (-(T::from_f64(8.0) * t379) - T::from_f64(8.0) * t380)
                            - t19 * t341) - T::from_f64(0.125) * t159 * (t340 + t405),
                t83
                    * (t65
                        * (T::from_f64(8.0) * t297 * t177
                            + T::from_f64(8.0) * t391 * t178)
                        + t62 * (T::from_f64(8.0) * t379 + T::from_f64(8.0) * t380)
                            * cos_theta) + sin_theta * t404
                    + mu
                        * (cos_theta * t341 * k_edge
                            + k_wall * (t179 * t113 + t180 * t128)),
                t83
                    * (t62
                        * (T::from_f64(8.0) * t299
                            * (t229 * t231 + slip_edge_left * t253)
                            - T::from_f64(8.0) * t300
                                * (t78 * t81 + slip_edge_right * t152))
                        + t65
                            * (T::from_f64(8.0) * t297
                                * (t54 * t64 - slip_wall_right * t156)
                                + T::from_f64(8.0) * t391
                                    * (t58 * t60 + slip_wall_left * t157)))
                    + k_edge
                        * (t109 * (t110 * t339 + mu * t18 * t231 * sign_slip_edge_left)
                            - t122
                                * (mu * t42 * t81 * sign_slip_edge_right - t76 * t176))
                    + k_wall
                        * (t128 * (t90 * (t147 + t210) + t180 * mu * t58)
                            - t113 * (t179 * mu * t54 - t100 * (t342 - t119)))
                    + t88
                        * (T::from_f64(0.125) * t87 * (t401 * t110 + t403 * t76)
                            - T::from_f64(0.125) * t97 * (t340 * t100 + t405 * t90)),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t109
                    * (slip_edge_left_2
                        * (T::from_f64(2.0) * t82
                            - T::from_f64(8.0) * t234 * slip_edge_left)
                        + T::from_f64(0.5) * t143 * t247
                            * (u_edge_left * u_edge_left * u_edge_left)),
                t113
                    * (abs_slip_wall_right
                        * (T::from_f64(2.0) * t85
                            - T::from_f64(8.0) * t241 * slip_wall_right)
                        + T::from_f64(0.5) * t159 * t120
                            * (u_wall_right * u_wall_right * u_wall_right)),
                t122
                    * (slip_edge_right_2
                        * (T::from_f64(2.0) * t84
                            - T::from_f64(8.0) * t237 * slip_edge_right)
                        + T::from_f64(0.5) * t143 * t249
                            * (u_edge_right * u_edge_right * u_edge_right)),
                t128
                    * (slip_wall_left_2
                        * (T::from_f64(2.0) * t86
                            - T::from_f64(8.0) * t148 * slip_wall_left)
                        + T::from_f64(0.5) * t159 * t95
                            * (u_wall_left * u_wall_left * u_wall_left)),
                t427 * t11
                    - t407
                        * (t11 * (-t311 - t312) + t343 - T::from_f64(2.0) * t308
                            + t406 * t369),
                t407 * (t329 + t372 - t406 * t373) - t427 * sin_theta,
                t118
                    * (u_edge_left * (t421 + t376 - t406 * t422)
                        - T::from_f64(8.0) * t63 * t357) - t427 * t110,
                -t118 * (t408 * t11 - T::from_f64(8.0) * t191 * t362),
                t118 * (T::from_f64(8.0) * t192 * t362 + t408 * sin_theta),
                t118 * (T::from_f64(8.0) * t63 * t253 + t408 * t110),
                T::from_f64(0.0),
                T::from_f64(0.0),
                -t118
                    * (-t240 + T::from_f64(8.0) * t63 * slip_edge_left_2
                        + T::from_f64(3.0) * t248),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t344 + t347 * (-t314 - t315 + t345 * t316),
                T::from_f64(0.0),
                t344 * t100
                    - t115
                        * (u_wall_right * (t423 - t377 - t345 * t424)
                            - T::from_f64(8.0) * t181 * t190),
                -t347 * t346,
                T::from_f64(8.0) * t181 * t115,
                -t115 * (T::from_f64(8.0) * t66 * t156 + t307 * t346),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                -t115
                    * (t116 + T::from_f64(8.0) * t66 * abs_slip_wall_right
                        + T::from_f64(3.0) * t121),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t428 * t11 + t410 * (t321 + t370 + t318 - t409 * t371),
                t410 * (t330 + t374 - t409 * t375) - t428 * sin_theta,
                t124
                    * (T::from_f64(8.0) * t63 * t186
                        + u_edge_right * (t425 + t378 - t409 * t426)) - t428 * t76,
                -t124 * (t411 * t11 - T::from_f64(8.0) * t191 * t187),
                t124 * (T::from_f64(8.0) * t192 * t187 + t411 * sin_theta),
                t124 * (t411 * t76 - T::from_f64(8.0) * t63 * t152),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                -t124
                    * (-t243 + T::from_f64(8.0) * t63 * slip_edge_right_2
                        + T::from_f64(3.0) * t250),
                T::from_f64(0.0),
                t211 + t214 * (-t204 - t205 + t212 * t206),
                T::from_f64(0.0),
                t211 * t90
                    + t93
                        * (u_wall_left * (-t216 + t209 + t212 * t217)
                            - T::from_f64(8.0) * t193 * t194),
                -t214 * t213,
                T::from_f64(8.0) * t193 * t93,
                -t93 * (t201 * t213 - T::from_f64(8.0) * t66 * t157),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                -t93
                    * (t94 + T::from_f64(8.0) * t66 * slip_wall_left_2
                        + T::from_f64(3.0) * t96),
            ],
        )
    }
    /// The outputs of [`contacts`].
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct ContactsOut<T: Real> {
        /// Normal force f on the peg, N, per contact (edge_left, wall_right, edge_right, wall_left).
        pub normal: SVector<T, 4>,
        /// Friction force along the contact tangent, N, per contact (edge_left, wall_right, edge_right, wall_left).
        pub friction: SVector<T, 4>,
        /// Penetration δ (negative: gap), m, per contact (edge_left, wall_right, edge_right, wall_left).
        pub delta: SVector<T, 4>,
        /// Sliding velocity of the peg's material point, m/s, per contact (edge_left, wall_right, edge_right, wall_left).
        pub slip: SVector<T, 4>,
        /// Semi-major axis a of the Hertz ellipse (9), m, per contact (edge_left, wall_right, edge_right, wall_left).
        pub a: SVector<T, 4>,
        /// Semi-minor axis b of the Hertz ellipse (10), m, per contact (edge_left, wall_right, edge_right, wall_left).
        pub b: SVector<T, 4>,
        /// Maximum Hertz pressure p₀ (11), Pa, per contact (edge_left, wall_right, edge_right, wall_left).
        pub p0: SVector<T, 4>,
    }
    /// Per contact (edge_left, wall_right, edge_right, wall_left): normal force f (N), friction force along the tangent (N), penetration delta (m), sliding velocity (m/s), contact ellipse a, b (m) and maximum pressure p0 (Pa) ((9)-(11)).
    ///
    /// # Inputs
    /// - `y` = (`x`, `z`, `theta`, `xdot`, `zdot`, `thetadot`, `work`, `dissipation`, `u_edge_left`, `u_wall_right`, `u_edge_right`, `u_wall_left`)
    /// - `p` = (`m`, `J`, `r`, `l_c`, `D`, `rho_p`, `rho_h`, `mu`, `v_s`, `k_edge`, `k_wall`, `f1`, `f2`, `M`, `e_star`, `edge_sum`, `edge_ma`, `edge_mb`, `edge_dstar`, `wall_sum`, `wall_ma`, `wall_mb`, `wall_dstar`, `hc_alpha`, `g_star`, `delta_floor`, `tau_t`)
    ///
    /// # Outputs
    /// The fields of [`ContactsOut`]:
    /// - `normal`: vector of 4
    /// - `friction`: vector of 4
    /// - `delta`: vector of 4
    /// - `slip`: vector of 4
    /// - `a`: vector of 4
    /// - `b`: vector of 4
    /// - `p0`: vector of 4
    ///
    /// # Cost
    /// 79 add/sub, 129 mul, 10 div, 6 sqrt, 12 transcendental, 8 branches; 85 `let`s.
    #[inline]
    pub fn contacts<T: Real>(y: &SVector<T, 12>, p: &SVector<T, 27>) -> ContactsOut<T> {
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
        let t1 = T::from_f64(0.5) * theta;
        let (t2, t3) = t1.sin_cos();
        let t4 = t2 * t2;
        let t5 = r * sin_theta;
        let t6 = r * cos_theta;
        let t7 = zdot * sin_theta;
        let t8 = t2 * t3;
        let t9 = (edge_ma * edge_mb).sqrt();
        let t10 = mu * k_edge;
        let t11 = l_c - rho_p;
        let t12 = r - rho_p;
        let t13 = sin_theta * t11;
        let t14 = rho_p * sin_theta;
        let t15 = cos_theta * (r - T::from_f64(2.0) * rho_p * t4);
        let t16 = cos_theta * t11;
        let t17 = (wall_ma * wall_mb).sqrt();
        let t18 = mu * k_wall;
        let t19 = rho_h + t0 - x;
        let t20 = z - rho_h;
        let t21 = sin_theta * t20;
        let t22 = -xdot * (T::from_f64(1.0) - T::from_f64(2.0) * t4);
        let t23 = cos_theta * t20;
        let t24 = thetadot * (sin_theta * (l_c - rho_p + t14) + t15);
        let t25 = thetadot * (sin_theta * (-l_c + rho_p + t14) + t15);
        let slip_wall_left = zdot + t25;
        let slip_wall_right = zdot - t24;
        let t26 = sin_theta * t19 - t23;
        let t27 = sin_theta * (xdot - thetadot * (t5 - cos_theta * t26));
        let t28 = cos_theta * (zdot - thetadot * (t6 + sin_theta * t26));
        let slip_edge_right = t27 + t28;
        let t29 = (T::from_f64(1.0)
            - hc_alpha * (t22 + t7 + thetadot * (t23 - T::from_f64(2.0) * t8 * t19)))
            .max0();
        let t30 = g_star * tau_t;
        let t31 = T::from_f64(2.0) * (t8 * t12);
        let t32 = (T::from_f64(1.0) - hc_alpha * (xdot + thetadot * (t16 + t31))).max0();
        let t33 = T::from_f64(2.0) * (t4 * t12);
        let t34 = delta_floor.hypot(t0 - r + x + t13 + t33);
        let t35 = -rho_h - t0 - x;
        let t36 = t35 * t4;
        let delta_rate_wall_right = xdot + thetadot * (t16 - t31);
        let t37 = (T::from_f64(1.0) + hc_alpha * delta_rate_wall_right).max0();
        let delta_edge_left = r - t0 - x + t21 - T::from_f64(2.0) * t36;
        let t38 = sin_theta * t35 - t23;
        let t39 = sin_theta * (xdot + thetadot * (cos_theta * t38 + t5));
        let t40 = cos_theta * (zdot + thetadot * (t6 - sin_theta * t38));
        let slip_edge_left = t39 + t40;
        let pen_edge_left = delta_edge_left.max0();
        let t41 = pen_edge_left * pen_edge_left.sqrt();
        let delta_rate_edge_left = t22 + t7
            + thetadot * (t23 - T::from_f64(2.0) * t8 * t35);
        let t42 = (T::from_f64(1.0) + hc_alpha * delta_rate_edge_left).max0();
        let delta_wall_right = r - t0 + x + t13 - t33;
        let pen_wall_right = delta_wall_right.max0();
        let t43 = pen_wall_right * pen_wall_right.sqrt();
        let t44 = delta_floor.hypot(delta_wall_right);
        let t45 = delta_floor.hypot(t0 - r + x - t21 + T::from_f64(2.0) * t36);
        let delta_edge_right = r - t0 + x - t21 + T::from_f64(2.0) * t4 * t19;
        let pen_edge_right = delta_edge_right.max0();
        let t46 = pen_edge_right * pen_edge_right.sqrt();
        let t47 = delta_floor.hypot(delta_edge_right);
        let delta_wall_left = r - t0 - x - t13 - t33;
        let pen_wall_left = delta_wall_left.max0();
        let t48 = pen_wall_left * pen_wall_left.sqrt();
        let t49 = k_edge / e_star / edge_sum;
        let t50 = (T::from_f64(1.5) * t49).cbrt();
        let t51 = k_wall / e_star / wall_sum;
        let t52 = (T::from_f64(1.5) * t51).cbrt();
        let t53 = t30 * (t9 * t50);
        let t54 = t30 * (t17 * t52);
        let t55 = e_star * edge_sum * (T::from_f64(1.0) / (edge_ma * edge_mb));
        let t56 = e_star * wall_sum * (T::from_f64(1.0) / (wall_ma * wall_mb));
        let t57 = t41 * t42;
        let normal_edge_left = t57 * k_edge;
        let t58 = t37 * t43;
        let normal_wall_right = t58 * k_wall;
        let t59 = (T::from_f64(1.5) * t57 * t49).cbrt();
        let t60 = (T::from_f64(1.5) * t58 * t51).cbrt();
        let t61 = t29 * t46;
        let normal_edge_right = t61 * k_edge;
        let t62 = (T::from_f64(1.5) * t61 * t49).cbrt();
        let t63 = t48 * t32;
        let normal_wall_left = t63 * k_wall;
        let t64 = (T::from_f64(1.5) * t63 * t51).cbrt();
        ContactsOut {
            normal: Vector4::new(
                normal_edge_left,
                normal_wall_right,
                normal_edge_right,
                normal_wall_left,
            ),
            friction: Vector4::new(
                -(t41
                    * (t10 * u_edge_left
                        + T::from_f64(8.0) * t53
                            * (t39 + t40 - u_edge_left * slip_edge_left.abs()) / t45)),
                -(t43
                    * (t18 * u_wall_right
                        - T::from_f64(8.0) * t54
                            * (-zdot + t24 + u_wall_right * slip_wall_right.abs())
                            / t44)),
                -(t46
                    * (t10 * u_edge_right
                        + T::from_f64(8.0) * t53
                            * (t27 + t28 - u_edge_right * slip_edge_right.abs()) / t47)),
                -(t48
                    * (t18 * u_wall_left
                        + T::from_f64(8.0) * t54
                            * (zdot + t25 - u_wall_left * slip_wall_left.abs()) / t34)),
            ),
            delta: Vector4::new(
                delta_edge_left,
                delta_wall_right,
                delta_edge_right,
                delta_wall_left,
            ),
            slip: Vector4::new(
                slip_edge_left,
                slip_wall_right,
                slip_edge_right,
                slip_wall_left,
            ),
            a: Vector4::new(edge_ma * t59, wall_ma * t60, edge_ma * t62, wall_ma * t64),
            b: Vector4::new(edge_mb * t59, wall_mb * t60, edge_mb * t62, wall_mb * t64),
            p0: Vector4::new(
                T::from_f64(0.3183098861837907) * t55 * t59,
                T::from_f64(0.3183098861837907) * t56 * t60,
                T::from_f64(0.3183098861837907) * t55 * t62,
                T::from_f64(0.3183098861837907) * t56 * t64,
            ),
        }
    }
    /// The outputs of [`energy`].
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct EnergyOut<T: Real> {
        /// Kinetic energy T (59), J.
        pub kinetic: T,
        /// Contact potential P (63), J.
        pub potential: T,
        /// Insertion depth l of the bottom face's centre, m.
        pub depth: T,
        /// Energy stored in the tangential springs, J.
        pub tangential: T,
    }
    /// Kinetic energy (59) (J), contact potential (63) (J), insertion depth of the bottom face (m) and stored tangential energy (J).
    ///
    /// # Inputs
    /// - `y` = (`x`, `z`, `theta`, `xdot`, `zdot`, `thetadot`, `work`, `dissipation`, `u_edge_left`, `u_wall_right`, `u_edge_right`, `u_wall_left`)
    /// - `p` = (`m`, `J`, `r`, `l_c`, `D`, `rho_p`, `rho_h`, `mu`, `v_s`, `k_edge`, `k_wall`, `f1`, `f2`, `M`, `e_star`, `edge_sum`, `edge_ma`, `edge_mb`, `edge_dstar`, `wall_sum`, `wall_ma`, `wall_mb`, `wall_dstar`, `hc_alpha`, `g_star`, `delta_floor`, `tau_t`)
    ///
    /// # Outputs
    /// The fields of [`EnergyOut`]:
    /// - `kinetic`: scalar
    /// - `potential`: scalar
    /// - `depth`: scalar
    /// - `tangential`: scalar
    ///
    /// # Cost
    /// 32 add/sub, 48 mul, 5 div, 2 sqrt, 8 transcendental, 4 branches; 24 `let`s.
    #[inline]
    pub fn energy<T: Real>(y: &SVector<T, 12>, p: &SVector<T, 27>) -> EnergyOut<T> {
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
        let t0 = T::from_f64(0.5) * d;
        let t1 = (T::from_f64(0.5) * theta).sin();
        let t2 = t1 * t1;
        let t3 = T::from_f64(1.0) / (edge_ma * edge_mb).sqrt();
        let t4 = (T::from_f64(1.5) * k_edge / (e_star * edge_sum))
            .powf(-T::from_f64(1.0 / 3.0));
        let t5 = sin_theta * (l_c - rho_p);
        let t6 = -T::from_f64(2.0) * t2 * (r - rho_p);
        let t7 = T::from_f64(1.0) / (wall_ma * wall_mb).sqrt();
        let t8 = (T::from_f64(1.5) * k_wall / (e_star * wall_sum))
            .powf(-T::from_f64(1.0 / 3.0));
        let t9 = sin_theta * (z - rho_h);
        let delta_edge_right = r - t0 + x - t9
            + T::from_f64(2.0) * t2 * (rho_h + t0 - x);
        let pen_edge_right = delta_edge_right.max0();
        let delta_edge_left = r - t0 - x + t9
            - T::from_f64(2.0) * (-rho_h - t0 - x) * t2;
        let pen_edge_left = delta_edge_left.max0();
        let delta_wall_right = r - t0 + x + t5 + t6;
        let pen_wall_right = delta_wall_right.max0();
        let t10 = pen_edge_left.powf(T::from_f64(2.5));
        let t11 = pen_wall_right.powf(T::from_f64(2.5));
        let delta_wall_left = r - t0 - x - t5 + t6;
        let pen_wall_left = delta_wall_left.max0();
        let t12 = pen_edge_right.powf(T::from_f64(2.5));
        let t13 = pen_wall_left.powf(T::from_f64(2.5));
        EnergyOut {
            kinetic: T::from_f64(0.5)
                * (m * (xdot * xdot + zdot * zdot) + j * (thetadot * thetadot)),
            potential: T::from_f64(0.4) * (t10 + t12) * k_edge
                + T::from_f64(0.4) * (t11 + t13) * k_wall,
            depth: z + l_c * cos_theta,
            tangential: (T::from_f64(0.0625)
                * (k_edge * k_edge
                    * (t10 * (u_edge_left * u_edge_left)
                        + t12 * (u_edge_right * u_edge_right)) * t4) * t3
                + T::from_f64(0.0625)
                    * (k_wall * k_wall
                        * (t11 * (u_wall_right * u_wall_right)
                            + t13 * (u_wall_left * u_wall_left)) * t8) * t7) / g_star
                * (mu * mu),
        }
    }
}
