// @generated readable copy of `pegdyn::generated::compliant_peg_3d` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generator snapshot::

/// Compliant 3-D peg-in-hole: contact-pair gaps along the edge circles and Newton-Euler dynamics in centre of mass, unit quaternion and body angular velocity. Inputs: pose x (see X_NAMES), edge angle a, state y, contact wrench w, parameters p (see P_NAMES). SI units.
pub mod compliant_peg_3d {
    use nalgebra::{SMatrix, SVector, Vector3};
    use pegdyn::scalar::Real;
    /// Symbol names of the components of `x`, in order.
    pub const X_NAMES: [&str; 7] = ["px", "py", "pz", "q0", "q1", "q2", "q3"];
    /// Symbol names of the components of `a`, in order.
    pub const A_NAMES: [&str; 1] = ["angle"];
    /// Symbol names of the components of `p`, in order.
    pub const P_NAMES: [&str; 16] = [
        "r",
        "L",
        "rho_p",
        "R",
        "rho_h",
        "h_b",
        "m",
        "J_t",
        "J_a",
        "g",
        "fa_x",
        "fa_y",
        "fa_z",
        "ma_x",
        "ma_y",
        "ma_z",
    ];
    /// Symbol names of the components of `y`, in order.
    pub const Y_NAMES: [&str; 15] = [
        "px",
        "py",
        "pz",
        "q0",
        "q1",
        "q2",
        "q3",
        "vx",
        "vy",
        "vz",
        "wx",
        "wy",
        "wz",
        "work",
        "dissipation",
    ];
    /// Symbol names of the components of `w`, in order.
    pub const W_NAMES: [&str; 7] = ["Fx", "Fy", "Fz", "Tx", "Ty", "Tz", "Sdot"];
    /// The parameters of `compliant_peg_3d`: the input `p` of its functions as a struct, one field per component in vector order (`From`/`Into` convert both ways).
    #[derive(Clone, Copy, Debug, PartialEq)]
    #[allow(non_snake_case)]
    pub struct Params<T> {
        /// Peg radius r, m.
        pub r: T,
        /// Peg length L, m.
        pub L: T,
        /// Fillet radius of the peg's bottom rim rho_p, m.
        pub rho_p: T,
        /// Bore radius R, m.
        pub R: T,
        /// Fillet radius of the hole's mouth edge rho_h, m.
        pub rho_h: T,
        /// Bore depth h_b, m.
        pub h_b: T,
        /// Mass m, kg.
        pub m: T,
        /// Transverse moment of inertia about the centre of mass, kg m^2.
        pub J_t: T,
        /// Axial moment of inertia, kg m^2.
        pub J_a: T,
        /// Gravitational acceleration along -z, m/s^2.
        pub g: T,
        /// Applied force x, N.
        pub fa_x: T,
        /// Applied force y, N.
        pub fa_y: T,
        /// Applied force z, N.
        pub fa_z: T,
        /// Applied moment x, N m.
        pub ma_x: T,
        /// Applied moment y, N m.
        pub ma_y: T,
        /// Applied moment z, N m.
        pub ma_z: T,
    }
    impl<T> Params<T> {
        /// The field names in vector order: the symbol names of `p` ([`P_NAMES`]).
        pub const NAMES: [&'static str; 16] = P_NAMES;
    }
    impl<T: Real> From<Params<T>> for SVector<T, 16> {
        /// The `p` vector of these values, in field order.
        fn from(v: Params<T>) -> SVector<T, 16> {
            SVector::from([
                v.r,
                v.L,
                v.rho_p,
                v.R,
                v.rho_h,
                v.h_b,
                v.m,
                v.J_t,
                v.J_a,
                v.g,
                v.fa_x,
                v.fa_y,
                v.fa_z,
                v.ma_x,
                v.ma_y,
                v.ma_z,
            ])
        }
    }
    impl<T: Real> From<&SVector<T, 16>> for Params<T> {
        /// The fields of a `p` vector, in field order.
        fn from(v: &SVector<T, 16>) -> Params<T> {
            Params {
                r: v[0],
                L: v[1],
                rho_p: v[2],
                R: v[3],
                rho_h: v[4],
                h_b: v[5],
                m: v[6],
                J_t: v[7],
                J_a: v[8],
                g: v[9],
                fa_x: v[10],
                fa_y: v[11],
                fa_z: v[12],
                ma_x: v[13],
                ma_y: v[14],
                ma_z: v[15],
            }
        }
    }
    impl<T: Real> From<SVector<T, 16>> for Params<T> {
        /// The fields of a `p` vector, in field order.
        fn from(v: SVector<T, 16>) -> Params<T> {
            Params::from(&v)
        }
    }
    /// One contact pair at one angle along its edge circle: the gap with its first and second derivatives in the angle, its gradient in the pose, the force direction on the peg and the contact point.
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct PairGeometry<T: Real> {
        /// Gap g along the pair's normal (negative: penetration), m.
        pub gap: T,
        /// First derivative dg/dangle of the gap, m/rad.
        pub d1: T,
        /// Second derivative d²g/dangle² of the gap, m/rad².
        pub d2: T,
        /// Gradient dg/d(px, py, pz, q0, q1, q2, q3) of the gap in the pose, m per unit.
        pub grad: SVector<T, 7>,
        /// Unit direction of the contact force on the peg, hole frame.
        pub normal: SVector<T, 3>,
        /// Contact point, hole frame, m.
        pub point: SVector<T, 3>,
        /// Axial coordinate of the contact point along the peg from the centre of mass, m.
        pub axial: T,
    }
    /// Contact pair: the mouth-edge torus against the peg's side, angle along the mouth-edge circle. Gap g (m, negative = penetration), dg/dangle and d2g/dangle2 (m/rad, m/rad^2), gradient dg/d(px, py, pz, q0..q3), unit force direction on the peg, contact point (m) and its axial coordinate along the peg from the centre of mass (m).
    ///
    /// # Inputs
    /// - `x` = (`px`, `py`, `pz`, `q0`, `q1`, `q2`, `q3`)
    /// - `a` = (`angle`)
    /// - `p` = (`r`, `L`, `rho_p`, `R`, `rho_h`, `h_b`, `m`, `J_t`, `J_a`, `g`, `fa_x`, `fa_y`, `fa_z`, `ma_x`, `ma_y`, `ma_z`)
    ///
    /// # Outputs
    /// The fields of [`PairGeometry`]:
    /// - `gap`: scalar
    /// - `d1`: scalar
    /// - `d2`: scalar
    /// - `grad`: vector of 7
    /// - `normal`: vector of 3
    /// - `point`: vector of 3
    /// - `axial`: scalar
    ///
    /// # Cost
    /// 78 add/sub, 143 mul, 2 div, 0 sqrt, 3 transcendental, 0 branches; 45 `let`s.
    #[inline]
    pub fn edge_side<T: Real>(
        x: &SVector<T, 7>,
        a: &SVector<T, 1>,
        p: &SVector<T, 16>,
    ) -> PairGeometry<T> {
        let px = x[0];
        let py = x[1];
        let pz = x[2];
        let q0 = x[3];
        let q1 = x[4];
        let q2 = x[5];
        let q3 = x[6];
        let angle = a[0];
        let r = p[0];
        let r_2 = p[3];
        let rho_h = p[4];
        let t0 = q1 * q3 + q0 * q2;
        let (sin_angle, cos_angle) = angle.sin_cos();
        let t1 = r_2 + rho_h;
        let t2 = cos_angle * t1;
        let t3 = sin_angle * t1;
        let t4 = rho_h + pz;
        let t5 = q0 * q1 - q2 * q3;
        let t6 = T::from_f64(1.0) - T::from_f64(2.0) * (q2 * q2 + q1 * q1);
        let t7 = t6 * t6;
        let t8 = t0 * sin_angle + t5 * cos_angle;
        let t9 = T::from_f64(4.0) * t0 * t8 - sin_angle;
        let t10 = t1 * t9;
        let t11 = cos_angle - T::from_f64(4.0) * t5 * t8;
        let t12 = t1 * t11;
        let t13 = t0 * cos_angle - t5 * sin_angle;
        let t14 = px - t2;
        let t15 = py - t3;
        let t16 = q1 * t15 - q2 * t14;
        let t17 = T::from_f64(2.0) * (q0 * t15 - q3 * t14) + T::from_f64(4.0) * q1 * t4;
        let t18 = q1 * t14 + q2 * t15;
        let t19 = T::from_f64(4.0) * q2 * t4 - T::from_f64(2.0) * (q0 * t14 + q3 * t15);
        let t20 = T::from_f64(2.0) * t8 * t1;
        let t21 = T::from_f64(2.0) * (t0 * t14 - t5 * t15) + t6 * t4;
        let t22 = -px + T::from_f64(2.0) * t0 * t21 + t2;
        let t23 = py + T::from_f64(2.0) * t5 * t21 - t3;
        let t24 = rho_h + pz - t6 * t21;
        let t25 = (-t22).hypot(t23);
        let t26 = t24.hypot(t25);
        let t27 = T::from_f64(1.0) / t26;
        let t28 = t27 * (T::from_f64(0.5) * t26 - T::from_f64(0.5) * (r - rho_h));
        let t29 = t28 * t22;
        let t30 = t28 * t23;
        let t31 = -t28 * t24;
        let t32 = t6 * t24;
        let t33 = t1 * (-(t22 * t9) + t23 * t11 + T::from_f64(2.0) * t32 * t8);
        let t34 = t5 * t23;
        let t35 = -T::from_f64(2.0) * t32;
        let t36 = t0 * t22;
        let t37 = q2 * t21;
        let t38 = -T::from_f64(2.0) * t37;
        let t39 = q1 * t21;
        let t40 = -T::from_f64(2.0) * t39;
        let t41 = q3 * t21;
        let t42 = q0 * t21;
        PairGeometry {
            gap: -rho_h - r + t26,
            d1: -t33 * t27,
            d2: t27
                * (t1
                    * (t22 * (T::from_f64(4.0) * t0 * t13 - cos_angle)
                        + t23 * (sin_angle + T::from_f64(4.0) * t5 * t13)
                        - T::from_f64(2.0) * t32 * t13) + t10 * t10 + t12 * t12
                    + t7 * (t20 * t20)) - t33 * t33 / (t26 * t26 * t26),
            grad: SMatrix::<
                T,
                7,
                1,
            >::from_row_slice(
                &[
                    t27
                        * (t0 * (T::from_f64(4.0) * t34 + t35)
                            - t22 * (T::from_f64(1.0) - T::from_f64(4.0) * (t0 * t0))),
                    -t27
                        * (t5 * (T::from_f64(4.0) * t36 + t35)
                            - t23 * (T::from_f64(1.0) - T::from_f64(4.0) * (t5 * t5))),
                    t27
                        * (T::from_f64(2.0) * (t36 + t34) * t6
                            + t24 * (T::from_f64(1.0) - t7)),
                    -t27
                        * (t22 * (t38 + T::from_f64(4.0) * t0 * t16)
                            + t23 * (t40 + T::from_f64(4.0) * t5 * t16)
                            - T::from_f64(2.0) * t32 * t16),
                    t27
                        * (T::from_f64(2.0)
                            * (t22 * (t41 - t0 * t17) + t23 * (t42 - t5 * t17))
                            + t24 * (T::from_f64(4.0) * t39 + t6 * t17)),
                    t27
                        * (T::from_f64(2.0)
                            * (t22 * (t42 - t0 * t19) - t23 * (t41 + t5 * t19))
                            + t24 * (T::from_f64(4.0) * t37 + t6 * t19)),
                    -t27
                        * (t22 * (t40 - T::from_f64(4.0) * t0 * t18)
                            - t23 * (t38 + T::from_f64(4.0) * t5 * t18)
                            + T::from_f64(2.0) * t32 * t18),
                ],
            ),
            normal: Vector3::new(-t22 * t27, t23 * t27, t24 * t27),
            point: Vector3::new(t2 - t29, t3 + t30, -rho_h - t31),
            axial: -(T::from_f64(2.0) * (t0 * (-t2 + px + t29) + t5 * (t3 - py + t30)))
                - t6 * (rho_h + pz + t31),
        }
    }
    /// Contact pair: the peg's rim torus against the bore wall, angle along the rim circle (body). Gap g (m, negative = penetration), dg/dangle and d2g/dangle2 (m/rad, m/rad^2), gradient dg/d(px, py, pz, q0..q3), unit force direction on the peg, contact point (m) and its axial coordinate along the peg from the centre of mass (m).
    ///
    /// # Inputs
    /// - `x` = (`px`, `py`, `pz`, `q0`, `q1`, `q2`, `q3`)
    /// - `a` = (`angle`)
    /// - `p` = (`r`, `L`, `rho_p`, `R`, `rho_h`, `h_b`, `m`, `J_t`, `J_a`, `g`, `fa_x`, `fa_y`, `fa_z`, `ma_x`, `ma_y`, `ma_z`)
    ///
    /// # Outputs
    /// The fields of [`PairGeometry`]:
    /// - `gap`: scalar
    /// - `d1`: scalar
    /// - `d2`: scalar
    /// - `grad`: vector of 7
    /// - `normal`: vector of 3
    /// - `point`: vector of 3
    /// - `axial`: scalar
    ///
    /// # Cost
    /// 55 add/sub, 107 mul, 2 div, 0 sqrt, 2 transcendental, 0 branches; 46 `let`s.
    #[inline]
    pub fn rim_wall<T: Real>(
        x: &SVector<T, 7>,
        a: &SVector<T, 1>,
        p: &SVector<T, 16>,
    ) -> PairGeometry<T> {
        let px = x[0];
        let py = x[1];
        let pz = x[2];
        let q0 = x[3];
        let q1 = x[4];
        let q2 = x[5];
        let q3 = x[6];
        let angle = a[0];
        let r = p[0];
        let l = p[1];
        let rho_p = p[2];
        let r_2 = p[3];
        let t0 = q2 * q2;
        let t1 = q3 * q3;
        let t2 = q1 * q2;
        let t3 = q0 * q3;
        let t4 = q1 * q3;
        let t5 = q0 * q2;
        let t6 = t4 + t5;
        let t7 = t2 + t3;
        let t8 = q1 * q1;
        let t9 = q2 * q3;
        let t10 = q0 * q1;
        let (sin_angle, cos_angle) = angle.sin_cos();
        let t11 = r - rho_p;
        let t12 = T::from_f64(1.0) - T::from_f64(2.0) * (t0 + t8);
        let t13 = T::from_f64(0.5) * l - rho_p;
        let t14 = T::from_f64(2.0) * q0 * t13;
        let t15 = q1 * t13;
        let t16 = -q3 * t13;
        let t17 = T::from_f64(1.0) - T::from_f64(2.0) * (t0 + t1);
        let t18 = T::from_f64(1.0) - T::from_f64(2.0) * (t1 + t8);
        let t19 = T::from_f64(2.0) * t7 * cos_angle + t18 * sin_angle;
        let t20 = T::from_f64(2.0) * t7 * sin_angle - t18 * cos_angle;
        let t21 = t11 * t20;
        let t22 = t12 * t13;
        let t23 = q2 * t13;
        let t24 = q3 * sin_angle;
        let t25 = q3 * cos_angle;
        let t26 = t10 - t9;
        let t27 = t3 - t2;
        let t28 = T::from_f64(2.0) * t27 * sin_angle - t17 * cos_angle;
        let t29 = t17 * sin_angle + T::from_f64(2.0) * t27 * cos_angle;
        let t30 = t11 * t29;
        let t31 = T::from_f64(2.0)
            * (t11 * ((t9 + t10) * sin_angle - (t5 - t4) * cos_angle));
        let t32 = t11 * t28 - px + T::from_f64(2.0) * t6 * t13;
        let t33 = t11 * t19 + py + T::from_f64(2.0) * t26 * t13;
        let t34 = (-t32).hypot(t33);
        let t35 = T::from_f64(1.0) / t34;
        let t36 = t32 * t35;
        let t37 = t33 * t35;
        let t38 = T::from_f64(0.5) * (rho_p + r_2) + T::from_f64(0.5) * t34;
        let t39 = t36 * t38;
        let t40 = t37 * t38;
        let t41 = t11 * (t32 * t29 - t33 * t20);
        let t42 = q2 * cos_angle;
        let t43 = q1 * sin_angle;
        PairGeometry {
            gap: r_2 - rho_p - t34,
            d1: -t41 * t35,
            d2: t41 * t41 / (t34 * t34 * t34)
                - t35 * (-(t11 * (t32 * t28 + t33 * t19)) + t30 * t30 + t21 * t21),
            grad: SMatrix::<
                T,
                7,
                1,
            >::from_row_slice(
                &[
                    t36,
                    -t37,
                    T::from_f64(0.0),
                    -T::from_f64(2.0) * t35
                        * (t32 * (t24 * t11 + t23) + t33 * (t25 * t11 + t15)),
                    t35
                        * (T::from_f64(2.0) * t32 * (q2 * sin_angle * t11 + t16)
                            - t33
                                * (t14
                                    - t11 * (T::from_f64(4.0) * t43 - T::from_f64(2.0) * t42))),
                    -t35
                        * (t32
                            * (t14
                                - t11 * (T::from_f64(2.0) * t43 - T::from_f64(4.0) * t42))
                            + T::from_f64(2.0) * t33 * (t16 + q1 * cos_angle * t11)),
                    -t35
                        * (t32
                            * (t11
                                * (T::from_f64(4.0) * t25
                                    + T::from_f64(2.0) * q0 * sin_angle)
                                + T::from_f64(2.0) * t15)
                            - t33
                                * (T::from_f64(2.0) * t23
                                    - t11
                                        * (T::from_f64(2.0) * q0 * cos_angle
                                            - T::from_f64(4.0) * t24))),
                ],
            ),
            normal: Vector3::new(t36, -t37, T::from_f64(0.0)),
            point: Vector3::new(-t39, t40, t31 + pz - t22),
            axial: -(T::from_f64(2.0) * (t6 * (px + t39) - t26 * (py - t40)))
                - t12 * (t22 - t31),
        }
    }
    /// Contact pair: the peg's rim torus against the block's top face z = 0, angle along the rim circle. Gap g (m, negative = penetration), dg/dangle and d2g/dangle2 (m/rad, m/rad^2), gradient dg/d(px, py, pz, q0..q3), unit force direction on the peg, contact point (m) and its axial coordinate along the peg from the centre of mass (m).
    ///
    /// # Inputs
    /// - `x` = (`px`, `py`, `pz`, `q0`, `q1`, `q2`, `q3`)
    /// - `a` = (`angle`)
    /// - `p` = (`r`, `L`, `rho_p`, `R`, `rho_h`, `h_b`, `m`, `J_t`, `J_a`, `g`, `fa_x`, `fa_y`, `fa_z`, `ma_x`, `ma_y`, `ma_z`)
    ///
    /// # Outputs
    /// The fields of [`PairGeometry`]:
    /// - `gap`: scalar
    /// - `d1`: scalar
    /// - `d2`: scalar
    /// - `grad`: vector of 7
    /// - `normal`: vector of 3
    /// - `point`: vector of 3
    /// - `axial`: scalar
    ///
    /// # Cost
    /// 41 add/sub, 62 mul, 0 div, 0 sqrt, 1 transcendental, 0 branches; 25 `let`s.
    #[inline]
    pub fn rim_top<T: Real>(
        x: &SVector<T, 7>,
        a: &SVector<T, 1>,
        p: &SVector<T, 16>,
    ) -> PairGeometry<T> {
        let px = x[0];
        let py = x[1];
        let pz = x[2];
        let q0 = x[3];
        let q1 = x[4];
        let q2 = x[5];
        let q3 = x[6];
        let angle = a[0];
        let r = p[0];
        let l = p[1];
        let rho_p = p[2];
        let t0 = q2 * q2;
        let t1 = q3 * q3;
        let t2 = q1 * q2;
        let t3 = q0 * q3;
        let t4 = q1 * q3;
        let t5 = q0 * q2;
        let t6 = t4 + t5;
        let t7 = q1 * q1;
        let t8 = q2 * q3;
        let t9 = q0 * q1;
        let t10 = t8 + t9;
        let (sin_angle, cos_angle) = angle.sin_cos();
        let t11 = r - rho_p;
        let t12 = -T::from_f64(0.5) * rho_p;
        let t13 = T::from_f64(1.0) - T::from_f64(2.0) * (t0 + t7);
        let t14 = T::from_f64(0.5) * l - rho_p;
        let t15 = -T::from_f64(2.0) * t6 * t14;
        let t16 = t11
            * (T::from_f64(2.0) * (t2 + t3) * cos_angle
                + (T::from_f64(1.0) - T::from_f64(2.0) * (t1 + t7)) * sin_angle);
        let t17 = t13 * t14;
        let t18 = t9 - t8;
        let t19 = t5 - t4;
        let t20 = t11 * (t10 * sin_angle - t19 * cos_angle);
        let t21 = T::from_f64(2.0) * t18 * t14;
        let t22 = -t11
            * (T::from_f64(2.0) * (t3 - t2) * sin_angle
                - (T::from_f64(1.0) - T::from_f64(2.0) * (t0 + t1)) * cos_angle);
        PairGeometry {
            gap: -rho_p + T::from_f64(2.0) * t20 + pz - t17,
            d1: T::from_f64(2.0) * (t11 * (t19 * sin_angle + t10 * cos_angle)),
            d2: -T::from_f64(2.0) * t20,
            grad: SMatrix::<
                T,
                7,
                1,
            >::from_row_slice(
                &[
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(1.0),
                    T::from_f64(2.0) * (q1 * sin_angle - q2 * cos_angle) * t11,
                    T::from_f64(2.0) * (q3 * cos_angle + q0 * sin_angle) * t11
                        + T::from_f64(4.0) * q1 * t14,
                    T::from_f64(4.0) * q2 * t14
                        - T::from_f64(2.0) * (q0 * cos_angle - q3 * sin_angle) * t11,
                    T::from_f64(2.0) * (q2 * sin_angle + q1 * cos_angle) * t11,
                ],
            ),
            normal: Vector3::new(T::from_f64(0.0), T::from_f64(0.0), T::from_f64(1.0)),
            point: Vector3::new(
                t22 + px + t15,
                t16 + py + t21,
                t12 + t20 + T::from_f64(0.5) * (pz - t17),
            ),
            axial: T::from_f64(2.0) * (t6 * (t22 + t15) - t18 * (t16 + t21))
                + t13 * (t12 + t20 - T::from_f64(0.5) * (t17 + pz)),
        }
    }
    /// Contact pair: the peg's rim torus against the bore bottom z = -h_b, angle along the rim circle. Gap g (m, negative = penetration), dg/dangle and d2g/dangle2 (m/rad, m/rad^2), gradient dg/d(px, py, pz, q0..q3), unit force direction on the peg, contact point (m) and its axial coordinate along the peg from the centre of mass (m).
    ///
    /// # Inputs
    /// - `x` = (`px`, `py`, `pz`, `q0`, `q1`, `q2`, `q3`)
    /// - `a` = (`angle`)
    /// - `p` = (`r`, `L`, `rho_p`, `R`, `rho_h`, `h_b`, `m`, `J_t`, `J_a`, `g`, `fa_x`, `fa_y`, `fa_z`, `ma_x`, `ma_y`, `ma_z`)
    ///
    /// # Outputs
    /// The fields of [`PairGeometry`]:
    /// - `gap`: scalar
    /// - `d1`: scalar
    /// - `d2`: scalar
    /// - `grad`: vector of 7
    /// - `normal`: vector of 3
    /// - `point`: vector of 3
    /// - `axial`: scalar
    ///
    /// # Cost
    /// 43 add/sub, 62 mul, 0 div, 0 sqrt, 1 transcendental, 0 branches; 25 `let`s.
    #[inline]
    pub fn rim_bottom<T: Real>(
        x: &SVector<T, 7>,
        a: &SVector<T, 1>,
        p: &SVector<T, 16>,
    ) -> PairGeometry<T> {
        let px = x[0];
        let py = x[1];
        let pz = x[2];
        let q0 = x[3];
        let q1 = x[4];
        let q2 = x[5];
        let q3 = x[6];
        let angle = a[0];
        let r = p[0];
        let l = p[1];
        let rho_p = p[2];
        let h_b = p[5];
        let t0 = q2 * q2;
        let t1 = q3 * q3;
        let t2 = q1 * q2;
        let t3 = q0 * q3;
        let t4 = q1 * q3;
        let t5 = q0 * q2;
        let t6 = t4 + t5;
        let t7 = q1 * q1;
        let t8 = q2 * q3;
        let t9 = q0 * q1;
        let t10 = t8 + t9;
        let (sin_angle, cos_angle) = angle.sin_cos();
        let t11 = r - rho_p;
        let t12 = T::from_f64(1.0) - T::from_f64(2.0) * (t0 + t7);
        let t13 = T::from_f64(0.5) * l - rho_p;
        let t14 = -T::from_f64(2.0) * t6 * t13;
        let t15 = t11
            * (T::from_f64(2.0) * (t2 + t3) * cos_angle
                + (T::from_f64(1.0) - T::from_f64(2.0) * (t1 + t7)) * sin_angle);
        let t16 = t12 * t13;
        let t17 = t9 - t8;
        let t18 = t5 - t4;
        let t19 = t11 * (t10 * sin_angle - t18 * cos_angle);
        let t20 = T::from_f64(2.0) * t17 * t13;
        let t21 = -t11
            * (T::from_f64(2.0) * (t3 - t2) * sin_angle
                - (T::from_f64(1.0) - T::from_f64(2.0) * (t0 + t1)) * cos_angle);
        let t22 = -T::from_f64(0.5) * (rho_p + h_b);
        PairGeometry {
            gap: h_b - rho_p + T::from_f64(2.0) * t19 + pz - t16,
            d1: T::from_f64(2.0) * (t11 * (t18 * sin_angle + t10 * cos_angle)),
            d2: -T::from_f64(2.0) * t19,
            grad: SMatrix::<
                T,
                7,
                1,
            >::from_row_slice(
                &[
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(1.0),
                    T::from_f64(2.0) * (q1 * sin_angle - q2 * cos_angle) * t11,
                    T::from_f64(2.0) * (q3 * cos_angle + q0 * sin_angle) * t11
                        + T::from_f64(4.0) * q1 * t13,
                    T::from_f64(4.0) * q2 * t13
                        - T::from_f64(2.0) * (q0 * cos_angle - q3 * sin_angle) * t11,
                    T::from_f64(2.0) * (q2 * sin_angle + q1 * cos_angle) * t11,
                ],
            ),
            normal: Vector3::new(T::from_f64(0.0), T::from_f64(0.0), T::from_f64(1.0)),
            point: Vector3::new(
                t21 + px + t14,
                t15 + py + t20,
                t22 + t19 + T::from_f64(0.5) * (pz - t16),
            ),
            axial: T::from_f64(2.0) * (t6 * (t21 + t14) - t17 * (t15 + t20))
                + t12 * (t22 + t19 - T::from_f64(0.5) * (t16 + pz)),
        }
    }
    /// Contact pair: the peg's rim torus against the mouth-edge torus, angle along the rim circle (body), closest mouth-circle point in closed form. Gap g (m, negative = penetration), dg/dangle and d2g/dangle2 (m/rad, m/rad^2), gradient dg/d(px, py, pz, q0..q3), unit force direction on the peg, contact point (m) and its axial coordinate along the peg from the centre of mass (m).
    ///
    /// # Inputs
    /// - `x` = (`px`, `py`, `pz`, `q0`, `q1`, `q2`, `q3`)
    /// - `a` = (`angle`)
    /// - `p` = (`r`, `L`, `rho_p`, `R`, `rho_h`, `h_b`, `m`, `J_t`, `J_a`, `g`, `fa_x`, `fa_y`, `fa_z`, `ma_x`, `ma_y`, `ma_z`)
    ///
    /// # Outputs
    /// The fields of [`PairGeometry`]:
    /// - `gap`: scalar
    /// - `d1`: scalar
    /// - `d2`: scalar
    /// - `grad`: vector of 7
    /// - `normal`: vector of 3
    /// - `point`: vector of 3
    /// - `axial`: scalar
    ///
    /// # Cost
    /// 78 add/sub, 145 mul, 6 div, 0 sqrt, 3 transcendental, 0 branches; 64 `let`s.
    #[inline]
    pub fn rim_edge<T: Real>(
        x: &SVector<T, 7>,
        a: &SVector<T, 1>,
        p: &SVector<T, 16>,
    ) -> PairGeometry<T> {
        let px = x[0];
        let py = x[1];
        let pz = x[2];
        let q0 = x[3];
        let q1 = x[4];
        let q2 = x[5];
        let q3 = x[6];
        let angle = a[0];
        let r = p[0];
        let l = p[1];
        let rho_p = p[2];
        let r_2 = p[3];
        let rho_h = p[4];
        let t0 = q2 * q2;
        let t1 = q3 * q3;
        let t2 = q1 * q2;
        let t3 = q0 * q3;
        let t4 = q1 * q3;
        let t5 = q0 * q2;
        let t6 = t4 + t5;
        let t7 = t2 + t3;
        let t8 = q1 * q1;
        let t9 = q2 * q3;
        let t10 = q0 * q1;
        let t11 = t9 + t10;
        let (sin_angle, cos_angle) = angle.sin_cos();
        let t12 = r - rho_p;
        let t13 = T::from_f64(1.0) - T::from_f64(2.0) * (t0 + t8);
        let t14 = T::from_f64(0.5) * l - rho_p;
        let t15 = T::from_f64(2.0) * q0 * t14;
        let t16 = q1 * t14;
        let t17 = -q3 * t14;
        let t18 = T::from_f64(1.0) - T::from_f64(2.0) * (t0 + t1);
        let t19 = T::from_f64(1.0) - T::from_f64(2.0) * (t1 + t8);
        let t20 = T::from_f64(2.0) * t7 * cos_angle + t19 * sin_angle;
        let t21 = T::from_f64(2.0) * t7 * sin_angle - t19 * cos_angle;
        let t22 = t12 * t21;
        let t23 = q2 * t14;
        let t24 = q3 * sin_angle;
        let t25 = q3 * cos_angle;
        let t26 = t10 - t9;
        let t27 = t3 - t2;
        let t28 = t5 - t4;
        let t29 = T::from_f64(2.0) * t27 * sin_angle - t18 * cos_angle;
        let t30 = t18 * sin_angle + T::from_f64(2.0) * t27 * cos_angle;
        let t31 = t12 * t30;
        let t32 = t11 * sin_angle - t28 * cos_angle;
        let t33 = t12 * t29 - px + T::from_f64(2.0) * t6 * t14;
        let t34 = t12 * t20 + py + T::from_f64(2.0) * t26 * t14;
        let t35 = (-t33).hypot(t34);
        let t36 = t33 * t30 - t34 * t21;
        let t37 = q2 * cos_angle;
        let t38 = q1 * sin_angle;
        let t39 = q2 * sin_angle;
        let t40 = q1 * cos_angle;
        let t41 = q0 * sin_angle;
        let t42 = q0 * cos_angle;
        let t43 = t28 * sin_angle + t11 * cos_angle;
        let t44 = -t12 * t36;
        let t45 = -T::from_f64(2.0) * t43 * t12;
        let t46 = rho_h + r_2 - t35;
        let t47 = rho_h + T::from_f64(2.0) * t32 * t12 + pz - t13 * t14;
        let t48 = t12 * t47;
        let t49 = t47.hypot(t46);
        let t50 = T::from_f64(1.0) / t49;
        let t51 = t46 / t35;
        let t52 = t51 * t50;
        let t53 = t52 * t33;
        let t54 = -t52 * t34;
        let t55 = t47 * t50;
        let t56 = T::from_f64(0.5) * t49 - T::from_f64(0.5) * (rho_p - rho_h);
        let t57 = (r_2 + rho_h - t46 * t50 * t56) / t35;
        let t58 = t57 * t33;
        let t59 = t57 * t34;
        let t60 = -t55 * t56;
        let t61 = t12 * (t51 * t36 - T::from_f64(2.0) * t43 * t47);
        PairGeometry {
            gap: -rho_h - rho_p + t49,
            d1: -t61 * t50,
            d2: -(t61 * t61 / (t49 * t49 * t49))
                - t50
                    * (-(t44 * t44
                        * (t46 / (t35 * t35 * t35) + T::from_f64(1.0) / (t35 * t35)))
                        + T::from_f64(2.0) * t48 * t32 - t45 * t45
                        + t51
                            * (-(t12 * (t33 * t29 + t34 * t20)) + t31 * t31
                                + t22 * t22)),
            grad: SMatrix::<
                T,
                7,
                1,
            >::from_row_slice(
                &[
                    t53,
                    t54,
                    t55,
                    -T::from_f64(2.0) * t50
                        * (t51 * (t33 * (t24 * t12 + t23) + t34 * (t25 * t12 + t16))
                            - t48 * (t38 - t37)),
                    t50
                        * ((T::from_f64(2.0) * (t25 + t41) * t12
                            + T::from_f64(4.0) * t16) * t47
                            + t51
                                * (T::from_f64(2.0) * t33 * (t39 * t12 + t17)
                                    - t34
                                        * (t15
                                            - t12
                                                * (T::from_f64(4.0) * t38 - T::from_f64(2.0) * t37)))),
                    -t50
                        * (t51
                            * (t33
                                * (t15
                                    - t12 * (T::from_f64(2.0) * t38 - T::from_f64(4.0) * t37))
                                + T::from_f64(2.0) * t34 * (t17 + t40 * t12))
                            - (T::from_f64(4.0) * t23
                                - T::from_f64(2.0) * (t42 - t24) * t12) * t47),
                    -t50
                        * (t51
                            * (t33
                                * (t12 * (T::from_f64(4.0) * t25 + T::from_f64(2.0) * t41)
                                    + T::from_f64(2.0) * t16)
                                - t34
                                    * (T::from_f64(2.0) * t23
                                        - t12 * (T::from_f64(2.0) * t42 - T::from_f64(4.0) * t24)))
                            - T::from_f64(2.0) * t48 * (t39 + t40)),
                ],
            ),
            normal: Vector3::new(t53, t54, t55),
            point: Vector3::new(-t58, t59, -rho_h - t60),
            axial: -(T::from_f64(2.0) * (t6 * (t58 + px) - t26 * (py - t59)))
                - t13 * (rho_h + pz + t60),
        }
    }
    /// Newton-Euler right-hand side of y = (p, q, v, omega_body, work, dissipation) under the contact wrench w = (F, T about the centre of mass, hole frame; dissipation rate), the applied loads and gravity along -z. SI units.
    ///
    /// # Inputs
    /// - `y` = (`px`, `py`, `pz`, `q0`, `q1`, `q2`, `q3`, `vx`, `vy`, `vz`, `wx`, `wy`, `wz`, `work`, `dissipation`)
    /// - `w` = (`Fx`, `Fy`, `Fz`, `Tx`, `Ty`, `Tz`, `Sdot`)
    /// - `p` = (`r`, `L`, `rho_p`, `R`, `rho_h`, `h_b`, `m`, `J_t`, `J_a`, `g`, `fa_x`, `fa_y`, `fa_z`, `ma_x`, `ma_y`, `ma_z`)
    ///
    /// # Outputs
    /// - `ydot`: vector of 15
    ///
    /// # Cost
    /// 47 add/sub, 64 mul, 4 div, 0 sqrt, 0 transcendental, 0 branches; 23 `let`s.
    #[inline]
    pub fn rhs<T: Real>(
        y: &SVector<T, 15>,
        w: &SVector<T, 7>,
        p: &SVector<T, 16>,
    ) -> SVector<T, 15> {
        let q0 = y[3];
        let q1 = y[4];
        let q2 = y[5];
        let q3 = y[6];
        let vx = y[7];
        let vy = y[8];
        let vz = y[9];
        let wx = y[10];
        let wy = y[11];
        let wz = y[12];
        let fx = w[0];
        let fy = w[1];
        let fz = w[2];
        let tx = w[3];
        let ty = w[4];
        let tz = w[5];
        let sdot = w[6];
        let m = p[6];
        let j_t = p[7];
        let j_a = p[8];
        let g = p[9];
        let fa_x = p[10];
        let fa_y = p[11];
        let fa_z = p[12];
        let ma_x = p[13];
        let ma_y = p[14];
        let ma_z = p[15];
        let t0 = q2 * q2;
        let t1 = q3 * q3;
        let t2 = q1 * q2;
        let t3 = q0 * q3;
        let t4 = q1 * q3;
        let t5 = q0 * q2;
        let t6 = t4 + t5;
        let t7 = t2 + t3;
        let t8 = q1 * q1;
        let t9 = q2 * q3;
        let t10 = q0 * q1;
        let t11 = t9 + t10;
        let t12 = ma_x + tx;
        let t13 = ma_y + ty;
        let t14 = ma_z + tz;
        let t15 = T::from_f64(1.0) / m;
        let t16 = T::from_f64(1.0) - T::from_f64(2.0) * (t0 + t8);
        let t17 = T::from_f64(1.0) - T::from_f64(2.0) * (t0 + t1);
        let t18 = T::from_f64(1.0) - T::from_f64(2.0) * (t1 + t8);
        let t19 = t10 - t9;
        let t20 = t3 - t2;
        let t21 = t5 - t4;
        let t22 = wz * (j_t - j_a);
        SMatrix::<
            T,
            15,
            1,
        >::from_row_slice(
            &[
                vx,
                vy,
                vz,
                -T::from_f64(0.5) * (q1 * wx + q2 * wy + q3 * wz),
                T::from_f64(0.5) * (q0 * wx + q2 * wz - q3 * wy),
                T::from_f64(0.5) * (q0 * wy + q3 * wx - q1 * wz),
                T::from_f64(0.5) * (q0 * wz + q1 * wy - q2 * wx),
                (fa_x + fx) * t15,
                t15 * (fa_y + fy),
                t15 * (fa_z + fz) - g,
                (t22 * wy + T::from_f64(2.0) * (t7 * t13 - t21 * t14) + t17 * t12) / j_t,
                (-(t22 * wx) + T::from_f64(2.0) * (t11 * t14 - t20 * t12) + t18 * t13)
                    / j_t,
                (T::from_f64(2.0) * (t6 * t12 - t19 * t13) + t16 * t14) / j_a,
                fa_x * vx + fa_y * vy + fa_z * vz
                    + ma_x * (T::from_f64(2.0) * (t6 * wz - t20 * wy) + t17 * wx)
                    + ma_y * (T::from_f64(2.0) * (t7 * wx - t19 * wz) + t18 * wy)
                    + ma_z * (T::from_f64(2.0) * (t11 * wy - t21 * wx) + t16 * wz),
                sdot,
            ],
        )
    }
    /// The outputs of [`rhs_jacobian`].
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct RhsJacobianOut<T: Real> {
        /// D(ydot)/dy at a fixed wrench (15 x 15).
        pub dy: SMatrix<T, 15, 15>,
        /// D(ydot)/dw (15 x 7).
        pub dw: SMatrix<T, 15, 7>,
    }
    /// Exact partial derivatives of `rhs`: dy = d(ydot)/dy (15 x 15) at a fixed wrench and dw = d(ydot)/dw (15 x 7); the runtime adds dw times the wrench's own derivative in y.
    ///
    /// # Inputs
    /// - `y` = (`px`, `py`, `pz`, `q0`, `q1`, `q2`, `q3`, `vx`, `vy`, `vz`, `wx`, `wy`, `wz`, `work`, `dissipation`)
    /// - `w` = (`Fx`, `Fy`, `Fz`, `Tx`, `Ty`, `Tz`, `Sdot`)
    /// - `p` = (`r`, `L`, `rho_p`, `R`, `rho_h`, `h_b`, `m`, `J_t`, `J_a`, `g`, `fa_x`, `fa_y`, `fa_z`, `ma_x`, `ma_y`, `ma_z`)
    ///
    /// # Outputs
    /// The fields of [`RhsJacobianOut`]:
    /// - `dy`: 15×15 matrix
    /// - `dw`: 15×7 matrix
    ///
    /// # Cost
    /// 66 add/sub, 138 mul, 3 div, 0 sqrt, 0 transcendental, 0 branches; 60 `let`s.
    #[inline]
    pub fn rhs_jacobian<T: Real>(
        y: &SVector<T, 15>,
        w: &SVector<T, 7>,
        p: &SVector<T, 16>,
    ) -> RhsJacobianOut<T> {
        let q0 = y[3];
        let q1 = y[4];
        let q2 = y[5];
        let q3 = y[6];
        let wx = y[10];
        let wy = y[11];
        let wz = y[12];
        let tx = w[3];
        let ty = w[4];
        let tz = w[5];
        let m = p[6];
        let j_t = p[7];
        let j_a = p[8];
        let fa_x = p[10];
        let fa_y = p[11];
        let fa_z = p[12];
        let ma_x = p[13];
        let ma_y = p[14];
        let ma_z = p[15];
        let t0 = q2 * q2;
        let t1 = q3 * q3;
        let t2 = q1 * q2;
        let t3 = q0 * q3;
        let t4 = q1 * q3;
        let t5 = q0 * q2;
        let t6 = t4 + t5;
        let t7 = t2 + t3;
        let t8 = q1 * q1;
        let t9 = q2 * q3;
        let t10 = q0 * q1;
        let t11 = t9 + t10;
        let t12 = ma_x + tx;
        let t13 = ma_y + ty;
        let t14 = ma_z + tz;
        let t15 = q1 * wx;
        let t16 = q2 * wy;
        let t17 = q3 * wz;
        let t18 = q0 * wx;
        let t19 = q2 * wz;
        let t20 = q3 * wy;
        let t21 = q0 * wy;
        let t22 = q3 * wx;
        let t23 = q1 * wz;
        let t24 = q0 * wz;
        let t25 = q1 * wy;
        let t26 = q2 * wx;
        let t27 = T::from_f64(1.0) / m;
        let t28 = T::from_f64(1.0) / j_t;
        let t29 = T::from_f64(1.0) / j_a;
        let t30 = -T::from_f64(0.5) * wx;
        let t31 = -T::from_f64(0.5) * wy;
        let t32 = -T::from_f64(0.5) * wz;
        let t33 = -T::from_f64(0.5) * q1;
        let t34 = -T::from_f64(0.5) * q2;
        let t35 = -T::from_f64(0.5) * q3;
        let t36 = T::from_f64(0.5) * wx;
        let t37 = T::from_f64(0.5) * wz;
        let t38 = T::from_f64(0.5) * q0;
        let t39 = T::from_f64(0.5) * wy;
        let t40 = q3 * t13;
        let t41 = q2 * t14;
        let t42 = q2 * t13;
        let t43 = q3 * t14;
        let t44 = q2 * t12;
        let t45 = q1 * t13;
        let t46 = q0 * t14;
        let t47 = q3 * t12;
        let t48 = q0 * t13;
        let t49 = q1 * t14;
        let t50 = q1 * t12;
        let t51 = q0 * t12;
        let t52 = T::from_f64(1.0) - T::from_f64(2.0) * (t0 + t8);
        let t53 = T::from_f64(1.0) - T::from_f64(2.0) * (t0 + t1);
        let t54 = T::from_f64(1.0) - T::from_f64(2.0) * (t1 + t8);
        let t55 = t10 - t9;
        let t56 = t3 - t2;
        let t57 = t5 - t4;
        let t58 = t28 * (j_t - j_a);
        let t59 = t58 * wz;
        RhsJacobianOut {
            dy: SMatrix::<
                T,
                15,
                15,
            >::from_row_slice(
                &[
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(1.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(1.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(1.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    t30,
                    t31,
                    t32,
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    t33,
                    t34,
                    t35,
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    t36,
                    T::from_f64(0.0),
                    t37,
                    t31,
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    t38,
                    t35,
                    T::from_f64(0.5) * q2,
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    t39,
                    t32,
                    T::from_f64(0.0),
                    t36,
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.5) * q3,
                    t38,
                    t33,
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    t37,
                    t39,
                    t30,
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    t34,
                    T::from_f64(0.5) * q1,
                    t38,
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    -T::from_f64(2.0) * t28 * (t41 - t40),
                    T::from_f64(2.0) * t28 * (t42 + t43),
                    -t28 * (T::from_f64(2.0) * (t46 - t45) + T::from_f64(4.0) * t44),
                    -t28 * (T::from_f64(4.0) * t47 - T::from_f64(2.0) * (t48 + t49)),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    t59,
                    t58 * wy,
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(2.0) * t28 * (t49 - t47),
                    -t28 * (T::from_f64(4.0) * t45 - T::from_f64(2.0) * (t44 + t46)),
                    T::from_f64(2.0) * t28 * (t43 + t50),
                    -t28 * (T::from_f64(2.0) * (t51 - t41) + T::from_f64(4.0) * t40),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    -t59,
                    T::from_f64(0.0),
                    -t58 * wx,
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    -T::from_f64(2.0) * t29 * (t45 - t44),
                    -t29 * (T::from_f64(2.0) * (t48 - t47) + T::from_f64(4.0) * t49),
                    -t29 * (T::from_f64(4.0) * t41 - T::from_f64(2.0) * (t40 + t51)),
                    T::from_f64(2.0) * t29 * (t42 + t50),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(2.0)
                        * (ma_x * (t19 - t20) - ma_y * (t23 - t22) + ma_z * (t25 - t26)),
                    T::from_f64(2.0) * ma_x * (t16 + t17)
                        - ma_y
                            * (T::from_f64(2.0) * (t24 - t26) + T::from_f64(4.0) * t25)
                        - ma_z
                            * (T::from_f64(4.0) * t23 - T::from_f64(2.0) * (t22 + t21)),
                    -(ma_x * (T::from_f64(4.0) * t26 - T::from_f64(2.0) * (t25 + t24)))
                        + T::from_f64(2.0) * ma_y * (t17 + t15)
                        - ma_z
                            * (T::from_f64(2.0) * (t18 - t20) + T::from_f64(4.0) * t19),
                    -(ma_x * (T::from_f64(2.0) * (t21 - t23) + T::from_f64(4.0) * t22))
                        - ma_y
                            * (T::from_f64(4.0) * t20 - T::from_f64(2.0) * (t19 + t18))
                        + T::from_f64(2.0) * ma_z * (t16 + t15),
                    fa_x,
                    fa_y,
                    fa_z,
                    T::from_f64(2.0) * (ma_y * t7 - ma_z * t57) + ma_x * t53,
                    ma_y * t54 - T::from_f64(2.0) * (ma_x * t56 - ma_z * t11),
                    T::from_f64(2.0) * (ma_x * t6 - ma_y * t55) + ma_z * t52,
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                ],
            ),
            dw: SMatrix::<
                T,
                15,
                7,
            >::from_row_slice(
                &[
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    t27,
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    t27,
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    t27,
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    t53 * t28,
                    T::from_f64(2.0) * t7 * t28,
                    -T::from_f64(2.0) * t57 * t28,
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    -T::from_f64(2.0) * t56 * t28,
                    t54 * t28,
                    T::from_f64(2.0) * t11 * t28,
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(2.0) * t6 * t29,
                    -T::from_f64(2.0) * t55 * t29,
                    t52 * t29,
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(0.0),
                    T::from_f64(1.0),
                ],
            ),
        }
    }
    /// The outputs of [`energy`].
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct EnergyOut<T: Real> {
        /// Kinetic energy of translation and rotation, J.
        pub kinetic: T,
        /// Gravitational potential m g p_z, J.
        pub gravity: T,
    }
    /// Kinetic energy (J) and gravitational potential m g p_z (J).
    ///
    /// # Inputs
    /// - `y` = (`px`, `py`, `pz`, `q0`, `q1`, `q2`, `q3`, `vx`, `vy`, `vz`, `wx`, `wy`, `wz`, `work`, `dissipation`)
    /// - `p` = (`r`, `L`, `rho_p`, `R`, `rho_h`, `h_b`, `m`, `J_t`, `J_a`, `g`, `fa_x`, `fa_y`, `fa_z`, `ma_x`, `ma_y`, `ma_z`)
    ///
    /// # Outputs
    /// The fields of [`EnergyOut`]:
    /// - `kinetic`: scalar
    /// - `gravity`: scalar
    ///
    /// # Cost
    /// 5 add/sub, 12 mul, 0 div, 0 sqrt, 0 transcendental, 0 branches; 0 `let`s.
    #[inline]
    pub fn energy<T: Real>(y: &SVector<T, 15>, p: &SVector<T, 16>) -> EnergyOut<T> {
        let pz = y[2];
        let vx = y[7];
        let vy = y[8];
        let vz = y[9];
        let wx = y[10];
        let wy = y[11];
        let wz = y[12];
        let m = p[6];
        let j_t = p[7];
        let j_a = p[8];
        let g = p[9];
        EnergyOut {
            kinetic: T::from_f64(0.5)
                * (m * (vx * vx + vy * vy + vz * vz) + j_t * (wx * wx + wy * wy)
                    + j_a * (wz * wz)),
            gravity: pz * m * g,
        }
    }
}
