// @generated readable copy of `pegdyn::generated::cart_pole` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generated_snapshot

/// Cart-pole (textbook reference system): cart of mass `mc` at `xc` pushed by force `u`, point
/// mass `m` on a massless rod of length `l` at angle `theta` from the downward vertical,
/// gravity `g`. SI units.
pub mod cart_pole {
    use nalgebra::{Matrix2, Matrix2x4, SMatrix, SVector, Vector2, Vector4};
    use pegdyn::scalar::Real;
    /// Symbol names of the components of `x`, in order.
    pub const X_NAMES: [&str; 4] = ["xc", "theta", "xcdot", "thetadot"];
    /// Symbol names of the components of `p`, in order.
    pub const P_NAMES: [&str; 5] = ["mc", "m", "l", "g", "u"];
    /// Symbol names of the components of `qdd`, in order.
    pub const QDD_NAMES: [&str; 2] = ["xcddot", "thetaddot"];
    /// Mass matrix M(q) and forcing f(q, q̇) of M q̈ = f (Lagrange's equations, derived symbolically).
    ///
    /// Reference: Tedrake, Underactuated Robotics, ch. 3 (cart-pole). Units: SI.
    ///
    /// # Inputs
    /// - `x` = (`xc`, `theta`, `xcdot`, `thetadot`)
    /// - `p` = (`mc`, `m`, `l`, `g`, `u`)
    ///
    /// # Outputs
    /// - `mass`: symmetric 2×2 matrix
    /// - `forcing`: vector of 2
    ///
    /// # Cost
    /// 7 add/sub, 33 mul, 0 div, 0 sqrt, 2 transcendental, 0 branches; 6 `let`s.
    #[inline]
    pub fn dynamics<T: Real>(
        x: &SVector<T, 4>,
        p: &SVector<T, 5>,
    ) -> (SMatrix<T, 2, 2>, SVector<T, 2>) {
        let theta = x[1];
        let xcdot = x[2];
        let thetadot = x[3];
        let mc = p[0];
        let m = p[1];
        let l = p[2];
        let g = p[3];
        let u = p[4];
        let sin_theta = theta.sin();
        let cos_theta = theta.cos();
        let t0 = thetadot * thetadot;
        let t1 = l * l;
        let t2 = T::from_f64(2.0) * xcdot + T::from_f64(2.0) * thetadot * l * cos_theta;
        let t3 = m * l * cos_theta;
        let mass = Matrix2::new(mc + m, t3, t3, m * t1);
        let forcing = Vector2::new(
            u + m * l * sin_theta * t0,
            -(m * l * g * sin_theta)
                + T::from_f64(0.5) * m
                    * (-(thetadot * l * sin_theta * t2)
                        + T::from_f64(2.0) * sin_theta * cos_theta * t0 * t1)
                - T::from_f64(0.5) * thetadot * m
                    * (-(l * sin_theta * t2)
                        + T::from_f64(2.0) * thetadot * sin_theta * cos_theta * t1),
        );
        (mass, forcing)
    }
    /// First-order right-hand side ẋ = (q̇, M⁻¹f), M⁻¹f by Cramer's rule.
    ///
    /// Reference: Tedrake, Underactuated Robotics, ch. 3 (cart-pole). Units: SI.
    ///
    /// # Inputs
    /// - `x` = (`xc`, `theta`, `xcdot`, `thetadot`)
    /// - `p` = (`mc`, `m`, `l`, `g`, `u`)
    ///
    /// # Outputs
    /// - `xdot`: vector of 4
    ///
    /// # Cost
    /// 10 add/sub, 47 mul, 1 div, 0 sqrt, 2 transcendental, 0 branches; 9 `let`s.
    #[inline]
    pub fn rhs<T: Real>(x: &SVector<T, 4>, p: &SVector<T, 5>) -> SVector<T, 4> {
        let theta = x[1];
        let xcdot = x[2];
        let thetadot = x[3];
        let mc = p[0];
        let m = p[1];
        let l = p[2];
        let g = p[3];
        let u = p[4];
        let sin_theta = theta.sin();
        let cos_theta = theta.cos();
        let t0 = thetadot * thetadot;
        let t1 = l * l;
        let t2 = T::from_f64(2.0) * xcdot + T::from_f64(2.0) * thetadot * l * cos_theta;
        let t3 = mc + m;
        let t4 = u + m * l * sin_theta * t0;
        let t5 = -(m * l * g * sin_theta)
            + T::from_f64(0.5) * m
                * (-(thetadot * l * sin_theta * t2)
                    + T::from_f64(2.0) * sin_theta * cos_theta * t0 * t1)
            - T::from_f64(0.5) * thetadot * m
                * (-(l * sin_theta * t2)
                    + T::from_f64(2.0) * thetadot * sin_theta * cos_theta * t1);
        let t6 = T::from_f64(1.0)
            / (m * t1 * t3 - t1 * (cos_theta * cos_theta) * (m * m));
        Vector4::new(
            xcdot,
            thetadot,
            (m * t1 * t4 - m * l * cos_theta * t5) * t6,
            t6 * (t3 * t5 - m * l * cos_theta * t4),
        )
    }
    /// G = ∂f/∂x − Σ_j (∂M_{·j}/∂x) q̈_j (n × 2n) at the accelerations `qdd`;
    /// the state Jacobian is ∂ẋ/∂x = [[0, I], [M⁻¹G]] (one LU solve of M).
    ///
    /// Reference: Tedrake, Underactuated Robotics, ch. 3 (cart-pole). Units: SI.
    ///
    /// # Inputs
    /// - `x` = (`xc`, `theta`, `xcdot`, `thetadot`)
    /// - `qdd` = (`xcddot`, `thetaddot`)
    /// - `p` = (`mc`, `m`, `l`, `g`, `u`)
    ///
    /// # Outputs
    /// - `terms`: 2×4 matrix
    ///
    /// # Cost
    /// 7 add/sub, 39 mul, 0 div, 0 sqrt, 2 transcendental, 0 branches; 6 `let`s.
    #[inline]
    pub fn jacobian_terms<T: Real>(
        x: &SVector<T, 4>,
        qdd: &SVector<T, 2>,
        p: &SVector<T, 5>,
    ) -> SMatrix<T, 2, 4> {
        let theta = x[1];
        let xcdot = x[2];
        let thetadot = x[3];
        let xcddot = qdd[0];
        let thetaddot = qdd[1];
        let m = p[1];
        let l = p[2];
        let g = p[3];
        let sin_theta = theta.sin();
        let cos_theta = theta.cos();
        let t0 = thetadot * thetadot;
        let t1 = l * l;
        let t2 = T::from_f64(2.0) * xcdot + T::from_f64(2.0) * thetadot * l * cos_theta;
        let t3 = cos_theta * cos_theta;
        Matrix2x4::new(
            T::from_f64(0.0),
            thetaddot * m * l * sin_theta + m * l * cos_theta * t0,
            T::from_f64(0.0),
            T::from_f64(2.0) * thetadot * m * l * sin_theta,
            T::from_f64(0.0),
            -(m * l * g * cos_theta) + xcddot * m * l * sin_theta
                + T::from_f64(0.5) * m
                    * (-(thetadot * l * cos_theta * t2)
                        + T::from_f64(2.0) * t0 * t1 * t3)
                - T::from_f64(0.5) * thetadot * m
                    * (-(l * cos_theta * t2) + T::from_f64(2.0) * thetadot * t1 * t3),
            T::from_f64(0.0),
            T::from_f64(0.0),
        )
    }
    /// Total mechanical energy T + V (conserved without generalized forces).
    ///
    /// Reference: Tedrake, Underactuated Robotics, ch. 3 (cart-pole). Units: SI.
    ///
    /// # Inputs
    /// - `x` = (`xc`, `theta`, `xcdot`, `thetadot`)
    /// - `p` = (`mc`, `m`, `l`, `g`, `u`)
    ///
    /// # Outputs
    /// - `energy`: scalar
    ///
    /// # Cost
    /// 4 add/sub, 16 mul, 0 div, 0 sqrt, 2 transcendental, 0 branches; 3 `let`s.
    #[inline]
    pub fn energy<T: Real>(x: &SVector<T, 4>, p: &SVector<T, 5>) -> T {
        let theta = x[1];
        let xcdot = x[2];
        let thetadot = x[3];
        let mc = p[0];
        let m = p[1];
        let l = p[2];
        let g = p[3];
        let sin_theta = theta.sin();
        let cos_theta = theta.cos();
        let t0 = xcdot + thetadot * l * cos_theta;
        T::from_f64(0.5) * mc * (xcdot * xcdot)
            + T::from_f64(0.5) * m
                * (t0 * t0 + thetadot * thetadot * (l * l) * (sin_theta * sin_theta))
            - m * l * g * cos_theta
    }
}
