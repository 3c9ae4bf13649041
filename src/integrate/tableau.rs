//! Explicit Runge–Kutta methods as data (Butcher tableaux).
//!
//! One engine (`integrate/explicit_rk.rs`) runs every tableau here; the tests in
//! `tests/integrate/integrators.rs` check each against the Runge–Kutta order
//! conditions (Hairer, Nørsett & Wanner, *Solving ODEs I*, §II.2, Table 2.2).

/// How a method interpolates inside an accepted step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DenseKind {
    /// Cubic Hermite interpolation of the step end points and slopes
    /// (third order; used when the method has no continuous extension).
    Hermite,
    /// The fourth-order continuous extension of Dormand–Prince 5(4)
    /// (Hairer, Nørsett & Wanner I, §II.6, eq. (6.12) ff.; coefficients of
    /// Shampine's dense output in Hairer's `DOPRI5`).
    Dopri5,
}

/// An explicit Runge–Kutta method with `S` stages:
/// `kᵢ = f(t + cᵢh, x + h Σⱼ<ᵢ aᵢⱼ kⱼ)`, `x₁ = x + h Σ bᵢ kᵢ`.
#[derive(Debug, Clone, PartialEq)]
pub struct Tableau<const S: usize> {
    /// Method name as used in bench ids and CLI options.
    pub name: &'static str,
    /// Strictly lower-triangular stage matrix `A`.
    pub a: [[f64; S]; S],
    /// Weights `b` of the propagated solution.
    pub b: [f64; S],
    /// Nodes `c` (`cᵢ = Σⱼ aᵢⱼ`).
    pub c: [f64; S],
    /// Weights `b̂` of the embedded solution used only for the error
    /// estimate `h Σ (bᵢ − b̂ᵢ) kᵢ`; `None` for fixed-step methods.
    pub b_embedded: Option<[f64; S]>,
    /// Classical order of `b`.
    pub order: u32,
    /// Order of the embedded weights (0 when there are none).
    pub embedded_order: u32,
    /// First-same-as-last: the last stage is evaluated at `x₁`
    /// (`a[S-1] == b`, `c[S-1] == 1`), so `f(t + h, x₁)` comes for free.
    pub fsal: bool,
    /// The interpolant used for dense output and event location.
    pub dense: DenseKind,
}

impl Tableau<4> {
    /// The classical fourth-order Runge–Kutta method (fixed step).
    pub const fn rk4() -> Self {
        Tableau {
            name: "rk4",
            a: [
                [0.0, 0.0, 0.0, 0.0],
                [0.5, 0.0, 0.0, 0.0],
                [0.0, 0.5, 0.0, 0.0],
                [0.0, 0.0, 1.0, 0.0],
            ],
            b: [1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0],
            c: [0.0, 0.5, 0.5, 1.0],
            b_embedded: None,
            order: 4,
            embedded_order: 0,
            fsal: false,
            dense: DenseKind::Hermite,
        }
    }
}

impl Tableau<7> {
    /// Dormand & Prince (1980) 5(4), "DOPRI5": seven stages, FSAL, local
    /// extrapolation with the fifth-order weights, fourth-order embedded
    /// weights for the error estimate (Hairer, Nørsett & Wanner I, Table 5.2).
    pub const fn dopri5() -> Self {
        Tableau {
            name: "dopri5",
            a: [
                [0.0; 7],
                [1.0 / 5.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
                [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0, 0.0],
                [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0, 0.0],
                [
                    19372.0 / 6561.0,
                    -25360.0 / 2187.0,
                    64448.0 / 6561.0,
                    -212.0 / 729.0,
                    0.0,
                    0.0,
                    0.0,
                ],
                [
                    9017.0 / 3168.0,
                    -355.0 / 33.0,
                    46732.0 / 5247.0,
                    49.0 / 176.0,
                    -5103.0 / 18656.0,
                    0.0,
                    0.0,
                ],
                DOPRI5_B,
            ],
            b: DOPRI5_B,
            c: [0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0],
            b_embedded: Some([
                5179.0 / 57600.0,
                0.0,
                7571.0 / 16695.0,
                393.0 / 640.0,
                -92097.0 / 339200.0,
                187.0 / 2100.0,
                1.0 / 40.0,
            ]),
            order: 5,
            embedded_order: 4,
            fsal: true,
            dense: DenseKind::Dopri5,
        }
    }
}

/// Fifth-order weights of DOPRI5 (also its last stage row: FSAL).
const DOPRI5_B: [f64; 7] = [
    35.0 / 384.0,
    0.0,
    500.0 / 1113.0,
    125.0 / 192.0,
    -2187.0 / 6784.0,
    11.0 / 84.0,
    0.0,
];

/// Coefficients `d` of the DOPRI5 dense output (Hairer's `CONTD5`): the
/// fifth term of the interpolant is `h Σ dᵢ kᵢ` (stages 2 has weight 0).
pub const DOPRI5_DENSE_D: [f64; 7] = [
    -12715105075.0 / 11282082432.0,
    0.0,
    87487479700.0 / 32700410799.0,
    -10690763975.0 / 1880347072.0,
    701980252875.0 / 199316789632.0,
    -1453857185.0 / 822651844.0,
    69997945.0 / 29380423.0,
];

/// The weights `wᵢ(θ)` of the DOPRI5 continuous extension, so that
/// `x(t + θh) = x + h Σ wᵢ(θ) kᵢ` for `θ ∈ [0, 1]`.
///
/// Expanded from Hairer's `CONTD5` form
/// `x + θ(Δ + (1−θ)(hk₁ − Δ + θ(2Δ − hk₁ − hk₇ + (1−θ) h Σ dᵢkᵢ)))`,
/// `Δ = h Σ bᵢkᵢ`; it is of order 4 for every `θ` and reproduces the
/// fifth-order step at `θ = 1`.
pub fn dopri5_dense_weights(theta: f64) -> [f64; 7] {
    let b = DOPRI5_B;
    let d = DOPRI5_DENSE_D;
    let s = 1.0 - theta;
    let mut w = [0.0; 7];
    for i in 0..7 {
        let first = if i == 0 { 1.0 } else { 0.0 };
        let last = if i == 6 { 1.0 } else { 0.0 };
        w[i] = theta * b[i]
            + theta * s * (first - b[i])
            + theta * theta * s * (2.0 * b[i] - first - last)
            + theta * theta * s * s * d[i];
    }
    w
}

/// A Rosenbrock method with `S` stages in the form of Hairer & Wanner II,
/// §IV.7, eq. (7.4):
/// `(I − hγJ) kᵢ = h f(t + αᵢh, x + Σⱼ<ᵢ αᵢⱼkⱼ) + hJ Σⱼ<ᵢ γᵢⱼkⱼ + γᵢh² ∂f/∂t`,
/// `x₁ = x + Σ bᵢkᵢ`, with `αᵢ = Σⱼ αᵢⱼ`, `γᵢ = γ + Σⱼ<ᵢ γᵢⱼ`.
///
/// The stepper (`integrate/rosenbrock.rs`) runs the equivalent transformed form
/// (eq. (7.25)) whose coefficients it derives from these once.
#[derive(Debug, Clone, PartialEq)]
pub struct RosenbrockTableau<const S: usize> {
    /// Method name as used in bench ids and CLI options.
    pub name: &'static str,
    /// Diagonal coefficient γ (the same for every stage).
    pub gamma: f64,
    /// Strictly lower-triangular `αᵢⱼ`.
    pub alpha: [[f64; S]; S],
    /// Strictly lower-triangular `γᵢⱼ` (the diagonal is [`Self::gamma`]).
    pub gamma_lower: [[f64; S]; S],
    /// Weights `b` of the propagated solution.
    pub b: [f64; S],
    /// Weights `b̂` of the embedded solution (error estimate only).
    pub b_embedded: [f64; S],
    /// Order of `b` (with the exact Jacobian).
    pub order: u32,
    /// Order of `b̂`.
    pub embedded_order: u32,
}

impl RosenbrockTableau<4> {
    /// RODAS3 (Sandu et al., *Atmos. Environ.* 31 (1997) 3459, "Rodas3"):
    /// four stages, order 3 with embedded order 2, stiffly accurate and
    /// L-stable (`R(∞) = 0`), γ = 1/2. Coefficients converted from the
    /// transformed form of that paper (`A`, `C`, `M`, `E`) to eq. (7.4) by
    /// `Γ = (diag(1/γ) − C)⁻¹`, `α = AΓ`, `b = MΓ`, `b̂ = (M − E)Γ`; the
    /// tests check them against the Rosenbrock order conditions.
    pub const fn rodas3() -> Self {
        RosenbrockTableau {
            name: "rodas3",
            gamma: 0.5,
            alpha: [
                [0.0; 4],
                [0.0; 4],
                [1.0, 0.0, 0.0, 0.0],
                [0.75, -0.25, 0.5, 0.0],
            ],
            gamma_lower: [
                [0.0; 4],
                [1.0, 0.0, 0.0, 0.0],
                [-0.25, -0.25, 0.0, 0.0],
                [1.0 / 12.0, 1.0 / 12.0, -2.0 / 3.0, 0.0],
            ],
            b: [5.0 / 6.0, -1.0 / 6.0, -1.0 / 6.0, 0.5],
            b_embedded: [0.75, -0.25, 0.5, 0.0],
            order: 3,
            embedded_order: 2,
        }
    }
}

/// Coefficients of a Rosenbrock method in the transformed form of Hairer &
/// Wanner II, §IV.7, eq. (7.25) (the form in which RODAS-type codes print
/// them): strictly lower-triangular `A = (aᵢⱼ)`, `C = (cᵢⱼ)`, solution weights
/// `M` and error weights `E` (`x₁ − x̂₁ = Σ Eᵢuᵢ`).
#[derive(Debug, Clone, PartialEq)]
pub struct TransformedCoefficients<const S: usize> {
    /// Diagonal coefficient γ.
    pub gamma: f64,
    /// Stage matrix `A` (strictly lower triangular).
    pub a: [[f64; S]; S],
    /// Coupling matrix `C` (strictly lower triangular).
    pub c: [[f64; S]; S],
    /// Solution weights `M`.
    pub m: [f64; S],
    /// Error weights `E`.
    pub e: [f64; S],
}

impl<const S: usize> RosenbrockTableau<S> {
    /// The tableau of eq. (7.4) equivalent to transformed coefficients:
    /// `Γ = (diag(1/γ) − C)⁻¹` (lower triangular, by forward substitution),
    /// `α = AΓ`, `b = MΓ`, `b̂ = (M − E)Γ`, `γᵢⱼ = Γᵢⱼ` below the diagonal.
    #[allow(clippy::needless_range_loop)] // triangular index ranges
    pub fn from_transformed(
        name: &'static str,
        t: &TransformedCoefficients<S>,
        order: u32,
        embedded_order: u32,
    ) -> Self {
        // L = diag(1/γ) − C; solve L Γ = I column by column.
        let mut big_gamma = [[0.0; S]; S];
        for col in 0..S {
            for i in col..S {
                let rhs = if i == col { 1.0 } else { 0.0 };
                let s: f64 = (col..i).map(|k| t.c[i][k] * big_gamma[k][col]).sum();
                big_gamma[i][col] = (rhs + s) * t.gamma;
            }
        }
        let times_gamma = |v: &[f64; S]| {
            let mut out = [0.0; S];
            for (j, o) in out.iter_mut().enumerate() {
                *o = (0..S).map(|k| v[k] * big_gamma[k][j]).sum();
            }
            out
        };
        let mut alpha = [[0.0; S]; S];
        let mut gamma_lower = [[0.0; S]; S];
        for i in 0..S {
            alpha[i] = times_gamma(&t.a[i]);
            for j in 0..i {
                gamma_lower[i][j] = big_gamma[i][j];
            }
            // A is strictly lower triangular, so α is too (rounding aside).
            for a in alpha[i].iter_mut().skip(i) {
                *a = 0.0;
            }
        }
        let mut m_hat = t.m;
        for (mh, e) in m_hat.iter_mut().zip(t.e) {
            *mh -= e;
        }
        RosenbrockTableau {
            name,
            gamma: t.gamma,
            alpha,
            gamma_lower,
            b: times_gamma(&t.m),
            b_embedded: times_gamma(&m_hat),
            order,
            embedded_order,
        }
    }
}

/// RODAS4 in the transformed form of Hairer & Wanner II, §IV.7 (their code
/// `RODAS`, method 1; Table 7.2 family): six stages, γ = 1/4, stiffly
/// accurate (the last two stages evaluate at `α = 1`, `x₁` is the sixth
/// stage point plus `u₆`, the embedded solution the fifth), order 4 with an
/// embedded order-3 solution, L-stable. Stage nodes `αᵢ = (0, 0.386, 0.21,
/// 0.63, 1, 1)` and `γᵢ = (1/4, −0.1043, 0.1035, −0.0362, 0, 0)` follow from
/// these; `tests/integrate/rosenbrock.rs` checks them and the order conditions.
pub const RODAS4_TRANSFORMED: TransformedCoefficients<6> = {
    const A51: f64 = 1.221224509226641;
    const A52: f64 = 6.019134481288629;
    const A53: f64 = 12.53708332932087;
    const A54: f64 = -0.687886036105895;
    TransformedCoefficients {
        gamma: 0.25,
        a: [
            [0.0; 6],
            [1.544, 0.0, 0.0, 0.0, 0.0, 0.0],
            [0.9466785280815826, 0.2557011698983284, 0.0, 0.0, 0.0, 0.0],
            [
                3.314825187068521,
                2.896124015972201,
                0.9986419139977817,
                0.0,
                0.0,
                0.0,
            ],
            [A51, A52, A53, A54, 0.0, 0.0],
            [A51, A52, A53, A54, 1.0, 0.0],
        ],
        c: [
            [0.0; 6],
            [-5.6688, 0.0, 0.0, 0.0, 0.0, 0.0],
            [-2.430093356833875, -0.2063599157091915, 0.0, 0.0, 0.0, 0.0],
            [
                -0.1073529058151375,
                -9.594562251023355,
                -20.47028614809616,
                0.0,
                0.0,
                0.0,
            ],
            [
                7.496443313967647,
                -10.24680431464352,
                -33.99990352819905,
                11.7089089320616,
                0.0,
                0.0,
            ],
            [
                8.083246795921522,
                -7.981132988064893,
                -31.52159432874371,
                16.31930543123136,
                -6.058818238834054,
                0.0,
            ],
        ],
        m: [A51, A52, A53, A54, 1.0, 1.0],
        e: [0.0, 0.0, 0.0, 0.0, 0.0, 1.0],
    }
};

impl RosenbrockTableau<6> {
    /// RODAS4 ([`RODAS4_TRANSFORMED`]) in the form of eq. (7.4).
    pub fn rodas4() -> Self {
        RosenbrockTableau::from_transformed("rodas4", &RODAS4_TRANSFORMED, 4, 3)
    }
}
