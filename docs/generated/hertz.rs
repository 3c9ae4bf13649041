// @generated readable copy of `pegdyn::generated::hertz` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generator snapshot::

/// Hertz elliptical contact (*Dynamic analysis for peg-in-hole assembly with contact deformation*, (9)-(13)) from setup-time coefficients c = (sum of curvatures 1/m, contact modulus Pa, m_a, m_b, delta_star). SI units.
pub mod hertz {
    use nalgebra::SVector;
    use pegdyn::scalar::Real;
    /// Symbol names of the components of `load`, in order.
    pub const LOAD_NAMES: [&str; 1] = ["load"];
    /// Symbol names of the components of `c`, in order.
    pub const C_NAMES: [&str; 5] = ["c_sum", "e_star", "c_ma", "c_mb", "c_dstar"];
    /// The parameters of `hertz`: the input `c` of its functions as a struct, one field per component in vector order (`From`/`Into` convert both ways).
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct Params<T> {
        /// Sum of the principal curvatures Σρ of the two bodies, 1/m.
        pub c_sum: T,
        /// Contact modulus E* = [Σ (1 − νᵢ²)/Eᵢ]⁻¹, Pa.
        pub e_star: T,
        /// Ellipse coefficient m_a of the semi-major axis (9), dimensionless.
        pub c_ma: T,
        /// Ellipse coefficient m_b of the semi-minor axis (10), dimensionless.
        pub c_mb: T,
        /// Approach coefficient δ* (the paper's K of (13)), dimensionless.
        pub c_dstar: T,
    }
    impl<T> Params<T> {
        /// The field names in vector order: the symbol names of `c` ([`C_NAMES`]).
        pub const NAMES: [&'static str; 5] = C_NAMES;
    }
    impl<T: Real> From<Params<T>> for SVector<T, 5> {
        /// The `c` vector of these values, in field order.
        fn from(v: Params<T>) -> SVector<T, 5> {
            SVector::from([v.c_sum, v.e_star, v.c_ma, v.c_mb, v.c_dstar])
        }
    }
    impl<T: Real> From<&SVector<T, 5>> for Params<T> {
        /// The fields of a `c` vector, in field order.
        fn from(v: &SVector<T, 5>) -> Params<T> {
            Params {
                c_sum: v[0],
                e_star: v[1],
                c_ma: v[2],
                c_mb: v[3],
                c_dstar: v[4],
            }
        }
    }
    impl<T: Real> From<SVector<T, 5>> for Params<T> {
        /// The fields of a `c` vector, in field order.
        fn from(v: SVector<T, 5>) -> Params<T> {
            Params::from(&v)
        }
    }
    /// The outputs of [`ellipse`].
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct EllipseOut<T: Real> {
        /// Semi-major axis a of the contact ellipse (9), m.
        pub a: T,
        /// Semi-minor axis b of the contact ellipse (10), m.
        pub b: T,
        /// Maximum contact pressure p₀ (11), Pa.
        pub p0: T,
        /// Approach δ of the two bodies (13), m.
        pub delta: T,
    }
    /// Semi-axes a, b (m) (9)-(10), maximum pressure p0 (Pa) (11) and approach delta (m) (13) at load Q (N); negative loads count as 0.
    ///
    /// # Inputs
    /// - `load` = (`load`)
    /// - `c` = (`c_sum`, `e_star`, `c_ma`, `c_mb`, `c_dstar`)
    ///
    /// # Outputs
    /// The fields of [`EllipseOut`]:
    /// - `a`: scalar
    /// - `b`: scalar
    /// - `p0`: scalar
    /// - `delta`: scalar
    ///
    /// # Cost
    /// 0 add/sub, 13 mul, 3 div, 0 sqrt, 2 transcendental, 1 branches; 3 `let`s.
    #[inline]
    pub fn ellipse<T: Real>(load: &SVector<T, 1>, c: &SVector<T, 5>) -> EllipseOut<T> {
        let load_2 = load[0];
        let c_sum = c[0];
        let e_star = c[1];
        let c_ma = c[2];
        let c_mb = c[3];
        let c_dstar = c[4];
        let max0_load_2 = load_2.max0();
        let t0 = (T::from_f64(1.5) * max0_load_2 / (c_sum * e_star)).cbrt();
        let t1 = (T::from_f64(0.28125) * c_sum * (max0_load_2 * max0_load_2)
            / (e_star * e_star))
            .cbrt();
        EllipseOut {
            a: c_ma * t0,
            b: c_mb * t0,
            p0: T::from_f64(0.3183098861837907) * c_sum * e_star * t0 / (c_ma * c_mb),
            delta: c_dstar * t1,
        }
    }
    /// Stiffness k (N/m^1.5) of Q = k delta^1.5 ((13) inverted).
    ///
    /// # Inputs
    /// - `c` = (`c_sum`, `e_star`, `c_ma`, `c_mb`, `c_dstar`)
    ///
    /// # Outputs
    /// - `k`: scalar
    ///
    /// # Cost
    /// 0 add/sub, 5 mul, 1 div, 1 sqrt, 0 transcendental, 0 branches; 1 `let`s.
    #[inline]
    pub fn stiffness<T: Real>(c: &SVector<T, 5>) -> T {
        let c_sum = c[0];
        let e_star = c[1];
        let c_dstar = c[4];
        let t0 = (T::from_f64(8.0) / (c_sum * (c_dstar * c_dstar * c_dstar))).sqrt();
        T::from_f64(2.0 / 3.0) * e_star * t0
    }
}
