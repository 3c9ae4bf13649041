//! Valid ranges of the compliant 3-D peg kinds' shared tables (`[peg]`,
//! `[wrist]`, `[robot]`, `[criteria]`; `docs/scenes.md`):
//!
//! - Sizes from a micrometre to a kilometre: the contact search's
//!   tolerances and the energies stay far inside f64.
//! - Materials, friction and damping over the span of engineering
//!   materials (the same limits as the other compliant kinds).
//! - Wrist stiffnesses from a barely held peg to a near-rigid mount, robot
//!   errors and rates of a positioning robot, force limits up to far beyond
//!   what the peg survives.
//!
//! Some bounds depend on other fields (a fillet at most half the peg
//! radius, a lateral error within two bore diameters): the constant holds
//! the widest bound and the check narrows it with [`FieldRange::within`],
//! so that a refusal shows the scene's own limit.

use crate::scene::ranges::{
    FieldRange, MAX_YOUNGS_MODULUS, MIN_YOUNGS_MODULUS, WHY_CONTACT_DAMPING,
};

const WHY_SIZE: &str = "engineering sizes, a micrometre to a kilometre: the contact search's tolerances and the energies stay far inside f64";
const WHY_ANGLE: &str = "a direction, at most one turn either way";
const WHY_RATE: &str = "a robot's rotation, up to about 1600 turns per second";
const WHY_WRIST_STIFFNESS: &str = "a barely held peg to a near-rigid mount: stiffer, the wrist's own vibration (a 50 g peg on 1e9 N/m: a period of 44 us) sets every step";
const WHY_WRIST_DAMPING: &str = "none to heavily overdamped";

/// `peg.hole_diameter`.
pub const HOLE_DIAMETER: FieldRange =
    FieldRange::new("peg.hole_diameter", 1e-6, 1e3, "m", WHY_SIZE);
/// `peg.clearance_ratio`.
pub const CLEARANCE_RATIO: FieldRange = FieldRange::new(
    "peg.clearance_ratio",
    1e-6,
    0.2,
    "",
    "(D - d)/D of a fit, from tight (1e-6) to loose (a fifth of the bore)",
);
/// `peg.length`.
pub const LENGTH: FieldRange = FieldRange::new("peg.length", 1e-6, 1e3, "m", WHY_SIZE);
/// `peg.rim_fillet` (at most half the peg radius `r`; the check uses the
/// scene's `r`).
pub const RIM_FILLET: FieldRange = FieldRange::new(
    "peg.rim_fillet",
    1e-7,
    250.0,
    "m",
    "a rounded rim, at most half the peg radius r = D (1 - c)/2",
);
/// `peg.mouth_fillet` (at most a quarter of the bore diameter `D`; the
/// check uses the scene's `D`).
pub const MOUTH_FILLET: FieldRange = FieldRange::new(
    "peg.mouth_fillet",
    1e-7,
    250.0,
    "m",
    "a rounded mouth (the stand-in for a chamfer), at most a quarter of the bore diameter D",
);
/// `peg.bore_depth`.
pub const BORE_DEPTH: FieldRange = FieldRange::new("peg.bore_depth", 1e-6, 1e3, "m", WHY_SIZE);
/// `peg.density`.
pub const DENSITY: FieldRange = FieldRange::new(
    "peg.density",
    1.0,
    1e5,
    "kg/m^3",
    "foams to beyond the densest metals (osmium: 22,600 kg/m^3)",
);
/// `peg.gravity`.
pub const GRAVITY: FieldRange = FieldRange::new("peg.gravity", 0.0, 1e3, "m/s^2", "none to 100 g");
/// `peg.friction`.
pub const FRICTION: FieldRange = FieldRange::new(
    "peg.friction",
    0.0,
    2.0,
    "",
    "Coulomb coefficients of material pairs lie below about 1.5",
);
/// `peg.slip_velocity`.
pub const SLIP_VELOCITY: FieldRange = FieldRange::new(
    "peg.slip_velocity",
    1e-9,
    1.0,
    "m/s",
    "the regularized friction's velocity scale: at 1 m/s an insertion at 1 cm/s feels 1 % of Coulomb's friction",
);
/// `peg.contact_damping`.
pub const CONTACT_DAMPING: FieldRange =
    FieldRange::new("peg.contact_damping", 0.0, 1e3, "s/m", WHY_CONTACT_DAMPING);
/// `peg.contact_stiffness`.
pub const CONTACT_STIFFNESS: FieldRange = FieldRange::new(
    "peg.contact_stiffness",
    1e3,
    1e15,
    "N/m^1.5",
    "a fixed Hertz k = 4/3 E* sqrt(R): steel on steel at R = 1 mm is about 5e9; the span runs from soft foams to far stiffer than any metal contact",
);
/// `peg.peg_material.youngs_modulus`.
pub const PEG_YOUNGS_MODULUS: FieldRange = FieldRange::new(
    "peg.peg_material.youngs_modulus",
    MIN_YOUNGS_MODULUS,
    MAX_YOUNGS_MODULUS,
    "Pa",
    "soft foams to ten times diamond",
);
/// `peg.hole_material.youngs_modulus`.
pub const HOLE_YOUNGS_MODULUS: FieldRange = FieldRange {
    field: "peg.hole_material.youngs_modulus",
    ..PEG_YOUNGS_MODULUS
};
/// `peg.peg_material.poisson_ratio`.
pub const PEG_POISSON_RATIO: FieldRange = FieldRange::new(
    "peg.peg_material.poisson_ratio",
    -0.99,
    0.499,
    "",
    "inside the bounds (-1, 1/2) of an isotropic solid; at -1, E* = E/(1 - nu^2) diverges",
);
/// `peg.hole_material.poisson_ratio`.
pub const HOLE_POISSON_RATIO: FieldRange = FieldRange {
    field: "peg.hole_material.poisson_ratio",
    ..PEG_POISSON_RATIO
};

/// The `[peg]` table.
pub const PEG: &[FieldRange] = &[
    HOLE_DIAMETER,
    CLEARANCE_RATIO,
    LENGTH,
    RIM_FILLET,
    MOUTH_FILLET,
    BORE_DEPTH,
    DENSITY,
    GRAVITY,
    FRICTION,
    SLIP_VELOCITY,
    CONTACT_DAMPING,
    CONTACT_STIFFNESS,
    PEG_YOUNGS_MODULUS,
    HOLE_YOUNGS_MODULUS,
    PEG_POISSON_RATIO,
    HOLE_POISSON_RATIO,
];

/// `wrist.centre_height` (within ten peg lengths of the tip; the check
/// uses the scene's length).
pub const CENTRE_HEIGHT: FieldRange = FieldRange::new(
    "wrist.centre_height",
    -1e4,
    1e4,
    "m",
    "the compliance centre within ten peg lengths of the tip",
);
/// `wrist.lateral_stiffness`.
pub const LATERAL_STIFFNESS: FieldRange = FieldRange::new(
    "wrist.lateral_stiffness",
    1.0,
    1e9,
    "N/m",
    WHY_WRIST_STIFFNESS,
);
/// `wrist.lateral_stiffness_y`.
pub const LATERAL_STIFFNESS_Y: FieldRange = FieldRange {
    field: "wrist.lateral_stiffness_y",
    ..LATERAL_STIFFNESS
};
/// `wrist.axial_stiffness`.
pub const AXIAL_STIFFNESS: FieldRange = FieldRange::new(
    "wrist.axial_stiffness",
    1.0,
    1e10,
    "N/m",
    WHY_WRIST_STIFFNESS,
);
/// `wrist.angular_stiffness`.
pub const ANGULAR_STIFFNESS: FieldRange = FieldRange::new(
    "wrist.angular_stiffness",
    1e-3,
    1e7,
    "N m/rad",
    WHY_WRIST_STIFFNESS,
);
/// `wrist.torsional_stiffness`.
pub const TORSIONAL_STIFFNESS: FieldRange = FieldRange {
    field: "wrist.torsional_stiffness",
    ..ANGULAR_STIFFNESS
};
/// `wrist.lateral_damping`.
pub const LATERAL_DAMPING: FieldRange = FieldRange::new(
    "wrist.lateral_damping",
    0.0,
    1e6,
    "N s/m",
    WHY_WRIST_DAMPING,
);
/// `wrist.axial_damping`.
pub const AXIAL_DAMPING: FieldRange = FieldRange {
    field: "wrist.axial_damping",
    ..LATERAL_DAMPING
};
/// `wrist.angular_damping` (angular and torsional).
pub const ANGULAR_DAMPING: FieldRange = FieldRange::new(
    "wrist.angular_damping",
    0.0,
    1e4,
    "N m s/rad",
    WHY_WRIST_DAMPING,
);

/// The `[wrist]` table.
pub const WRIST: &[FieldRange] = &[
    CENTRE_HEIGHT,
    LATERAL_STIFFNESS,
    LATERAL_STIFFNESS_Y,
    AXIAL_STIFFNESS,
    ANGULAR_STIFFNESS,
    TORSIONAL_STIFFNESS,
    LATERAL_DAMPING,
    AXIAL_DAMPING,
    ANGULAR_DAMPING,
];

/// `robot.lateral_error` (within two bore diameters; the check uses the
/// scene's `D`).
pub const LATERAL_ERROR: FieldRange = FieldRange::new(
    "robot.lateral_error",
    -2e3,
    2e3,
    "m",
    "the tip within two bore diameters D of the hole's axis",
);
/// `robot.lateral_error_direction_deg`.
pub const LATERAL_ERROR_DIRECTION: FieldRange = FieldRange::new(
    "robot.lateral_error_direction_deg",
    -360.0,
    360.0,
    "deg",
    WHY_ANGLE,
);
/// `robot.angular_error_deg`.
pub const ANGULAR_ERROR: FieldRange = FieldRange::new(
    "robot.angular_error_deg",
    -30.0,
    30.0,
    "deg",
    "a positioning robot's angular error",
);
/// `robot.tilt_direction_deg`.
pub const TILT_DIRECTION: FieldRange =
    FieldRange::new("robot.tilt_direction_deg", -360.0, 360.0, "deg", WHY_ANGLE);
/// `robot.start_height` (down to minus the seat depth; the check uses the
/// scene's seat depth).
pub const START_HEIGHT: FieldRange = FieldRange::new(
    "robot.start_height",
    -1e3,
    1.0,
    "m",
    "a start in the bore above the seat depth (negative) up to a metre above the top face",
);
/// `robot.speed`.
pub const SPEED: FieldRange = FieldRange::new(
    "robot.speed",
    0.0,
    10.0,
    "m/s",
    "a robot's descent, up to 10 m/s",
);
/// `robot.overtravel`.
pub const OVERTRAVEL: FieldRange = FieldRange::new(
    "robot.overtravel",
    0.0,
    1.0,
    "m",
    "the target below the seat, up to a metre",
);
/// `robot.precession_rate`.
pub const PRECESSION_RATE: FieldRange =
    FieldRange::new("robot.precession_rate", -1e4, 1e4, "rad/s", WHY_RATE);
/// `robot.spin_rate`.
pub const SPIN_RATE: FieldRange = FieldRange::new("robot.spin_rate", -1e4, 1e4, "rad/s", WHY_RATE);
/// `robot.spiral_pitch` (at most one bore diameter per turn; the check
/// uses the scene's `D`).
pub const SPIRAL_PITCH: FieldRange = FieldRange::new(
    "robot.spiral_pitch",
    0.0,
    1e3,
    "m",
    "a search spiral growing at most one bore diameter D per turn",
);
/// `robot.spiral_rate`.
pub const SPIRAL_RATE: FieldRange =
    FieldRange::new("robot.spiral_rate", -1e4, 1e4, "rad/s", WHY_RATE);
/// `robot.axial_force`.
pub const AXIAL_FORCE: FieldRange = FieldRange::new(
    "robot.axial_force",
    0.0,
    1e6,
    "N",
    "a pushing force up to a meganewton",
);

/// The `[robot]` table.
pub const ROBOT: &[FieldRange] = &[
    LATERAL_ERROR,
    LATERAL_ERROR_DIRECTION,
    ANGULAR_ERROR,
    TILT_DIRECTION,
    START_HEIGHT,
    SPEED,
    OVERTRAVEL,
    PRECESSION_RATE,
    SPIN_RATE,
    SPIRAL_PITCH,
    SPIRAL_RATE,
    AXIAL_FORCE,
];

/// `criteria.seat_depth` (below 0.999 of the bore depth; the check uses
/// the scene's bore).
pub const SEAT_DEPTH: FieldRange = FieldRange::new(
    "criteria.seat_depth",
    1e-6,
    999.0,
    "m",
    "a depth in the bore, below 0.999 peg.bore_depth",
);
/// `criteria.wrist_force_limit`.
pub const WRIST_FORCE_LIMIT: FieldRange = FieldRange::new(
    "criteria.wrist_force_limit",
    1e-6,
    1e7,
    "N",
    "a force limit, a micronewton to far beyond what the peg survives",
);
/// `criteria.contact_force_limit`.
pub const CONTACT_FORCE_LIMIT: FieldRange = FieldRange {
    field: "criteria.contact_force_limit",
    max: 1e8,
    ..WRIST_FORCE_LIMIT
};
/// `criteria.release_time`.
pub const RELEASE_TIME: FieldRange = FieldRange::new(
    "criteria.release_time",
    1e-5,
    1.0,
    "s",
    "the release test that tells a wedge from a jam, 10 us to a second",
);

/// The `[criteria]` table.
pub const CRITERIA: &[FieldRange] = &[
    SEAT_DEPTH,
    WRIST_FORCE_LIMIT,
    CONTACT_FORCE_LIMIT,
    RELEASE_TIME,
];
