// @generated readable copy of `pegdyn::generated::quasi_static` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generator snapshot::

/// Quasi-static contact forces of the planar peg in two-point and one-point contact (*Dynamic analysis for peg-in-hole assembly with contact deformation*, Eqs. 51-54), derived from the contact geometry. Inputs: pose = (theta rad, l m), load = (f1 axial N, f2 radial N), acc = (xdd, ydd m/s^2, thdd rad/s^2), p = (mu, r m, l_c m, m kg, J kg m^2).
pub mod quasi_static {
    use nalgebra::SVector;
    use pegdyn::scalar::Real;
    /// Symbol names of the components of `pose`, in order.
    pub const POSE_NAMES: [&str; 2] = ["theta", "l"];
    /// Symbol names of the components of `load`, in order.
    pub const LOAD_NAMES: [&str; 2] = ["f1", "f2"];
    /// Symbol names of the components of `acc`, in order.
    pub const ACC_NAMES: [&str; 3] = ["xdd", "ydd", "thdd"];
    /// Symbol names of the components of `p`, in order.
    pub const P_NAMES: [&str; 5] = ["mu", "r", "l_c", "m", "J"];
    /// Symbol names of the components of `w`, in order.
    pub const W_NAMES: [&str; 2] = ["fx", "fz"];
    /// Symbol names of the components of `q`, in order.
    pub const Q_NAMES: [&str; 2] = ["mu", "r"];
    /// The parameters of `quasi_static`: the input `p` of its functions as a struct, one field per component in vector order (`From`/`Into` convert both ways).
    #[derive(Clone, Copy, Debug, PartialEq)]
    #[allow(non_snake_case)]
    pub struct Params<T> {
        /// Coulomb friction coefficient, dimensionless.
        pub mu: T,
        /// Peg radius, m.
        pub r: T,
        /// Distance from the centre of mass to the tip face, m.
        pub l_c: T,
        /// Mass of the peg, kg.
        pub m: T,
        /// Moment of inertia about the centre of mass, kg·m².
        pub J: T,
    }
    impl<T> Params<T> {
        /// The field names in vector order: the symbol names of `p` ([`P_NAMES`]).
        pub const NAMES: [&'static str; 5] = P_NAMES;
    }
    impl<T: Real> From<Params<T>> for SVector<T, 5> {
        /// The `p` vector of these values, in field order.
        fn from(v: Params<T>) -> SVector<T, 5> {
            SVector::from([v.mu, v.r, v.l_c, v.m, v.J])
        }
    }
    impl<T: Real> From<&SVector<T, 5>> for Params<T> {
        /// The fields of a `p` vector, in field order.
        fn from(v: &SVector<T, 5>) -> Params<T> {
            Params {
                mu: v[0],
                r: v[1],
                l_c: v[2],
                m: v[3],
                J: v[4],
            }
        }
    }
    impl<T: Real> From<SVector<T, 5>> for Params<T> {
        /// The fields of a `p` vector, in field order.
        fn from(v: SVector<T, 5>) -> Params<T> {
            Params::from(&v)
        }
    }
    /// The parameters of Whitney's tip equilibrium ([`whitney_tip`]): friction and radius.
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct WhitneyParams<T> {
        /// Coulomb friction coefficient, dimensionless.
        pub mu: T,
        /// Peg radius, m.
        pub r: T,
    }
    impl<T> WhitneyParams<T> {
        /// The field names in vector order: the symbol names of `q` ([`Q_NAMES`]).
        pub const NAMES: [&'static str; 2] = Q_NAMES;
    }
    impl<T: Real> From<WhitneyParams<T>> for SVector<T, 2> {
        /// The `q` vector of these values, in field order.
        fn from(v: WhitneyParams<T>) -> SVector<T, 2> {
            SVector::from([v.mu, v.r])
        }
    }
    impl<T: Real> From<&SVector<T, 2>> for WhitneyParams<T> {
        /// The fields of a `q` vector, in field order.
        fn from(v: &SVector<T, 2>) -> WhitneyParams<T> {
            WhitneyParams { mu: v[0], r: v[1] }
        }
    }
    impl<T: Real> From<SVector<T, 2>> for WhitneyParams<T> {
        /// The fields of a `q` vector, in field order.
        fn from(v: SVector<T, 2>) -> WhitneyParams<T> {
            WhitneyParams::from(&v)
        }
    }
    /// The outputs of [`two_point`].
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct TwoPointOut<T: Real> {
        /// Normal force f_A at the hole's edge A, N.
        pub f_a: T,
        /// Normal force f_B at the peg's tip corner B, N.
        pub f_b: T,
        /// Input moment about the centre of mass C, N·m.
        pub moment: T,
    }
    /// Eq. 52: edge force f_a (N), tip force f_b (N) and input moment about C (N m) for two-point sliding contact with the given accelerations.
    ///
    /// # Inputs
    /// - `pose` = (`theta`, `l`)
    /// - `load` = (`f1`, `f2`)
    /// - `acc` = (`xdd`, `ydd`, `thdd`)
    /// - `p` = (`mu`, `r`, `l_c`, `m`, `J`)
    ///
    /// # Outputs
    /// The fields of [`TwoPointOut`]:
    /// - `f_a`: scalar
    /// - `f_b`: scalar
    /// - `moment`: scalar
    ///
    /// # Cost
    /// 17 add/sub, 21 mul, 1 div, 0 sqrt, 1 transcendental, 0 branches; 11 `let`s.
    #[inline]
    pub fn two_point<T: Real>(
        pose: &SVector<T, 2>,
        load: &SVector<T, 2>,
        acc: &SVector<T, 3>,
        p: &SVector<T, 5>,
    ) -> TwoPointOut<T> {
        let theta = pose[0];
        let l = pose[1];
        let f1 = load[0];
        let f2 = load[1];
        let xdd = acc[0];
        let ydd = acc[1];
        let thdd = acc[2];
        let mu = p[0];
        let r = p[1];
        let l_c = p[2];
        let m = p[3];
        let j = p[4];
        let (sin_theta, cos_theta) = theta.sin_cos();
        let t0 = f2 * sin_theta;
        let t1 = ydd * m;
        let t2 = -f1 * cos_theta;
        let t3 = sin_theta + mu * cos_theta;
        let t4 = mu * sin_theta - cos_theta;
        let t5 = -(xdd * m) + f1 * sin_theta + f2 * cos_theta;
        let t6 = t0 + t1 + t2 + mu * t5;
        let t7 = t4 * (t0 + t1 + t2) + t3 * t5;
        let t8 = T::from_f64(1.0) / (mu * (cos_theta - t4) + sin_theta);
        TwoPointOut {
            f_a: -t6 * t8,
            f_b: t8 * t7,
            moment: thdd * j - t8 * (t6 * (-l_c + mu * r + l) + t7 * (r * t3 + l_c * t4)),
        }
    }
    /// The outputs of [`edge_only`].
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct EdgeOnlyOut<T: Real> {
        /// Normal force f_A at the hole's edge A, N.
        pub f_a: T,
        /// Input moment about the centre of mass C, N·m.
        pub moment: T,
    }
    /// Eq. 53 (signs corrected): edge force f_a (N) from the normal balance and input moment about C (N m), one-point contact at the edge A.
    ///
    /// # Inputs
    /// - `pose` = (`theta`, `l`)
    /// - `load` = (`f1`, `f2`)
    /// - `acc` = (`xdd`, `ydd`, `thdd`)
    /// - `p` = (`mu`, `r`, `l_c`, `m`, `J`)
    ///
    /// # Outputs
    /// The fields of [`EdgeOnlyOut`]:
    /// - `f_a`: scalar
    /// - `moment`: scalar
    ///
    /// # Cost
    /// 5 add/sub, 6 mul, 0 div, 0 sqrt, 1 transcendental, 0 branches; 3 `let`s.
    #[inline]
    pub fn edge_only<T: Real>(
        pose: &SVector<T, 2>,
        load: &SVector<T, 2>,
        acc: &SVector<T, 3>,
        p: &SVector<T, 5>,
    ) -> EdgeOnlyOut<T> {
        let theta = pose[0];
        let l = pose[1];
        let f2 = load[1];
        let xdd = acc[0];
        let ydd = acc[1];
        let thdd = acc[2];
        let mu = p[0];
        let r = p[1];
        let l_c = p[2];
        let m = p[3];
        let j = p[4];
        let (sin_theta, cos_theta) = theta.sin_cos();
        let t0 = f2 - m * (xdd * cos_theta - ydd * sin_theta);
        EdgeOnlyOut {
            f_a: -t0,
            moment: thdd * j - (-l_c + mu * r + l) * t0,
        }
    }
    /// The outputs of [`tip_only`].
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct TipOnlyOut<T: Real> {
        /// Normal force f_B at the peg's tip corner B, N.
        pub f_b: T,
        /// Input moment about the centre of mass C, N·m.
        pub moment: T,
    }
    /// Eq. 54: tip force f_b (N) from the normal balance and input moment about C (N m), one-point contact at the tip corner B.
    ///
    /// # Inputs
    /// - `pose` = (`theta`, `l`)
    /// - `load` = (`f1`, `f2`)
    /// - `acc` = (`xdd`, `ydd`, `thdd`)
    /// - `p` = (`mu`, `r`, `l_c`, `m`, `J`)
    ///
    /// # Outputs
    /// The fields of [`TipOnlyOut`]:
    /// - `f_b`: scalar
    /// - `moment`: scalar
    ///
    /// # Cost
    /// 6 add/sub, 9 mul, 0 div, 0 sqrt, 1 transcendental, 0 branches; 3 `let`s.
    #[inline]
    pub fn tip_only<T: Real>(
        pose: &SVector<T, 2>,
        load: &SVector<T, 2>,
        acc: &SVector<T, 3>,
        p: &SVector<T, 5>,
    ) -> TipOnlyOut<T> {
        let theta = pose[0];
        let f1 = load[0];
        let f2 = load[1];
        let xdd = acc[0];
        let thdd = acc[2];
        let mu = p[0];
        let r = p[1];
        let l_c = p[2];
        let m = p[3];
        let j = p[4];
        let (sin_theta, cos_theta) = theta.sin_cos();
        let t0 = f1 * sin_theta + f2 * cos_theta - xdd * m;
        TipOnlyOut {
            f_b: t0,
            moment: thdd * j
                - (r * (sin_theta + mu * cos_theta) + l_c * (mu * sin_theta - cos_theta))
                    * t0,
        }
    }
    /// The outputs of [`whitney_tip`].
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct WhitneyTipOut<T: Real> {
        /// Normal force at the peg's tip, N.
        pub f_tip: T,
        /// Normal force at the hole's edge, N.
        pub f_edge: T,
        /// Moment about the tip holding the peg, N·m.
        pub moment: T,
    }
    /// Whitney's frame (x lateral, z into the hole, moment about the tip): tip force f_tip (N), edge force f_edge (N) and the moment M (N m) holding the peg in two-point sliding under applied (F_x, F_z) (N); pose = (theta rad, l m), w = (F_x, F_z), q = (mu, r m).
    ///
    /// # Inputs
    /// - `pose` = (`theta`, `l`)
    /// - `w` = (`fx`, `fz`)
    /// - `q` = (`mu`, `r`)
    ///
    /// # Outputs
    /// The fields of [`WhitneyTipOut`]:
    /// - `f_tip`: scalar
    /// - `f_edge`: scalar
    /// - `moment`: scalar
    ///
    /// # Cost
    /// 8 add/sub, 13 mul, 1 div, 0 sqrt, 1 transcendental, 0 branches; 7 `let`s.
    #[inline]
    pub fn whitney_tip<T: Real>(
        pose: &SVector<T, 2>,
        w: &SVector<T, 2>,
        q: &SVector<T, 2>,
    ) -> WhitneyTipOut<T> {
        let theta = pose[0];
        let l = pose[1];
        let fx = w[0];
        let fz = w[1];
        let mu = q[0];
        let r = q[1];
        let (sin_theta, cos_theta) = theta.sin_cos();
        let t0 = sin_theta + mu * cos_theta;
        let t1 = mu * sin_theta - cos_theta;
        let t2 = t0 * fx + fz * t1;
        let t3 = fz + mu * fx;
        let t4 = T::from_f64(1.0) / (mu * (cos_theta - t1) + sin_theta);
        WhitneyTipOut {
            f_tip: -t2 * t4,
            f_edge: t4 * t3,
            moment: t4 * (t2 * r * t0 + t3 * (mu * r + l)),
        }
    }
}
