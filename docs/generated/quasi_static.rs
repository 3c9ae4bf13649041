// @generated readable copy of `pegdyn::generated::quasi_static` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generated_snapshot

/// Quasi-static contact forces of the planar peg in two-point and one-point contact (paper 001, Eqs. 51-54), derived from the contact geometry. Inputs: pose = (theta rad, l m), load = (f1 axial N, f2 radial N), acc = (xdd, ydd m/s^2, thdd rad/s^2), p = (mu, r m, l_c m, m kg, J kg m^2).
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
    /// Eq. 52: edge force f_a (N), tip force f_b (N) and input moment about C (N m) for two-point sliding contact with the given accelerations.
    ///
    /// # Inputs
    /// - `pose` = (`theta`, `l`)
    /// - `load` = (`f1`, `f2`)
    /// - `acc` = (`xdd`, `ydd`, `thdd`)
    /// - `p` = (`mu`, `r`, `l_c`, `m`, `J`)
    ///
    /// # Outputs
    /// - `f_a`: scalar
    /// - `f_b`: scalar
    /// - `moment`: scalar
    ///
    /// # Cost
    /// 18 add/sub, 21 mul, 1 div, 0 sqrt, 1 transcendental, 0 branches; 12 `let`s.
    #[inline]
    pub fn two_point<T: Real>(
        pose: &SVector<T, 2>,
        load: &SVector<T, 2>,
        acc: &SVector<T, 3>,
        p: &SVector<T, 5>,
    ) -> (T, T, T) {
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
        let t0 = mu * sin_theta;
        let t1 = f2 * sin_theta;
        let t2 = ydd * m;
        let t3 = -f1 * cos_theta;
        let t4 = sin_theta + mu * cos_theta;
        let t5 = t0 - cos_theta;
        let t6 = -(xdd * m) + f1 * sin_theta + f2 * cos_theta;
        let t7 = t1 + t2 + t3 + mu * t6;
        let t8 = t5 * (t1 + t2 + t3) + t4 * t6;
        let t9 = T::from_f64(1.0) / (mu * (cos_theta - t5) + sin_theta);
        let f_a = -t7 * t9;
        let f_b = t9 * t8;
        let moment = thdd * j
            - t9 * (t7 * (-l_c + mu * r + l) + t8 * (r * t4 + l_c * (-cos_theta + t0)));
        (f_a, f_b, moment)
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
    ) -> (T, T) {
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
        let t0 = -(m * (xdd * cos_theta - ydd * sin_theta)) + f2;
        let f_a = -t0;
        let moment = thdd * j - (-l_c + mu * r + l) * t0;
        (f_a, moment)
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
    ) -> (T, T) {
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
        let f_b = t0;
        let moment = thdd * j
            - (r * (sin_theta + mu * cos_theta) + l_c * (-cos_theta + mu * sin_theta))
                * t0;
        (f_b, moment)
    }
    /// Whitney's frame (x lateral, z into the hole, moment about the tip): tip force f_tip (N), edge force f_edge (N) and the moment M (N m) holding the peg in two-point sliding under applied (F_x, F_z) (N); pose = (theta rad, l m), w = (F_x, F_z), q = (mu, r m).
    ///
    /// # Inputs
    /// - `pose` = (`theta`, `l`)
    /// - `w` = (`fx`, `fz`)
    /// - `q` = (`mu`, `r`)
    ///
    /// # Outputs
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
    ) -> (T, T, T) {
        let theta = pose[0];
        let l = pose[1];
        let fx = w[0];
        let fz = w[1];
        let mu = q[0];
        let r = q[1];
        let (sin_theta, cos_theta) = theta.sin_cos();
        let t0 = sin_theta + mu * cos_theta;
        let t1 = mu * sin_theta - cos_theta;
        let t2 = T::from_f64(1.0) / (mu * (cos_theta - t1) + sin_theta);
        let t3 = t0 * fx + fz * t1;
        let t4 = fz + mu * fx;
        let f_tip = -t3 * t2;
        let f_edge = t2 * t4;
        let moment = t2 * (t3 * r * t0 + t4 * (mu * r + l));
        (f_tip, f_edge, moment)
    }
}
