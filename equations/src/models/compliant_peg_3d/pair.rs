//! The contact pairs of the compliant 3-D peg. One file, compiled into
//! both the generator (`pegdyn_equations::models::compliant_peg_3d`) and
//! the runtime (`pegdyn::compliant_peg_3d`, through `#[path]`), so the two
//! cannot disagree on the pairs or their names. It uses nothing but `core`.

/// The contact pairs, each a function of the pose and one angle.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Pair {
    /// The hole's mouth-edge torus against the peg's cylindrical side.
    EdgeSide,
    /// The peg's bottom-rim torus against the bore wall.
    RimWall,
    /// The peg's bottom-rim torus against the block's top face.
    RimTop,
    /// The peg's bottom-rim torus against the bore bottom.
    RimBottom,
    /// The peg's bottom-rim torus against the hole's mouth-edge torus (a
    /// peg landing on, or leaning its rim on, the filleted mouth).
    RimEdge,
}

impl Pair {
    /// Every pair, in emission order.
    pub const ALL: [Pair; 5] = [
        Pair::EdgeSide,
        Pair::RimWall,
        Pair::RimTop,
        Pair::RimBottom,
        Pair::RimEdge,
    ];

    /// The generated function's name (also the CSV column and event name).
    pub fn name(self) -> &'static str {
        match self {
            Pair::EdgeSide => "edge_side",
            Pair::RimWall => "rim_wall",
            Pair::RimTop => "rim_top",
            Pair::RimBottom => "rim_bottom",
            Pair::RimEdge => "rim_edge",
        }
    }
}
