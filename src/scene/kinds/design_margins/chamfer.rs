//! The mouth's capture rule: which initial lateral and angular errors the
//! rounded chamfer guides into the bore (derivation in `docs/insertion.md`,
//! "Chamfer acceptance with a compliance centre").
//!
//! The robot positions the compliance centre, `L_c` above the tip on the
//! peg's axis, with a lateral error `e_c` (a horizontal vector) and tilts
//! the axis by `θ` towards the azimuth `ψ`. The tip lies `L_c` below the
//! centre along the axis `a = (sin θ cos ψ, sin θ sin ψ, cos θ)`, so its
//! lateral error is
//!
//! ```text
//! e_t = e_c − L_c sin θ (cos ψ, sin ψ)                      (m)
//! ```
//!
//! The rim is the torus swept by a sphere of radius `ρ_p` whose centre runs
//! on the circle `C(φ) = t + ρ_p a + (r − ρ_p)(cos φ e₁ + sin φ e₂)` (`t` the
//! tip, `e₁ = (cos θ cos ψ, cos θ sin ψ, −sin θ)`, `e₂ = (−sin ψ, cos ψ, 0)`);
//! the mouth is the top face `z = 0` outside the radius `R + ρ_h` and,
//! inside it, the round: points at `ρ_h` from the circle of radius `R + ρ_h`
//! at `z = −ρ_h`. A sphere centred at `C` (radius `ρ_C = |C_xy|` from the
//! hole's axis) touches, in the vertical plane through the axis and `C`,
//!
//! ```text
//! the top face   when C_z = ρ_p                                 (ρ_C ≥ R + ρ_h)
//! the round      when C_z = −ρ_h + √((ρ_h + ρ_p)² − δ²),  δ = R + ρ_h − ρ_C
//!                                                              (0 < δ < ρ_h + ρ_p)
//! ```
//!
//! and passes into the bore for `δ ≥ ρ_h + ρ_p`. The peg descends
//! undeflected until the rim point with the smallest remaining drop touches
//! first (a scan over `φ`, refined by golden section). On the round the
//! contact normal makes the angle `α`, `sin α = δ/(ρ_h + ρ_p)`, with the
//! vertical and points inwards; the robot pushes down and the wrist's
//! lateral spring holds the peg back, so the rim slides in only if the
//! contact force leans inwards against friction, `tan α > μ`:
//!
//! ```text
//! accepted  ⇔  δ > (ρ_h + ρ_p) μ/√(1 + μ²)   at the first touch
//! ```
//!
//! in the plane of the error. Off that plane, at the angle `ϑ` between the
//! contact's radial direction and the error, the peg still moves along the
//! error's line (the tilt's symmetry pairs the contacts at `±ϑ`): sliding
//! horizontally by `u` it descends by `u t`, `t = tan α cos ϑ`, friction
//! opposes that velocity, and the horizontal force along the line is
//! inward when `t cos α √(1 + t²) > μ` (the same test at `ϑ = 0`). The
//! margin is `(ρ_h + ρ_p)(sin α_e − μ/√(1 + μ²))` with
//! `tan α_e = t cos α √(1 + t²)`, which is `δ − (ρ_h + ρ_p) μ/√(1 + μ²)` in
//! the error's plane (m). On the top face (`δ ≤ 0`) the
//! normal is vertical and nothing pushes the peg in. An aligned peg
//! touches first at its farthest point, `ρ_C = |e_t| + r − ρ_p`, so it is
//! accepted for `|e_t| < W_μ − (r − ρ_p)`,
//! `W_μ = R + ρ_h − (ρ_h + ρ_p) μ/√(1 + μ²)`; without friction the bound is
//! `W_0 = R + ρ_h`, i.e. the capture width `(R − r) + ρ_h + ρ_p`. A tilted
//! peg raises one side of its rim by up to `(r − ρ_p) sin θ`: when the
//! raised side faces the error, the first touch moves off the error's plane
//! to lower rim points nearer the axis.

/// The capture geometry: peg, hole, fillets, friction and where the
/// compliance centre sits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Capture {
    /// Peg radius `r` (m).
    pub peg_radius: f64,
    /// Bore radius `R` (m).
    pub bore_radius: f64,
    /// Rim fillet `ρ_p` (m).
    pub rim_fillet: f64,
    /// Mouth fillet `ρ_h` (m): the chamfer's width.
    pub mouth_fillet: f64,
    /// Coulomb friction `μ`.
    pub friction: f64,
    /// Height `L_c` of the compliance centre above the tip (m).
    pub centre_height: f64,
}

/// One initial error of the robot: the compliance centre's lateral error
/// and the axis's tilt.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InitialError {
    /// Lateral error of the compliance centre, `(x, y)` (m).
    pub centre: [f64; 2],
    /// Tilt `θ` of the axis (rad).
    pub tilt: f64,
    /// Azimuth `ψ` of the tilt (rad from `x`).
    pub azimuth: f64,
}

/// Where the rim first touches the mouth.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Touch {
    /// On the round, at the rim angle `φ` (rad), contact angle `α` from the
    /// vertical (rad).
    Round {
        /// Rim angle `φ` of the touching point (rad, 0 towards the tilt).
        rim_angle: f64,
        /// Contact angle `α` from the vertical (rad).
        alpha: f64,
        /// Cosine of the angle `ϑ` between the contact's radial direction
        /// and the tip's error.
        cos_azimuth: f64,
    },
    /// On the flat top face, at the rim angle `φ` (rad).
    TopFace {
        /// Rim angle `φ` (rad).
        rim_angle: f64,
    },
    /// Nowhere: the whole rim passes inside the round into the bore.
    None,
}

/// What the rule says about one initial error.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Verdict {
    /// The tip's lateral error `e_t` (m).
    pub tip: [f64; 2],
    /// Where the rim first touches.
    pub touch: Touch,
    /// `(ρ_h + ρ_p)(sin α_e − μ/√(1 + μ²))` at the first touch (m; on the
    /// top face `δ − (ρ_h + ρ_p) μ/√(1 + μ²)`; with no touch,
    /// the smallest `δ` over the rim): positive when the chamfer accepts.
    pub margin: f64,
    /// `(ρ_h + ρ_p) sin α_e` at the first touch (m; `δ` on the top face):
    /// positive when a frictionless chamfer would accept.
    pub frictionless_margin: f64,
}

impl Verdict {
    /// True when the rule predicts that the chamfer guides the peg in.
    pub fn accepts(&self) -> bool {
        self.margin > 0.0
    }
}

/// Rim angles scanned for the first touch.
const SCAN: usize = 720;

impl Capture {
    /// `W_0 = R + ρ_h` (m): the largest tube-centre distance a frictionless
    /// chamfer captures.
    pub fn frictionless_width(&self) -> f64 {
        self.bore_radius + self.mouth_fillet
    }

    /// `W_μ = R + ρ_h − (ρ_h + ρ_p) μ/√(1 + μ²)` (m).
    pub fn width(&self) -> f64 {
        self.frictionless_width() - self.friction_offset()
    }

    /// The largest lateral error of the tip an aligned peg may have,
    /// `W_μ − (r − ρ_p)` (m); `(R − r) + ρ_h + ρ_p` without friction.
    pub fn aligned_tip_error(&self) -> f64 {
        self.width() - (self.peg_radius - self.rim_fillet)
    }

    /// The tip's lateral error `e_t = e_c − L_c sin θ (cos ψ, sin ψ)` (m).
    pub fn tip_error(&self, e: &InitialError) -> [f64; 2] {
        let s = self.centre_height * e.tilt.sin();
        [
            e.centre[0] - s * e.azimuth.cos(),
            e.centre[1] - s * e.azimuth.sin(),
        ]
    }

    /// The friction's share of the round, `(ρ_h + ρ_p) μ/√(1 + μ²)` (m).
    fn friction_offset(&self) -> f64 {
        let mu = self.friction;
        (self.mouth_fillet + self.rim_fillet) * mu / mu.hypot(1.0)
    }

    /// `(remaining drop, δ, C_xy)` of the rim sphere at rim angle `phi`
    /// (m); the drop is infinite when the sphere passes into the bore.
    fn drop_at(&self, tip: [f64; 2], tilt: f64, azimuth: f64, phi: f64) -> (f64, f64, [f64; 2]) {
        let (st, ct) = tilt.sin_cos();
        let (sp, cp) = azimuth.sin_cos();
        let a = [st * cp, st * sp, ct];
        let e1 = [ct * cp, ct * sp, -st];
        let e2 = [-sp, cp, 0.0];
        let k = self.peg_radius - self.rim_fillet;
        let (s, c) = phi.sin_cos();
        let cx = tip[0] + self.rim_fillet * a[0] + k * (c * e1[0] + s * e2[0]);
        let cy = tip[1] + self.rim_fillet * a[1] + k * (c * e1[1] + s * e2[1]);
        let cz = self.rim_fillet * a[2] + k * (c * e1[2] + s * e2[2]);
        let delta = self.frictionless_width() - cx.hypot(cy);
        let reach = self.mouth_fillet + self.rim_fillet;
        let drop = if delta <= 0.0 {
            cz - self.rim_fillet
        } else if delta < reach {
            cz + self.mouth_fillet - (reach * reach - delta * delta).sqrt()
        } else {
            f64::INFINITY
        };
        (drop, delta, [cx, cy])
    }

    /// The rule applied to `e`.
    pub fn verdict(&self, e: &InitialError) -> Verdict {
        let tip = self.tip_error(e);
        let f = |phi: f64| self.drop_at(tip, e.tilt, e.azimuth, phi);
        let step = std::f64::consts::TAU / SCAN as f64;
        let mut best = (f64::INFINITY, 0.0);
        let mut smallest_delta = f64::INFINITY;
        for k in 0..SCAN {
            let phi = k as f64 * step;
            let (h, d, _) = f(phi);
            smallest_delta = smallest_delta.min(d);
            if h < best.0 {
                best = (h, phi);
            }
        }
        if !best.0.is_finite() {
            return Verdict {
                tip,
                touch: Touch::None,
                margin: smallest_delta - self.friction_offset(),
                frictionless_margin: smallest_delta,
            };
        }
        // Golden section on the drop around the best scanned angle.
        let g = 0.5 * (5f64.sqrt() - 1.0);
        let (mut lo, mut hi) = (best.1 - step, best.1 + step);
        for _ in 0..60 {
            let (x1, x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
            if f(x1).0 <= f(x2).0 {
                hi = x2;
            } else {
                lo = x1;
            }
        }
        let mid = 0.5 * (lo + hi);
        let phi = if f(mid).0 <= best.0 { mid } else { best.1 };
        let (h, delta, centre) = f(phi);
        // The top face touched at the same drop (an aligned rim lands on an
        // arc of it at once): the outermost of those points.
        let tol = 1e-9 * (self.mouth_fillet + self.rim_fillet);
        let flat = (0..SCAN)
            .map(|k| (k as f64 * step, f(k as f64 * step)))
            .filter(|(_, (hk, dk, _))| *dk <= 0.0 && *hk <= h.min(best.0) + tol)
            .min_by(|a, b| a.1.1.total_cmp(&b.1.1));
        if let Some((phi_flat, (_, d_flat, _))) = flat {
            return Verdict {
                tip,
                touch: Touch::TopFace {
                    rim_angle: phi_flat,
                },
                margin: d_flat - self.friction_offset(),
                frictionless_margin: d_flat,
            };
        }
        let rim_angle = phi.rem_euclid(std::f64::consts::TAU);
        if delta <= 0.0 {
            return Verdict {
                tip,
                touch: Touch::TopFace { rim_angle },
                margin: delta - self.friction_offset(),
                frictionless_margin: delta,
            };
        }
        let reach = self.mouth_fillet + self.rim_fillet;
        let alpha = (delta / reach).asin();
        // The contact's radial direction against the tip's error: the peg
        // moves towards the axis along the error's line.
        let n = tip[0].hypot(tip[1]);
        let cos_theta = if n > 0.0 {
            (centre[0] * tip[0] + centre[1] * tip[1]) / (n * centre[0].hypot(centre[1]))
        } else {
            1.0
        };
        let t = alpha.tan() * cos_theta;
        let effective = (t * alpha.cos() * t.hypot(1.0)).atan();
        Verdict {
            tip,
            touch: Touch::Round {
                rim_angle,
                alpha,
                cos_azimuth: cos_theta,
            },
            margin: reach * (effective.sin() - self.friction_offset() / reach),
            frictionless_margin: reach * effective.sin(),
        }
    }

    /// The compliance-centre errors `e_c` along the unit direction `dir`
    /// (rad from `x`) at which the rule's margin (`frictionless`: the
    /// frictionless margin) first turns negative on either side of the
    /// error that centres the tip, at tilt `tilt` towards `azimuth`: the
    /// two ends `(lower, upper)` of the accepted interval around it, or
    /// `None` when that error is not accepted. Steps of `(ρ_h + ρ_p)/8`
    /// outwards (the margin need not be monotone far out, where the rim's
    /// near side can reach the round across the hole) while the tip stays
    /// within `W_0` of the axis, then bisection to 1e-12 of `W_0`.
    pub fn boundary(
        &self,
        dir: f64,
        tilt: f64,
        azimuth: f64,
        frictionless: bool,
    ) -> Option<(f64, f64)> {
        let m = |s: f64| {
            let v = self.verdict(&InitialError {
                centre: [s * dir.cos(), s * dir.sin()],
                tilt,
                azimuth,
            });
            if frictionless {
                v.frictionless_margin
            } else {
                v.margin
            }
        };
        // The centre of the accepted interval: where the tip is centred
        // along `dir`.
        let s0 = self.centre_height * tilt.sin() * (azimuth - dir).cos();
        if m(s0) <= 0.0 {
            return None;
        }
        let span = self.frictionless_width();
        let step = 0.125 * (self.mouth_fillet + self.rim_fillet);
        let steps = (span / step).ceil().min(1e5) as usize;
        let solve = |sign: f64| {
            let mut a = s0;
            let mut b = s0 + sign * span;
            for k in 1..=steps {
                let s = s0 + sign * step * k as f64;
                if m(s) <= 0.0 {
                    b = s;
                    break;
                }
                a = s;
            }
            for _ in 0..200 {
                let c = 0.5 * (a + b);
                if m(c) > 0.0 {
                    a = c;
                } else {
                    b = c;
                }
                if (b - a).abs() < 1e-12 * span {
                    break;
                }
            }
            0.5 * (a + b)
        };
        Some((solve(-1.0), solve(1.0)))
    }
}
