// @generated readable copy of `pegdyn::generated::pendulum` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generator snapshot::

/// Simple pendulum (textbook reference system): point mass `m` on a massless rod of length `l`,
/// angle `theta` from the downward vertical, gravity `g`. SI units.
pub mod pendulum {
    use nalgebra::{Matrix1, Matrix1x2, SMatrix, SVector, Vector1, Vector2};
    use pegdyn::scalar::Real;
    /// Symbol names of the components of `x`, in order.
    pub const X_NAMES: [&str; 2] = ["theta", "thetadot"];
    /// Symbol names of the components of `p`, in order.
    pub const P_NAMES: [&str; 3] = ["m", "l", "g"];
    /// Symbol names of the components of `qdd`, in order.
    pub const QDD_NAMES: [&str; 1] = ["thetaddot"];
    /// The parameters of `pendulum`: the input `p` of its functions as a struct, one field per component in vector order (`From`/`Into` convert both ways).
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct Params<T> {
        /// Mass of the bob, kg.
        pub m: T,
        /// Length of the rod, m.
        pub l: T,
        /// Gravitational acceleration, m/s².
        pub g: T,
    }
    impl<T> Params<T> {
        /// The field names in vector order: the symbol names of `p` ([`P_NAMES`]).
        pub const NAMES: [&'static str; 3] = P_NAMES;
    }
    impl<T: Real> From<Params<T>> for SVector<T, 3> {
        /// The `p` vector of these values, in field order.
        fn from(v: Params<T>) -> SVector<T, 3> {
            SVector::from([v.m, v.l, v.g])
        }
    }
    impl<T: Real> From<&SVector<T, 3>> for Params<T> {
        /// The fields of a `p` vector, in field order.
        fn from(v: &SVector<T, 3>) -> Params<T> {
            Params {
                m: v[0],
                l: v[1],
                g: v[2],
            }
        }
    }
    impl<T: Real> From<SVector<T, 3>> for Params<T> {
        /// The fields of a `p` vector, in field order.
        fn from(v: SVector<T, 3>) -> Params<T> {
            Params::from(&v)
        }
    }
    /// The outputs of [`dynamics`].
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct DynamicsOut<T: Real> {
        /// Mass matrix M(q), symmetric.
        pub mass: SMatrix<T, 1, 1>,
        /// Forcing f(q, q̇) of M q̈ = f.
        pub forcing: SVector<T, 1>,
    }
    /// Mass matrix M(q) and forcing f(q, q̇) of M q̈ = f (Lagrange's equations, derived symbolically).
    ///
    /// Reference: Goldstein, Classical Mechanics, §1.6. Units: SI.
    ///
    /// # Inputs
    /// - `x` = (`theta`, `thetadot`)
    /// - `p` = (`m`, `l`, `g`)
    ///
    /// # Outputs
    /// The fields of [`DynamicsOut`]:
    /// - `mass`: symmetric 1×1 matrix
    /// - `forcing`: vector of 1
    ///
    /// # Cost
    /// 0 add/sub, 5 mul, 0 div, 0 sqrt, 1 transcendental, 0 branches; 1 `let`s.
    #[inline]
    pub fn dynamics<T: Real>(x: &SVector<T, 2>, p: &SVector<T, 3>) -> DynamicsOut<T> {
        let theta = x[0];
        let m = p[0];
        let l = p[1];
        let g = p[2];
        let sin_theta = theta.sin();
        DynamicsOut {
            mass: Matrix1::new(m * (l * l)),
            forcing: Vector1::new(-m * l * g * sin_theta),
        }
    }
    /// First-order right-hand side ẋ = (q̇, M⁻¹f), M⁻¹f by Cramer's rule.
    ///
    /// Reference: Goldstein, Classical Mechanics, §1.6. Units: SI.
    ///
    /// # Inputs
    /// - `x` = (`theta`, `thetadot`)
    /// - `p` = (`m`, `l`, `g`)
    ///
    /// # Outputs
    /// - `xdot`: vector of 2
    ///
    /// # Cost
    /// 0 add/sub, 1 mul, 1 div, 0 sqrt, 1 transcendental, 0 branches; 1 `let`s.
    #[inline]
    pub fn rhs<T: Real>(x: &SVector<T, 2>, p: &SVector<T, 3>) -> SVector<T, 2> {
        let theta = x[0];
        let thetadot = x[1];
        let l = p[1];
        let g = p[2];
        let sin_theta = theta.sin();
        Vector2::new(thetadot, -g * sin_theta / l)
    }
    /// G = ∂f/∂x − Σ_j (∂M_{·j}/∂x) q̈_j (n × 2n) at the accelerations `qdd`;
    /// the state Jacobian is ∂ẋ/∂x = [[0, I], [M⁻¹G]] (one LU solve of M).
    ///
    /// Reference: Goldstein, Classical Mechanics, §1.6. Units: SI.
    ///
    /// # Inputs
    /// - `x` = (`theta`, `thetadot`)
    /// - `qdd` = (`thetaddot`)
    /// - `p` = (`m`, `l`, `g`)
    ///
    /// # Outputs
    /// - `terms`: 1×2 matrix
    ///
    /// # Cost
    /// 0 add/sub, 3 mul, 0 div, 0 sqrt, 1 transcendental, 0 branches; 1 `let`s.
    #[inline]
    pub fn jacobian_terms<T: Real>(
        x: &SVector<T, 2>,
        _qdd: &SVector<T, 1>,
        p: &SVector<T, 3>,
    ) -> SMatrix<T, 1, 2> {
        let theta = x[0];
        let m = p[0];
        let l = p[1];
        let g = p[2];
        let cos_theta = theta.cos();
        Matrix1x2::new(-m * l * g * cos_theta, T::from_f64(0.0))
    }
    /// Total mechanical energy T + V (conserved without generalized forces).
    ///
    /// Reference: Goldstein, Classical Mechanics, §1.6. Units: SI.
    ///
    /// # Inputs
    /// - `x` = (`theta`, `thetadot`)
    /// - `p` = (`m`, `l`, `g`)
    ///
    /// # Outputs
    /// - `energy`: scalar
    ///
    /// # Cost
    /// 1 add/sub, 7 mul, 0 div, 0 sqrt, 1 transcendental, 0 branches; 1 `let`s.
    #[inline]
    pub fn energy<T: Real>(x: &SVector<T, 2>, p: &SVector<T, 3>) -> T {
        let theta = x[0];
        let thetadot = x[1];
        let m = p[0];
        let l = p[1];
        let g = p[2];
        let cos_theta = theta.cos();
        -(m * (l * g * cos_theta - T::from_f64(0.5) * (thetadot * thetadot) * (l * l)))
    }
}
