// @generated readable copy of `pegdyn::generated::compliant_peg` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generator snapshot::

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
    /// The parameters of `compliant_peg`: the input `p` of its functions as a struct, one field per component in vector order (`From`/`Into` convert both ways).
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
    }
    impl<T> Params<T> {
        /// The field names in vector order: the symbol names of `p` ([`P_NAMES`]).
        pub const NAMES: [&'static str; 24] = P_NAMES;
    }
    impl<T: Real> From<Params<T>> for SVector<T, 24> {
        /// The `p` vector of these values, in field order.
        fn from(v: Params<T>) -> SVector<T, 24> {
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
            ])
        }
    }
    impl<T: Real> From<&SVector<T, 24>> for Params<T> {
        /// The fields of a `p` vector, in field order.
        fn from(v: &SVector<T, 24>) -> Params<T> {
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
            }
        }
    }
    impl<T: Real> From<SVector<T, 24>> for Params<T> {
        /// The fields of a `p` vector, in field order.
        fn from(v: SVector<T, 24>) -> Params<T> {
            Params::from(&v)
        }
    }
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
    /// 104 add/sub, 135 mul, 7 div, 4 sqrt, 6 transcendental, 16 branches; 90 `let`s.
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
        let t4 = T::from_f64(0.5) * d;
        let t5 = T::from_f64(0.5) * theta;
        let (t6, t7) = t5.sin_cos();
        let t8 = t6 * t6;
        let t9 = r * sin_theta;
        let t10 = r * cos_theta;
        let t11 = zdot * sin_theta;
        let t12 = t6 * t7;
        let t13 = l_c - rho_p;
        let t14 = r - rho_p;
        let t15 = sin_theta * t13;
        let t16 = -T::from_f64(2.0) * t8 * t14;
        let t17 = rho_p * sin_theta;
        let t18 = cos_theta * (r - T::from_f64(2.0) * rho_p * t8);
        let t19 = cos_theta * t13;
        let t20 = rho_h + t4 - x;
        let t21 = T::from_f64(1.0) - T::from_f64(2.0) * t8;
        let t22 = z - rho_h;
        let t23 = sin_theta * t22;
        let t24 = -xdot * t21;
        let t25 = cos_theta * t22;
        let t26 = sin_theta * (l_c - rho_p + t17) + t18;
        let slip_wall_right = zdot - thetadot * t26;
        let t27 = v_s.hypot(slip_wall_right);
        let t28 = sin_theta * (-l_c + rho_p + t17) + t18;
        let slip_wall_left = zdot + thetadot * t28;
        let t29 = v_s.hypot(slip_wall_left);
        let t30 = sin_theta * t20 - t25;
        let t31 = t9 - cos_theta * t30;
        let t32 = t10 + sin_theta * t30;
        let slip_edge_right = sin_theta * (xdot - thetadot * t31)
            + cos_theta * (zdot - thetadot * t32);
        let t33 = t25 - T::from_f64(2.0) * t12 * t20;
        let neg_delta_rate_edge_right = t24 + t11 + thetadot * t33;
        let t34 = (T::from_f64(1.0) - hc_alpha * neg_delta_rate_edge_right).max0();
        let t35 = v_s.hypot(slip_edge_right);
        let t36 = T::from_f64(1.0) - t34;
        let t37 = t34 / t35;
        let t38 = t37 * slip_edge_right;
        let t39 = T::from_f64(2.0) * (t12 * t14);
        let t40 = t19 + t39;
        let neg_delta_rate_wall_left = xdot + thetadot * t40;
        let t41 = (T::from_f64(1.0) - hc_alpha * neg_delta_rate_wall_left).max0();
        let t42 = T::from_f64(1.0) - t41;
        let t43 = t41 / t29;
        let t44 = t43 * slip_wall_left;
        let t45 = -rho_h - t4 - x;
        let delta_edge_left = r - t4 - x + t23 - T::from_f64(2.0) * t45 * t8;
        let pen_edge_left = delta_edge_left.max0();
        let t46 = pen_edge_left * pen_edge_left.sqrt();
        let step_delta_edge_left = delta_edge_left.step();
        let delta_wall_right = r - t4 + x + t15 + t16;
        let pen_wall_right = delta_wall_right.max0();
        let t47 = pen_wall_right * pen_wall_right.sqrt();
        let step_delta_wall_right = delta_wall_right.step();
        let t48 = t19 - t39;
        let delta_rate_wall_right = xdot + thetadot * t48;
        let t49 = (T::from_f64(1.0) + hc_alpha * delta_rate_wall_right).max0();
        let t50 = sin_theta * t45 - t25;
        let t51 = cos_theta * t50 + t9;
        let t52 = t10 - sin_theta * t50;
        let slip_edge_left = sin_theta * (xdot + thetadot * t51)
            + cos_theta * (zdot + thetadot * t52);
        let t53 = t25 - T::from_f64(2.0) * t12 * t45;
        let delta_rate_edge_left = t24 + t11 + thetadot * t53;
        let t54 = (T::from_f64(1.0) + hc_alpha * delta_rate_edge_left).max0();
        let t55 = v_s.hypot(slip_edge_left);
        let t56 = T::from_f64(1.0) - t54;
        let t57 = T::from_f64(1.0) - t49;
        let delta_edge_right = r - t4 + x - t23 + T::from_f64(2.0) * t8 * t20;
        let pen_edge_right = delta_edge_right.max0();
        let t58 = pen_edge_right * pen_edge_right.sqrt();
        let step_delta_edge_right = delta_edge_right.step();
        let t59 = t54 / t55;
        let t60 = t59 * slip_edge_left;
        let t61 = step_delta_edge_left - t56;
        let t62 = t36 - step_delta_edge_right;
        let t63 = t46 * t61 + t58 * t62;
        let t64 = mu * (t60 * t46 + t38 * t58);
        let t65 = t49 / t27;
        let t66 = t65 * slip_wall_right;
        let delta_wall_left = r - t4 - x - t15 + t16;
        let pen_wall_left = delta_wall_left.max0();
        let t67 = pen_wall_left * pen_wall_left.sqrt();
        let step_delta_wall_left = delta_wall_left.step();
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
                        * (t67 * (t41 - T::from_f64(1.0) + step_delta_wall_left)
                            - t47 * (-T::from_f64(1.0) + step_delta_wall_right + t49))
                    + t0 + t1) / m,
                -(k_edge * (sin_theta * t63 + t64 * cos_theta)
                    + k_wall * (t66 * t47 + t44 * t67) * mu - t2 + t3) / m,
                -(-m_2
                    + k_edge
                        * (t46
                            * (t53 * t61
                                + t60 * mu * (sin_theta * t51 + cos_theta * t52))
                            - t58
                                * (t38 * mu * (sin_theta * t31 + cos_theta * t32)
                                    - t33 * t62))
                    + k_wall
                        * (t67 * (t44 * mu * t28 - t40 * (step_delta_wall_left - t42))
                            - t47
                                * (t66 * mu * t26 - t48 * (step_delta_wall_right - t57))))
                    / j,
                xdot * (t0 + t1) + zdot * (t2 - t3) + thetadot * m_2,
                mu
                    * (k_edge
                        * (t59 * t46 * (slip_edge_left * slip_edge_left)
                            + t37 * t58 * (slip_edge_right * slip_edge_right))
                        + k_wall
                            * (t65 * t47 * (slip_wall_right * slip_wall_right)
                                + t43 * t67 * (slip_wall_left * slip_wall_left)))
                    - k_edge
                        * (delta_rate_edge_left * t46 * t56
                            - neg_delta_rate_edge_right * t58 * t36)
                    - k_wall
                        * (delta_rate_wall_right * t47 * t57
                            - neg_delta_rate_wall_left * t67 * t42),
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
    /// 360 add/sub, 715 mul, 10 div, 8 sqrt, 6 transcendental, 24 branches; 285 `let`s.
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
        let t6 = T::from_f64(0.5) * d;
        let t7 = T::from_f64(0.5) * theta;
        let (t8, t9) = t7.sin_cos();
        let t10 = t8 * t8;
        let t11 = r * sin_theta;
        let t12 = r * cos_theta;
        let t13 = zdot * sin_theta;
        let t14 = t8 * t9;
        let t15 = l_c - rho_p;
        let t16 = r - rho_p;
        let t17 = sin_theta * t15;
        let t18 = -T::from_f64(2.0) * t10 * t16;
        let t19 = rho_p * sin_theta;
        let t20 = l_c - rho_p + t19;
        let t21 = r - T::from_f64(2.0) * rho_p * t10;
        let t22 = sin_theta * t21;
        let t23 = cos_theta * t21;
        let t24 = cos_theta * t15;
        let t25 = rho_h + t6 - x;
        let t26 = T::from_f64(1.0) - T::from_f64(2.0) * t10;
        let t27 = T::from_f64(1.0) / m;
        let t28 = T::from_f64(1.0) / j;
        let t29 = sin_theta * sin_theta;
        let t30 = t26 * t26;
        let t31 = cos_theta * cos_theta;
        let t32 = zdot * cos_theta;
        let t33 = t23 + sin_theta * t20;
        let t34 = z - rho_h;
        let t35 = sin_theta * t34;
        let t36 = -xdot * t26;
        let t37 = cos_theta * t34;
        let t38 = -l_c + rho_p + t19;
        let t39 = sin_theta * t38 + t23;
        let slip_wall_left = zdot + thetadot * t39;
        let t40 = v_s.hypot(slip_wall_left);
        let t41 = T::from_f64(1.0) / t40;
        let t42 = slip_wall_left * slip_wall_left;
        let t43 = sin_theta * t25 - t37;
        let t44 = -cos_theta * t43;
        let t45 = t11 + t44;
        let t46 = xdot - thetadot * t45;
        let t47 = sin_theta * t43;
        let t48 = t12 + t47;
        let t49 = zdot - thetadot * t48;
        let slip_edge_right = sin_theta * t46 + cos_theta * t49;
        let t50 = t37 - T::from_f64(2.0) * t14 * t25;
        let neg_delta_rate_edge_right = t36 + t13 + thetadot * t50;
        let t51 = T::from_f64(1.0) - hc_alpha * neg_delta_rate_edge_right;
        let t52 = t51.max0();
        let t53 = v_s.hypot(slip_edge_right);
        let t54 = T::from_f64(1.0) / t53;
        let t55 = sin_theta * t45 + cos_theta * t48;
        let t56 = slip_edge_right * slip_edge_right;
        let t57 = T::from_f64(1.0) - t52;
        let t58 = T::from_f64(2.0) * (t14 * t16);
        let t59 = t24 + t58;
        let neg_delta_rate_wall_left = xdot + thetadot * t59;
        let t60 = T::from_f64(1.0) - hc_alpha * neg_delta_rate_wall_left;
        let t61 = t60.max0();
        let t62 = T::from_f64(1.0) - t61;
        let t63 = -rho_h - t6 - x;
        let delta_edge_left = r - t6 - x + t35 - T::from_f64(2.0) * t63 * t10;
        let pen_edge_left = delta_edge_left.max0();
        let t64 = pen_edge_left * pen_edge_left.sqrt();
        let step_delta_edge_left = delta_edge_left.step();
        let delta_wall_right = r - t6 + x + t17 + t18;
        let pen_wall_right = delta_wall_right.max0();
        let t65 = pen_wall_right * pen_wall_right.sqrt();
        let step_delta_wall_right = delta_wall_right.step();
        let t66 = t24 - t58;
        let delta_rate_wall_right = xdot + thetadot * t66;
        let t67 = T::from_f64(1.0) + hc_alpha * delta_rate_wall_right;
        let t68 = t67.max0();
        let t69 = sin_theta * t63 - t37;
        let t70 = cos_theta * t69;
        let t71 = t70 + t11;
        let t72 = xdot + thetadot * t71;
        let t73 = t37 - T::from_f64(2.0) * t14 * t63;
        let delta_rate_edge_left = t36 + t13 + thetadot * t73;
        let t74 = T::from_f64(1.0) + hc_alpha * delta_rate_edge_left;
        let t75 = t74.max0();
        let t76 = T::from_f64(1.0) - t75;
        let t77 = T::from_f64(1.0) - t68;
        let delta_edge_right = r - t6 + x - t35 + T::from_f64(2.0) * t10 * t25;
        let pen_edge_right = delta_edge_right.max0();
        let t78 = pen_edge_right * pen_edge_right.sqrt();
        let step_delta_edge_right = delta_edge_right.step();
        let t79 = t64 * (step_delta_edge_left - t76);
        let t80 = t78 * (t57 - step_delta_edge_right);
        let delta_wall_left = r - t6 - x - t17 + t18;
        let pen_wall_left = delta_wall_left.max0();
        let t81 = pen_wall_left * pen_wall_left.sqrt();
        let step_delta_wall_left = delta_wall_left.step();
        let t82 = T::from_f64(1.0) / (t40 * t40 * t40);
        let t83 = r - (t35 + cos_theta * t25);
        let t84 = t10 - t9 * t9;
        let t85 = t35 - t25 * t84;
        let slip_wall_right = zdot - thetadot * t33;
        let t86 = v_s.hypot(slip_wall_right);
        let t87 = T::from_f64(1.0) / t86;
        let t88 = slip_wall_right * slip_wall_right;
        let t89 = T::from_f64(1.0) / (t86 * t86 * t86);
        let t90 = t16 * t84;
        let t91 = t90 + t17;
        let t92 = T::from_f64(2.0) * t14 * xdot;
        let t93 = slip_edge_right * t54;
        let t94 = t51.step();
        let t95 = T::from_f64(1.0) / (t53 * t53 * t53);
        let t96 = t50 * t50;
        let t97 = thetadot * hc_alpha;
        let t98 = t14 * t97;
        let t99 = t97 * cos_theta;
        let t100 = cos_theta * t83 + t47;
        let t101 = t56 * t95;
        let t102 = t52 * (t54 - t101);
        let t103 = rho_p * (sin_theta - T::from_f64(2.0) * t14);
        let t104 = t93 * t55;
        let t105 = t102 * t55;
        let t106 = mu * t39;
        let t107 = slip_wall_left * t41;
        let t108 = hc_alpha * t94;
        let t109 = t108 * t50;
        let t110 = t54 * t56;
        let t111 = t41 * t42;
        let t112 = t95 * (slip_edge_right * slip_edge_right * slip_edge_right);
        let t113 = t82 * (slip_wall_left * slip_wall_left * slip_wall_left);
        let t114 = t52 * t55;
        let t115 = k_edge * t27;
        let t116 = t92 + t32 - thetadot * t85;
        let t117 = sin_theta * t83 + t44;
        let t118 = sin_theta * (thetadot * t100 + t49)
            - cos_theta * (t46 + thetadot * t117);
        let t119 = t108 * t116;
        let t120 = t22 - cos_theta * (t103 + t20);
        let t121 = t22 - cos_theta * (t103 + t38);
        let t122 = t97 * mu;
        let t123 = t55 * t118;
        let t124 = t60.step();
        let t125 = t59 * t59;
        let t126 = T::from_f64(1.5) - T::from_f64(1.5) * t61;
        let t127 = k_wall * hc_alpha;
        let t128 = t61 * (t41 - t42 * t82);
        let t129 = slip_wall_right * t87;
        let t130 = mu * t33;
        let t131 = t107 * t61;
        let t132 = hc_alpha * t124;
        let t133 = t132 * t91;
        let t134 = t111 * t61;
        let t135 = t89 * (slip_wall_right * slip_wall_right * slip_wall_right);
        let t136 = t17 - t90;
        let t137 = t133 * t107 - t128 * t121;
        let t138 = t132 * t59;
        let t139 = t107 * t138;
        let t140 = t61 * t121;
        let t141 = t39 * t61;
        let sqrt_pen_edge_left = pen_edge_left.sqrt();
        let t142 = step_delta_edge_left * step_delta_edge_left;
        let sqrt_pen_wall_right = pen_wall_right.sqrt();
        let t143 = step_delta_wall_right * step_delta_wall_right;
        let t144 = -T::from_f64(1.5) * t143;
        let t145 = sqrt_pen_edge_left * t142;
        let t146 = r + cos_theta * t63 + t35;
        let t147 = t35 - t63 * t84;
        let t148 = t67.step();
        let t149 = t66 * t66;
        let t150 = sin_theta * t69;
        let t151 = t12 - t150;
        let t152 = zdot + thetadot * t151;
        let slip_edge_left = sin_theta * t72 + cos_theta * t152;
        let t153 = v_s.hypot(slip_edge_left);
        let t154 = T::from_f64(1.0) / t153;
        let t155 = sin_theta * t71 + cos_theta * t151;
        let t156 = slip_edge_left * slip_edge_left;
        let t157 = t64 * t76;
        let t158 = t78 * t57;
        let t159 = slip_edge_left * t154;
        let t160 = t159 * t64 * t75 + t93 * t78 * t52;
        let t161 = t74.step();
        let t162 = T::from_f64(1.0) / (t153 * t153 * t153);
        let t163 = t73 * t73;
        let t164 = step_delta_edge_left * sqrt_pen_edge_left;
        let t165 = t164 * (T::from_f64(1.5) - T::from_f64(1.5) * t75);
        let t166 = t64 * t161;
        let t167 = T::from_f64(2.0) * t98 * t166;
        let t168 = t165 * t26 + t167;
        let sqrt_pen_edge_right = pen_edge_right.sqrt();
        let t169 = step_delta_edge_right * step_delta_edge_right;
        let t170 = step_delta_edge_right * sqrt_pen_edge_right;
        let t171 = t170 * (T::from_f64(1.5) - T::from_f64(1.5) * t52);
        let t172 = t78 * t94;
        let t173 = T::from_f64(2.0) * t98 * t172;
        let t174 = t171 * t26 + t173;
        let t175 = t164 * t75;
        let t176 = t170 * t52;
        let t177 = mu * (t175 * t159 - t176 * t93);
        let t178 = T::from_f64(1.5) - T::from_f64(1.5) * t68;
        let t179 = sqrt_pen_wall_right * (step_delta_wall_right * t178 + t144);
        let t180 = sqrt_pen_edge_right * t169;
        let t181 = t145 + t180;
        let t182 = t26 * t181;
        let t183 = sin_theta * t146 + t70;
        let t184 = t156 * t162;
        let t185 = t75 * (t154 - t184);
        let t186 = t185 * t64;
        let t187 = t102 * t78;
        let t188 = t186 + t187;
        let t189 = hc_alpha * (t166 + t172);
        let t190 = t148 * t65;
        let t191 = hc_alpha * t161;
        let t192 = t191 * t73;
        let t193 = hc_alpha * (t166 * t159 - t172 * t93);
        let t194 = t193 * mu;
        let t195 = t194 * thetadot;
        let t196 = hc_alpha * (t166 * t73 + t172 * t50);
        let t197 = t196 * sin_theta * k_edge;
        let t198 = t159 * t155;
        let t199 = sqrt_pen_edge_left
            * (t73 * t142 + t198 * mu * t75 * step_delta_edge_left);
        let t200 = sqrt_pen_edge_right
            * (t50 * t169 + t104 * mu * t52 * step_delta_edge_right);
        let t201 = t175 * t73;
        let t202 = t176 * t50;
        let t203 = t105 * t78;
        let t204 = hc_alpha * (t198 * t166 + t104 * t172);
        let t205 = t196 * t26;
        let t206 = t186 * t155;
        let t207 = t154 * t156;
        let t208 = t207 * t166 - t110 * t172;
        let t209 = t207 * t175 - t110 * t176;
        let t210 = hc_alpha
            * (mu * t208 + t166 * delta_rate_edge_left
                + t172 * neg_delta_rate_edge_right) - t157 + t158;
        let t211 = t162 * (slip_edge_left * slip_edge_left * slip_edge_left);
        let t212 = t75 * (T::from_f64(2.0) * t159 - t211) * t64;
        let t213 = t52 * (T::from_f64(2.0) * t93 - t112) * t78;
        let t214 = t75 * t155;
        let t215 = hc_alpha * t148;
        let t216 = t99 * t166 - t165 * sin_theta;
        let t217 = t99 * t172 - t171 * sin_theta;
        let t218 = t150 - cos_theta * t146;
        let t219 = cos_theta * (thetadot * t183 - t72)
            + sin_theta * (thetadot * t218 + t152);
        let t220 = t172 * t116;
        let t221 = t220 * hc_alpha - t171 * t50;
        let t222 = sin_theta * (cos_theta * (-t186 - t187) * mu + t189 * t26);
        let t223 = t64 * (t185 * t155 + t192 * t159) - t78 * (t105 + t109 * t93);
        let t224 = t64 * (step_delta_edge_left - t76 + t122 * t198 * t161);
        let t225 = t78 * (-step_delta_edge_right + t57 + t122 * t104 * t94);
        let t226 = t155 * t219;
        let t227 = thetadot * (t157 - t158);
        let t228 = t64 * t219;
        let t229 = t78 * t118;
        let sqrt_pen_wall_left = pen_wall_left.sqrt();
        let t230 = step_delta_wall_left * step_delta_wall_left;
        let t231 = -T::from_f64(1.5) * t230;
        let t232 = sqrt_pen_wall_left * (step_delta_wall_left * t126 + t231);
        let t233 = t81 * t124;
        let t234 = t233 * t91;
        let t235 = t68 * (t87 - t88 * t89);
        let t236 = t235 * t65;
        let t237 = t215 * t66;
        let t238 = t129 * t237;
        let t239 = step_delta_wall_left * sqrt_pen_wall_left;
        let t240 = t129 * t68;
        let t241 = step_delta_wall_right * sqrt_pen_wall_right;
        let t242 = t241 * t66;
        let t243 = t239 * t59;
        let t244 = t243 * t126 + t234 * t97;
        let t245 = t39 * t81;
        let t246 = t68 * t87 * t88;
        let t247 = t68 * t33;
        let t248 = t92 + t32 - thetadot * t147;
        let t249 = t166 * t248;
        let t250 = t249 * hc_alpha - t165 * t73;
        let t251 = t191 * t248;
        let t252 = t64 * (t251 * t159 - t185 * t219) - t78 * (t102 * t118 + t119 * t93)
            + T::from_f64(1.5) * (t201 * t159 - t202 * t93);
        let t253 = T::from_f64(1.5) * (t145 * t73 + t180 * t50) + t250 + t221;
        let t254 = t190 * t136;
        let t255 = t215 * t136;
        let t256 = t65 * (t255 * t129 - t235 * t120);
        let t257 = t242 * t178 + t254 * t97;
        let t258 = t68 * t120;
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
                t27
                    * (k_edge
                        * (t26 * (T::from_f64(1.5) * t177 * sin_theta + t168 + t174)
                            - T::from_f64(1.5) * t181 * t30
                            - T::from_f64(2.0) * t195 * (t14 * sin_theta))
                        + k_wall * (t179 + t232)),
                t115
                    * (sin_theta * (T::from_f64(1.5) * t182 - t195 * cos_theta)
                        + t26 * (t216 + t217) - T::from_f64(1.5) * t177 * t29),
                t27
                    * (k_edge
                        * (-(mu * (sin_theta * t252 + cos_theta * t160)) + t26 * t253
                            + t14 * (-(T::from_f64(2.0) * t79) - T::from_f64(2.0) * t80))
                        + k_wall * (t179 * t66 + t232 * t59 + t97 * (t254 + t234)) + t3
                        + t4),
                -t27
                    * (k_edge * (mu * (t29 * t188 - sin_theta * t26 * t193) + t189 * t30)
                        + t127 * (t190 + t233)),
                t115 * (t222 - t194 * t29),
                -t27
                    * (k_edge * (sin_theta * t223 * mu - t205)
                        + t127 * (t190 * t66 + t233 * t59)),
                T::from_f64(0.0),
                T::from_f64(0.0),
                -t27
                    * (k_edge
                        * (sin_theta * (-(T::from_f64(1.5) * t182) + t168 + t174)
                            - cos_theta
                                * (t93 * (t173 - T::from_f64(1.5) * t176 * t26)
                                    - t159 * (t167 - T::from_f64(1.5) * t175 * t26)) * mu)
                        + T::from_f64(1.5) * (k_wall * (t240 * t241 - t131 * t239))
                            * mu),
                -t115
                    * (sin_theta * (T::from_f64(1.5) * t177 * cos_theta + t216 + t217)
                        + T::from_f64(1.5) * t181 * t29 + t195 * t31),
                -t27
                    * (-(mu
                        * (k_edge * (sin_theta * t160 - cos_theta * t252)
                            - k_wall
                                * (thetadot * (t81 * t137 - t256)
                                    + T::from_f64(1.5) * (t240 * t242 - t131 * t243))))
                        + k_edge * (cos_theta * (t79 + t80) + sin_theta * t253) + t0
                        + t1),
                t27
                    * (k_edge * (t222 + cos_theta * t26 * t194)
                        - t127 * (t190 * t129 - t233 * t107) * mu),
                -t27
                    * (mu
                        * (k_edge * (t31 * t188 + sin_theta * cos_theta * t193)
                            + k_wall * (t236 + t128 * t81)) + t189 * t29 * k_edge),
                t27
                    * (mu
                        * (k_wall
                            * (t81 * (t139 - t128 * t39) - t65 * (t238 - t235 * t33))
                            - cos_theta * t223 * k_edge) - t197),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t28
                    * (k_edge
                        * (t14 * (-(T::from_f64(2.0) * t224) - T::from_f64(2.0) * t225)
                            + t26 * (T::from_f64(1.5) * t199 + T::from_f64(1.5) * t200)
                            - t73 * t168 - t50 * t174)
                        + k_wall
                            * (sqrt_pen_wall_right
                                * (t66 * (t144 + t178 * step_delta_wall_right)
                                    + T::from_f64(1.5) * t130 * t240 * step_delta_wall_right)
                                + sqrt_pen_wall_left
                                    * (t59 * (t231 + t126 * step_delta_wall_left)
                                        + T::from_f64(1.5) * t106 * t131 * step_delta_wall_left))),
                -(k_edge
                    * (cos_theta * (t224 + t225)
                        - sin_theta
                            * (-(T::from_f64(1.5) * t199) - T::from_f64(1.5) * t200)
                        + t73 * t216 + t50 * t217)) * t28,
                -t28
                    * (mu
                        * (k_edge
                            * (t64
                                * (t251 * t198
                                    - t75
                                        * (t154
                                            * (t226
                                                + slip_edge_left
                                                    * (sin_theta * (t218 + t151) - cos_theta * (t71 - t183)))
                                            - t184 * t226))
                                + t78
                                    * (t52
                                        * (t54
                                            * (t123
                                                + slip_edge_right
                                                    * (sin_theta * (t48 - t100) - cos_theta * (t45 - t117)))
                                            - t101 * t123) + t119 * t104)
                                + T::from_f64(1.5) * (t201 * t198 + t202 * t104))
                            + k_wall
                                * (thetadot * (t256 * t33 + t245 * t137)
                                    - t240 * (T::from_f64(1.5) * t242 * t33 - t65 * t120)
                                    - t131 * (t81 * t121 + T::from_f64(1.5) * t243 * t39)))
                        + k_edge
                            * (-(t79 * t147) - t80 * t85
                                + T::from_f64(1.5) * (t145 * t163 + t180 * t96) + t73 * t250
                                + t50 * t221)
                        + k_wall
                            * (-((step_delta_wall_right - t77) * t136 * t65)
                                + (step_delta_wall_left - t62) * t91 * t81
                                + T::from_f64(1.5)
                                    * (sqrt_pen_wall_right * t143 * t149
                                        + sqrt_pen_wall_left * t230 * t125) - t66 * t257
                                - t59 * t244)),
                t28
                    * (k_edge * (mu * (sin_theta * (t203 - t206) + t204 * t26) + t205)
                        + t127
                            * (t190 * (t130 * t129 - t66) + t233 * (t106 * t107 - t59))),
                -t28
                    * (mu
                        * (k_edge * (cos_theta * (t206 - t203) + t204 * sin_theta)
                            + k_wall * (t245 * t128 - t236 * t33)) + t197),
                -t28
                    * (mu
                        * (k_edge
                            * (t64 * (t185 * (t155 * t155) + t192 * t198)
                                + t78 * (t102 * (t55 * t55) + t109 * t104))
                            - k_wall
                                * (t65 * (t238 * t33 - t235 * (t33 * t33))
                                    + t81 * (t139 * t39 - t128 * (t39 * t39))))
                        + hc_alpha
                            * (k_edge * (t166 * t163 + t172 * t96)
                                + k_wall * (t190 * t149 + t233 * t125))),
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
                        * (T::from_f64(2.0) * (t14 * t208) * t97
                            - T::from_f64(1.5) * t209 * t26)
                        - T::from_f64(2.0) * t227 * t14 + delta_rate_edge_left * t168
                        + neg_delta_rate_edge_right * t174)
                    - k_wall
                        * (-(T::from_f64(1.5) * (t246 * t241 - t134 * t239) * mu)
                            + t241 * t178 * delta_rate_wall_right
                            + t239 * t126 * neg_delta_rate_wall_left),
                k_edge
                    * (mu
                        * (T::from_f64(1.5) * t209 * sin_theta + cos_theta * t208 * t97)
                        - t227 * cos_theta + delta_rate_edge_left * t216
                        + neg_delta_rate_edge_right * t217),
                mu
                    * (k_edge
                        * (t75
                            * (t228 * t211
                                - t154
                                    * (T::from_f64(2.0) * t228 * slip_edge_left
                                        - T::from_f64(1.5) * t164 * t73 * t156))
                            - t52
                                * (t54
                                    * (T::from_f64(1.5) * t170 * t50 * t56
                                        + T::from_f64(2.0) * t229 * slip_edge_right) - t229 * t112)
                            + hc_alpha * (t249 * t207 - t220 * t110))
                        + k_wall
                            * (thetadot
                                * (t81
                                    * (t41
                                        * (t133 * t42 - T::from_f64(2.0) * t140 * slip_wall_left)
                                        + t140 * t113)
                                    - t65
                                        * (t87
                                            * (t255 * t88 - T::from_f64(2.0) * t258 * slip_wall_right)
                                            + t258 * t135))
                                + T::from_f64(1.5) * (t246 * t242 - t134 * t243)))
                    + k_edge
                        * (-(t157 * t248) + delta_rate_edge_left * t250 + t158 * t116
                            + neg_delta_rate_edge_right * t221)
                    - k_wall
                        * (thetadot * (t81 * t62 * t91 - t65 * t77 * t136)
                            + delta_rate_wall_right * t257
                            + neg_delta_rate_wall_left * t244),
                -(k_edge * (t26 * t210 + sin_theta * (-t212 - t213) * mu))
                    - k_wall
                        * (t65
                            * (-(t215 * (mu * t87 * t88 + delta_rate_wall_right)) - t68
                                + T::from_f64(1.0))
                            + t81
                                * (t132 * (t111 * mu - neg_delta_rate_wall_left)
                                    - T::from_f64(1.0) + t61)),
                k_edge * (sin_theta * t210 + cos_theta * (t212 + t213) * mu)
                    + k_wall
                        * (t68 * (T::from_f64(2.0) * t129 - t135) * t65
                            + t61 * (T::from_f64(2.0) * t107 - t113) * t81) * mu,
                -(mu
                    * (k_edge
                        * (t64
                            * (t214 * t211
                                - t154
                                    * (t192 * t156 + T::from_f64(2.0) * t214 * slip_edge_left))
                            - t78
                                * (t114 * t112
                                    - t54
                                        * (t109 * t56 + T::from_f64(2.0) * t114 * slip_edge_right)))
                        + k_wall
                            * (t81
                                * (t41
                                    * (t138 * t42 - T::from_f64(2.0) * t141 * slip_wall_left)
                                    + t141 * t113)
                                - t65
                                    * (t87
                                        * (t237 * t88 - T::from_f64(2.0) * t247 * slip_wall_right)
                                        + t247 * t135))))
                    + k_edge
                        * (t64 * (t191 * delta_rate_edge_left - t76) * t73
                            + t78 * (t57 + t108 * neg_delta_rate_edge_right) * t50)
                    + k_wall
                        * (t65 * (t215 * delta_rate_wall_right - t77) * t66
                            + t81 * (t62 + t132 * neg_delta_rate_wall_left) * t59),
                T::from_f64(0.0),
                T::from_f64(0.0),
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
    /// - `y` = (`x`, `z`, `theta`, `xdot`, `zdot`, `thetadot`, `work`, `dissipation`)
    /// - `p` = (`m`, `J`, `r`, `l_c`, `D`, `rho_p`, `rho_h`, `mu`, `v_s`, `k_edge`, `k_wall`, `f1`, `f2`, `M`, `e_star`, `edge_sum`, `edge_ma`, `edge_mb`, `edge_dstar`, `wall_sum`, `wall_ma`, `wall_mb`, `wall_dstar`, `hc_alpha`)
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
    /// 59 add/sub, 107 mul, 8 div, 4 sqrt, 10 transcendental, 8 branches; 65 `let`s.
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
        let t0 = T::from_f64(0.5) * d;
        let t1 = T::from_f64(0.5) * theta;
        let (t2, t3) = t1.sin_cos();
        let t4 = t2 * t2;
        let t5 = r * sin_theta;
        let t6 = r * cos_theta;
        let t7 = zdot * sin_theta;
        let t8 = t2 * t3;
        let t9 = T::from_f64(1.0) / (e_star * edge_sum);
        let t10 = l_c - rho_p;
        let t11 = r - rho_p;
        let t12 = sin_theta * t10;
        let t13 = -T::from_f64(2.0) * t4 * t11;
        let t14 = rho_p * sin_theta;
        let t15 = cos_theta * (r - T::from_f64(2.0) * rho_p * t4);
        let t16 = cos_theta * t10;
        let t17 = T::from_f64(1.0) / (e_star * wall_sum);
        let t18 = rho_h + t0 - x;
        let t19 = z - rho_h;
        let t20 = sin_theta * t19;
        let t21 = -xdot * (T::from_f64(1.0) - T::from_f64(2.0) * t4);
        let t22 = cos_theta * t19;
        let slip_wall_right = zdot - thetadot * (sin_theta * (l_c - rho_p + t14) + t15);
        let t23 = v_s.hypot(slip_wall_right);
        let slip_wall_left = zdot + thetadot * (sin_theta * (-l_c + rho_p + t14) + t15);
        let t24 = v_s.hypot(slip_wall_left);
        let t25 = sin_theta * t18 - t22;
        let slip_edge_right = sin_theta * (xdot - thetadot * (t5 - cos_theta * t25))
            + cos_theta * (zdot - thetadot * (t6 + sin_theta * t25));
        let t26 = (T::from_f64(1.0)
            - hc_alpha * (t21 + t7 + thetadot * (t22 - T::from_f64(2.0) * t8 * t18)))
            .max0();
        let t27 = v_s.hypot(slip_edge_right);
        let t28 = T::from_f64(2.0) * (t8 * t11);
        let t29 = (T::from_f64(1.0) - hc_alpha * (xdot + thetadot * (t16 + t28))).max0();
        let t30 = -rho_h - t0 - x;
        let delta_edge_left = r - t0 - x + t20 - T::from_f64(2.0) * t30 * t4;
        let pen_edge_left = delta_edge_left.max0();
        let t31 = pen_edge_left * pen_edge_left.sqrt();
        let delta_wall_right = r - t0 + x + t12 + t13;
        let pen_wall_right = delta_wall_right.max0();
        let t32 = pen_wall_right * pen_wall_right.sqrt();
        let delta_rate_wall_right = xdot + thetadot * (t16 - t28);
        let t33 = (T::from_f64(1.0) + hc_alpha * delta_rate_wall_right).max0();
        let t34 = sin_theta * t30 - t22;
        let slip_edge_left = sin_theta * (xdot + thetadot * (cos_theta * t34 + t5))
            + cos_theta * (zdot + thetadot * (t6 - sin_theta * t34));
        let delta_rate_edge_left = t21 + t7
            + thetadot * (t22 - T::from_f64(2.0) * t8 * t30);
        let t35 = (T::from_f64(1.0) + hc_alpha * delta_rate_edge_left).max0();
        let t36 = v_s.hypot(slip_edge_left);
        let delta_edge_right = r - t0 + x - t20 + T::from_f64(2.0) * t4 * t18;
        let pen_edge_right = delta_edge_right.max0();
        let t37 = pen_edge_right * pen_edge_right.sqrt();
        let delta_wall_left = r - t0 - x - t12 + t13;
        let pen_wall_left = delta_wall_left.max0();
        let t38 = pen_wall_left * pen_wall_left.sqrt();
        let t39 = e_star * edge_sum * (T::from_f64(1.0) / (edge_ma * edge_mb));
        let t40 = e_star * wall_sum * (T::from_f64(1.0) / (wall_ma * wall_mb));
        let normal_edge_left = k_edge * t31 * t35;
        let normal_wall_right = k_wall * t33 * t32;
        let t41 = (T::from_f64(1.5) * t9 * normal_edge_left).cbrt();
        let t42 = (T::from_f64(1.5) * t17 * normal_wall_right).cbrt();
        let normal_edge_right = k_edge * t26 * t37;
        let t43 = (T::from_f64(1.5) * t9 * normal_edge_right).cbrt();
        let normal_wall_left = k_wall * t38 * t29;
        let t44 = (T::from_f64(1.5) * t17 * normal_wall_left).cbrt();
        ContactsOut {
            normal: Vector4::new(
                normal_edge_left,
                normal_wall_right,
                normal_edge_right,
                normal_wall_left,
            ),
            friction: Vector4::new(
                -normal_edge_left * mu * slip_edge_left / t36,
                -normal_wall_right * mu * slip_wall_right / t23,
                -normal_edge_right * mu * slip_edge_right / t27,
                -normal_wall_left * mu * slip_wall_left / t24,
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
            a: Vector4::new(edge_ma * t41, wall_ma * t42, edge_ma * t43, wall_ma * t44),
            b: Vector4::new(edge_mb * t41, wall_mb * t42, edge_mb * t43, wall_mb * t44),
            p0: Vector4::new(
                T::from_f64(0.3183098861837907) * t39 * t41,
                T::from_f64(0.3183098861837907) * t40 * t42,
                T::from_f64(0.3183098861837907) * t39 * t43,
                T::from_f64(0.3183098861837907) * t40 * t44,
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
    }
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
    /// 29 add/sub, 22 mul, 0 div, 0 sqrt, 6 transcendental, 4 branches; 20 `let`s.
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
        let t0 = T::from_f64(0.5) * d;
        let t1 = (T::from_f64(0.5) * theta).sin();
        let t2 = t1 * t1;
        let t3 = sin_theta * (l_c - rho_p);
        let t4 = -T::from_f64(2.0) * t2 * (r - rho_p);
        let t5 = sin_theta * (z - rho_h);
        let delta_edge_left = r - t0 - x + t5
            - T::from_f64(2.0) * (-rho_h - t0 - x) * t2;
        let pen_edge_left = delta_edge_left.max0();
        let delta_wall_right = r - t0 + x + t3 + t4;
        let pen_wall_right = delta_wall_right.max0();
        let delta_edge_right = r - t0 + x - t5
            + T::from_f64(2.0) * t2 * (rho_h + t0 - x);
        let pen_edge_right = delta_edge_right.max0();
        let delta_wall_left = r - t0 - x - t3 + t4;
        let pen_wall_left = delta_wall_left.max0();
        let t6 = pen_edge_left.powf(T::from_f64(2.5));
        let t7 = pen_wall_right.powf(T::from_f64(2.5));
        let t8 = pen_edge_right.powf(T::from_f64(2.5));
        let t9 = pen_wall_left.powf(T::from_f64(2.5));
        EnergyOut {
            kinetic: T::from_f64(0.5)
                * (m * (xdot * xdot + zdot * zdot) + j * (thetadot * thetadot)),
            potential: T::from_f64(0.4) * (t6 + t8) * k_edge
                + T::from_f64(0.4) * (t7 + t9) * k_wall,
            depth: z + l_c * cos_theta,
        }
    }
    /// Exact parameter Jacobian of [`rhs`]: `dydot_dp` with entry (i, k) = ∂ydotᵢ/∂p_k (columns in `P_NAMES` order).
    ///
    /// # Inputs
    /// - `y` = (`x`, `z`, `theta`, `xdot`, `zdot`, `thetadot`, `work`, `dissipation`)
    /// - `p` = (`m`, `J`, `r`, `l_c`, `D`, `rho_p`, `rho_h`, `mu`, `v_s`, `k_edge`, `k_wall`, `f1`, `f2`, `M`, `e_star`, `edge_sum`, `edge_ma`, `edge_mb`, `edge_dstar`, `wall_sum`, `wall_ma`, `wall_mb`, `wall_dstar`, `hc_alpha`)
    ///
    /// # Outputs
    /// - `dydot_dp`: 8×24 matrix
    ///
    /// # Cost
    /// 364 add/sub, 728 mul, 10 div, 8 sqrt, 6 transcendental, 24 branches; 280 `let`s.
    pub fn rhs_p<T: Real>(y: &SVector<T, 8>, p: &SVector<T, 24>) -> SMatrix<T, 8, 24> {
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
        let t0 = T::from_f64(0.5) * d;
        let t1 = T::from_f64(0.5) * theta;
        let (t2, t3) = t1.sin_cos();
        let t4 = t2 * t2;
        let t5 = r * sin_theta;
        let t6 = r * cos_theta;
        let t7 = T::from_f64(2.0) * t4;
        let t8 = t7 - T::from_f64(1.0);
        let t9 = zdot * sin_theta;
        let t10 = t2 * t3;
        let t11 = l_c - rho_p;
        let t12 = r - rho_p;
        let t13 = sin_theta * t11;
        let t14 = -T::from_f64(2.0) * t4 * t12;
        let t15 = rho_p * sin_theta;
        let t16 = cos_theta * (r - T::from_f64(2.0) * rho_p * t4);
        let t17 = cos_theta * t11;
        let t18 = rho_h + t0 - x;
        let t19 = T::from_f64(1.0) / m;
        let t20 = T::from_f64(1.0) / j;
        let t21 = t7 - sin_theta;
        let t22 = sin_theta + t7;
        let t23 = sin_theta * t19;
        let t24 = cos_theta * t19;
        let t25 = z - rho_h;
        let t26 = sin_theta * t25;
        let t27 = cos_theta * t25;
        let t28 = sin_theta * (l_c - rho_p + t15) + t16;
        let t29 = sin_theta * (-l_c + rho_p + t15) + t16;
        let t30 = thetadot * t29;
        let slip_wall_left = zdot + t30;
        let t31 = v_s.hypot(slip_wall_left);
        let t32 = T::from_f64(1.0) / t31;
        let t33 = slip_wall_left * slip_wall_left;
        let t34 = sin_theta * t18 - t27;
        let t35 = t5 - cos_theta * t34;
        let t36 = t6 + sin_theta * t34;
        let slip_edge_right = sin_theta * (xdot - thetadot * t35)
            + cos_theta * (zdot - thetadot * t36);
        let t37 = t27 - T::from_f64(2.0) * t10 * t18;
        let t38 = v_s.hypot(slip_edge_right);
        let t39 = T::from_f64(1.0) / t38;
        let t40 = sin_theta * t35 + cos_theta * t36;
        let t41 = slip_edge_right * slip_edge_right;
        let t42 = T::from_f64(2.0) * (t10 * t12);
        let t43 = t17 + t42;
        let neg_delta_rate_wall_left = xdot + thetadot * t43;
        let t44 = T::from_f64(1.0) - hc_alpha * neg_delta_rate_wall_left;
        let t45 = t44.max0();
        let t46 = T::from_f64(1.0) - t45;
        let t47 = -rho_h - t0 - x;
        let delta_edge_left = r - t0 - x + t26 - T::from_f64(2.0) * t47 * t4;
        let pen_edge_left = delta_edge_left.max0();
        let t48 = pen_edge_left * pen_edge_left.sqrt();
        let step_delta_edge_left = delta_edge_left.step();
        let delta_wall_right = r - t0 + x + t13 + t14;
        let pen_wall_right = delta_wall_right.max0();
        let t49 = pen_wall_right * pen_wall_right.sqrt();
        let step_delta_wall_right = delta_wall_right.step();
        let t50 = t17 - t42;
        let delta_rate_wall_right = xdot + thetadot * t50;
        let t51 = T::from_f64(1.0) + hc_alpha * delta_rate_wall_right;
        let t52 = t51.max0();
        let t53 = sin_theta * t47 - t27;
        let t54 = cos_theta * t53 + t5;
        let t55 = t6 - sin_theta * t53;
        let slip_edge_left = sin_theta * (xdot + thetadot * t54)
            + cos_theta * (zdot + thetadot * t55);
        let t56 = t27 - T::from_f64(2.0) * t10 * t47;
        let t57 = v_s.hypot(slip_edge_left);
        let t58 = T::from_f64(1.0) / t57;
        let t59 = sin_theta * t54 + cos_theta * t55;
        let t60 = slip_edge_left * slip_edge_left;
        let t61 = T::from_f64(1.0) - t52;
        let delta_edge_right = r - t0 + x - t26 + T::from_f64(2.0) * t4 * t18;
        let pen_edge_right = delta_edge_right.max0();
        let t62 = pen_edge_right * pen_edge_right.sqrt();
        let step_delta_edge_right = delta_edge_right.step();
        let t63 = step_delta_wall_right - t61;
        let delta_wall_left = r - t0 - x - t13 + t14;
        let pen_wall_left = delta_wall_left.max0();
        let t64 = pen_wall_left * pen_wall_left.sqrt();
        let step_delta_wall_left = delta_wall_left.step();
        let t65 = step_delta_wall_left - t46;
        let t66 = t64 * (t45 - T::from_f64(1.0) + step_delta_wall_left)
            - t49 * (-T::from_f64(1.0) + step_delta_wall_right + t52);
        let t67 = T::from_f64(1.0) / (t31 * t31 * t31);
        let t68 = t33 * t67;
        let t69 = slip_edge_right * t39;
        let t70 = T::from_f64(1.0) / (t38 * t38 * t38);
        let t71 = thetadot * hc_alpha;
        let t72 = t10 * t71;
        let t73 = t71 * cos_theta;
        let t74 = slip_wall_left * t32;
        let t75 = t39 * t41;
        let t76 = t32 * t33;
        let t77 = t67 * (slip_wall_left * slip_wall_left * slip_wall_left);
        let t78 = t44.step();
        let t79 = T::from_f64(1.5) - T::from_f64(1.5) * t45;
        let sqrt_pen_edge_left = pen_edge_left.sqrt();
        let t80 = step_delta_edge_left * step_delta_edge_left;
        let sqrt_pen_wall_right = pen_wall_right.sqrt();
        let t81 = step_delta_wall_right * step_delta_wall_right;
        let t82 = sqrt_pen_edge_left * t80;
        let t83 = t51.step();
        let t84 = step_delta_edge_left * sqrt_pen_edge_left;
        let sqrt_pen_edge_right = pen_edge_right.sqrt();
        let t85 = step_delta_edge_right * step_delta_edge_right;
        let t86 = step_delta_edge_right * sqrt_pen_edge_right;
        let t87 = T::from_f64(1.5) - T::from_f64(1.5) * t52;
        let t88 = sqrt_pen_wall_right
            * (step_delta_wall_right * t87 - T::from_f64(1.5) * t81);
        let t89 = sqrt_pen_edge_right * t85;
        let t90 = t83 * t49;
        let sqrt_pen_wall_left = pen_wall_left.sqrt();
        let t91 = step_delta_wall_left * step_delta_wall_left;
        let t92 = step_delta_wall_left * t79 - T::from_f64(1.5) * t91;
        let t93 = sqrt_pen_wall_left * t92;
        let t94 = t64 * t78;
        let t95 = step_delta_wall_left * sqrt_pen_wall_left;
        let t96 = t95 * t79;
        let t97 = step_delta_wall_right * sqrt_pen_wall_right;
        let t98 = t97 * t87;
        let t99 = T::from_f64(0.5) - t4;
        let t100 = thetadot * t28;
        let t101 = T::from_f64(2.0) * t10;
        let t102 = t101 - cos_theta;
        let t103 = cos_theta + t101;
        let t104 = T::from_f64(2.0) * (cos_theta * t4);
        let slip_wall_right = zdot - t100;
        let t105 = v_s.hypot(slip_wall_right);
        let t106 = T::from_f64(1.0) / t105;
        let t107 = slip_wall_right * slip_wall_right;
        let t108 = slip_wall_right * t106;
        let t109 = mu * t40;
        let t110 = t108 * t28;
        let t111 = t110 * mu;
        let t112 = t106 * t107;
        let t113 = mu * k_wall;
        let t114 = t74 * t29;
        let t115 = t114 * mu;
        let t116 = t115 * t45;
        let t117 = T::from_f64(1.0) / (t105 * t105 * t105);
        let t118 = t39 - t41 * t70;
        let t119 = t107 * t117;
        let t120 = t106 - t119;
        let t121 = t32 - t68;
        let t122 = t117 * (slip_wall_right * slip_wall_right * slip_wall_right);
        let t123 = t69 * t109;
        let t124 = sin_theta * (T::from_f64(1.0) - sin_theta) + t104;
        let t125 = t71 * t102;
        let t126 = mu * sin_theta;
        let t127 = mu * cos_theta;
        let t128 = t71 * t103;
        let t129 = slip_wall_right * t117;
        let t130 = t10 * hc_alpha;
        let t131 = t10 * thetadot;
        let t132 = T::from_f64(0.75) - T::from_f64(0.75) * t45;
        let t133 = hc_alpha * t103 * t78;
        let t134 = t113 * t19;
        let t135 = mu * t19;
        let t136 = k_wall * t20;
        let t137 = t19 * t19;
        let t138 = T::from_f64(1.0) - t7;
        let neg_delta_rate_edge_right = -(xdot * t138) + t9 + thetadot * t37;
        let t139 = T::from_f64(1.0) - hc_alpha * neg_delta_rate_edge_right;
        let t140 = t139.max0();
        let t141 = T::from_f64(1.0) - t140;
        let t142 = t141 - step_delta_edge_right;
        let t143 = t62 * t141;
        let t144 = t139.step();
        let t145 = T::from_f64(1.5) - T::from_f64(1.5) * t140;
        let t146 = t62 * t144;
        let t147 = t86 * t140;
        let t148 = t146 * neg_delta_rate_edge_right;
        let t149 = T::from_f64(0.75) * t81;
        let t150 = t49 * t61;
        let t151 = t140 * t62;
        let t152 = t69 * t151;
        let t153 = t52 * t49;
        let t154 = t153 * t108;
        let t155 = t69 * t140;
        let t156 = t111 * t52;
        let t157 = t64 * t45;
        let t158 = t74 * t157;
        let t159 = t154 + t158;
        let t160 = t112 * t153 + t76 * t157;
        let t161 = t64 * (t116 - t43 * t65) - t49 * (t156 - t50 * t63);
        let t162 = T::from_f64(1.0) / (t57 * t57 * t57);
        let t163 = t58 - t60 * t162;
        let t164 = t151 * t118;
        let t165 = t155 * step_delta_edge_right;
        let t166 = t97 * t52;
        let t167 = t166 * t112;
        let t168 = slip_edge_left * t58;
        let t169 = t166 * t108;
        let t170 = t90 * t108;
        let t171 = -t153 * t120;
        let t172 = t153 * t28;
        let t173 = t157 * t121;
        let t174 = t95 * t45;
        let t175 = t174 * t76;
        let t176 = t157 * (T::from_f64(2.0) * t74 - t77);
        let t177 = t74 * t174;
        let t178 = t74 * t94;
        let delta_rate_edge_left = xdot * t8 + t9 + thetadot * t56;
        let t179 = T::from_f64(1.0) + hc_alpha * delta_rate_edge_left;
        let t180 = t179.max0();
        let t181 = t179.step();
        let t182 = sin_theta * (T::from_f64(1.0) + sin_theta) - t104;
        let t183 = T::from_f64(1.0) - t180;
        let t184 = t48 * t183;
        let t185 = step_delta_edge_left - t183;
        let t186 = t168 * t180;
        let t187 = t126 * t186;
        let t188 = t48 * t180;
        let t189 = t188 * t168 + t152;
        let t190 = sin_theta * (t48 * t185 + t62 * t142) + t127 * t189;
        let t191 = T::from_f64(1.5) - T::from_f64(1.5) * t180;
        let t192 = t48 * t181;
        let t193 = t72 * t192;
        let t194 = t99 * t191 * t84 + t193;
        let t195 = t72 * t146;
        let t196 = t145 * t99 * t86 + t195;
        let t197 = T::from_f64(0.75) * t52 - T::from_f64(0.75);
        let t198 = t125 * t192;
        let t199 = t128 * t146;
        let t200 = t84 * t180;
        let t201 = T::from_f64(1.5) * t200 * t21 + t198;
        let t202 = T::from_f64(1.5) * t147 * t22 + t199;
        let t203 = t168 * t201 + t69 * t202;
        let t204 = t82 * t21;
        let t205 = t89 * t22;
        let t206 = k_edge * t189;
        let t207 = t188 * t162;
        let t208 = t207 * slip_edge_left;
        let t209 = t151 * t70;
        let t210 = t209 * slip_edge_right;
        let t211 = k_edge * (t208 + t210);
        let t212 = t192 * delta_rate_edge_left;
        let t213 = t90 * delta_rate_wall_right;
        let t214 = t188 * t163;
        let t215 = t186 * t84 + t155 * t86;
        let t216 = sqrt_pen_edge_left
            * (T::from_f64(1.5) * t80 - t191 * step_delta_edge_left);
        let t217 = t52 * t124;
        let t218 = hc_alpha * t83 * t102;
        let t219 = t49 * (t217 * t120 + t218 * t108);
        let t220 = t166 * t21;
        let t221 = t168 * t59;
        let t222 = t221 * mu;
        let t223 = t222 * t180;
        let t224 = sqrt_pen_wall_right * t81;
        let t225 = t90 * t112;
        let t226 = t58 * t60;
        let t227 = t200 * t226 + t147 * t75;
        let t228 = t226 * t188 + t75 * t151;
        let t229 = t48 * (t8 * t185 + t187) + t62 * (t155 * t126 - t138 * t142);
        let t230 = t48 * (t56 * t185 + t223) - t62 * (t109 * t155 - t37 * t142);
        let t231 = sqrt_pen_edge_right
            * (T::from_f64(1.5) * t85 - t145 * step_delta_edge_right);
        let t232 = t198 - t21 * t191 * t84;
        let t233 = t199 - t22 * t145 * t86;
        let t234 = T::from_f64(1.5) * t204 + t232;
        let t235 = T::from_f64(1.5) * t205 + t233;
        let t236 = -t153 * (T::from_f64(2.0) * t108 - t122);
        let t237 = t64 * t46;
        let t238 = -T::from_f64(0.75) * t91;
        let t239 = t94 * neg_delta_rate_wall_left;
        let t240 = t169 + t177;
        let t241 = k_wall * t138;
        let t242 = t45 * t182;
        let t243 = t64 * (t242 * t121 + t133 * t74);
        let t244 = t157 * (slip_wall_left * t67);
        let t245 = t98 * t138 + T::from_f64(2.0) * t72 * t90;
        let t246 = sqrt_pen_wall_left * t91;
        let t247 = t167 + t175;
        let t248 = t73 * t90 - t98 * sin_theta;
        let t249 = t125 * t90 - t98 * t21;
        let t250 = t96 * t138 + T::from_f64(2.0) * t72 * t94;
        let t251 = t73 * t94 - t96 * sin_theta;
        let t252 = t128 * t94 - t96 * t22;
        let t253 = t76 * t94;
        SMatrix::<
            T,
            8,
            24,
        >::from_row_slice(
            &[
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
                -(-(k_edge * t229) + k_wall * t66 + f1 * sin_theta + f2 * cos_theta)
                    * t137,
                T::from_f64(0.0),
                t19
                    * (k_edge
                        * (t126 * (thetadot * (t164 - t214) - T::from_f64(1.5) * t215)
                            - t216 * t8 - t231 * t138)
                        - k_wall
                            * (t138 * (t93 - t88)
                                + T::from_f64(2.0) * t72 * (t94 - t90))),
                k_wall * (sin_theta * (t88 + t93) - t73 * (t90 + t94)) * t19,
                -t19
                    * (k_edge
                        * (-(t99
                            * (T::from_f64(1.5)
                                * (t8 * t80 + t187 * step_delta_edge_left)
                                * sqrt_pen_edge_left
                                + T::from_f64(1.5) * (t138 * t85 + t165 * t126)
                                    * sqrt_pen_edge_right))
                            + t126 * (t192 * t168 + t146 * t69) * t72 + t8 * t194
                            + t138 * t196)
                        - k_wall
                            * (sqrt_pen_wall_right
                                * (step_delta_wall_right * t197 + t149)
                                + sqrt_pen_wall_left
                                    * (step_delta_wall_left * t132 + t238))),
                k_wall
                    * (t88 * t21 - t22 * t92 * sqrt_pen_wall_left
                        + t71 * (t94 * t103 - t90 * t102)) * t19,
                -(k_edge * (t126 * t203 + t8 * t234 + t138 * t235)) * t19,
                -t23 * t206,
                t126 * (t211 * v_s) * t19,
                -t19 * t229,
                t19 * t66,
                t23,
                t24,
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
                -t19
                    * (k_edge * (t212 * (t8 + t126 * t168) - t148 * (t138 + t126 * t69))
                        + k_wall * (t213 + t239)),
                (k_edge * t190 + t113 * t159 - f1 * cos_theta + f2 * sin_theta) * t137,
                T::from_f64(0.0),
                -t19
                    * (mu
                        * (thetadot
                            * (cos_theta
                                * (k_edge * (t214 - t164) + k_wall * (t171 + t173))
                                - T::from_f64(2.0) * (t130 * (t170 + t178)) * k_wall)
                            + T::from_f64(1.5) * (cos_theta * t215) * k_edge
                            + T::from_f64(1.5) * t241 * t240)
                        + sin_theta * (t216 - t231) * k_edge),
                -t134
                    * (thetadot
                        * (sin_theta * (t171 - t173)
                            + cos_theta * (t170 - t178) * hc_alpha)
                        + T::from_f64(1.5) * (t169 - t177) * sin_theta),
                t19
                    * (k_edge
                        * (sin_theta
                            * (T::from_f64(1.5) * (t82 - t89) * t99 - t194 + t196)
                            + t127
                                * (-(t168 * (t193 - T::from_f64(1.5) * t200 * t99))
                                    - t69 * (t195 - T::from_f64(1.5) * t147 * t99)))
                        + T::from_f64(0.75) * t113 * t240),
                -t134
                    * (thetadot * (t219 + t243)
                        + T::from_f64(1.5) * (t220 * t108 + t177 * t22)),
                -(k_edge
                    * (sin_theta * (T::from_f64(1.5) * (t204 - t205) + t232 - t233)
                        + t127 * t203)) * t19,
                -t19 * (t206 * cos_theta + k_wall * t159),
                t135 * (v_s * (t211 * cos_theta + k_wall * (t129 * t153 + t244))),
                -t19 * t190,
                -t135 * t159,
                t24,
                -t23,
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
                -t19
                    * (k_edge
                        * (sin_theta * (t212 + t148) + t127 * (t212 * t168 - t148 * t69))
                        + t113 * (t213 * t108 - t239 * t74)),
                T::from_f64(0.0),
                (-m_2 + k_edge * t230 + k_wall * t161) * (t20 * t20),
                t20
                    * (mu
                        * (thetadot
                            * (k_wall
                                * (cos_theta * (-(t172 * t120) - t173 * t29)
                                    - T::from_f64(2.0) * t130 * (t110 * t90 - t114 * t94))
                                + k_edge * (-(t59 * t163 * t188) - t40 * t118 * t151))
                            + k_edge
                                * (t155 * (t62 + T::from_f64(1.5) * t86 * t40)
                                    - t186 * (t48 + T::from_f64(1.5) * t84 * t59))
                            + k_wall
                                * (cos_theta * (t154 - t158)
                                    + T::from_f64(1.5) * (t166 * t110 - t174 * t114) * t138))
                        + k_wall
                            * (t10
                                * (T::from_f64(2.0) * t63 * t49
                                    + T::from_f64(2.0) * t65 * t64)
                                - t50 * (T::from_f64(1.5) * t224 * t138 - t245)
                                + t43 * (T::from_f64(1.5) * t246 * t138 - t250))
                        + k_edge * (t231 * t37 - t216 * t56)),
                t136
                    * (sin_theta
                        * (mu
                            * (t52
                                * (t49 * (t100 * t119 - t106 * (t100 - slip_wall_right))
                                    + T::from_f64(1.5) * t110 * t97)
                                + t45
                                    * (T::from_f64(1.5) * t114 * t95
                                        - t64 * (t30 * t68 - t32 * (slip_wall_left + t30))))
                            - T::from_f64(1.5) * (t224 * t50 + t246 * t43))
                        + cos_theta
                            * (t49 * (-step_delta_wall_right + t61 + t111 * t71 * t83)
                                + t64 * (step_delta_wall_left - t46 + t115 * t71 * t78))
                        - t50 * t248 - t43 * t251),
                t20
                    * (k_edge
                        * (-(t10
                            * (t48 * (step_delta_edge_left - t183 + t222 * t71 * t181)
                                - t62
                                    * (-step_delta_edge_right + t141 + t123 * t71 * t144)))
                            + t99
                                * (T::from_f64(1.5)
                                    * (t56 * t80 + t223 * step_delta_edge_left)
                                    * sqrt_pen_edge_left
                                    - T::from_f64(1.5) * (t37 * t85 + t165 * t109)
                                        * sqrt_pen_edge_right) - t56 * t194 + t37 * t196)
                        + k_wall
                            * (sqrt_pen_wall_left
                                * (t43 * (t238 + t132 * step_delta_wall_left)
                                    + T::from_f64(0.75) * t116 * step_delta_wall_left)
                                - sqrt_pen_wall_right
                                    * (T::from_f64(0.75) * t156 * step_delta_wall_right
                                        - t50 * (t149 + t197 * step_delta_wall_right)))),
                -t136
                    * (mu
                        * (thetadot * (t243 * t29 - t219 * t28)
                            - t52 * (T::from_f64(1.5) * t97 * t28 * t21 - t49 * t124)
                                * t108
                            + t45 * (t64 * t182 + T::from_f64(1.5) * t95 * t29 * t22)
                                * t74) + t50 * (T::from_f64(1.5) * t224 * t21 + t249)
                        + t102 * t63 * t49 - t43 * (T::from_f64(1.5) * t246 * t22 + t252)
                        + t103 * t65 * t64),
                -(k_edge
                    * (mu * (t221 * t201 - t40 * t202 * t69) + t56 * t234
                        + t102 * t185 * t48 - t37 * t235 - t103 * t142 * t62)) * t20,
                -t20
                    * (k_edge * (t221 * t188 - t152 * t40)
                        - k_wall * (t110 * t153 - t114 * t157)),
                v_s
                    * (k_edge * (t208 * t59 - t210 * t40)
                        - k_wall * (t129 * t172 - t244 * t29)) * mu * t20,
                -t20 * t230,
                -t20 * t161,
                T::from_f64(0.0),
                T::from_f64(0.0),
                t20,
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                -t20
                    * (k_edge * (t212 * (t56 + t222) + t148 * (t37 + t123))
                        + k_wall * (-(t213 * (t111 - t50)) - t239 * (t115 - t43))),
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
                zdot * cos_theta + xdot * sin_theta,
                xdot * cos_theta - t9,
                thetadot,
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
                mu
                    * (thetadot
                        * (k_wall
                            * (cos_theta * (t236 + t176)
                                - T::from_f64(2.0) * t130 * (t225 + t253))
                            + k_edge
                                * (t188
                                    * (T::from_f64(2.0) * t168
                                        - t162 * (slip_edge_left * slip_edge_left * slip_edge_left))
                                    - t151
                                        * (T::from_f64(2.0) * t69
                                            - t70
                                                * (slip_edge_right * slip_edge_right * slip_edge_right))))
                        + T::from_f64(1.5) * t227 * k_edge
                        + T::from_f64(1.5) * t241 * t247)
                    + k_wall
                        * (T::from_f64(2.0) * t131 * (t150 + t237)
                            - delta_rate_wall_right * t245
                            + neg_delta_rate_wall_left * t250)
                    + k_edge
                        * (t86 * neg_delta_rate_edge_right * t145
                            - t84 * delta_rate_edge_left * t191),
                k_wall
                    * (mu
                        * (sin_theta
                            * (thetadot * (t236 - t176)
                                + T::from_f64(1.5) * (t167 - t175)) - t73 * (t253 - t225))
                        + cos_theta * (t237 - t150) * thetadot
                        + delta_rate_wall_right * t248
                        + neg_delta_rate_wall_left * t251),
                -(k_edge
                    * (t131
                        * (-(hc_alpha * (t226 * t192 + t75 * t146) * mu) + t184 + t143)
                        + T::from_f64(1.5) * (t99 * t227) * mu
                        - delta_rate_edge_left * t194
                        + neg_delta_rate_edge_right * t196))
                    - k_wall
                        * (T::from_f64(0.75) * t247 * mu
                            + t97 * delta_rate_wall_right * t197
                            + t95 * neg_delta_rate_wall_left * t132),
                -k_wall
                    * (mu
                        * (thetadot
                            * (t49
                                * (t122 * t217
                                    - t106
                                        * (t218 * t107 + T::from_f64(2.0) * t217 * slip_wall_right))
                                + t64
                                    * (t77 * t242
                                        - t32
                                            * (t133 * t33 + T::from_f64(2.0) * t242 * slip_wall_left)))
                            - T::from_f64(1.5) * (t220 * t112 + t175 * t22))
                        + thetadot * (t150 * t102 + t237 * t103)
                        - delta_rate_wall_right * t249
                        + neg_delta_rate_wall_left * t252),
                -k_edge
                    * (-(mu * (t226 * t201 + t75 * t202))
                        + thetadot * (t184 * t102 + t143 * t103)
                        - delta_rate_edge_left * t232
                        + neg_delta_rate_edge_right * t233),
                k_edge * t228 + k_wall * t160,
                -(v_s
                    * (k_edge * (t207 * t60 + t209 * t41)
                        + k_wall * (t119 * t153 + t68 * t157)) * mu),
                mu * t228 - t184 * delta_rate_edge_left
                    + t143 * neg_delta_rate_edge_right,
                mu * t160 - t150 * delta_rate_wall_right
                    + t237 * neg_delta_rate_wall_left,
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
                mu
                    * (k_edge * (t212 * t226 - t75 * t148)
                        - k_wall * (t239 * t76 - t213 * t112))
                    + k_edge
                        * (t192 * (delta_rate_edge_left * delta_rate_edge_left)
                            + t146
                                * (neg_delta_rate_edge_right * neg_delta_rate_edge_right))
                    + k_wall
                        * (t90 * (delta_rate_wall_right * delta_rate_wall_right)
                            + t94
                                * (neg_delta_rate_wall_left * neg_delta_rate_wall_left)),
            ],
        )
    }
}
