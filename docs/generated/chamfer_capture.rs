// @generated readable copy of `pegdyn::generated::chamfer_capture` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generator snapshot::

/// Capture widths of a rounded chamfer for an aligned peg, frictionless and with friction, as functions of p = (r_peg m, r_bore m, rho_p m, rho_h m, mu) for their parameter Jacobian.
pub mod chamfer_capture {
    use nalgebra::{SVector, Vector5};
    use pegdyn::scalar::Real;
    /// Symbol names of the components of `p`, in order.
    pub const P_NAMES: [&str; 5] = ["r_peg", "r_bore", "rho_p", "rho_h", "mu"];
    /// The parameters of `chamfer_capture`: the input `p` of its functions as a struct, one field per component in vector order (`From`/`Into` convert both ways).
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct Params<T> {
        /// Peg radius r, m.
        pub r_peg: T,
        /// Bore radius R, m.
        pub r_bore: T,
        /// Rim fillet ρ_p of the peg, m.
        pub rho_p: T,
        /// Mouth fillet ρ_h of the hole (the chamfer's width), m.
        pub rho_h: T,
        /// Coulomb friction coefficient μ, dimensionless.
        pub mu: T,
    }
    impl<T> Params<T> {
        /// The field names in vector order: the symbol names of `p` ([`P_NAMES`]).
        pub const NAMES: [&'static str; 5] = P_NAMES;
    }
    impl<T: Real> From<Params<T>> for SVector<T, 5> {
        /// The `p` vector of these values, in field order.
        fn from(v: Params<T>) -> SVector<T, 5> {
            SVector::from([v.r_peg, v.r_bore, v.rho_p, v.rho_h, v.mu])
        }
    }
    impl<T: Real> From<&SVector<T, 5>> for Params<T> {
        /// The fields of a `p` vector, in field order.
        fn from(v: &SVector<T, 5>) -> Params<T> {
            Params {
                r_peg: v[0],
                r_bore: v[1],
                rho_p: v[2],
                rho_h: v[3],
                mu: v[4],
            }
        }
    }
    impl<T: Real> From<SVector<T, 5>> for Params<T> {
        /// The fields of a `p` vector, in field order.
        fn from(v: SVector<T, 5>) -> Params<T> {
            Params::from(&v)
        }
    }
    /// The outputs of [`widths`].
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct WidthsOut<T: Real> {
        /// W_0 = R + ρ_h, m.
        pub frictionless_width: T,
        /// W_μ = R + ρ_h − (ρ_h + ρ_p) μ/√(1 + μ²), m.
        pub width: T,
        /// Largest lateral tip error of an aligned peg, W_μ − (r − ρ_p), m.
        pub aligned_tip_error: T,
    }
    /// The capture widths W_0 = R + ρ_h and W_μ = W_0 − (ρ_h + ρ_p) μ/√(1 + μ²) (m) of the tube centre's distance from the hole's axis, and the aligned tip error W_μ − (r − ρ_p) (m) the chamfer accepts.
    ///
    /// # Inputs
    /// - `p` = (`r_peg`, `r_bore`, `rho_p`, `rho_h`, `mu`)
    ///
    /// # Outputs
    /// The fields of [`WidthsOut`]:
    /// - `frictionless_width`: scalar
    /// - `width`: scalar
    /// - `aligned_tip_error`: scalar
    ///
    /// # Cost
    /// 8 add/sub, 1 mul, 1 div, 0 sqrt, 1 transcendental, 0 branches; 2 `let`s.
    #[inline]
    pub fn widths<T: Real>(p: &SVector<T, 5>) -> WidthsOut<T> {
        let r_peg = p[0];
        let r_bore = p[1];
        let rho_p = p[2];
        let rho_h = p[3];
        let mu = p[4];
        let t0 = mu.hypot(T::from_f64(1.0));
        let t1 = -mu * (rho_p + rho_h) / t0;
        WidthsOut {
            frictionless_width: r_bore + rho_h,
            width: r_bore + rho_h + t1,
            aligned_tip_error: r_bore + rho_p + rho_h - r_peg + t1,
        }
    }
    /// The outputs of [`widths_p`].
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct WidthsPOut<T: Real> {
        /// `dfrictionless_width_dp`: vector of 5.
        pub dfrictionless_width_dp: SVector<T, 5>,
        /// `dwidth_dp`: vector of 5.
        pub dwidth_dp: SVector<T, 5>,
        /// `daligned_tip_error_dp`: vector of 5.
        pub daligned_tip_error_dp: SVector<T, 5>,
    }
    /// Exact parameter Jacobian of [`widths`]: `dfrictionless_width_dp` with entry (i, k) = ∂frictionless_widthᵢ/∂p_k; `dwidth_dp` with entry (i, k) = ∂widthᵢ/∂p_k; `daligned_tip_error_dp` with entry (i, k) = ∂aligned_tip_errorᵢ/∂p_k (columns in `P_NAMES` order).
    ///
    /// # Inputs
    /// - `p` = (`r_peg`, `r_bore`, `rho_p`, `rho_h`, `mu`)
    ///
    /// # Outputs
    /// The fields of [`WidthsPOut`]:
    /// - `dfrictionless_width_dp`: vector of 5
    /// - `dwidth_dp`: vector of 5
    /// - `daligned_tip_error_dp`: vector of 5
    ///
    /// # Cost
    /// 3 add/sub, 4 mul, 3 div, 0 sqrt, 1 transcendental, 0 branches; 4 `let`s.
    #[inline]
    pub fn widths_p<T: Real>(p: &SVector<T, 5>) -> WidthsPOut<T> {
        let rho_p = p[2];
        let rho_h = p[3];
        let mu = p[4];
        let t0 = mu.hypot(T::from_f64(1.0));
        let t1 = -mu / t0;
        let t2 = T::from_f64(1.0) + t1;
        let t3 = (rho_p + rho_h) * (T::from_f64(1.0) / t0 - mu * mu / (t0 * t0 * t0));
        WidthsPOut {
            dfrictionless_width_dp: Vector5::new(
                T::from_f64(0.0),
                T::from_f64(1.0),
                T::from_f64(0.0),
                T::from_f64(1.0),
                T::from_f64(0.0),
            ),
            dwidth_dp: Vector5::new(T::from_f64(0.0), T::from_f64(1.0), t1, t2, -t3),
            daligned_tip_error_dp: Vector5::new(
                -T::from_f64(1.0),
                T::from_f64(1.0),
                t2,
                t2,
                -t3,
            ),
        }
    }
}
