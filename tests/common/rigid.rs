//! Fixtures shared by the rigid three-point peg tests: a grid of inclinations
//! and the loads.

use pegdyn::rigid_peg::{Loads, PegParams};

/// Inclinations γ (rad) from γ0 (1 + 1e-9) up to 1.2.
pub fn gammas(p: &PegParams) -> [f64; 5] {
    let g0 = p.gamma0();
    [g0 * (1.0 + 1e-9), g0 * (1.0 + 1e-6), 0.1, 0.5, 1.2]
}

/// Loads with every component nonzero (N m, N m, N).
pub fn loads() -> Loads {
    Loads {
        m_gamma: 0.02,
        m_psi: -0.01,
        force: [0.3, -0.2, 1.5],
    }
}

/// In-plane loads (no M_ψ, no lateral force at ψ = 0).
pub fn planar_loads() -> Loads {
    Loads {
        m_gamma: 0.02,
        m_psi: 0.0,
        force: [0.3, 0.0, 1.5],
    }
}
