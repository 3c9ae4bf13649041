//! [`Outputs`]: which functions of its dynamics a model's module contains.

/// Which functions a model's generated module contains.
///
/// With [`Outputs::adapter`] on, the functions the adapter needs are
/// generated whatever the other flags say.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Outputs {
    /// `rhs(x, p) -> xdot`: the first-order right-hand side ẋ = f(x, p).
    /// For a Lagrangian model it is emitted in closed form (Cramer's rule)
    /// for up to three degrees of freedom; beyond, the adapter solves
    /// M q̈ = f by LU at run time.
    pub rhs: bool,
    /// `dynamics(x, p) -> DynamicsOut { mass, forcing }`: M and f of
    /// M q̈ = f (Lagrangian models only).
    pub mass_forcing: bool,
    /// The exact Jacobian: `jacobian_terms(x, qdd, p)` (G with
    /// ∂ẋ/∂x = [[0, I], [M⁻¹G]]) for a Lagrangian model, `jacobian(x, p)`
    /// (∂f/∂x) for an explicit one.
    pub jacobian: bool,
    /// `energy(x, p) -> energy`: T + V for a Lagrangian model, the
    /// expression given to [`ModelBuilder::energy`](crate::ModelBuilder::energy) for an explicit one
    /// (none when it was not given).
    pub energy: bool,
    /// The ODE adapter `System` implementing `pegdyn::system::OdeSystem`
    /// and the layout constants (`X_<NAME>`, `X_DOCS`, `STATE_DIM`, ...).
    pub adapter: bool,
}

impl Outputs {
    /// Everything off: the model emits only the functions given to
    /// [`ModelBuilder::function`](crate::ModelBuilder::function) and [`ModelBuilder::output`](crate::ModelBuilder::output).
    pub const NONE: Outputs = Outputs {
        rhs: false,
        mass_forcing: false,
        jacobian: false,
        energy: false,
        adapter: false,
    };

    /// Every function of the dynamics, no adapter: what a model whose
    /// runtime wraps the functions itself (pegdyn's textbook systems) needs.
    pub const FUNCTIONS: Outputs = Outputs {
        rhs: true,
        mass_forcing: true,
        jacobian: true,
        energy: true,
        adapter: false,
    };
}

impl Default for Outputs {
    /// Everything on.
    fn default() -> Outputs {
        Outputs {
            adapter: true,
            ..Outputs::FUNCTIONS
        }
    }
}
