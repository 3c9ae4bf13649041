//! The integration methods: [`Method`] as the engine runs it (RK4 with its
//! step) and [`MethodKind`], the one vocabulary of method names that scene
//! files, the CLI, benches and summaries read and print.

/// Which integration method, by name only (no step size): the vocabulary
/// shared by the engine ([`Method::kind`]) and every layer that names a
/// method in text.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MethodKind {
    /// Classical fixed-step Runge–Kutta 4 (needs a step `h`).
    Rk4,
    /// Dormand–Prince 5(4), adaptive, with dense output and events.
    Dopri5,
    /// Linearly implicit, L-stable Rosenbrock method RODAS3 (order 3(2)).
    Rodas3,
    /// Linearly implicit, L-stable Rosenbrock method RODAS4 (order 4(3)).
    Rodas4,
}

impl MethodKind {
    /// Every method, in the order names are listed in messages.
    pub const ALL: [MethodKind; 4] = [
        MethodKind::Rk4,
        MethodKind::Dopri5,
        MethodKind::Rodas3,
        MethodKind::Rodas4,
    ];

    /// Older spellings still accepted by [`MethodKind::from_name`]:
    /// (alias, method).
    pub const ALIASES: [(&'static str, MethodKind); 1] = [("rosenbrock", MethodKind::Rodas3)];

    /// The name as written in scene files and printed in summaries.
    pub fn name(self) -> &'static str {
        match self {
            MethodKind::Rk4 => "rk4",
            MethodKind::Dopri5 => "dopri5",
            MethodKind::Rodas3 => "rodas3",
            MethodKind::Rodas4 => "rodas4",
        }
    }

    /// The method called `name` (a name of [`MethodKind::ALL`] or an alias
    /// of [`MethodKind::ALIASES`]), if any.
    pub fn from_name(name: &str) -> Option<MethodKind> {
        MethodKind::ALL
            .into_iter()
            .find(|m| m.name() == name)
            .or_else(|| {
                MethodKind::ALIASES
                    .iter()
                    .find(|(alias, _)| *alias == name)
                    .map(|&(_, m)| m)
            })
    }

    /// Whether the method chooses its own step from `rtol`/`atol`.
    pub fn is_adaptive(self) -> bool {
        self != MethodKind::Rk4
    }

    /// The engine's method: `h` is the step of RK4 (`None` for RK4 gives
    /// `None`); the adaptive methods ignore it.
    pub fn with_step(self, h: Option<f64>) -> Option<Method> {
        Some(match self {
            MethodKind::Rk4 => Method::Rk4 { h: h? },
            MethodKind::Dopri5 => Method::Dopri5,
            MethodKind::Rodas3 => Method::Rodas3,
            MethodKind::Rodas4 => Method::Rodas4,
        })
    }
}

/// An integration method.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Method {
    /// Classical fourth-order Runge–Kutta with fixed step `h` (the last
    /// step is shortened to land on the end time). Tolerances are unused;
    /// a non-finite value stops the integration at once with
    /// [`StopReason::NonFinite`](super::StopReason::NonFinite).
    Rk4 {
        /// Step size (> 0), in time units.
        h: f64,
    },
    /// Adaptive Dormand–Prince 5(4) with PI step control and fourth-order
    /// dense output. The default for non-stiff problems.
    Dopri5,
    /// Adaptive L-stable Rosenbrock method RODAS3, order 3(2), one
    /// Jacobian and one LU factorization per step, cubic Hermite dense
    /// output. For stiff problems (stiff contacts, large damping).
    Rodas3,
    /// Adaptive L-stable Rosenbrock method RODAS4 (Hairer & Wanner),
    /// order 4(3), six stages, one Jacobian and one LU factorization per
    /// step, cubic Hermite dense output. For stiff problems at tighter
    /// tolerances than RODAS3 pays for.
    Rodas4,
}

impl Method {
    /// Which method, without its step.
    pub fn kind(&self) -> MethodKind {
        match self {
            Method::Rk4 { .. } => MethodKind::Rk4,
            Method::Dopri5 => MethodKind::Dopri5,
            Method::Rodas3 => MethodKind::Rodas3,
            Method::Rodas4 => MethodKind::Rodas4,
        }
    }

    /// Short name used in scene files, bench ids and CLI options
    /// ([`MethodKind::name`]).
    pub fn name(&self) -> &'static str {
        self.kind().name()
    }
}
