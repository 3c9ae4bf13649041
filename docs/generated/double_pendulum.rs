// @generated readable copy of `pegdyn::generated::double_pendulum` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generator snapshot::

/// Double pendulum (textbook reference system): point masses `m1`, `m2` on massless rods of
/// lengths `l1`, `l2`, absolute angles `theta1`, `theta2` from the downward vertical, gravity `g`.
/// SI units.
pub mod double_pendulum {
    use nalgebra::{Matrix2, Matrix2x4, SMatrix, SVector, Vector2, Vector4};
    use pegdyn::scalar::Real;
    /// Symbol names of the components of `x`, in order.
    pub const X_NAMES: [&str; 4] = ["theta1", "theta2", "theta1dot", "theta2dot"];
    /// Symbol names of the components of `p`, in order.
    pub const P_NAMES: [&str; 5] = ["m1", "m2", "l1", "l2", "g"];
    /// Symbol names of the components of `qdd`, in order.
    pub const QDD_NAMES: [&str; 2] = ["theta1ddot", "theta2ddot"];
    /// The parameters of `double_pendulum`: the input `p` of its functions as a struct, one field per component in vector order (`From`/`Into` convert both ways).
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct Params<T> {
        /// Mass of the upper bob, kg.
        pub m1: T,
        /// Mass of the lower bob, kg.
        pub m2: T,
        /// Length of the upper rod, m.
        pub l1: T,
        /// Length of the lower rod, m.
        pub l2: T,
        /// Gravitational acceleration, m/s².
        pub g: T,
    }
    impl<T> Params<T> {
        /// The field names in vector order: the symbol names of `p` ([`P_NAMES`]).
        pub const NAMES: [&'static str; 5] = P_NAMES;
    }
    impl<T: Real> From<Params<T>> for SVector<T, 5> {
        /// The `p` vector of these values, in field order.
        fn from(v: Params<T>) -> SVector<T, 5> {
            SVector::from([v.m1, v.m2, v.l1, v.l2, v.g])
        }
    }
    impl<T: Real> From<&SVector<T, 5>> for Params<T> {
        /// The fields of a `p` vector, in field order.
        fn from(v: &SVector<T, 5>) -> Params<T> {
            Params {
                m1: v[0],
                m2: v[1],
                l1: v[2],
                l2: v[3],
                g: v[4],
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
    /// Reference: Goldstein, Classical Mechanics, §1.6 (double pendulum). Units: SI.
    ///
    /// # Inputs
    /// - `x` = (`theta1`, `theta2`, `theta1dot`, `theta2dot`)
    /// - `p` = (`m1`, `m2`, `l1`, `l2`, `g`)
    ///
    /// # Outputs
    /// The fields of [`DynamicsOut`]:
    /// - `mass`: symmetric 2×2 matrix
    /// - `forcing`: vector of 2
    ///
    /// # Cost
    /// 4 add/sub, 18 mul, 0 div, 0 sqrt, 3 transcendental, 0 branches; 8 `let`s.
    #[inline]
    pub fn dynamics<T: Real>(x: &SVector<T, 4>, p: &SVector<T, 5>) -> DynamicsOut<T> {
        let theta1 = x[0];
        let theta2 = x[1];
        let theta1dot = x[2];
        let theta2dot = x[3];
        let m1 = p[0];
        let m2 = p[1];
        let l1 = p[2];
        let l2 = p[3];
        let g = p[4];
        let sin_theta1 = theta1.sin();
        let sin_theta2 = theta2.sin();
        let t0 = theta1 - theta2;
        let (t1, t2) = t0.sin_cos();
        let t3 = m1 + m2;
        let t4 = m2 * l2;
        let t5 = t4 * l1 * t2;
        DynamicsOut {
            mass: Matrix2::new(l1 * l1 * t3, t5, t5, m2 * (l2 * l2)),
            forcing: Vector2::new(
                -(l1 * (g * sin_theta1 * t3 + t4 * (theta2dot * theta2dot) * t1)),
                t4 * (l1 * (theta1dot * theta1dot) * t1 - g * sin_theta2),
            ),
        }
    }
    /// First-order right-hand side ẋ = (q̇, M⁻¹f), M⁻¹f by Cramer's rule.
    ///
    /// Reference: Goldstein, Classical Mechanics, §1.6 (double pendulum). Units: SI.
    ///
    /// # Inputs
    /// - `x` = (`theta1`, `theta2`, `theta1dot`, `theta2dot`)
    /// - `p` = (`m1`, `m2`, `l1`, `l2`, `g`)
    ///
    /// # Outputs
    /// - `xdot`: vector of 4
    ///
    /// # Cost
    /// 7 add/sub, 22 mul, 2 div, 0 sqrt, 3 transcendental, 0 branches; 10 `let`s.
    #[inline]
    pub fn rhs<T: Real>(x: &SVector<T, 4>, p: &SVector<T, 5>) -> SVector<T, 4> {
        let theta1 = x[0];
        let theta2 = x[1];
        let theta1dot = x[2];
        let theta2dot = x[3];
        let m1 = p[0];
        let m2 = p[1];
        let l1 = p[2];
        let l2 = p[3];
        let g = p[4];
        let sin_theta1 = theta1.sin();
        let sin_theta2 = theta2.sin();
        let t0 = theta1 - theta2;
        let (t1, t2) = t0.sin_cos();
        let t3 = m2 * m2;
        let t4 = m1 + m2;
        let t5 = l1 * (theta1dot * theta1dot) * t1 - g * sin_theta2;
        let t6 = g * sin_theta1 * t4 + m2 * l2 * (theta2dot * theta2dot) * t1;
        let t7 = m2 * t4 - t3 * (t2 * t2);
        Vector4::new(
            theta1dot,
            theta2dot,
            -(m2 * t6 + t3 * t2 * t5) / (l1 * t7),
            m2 * (t4 * t5 + t2 * t6) / (t7 * l2),
        )
    }
    /// G = ∂f/∂x − Σ_j (∂M_{·j}/∂x) q̈_j (n × 2n) at the accelerations `qdd`;
    /// the state Jacobian is ∂ẋ/∂x = [[0, I], [M⁻¹G]] (one LU solve of M).
    ///
    /// Reference: Goldstein, Classical Mechanics, §1.6 (double pendulum). Units: SI.
    ///
    /// # Inputs
    /// - `x` = (`theta1`, `theta2`, `theta1dot`, `theta2dot`)
    /// - `qdd` = (`theta1ddot`, `theta2ddot`)
    /// - `p` = (`m1`, `m2`, `l1`, `l2`, `g`)
    ///
    /// # Outputs
    /// - `terms`: 2×4 matrix
    ///
    /// # Cost
    /// 6 add/sub, 22 mul, 0 div, 0 sqrt, 3 transcendental, 0 branches; 10 `let`s.
    #[inline]
    pub fn jacobian_terms<T: Real>(
        x: &SVector<T, 4>,
        qdd: &SVector<T, 2>,
        p: &SVector<T, 5>,
    ) -> SMatrix<T, 2, 4> {
        let theta1 = x[0];
        let theta2 = x[1];
        let theta1dot = x[2];
        let theta2dot = x[3];
        let theta1ddot = qdd[0];
        let theta2ddot = qdd[1];
        let m1 = p[0];
        let m2 = p[1];
        let l1 = p[2];
        let l2 = p[3];
        let g = p[4];
        let cos_theta1 = theta1.cos();
        let cos_theta2 = theta2.cos();
        let t0 = theta1 - theta2;
        let (t1, t2) = t0.sin_cos();
        let t3 = m2 * l2;
        let t4 = theta1ddot * t1 + theta1dot * theta1dot * t2;
        let t5 = theta2ddot * t1 - theta2dot * theta2dot * t2;
        let t6 = t3 * l1;
        let t7 = t6 * t1;
        Matrix2x4::new(
            -(l1 * (g * cos_theta1 * (m1 + m2) - t3 * t5)),
            -(t6 * t5),
            T::from_f64(0.0),
            -T::from_f64(2.0) * t7 * theta2dot,
            t6 * t4,
            -(t3 * (l1 * t4 + g * cos_theta2)),
            T::from_f64(2.0) * t7 * theta1dot,
            T::from_f64(0.0),
        )
    }
    /// Total mechanical energy T + V (conserved without generalized forces).
    ///
    /// Reference: Goldstein, Classical Mechanics, §1.6 (double pendulum). Units: SI.
    ///
    /// # Inputs
    /// - `x` = (`theta1`, `theta2`, `theta1dot`, `theta2dot`)
    /// - `p` = (`m1`, `m2`, `l1`, `l2`, `g`)
    ///
    /// # Outputs
    /// - `energy`: scalar
    ///
    /// # Cost
    /// 7 add/sub, 19 mul, 0 div, 0 sqrt, 3 transcendental, 0 branches; 5 `let`s.
    #[inline]
    pub fn energy<T: Real>(x: &SVector<T, 4>, p: &SVector<T, 5>) -> T {
        let theta1 = x[0];
        let theta2 = x[1];
        let theta1dot = x[2];
        let theta2dot = x[3];
        let m1 = p[0];
        let m2 = p[1];
        let l1 = p[2];
        let l2 = p[3];
        let g = p[4];
        let cos_theta1 = theta1.cos();
        let cos_theta2 = theta2.cos();
        let t0 = l1 * cos_theta1;
        let t1 = theta1dot * theta1dot * (l1 * l1);
        let t2 = (theta1 - theta2).cos();
        m2
            * (T::from_f64(0.5) * (t1 + theta2dot * theta2dot * (l2 * l2))
                + theta1dot * theta2dot * l1 * l2 * t2) + T::from_f64(0.5) * t1 * m1
            - g * (t0 * m1 + m2 * (t0 + l2 * cos_theta2))
    }
}
