// @generated readable copy of `pegdyn::generated::compliant_peg_3d` — do not edit.
// Regenerate: PEGDYN_BLESS=1 cargo test --test generated_snapshot

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
    /// Contact pair: the mouth-edge torus against the peg's side, angle along the mouth-edge circle. Gap g (m, negative = penetration), dg/dangle and d2g/dangle2 (m/rad, m/rad^2), gradient dg/d(px, py, pz, q0..q3), unit force direction on the peg, contact point (m) and its axial coordinate along the peg from the centre of mass (m).
    ///
    /// # Inputs
    /// - `x` = (`px`, `py`, `pz`, `q0`, `q1`, `q2`, `q3`)
    /// - `a` = (`angle`)
    /// - `p` = (`r`, `L`, `rho_p`, `R`, `rho_h`, `h_b`, `m`, `J_t`, `J_a`, `g`, `fa_x`, `fa_y`, `fa_z`, `ma_x`, `ma_y`, `ma_z`)
    ///
    /// # Outputs
    /// - `gap`: scalar
    /// - `d1`: scalar
    /// - `d2`: scalar
    /// - `grad`: vector of 7
    /// - `normal`: vector of 3
    /// - `point`: vector of 3
    /// - `axial`: scalar
    ///
    /// # Cost
    /// 83 add/sub, 146 mul, 2 div, 0 sqrt, 3 transcendental, 0 branches; 59 `let`s.
    #[inline]
    pub fn edge_side<T: Real>(
        x: &SVector<T, 7>,
        a: &SVector<T, 1>,
        p: &SVector<T, 16>,
    ) -> (T, T, T, SVector<T, 7>, SVector<T, 3>, SVector<T, 3>, T) {
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
        let t0 = q2 * q2;
        let t1 = q1 * q3;
        let t2 = q0 * q2;
        let t3 = t1 + t2;
        let t4 = q1 * q1;
        let t5 = q2 * q3;
        let t6 = q0 * q1;
        let (sin_angle, cos_angle) = angle.sin_cos();
        let t7 = r_2 + rho_h;
        let t8 = cos_angle * t7;
        let t9 = sin_angle * t7;
        let t10 = -rho_h;
        let t11 = -px;
        let t12 = t8 + t11;
        let t13 = -py;
        let t14 = t9 + t13;
        let t15 = -pz;
        let t16 = t10 + t15;
        let t17 = -r;
        let t18 = T::from_f64(2.0) * (-t0 - t4) + T::from_f64(1.0);
        let t19 = t3 * sin_angle;
        let t20 = T::from_f64(2.0) * (t0 + t4) - T::from_f64(1.0);
        let t21 = q2 * t12 - q1 * t14;
        let t22 = T::from_f64(2.0) * (q3 * t12 - q0 * t14) - T::from_f64(4.0) * q1 * t16;
        let t23 = T::from_f64(2.0) * (q0 * t12 + q3 * t14) - T::from_f64(4.0) * q2 * t16;
        let t24 = q1 * t12 + q2 * t14;
        let t25 = t5 - t6;
        let t26 = T::from_f64(2.0) * (t3 * t12 + t25 * t14) + t18 * t16;
        let t27 = px + T::from_f64(2.0) * t3 * t26 - t8;
        let t28 = py + T::from_f64(2.0) * t25 * t26 - t9;
        let t29 = rho_h + pz + t18 * t26;
        let t30 = t27.hypot(t28);
        let t31 = t29.hypot(t30);
        let t32 = T::from_f64(1.0) / t31;
        let t33 = t32 * (T::from_f64(0.5) * (rho_h + t17) + T::from_f64(0.5) * t31);
        let t34 = t33 * t27;
        let t35 = t33 * t28;
        let t36 = t33 * t29;
        let t37 = t25 * cos_angle;
        let t38 = -t19 + t37;
        let t39 = sin_angle + T::from_f64(4.0) * t3 * t38;
        let t40 = t7 * t39;
        let t41 = -cos_angle + T::from_f64(4.0) * t25 * t38;
        let t42 = t7 * t41;
        let t43 = t18 * t29;
        let t44 = t7 * (t27 * t39 + t28 * t41 + T::from_f64(2.0) * t43 * t38);
        let t45 = -(t3 * cos_angle) - t25 * sin_angle;
        let t46 = T::from_f64(2.0) * (t19 - t37) * t7;
        let t47 = -t2 - t1;
        let t48 = t25 * t28;
        let t49 = T::from_f64(2.0) * t43;
        let t50 = t6 - t5;
        let t51 = t3 * t27;
        let t52 = q2 * t26;
        let t53 = T::from_f64(2.0) * t52;
        let t54 = q1 * t26;
        let t55 = q3 * t26;
        let t56 = q0 * t26;
        let gap = t10 + t17 + t31;
        let d1 = t44 * t32;
        let d2 = -(t44 * t44 / (t31 * t31 * t31))
            + t32
                * (t7
                    * (t27 * (cos_angle + T::from_f64(4.0) * t3 * t45)
                        + t28 * (sin_angle + T::from_f64(4.0) * t25 * t45)
                        + T::from_f64(2.0) * t43 * t45) + t40 * t40 + t42 * t42
                    + t18 * t18 * (t46 * t46));
        let grad = SMatrix::<
            T,
            7,
            1,
        >::from_row_slice(
            &[
                t32
                    * (t47 * (T::from_f64(4.0) * t48 + t49)
                        + t27 * (T::from_f64(1.0) + T::from_f64(4.0) * t3 * t47)),
                t32
                    * (t50 * (T::from_f64(4.0) * t51 + t49)
                        + t28 * (T::from_f64(1.0) + T::from_f64(4.0) * t25 * t50)),
                t32
                    * (T::from_f64(2.0) * (t51 + t48) * t20
                        + t29 * (T::from_f64(1.0) + t18 * t20)),
                t32
                    * (t27 * (t53 + T::from_f64(4.0) * t3 * t21)
                        + t28
                            * (-(T::from_f64(2.0) * t54) + T::from_f64(4.0) * t25 * t21)
                        + T::from_f64(2.0) * t43 * t21),
                t32
                    * (T::from_f64(2.0)
                        * (t27 * (t55 + t3 * t22) + t28 * (-t56 + t25 * t22))
                        + t29 * (-(T::from_f64(4.0) * t54) + t18 * t22)),
                t32
                    * (T::from_f64(2.0)
                        * (t27 * (t56 + t3 * t23) + t28 * (t55 + t25 * t23))
                        + t29 * (-(T::from_f64(4.0) * t52) + t18 * t23)),
                t32
                    * (t27 * (T::from_f64(2.0) * t54 + T::from_f64(4.0) * t3 * t24)
                        + t28 * (t53 + T::from_f64(4.0) * t25 * t24)
                        + T::from_f64(2.0) * t43 * t24),
            ],
        );
        let normal = Vector3::new(t27 * t32, t28 * t32, t29 * t32);
        let point = Vector3::new(t8 + t34, t9 + t35, t10 + t36);
        let axial = T::from_f64(2.0) * (t3 * (t8 + t11 + t34) + t25 * (t9 + t13 + t35))
            + t18 * (t10 + t15 + t36);
        (gap, d1, d2, grad, normal, point, axial)
    }
    /// Contact pair: the peg's rim torus against the bore wall, angle along the rim circle (body). Gap g (m, negative = penetration), dg/dangle and d2g/dangle2 (m/rad, m/rad^2), gradient dg/d(px, py, pz, q0..q3), unit force direction on the peg, contact point (m) and its axial coordinate along the peg from the centre of mass (m).
    ///
    /// # Inputs
    /// - `x` = (`px`, `py`, `pz`, `q0`, `q1`, `q2`, `q3`)
    /// - `a` = (`angle`)
    /// - `p` = (`r`, `L`, `rho_p`, `R`, `rho_h`, `h_b`, `m`, `J_t`, `J_a`, `g`, `fa_x`, `fa_y`, `fa_z`, `ma_x`, `ma_y`, `ma_z`)
    ///
    /// # Outputs
    /// - `gap`: scalar
    /// - `d1`: scalar
    /// - `d2`: scalar
    /// - `grad`: vector of 7
    /// - `normal`: vector of 3
    /// - `point`: vector of 3
    /// - `axial`: scalar
    ///
    /// # Cost
    /// 63 add/sub, 118 mul, 2 div, 0 sqrt, 2 transcendental, 0 branches; 57 `let`s.
    #[inline]
    pub fn rim_wall<T: Real>(
        x: &SVector<T, 7>,
        a: &SVector<T, 1>,
        p: &SVector<T, 16>,
    ) -> (T, T, T, SVector<T, 7>, SVector<T, 3>, SVector<T, 3>, T) {
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
        let t0 = q1 * q2;
        let t1 = q0 * q3;
        let t2 = q1 * q3;
        let t3 = q0 * q2;
        let t4 = t2 + t3;
        let t5 = t0 + t1;
        let t6 = q2 * q3;
        let t7 = q0 * q1;
        let (sin_angle, cos_angle) = angle.sin_cos();
        let t8 = -px;
        let t9 = -py;
        let t10 = -rho_p;
        let t11 = r + t10;
        let t12 = rho_p - T::from_f64(0.5) * l;
        let t13 = q2 * t12;
        let t14 = q1 * t12;
        let t15 = q3 * t12;
        let t16 = q0 * t12;
        let t17 = -(q2 * q2);
        let t18 = -(q1 * q1);
        let t19 = T::from_f64(2.0) * (t17 + t18) + T::from_f64(1.0);
        let t20 = t6 - t7;
        let t21 = -(q3 * q3);
        let t22 = T::from_f64(2.0) * (t17 + t21) + T::from_f64(1.0);
        let t23 = T::from_f64(2.0) * (t21 + t18) + T::from_f64(1.0);
        let t24 = t19 * t12;
        let t25 = t0 - t1;
        let t26 = q3 * cos_angle;
        let t27 = T::from_f64(2.0) * ((t2 - t3) * cos_angle + (t6 + t7) * sin_angle)
            * t11;
        let t28 = cos_angle * t22;
        let t29 = t25 * sin_angle;
        let t30 = t4 * t12;
        let t31 = t11 * (t28 + T::from_f64(2.0) * t29) + px + T::from_f64(2.0) * t30;
        let t32 = t5 * cos_angle;
        let t33 = sin_angle * t23;
        let t34 = t20 * t12;
        let t35 = t11 * (T::from_f64(2.0) * t32 + t33) + py + T::from_f64(2.0) * t34;
        let t36 = t31.hypot(t35);
        let t37 = -t28 - T::from_f64(2.0) * t29;
        let t38 = T::from_f64(1.0) / t36;
        let t39 = (t11 * t37 + t8 - T::from_f64(2.0) * t30) * t38;
        let t40 = -(T::from_f64(2.0) * t32) - t33;
        let t41 = t38 * (t11 * t40 + t9 - T::from_f64(2.0) * t34);
        let t42 = T::from_f64(0.5) * (t10 - r_2) - T::from_f64(0.5) * t36;
        let t43 = t39 * t42;
        let t44 = t41 * t42;
        let t45 = sin_angle * t22;
        let t46 = t25 * cos_angle;
        let t47 = t5 * sin_angle;
        let t48 = cos_angle * t23;
        let t49 = t11
            * (t31 * (-t45 + T::from_f64(2.0) * t46)
                + t35 * (-(T::from_f64(2.0) * t47) + t48));
        let t50 = t11 * (t45 - T::from_f64(2.0) * t46);
        let t51 = t11 * (T::from_f64(2.0) * t47 - t48);
        let t52 = q3 * sin_angle;
        let t53 = q2 * cos_angle;
        let t54 = q1 * sin_angle;
        let gap = r_2 + t10 - t36;
        let d1 = -t49 * t38;
        let d2 = t49 * t49 / (t36 * t36 * t36)
            - t38 * (t11 * (t31 * t37 + t35 * t40) + t50 * t50 + t51 * t51);
        let grad = SMatrix::<
            T,
            7,
            1,
        >::from_row_slice(
            &[
                -t31 * t38,
                -t35 * t38,
                T::from_f64(0.0),
                -T::from_f64(2.0) * t38
                    * (t31 * (-(t52 * t11) + t13) + t35 * (t26 * t11 - t14)),
                -t38
                    * (T::from_f64(2.0) * t31 * (q2 * sin_angle * t11 + t15)
                        + t35
                            * (t11 * (T::from_f64(2.0) * t53 - T::from_f64(4.0) * t54)
                                - T::from_f64(2.0) * t16)),
                -t38
                    * (t31
                        * (t11 * (-(T::from_f64(4.0) * t53) + T::from_f64(2.0) * t54)
                            + T::from_f64(2.0) * t16)
                        + T::from_f64(2.0) * t35 * (t15 + q1 * cos_angle * t11)),
                -t38
                    * (t31
                        * (t11
                            * (-(T::from_f64(4.0) * t26)
                                - T::from_f64(2.0) * q0 * sin_angle)
                            + T::from_f64(2.0) * t14)
                        + t35
                            * (t11
                                * (T::from_f64(2.0) * q0 * cos_angle
                                    - T::from_f64(4.0) * t52) + T::from_f64(2.0) * t13)),
            ],
        );
        let normal = Vector3::new(t39, t41, T::from_f64(0.0));
        let point = Vector3::new(t43, t44, t27 + pz + t24);
        let axial = T::from_f64(2.0) * (t4 * (t8 + t43) + t20 * (t9 + t44))
            + t19 * (t27 + t24);
        (gap, d1, d2, grad, normal, point, axial)
    }
    /// Contact pair: the peg's rim torus against the block's top face z = 0, angle along the rim circle. Gap g (m, negative = penetration), dg/dangle and d2g/dangle2 (m/rad, m/rad^2), gradient dg/d(px, py, pz, q0..q3), unit force direction on the peg, contact point (m) and its axial coordinate along the peg from the centre of mass (m).
    ///
    /// # Inputs
    /// - `x` = (`px`, `py`, `pz`, `q0`, `q1`, `q2`, `q3`)
    /// - `a` = (`angle`)
    /// - `p` = (`r`, `L`, `rho_p`, `R`, `rho_h`, `h_b`, `m`, `J_t`, `J_a`, `g`, `fa_x`, `fa_y`, `fa_z`, `ma_x`, `ma_y`, `ma_z`)
    ///
    /// # Outputs
    /// - `gap`: scalar
    /// - `d1`: scalar
    /// - `d2`: scalar
    /// - `grad`: vector of 7
    /// - `normal`: vector of 3
    /// - `point`: vector of 3
    /// - `axial`: scalar
    ///
    /// # Cost
    /// 42 add/sub, 63 mul, 0 div, 0 sqrt, 1 transcendental, 0 branches; 28 `let`s.
    #[inline]
    pub fn rim_top<T: Real>(
        x: &SVector<T, 7>,
        a: &SVector<T, 1>,
        p: &SVector<T, 16>,
    ) -> (T, T, T, SVector<T, 7>, SVector<T, 3>, SVector<T, 3>, T) {
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
        let t0 = q1 * q2;
        let t1 = q0 * q3;
        let t2 = q1 * q3;
        let t3 = q0 * q2;
        let t4 = t2 + t3;
        let t5 = q2 * q3;
        let t6 = q0 * q1;
        let t7 = t5 + t6;
        let (sin_angle, cos_angle) = angle.sin_cos();
        let t8 = -rho_p;
        let t9 = r + t8;
        let t10 = rho_p - T::from_f64(0.5) * l;
        let t11 = -T::from_f64(0.5) * rho_p;
        let t12 = -(q2 * q2);
        let t13 = -(q1 * q1);
        let t14 = T::from_f64(2.0) * (t12 + t13) + T::from_f64(1.0);
        let t15 = t5 - t6;
        let t16 = -(q3 * q3);
        let t17 = t14 * t10;
        let t18 = t7 * sin_angle;
        let t19 = T::from_f64(2.0) * t4 * t10;
        let t20 = t9
            * (T::from_f64(2.0) * (t0 + t1) * cos_angle
                + (T::from_f64(2.0) * (t16 + t13) + T::from_f64(1.0)) * sin_angle);
        let t21 = t2 - t3;
        let t22 = t21 * cos_angle;
        let t23 = t9 * (t22 + t18);
        let t24 = t9
            * ((T::from_f64(2.0) * (t12 + t16) + T::from_f64(1.0)) * cos_angle
                + T::from_f64(2.0) * (t0 - t1) * sin_angle);
        let t25 = T::from_f64(2.0) * t15 * t10;
        let gap = t8 + T::from_f64(2.0) * t23 + pz + t17;
        let d1 = T::from_f64(2.0) * (-(t21 * sin_angle) + t7 * cos_angle) * t9;
        let d2 = T::from_f64(2.0) * (-t22 - t18) * t9;
        let grad = SMatrix::<
            T,
            7,
            1,
        >::from_row_slice(
            &[
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(1.0),
                T::from_f64(2.0) * (q1 * sin_angle - q2 * cos_angle) * t9,
                T::from_f64(2.0) * (q3 * cos_angle + q0 * sin_angle) * t9
                    - T::from_f64(4.0) * q1 * t10,
                T::from_f64(2.0) * (-(q0 * cos_angle) + q3 * sin_angle) * t9
                    - T::from_f64(4.0) * q2 * t10,
                T::from_f64(2.0) * (q2 * sin_angle + q1 * cos_angle) * t9,
            ],
        );
        let normal = Vector3::new(T::from_f64(0.0), T::from_f64(0.0), T::from_f64(1.0));
        let point = Vector3::new(
            t24 + px + t19,
            t20 + py + t25,
            t11 + t23 + T::from_f64(0.5) * (pz + t17),
        );
        let axial = T::from_f64(2.0) * (t4 * (t24 + t19) + t15 * (t20 + t25))
            + t14 * (t11 + t23 + T::from_f64(0.5) * (t17 - pz));
        (gap, d1, d2, grad, normal, point, axial)
    }
    /// Contact pair: the peg's rim torus against the bore bottom z = -h_b, angle along the rim circle. Gap g (m, negative = penetration), dg/dangle and d2g/dangle2 (m/rad, m/rad^2), gradient dg/d(px, py, pz, q0..q3), unit force direction on the peg, contact point (m) and its axial coordinate along the peg from the centre of mass (m).
    ///
    /// # Inputs
    /// - `x` = (`px`, `py`, `pz`, `q0`, `q1`, `q2`, `q3`)
    /// - `a` = (`angle`)
    /// - `p` = (`r`, `L`, `rho_p`, `R`, `rho_h`, `h_b`, `m`, `J_t`, `J_a`, `g`, `fa_x`, `fa_y`, `fa_z`, `ma_x`, `ma_y`, `ma_z`)
    ///
    /// # Outputs
    /// - `gap`: scalar
    /// - `d1`: scalar
    /// - `d2`: scalar
    /// - `grad`: vector of 7
    /// - `normal`: vector of 3
    /// - `point`: vector of 3
    /// - `axial`: scalar
    ///
    /// # Cost
    /// 44 add/sub, 63 mul, 0 div, 0 sqrt, 1 transcendental, 0 branches; 28 `let`s.
    #[inline]
    pub fn rim_bottom<T: Real>(
        x: &SVector<T, 7>,
        a: &SVector<T, 1>,
        p: &SVector<T, 16>,
    ) -> (T, T, T, SVector<T, 7>, SVector<T, 3>, SVector<T, 3>, T) {
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
        let t0 = q1 * q2;
        let t1 = q0 * q3;
        let t2 = q1 * q3;
        let t3 = q0 * q2;
        let t4 = t2 + t3;
        let t5 = q2 * q3;
        let t6 = q0 * q1;
        let t7 = t5 + t6;
        let (sin_angle, cos_angle) = angle.sin_cos();
        let t8 = -rho_p;
        let t9 = r + t8;
        let t10 = rho_p - T::from_f64(0.5) * l;
        let t11 = -(q2 * q2);
        let t12 = -(q1 * q1);
        let t13 = T::from_f64(2.0) * (t11 + t12) + T::from_f64(1.0);
        let t14 = t5 - t6;
        let t15 = -(q3 * q3);
        let t16 = t13 * t10;
        let t17 = t7 * sin_angle;
        let t18 = T::from_f64(2.0) * t4 * t10;
        let t19 = t9
            * (T::from_f64(2.0) * (t0 + t1) * cos_angle
                + (T::from_f64(2.0) * (t15 + t12) + T::from_f64(1.0)) * sin_angle);
        let t20 = t2 - t3;
        let t21 = t20 * cos_angle;
        let t22 = t9 * (t21 + t17);
        let t23 = t9
            * ((T::from_f64(2.0) * (t11 + t15) + T::from_f64(1.0)) * cos_angle
                + T::from_f64(2.0) * (t0 - t1) * sin_angle);
        let t24 = T::from_f64(2.0) * t14 * t10;
        let t25 = T::from_f64(0.5) * (t8 - h_b);
        let gap = h_b + t8 + T::from_f64(2.0) * t22 + pz + t16;
        let d1 = T::from_f64(2.0) * (-(t20 * sin_angle) + t7 * cos_angle) * t9;
        let d2 = T::from_f64(2.0) * (-t21 - t17) * t9;
        let grad = SMatrix::<
            T,
            7,
            1,
        >::from_row_slice(
            &[
                T::from_f64(0.0),
                T::from_f64(0.0),
                T::from_f64(1.0),
                T::from_f64(2.0) * (q1 * sin_angle - q2 * cos_angle) * t9,
                T::from_f64(2.0) * (q3 * cos_angle + q0 * sin_angle) * t9
                    - T::from_f64(4.0) * q1 * t10,
                T::from_f64(2.0) * (-(q0 * cos_angle) + q3 * sin_angle) * t9
                    - T::from_f64(4.0) * q2 * t10,
                T::from_f64(2.0) * (q2 * sin_angle + q1 * cos_angle) * t9,
            ],
        );
        let normal = Vector3::new(T::from_f64(0.0), T::from_f64(0.0), T::from_f64(1.0));
        let point = Vector3::new(
            t23 + px + t18,
            t19 + py + t24,
            t25 + t22 + T::from_f64(0.5) * (pz + t16),
        );
        let axial = T::from_f64(2.0) * (t4 * (t23 + t18) + t14 * (t19 + t24))
            + t13 * (t25 + t22 + T::from_f64(0.5) * (t16 - pz));
        (gap, d1, d2, grad, normal, point, axial)
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
    /// 48 add/sub, 65 mul, 4 div, 0 sqrt, 0 transcendental, 0 branches; 22 `let`s.
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
        let t0 = q1 * q2;
        let t1 = q0 * q3;
        let t2 = q1 * q3;
        let t3 = q0 * q2;
        let t4 = t2 + t3;
        let t5 = t0 + t1;
        let t6 = q2 * q3;
        let t7 = q0 * q1;
        let t8 = t6 + t7;
        let t9 = ma_x + tx;
        let t10 = ma_y + ty;
        let t11 = ma_z + tz;
        let t12 = T::from_f64(1.0) / m;
        let t13 = -(q2 * q2);
        let t14 = -(q1 * q1);
        let t15 = T::from_f64(2.0) * (t13 + t14) + T::from_f64(1.0);
        let t16 = t6 - t7;
        let t17 = -(q3 * q3);
        let t18 = T::from_f64(2.0) * (t13 + t17) + T::from_f64(1.0);
        let t19 = T::from_f64(2.0) * (t17 + t14) + T::from_f64(1.0);
        let t20 = t0 - t1;
        let t21 = t2 - t3;
        SMatrix::<
            T,
            15,
            1,
        >::from_row_slice(
            &[
                vx,
                vy,
                vz,
                T::from_f64(0.5) * (-(q1 * wx) - q2 * wy - q3 * wz),
                T::from_f64(0.5) * (q0 * wx + q2 * wz - q3 * wy),
                T::from_f64(0.5) * (q0 * wy + q3 * wx - q1 * wz),
                T::from_f64(0.5) * (q0 * wz + q1 * wy - q2 * wx),
                (fa_x + fx) * t12,
                t12 * (fa_y + fy),
                -g + t12 * (fa_z + fz),
                (wz * (j_t - j_a) * wy + T::from_f64(2.0) * (t5 * t10 + t21 * t11)
                    + t18 * t9) / j_t,
                (wz * (j_a - j_t) * wx + T::from_f64(2.0) * (t20 * t9 + t8 * t11)
                    + t19 * t10) / j_t,
                (T::from_f64(2.0) * (t4 * t9 + t16 * t10) + t15 * t11) / j_a,
                fa_x * vx + fa_y * vy + fa_z * vz
                    + ma_x * (T::from_f64(2.0) * (t20 * wy + t4 * wz) + t18 * wx)
                    + ma_y * (T::from_f64(2.0) * (t5 * wx + t16 * wz) + t19 * wy)
                    + ma_z * (T::from_f64(2.0) * (t21 * wx + t8 * wy) + t15 * wz),
                sdot,
            ],
        )
    }
    /// Kinetic energy (J) and gravitational potential m g p_z (J).
    ///
    /// # Inputs
    /// - `y` = (`px`, `py`, `pz`, `q0`, `q1`, `q2`, `q3`, `vx`, `vy`, `vz`, `wx`, `wy`, `wz`, `work`, `dissipation`)
    /// - `p` = (`r`, `L`, `rho_p`, `R`, `rho_h`, `h_b`, `m`, `J_t`, `J_a`, `g`, `fa_x`, `fa_y`, `fa_z`, `ma_x`, `ma_y`, `ma_z`)
    ///
    /// # Outputs
    /// - `kinetic`: scalar
    /// - `gravity`: scalar
    ///
    /// # Cost
    /// 5 add/sub, 12 mul, 0 div, 0 sqrt, 0 transcendental, 0 branches; 0 `let`s.
    #[inline]
    pub fn energy<T: Real>(y: &SVector<T, 15>, p: &SVector<T, 16>) -> (T, T) {
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
        let kinetic = T::from_f64(0.5)
            * (m * (vx * vx + vy * vy + vz * vz) + j_t * (wx * wx + wy * wy)
                + j_a * (wz * wz));
        let gravity = pz * m * g;
        (kinetic, gravity)
    }
}
