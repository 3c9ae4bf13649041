//! The compliant 3-D peg as an ODE system: the contact points of
//! [`super::search`] (and the rings of [`super::face`]) with their Hertz
//! setups, the contact law ([`super::law`]) summed into the wrench of the
//! generated Newton–Euler right-hand side
//! (`pegdyn::generated::compliant_peg_3d::rhs`), and its exact Jacobian
//! ([`super::jacobian`]).
//!
//! A contact whose Hertz setup fails (relative curvatures not positive)
//! is an error value: [`Peg3d::forces`] returns it,
//! [`OdeSystem::try_rhs`] and [`OdeSystem::try_jacobian`] return it as a
//! [`ModelError`], and the integrators carry the first one met out in
//! [`crate::integrate::Solution::model_error`]. Further generalized forces
//! (a wrist spring–damper, a prescribed frame) add to the same wrench.

use super::contact::{ContactPoint, Contacts, Pair};
use super::face;
use super::forces::{self, ContactForce, Setups};
use super::frame;
use super::jacobian;
use super::law::LawParams;
use super::params::Peg3dParams;
use super::prune;
use super::search::Search;
use crate::generated::compliant_peg_3d as generated;
use crate::hertz::HertzError;
use crate::system::{KinematicSplit, ModelError, OdeSystem};
use nalgebra::{SMatrix, SVector, UnitQuaternion, Vector3};
use std::cell::RefCell;

/// The state `(p, q, v, ω_body, W = 0, S = 0)` of a pose and velocities.
pub fn pose_state(
    p: Vector3<f64>,
    q: UnitQuaternion<f64>,
    v: Vector3<f64>,
    omega_body: Vector3<f64>,
) -> SVector<f64, 15> {
    let mut y = SVector::<f64, 15>::zeros();
    y.fixed_rows_mut::<3>(0).copy_from(&p);
    y[3] = q.w;
    y[4] = q.i;
    y[5] = q.j;
    y[6] = q.k;
    y.fixed_rows_mut::<3>(7).copy_from(&v);
    y.fixed_rows_mut::<3>(10).copy_from(&omega_body);
    y
}

/// The compliant 3-D peg.
pub struct Peg3d {
    /// The parameters.
    pub params: Peg3dParams,
    p: SVector<f64, 16>,
    /// The warm starts of each pair's search: a cache (any call may
    /// search from scratch), not state of the model.
    searches: RefCell<[Search; Pair::ALL.len()]>,
    /// The contacts and setups of the last pose searched ([`Found`]).
    found: RefCell<Found>,
}

/// The contacts (and, once asked for, their Hertz setups) of the last
/// state searched, with what they were found at: the bits of the pose
/// part `(p, q)` of the state (the search and the setups read nothing
/// else of it) and the parameters. A later call at the same pose with the
/// same parameters takes these instead of searching again: the Jacobian
/// that a Rosenbrock step asks for right after `f(y)`, and the event
/// functions, output samples and force checks at the step's end, where
/// the last right-hand side was evaluated. A second search there would
/// return the same contacts to rounding (every search finds every contact
/// of the pose, [`Search::find`]; a pair certified apart at that pose stays
/// apart there), so the memo changes no result beyond rounding. At any
/// other state, or after the parameters changed, it searches.
struct Found {
    /// `None` before the first search.
    pose_bits: Option<[u64; 7]>,
    params: Peg3dParams,
    contacts: Contacts,
    /// The setups of `contacts`, valid when `has_setups` (kept in place:
    /// the array is a few kilobytes).
    setups: Setups,
    has_setups: bool,
}

impl Found {
    /// Whether these were found at the pose of `y` with `params`.
    fn at(&self, y: &SVector<f64, 15>, params: &Peg3dParams) -> bool {
        self.pose_bits == Some(pose_bits(y)) && self.params == *params
    }
}

/// The bits of the pose part `(p, q)` of a state.
fn pose_bits(y: &SVector<f64, 15>) -> [u64; 7] {
    std::array::from_fn(|k| y[k].to_bits())
}

impl Peg3d {
    /// The system with parameters `params`.
    pub fn new(params: Peg3dParams) -> Peg3d {
        Peg3d {
            p: params.vector(),
            params,
            searches: RefCell::new(Default::default()),
            found: RefCell::new(Found {
                pose_bits: None,
                params,
                contacts: Contacts::new(),
                setups: Setups::new(),
                has_setups: false,
            }),
        }
    }

    /// The generated functions' parameter vector.
    pub fn param_vector(&self) -> &SVector<f64, 16> {
        &self.p
    }

    /// The pose `(p, q/|q|)` of a state.
    pub fn pose(y: &SVector<f64, 15>) -> SVector<f64, 7> {
        SVector::from(frame::pose(y.as_slice()))
    }

    /// Every contact point of the state, pair by pair: the point contacts
    /// of each pair's search, then, for the block's top face and the bore
    /// bottom at small tilt, the distributed ring of [`super::face`] (the
    /// point search is skipped where the ring carries the flat alone).
    pub fn contacts(&self, y: &SVector<f64, 15>) -> Vec<ContactPoint> {
        self.with_contacts(y, <[ContactPoint]>::to_vec)
    }

    /// [`Peg3d::contacts`] in a fixed-capacity array (no allocation).
    pub fn contacts_fixed(&self, y: &SVector<f64, 15>) -> Contacts {
        self.with_contacts(y, |c| c.iter().copied().collect())
    }

    /// `f` of the contacts of state `y` ([`Peg3d::contacts`]): those of the
    /// last search when it was at the same pose with the same parameters
    /// (kept with the system), else those of a new search, which replace them.
    pub fn with_contacts<R>(
        &self,
        y: &SVector<f64, 15>,
        f: impl FnOnce(&[ContactPoint]) -> R,
    ) -> R {
        f(&self.found_at(y).contacts)
    }

    /// The memo of [`Found`] at state `y`: a new search unless it is at the
    /// pose of `y` with the current parameters.
    fn found_at(&self, y: &SVector<f64, 15>) -> std::cell::RefMut<'_, Found> {
        let mut found = self.found.borrow_mut();
        if !found.at(y, &self.params) {
            found.pose_bits = Some(pose_bits(y));
            found.params = self.params;
            found.has_setups = false;
            self.search(y, &mut found.contacts);
        }
        found
    }

    /// Every contact point of state `y` into `out` (cleared first): the
    /// search of each pair, not kept; each pair's search keeps
    /// its own certified clearance.
    pub fn search(&self, y: &SVector<f64, 15>, out: &mut Contacts) {
        let x = Self::pose(y);
        out.clear();
        let mut s = self.searches.borrow_mut();
        for (k, pair) in Pair::ALL.iter().enumerate() {
            let ring = prune::ring_applies(*pair, &self.params, &x);
            let weight = if ring { self.point_weight(&x) } else { 1.0 };
            if weight > 0.0 && prune::can_touch(*pair, &self.params, &x) {
                s[k].find(*pair, &self.params, &x, &self.p, out);
            } else {
                s[k] = Search::default();
            }
            if ring && weight < 1.0 {
                // A ring per flat: within MAX_CONTACTS.
                if let Some(c) = self.ring_contact(*pair, &x) {
                    let _ = out.try_push(c);
                }
            }
        }
    }

    /// The hand-over weight `s` of the plane pairs' point contacts at pose
    /// `x` (where their ring applies).
    fn point_weight(&self, x: &SVector<f64, 7>) -> f64 {
        forces::point_weight(&(*x).into())
    }

    /// The ring of a plane pair at pose `x`, as a contact point.
    fn ring_contact(&self, pair: Pair, x: &SVector<f64, 7>) -> Option<ContactPoint> {
        let z0 = face::plane(pair, &self.params)?;
        let xs: [f64; 7] = (*x).into();
        let r = face::ring(&self.params, z0, face::line_stiffness(&self.params), &xs)?;
        let cop = face::centre_of_pressure(&xs, &r, z0);
        Some(ContactPoint {
            pair,
            angle: r.angle,
            penetration: r.depth,
            gradient: pair.eval(x, r.angle, &self.p).grad,
            normal: Vector3::z(),
            point: Vector3::from(cop),
            saddle: None,
            ring: true,
        })
    }

    /// Every contact of state `y` ([`Peg3d::contacts`]) with its Hertz
    /// setup ([`forces::setups_into`]): the point contacts, then the rings;
    /// those of the last call when it was at the same pose with the same
    /// parameters.
    ///
    /// # Errors
    /// A contact whose Hertz setup fails (relative curvature not positive).
    pub fn setups(&self, y: &SVector<f64, 15>) -> Result<Setups, HertzError> {
        self.with_setups(y, |s| s.iter().copied().collect())
    }

    /// Every contact with its forces at state `y`: the point contacts,
    /// then the rings.
    ///
    /// # Errors
    /// A contact whose Hertz setup fails (relative curvature not positive).
    pub fn forces(&self, y: &SVector<f64, 15>) -> Result<Vec<ContactForce>, HertzError> {
        self.with_setups(y, |s| forces::forces(&self.params, y, s))
    }

    /// The contact wrench `(F, T about the centre of mass, Ṡ)` at state
    /// `y`: the law of every contact summed straight into the wrench
    /// ([`forces::contact_wrench`] at `f64`; the same as
    /// [`Peg3d::wrench`] of [`Peg3d::forces`]).
    ///
    /// # Errors
    /// A contact whose Hertz setup fails (relative curvature not positive).
    pub fn contact_wrench(&self, y: &SVector<f64, 15>) -> Result<SVector<f64, 7>, HertzError> {
        let m = frame::Motion::of_state(y.as_slice());
        let law = LawParams::of(&self.params);
        self.with_setups(y, |setups| {
            SVector::from(forces::contact_wrench(
                &self.params,
                &law,
                &m,
                setups,
                |_, _, at| *at,
            ))
        })
    }

    /// `f` of the setups of state `y`: those found at the last call at the
    /// same pose with the same parameters, else those of a new
    /// search, which replace them.
    ///
    /// # Errors
    /// A contact whose Hertz setup fails (relative curvature not positive).
    pub fn with_setups<R>(
        &self,
        y: &SVector<f64, 15>,
        f: impl FnOnce(&[forces::Setup]) -> R,
    ) -> Result<R, HertzError> {
        let mut found = self.found_at(y);
        let found = &mut *found;
        if !found.has_setups {
            forces::setups_into(
                &self.params,
                &self.p,
                &Self::pose(y),
                &found.contacts,
                &mut found.setups,
            )?;
            found.has_setups = true;
        }
        Ok(f(&found.setups))
    }

    /// The contact wrench at state `y` in dual numbers of the state
    /// ([`jacobian::wrench_dual`]): its value and exact derivative, at the
    /// contacts of [`Peg3d::with_setups`].
    ///
    /// # Errors
    /// As [`Peg3d::setups`] when it has to search.
    pub fn contact_wrench_dual(
        &self,
        y: &SVector<f64, 15>,
    ) -> Result<[jacobian::D; 7], HertzError> {
        let yd = jacobian::seeded(y);
        self.with_setups(y, |s| jacobian::wrench_dual(&self.params, &self.p, &yd, s))
    }

    /// The contact wrench `(F, T about the centre of mass, Ṡ)` of
    /// `forces` at state `y` ([`forces::wrench`]).
    pub fn wrench(y: &SVector<f64, 15>, forces: &[ContactForce]) -> SVector<f64, 7> {
        forces::wrench(y, forces)
    }

    /// `T + m g z + Σ (2/5) k δ^{5/2} − W + S` at state `y` (J): constant
    /// along solutions.
    ///
    /// # Errors
    /// As [`Peg3d::forces`].
    pub fn energy_balance(&self, y: &SVector<f64, 15>) -> Result<f64, HertzError> {
        let e = generated::energy(y, &self.p);
        let pot: f64 = self.forces(y)?.iter().map(|f| f.potential).sum();
        Ok(e.kinetic + e.gravity + pot - y[13] + y[14])
    }
}

impl OdeSystem<15> for Peg3d {
    /// [`OdeSystem::try_rhs`], NaN after a Hertz setup error.
    fn rhs(&self, t: f64, y: &SVector<f64, 15>) -> SVector<f64, 15> {
        self.try_rhs(t, y)
            .unwrap_or_else(|_| SVector::repeat(f64::NAN))
    }

    /// The generated right-hand side with the contact wrench.
    fn try_rhs(&self, _t: f64, y: &SVector<f64, 15>) -> Result<SVector<f64, 15>, ModelError> {
        Ok(generated::rhs(y, &self.contact_wrench(y)?, &self.p))
    }

    /// [`OdeSystem::try_jacobian`], NaN after a Hertz setup error.
    fn jacobian(&self, t: f64, y: &SVector<f64, 15>) -> SMatrix<f64, 15, 15> {
        self.try_jacobian(t, y)
            .unwrap_or_else(|_| SMatrix::repeat(f64::NAN))
    }

    /// The exact Jacobian ([`super::jacobian`]) at the contacts of `y`
    /// ([`Peg3d::with_setups`]: those the right-hand side just found at
    /// `y`, no second search).
    fn try_jacobian(
        &self,
        _t: f64,
        y: &SVector<f64, 15>,
    ) -> Result<SMatrix<f64, 15, 15>, ModelError> {
        Ok(self.with_setups(y, |s| jacobian::of(&self.params, &self.p, y, s))?)
    }

    fn time_derivative(&self, _t: f64, _y: &SVector<f64, 15>) -> SVector<f64, 15> {
        SVector::zeros()
    }

    /// Positions `(p, q)` with the kinematic map `ṗ = v`,
    /// `q̇ = ½ q ⊗ (0, ω)`, velocities `(v, ω)`, then the work integrals.
    fn kinematic_split(&self) -> Option<KinematicSplit> {
        Some(KinematicSplit {
            positions: 7,
            velocities: 6,
        })
    }

    fn state_names(&self) -> &'static [&'static str] {
        &generated::Y_NAMES
    }
}
