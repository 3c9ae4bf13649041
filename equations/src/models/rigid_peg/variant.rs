//! The four specializations of the rigid three-point peg, one generated
//! module each. This file is the one definition of [`Variant`]: the
//! generator uses it to specialize the derivation, and the runtime crate
//! includes the same file (`#[path]`) to pick the generated module, so the
//! names cannot drift apart. It depends on nothing, so that both crates
//! can compile it.

/// Which specialization of the rigid-peg model (and which generated
/// module) to use.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Variant {
    /// `rigid_peg`: γ and ψ (2 DOF), Coulomb friction.
    Full,
    /// `rigid_peg_frictionless`: γ and ψ, f = 0.
    Frictionless,
    /// `rigid_peg_planar`: γ only (ψ ≡ 0), one unknown N_B = N_B1 = N_B2,
    /// friction in the symmetry plane.
    Planar,
    /// `rigid_peg_planar_frictionless`: γ only, f = 0.
    PlanarFrictionless,
}

impl Variant {
    /// All variants, largest first.
    pub const ALL: [Variant; 4] = [
        Variant::Full,
        Variant::Frictionless,
        Variant::Planar,
        Variant::PlanarFrictionless,
    ];

    /// The generated module's name.
    pub fn module_name(self) -> &'static str {
        match self {
            Variant::Full => "rigid_peg",
            Variant::Frictionless => "rigid_peg_frictionless",
            Variant::Planar => "rigid_peg_planar",
            Variant::PlanarFrictionless => "rigid_peg_planar_frictionless",
        }
    }

    /// ψ ≡ 0 (one degree of freedom).
    pub fn is_planar(self) -> bool {
        matches!(self, Variant::Planar | Variant::PlanarFrictionless)
    }

    /// f is a parameter (not eliminated).
    pub fn has_friction(self) -> bool {
        matches!(self, Variant::Full | Variant::Planar)
    }
}
