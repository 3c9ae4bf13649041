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
    /// Semi-axes a, b (m) (9)-(10), maximum pressure p0 (Pa) (11) and approach delta (m) (13) at load Q (N); negative loads count as 0.
    ///
    /// # Inputs
    /// - `load` = (`load`)
    /// - `c` = (`c_sum`, `e_star`, `c_ma`, `c_mb`, `c_dstar`)
    ///
    /// # Outputs
    /// - `a`: scalar
    /// - `b`: scalar
    /// - `p0`: scalar
    /// - `delta`: scalar
    ///
    /// # Cost
    /// 0 add/sub, 13 mul, 3 div, 0 sqrt, 2 transcendental, 1 branches; 3 `let`s.
    #[inline]
    pub fn ellipse<T: Real>(load: &SVector<T, 1>, c: &SVector<T, 5>) -> (T, T, T, T) {
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
        let a = c_ma * t0;
        let b = c_mb * t0;
        let p0 = T::from_f64(0.3183098861837907) * c_sum * e_star * t0 / (c_ma * c_mb);
        let delta = c_dstar * t1;
        (a, b, p0, delta)
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
