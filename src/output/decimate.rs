//! Keeping a bounded copy of a streamed series for a plot: of `expected`
//! samples, every `k`-th with `k = ⌈expected / max_points⌉`, so that a plot
//! holds at most about `max_points` points however long the run (the CSV
//! gets every sample).
//!
//! ```
//! use pegdyn::output::decimate::Decimate;
//! let mut d = Decimate::new(1e6, 1000.0);
//! let kept = (0..1_000_000).filter(|_| d.keep()).count();
//! assert_eq!(kept, 1000);
//! ```

/// Points a plot keeps by default.
pub const PLOT_POINTS: f64 = 4000.0;

/// Decides which of a stream of samples a plot keeps.
#[derive(Debug, Clone)]
pub struct Decimate {
    every: u64,
    seen: u64,
}

impl Decimate {
    /// For a stream of about `expected` samples (an estimate, may be
    /// absurd or NaN: the stride is then 1), keeping at most about
    /// `max_points`.
    pub fn new(expected: f64, max_points: f64) -> Self {
        let every = (expected / max_points.max(1.0)).ceil();
        let every = if every.is_finite() && every >= 1.0 {
            every.min(u64::MAX as f64) as u64
        } else {
            1
        };
        Decimate { every, seen: 0 }
    }

    /// Whether to keep the next sample (the first always).
    pub fn keep(&mut self) -> bool {
        let keep = self.seen % self.every == 0;
        self.seen += 1;
        keep
    }

    /// The stride `k`.
    pub fn every(&self) -> u64 {
        self.every
    }
}
