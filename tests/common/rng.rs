//! SplitMix64, the seeded input source of the tests and (through
//! `#[path]`) of the benches: one definition, so both draw the same values.

#![allow(dead_code)]

/// SplitMix64: a seeded, dependency-free source of inputs.
pub struct Rng(pub u64);

impl Rng {
    /// Uniform in [0, 1).
    pub fn next_f64(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [lo, hi).
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next_f64()
    }

    /// A vector of `N` draws, each uniform in [lo, hi).
    pub fn vector<const N: usize>(&mut self, lo: f64, hi: f64) -> nalgebra::SVector<f64, N> {
        nalgebra::SVector::from_fn(|_, _| self.uniform(lo, hi))
    }
}
