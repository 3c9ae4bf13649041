// @generated readable copy of `pegdyn::generated::jamming_design` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generator snapshot::

/// Quasi-static design quantities of a peg in two-point contact (Whitney, *Quasi-static assembly of compliantly supported rigid parts*): the corners of the jamming parallelogram, Whitney's and exact, and the wedging angle, as functions of p = (r m, c, mu, l m) for their parameter Jacobians.
pub mod jamming_design {
    use nalgebra::{Matrix2x4, SMatrix, SVector, Vector2, Vector4};
    use pegdyn::scalar::Real;
    /// Symbol names of the components of `p`, in order.
    pub const P_NAMES: [&str; 4] = ["r", "c", "mu", "l"];
    /// The parameters of `jamming_design`: the input `p` of its functions as a struct, one field per component in vector order (`From`/`Into` convert both ways).
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct Params<T> {
        /// Peg radius r, m.
        pub r: T,
        /// Clearance ratio c = (D − d)/D, dimensionless.
        pub c: T,
        /// Coulomb friction coefficient μ, dimensionless.
        pub mu: T,
        /// Insertion depth l along the peg's axis from the tip face to the edge contact, m.
        pub l: T,
    }
    impl<T> Params<T> {
        /// The field names in vector order: the symbol names of `p` ([`P_NAMES`]).
        pub const NAMES: [&'static str; 4] = P_NAMES;
    }
    impl<T: Real> From<Params<T>> for SVector<T, 4> {
        /// The `p` vector of these values, in field order.
        fn from(v: Params<T>) -> SVector<T, 4> {
            SVector::from([v.r, v.c, v.mu, v.l])
        }
    }
    impl<T: Real> From<&SVector<T, 4>> for Params<T> {
        /// The fields of a `p` vector, in field order.
        fn from(v: &SVector<T, 4>) -> Params<T> {
            Params {
                r: v[0],
                c: v[1],
                mu: v[2],
                l: v[3],
            }
        }
    }
    impl<T: Real> From<SVector<T, 4>> for Params<T> {
        /// The fields of a `p` vector, in field order.
        fn from(v: SVector<T, 4>) -> Params<T> {
            Params::from(&v)
        }
    }
    /// The outputs of [`whitney_diagram`].
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct WhitneyDiagramOut<T: Real> {
        /// Edge-only corner P₁ = (F_x/F_z, M/(r F_z)) of the reference two-point line.
        pub edge_corner: SVector<T, 2>,
        /// Corner Q = (F_x/F_z, M/(r F_z)) where the mirrored two-point line meets the edge cone limit through P₁.
        pub mirrored_corner: SVector<T, 2>,
        /// Slope of the reference two-point line M/(r F_z) against F_x/F_z.
        pub slope: T,
        /// Intercept of the reference two-point line at F_x/F_z = 0.
        pub intercept: T,
    }
    /// Whitney's small-angle jamming parallelogram: corners P₁ = (1/μ, 1 + 2λ) and Q = (1/μ, 1) (the others are −P₁, −Q), slope μ(1 + λ) and intercept λ of the two-point line, λ = l/(2rμ).
    ///
    /// # Inputs
    /// - `p` = (`r`, `c`, `mu`, `l`)
    ///
    /// # Outputs
    /// The fields of [`WhitneyDiagramOut`]:
    /// - `edge_corner`: vector of 2
    /// - `mirrored_corner`: vector of 2
    /// - `slope`: scalar
    /// - `intercept`: scalar
    ///
    /// # Cost
    /// 2 add/sub, 3 mul, 2 div, 0 sqrt, 0 transcendental, 0 branches; 3 `let`s.
    #[inline]
    pub fn whitney_diagram<T: Real>(p: &SVector<T, 4>) -> WhitneyDiagramOut<T> {
        let r = p[0];
        let mu = p[2];
        let l = p[3];
        let t0 = T::from_f64(1.0) / mu;
        let t1 = l / r * t0;
        let t2 = T::from_f64(0.5) * t1;
        WhitneyDiagramOut {
            edge_corner: Vector2::new(t0, T::from_f64(1.0) + t1),
            mirrored_corner: Vector2::new(t0, T::from_f64(1.0)),
            slope: mu * (T::from_f64(1.0) + t2),
            intercept: t2,
        }
    }
    /// The outputs of [`exact_diagram`].
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct ExactDiagramOut<T: Real> {
        /// Exact two-point tilt θ, the small root of l sin θ + d cos θ = D, rad.
        pub tilt: T,
        /// Edge-only corner P₁ = (F_x/F_z, M/(r F_z)) of the reference two-point line.
        pub edge_corner: SVector<T, 2>,
        /// Corner Q = (F_x/F_z, M/(r F_z)) where the mirrored two-point line meets the edge cone limit through P₁.
        pub mirrored_corner: SVector<T, 2>,
        /// Slope of the reference two-point line M/(r F_z) against F_x/F_z.
        pub slope: T,
        /// Intercept of the reference two-point line at F_x/F_z = 0.
        pub intercept: T,
    }
    /// The exact finite-angle jamming parallelogram at the exact two-point tilt θ (defined for l ≥ √(D² − d²)): corners P₁ = (k1/k2, (l + μr)/(r k2)) and Q = (P₁ₓ, −P₁ᵧ + 2 s P₁ₓ) (the others are −P₁, −Q), slope s and intercept of the two-point line through P₂ = (−1/μ, −k2/μ) and P₁.
    ///
    /// # Inputs
    /// - `p` = (`r`, `c`, `mu`, `l`)
    ///
    /// # Outputs
    /// The fields of [`ExactDiagramOut`]:
    /// - `tilt`: scalar
    /// - `edge_corner`: vector of 2
    /// - `mirrored_corner`: vector of 2
    /// - `slope`: scalar
    /// - `intercept`: scalar
    ///
    /// # Cost
    /// 11 add/sub, 12 mul, 6 div, 1 sqrt, 4 transcendental, 0 branches; 17 `let`s.
    #[inline]
    pub fn exact_diagram<T: Real>(p: &SVector<T, 4>) -> ExactDiagramOut<T> {
        let r = p[0];
        let c = p[1];
        let mu = p[2];
        let l = p[3];
        let t0 = T::from_f64(2.0) * r;
        let t1 = l.hypot(t0);
        let t2 = l.atan2(t0);
        let t3 = T::from_f64(2.0) * r / (T::from_f64(1.0) - c);
        let t4 = (-(t3 - t1) * (t3 + t1)).sqrt();
        let t5 = t4.atan2(t3);
        let t6 = t2 - t5;
        let (t7, t8) = t6.sin_cos();
        let t9 = mu * t7 - t8;
        let t10 = t7 + mu * t8;
        let t11 = T::from_f64(1.0) / t10;
        let t12 = -t9 * t11;
        let t13 = (l + r * mu) / r;
        let t14 = t13 * t11;
        let t15 = (t14 + t10 / mu) / (T::from_f64(1.0) / mu + t12);
        let t16 = t15 * t9;
        ExactDiagramOut {
            tilt: t6,
            edge_corner: Vector2::new(t12, t14),
            mirrored_corner: Vector2::new(t12, -(t11 * (t13 + T::from_f64(2.0) * t16))),
            slope: t15,
            intercept: t11 * (t13 + t16),
        }
    }
    /// The outputs of [`wedging`].
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct WedgingOut<T: Real> {
        /// Critical wedging tilt θ_c, rad.
        pub exact: T,
        /// Two-term small-clearance series of θ_c, rad.
        pub series: T,
        /// Whitney's small-clearance wedging angle c/μ, rad.
        pub whitney: T,
    }
    /// The critical wedging tilt θ_c = atan μ − acos(D/(d √(1 + μ²))) (rad, defined when D ≤ d √(1 + μ²)), its series c/μ + (1 + 2μ²) c²/(2μ³) and Whitney's c/μ.
    ///
    /// # Inputs
    /// - `p` = (`r`, `c`, `mu`, `l`)
    ///
    /// # Outputs
    /// The fields of [`WedgingOut`]:
    /// - `exact`: scalar
    /// - `series`: scalar
    /// - `whitney`: scalar
    ///
    /// # Cost
    /// 6 add/sub, 9 mul, 3 div, 1 sqrt, 3 transcendental, 0 branches; 6 `let`s.
    #[inline]
    pub fn wedging<T: Real>(p: &SVector<T, 4>) -> WedgingOut<T> {
        let c = p[1];
        let mu = p[2];
        let t0 = mu.hypot(T::from_f64(1.0));
        let atan_mu = mu.atan();
        let t1 = c / mu;
        let t2 = T::from_f64(1.0) / (t0 * (T::from_f64(1.0) - c));
        let t3 = ((T::from_f64(1.0) - t2) * (T::from_f64(1.0) + t2)).sqrt();
        let t4 = t3.atan2(t2);
        WedgingOut {
            exact: atan_mu - t4,
            series: t1
                + T::from_f64(0.5) * (T::from_f64(1.0) + T::from_f64(2.0) * (mu * mu))
                    * (c * c) / (mu * mu * mu),
            whitney: t1,
        }
    }
    /// The outputs of [`whitney_diagram_p`].
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct WhitneyDiagramPOut<T: Real> {
        /// `dedge_corner_dp`: 2×4 matrix.
        pub dedge_corner_dp: SMatrix<T, 2, 4>,
        /// `dmirrored_corner_dp`: 2×4 matrix.
        pub dmirrored_corner_dp: SMatrix<T, 2, 4>,
        /// `dslope_dp`: vector of 4.
        pub dslope_dp: SVector<T, 4>,
        /// `dintercept_dp`: vector of 4.
        pub dintercept_dp: SVector<T, 4>,
    }
    /// Exact parameter Jacobian of [`whitney_diagram`]: `dedge_corner_dp` with entry (i, k) = ∂edge_cornerᵢ/∂p_k; `dmirrored_corner_dp` with entry (i, k) = ∂mirrored_cornerᵢ/∂p_k; `dslope_dp` with entry (i, k) = ∂slopeᵢ/∂p_k; `dintercept_dp` with entry (i, k) = ∂interceptᵢ/∂p_k (columns in `P_NAMES` order).
    ///
    /// # Inputs
    /// - `p` = (`r`, `c`, `mu`, `l`)
    ///
    /// # Outputs
    /// The fields of [`WhitneyDiagramPOut`]:
    /// - `dedge_corner_dp`: 2×4 matrix
    /// - `dmirrored_corner_dp`: 2×4 matrix
    /// - `dslope_dp`: vector of 4
    /// - `dintercept_dp`: vector of 4
    ///
    /// # Cost
    /// 0 add/sub, 10 mul, 4 div, 0 sqrt, 0 transcendental, 0 branches; 6 `let`s.
    #[inline]
    pub fn whitney_diagram_p<T: Real>(p: &SVector<T, 4>) -> WhitneyDiagramPOut<T> {
        let r = p[0];
        let mu = p[2];
        let l = p[3];
        let t0 = T::from_f64(1.0) / r;
        let t1 = T::from_f64(1.0) / (mu * mu);
        let t2 = t0 / mu;
        let t3 = l * t0 * t1;
        let t4 = l * (t0 * t0);
        let t5 = t4 / mu;
        WhitneyDiagramPOut {
            dedge_corner_dp: Matrix2x4::new(
                T::from_f64(0.0),
                T::from_f64(0.0),
                -t1,
                T::from_f64(0.0),
                -t5,
                T::from_f64(0.0),
                -t3,
                t2,
            ),
            dmirrored_corner_dp: Matrix2x4::new(
                T::from_f64(0.0),
                T::from_f64(0.0),
                -t1,
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(0.0),
            ),
            dslope_dp: Vector4::new(
                -T::from_f64(0.5) * t4,
                T::from_f64(0.0),
                T::from_f64(1.0),
                T::from_f64(0.5) * t0,
            ),
            dintercept_dp: Vector4::new(
                -T::from_f64(0.5) * t5,
                T::from_f64(0.0),
                -T::from_f64(0.5) * t3,
                T::from_f64(0.5) * t2,
            ),
        }
    }
    /// The outputs of [`exact_diagram_p`].
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct ExactDiagramPOut<T: Real> {
        /// `dtilt_dp`: vector of 4.
        pub dtilt_dp: SVector<T, 4>,
        /// `dedge_corner_dp`: 2×4 matrix.
        pub dedge_corner_dp: SMatrix<T, 2, 4>,
        /// `dmirrored_corner_dp`: 2×4 matrix.
        pub dmirrored_corner_dp: SMatrix<T, 2, 4>,
        /// `dslope_dp`: vector of 4.
        pub dslope_dp: SVector<T, 4>,
        /// `dintercept_dp`: vector of 4.
        pub dintercept_dp: SVector<T, 4>,
    }
    /// Exact parameter Jacobian of [`exact_diagram`]: `dtilt_dp` with entry (i, k) = ∂tiltᵢ/∂p_k; `dedge_corner_dp` with entry (i, k) = ∂edge_cornerᵢ/∂p_k; `dmirrored_corner_dp` with entry (i, k) = ∂mirrored_cornerᵢ/∂p_k; `dslope_dp` with entry (i, k) = ∂slopeᵢ/∂p_k; `dintercept_dp` with entry (i, k) = ∂interceptᵢ/∂p_k (columns in `P_NAMES` order).
    ///
    /// # Inputs
    /// - `p` = (`r`, `c`, `mu`, `l`)
    ///
    /// # Outputs
    /// The fields of [`ExactDiagramPOut`]:
    /// - `dtilt_dp`: vector of 4
    /// - `dedge_corner_dp`: 2×4 matrix
    /// - `dmirrored_corner_dp`: 2×4 matrix
    /// - `dslope_dp`: vector of 4
    /// - `dintercept_dp`: vector of 4
    ///
    /// # Cost
    /// 70 add/sub, 147 mul, 11 div, 2 sqrt, 4 transcendental, 0 branches; 73 `let`s.
    #[inline]
    pub fn exact_diagram_p<T: Real>(p: &SVector<T, 4>) -> ExactDiagramPOut<T> {
        let r = p[0];
        let c = p[1];
        let mu = p[2];
        let l = p[3];
        let t0 = T::from_f64(2.0) * r;
        let t1 = T::from_f64(1.0) / r;
        let t2 = T::from_f64(1.0) / mu;
        let t3 = l.hypot(t0);
        let t4 = l.atan2(t0);
        let t5 = l + r * mu;
        let t6 = r * r;
        let t7 = l * l + T::from_f64(4.0) * t6;
        let t8 = T::from_f64(4.0) * r / t3;
        let t9 = T::from_f64(1.0) / (T::from_f64(1.0) - c);
        let t10 = T::from_f64(2.0) * r * t9;
        let t11 = t10 - t3;
        let t12 = t10 + t3;
        let t13 = -t11 * t12;
        let t14 = t13.sqrt();
        let t15 = t14.atan2(t10);
        let t16 = t4 - t15;
        let (t17, t18) = t16.sin_cos();
        let t19 = mu * t17 - t18;
        let t20 = t17 + mu * t18;
        let t21 = T::from_f64(1.0) / t20;
        let t22 = t1 * t5;
        let t23 = t22 * t21 + t2 * t20;
        let t24 = T::from_f64(2.0) * t9;
        let t25 = T::from_f64(1.0) / t13.sqrt();
        let t26 = t17 * t21;
        let t27 = t19 * t19;
        let t28 = mu * t1;
        let t29 = t19 * t21;
        let t30 = T::from_f64(1.0) / (t2 - t29);
        let t31 = t19 * t30;
        let t32 = t31 * t23;
        let t33 = t9 * t25;
        let t34 = t20 * t30;
        let t35 = t22 * t19;
        let t36 = t30 * t27;
        let t37 = t36 * t23;
        let t38 = t2 * t2;
        let t39 = t9 * t9;
        let t40 = T::from_f64(1.0) / (t13 + T::from_f64(4.0) * t6 * t39);
        let t41 = t21 * t21;
        let t42 = t21 * t20 + t27 * t41;
        let t43 = t5 * (t1 * t1);
        let t44 = t19 * t41;
        let t45 = -t44 * t18;
        let t46 = t26 + t45;
        let t47 = t22 * t41;
        let t48 = t30 * t30;
        let t49 = t48 * (t38 + t26 + t45);
        let t50 = t39 * (t33 * t6 * (t12 + t11) + r * t14) * t40;
        let t51 = r * (T::from_f64(2.0) / t7 + t33 * t40 * (t11 - t12) * l / t3);
        let t52 = -T::from_f64(2.0) * (t50 * t42);
        let t53 = t51 * t42;
        let t54 = t22 * t44;
        let t55 = t1 * (t21 + t44 * t51 * t5);
        let t56 = t21 * (t28 - t43);
        let t57 = t48 * t42;
        let t58 = t34 + t57 * t19;
        let t59 = t47 - t2;
        let t60 = t36 * t59;
        let t61 = t18 * t59 - t21 + t20 * t38;
        let t62 = t31 * t61;
        let t63 = t55 - t51 * t2 * t19;
        let t64 = t51 * t23;
        let t65 = t30 * t63 + t64 * t57;
        let t66 = t41 * (t35 + t37);
        let t67 = t23 * (t17 * t30 + t49 * t19);
        let t68 = T::from_f64(2.0) * l / t7
            - t9
                * (r * (t11 * (t8 + t24) - t12 * (t8 - t24)) * t25
                    + T::from_f64(2.0) * t14) * t40;
        let t69 = t68 * t42;
        let t70 = t23 * t68;
        let t71 = t56 - t19 * t59 * t68;
        let t72 = t70 * t57 - t30 * t71;
        ExactDiagramPOut {
            dtilt_dp: Vector4::new(-t68, T::from_f64(2.0) * t50, T::from_f64(0.0), t51),
            dedge_corner_dp: Matrix2x4::new(
                t69,
                t52,
                -t46,
                -t53,
                t56 - t54 * t68,
                T::from_f64(2.0) * t54 * t50,
                t21 - t47 * t18,
                t55,
            ),
            dmirrored_corner_dp: Matrix2x4::new(
                t69,
                t52,
                -t46,
                -t53,
                t41 * (t35 + T::from_f64(2.0) * t37) * t68
                    - t21
                        * (-(T::from_f64(2.0) * t70 * t58) - t43 + t28
                            + T::from_f64(2.0) * t31 * t71),
                -(t50
                    * (t21 * (T::from_f64(4.0) * t58 * t23 + T::from_f64(4.0) * t60)
                        + t41 * (T::from_f64(2.0) * t35 + T::from_f64(4.0) * t37))),
                t21
                    * (-(T::from_f64(2.0) * t67) - T::from_f64(1.0)
                        + T::from_f64(2.0) * t62)
                    + (t22 + T::from_f64(2.0) * t32) * t41 * t18,
                -(t51
                    * (t23
                        * (T::from_f64(2.0) * t58 * t21 + T::from_f64(2.0) * t36 * t41)
                        + t54)) - t21 * (t1 + T::from_f64(2.0) * t31 * t63),
            ),
            dslope_dp: Vector4::new(
                -t72,
                T::from_f64(2.0) * t50 * (t31 * t59 + t57 * t23),
                t49 * t23 - t30 * t61,
                t65,
            ),
            dintercept_dp: Vector4::new(
                -(t21 * (t19 * t72 + t43 - t28 + t70 * t34)) - t66 * t68,
                t50
                    * (t23
                        * (T::from_f64(2.0) * t42 * t30 + T::from_f64(2.0) * t29 * t57)
                        + T::from_f64(2.0) * (t54 + t60 * t21)),
                t21 * (t67 + T::from_f64(1.0) - t62) - (t22 + t32) * t41 * t18,
                t21 * (t19 * t65 + t1 + t64 * t34) + t66 * t51,
            ),
        }
    }
    /// The outputs of [`wedging_p`].
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct WedgingPOut<T: Real> {
        /// `dexact_dp`: vector of 4.
        pub dexact_dp: SVector<T, 4>,
        /// `dseries_dp`: vector of 4.
        pub dseries_dp: SVector<T, 4>,
        /// `dwhitney_dp`: vector of 4.
        pub dwhitney_dp: SVector<T, 4>,
    }
    /// Exact parameter Jacobian of [`wedging`]: `dexact_dp` with entry (i, k) = ∂exactᵢ/∂p_k; `dseries_dp` with entry (i, k) = ∂seriesᵢ/∂p_k; `dwhitney_dp` with entry (i, k) = ∂whitneyᵢ/∂p_k (columns in `P_NAMES` order).
    ///
    /// # Inputs
    /// - `p` = (`r`, `c`, `mu`, `l`)
    ///
    /// # Outputs
    /// The fields of [`WedgingPOut`]:
    /// - `dexact_dp`: vector of 4
    /// - `dseries_dp`: vector of 4
    /// - `dwhitney_dp`: vector of 4
    ///
    /// # Cost
    /// 12 add/sub, 27 mul, 13 div, 2 sqrt, 1 transcendental, 0 branches; 15 `let`s.
    #[inline]
    pub fn wedging_p<T: Real>(p: &SVector<T, 4>) -> WedgingPOut<T> {
        let c = p[1];
        let mu = p[2];
        let t0 = mu.hypot(T::from_f64(1.0));
        let t1 = mu * mu;
        let t2 = T::from_f64(1.0) + T::from_f64(2.0) * t1;
        let t3 = c * c;
        let t4 = T::from_f64(1.0) / (mu * mu);
        let t5 = T::from_f64(1.0) - c;
        let t6 = T::from_f64(1.0) / (t0 * t5);
        let t7 = T::from_f64(1.0) - t6;
        let t8 = T::from_f64(1.0) + t6;
        let t9 = t7 * t8;
        let t10 = t9.sqrt();
        let t11 = T::from_f64(1.0) / (t5 * t5);
        let t12 = t9 + t11 / (t0 * t0);
        let t13 = T::from_f64(1.0) / t9.sqrt();
        let t14 = T::from_f64(0.5) * (t6 * (t13 * (t7 - t8))) - t10;
        WedgingPOut {
            dexact_dp: Vector4::new(
                T::from_f64(0.0),
                -(t11 * t14 / t0) / t12,
                T::from_f64(1.0) / (T::from_f64(1.0) + t1)
                    + mu * t14 / (t12 * (t0 * t0 * t0) * t5),
                T::from_f64(0.0),
            ),
            dseries_dp: Vector4::new(
                T::from_f64(0.0),
                T::from_f64(1.0) / mu + c * t2 / (mu * mu * mu),
                -(t4 * (c - T::from_f64(2.0) * t3))
                    - T::from_f64(1.5) * t2 * t3 / mu.powi(4),
                T::from_f64(0.0),
            ),
            dwhitney_dp: Vector4::new(
                T::from_f64(0.0),
                T::from_f64(1.0) / mu,
                -c * t4,
                T::from_f64(0.0),
            ),
        }
    }
}
