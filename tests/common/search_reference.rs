//! The dense reference of the contact search and the random poses it is
//! checked on: shared by `tests/compliant_peg_3d/search_property.rs` (CI
//! sized) and, through `#[path]`, `benches/tools/search_campaign.rs` (the
//! large campaign).
//!
//! The reference is independent of the library's search and of the
//! generated code: each pair's gap written again from the geometry
//! (quaternion sandwich rotation, closest points), evaluated on a grid of
//! [`SAMPLES`] angles per circle, halving intervals from 16 down to the
//! grid spacing `h` and skipping an interval `[a, b]` only where bounds
//! prove its gap above a candidate level (or below `−DEEPEST`): the gap
//! is `L`-Lipschitz in the angle (`L` the circle's radius: a distance to a
//! fixed set changes no faster than the point moves), so it is at least
//! `(g(a) + g(b))/2 − L (b − a)/2`, and it lies above its chord less
//! `M (b − a)²/8`, `M` a bound on `|g″|` from the curvature of the
//! distance field (see `Geo::curvature`). A minimum below zero has
//! `g′ = 0`, so its nearest sample is below the candidate level
//! `M h²/8`: every discrete local minimum of the full grid below it is
//! found. Each is refined by bisection on the sign of `g′` (a dual
//! number) between its neighbours.

#![allow(dead_code)]

use crate::common::rng::Rng;
use nalgebra::{SVector, Unit, UnitQuaternion, Vector3};
use pegdyn::compliant_peg_3d::{Pair, Peg3dParams, Search};
use pegdyn::scalar::{Dual, Real};
use std::f64::consts::{FRAC_PI_2, TAU};

/// Grid samples per circle (at least 10⁴).
pub const SAMPLES: usize = 1 << 14;

/// The deepest contact compared (m): far beyond any Hertz overlap of the
/// scenes (0.1 mm at `k = 1.5·10¹⁰ N/m^{3/2}` is 15 kN). Grid intervals
/// where the gap is certainly below `−DEEPEST` are skipped as well.
pub const DEEPEST: f64 = 1e-4;

/// Gap and point tolerance (m).
pub const TOL: f64 = 1e-12;

/// A reference minimum whose gap is within this of zero is grazing and
/// not counted as a contact either way (m).
pub const GRAZING: f64 = 1e-12;

/// The geometry of the pairs.
#[derive(Clone, Copy, Debug)]
pub struct Geo {
    pub r: f64,
    pub len: f64,
    pub rho_p: f64,
    pub big_r: f64,
    pub rho_h: f64,
    pub depth: f64,
}

impl Geo {
    pub fn of(prm: &Peg3dParams) -> Geo {
        Geo {
            r: prm.peg_radius(),
            len: prm.length,
            rho_p: prm.rim_fillet,
            big_r: prm.bore_radius(),
            rho_h: prm.mouth_fillet,
            depth: prm.bore_depth,
        }
    }

    /// The Lipschitz constant of the pair's gap in its angle (m/rad) at
    /// pose `x`: the circle's radius, times the sine of the tilt for the
    /// height of the rim circle (`|c_z′| ≤ ϱ |(e₁,z, e₂,z)| = ϱ sin γ`).
    fn lipschitz(&self, pair: Pair, x: &Pose) -> f64 {
        match pair {
            Pair::EdgeSide => self.big_r + self.rho_h,
            Pair::RimTop | Pair::RimBottom => {
                let [_, i, j, _] = x.q;
                let az = 1.0 - 2.0 * (i * i + j * j);
                (self.r - self.rho_p) * (1.0 - az * az).max(0.0).sqrt() * (1.0 + 1e-12) + 1e-300
            }
            _ => self.r - self.rho_p,
        }
    }

    /// The distance `D` whose curvature bounds `g″`, as a function of the
    /// gap: from the mouth circle to the axis line (`g + r + ρ_h`), of the
    /// rim circle from the hole's axis (`R − ρ_p − g`), from the rim circle
    /// to the mouth circle (`g + ρ_p + ρ_h`); the plane pairs need none.
    fn distance(&self, pair: Pair, gap: f64) -> f64 {
        match pair {
            Pair::EdgeSide => gap + self.r + self.rho_h,
            Pair::RimWall => self.big_r - self.rho_p - gap,
            Pair::RimEdge => gap + self.rho_p + self.rho_h,
            _ => 1.0,
        }
    }

    /// A bound on `|g″|` where the distance `D` lies in `[d_lo, d_hi]`.
    /// A point moving on a circle of radius `s` (speed `s`, acceleration
    /// `s`) has `|D″| ≤ s + s² |Hess D|`, and the Hessian of a distance
    /// has the curvatures of its level set: `1/D` for a line (a cylinder);
    /// `1/D` and at most `1/ρ` for a circle (a torus), `ρ ≥ R_m − D` the
    /// distance from the circle's axis. The plane's height has `|c_z″| ≤
    /// ϱ sin γ`. Infinite where `D` may vanish.
    fn curvature(&self, pair: Pair, x: &Pose, d_lo: f64, d_hi: f64) -> f64 {
        let rr = self.r - self.rho_p;
        let rm = self.big_r + self.rho_h;
        let inv = |d: f64| if d > 0.0 { 1.0 / d } else { f64::INFINITY };
        let m = match pair {
            Pair::EdgeSide => rm + rm * rm * inv(d_lo),
            Pair::RimWall => rr + rr * rr * inv(d_lo),
            Pair::RimEdge => rr + rr * rr * inv(d_lo).max(inv(rm - d_hi)),
            _ => self.lipschitz(pair, x),
        };
        m * (1.0 + 1e-9)
    }

    /// The distance at zero gap.
    fn contact_distance(&self, pair: Pair) -> f64 {
        self.distance(pair, 0.0)
    }
}

/// A pose: centre of mass and unit quaternion `(w, i, j, k)`.
#[derive(Clone, Copy, Debug)]
pub struct Pose {
    pub p: [f64; 3],
    pub q: [f64; 4],
}

impl Pose {
    /// The library's pose vector `(p, q)`.
    pub fn x(&self) -> SVector<f64, 7> {
        SVector::from([
            self.p[0], self.p[1], self.p[2], self.q[0], self.q[1], self.q[2], self.q[3],
        ])
    }
}

fn c<T: Real>(v: f64) -> T {
    T::from_f64(v)
}

fn cross<T: Real>(a: [T; 3], b: [T; 3]) -> [T; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `q v q*` as `v + 2w (u × v) + 2 u × (u × v)`.
fn rotate<T: Real>(q: &[f64; 4], v: [T; 3]) -> [T; 3] {
    let u = [c::<T>(q[1]), c(q[2]), c(q[3])];
    let uv = cross(u, v);
    let uuv = cross(u, uv);
    let w2 = c::<T>(2.0 * q[0]);
    let two = c::<T>(2.0);
    [
        v[0] + w2 * uv[0] + two * uuv[0],
        v[1] + w2 * uv[1] + two * uuv[1],
        v[2] + w2 * uv[2] + two * uuv[2],
    ]
}

/// A pose's centre of mass and body axes in the hole frame (quaternion
/// sandwich of the unit vectors).
#[derive(Clone, Copy, Debug)]
pub struct Frame {
    p: [f64; 3],
    e1: [f64; 3],
    e2: [f64; 3],
    a: [f64; 3],
}

impl Frame {
    pub fn of(x: &Pose) -> Frame {
        Frame {
            p: x.p,
            e1: rotate(&x.q, [1.0, 0.0, 0.0]),
            e2: rotate(&x.q, [0.0, 1.0, 0.0]),
            a: rotate(&x.q, [0.0, 0.0, 1.0]),
        }
    }
}

/// The gap of `pair` at the angle of cosine `co` and sine `si` (m).
pub fn gap_cs<T: Real>(g: &Geo, pair: Pair, f: &Frame, co: T, si: T) -> T {
    let v = |w: [f64; 3]| [c::<T>(w[0]), c::<T>(w[1]), c::<T>(w[2])];
    match pair {
        Pair::EdgeSide => {
            let rm = c::<T>(g.big_r + g.rho_h);
            let u = [
                rm * co - c(f.p[0]),
                rm * si - c(f.p[1]),
                c(-g.rho_h - f.p[2]),
            ];
            // |u × a| is the distance from the axis line.
            let w = cross(u, v(f.a));
            (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]).sqrt() - c(g.r + g.rho_h)
        }
        _ => {
            let rr = g.r - g.rho_p;
            let h = g.rho_p - 0.5 * g.len;
            let k: [T; 3] = std::array::from_fn(|i| {
                c::<T>(f.p[i] + h * f.a[i]) + (co * c(rr * f.e1[i]) + si * c(rr * f.e2[i]))
            });
            let radial = (k[0] * k[0] + k[1] * k[1]).sqrt();
            match pair {
                Pair::RimWall => c::<T>(g.big_r - g.rho_p) - radial,
                Pair::RimTop => k[2] - c(g.rho_p),
                Pair::RimBottom => k[2] - c(g.rho_p - g.depth),
                _ => {
                    let dr = radial - c(g.big_r + g.rho_h);
                    let dz = k[2] + c(g.rho_h);
                    (dr * dr + dz * dz).sqrt() - c(g.rho_p + g.rho_h)
                }
            }
        }
    }
}

/// The gap of `pair` at angle `a` (m).
pub fn gap<T: Real>(g: &Geo, pair: Pair, x: &Pose, a: T) -> T {
    gap_cs(g, pair, &Frame::of(x), a.cos(), a.sin())
}

/// The rim's tube-centre point at body angle `a`.
fn rim(g: &Geo, x: &Pose, a: f64) -> [f64; 3] {
    let f = Frame::of(x);
    let rr = g.r - g.rho_p;
    let h = g.rho_p - 0.5 * g.len;
    std::array::from_fn(|i| f.p[i] + h * f.a[i] + (a.cos() * rr * f.e1[i] + a.sin() * rr * f.e2[i]))
}

/// The cosines and sines of the grid's angles.
fn table() -> &'static [(f64, f64)] {
    static TABLE: std::sync::OnceLock<Vec<(f64, f64)>> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        (0..SAMPLES)
            .map(|k| {
                let a = k as f64 * TAU / SAMPLES as f64;
                (a.cos(), a.sin())
            })
            .collect()
    })
}

/// The contact point of `pair` at angle `a`: midway between the two
/// surfaces on the line of the force through the closest points.
pub fn point(g: &Geo, pair: Pair, x: &Pose, a: f64) -> Vector3<f64> {
    match pair {
        Pair::EdgeSide => {
            let rm = g.big_r + g.rho_h;
            let m = Vector3::new(rm * a.cos(), rm * a.sin(), -g.rho_h);
            let p = Vector3::from(x.p);
            let axis = Vector3::from(rotate(&x.q, [0.0, 0.0, 1.0]));
            let foot = p + axis * (m - p).dot(&axis);
            let n = (foot - m).normalize();
            // Mouth surface m + ρ_h n, side surface foot − r n.
            0.5 * ((m + n * g.rho_h) + (foot - n * g.r))
        }
        _ => {
            let k = Vector3::from(rim(g, x, a));
            let radial = k.xy().norm();
            let e = Vector3::new(k.x / radial, k.y / radial, 0.0);
            match pair {
                Pair::RimWall => {
                    let rad = 0.5 * (g.big_r + radial + g.rho_p);
                    Vector3::new(rad * e.x, rad * e.y, k.z)
                }
                Pair::RimTop => Vector3::new(k.x, k.y, 0.5 * (k.z - g.rho_p)),
                Pair::RimBottom => Vector3::new(k.x, k.y, 0.5 * (k.z - g.rho_p - g.depth)),
                _ => {
                    let m = e * (g.big_r + g.rho_h) - Vector3::z() * g.rho_h;
                    let n = (k - m).normalize();
                    0.5 * ((m + n * g.rho_h) + (k - n * g.rho_p))
                }
            }
        }
    }
}

/// `g′(a)` as a dual number.
fn slope(g: &Geo, pair: Pair, x: &Pose, a: f64) -> f64 {
    gap(g, pair, x, Dual::<1>::variable(a, 0)).d[0]
}

/// A minimum of the reference.
#[derive(Clone, Copy, Debug)]
pub struct RefMin {
    pub angle: f64,
    pub gap: f64,
    /// Whether the grid resolved it: a neighbouring sample is above it by
    /// more than the gap's rounding (not a plateau).
    pub resolved: bool,
}

/// The refined angle of the grid minimum between `lo` and `hi`.
fn refine(g: &Geo, pair: Pair, x: &Pose, mut lo: f64, mut hi: f64, iters: usize) -> f64 {
    let (slo, shi) = (slope(g, pair, x, lo), slope(g, pair, x, hi));
    if slo < 0.0 && shi > 0.0 {
        for _ in 0..iters {
            let m = 0.5 * (lo + hi);
            if m <= lo || m >= hi {
                break;
            }
            if slope(g, pair, x, m) > 0.0 {
                hi = m;
            } else {
                lo = m;
            }
        }
        return 0.5 * (lo + hi);
    }
    // Golden-section search on the gap.
    let phi = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..iters {
        let (a, b) = (hi - phi * (hi - lo), lo + phi * (hi - lo));
        if b <= a {
            break;
        }
        if gap(g, pair, x, a) < gap(g, pair, x, b) {
            hi = b;
        } else {
            lo = a;
        }
    }
    0.5 * (lo + hi)
}

/// Every discrete local minimum of the grid with a gap in `[−DEEPEST, 0)`,
/// refined (and possibly deeper ones).
pub fn reference(g: &Geo, pair: Pair, x: &Pose) -> (Vec<RefMin>, usize) {
    let h = TAU / SAMPLES as f64;
    let lip = g.lipschitz(pair, x);
    let mut evals = 0;
    if lip * h < 1e-15 {
        // A flat circle (a plane pair of an aligned peg): no minimum the
        // grid can resolve.
        return (Vec::new(), evals);
    }
    let frame = Frame::of(x);
    let cs = table();
    let at = |k: usize| {
        let (co, si) = cs[k % SAMPLES];
        gap_cs(g, pair, &frame, co, si)
    };
    // Grid samples evaluated, by index (in the active fine intervals).
    let mut fine: Vec<(usize, f64)> = Vec::new();
    // A minimum α* with g* in [−DEEPEST, 0) has g′ = 0, so its nearest
    // sample (within h/2) is below g* + M h²/8, M bounding |g″| there
    // (D within L h/2 of its value at α*).
    let d0 = g.contact_distance(pair);
    let (d_lo, d_hi) = match pair {
        Pair::RimWall => (d0 - lip * h, d0 + DEEPEST + lip * h),
        _ => (d0 - DEEPEST - lip * h, d0 + lip * h),
    };
    let candidate = g.curvature(pair, x, d_lo, d_hi) * h * h / 8.0 + 1e-15;
    let coarse = 16;
    let step = SAMPLES / coarse;
    let mut stack: Vec<(usize, usize, f64, f64)> = Vec::new();
    let ends: Vec<f64> = (0..=coarse).map(|j| at(j * step)).collect();
    evals += coarse;
    // Pushed right to left and each right half before its left: the fine
    // intervals come out in increasing angle.
    for j in (0..coarse).rev() {
        stack.push((j * step, (j + 1) * step, ends[j], ends[j + 1]));
    }
    while let Some((a, b, ga, gb)) = stack.pop() {
        // First order: |g′| ≤ L. Second order: g is above its chord less
        // M (b − a)²/8, M bounding |g″| on the interval, where D is within
        // L (b − a)/2 of its values at the ends.
        let w = (b - a) as f64 * h;
        let slack = lip * w * 0.5 + 1e-15;
        let (da, db) = (g.distance(pair, ga), g.distance(pair, gb));
        let m2 = g.curvature(pair, x, da.min(db) - slack, da.max(db) + slack);
        let bend = m2 * w * w / 8.0 + 1e-15;
        let lower = (0.5 * (ga + gb) - slack).max(ga.min(gb) - bend);
        let upper = (0.5 * (ga + gb) + slack).min(ga.max(gb) + bend);
        if lower > candidate || upper < -DEEPEST {
            continue;
        }
        if b - a == 1 {
            fine.push((a, ga));
            fine.push((b % SAMPLES, gb));
            continue;
        }
        let m = (a + b) / 2;
        let gm = at(m);
        evals += 1;
        stack.push((m, b, gm, gb));
        stack.push((a, m, ga, gm));
    }
    // In order but for the wrap of the last end to 0.
    if fine.last().is_some_and(|s| s.0 == 0) {
        let s0 = fine.pop();
        fine.extend(s0);
        fine.rotate_right(1);
    }
    fine.dedup_by_key(|s| s.0);
    debug_assert!(fine.windows(2).all(|w| w[0].0 < w[1].0));
    // Neighbours of entry i (consecutive entries, or the wrap).
    let n = fine.len();
    let at_index = |i: usize, k: usize| (fine[i % n].0 == k % SAMPLES).then(|| fine[i % n].1);
    let mut out = Vec::new();
    for (i, &(k, gk)) in fine.iter().enumerate() {
        if gk >= candidate || gk < -DEEPEST {
            continue;
        }
        let (Some(gp), Some(gn)) = (at_index(i + n - 1, k + SAMPLES - 1), at_index(i + 1, k + 1))
        else {
            continue;
        };
        if !(gk <= gp && gk < gn) {
            continue;
        }
        let a = k as f64 * h;
        let m = refine(g, pair, x, a - h, a + h, 200).rem_euclid(TAU);
        let noise = 1e-15;
        out.push(RefMin {
            angle: m,
            gap: gap(g, pair, x, m),
            resolved: gp - gk > noise || gn - gk > noise,
        });
    }
    (out, evals)
}

/// The orientation of tilt `gamma` towards azimuth `psi` after a spin
/// `phi` about the peg's axis.
fn orientation(gamma: f64, psi: f64, phi: f64) -> [f64; 4] {
    let tilt = Unit::new_normalize(Vector3::new(-psi.sin(), psi.cos(), 0.0));
    let q = UnitQuaternion::from_axis_angle(&tilt, gamma)
        * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), phi);
    [q.w, q.i, q.j, q.k]
}

/// The reference's smallest gap of `pair` over the circle (angle, gap),
/// roughly: 32 samples and a refinement.
fn lowest(g: &Geo, pair: Pair, x: &Pose) -> (f64, f64) {
    let n = 32;
    let h = TAU / n as f64;
    let frame = Frame::of(x);
    let cs = table();
    let (k, _) = (0..n)
        .map(|k| {
            let (co, si) = cs[k * (SAMPLES / n)];
            (k, gap_cs(g, pair, &frame, co, si))
        })
        .fold((0, f64::INFINITY), |b, s| if s.1 < b.1 { s } else { b });
    let a = refine(g, pair, x, (k as f64 - 1.0) * h, (k as f64 + 1.0) * h, 40);
    (a, gap(g, pair, x, a))
}

/// A random pose near contact of `pair`: tilt uniform in `[0, π/2]` (one
/// in fifty exactly aligned, one in fifty below a milliradian), any
/// azimuth and spin, a random position, then moved along the force
/// direction of the pair's lowest point until its gap is `−δ`, the
/// penetration `δ` uniform in `[−1 mm, 10 µm]` for a quarter of the poses,
/// otherwise log-uniform in magnitude in `[10⁻¹², 10⁻⁵]` m, penetrating
/// in two of three.
pub fn near_contact(g: &Geo, pair: Pair, rng: &mut Rng) -> Pose {
    let pick = rng.next_f64();
    let gamma = if pick < 0.02 {
        0.0
    } else if pick < 0.04 {
        10f64.powf(rng.uniform(-9.0, -3.0))
    } else {
        rng.uniform(0.0, FRAC_PI_2)
    };
    let q = orientation(gamma, rng.uniform(0.0, TAU), rng.uniform(0.0, TAU));
    let reach = g.big_r + 3e-3;
    let mut x = Pose {
        p: [
            rng.uniform(-reach, reach),
            rng.uniform(-reach, reach),
            rng.uniform(-g.depth, g.len),
        ],
        q,
    };
    let delta = if rng.next_f64() < 0.25 {
        rng.uniform(-1e-3, 1e-5)
    } else {
        let m = 10f64.powf(rng.uniform(-12.0, -5.0));
        if rng.next_f64() < 2.0 / 3.0 { m } else { -m }
    };
    for _ in 0..2 {
        let (a, g0) = lowest(g, pair, &x);
        // The gap's gradient in the centre of mass is the force direction.
        let e = 1e-7;
        let grad = Vector3::from_fn(|i, _| {
            let mut plus = x;
            let mut minus = x;
            plus.p[i] += e;
            minus.p[i] -= e;
            (gap(g, pair, &plus, a) - gap(g, pair, &minus, a)) / (2.0 * e)
        });
        let n2 = grad.norm_squared();
        // Also stops at a NaN gradient.
        if n2.partial_cmp(&1e-6) != Some(std::cmp::Ordering::Greater) {
            break;
        }
        let dp = grad * ((-delta - g0) / n2);
        for i in 0..3 {
            x.p[i] += dp[i];
        }
    }
    x
}

/// What one comparison found.
#[derive(Clone, Debug, Default)]
pub struct Tally {
    /// Poses and pair searches compared.
    pub poses: usize,
    pub searches: usize,
    /// Reference contacts (resolved, deeper than grazing), by pair.
    pub contacts: [usize; 5],
    /// Reference minima below the grid's resolution (plateaus), skipped.
    pub unresolved: usize,
    /// Library minima below zero that the grid did not show, each checked
    /// to be a local minimum of the reference gap.
    pub library_only: usize,
    /// Largest gap and point differences at matched contacts (m).
    pub gap_err: f64,
    pub point_err: f64,
    /// Reference contacts that exist (valid: on the part of each surface
    /// that exists, the rim's outer half), compared with the contact
    /// path's (`Search::find`), by pair.
    pub valid: [usize; 5],
    /// Largest number of arcs one library search visited.
    pub max_arcs: usize,
    /// Reference evaluations.
    pub evals: usize,
    /// Failures: a missed contact, a spurious minimum, an error above
    /// tolerance (first few, described).
    pub failures: Vec<String>,
    pub failed: usize,
}

impl Tally {
    pub fn merge(&mut self, o: &Tally) {
        self.poses += o.poses;
        self.searches += o.searches;
        for k in 0..5 {
            self.contacts[k] += o.contacts[k];
            self.valid[k] += o.valid[k];
        }
        self.unresolved += o.unresolved;
        self.library_only += o.library_only;
        self.gap_err = self.gap_err.max(o.gap_err);
        self.point_err = self.point_err.max(o.point_err);
        self.max_arcs = self.max_arcs.max(o.max_arcs);
        self.evals += o.evals;
        self.failed += o.failed;
        for f in &o.failures {
            if self.failures.len() < 10 {
                self.failures.push(f.clone());
            }
        }
    }

    fn fail(&mut self, what: String) {
        self.failed += 1;
        if self.failures.len() < 10 {
            self.failures.push(what);
        }
    }
}

/// The distance (rad) between two angles on the circle.
pub fn angle_distance(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(TAU);
    d.min(TAU - d)
}

/// Compares the library's minima below zero of every pair at pose `x`
/// with the reference's, into `tally`.
pub fn compare(prm: &Peg3dParams, pv: &SVector<f64, 16>, x: &Pose, tally: &mut Tally) {
    let g = Geo::of(prm);
    let xv = x.x();
    tally.poses += 1;
    for pair in Pair::ALL {
        tally.searches += 1;
        let mut search = Search::default();
        let found = search.minima(pair, &xv, pv, 0.0);
        tally.max_arcs = tally.max_arcs.max(search.work.arcs);
        if search.work.unresolved > 0 {
            tally.fail(format!("{pair:?} at {x:?}: search out of budget"));
        }
        let lib: Vec<(f64, f64, Vector3<f64>)> = found
            .iter()
            .map(|&a| {
                let e = pair.eval(&xv, a, pv);
                (a, e.gap, e.point)
            })
            .collect();
        let (refs, evals) = reference(&g, pair, x);
        tally.evals += evals;
        let h = TAU / SAMPLES as f64;
        let mut matched = vec![false; lib.len()];
        for r in &refs {
            if r.gap >= -GRAZING || r.gap < -DEEPEST {
                continue;
            }
            if !r.resolved {
                tally.unresolved += 1;
                continue;
            }
            tally.contacts[pair.index()] += 1;
            let hit = lib
                .iter()
                .enumerate()
                .filter(|(_, l)| angle_distance(l.0, r.angle) <= 2.0 * h)
                .min_by(|a, b| {
                    angle_distance(a.1.0, r.angle).total_cmp(&angle_distance(b.1.0, r.angle))
                });
            let Some((i, l)) = hit else {
                tally.fail(format!(
                    "{pair:?} at {x:?}: contact at {} (gap {}) missed; found {lib:?}",
                    r.angle, r.gap
                ));
                continue;
            };
            matched[i] = true;
            let ge = (l.1 - r.gap).abs();
            let pe = (l.2 - point(&g, pair, x, r.angle)).norm();
            tally.gap_err = tally.gap_err.max(ge);
            tally.point_err = tally.point_err.max(pe);
            if ge > TOL || pe > TOL {
                tally.fail(format!(
                    "{pair:?} at {x:?}: contact at {} vs {}: gap error {ge:e}, point error {pe:e}",
                    r.angle, l.0
                ));
            }
        }
        for (i, l) in lib.iter().enumerate() {
            if matched[i] || l.1 >= -GRAZING || l.1 < -DEEPEST {
                continue;
            }
            if refs.iter().any(|r| angle_distance(r.angle, l.0) <= 2.0 * h) {
                continue;
            }
            // Not on the grid: it must still be a local minimum.
            let gl = gap(&g, pair, x, l.0);
            let ok = [1e-3, 1e-5, 1e-7].iter().all(|&d| {
                gap(&g, pair, x, l.0 + d) >= gl - 1e-15 && gap(&g, pair, x, l.0 - d) >= gl - 1e-15
            });
            if ok {
                tally.library_only += 1;
            } else {
                tally.fail(format!(
                    "{pair:?} at {x:?}: minimum at {} (gap {}) is not one",
                    l.0, l.1
                ));
            }
        }
    }
}

/// Whether the minimum of `pair` at angle `a` is on the part of its
/// surfaces that exists (the library's rule, [`Pair::valid`] and
/// [`Pair::rim_faces_out`], on the generated geometry at that angle).
fn valid_at(
    prm: &Peg3dParams,
    pv: &SVector<f64, 16>,
    pair: Pair,
    x: &SVector<f64, 7>,
    a: f64,
) -> bool {
    let e = pair.eval(x, a, pv);
    let axis = pegdyn::compliant_peg_3d::axis_of(x);
    pair.valid(prm, &axis, &e.normal, &e.point, e.axial)
        && pair.rim_faces_out(x, &e.normal, &e.point)
}

/// Compares the contacts of a fresh contact path (`Search::find`, with
/// the pairs' windows and the plane pairs' certificates off their faces)
/// with the reference minima below zero that are valid at their angles,
/// into `tally`: each such minimum found with its depth and point to
/// `TOL`, and each contact found a valid reference minimum (or a local
/// minimum of the reference gap the grid did not show). A minimum whose
/// validity changes within two grid spacings is skipped (its angle's
/// rounding decides it), and so is one the library places within two grid
/// spacings but judges the other way at its own angle (validity decided
/// by rounding: a level rim over the mouth's round, whose normal is
/// vertical to rounding, on the boundary of the rim's outer half).
pub fn compare_contacts(prm: &Peg3dParams, pv: &SVector<f64, 16>, x: &Pose, tally: &mut Tally) {
    let g = Geo::of(prm);
    let xv = x.x();
    let h = TAU / SAMPLES as f64;
    for pair in Pair::ALL {
        let mut out = pegdyn::compliant_peg_3d::Contacts::new();
        Search::default().find(pair, prm, &xv, pv, &mut out);
        let minima = Search::default().minima(pair, &xv, pv, 0.0);
        let (refs, evals) = reference(&g, pair, x);
        tally.evals += evals;
        let mut matched = vec![false; out.len()];
        let mut borderline = Vec::new();
        for r in &refs {
            if r.gap >= -GRAZING || r.gap < -DEEPEST || !r.resolved {
                continue;
            }
            let valid = valid_at(prm, pv, pair, &xv, r.angle);
            let near = [-2.0 * h, 2.0 * h].map(|d| valid_at(prm, pv, pair, &xv, r.angle + d));
            let judged_apart = minima.iter().chain(out.iter().map(|c| &c.angle)).any(|&m| {
                angle_distance(m, r.angle) <= 2.0 * h && valid_at(prm, pv, pair, &xv, m) != valid
            });
            if near.iter().any(|&v| v != valid) || judged_apart {
                borderline.push(r.angle);
                continue;
            }
            if !valid {
                continue;
            }
            tally.valid[pair.index()] += 1;
            let hit = out
                .iter()
                .enumerate()
                .filter(|(_, c)| angle_distance(c.angle, r.angle) <= 2.0 * h)
                .min_by(|a, b| {
                    angle_distance(a.1.angle, r.angle)
                        .total_cmp(&angle_distance(b.1.angle, r.angle))
                });
            let Some((i, c)) = hit else {
                tally.fail(format!(
                    "{pair:?} at {x:?}: valid contact at {} (gap {}) missed by the contact path",
                    r.angle, r.gap
                ));
                continue;
            };
            matched[i] = true;
            let ge = (-c.penetration - r.gap).abs();
            let pe = (c.point - point(&g, pair, x, r.angle)).norm();
            if ge > TOL || pe > TOL {
                tally.fail(format!(
                    "{pair:?} at {x:?}: contact at {} vs {}: depth error {ge:e}, point error {pe:e}",
                    r.angle, c.angle
                ));
            }
        }
        for (i, c) in out.iter().enumerate() {
            let depth = c.penetration;
            if matched[i] || depth <= GRAZING || depth > DEEPEST {
                continue;
            }
            if borderline
                .iter()
                .any(|&b| angle_distance(b, c.angle) <= 2.0 * h)
            {
                continue;
            }
            let near = refs
                .iter()
                .filter(|r| angle_distance(r.angle, c.angle) <= 2.0 * h && r.resolved);
            let mut seen = false;
            for r in near {
                seen = true;
                // A reference minimum at the depth thresholds' edge is
                // compared on neither side; one off its surface is no
                // contact.
                if !valid_at(prm, pv, pair, &xv, r.angle) {
                    tally.fail(format!(
                        "{pair:?} at {x:?}: contact at {} (depth {depth}) where the reference's minimum is not valid",
                        c.angle
                    ));
                }
            }
            if seen {
                continue;
            }
            let gl = gap(&g, pair, x, c.angle);
            let ok = [1e-3, 1e-5, 1e-7].iter().all(|&d| {
                gap(&g, pair, x, c.angle + d) >= gl - 1e-15
                    && gap(&g, pair, x, c.angle - d) >= gl - 1e-15
            });
            if !ok {
                tally.fail(format!(
                    "{pair:?} at {x:?}: contact at {} (depth {depth}) is no minimum",
                    c.angle
                ));
            }
        }
    }
}

/// Runs `n` poses from seed `seed` (each pair in turn near contact).
pub fn campaign(prm: &Peg3dParams, seed: u64, n: usize) -> Tally {
    let pv = prm.vector();
    let g = Geo::of(prm);
    let mut rng = Rng(seed);
    let mut tally = Tally::default();
    for k in 0..n {
        let pair = Pair::ALL[k % 5];
        let x = near_contact(&g, pair, &mut rng);
        compare(prm, &pv, &x, &mut tally);
        compare_contacts(prm, &pv, &x, &mut tally);
    }
    tally
}
