// @generated readable copy of `pegdyn::generated::cart_pole` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generator snapshot::

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
    /// The parameters of `cart_pole`: the input `p` of its functions as a struct, one field per component in vector order (`From`/`Into` convert both ways).
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct Params<T> {
        /// Mass of the cart, kg.
        pub mc: T,
        /// Mass of the bob, kg.
        pub m: T,
        /// Length of the rod, m.
        pub l: T,
        /// Gravitational acceleration, m/s².
        pub g: T,
        /// Horizontal force pushing the cart, N.
        pub u: T,
    }
    impl<T> Params<T> {
        /// The field names in vector order: the symbol names of `p` ([`P_NAMES`]).
        pub const NAMES: [&'static str; 5] = P_NAMES;
    }
    impl<T: Real> From<Params<T>> for SVector<T, 5> {
        /// The `p` vector of these values, in field order.
        fn from(v: Params<T>) -> SVector<T, 5> {
            SVector::from([v.mc, v.m, v.l, v.g, v.u])
        }
    }
    impl<T: Real> From<&SVector<T, 5>> for Params<T> {
        /// The fields of a `p` vector, in field order.
        fn from(v: &SVector<T, 5>) -> Params<T> {
            Params {
                mc: v[0],
                m: v[1],
                l: v[2],
                g: v[3],
                u: v[4],
            }
        }
    }
    impl<T: Real> From<SVector<T, 5>> for Params<T> {
        /// The fields of a `p` vector, in field order.
        fn from(v: SVector<T, 5>) -> Params<T> {
            Params::from(&v)
        }
    }
    /// The outputs of [`dynamics`].
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct DynamicsOut<T: Real> {
        /// Mass matrix M(q), symmetric.
        pub mass: SMatrix<T, 2, 2>,
        /// Forcing f(q, q̇) of M q̈ = f.
        pub forcing: SVector<T, 2>,
    }
    /// Mass matrix M(q) and forcing f(q, q̇) of M q̈ = f (Lagrange's equations, derived symbolically).
    ///
    /// Reference: Tedrake, Underactuated Robotics, ch. 3 (cart-pole). Units: SI.
    ///
    /// # Inputs
    /// - `x` = (`xc`, `theta`, `xcdot`, `thetadot`)
    /// - `p` = (`mc`, `m`, `l`, `g`, `u`)
    ///
    /// # Outputs
    /// The fields of [`DynamicsOut`]:
    /// - `mass`: symmetric 2×2 matrix
    /// - `forcing`: vector of 2
    ///
    /// # Cost
    /// 2 add/sub, 8 mul, 0 div, 0 sqrt, 1 transcendental, 0 branches; 5 `let`s.
    #[inline]
    pub fn dynamics<T: Real>(x: &SVector<T, 4>, p: &SVector<T, 5>) -> DynamicsOut<T> {
        let theta = x[1];
        let thetadot = x[3];
        let mc = p[0];
        let m = p[1];
        let l = p[2];
        let g = p[3];
        let u = p[4];
        let (sin_theta, cos_theta) = theta.sin_cos();
        let t0 = m * l;
        let t1 = t0 * cos_theta;
        let t2 = t0 * sin_theta;
        DynamicsOut {
            mass: Matrix2::new(mc + m, t1, t1, m * (l * l)),
            forcing: Vector2::new(u + t2 * (thetadot * thetadot), -t2 * g),
        }
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
    /// 5 add/sub, 16 mul, 2 div, 0 sqrt, 1 transcendental, 0 branches; 7 `let`s.
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
        let (sin_theta, cos_theta) = theta.sin_cos();
        let t0 = mc + m;
        let t1 = u + m * l * sin_theta * (thetadot * thetadot);
        let t2 = m * m;
        let t3 = m * t0 - cos_theta * cos_theta * t2;
        let t4 = g * sin_theta;
        Vector4::new(
            xcdot,
            thetadot,
            (m * t1 + t4 * cos_theta * t2) / t3,
            -(t4 * t0 + cos_theta * t1) * m / (l * t3),
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
    /// 2 add/sub, 11 mul, 0 div, 0 sqrt, 1 transcendental, 0 branches; 3 `let`s.
    #[inline]
    pub fn jacobian_terms<T: Real>(
        x: &SVector<T, 4>,
        qdd: &SVector<T, 2>,
        p: &SVector<T, 5>,
    ) -> SMatrix<T, 2, 4> {
        let theta = x[1];
        let thetadot = x[3];
        let xcddot = qdd[0];
        let thetaddot = qdd[1];
        let m = p[1];
        let l = p[2];
        let g = p[3];
        let (sin_theta, cos_theta) = theta.sin_cos();
        let t0 = m * l;
        Matrix2x4::new(
            T::from_f64(0.0),
            t0 * (thetaddot * sin_theta + cos_theta * (thetadot * thetadot)),
            T::from_f64(0.0),
            T::from_f64(2.0) * t0 * thetadot * sin_theta,
            T::from_f64(0.0),
            t0 * (xcddot * sin_theta - g * cos_theta),
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
    /// 4 add/sub, 11 mul, 0 div, 0 sqrt, 1 transcendental, 0 branches; 2 `let`s.
    #[inline]
    pub fn energy<T: Real>(x: &SVector<T, 4>, p: &SVector<T, 5>) -> T {
        let theta = x[1];
        let xcdot = x[2];
        let thetadot = x[3];
        let mc = p[0];
        let m = p[1];
        let l = p[2];
        let g = p[3];
        let cos_theta = theta.cos();
        let t0 = xcdot * xcdot;
        m
            * (cos_theta * (xcdot * thetadot - g) * l
                + T::from_f64(0.5) * (t0 + thetadot * thetadot * (l * l)))
            + T::from_f64(0.5) * mc * t0
    }
}
