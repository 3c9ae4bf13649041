//! The compliant 3-D peg: a rigid cylinder with a filleted bottom rim in a
//! bore with a filleted mouth, six degrees of freedom (centre of mass, unit
//! quaternion, body angular velocity; Newton–Euler), Hertz point contacts
//! found along the edge circles at every right-hand-side call.
//!
//! The files read as layers, each using only those listed before it:
//!
//! - [`params`]: bodies, materials, loads and contact laws, and the
//!   generated functions' parameter vector.
//! - [`frame`]: 3-vectors, the unit quaternion, the axis and the peg's
//!   motion at any scalar, in the order of the `f64` right-hand side.
//! - [`contact`]: the contact pairs and their generated functions (called
//!   in [`Pair::eval`] alone), a contact point and its col, a contact's
//!   geometry at any scalar and through its stationary angle in dual
//!   numbers, the peg's axis.
//! - [`merge`]: the continuous rule by which two points of one pair share
//!   their force as they merge (prominence above the col between them).
//! - [`search`]: every local maximum of penetration of each contact pair,
//!   with certainty: each gap as a trigonometric profile of the edge
//!   angle, closed forms for the rim on a plane, certified branch and
//!   bound over arcs with Newton for the others.
//! - [`face`]: the peg's bottom on a flat at small tilt: the rim circle
//!   as a distributed line contact (closed-form ring potential), handed
//!   over to the rim's Hertz point contact as the tilt grows.
//! - [`prune`]: cheap bounds that skip the pairs a pose cannot touch.
//! - [`curvature`]: the principal curvatures of both surfaces at a contact
//!   point, for the Hertz ellipse.
//! - [`stiffness`]: the pose derivative of the curvature stiffness, whose
//!   term `−(2/5) δ^{5/2} ∂k/∂(pose)` completes the elastic force.
//! - [`law`]: the contact law, once, generic over the scalar: Hertz,
//!   Hunt–Crossley damping, regularized Coulomb friction with the material
//!   point's velocity, the subtracted col, the curvature-stiffness term,
//!   the ring, and the wrench they add up to.
//! - [`forces`]: each contact's Hertz setup, then the law over every
//!   contact at `f64` (the forces and wrench of the right-hand side) or at
//!   any scalar.
//! - [`jacobian`]: the exact Jacobian: the generated partial derivatives
//!   and the law at dual numbers of the state, at the given setups.
//! - [`system`]: the ODE system [`Peg3d`]: search, setups, law, generated
//!   Newton–Euler right-hand side; Hertz errors as values.
//! - [`mindlin`], [`elastic`]: the elastic friction law (Mindlin's
//!   tangential stiffness capped by Coulomb) and the system
//!   [`ElasticPeg3d`] that carries a tangential displacement per tracked
//!   contact in its state.
//! - [`prescribed`], [`wrist`], [`robot`], [`insertion`], [`outcome`]: the
//!   peg driven along a prescribed orientation, held by a compliant wrist
//!   that a robot moves, and how an insertion ends; [`held`]: the wrist's
//!   and the follower moment's wrench at any scalar, and the held peg's
//!   exact Jacobian; [`design`]: the insertion's derivatives in design
//!   parameters (wrist, robot, fillets, clearance, contact law) in dual
//!   numbers, for forward sensitivities.
//!
//! See `docs/compliant-peg-3d.md`.

pub mod contact;
pub mod curvature;
pub mod design;
pub mod elastic;
pub mod face;
pub mod forces;
pub mod frame;
pub mod held;
pub mod jacobian;
pub mod law;
pub mod merge;
pub mod mindlin;
pub mod no_jam;
pub mod params;
pub mod prescribed;
pub mod prune;
pub mod search;
pub mod stiffness;
pub mod system;

pub use contact::{ContactPoint, Contacts, MAX_CONTACTS, Pair, Saddle, axis_of};
pub use elastic::{ElasticError, ElasticPeg3d, MAX_SLOTS, SlotForce, SlotForces, SlotKey};
pub use forces::ContactForce;
pub use params::{FrictionLaw, HertzMode, Peg3dParams};
pub use search::Search;
pub use system::{Peg3d, pose_state};
pub mod insertion;
pub mod outcome;
pub mod robot;
pub mod wrist;
