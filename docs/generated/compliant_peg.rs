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
    #[inline]
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
        let t68 = T::from_f64(0.5) - t4;
        let t69 = t33 * t67;
        let t70 = t67 * (slip_wall_left * slip_wall_left * slip_wall_left);
        let t71 = thetadot * t28;
        let t72 = T::from_f64(2.0) * t10;
        let t73 = t72 - cos_theta;
        let t74 = cos_theta + t72;
        let t75 = T::from_f64(2.0) * (cos_theta * t4);
        let slip_wall_right = zdot - t71;
        let t76 = v_s.hypot(slip_wall_right);
        let t77 = T::from_f64(1.0) / t76;
        let t78 = slip_wall_right * slip_wall_right;
        let t79 = slip_edge_right * t39;
        let t80 = slip_wall_right * t77;
        let t81 = mu * t40;
        let t82 = t80 * t28;
        let t83 = t82 * mu;
        let t84 = t39 * t41;
        let t85 = t77 * t78;
        let t86 = slip_wall_left * t32;
        let t87 = mu * k_wall;
        let t88 = t32 * t33;
        let t89 = t86 * t29;
        let t90 = t89 * mu;
        let t91 = t90 * t45;
        let t92 = T::from_f64(1.0) / (t38 * t38 * t38);
        let t93 = T::from_f64(1.0) / (t76 * t76 * t76);
        let t94 = sin_theta * (T::from_f64(1.0) - sin_theta) + t75;
        let t95 = thetadot * hc_alpha;
        let t96 = t95 * cos_theta;
        let t97 = t95 * t73;
        let t98 = mu * sin_theta;
        let t99 = mu * cos_theta;
        let t100 = t39 - t41 * t92;
        let t101 = t10 * t95;
        let t102 = t95 * t74;
        let t103 = t32 - t69;
        let t104 = t78 * t93;
        let t105 = t77 - t104;
        let t106 = slip_wall_right * t93;
        let t107 = t79 * t81;
        let t108 = t10 * hc_alpha;
        let t109 = t93 * (slip_wall_right * slip_wall_right * slip_wall_right);
        let t110 = t10 * thetadot;
        let t111 = t44.step();
        let t112 = T::from_f64(1.5) - T::from_f64(1.5) * t45;
        let t113 = T::from_f64(0.75) - T::from_f64(0.75) * t45;
        let t114 = hc_alpha * t74 * t111;
        let t115 = t87 * t19;
        let t116 = mu * t19;
        let t117 = k_wall * t20;
        let t118 = t19 * t19;
        let t119 = T::from_f64(1.0) - t7;
        let neg_delta_rate_edge_right = -(xdot * t119) + t9 + thetadot * t37;
        let t120 = T::from_f64(1.0) - hc_alpha * neg_delta_rate_edge_right;
        let t121 = t120.max0();
        let t122 = T::from_f64(1.0) - t121;
        let t123 = t122 - step_delta_edge_right;
        let sqrt_pen_edge_left = pen_edge_left.sqrt();
        let t124 = step_delta_edge_left * step_delta_edge_left;
        let sqrt_pen_wall_right = pen_wall_right.sqrt();
        let t125 = step_delta_wall_right * step_delta_wall_right;
        let t126 = T::from_f64(0.75) * t125;
        let t127 = sqrt_pen_edge_left * t124;
        let t128 = t51.step();
        let t129 = t49 * t61;
        let t130 = t62 * t122;
        let t131 = t121 * t62;
        let t132 = t79 * t131;
        let t133 = t52 * t49;
        let t134 = t133 * t80;
        let t135 = t79 * t121;
        let t136 = t83 * t52;
        let t137 = t64 * t45;
        let t138 = t86 * t137;
        let t139 = t134 + t138;
        let t140 = t85 * t133 + t88 * t137;
        let t141 = t64 * (t91 - t43 * t65) - t49 * (t136 - t50 * t63);
        let delta_rate_edge_left = xdot * t8 + t9 + thetadot * t56;
        let t142 = T::from_f64(1.0) + hc_alpha * delta_rate_edge_left;
        let t143 = t142.max0();
        let t144 = t142.step();
        let t145 = t120.step();
        let t146 = T::from_f64(1.0) / (t57 * t57 * t57);
        let t147 = sin_theta * (T::from_f64(1.0) + sin_theta) - t75;
        let t148 = t128 * t49;
        let t149 = T::from_f64(1.0) - t143;
        let t150 = t48 * t149;
        let t151 = step_delta_edge_left - t149;
        let t152 = slip_edge_left * t58;
        let t153 = t152 * t143;
        let t154 = t98 * t153;
        let t155 = t48 * t143;
        let t156 = t155 * t152 + t132;
        let t157 = sin_theta * (t48 * t151 + t62 * t123) + t99 * t156;
        let sqrt_pen_edge_right = pen_edge_right.sqrt();
        let t158 = step_delta_edge_right * step_delta_edge_right;
        let t159 = T::from_f64(1.5) - T::from_f64(1.5) * t143;
        let t160 = t131 * t100;
        let t161 = T::from_f64(1.5) - T::from_f64(1.5) * t52;
        let t162 = sqrt_pen_wall_right
            * (step_delta_wall_right * t161 - T::from_f64(1.5) * t125);
        let t163 = step_delta_edge_left * sqrt_pen_edge_left;
        let t164 = t48 * t144;
        let t165 = t101 * t164;
        let t166 = t68 * t159 * t163 + t165;
        let t167 = T::from_f64(1.5) - T::from_f64(1.5) * t121;
        let t168 = step_delta_edge_right * sqrt_pen_edge_right;
        let t169 = t62 * t145;
        let t170 = t101 * t169;
        let t171 = t68 * t167 * t168 + t170;
        let t172 = t135 * step_delta_edge_right;
        let t173 = T::from_f64(0.75) * t52 - T::from_f64(0.75);
        let t174 = t97 * t164;
        let t175 = t102 * t169;
        let t176 = t163 * t143;
        let t177 = T::from_f64(1.5) * t176 * t21 + t174;
        let t178 = t168 * t121;
        let t179 = T::from_f64(1.5) * t178 * t22 + t175;
        let t180 = t152 * t177 + t79 * t179;
        let t181 = t127 * t21;
        let t182 = sqrt_pen_edge_right * t158;
        let t183 = t182 * t22;
        let t184 = k_edge * t156;
        let t185 = t155 * t146;
        let t186 = t185 * slip_edge_left;
        let t187 = t131 * t92;
        let t188 = t187 * slip_edge_right;
        let t189 = k_edge * (t186 + t188);
        let t190 = t164 * delta_rate_edge_left;
        let t191 = t148 * delta_rate_wall_right;
        let t192 = t58 - t60 * t146;
        let t193 = t155 * t192;
        let t194 = t153 * t163 + t135 * t168;
        let t195 = step_delta_wall_right * sqrt_pen_wall_right;
        let t196 = t195 * t52;
        let t197 = t196 * t80;
        let t198 = sqrt_pen_edge_left
            * (T::from_f64(1.5) * t124 - t159 * step_delta_edge_left);
        let t199 = t148 * t80;
        let t200 = t52 * t94;
        let t201 = hc_alpha * t128 * t73;
        let t202 = t49 * (t200 * t105 + t201 * t80);
        let t203 = t196 * t21;
        let t204 = t169 * neg_delta_rate_edge_right;
        let t205 = t152 * t59;
        let t206 = t205 * mu;
        let t207 = t206 * t143;
        let t208 = sqrt_pen_wall_right * t125;
        let t209 = t148 * t85;
        let t210 = t58 * t60;
        let t211 = t176 * t210 + t178 * t84;
        let t212 = t196 * t85;
        let t213 = t210 * t155 + t84 * t131;
        let t214 = t48 * (t8 * t151 + t154) + t62 * (t135 * t98 - t119 * t123);
        let t215 = t48 * (t56 * t151 + t207) - t62 * (t81 * t135 - t37 * t123);
        let t216 = sqrt_pen_edge_right
            * (T::from_f64(1.5) * t158 - t167 * step_delta_edge_right);
        let t217 = t174 - t21 * t159 * t163;
        let t218 = t175 - t22 * t167 * t168;
        let t219 = T::from_f64(1.5) * t181 + t217;
        let t220 = T::from_f64(1.5) * t183 + t218;
        let t221 = -t133 * t105;
        let t222 = t133 * t28;
        let t223 = -t133 * (T::from_f64(2.0) * t80 - t109);
        let t224 = t64 * t46;
        let sqrt_pen_wall_left = pen_wall_left.sqrt();
        let t225 = step_delta_wall_left * step_delta_wall_left;
        let t226 = step_delta_wall_left * t112 - T::from_f64(1.5) * t225;
        let t227 = sqrt_pen_wall_left * t226;
        let t228 = -T::from_f64(0.75) * t225;
        let t229 = t64 * t111;
        let t230 = t229 * neg_delta_rate_wall_left;
        let t231 = t137 * t103;
        let t232 = t86 * t229;
        let t233 = step_delta_wall_left * sqrt_pen_wall_left;
        let t234 = t233 * t45;
        let t235 = t86 * t234;
        let t236 = t197 + t235;
        let t237 = k_wall * t119;
        let t238 = t45 * t147;
        let t239 = t64 * (t238 * t103 + t114 * t86);
        let t240 = t137 * (slip_wall_left * t67);
        let t241 = t195 * t161;
        let t242 = t241 * t119 + T::from_f64(2.0) * t101 * t148;
        let t243 = sqrt_pen_wall_left * t225;
        let t244 = t233 * t112;
        let t245 = t137 * (T::from_f64(2.0) * t86 - t70);
        let t246 = t234 * t88;
        let t247 = t212 + t246;
        let t248 = t96 * t148 - t241 * sin_theta;
        let t249 = t97 * t148 - t241 * t21;
        let t250 = t244 * t119 + T::from_f64(2.0) * t101 * t229;
        let t251 = t96 * t229 - t244 * sin_theta;
        let t252 = t102 * t229 - t244 * t22;
        let t253 = t88 * t229;
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
                -(-(k_edge * t214) + k_wall * t66 + f1 * sin_theta + f2 * cos_theta)
                    * t118,
                T::from_f64(0.0),
                t19
                    * (k_edge
                        * (t98 * (thetadot * (t160 - t193) - T::from_f64(1.5) * t194)
                            - t198 * t8 - t216 * t119)
                        - k_wall
                            * (t119 * (t227 - t162)
                                + T::from_f64(2.0) * t101 * (t229 - t148))),
                k_wall * (sin_theta * (t162 + t227) - t96 * (t148 + t229)) * t19,
                -t19
                    * (k_edge
                        * (-(t68
                            * (T::from_f64(1.5)
                                * (t8 * t124 + t154 * step_delta_edge_left)
                                * sqrt_pen_edge_left
                                + T::from_f64(1.5) * (t119 * t158 + t172 * t98)
                                    * sqrt_pen_edge_right))
                            + t98 * (t164 * t152 + t169 * t79) * t101 + t8 * t166
                            + t119 * t171)
                        - k_wall
                            * (sqrt_pen_wall_right
                                * (step_delta_wall_right * t173 + t126)
                                + sqrt_pen_wall_left
                                    * (step_delta_wall_left * t113 + t228))),
                k_wall
                    * (t162 * t21 - t22 * t226 * sqrt_pen_wall_left
                        + t95 * (t229 * t74 - t148 * t73)) * t19,
                -(k_edge * (t98 * t180 + t8 * t219 + t119 * t220)) * t19,
                -t23 * t184,
                t98 * (t189 * v_s) * t19,
                -t19 * t214,
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
                    * (k_edge * (t190 * (t8 + t98 * t152) - t204 * (t119 + t98 * t79))
                        + k_wall * (t191 + t230)),
                (k_edge * t157 + t87 * t139 - f1 * cos_theta + f2 * sin_theta) * t118,
                T::from_f64(0.0),
                -t19
                    * (mu
                        * (thetadot
                            * (cos_theta
                                * (k_edge * (t193 - t160) + k_wall * (t221 + t231))
                                - T::from_f64(2.0) * (t108 * (t199 + t232)) * k_wall)
                            + T::from_f64(1.5) * (cos_theta * t194) * k_edge
                            + T::from_f64(1.5) * t237 * t236)
                        + sin_theta * (t198 - t216) * k_edge),
                -t115
                    * (thetadot
                        * (sin_theta * (t221 - t231)
                            + cos_theta * (t199 - t232) * hc_alpha)
                        + T::from_f64(1.5) * (t197 - t235) * sin_theta),
                t19
                    * (k_edge
                        * (sin_theta
                            * (T::from_f64(1.5) * (t127 - t182) * t68 - t166 + t171)
                            + t99
                                * (-(t152 * (t165 - T::from_f64(1.5) * t176 * t68))
                                    - t79 * (t170 - T::from_f64(1.5) * t178 * t68)))
                        + T::from_f64(0.75) * t87 * t236),
                -t115
                    * (thetadot * (t202 + t239)
                        + T::from_f64(1.5) * (t203 * t80 + t235 * t22)),
                -(k_edge
                    * (sin_theta * (T::from_f64(1.5) * (t181 - t183) + t217 - t218)
                        + t99 * t180)) * t19,
                -t19 * (t184 * cos_theta + k_wall * t139),
                t116 * (v_s * (t189 * cos_theta + k_wall * (t106 * t133 + t240))),
                -t19 * t157,
                -t116 * t139,
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
                        * (sin_theta * (t190 + t204) + t99 * (t190 * t152 - t204 * t79))
                        + t87 * (t191 * t80 - t230 * t86)),
                T::from_f64(0.0),
                (-m_2 + k_edge * t215 + k_wall * t141) * (t20 * t20),
                t20
                    * (mu
                        * (thetadot
                            * (k_wall
                                * (cos_theta * (-(t222 * t105) - t231 * t29)
                                    - T::from_f64(2.0) * t108 * (t82 * t148 - t89 * t229))
                                + k_edge * (-(t59 * t192 * t155) - t40 * t100 * t131))
                            + k_edge
                                * (t135 * (t62 + T::from_f64(1.5) * t168 * t40)
                                    - t153 * (t48 + T::from_f64(1.5) * t163 * t59))
                            + k_wall
                                * (cos_theta * (t134 - t138)
                                    + T::from_f64(1.5) * (t196 * t82 - t234 * t89) * t119))
                        + k_wall
                            * (t10
                                * (T::from_f64(2.0) * t63 * t49
                                    + T::from_f64(2.0) * t65 * t64)
                                - t50 * (T::from_f64(1.5) * t208 * t119 - t242)
                                + t43 * (T::from_f64(1.5) * t243 * t119 - t250))
                        + k_edge * (t216 * t37 - t198 * t56)),
                t117
                    * (sin_theta
                        * (mu
                            * (t52
                                * (t49 * (t71 * t104 - t77 * (t71 - slip_wall_right))
                                    + T::from_f64(1.5) * t82 * t195)
                                + t45
                                    * (T::from_f64(1.5) * t89 * t233
                                        - t64 * (t30 * t69 - t32 * (slip_wall_left + t30))))
                            - T::from_f64(1.5) * (t208 * t50 + t243 * t43))
                        + cos_theta
                            * (t49 * (-step_delta_wall_right + t61 + t83 * t95 * t128)
                                + t64 * (step_delta_wall_left - t46 + t90 * t95 * t111))
                        - t50 * t248 - t43 * t251),
                t20
                    * (k_edge
                        * (-(t10
                            * (t48 * (step_delta_edge_left - t149 + t206 * t95 * t144)
                                - t62
                                    * (-step_delta_edge_right + t122 + t107 * t95 * t145)))
                            + t68
                                * (T::from_f64(1.5)
                                    * (t56 * t124 + t207 * step_delta_edge_left)
                                    * sqrt_pen_edge_left
                                    - T::from_f64(1.5) * (t37 * t158 + t172 * t81)
                                        * sqrt_pen_edge_right) - t56 * t166 + t37 * t171)
                        + k_wall
                            * (sqrt_pen_wall_left
                                * (t43 * (t228 + t113 * step_delta_wall_left)
                                    + T::from_f64(0.75) * t91 * step_delta_wall_left)
                                - sqrt_pen_wall_right
                                    * (T::from_f64(0.75) * t136 * step_delta_wall_right
                                        - t50 * (t126 + t173 * step_delta_wall_right)))),
                -t117
                    * (mu
                        * (thetadot * (t239 * t29 - t202 * t28)
                            - t52 * (T::from_f64(1.5) * t195 * t28 * t21 - t49 * t94)
                                * t80
                            + t45 * (t64 * t147 + T::from_f64(1.5) * t233 * t29 * t22)
                                * t86) + t50 * (T::from_f64(1.5) * t208 * t21 + t249)
                        + t73 * t63 * t49 - t43 * (T::from_f64(1.5) * t243 * t22 + t252)
                        + t74 * t65 * t64),
                -(k_edge
                    * (mu * (t205 * t177 - t40 * t179 * t79) + t56 * t219
                        + t73 * t151 * t48 - t37 * t220 - t74 * t123 * t62)) * t20,
                -t20
                    * (k_edge * (t205 * t155 - t132 * t40)
                        - k_wall * (t82 * t133 - t89 * t137)),
                v_s
                    * (k_edge * (t186 * t59 - t188 * t40)
                        - k_wall * (t106 * t222 - t240 * t29)) * mu * t20,
                -t20 * t215,
                -t20 * t141,
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
                    * (k_edge * (t190 * (t56 + t206) + t204 * (t37 + t107))
                        + k_wall * (-(t191 * (t83 - t50)) - t230 * (t90 - t43))),
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
                            * (cos_theta * (t223 + t245)
                                - T::from_f64(2.0) * t108 * (t209 + t253))
                            + k_edge
                                * (t155
                                    * (T::from_f64(2.0) * t152
                                        - t146 * (slip_edge_left * slip_edge_left * slip_edge_left))
                                    - t131
                                        * (T::from_f64(2.0) * t79
                                            - t92
                                                * (slip_edge_right * slip_edge_right * slip_edge_right))))
                        + T::from_f64(1.5) * t211 * k_edge
                        + T::from_f64(1.5) * t237 * t247)
                    + k_wall
                        * (T::from_f64(2.0) * t110 * (t129 + t224)
                            - delta_rate_wall_right * t242
                            + neg_delta_rate_wall_left * t250)
                    + k_edge
                        * (t168 * neg_delta_rate_edge_right * t167
                            - t163 * delta_rate_edge_left * t159),
                k_wall
                    * (mu
                        * (sin_theta
                            * (thetadot * (t223 - t245)
                                + T::from_f64(1.5) * (t212 - t246)) - t96 * (t253 - t209))
                        + cos_theta * (t224 - t129) * thetadot
                        + delta_rate_wall_right * t248
                        + neg_delta_rate_wall_left * t251),
                -(k_edge
                    * (t110
                        * (-(hc_alpha * (t210 * t164 + t84 * t169) * mu) + t150 + t130)
                        + T::from_f64(1.5) * (t68 * t211) * mu
                        - delta_rate_edge_left * t166
                        + neg_delta_rate_edge_right * t171))
                    - k_wall
                        * (T::from_f64(0.75) * t247 * mu
                            + t195 * delta_rate_wall_right * t173
                            + t233 * neg_delta_rate_wall_left * t113),
                -k_wall
                    * (mu
                        * (thetadot
                            * (t49
                                * (t109 * t200
                                    - t77
                                        * (t201 * t78 + T::from_f64(2.0) * t200 * slip_wall_right))
                                + t64
                                    * (t70 * t238
                                        - t32
                                            * (t114 * t33 + T::from_f64(2.0) * t238 * slip_wall_left)))
                            - T::from_f64(1.5) * (t203 * t85 + t246 * t22))
                        + thetadot * (t129 * t73 + t224 * t74)
                        - delta_rate_wall_right * t249
                        + neg_delta_rate_wall_left * t252),
                -k_edge
                    * (-(mu * (t210 * t177 + t84 * t179))
                        + thetadot * (t150 * t73 + t130 * t74)
                        - delta_rate_edge_left * t217
                        + neg_delta_rate_edge_right * t218),
                k_edge * t213 + k_wall * t140,
                -(v_s
                    * (k_edge * (t185 * t60 + t187 * t41)
                        + k_wall * (t104 * t133 + t69 * t137)) * mu),
                mu * t213 - t150 * delta_rate_edge_left
                    + t130 * neg_delta_rate_edge_right,
                mu * t140 - t129 * delta_rate_wall_right
                    + t224 * neg_delta_rate_wall_left,
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
                    * (k_edge * (t190 * t210 - t84 * t204)
                        - k_wall * (t230 * t88 - t191 * t85))
                    + k_edge
                        * (t164 * (delta_rate_edge_left * delta_rate_edge_left)
                            + t169
                                * (neg_delta_rate_edge_right * neg_delta_rate_edge_right))
                    + k_wall
                        * (t148 * (delta_rate_wall_right * delta_rate_wall_right)
                            + t229
                                * (neg_delta_rate_wall_left * neg_delta_rate_wall_left)),
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
        let t83 = t82 * (slip_wall_left * slip_wall_left * slip_wall_left);
        let t84 = slip_edge_right * t54;
        let t85 = t54 * t56;
        let t86 = slip_wall_left * t41;
        let t87 = t41 * t42;
        let t88 = t51.step();
        let t89 = T::from_f64(1.0) / (t53 * t53 * t53);
        let t90 = thetadot * hc_alpha;
        let t91 = t90 * cos_theta;
        let t92 = t14 * t90;
        let t93 = t60.step();
        let t94 = T::from_f64(1.5) - T::from_f64(1.5) * t61;
        let sqrt_pen_edge_left = pen_edge_left.sqrt();
        let t95 = step_delta_edge_left * step_delta_edge_left;
        let sqrt_pen_wall_right = pen_wall_right.sqrt();
        let t96 = step_delta_wall_right * step_delta_wall_right;
        let t97 = -T::from_f64(1.5) * t96;
        let t98 = sqrt_pen_edge_left * t95;
        let t99 = t67.step();
        let t100 = t99 * t65;
        let sqrt_pen_edge_right = pen_edge_right.sqrt();
        let t101 = step_delta_edge_right * step_delta_edge_right;
        let t102 = T::from_f64(1.5) - T::from_f64(1.5) * t68;
        let t103 = sqrt_pen_wall_right * (step_delta_wall_right * t102 + t97);
        let t104 = step_delta_edge_left * sqrt_pen_edge_left;
        let t105 = step_delta_edge_right * sqrt_pen_edge_right;
        let t106 = sqrt_pen_edge_right * t101;
        let t107 = step_delta_wall_right * sqrt_pen_wall_right;
        let t108 = hc_alpha * t99;
        let sqrt_pen_wall_left = pen_wall_left.sqrt();
        let t109 = step_delta_wall_left * step_delta_wall_left;
        let t110 = -T::from_f64(1.5) * t109;
        let t111 = sqrt_pen_wall_left * (step_delta_wall_left * t94 + t110);
        let t112 = t81 * t93;
        let t113 = step_delta_wall_left * sqrt_pen_wall_left;
        let t114 = r - (t35 + cos_theta * t25);
        let t115 = t10 - t9 * t9;
        let t116 = t35 - t25 * t115;
        let slip_wall_right = zdot - thetadot * t33;
        let t117 = v_s.hypot(slip_wall_right);
        let t118 = T::from_f64(1.0) / t117;
        let t119 = slip_wall_right * slip_wall_right;
        let t120 = T::from_f64(1.0) / (t117 * t117 * t117);
        let t121 = t16 * t115;
        let t122 = t121 + t17;
        let t123 = T::from_f64(2.0) * t14 * xdot;
        let t124 = t56 * t89;
        let t125 = t52 * (t54 - t124);
        let t126 = t90 * mu;
        let t127 = t84 * t55;
        let t128 = t125 * t55;
        let t129 = mu * t39;
        let t130 = t89 * (slip_edge_right * slip_edge_right * slip_edge_right);
        let t131 = t61 * (t41 - t42 * t82);
        let t132 = t86 * t61;
        let t133 = t87 * t61;
        let t134 = t50 * t50;
        let t135 = cos_theta * t114 + t47;
        let t136 = rho_p * (sin_theta - T::from_f64(2.0) * t14);
        let t137 = hc_alpha * t88;
        let t138 = t137 * t50;
        let t139 = t52 * t55;
        let t140 = k_edge * t27;
        let t141 = t123 + t32 - thetadot * t116;
        let t142 = sin_theta * t114 + t44;
        let t143 = sin_theta * (thetadot * t135 + t49)
            - cos_theta * (t46 + thetadot * t142);
        let t144 = t137 * t141;
        let t145 = t22 - cos_theta * (t136 + t20);
        let t146 = t22 - cos_theta * (t136 + t38);
        let t147 = t55 * t143;
        let t148 = slip_wall_right * t118;
        let t149 = mu * t33;
        let t150 = t120 * (slip_wall_right * slip_wall_right * slip_wall_right);
        let t151 = t59 * t59;
        let t152 = k_wall * hc_alpha;
        let t153 = hc_alpha * t93;
        let t154 = t153 * t122;
        let t155 = t17 - t121;
        let t156 = t154 * t86 - t131 * t146;
        let t157 = t153 * t59;
        let t158 = t86 * t157;
        let t159 = t61 * t146;
        let t160 = t39 * t61;
        let t161 = t78 * t57;
        let t162 = t78 * t88;
        let t163 = t105 * t52;
        let t164 = r + cos_theta * t63 + t35;
        let t165 = t35 - t63 * t115;
        let t166 = t66 * t66;
        let t167 = sin_theta * t69;
        let t168 = t12 - t167;
        let t169 = zdot + thetadot * t168;
        let slip_edge_left = sin_theta * t72 + cos_theta * t169;
        let t170 = v_s.hypot(slip_edge_left);
        let t171 = T::from_f64(1.0) / t170;
        let t172 = sin_theta * t71 + cos_theta * t168;
        let t173 = slip_edge_left * slip_edge_left;
        let t174 = t64 * t76;
        let t175 = slip_edge_left * t171;
        let t176 = t175 * t64 * t75 + t84 * t78 * t52;
        let t177 = T::from_f64(1.0) / (t170 * t170 * t170);
        let t178 = t125 * t78;
        let t179 = t173 * t177;
        let t180 = t78 * (-step_delta_edge_right + t57 + t126 * t127 * t88);
        let t181 = t177 * (slip_edge_left * slip_edge_left * slip_edge_left);
        let t182 = t128 * t78;
        let t183 = sqrt_pen_edge_right
            * (t50 * t101 + t127 * mu * t52 * step_delta_edge_right);
        let t184 = t52 * (T::from_f64(2.0) * t84 - t130) * t78;
        let t185 = t74.step();
        let t186 = t73 * t73;
        let t187 = t104 * (T::from_f64(1.5) - T::from_f64(1.5) * t75);
        let t188 = t64 * t185;
        let t189 = T::from_f64(2.0) * t92 * t188;
        let t190 = t187 * t26 + t189;
        let t191 = t105 * (T::from_f64(1.5) - T::from_f64(1.5) * t52);
        let t192 = T::from_f64(2.0) * t92 * t162;
        let t193 = t191 * t26 + t192;
        let t194 = t104 * t75;
        let t195 = mu * (t194 * t175 - t163 * t84);
        let t196 = t98 + t106;
        let t197 = t26 * t196;
        let t198 = sin_theta * t164 + t70;
        let t199 = t75 * (t171 - t179);
        let t200 = t199 * t64;
        let t201 = t200 + t178;
        let t202 = hc_alpha * (t188 + t162);
        let t203 = hc_alpha * t185;
        let t204 = t203 * t73;
        let t205 = hc_alpha * (t188 * t175 - t162 * t84);
        let t206 = t205 * mu;
        let t207 = t206 * thetadot;
        let t208 = hc_alpha * (t188 * t73 + t162 * t50);
        let t209 = t208 * sin_theta * k_edge;
        let t210 = t175 * t172;
        let t211 = sqrt_pen_edge_left
            * (t73 * t95 + t210 * mu * t75 * step_delta_edge_left);
        let t212 = t194 * t73;
        let t213 = t163 * t50;
        let t214 = hc_alpha * (t210 * t188 + t127 * t162);
        let t215 = t208 * t26;
        let t216 = t200 * t172;
        let t217 = t171 * t173;
        let t218 = t217 * t188 - t85 * t162;
        let t219 = t217 * t194 - t85 * t163;
        let t220 = hc_alpha
            * (mu * t218 + t188 * delta_rate_edge_left
                + t162 * neg_delta_rate_edge_right) - t174 + t161;
        let t221 = t75 * (T::from_f64(2.0) * t175 - t181) * t64;
        let t222 = t75 * t172;
        let t223 = t91 * t188 - t187 * sin_theta;
        let t224 = t91 * t162 - t191 * sin_theta;
        let t225 = t167 - cos_theta * t164;
        let t226 = cos_theta * (thetadot * t198 - t72)
            + sin_theta * (thetadot * t225 + t169);
        let t227 = t162 * t141;
        let t228 = t227 * hc_alpha - t191 * t50;
        let t229 = sin_theta * (cos_theta * (-t200 - t178) * mu + t202 * t26);
        let t230 = t64 * (t199 * t172 + t204 * t175) - t78 * (t128 + t138 * t84);
        let t231 = t64 * (step_delta_edge_left - t76 + t126 * t210 * t185);
        let t232 = t172 * t226;
        let t233 = thetadot * (t174 - t161);
        let t234 = t64 * t226;
        let t235 = t78 * t143;
        let t236 = t148 * t68;
        let t237 = t68 * t118 * t119;
        let t238 = t68 * (t118 - t119 * t120);
        let t239 = t238 * t65;
        let t240 = t112 * t122;
        let t241 = t108 * t66;
        let t242 = t148 * t241;
        let t243 = t107 * t66;
        let t244 = t113 * t59;
        let t245 = t244 * t94 + t240 * t90;
        let t246 = t39 * t81;
        let t247 = t68 * t33;
        let t248 = t123 + t32 - thetadot * t165;
        let t249 = t188 * t248;
        let t250 = t249 * hc_alpha - t187 * t73;
        let t251 = t203 * t248;
        let t252 = t64 * (t251 * t175 - t199 * t226) - t78 * (t125 * t143 + t144 * t84)
            + T::from_f64(1.5) * (t212 * t175 - t213 * t84);
        let t253 = T::from_f64(1.5) * (t98 * t73 + t106 * t50) + t250 + t228;
        let t254 = t100 * t155;
        let t255 = t108 * t155;
        let t256 = t65 * (t255 * t148 - t238 * t145);
        let t257 = t243 * t102 + t254 * t90;
        let t258 = t68 * t145;
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
                        * (t26 * (T::from_f64(1.5) * t195 * sin_theta + t190 + t193)
                            - T::from_f64(1.5) * t196 * t30
                            - T::from_f64(2.0) * t207 * (t14 * sin_theta))
                        + k_wall * (t103 + t111)),
                t140
                    * (sin_theta * (T::from_f64(1.5) * t197 - t207 * cos_theta)
                        + t26 * (t223 + t224) - T::from_f64(1.5) * t195 * t29),
                t27
                    * (k_edge
                        * (-(mu * (sin_theta * t252 + cos_theta * t176)) + t26 * t253
                            + t14 * (-(T::from_f64(2.0) * t79) - T::from_f64(2.0) * t80))
                        + k_wall * (t103 * t66 + t111 * t59 + t90 * (t254 + t240)) + t3
                        + t4),
                -t27
                    * (k_edge * (mu * (t29 * t201 - sin_theta * t26 * t205) + t202 * t30)
                        + t152 * (t100 + t112)),
                t140 * (t229 - t206 * t29),
                -t27
                    * (k_edge * (sin_theta * t230 * mu - t215)
                        + t152 * (t100 * t66 + t112 * t59)),
                T::from_f64(0.0),
                T::from_f64(0.0),
                -t27
                    * (k_edge
                        * (sin_theta * (-(T::from_f64(1.5) * t197) + t190 + t193)
                            - cos_theta
                                * (t84 * (t192 - T::from_f64(1.5) * t163 * t26)
                                    - t175 * (t189 - T::from_f64(1.5) * t194 * t26)) * mu)
                        + T::from_f64(1.5) * (k_wall * (t236 * t107 - t132 * t113))
                            * mu),
                -t140
                    * (sin_theta * (T::from_f64(1.5) * t195 * cos_theta + t223 + t224)
                        + T::from_f64(1.5) * t196 * t29 + t207 * t31),
                -t27
                    * (-(mu
                        * (k_edge * (sin_theta * t176 - cos_theta * t252)
                            - k_wall
                                * (thetadot * (t81 * t156 - t256)
                                    + T::from_f64(1.5) * (t236 * t243 - t132 * t244))))
                        + k_edge * (cos_theta * (t79 + t80) + sin_theta * t253) + t0
                        + t1),
                t27
                    * (k_edge * (t229 + cos_theta * t26 * t206)
                        - t152 * (t100 * t148 - t112 * t86) * mu),
                -t27
                    * (mu
                        * (k_edge * (t31 * t201 + sin_theta * cos_theta * t205)
                            + k_wall * (t239 + t131 * t81)) + t202 * t29 * k_edge),
                t27
                    * (mu
                        * (k_wall
                            * (t81 * (t158 - t131 * t39) - t65 * (t242 - t238 * t33))
                            - cos_theta * t230 * k_edge) - t209),
                T::from_f64(0.0),
                T::from_f64(0.0),
                t28
                    * (k_edge
                        * (t14 * (-(T::from_f64(2.0) * t231) - T::from_f64(2.0) * t180)
                            + t26 * (T::from_f64(1.5) * t211 + T::from_f64(1.5) * t183)
                            - t73 * t190 - t50 * t193)
                        + k_wall
                            * (sqrt_pen_wall_right
                                * (t66 * (t97 + t102 * step_delta_wall_right)
                                    + T::from_f64(1.5) * t149 * t236 * step_delta_wall_right)
                                + sqrt_pen_wall_left
                                    * (t59 * (t110 + t94 * step_delta_wall_left)
                                        + T::from_f64(1.5) * t129 * t132 * step_delta_wall_left))),
                -(k_edge
                    * (cos_theta * (t231 + t180)
                        - sin_theta
                            * (-(T::from_f64(1.5) * t211) - T::from_f64(1.5) * t183)
                        + t73 * t223 + t50 * t224)) * t28,
                -t28
                    * (mu
                        * (k_edge
                            * (t64
                                * (t251 * t210
                                    - t75
                                        * (t171
                                            * (t232
                                                + slip_edge_left
                                                    * (sin_theta * (t225 + t168) - cos_theta * (t71 - t198)))
                                            - t179 * t232))
                                + t78
                                    * (t52
                                        * (t54
                                            * (t147
                                                + slip_edge_right
                                                    * (sin_theta * (t48 - t135) - cos_theta * (t45 - t142)))
                                            - t124 * t147) + t144 * t127)
                                + T::from_f64(1.5) * (t212 * t210 + t213 * t127))
                            + k_wall
                                * (thetadot * (t256 * t33 + t246 * t156)
                                    - t236 * (T::from_f64(1.5) * t243 * t33 - t65 * t145)
                                    - t132 * (t81 * t146 + T::from_f64(1.5) * t244 * t39)))
                        + k_edge
                            * (-(t79 * t165) - t80 * t116
                                + T::from_f64(1.5) * (t98 * t186 + t106 * t134) + t73 * t250
                                + t50 * t228)
                        + k_wall
                            * (-((step_delta_wall_right - t77) * t155 * t65)
                                + (step_delta_wall_left - t62) * t122 * t81
                                + T::from_f64(1.5)
                                    * (sqrt_pen_wall_right * t96 * t166
                                        + sqrt_pen_wall_left * t109 * t151) - t66 * t257
                                - t59 * t245)),
                t28
                    * (k_edge * (mu * (sin_theta * (t182 - t216) + t214 * t26) + t215)
                        + t152
                            * (t100 * (t149 * t148 - t66) + t112 * (t129 * t86 - t59))),
                -t28
                    * (mu
                        * (k_edge * (cos_theta * (t216 - t182) + t214 * sin_theta)
                            + k_wall * (t246 * t131 - t239 * t33)) + t209),
                -t28
                    * (mu
                        * (k_edge
                            * (t64 * (t199 * (t172 * t172) + t204 * t210)
                                + t78 * (t125 * (t55 * t55) + t138 * t127))
                            - k_wall
                                * (t65 * (t242 * t33 - t238 * (t33 * t33))
                                    + t81 * (t158 * t39 - t131 * (t39 * t39))))
                        + hc_alpha
                            * (k_edge * (t188 * t186 + t162 * t134)
                                + k_wall * (t100 * t166 + t112 * t151))),
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
                        * (T::from_f64(2.0) * (t14 * t218) * t90
                            - T::from_f64(1.5) * t219 * t26)
                        - T::from_f64(2.0) * t233 * t14 + delta_rate_edge_left * t190
                        + neg_delta_rate_edge_right * t193)
                    - k_wall
                        * (-(T::from_f64(1.5) * (t237 * t107 - t133 * t113) * mu)
                            + t107 * t102 * delta_rate_wall_right
                            + t113 * t94 * neg_delta_rate_wall_left),
                k_edge
                    * (mu
                        * (T::from_f64(1.5) * t219 * sin_theta + cos_theta * t218 * t90)
                        - t233 * cos_theta + delta_rate_edge_left * t223
                        + neg_delta_rate_edge_right * t224),
                mu
                    * (k_edge
                        * (t75
                            * (t234 * t181
                                - t171
                                    * (T::from_f64(2.0) * t234 * slip_edge_left
                                        - T::from_f64(1.5) * t104 * t73 * t173))
                            - t52
                                * (t54
                                    * (T::from_f64(1.5) * t105 * t50 * t56
                                        + T::from_f64(2.0) * t235 * slip_edge_right) - t235 * t130)
                            + hc_alpha * (t249 * t217 - t227 * t85))
                        + k_wall
                            * (thetadot
                                * (t81
                                    * (t41
                                        * (t154 * t42 - T::from_f64(2.0) * t159 * slip_wall_left)
                                        + t159 * t83)
                                    - t65
                                        * (t118
                                            * (t255 * t119 - T::from_f64(2.0) * t258 * slip_wall_right)
                                            + t258 * t150))
                                + T::from_f64(1.5) * (t237 * t243 - t133 * t244)))
                    + k_edge
                        * (-(t174 * t248) + delta_rate_edge_left * t250 + t161 * t141
                            + neg_delta_rate_edge_right * t228)
                    - k_wall
                        * (thetadot * (t81 * t62 * t122 - t65 * t77 * t155)
                            + delta_rate_wall_right * t257
                            + neg_delta_rate_wall_left * t245),
                -(k_edge * (t26 * t220 + sin_theta * (-t221 - t184) * mu))
                    - k_wall
                        * (t65
                            * (-(t108 * (mu * t118 * t119 + delta_rate_wall_right)) - t68
                                + T::from_f64(1.0))
                            + t81
                                * (t153 * (t87 * mu - neg_delta_rate_wall_left)
                                    - T::from_f64(1.0) + t61)),
                k_edge * (sin_theta * t220 + cos_theta * (t221 + t184) * mu)
                    + k_wall
                        * (t68 * (T::from_f64(2.0) * t148 - t150) * t65
                            + t61 * (T::from_f64(2.0) * t86 - t83) * t81) * mu,
                -(mu
                    * (k_edge
                        * (t64
                            * (t222 * t181
                                - t171
                                    * (t204 * t173 + T::from_f64(2.0) * t222 * slip_edge_left))
                            - t78
                                * (t139 * t130
                                    - t54
                                        * (t138 * t56 + T::from_f64(2.0) * t139 * slip_edge_right)))
                        + k_wall
                            * (t81
                                * (t41
                                    * (t157 * t42 - T::from_f64(2.0) * t160 * slip_wall_left)
                                    + t160 * t83)
                                - t65
                                    * (t118
                                        * (t241 * t119 - T::from_f64(2.0) * t247 * slip_wall_right)
                                        + t247 * t150))))
                    + k_edge
                        * (t64 * (t203 * delta_rate_edge_left - t76) * t73
                            + t78 * (t57 + t137 * neg_delta_rate_edge_right) * t50)
                    + k_wall
                        * (t65 * (t108 * delta_rate_wall_right - t77) * t66
                            + t81 * (t62 + t153 * neg_delta_rate_wall_left) * t59),
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
}
