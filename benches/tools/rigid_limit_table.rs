//! The three-moduli convergence table of the compliant 3-D peg towards the
//! rigid three-point peg (Fig. 9 motion, γ̇ = −2 1/s), for ψ̇ = 10 1/s from
//! γ = 0.3 rad and ψ̇ = 0 from γ = 0.14 rad (where the rigid motion stops
//! needing a pulling K), at k = 2.4·10⁹, 2.4·10¹⁰, 2.4·10¹¹ N/m^{3/2}: the
//! largest difference of the contact forces from N_K, N_B1, N_B2 (over m g)
//! and of the contact points from K, B1, B2 (m), down to γ = 0.06 rad.
//! See `docs/compliant-peg-3d.md`.
//!
//! ```text
//! cargo run -p pegdyn-benches --bin rigid_limit_table
//! ```

#[path = "../../tests/common/prescribed_rigid.rs"]
mod prescribed_rigid;

use prescribed_rigid::{fillet, grid, run, worst};

fn main() {
    println!(
        "| ψ̇ (1/s) | k (N/m^1.5) | fillets (m) | max \\|N − N_rigid\\| / (m g) | max point distance (m) |"
    );
    println!("|---|---|---|---|---|");
    for (psidot, start, count, skip) in [(10.0, 0.3, 12, 2), (0.0, 0.14, 8, 0)] {
        for k in [2.4e9, 2.4e10, 2.4e11] {
            let rows = run(k, psidot, start, &grid(start, 0.06, count));
            let (force, point) = worst(&rows[skip..]);
            println!(
                "| {psidot} | {k:.1e} | {:.1e} | {force:.4} | {point:.2e} |",
                fillet(k)
            );
        }
    }
}
