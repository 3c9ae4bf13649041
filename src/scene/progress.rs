//! A throttled progress line on stderr for long runs.
//!
//! Quiet when stderr is not a terminal (pipes, tests, CI) or when the user
//! passed `--quiet`; at most ten updates per second otherwise.

use std::io::{IsTerminal, Write};
use std::time::{Duration, Instant};

use crate::error::RunError;
use crate::integrate::Interrupt;

/// Progress reporter handed to a running scene via its run context; it
/// also carries the run's stop request ([`Interrupt`]), which the
/// integrations of the run (`scene::simulate`) and its loops over
/// many runs ([`par_map_counted`]) look at.
#[derive(Debug)]
pub struct Progress {
    interrupt: Interrupt,
    enabled: bool,
    t0: f64,
    t_end: f64,
    last: Option<Instant>,
    shown: bool,
    started: Option<Instant>,
}

/// The estimated time left when `fraction` of the work took `elapsed`:
/// `elapsed (1 − f) / f`, e.g. `ETA 3m20s`; empty before any progress.
pub fn eta(elapsed: Duration, fraction: f64) -> String {
    if !(fraction > 0.0 && fraction < 1.0) {
        return String::new();
    }
    let left = elapsed.as_secs_f64() * (1.0 - fraction) / fraction;
    let s = left.round() as u64;
    if s >= 3600 {
        format!(", ETA {}h{:02}m", s / 3600, (s % 3600) / 60)
    } else if s >= 60 {
        format!(", ETA {}m{:02}s", s / 60, s % 60)
    } else {
        format!(", ETA {s}s")
    }
}

const EVERY: Duration = Duration::from_millis(100);

impl Progress {
    /// A reporter that prints only if `!quiet` and stderr is a terminal.
    pub fn new(quiet: bool) -> Self {
        Progress {
            interrupt: Interrupt::new(),
            enabled: !quiet && std::io::stderr().is_terminal(),
            t0: 0.0,
            t_end: 1.0,
            last: None,
            shown: false,
            started: None,
        }
    }

    /// A reporter that never prints.
    pub fn silent() -> Self {
        Progress::new(true)
    }

    /// The same reporter, stopping when `interrupt` is requested.
    #[must_use]
    pub fn with_interrupt(mut self, interrupt: Interrupt) -> Self {
        self.interrupt = interrupt;
        self
    }

    /// The run's stop request.
    pub fn interrupt(&self) -> &Interrupt {
        &self.interrupt
    }

    /// [`RunError::Interrupted`] once a stop was requested.
    ///
    /// # Errors
    /// The stop request.
    pub fn check_interrupt(&self) -> Result<(), RunError> {
        if self.interrupt.is_requested() {
            Err(RunError::Interrupted)
        } else {
            Ok(())
        }
    }

    /// Sets the simulated time span the percentage refers to.
    pub fn set_span(&mut self, t0: f64, t_end: f64) {
        self.t0 = t0;
        self.t_end = t_end;
        self.started = Some(Instant::now());
    }

    /// Reports simulated time `t`, s (throttled).
    pub fn update(&mut self, t: f64) {
        if !self.enabled || self.last.is_some_and(|l| l.elapsed() < EVERY) {
            return;
        }
        self.last = Some(Instant::now());
        let span = self.t_end - self.t0;
        let pct = if span > 0.0 {
            100.0 * ((t - self.t0) / span).clamp(0.0, 1.0)
        } else {
            100.0
        };
        let started = *self.started.get_or_insert_with(Instant::now);
        let left = eta(started.elapsed(), pct / 100.0);
        let mut err = std::io::stderr().lock();
        // Progress output is best effort: a failed write to stderr is ignored.
        let _ = write!(
            err,
            "\r  t = {t:.4e} s / {:.4e} s ({pct:5.1}%{left})   ",
            self.t_end
        );
        let _ = err.flush();
        self.shown = true;
    }

    /// Reports `done` of `total` work items, e.g. runs of a sweep
    /// (throttled; the last one is always shown).
    pub fn update_count(&mut self, done: usize, total: usize, what: &str) {
        let last = done >= total;
        if !self.enabled || (!last && self.last.is_some_and(|l| l.elapsed() < EVERY)) {
            return;
        }
        self.last = Some(Instant::now());
        let pct = 100.0 * done as f64 / total.max(1) as f64;
        let started = *self.started.get_or_insert_with(Instant::now);
        let left = eta(started.elapsed(), pct / 100.0);
        let mut err = std::io::stderr().lock();
        // Progress output is best effort: a failed write to stderr is ignored.
        let _ = write!(err, "\r  {what} {done}/{total} ({pct:5.1}%{left})   ");
        let _ = err.flush();
        self.shown = true;
    }

    /// Clears the progress line, if one was printed.
    pub fn finish(&mut self) {
        if self.shown {
            let _ = write!(std::io::stderr(), "\r{:80}\r", "");
            self.shown = false;
        }
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        self.finish();
    }
}

/// `f` over `items` in parallel (rayon), counting each finished item on
/// `progress` as `what` and finishing the line at the end; results in item
/// order. Once `progress`'s stop is requested no further item starts.
///
/// # Errors
/// [`RunError::Interrupted`] when a stop was requested before every item
/// ran.
pub fn par_map_counted<T: Sync, R: Send>(
    items: &[T],
    progress: &mut Progress,
    what: &str,
    f: impl Fn(&T) -> R + Sync + Send,
) -> Result<Vec<R>, RunError> {
    use rayon::prelude::*;
    use std::sync::Mutex;
    use std::sync::atomic::{AtomicUsize, Ordering};
    let total = items.len();
    let done = AtomicUsize::new(0);
    let interrupt = progress.interrupt().clone();
    let shared = Mutex::new(&mut *progress);
    let out: Option<Vec<R>> = items
        .par_iter()
        .map(|item| {
            if interrupt.is_requested() {
                return None;
            }
            let r = f(item);
            let n = done.fetch_add(1, Ordering::Relaxed) + 1;
            if let Ok(mut pr) = shared.lock() {
                pr.update_count(n, total, what);
            }
            Some(r)
        })
        .collect();
    progress.finish();
    out.ok_or(RunError::Interrupted)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicUsize, Ordering};

    #[test]
    fn eta_scales_elapsed_by_the_work_left() {
        assert_eq!(eta(Duration::from_secs(10), 0.25), ", ETA 30s");
        assert_eq!(eta(Duration::from_secs(100), 0.5), ", ETA 1m40s");
        assert_eq!(eta(Duration::from_secs(3600), 0.5), ", ETA 1h00m");
        assert_eq!(eta(Duration::from_secs(1), 0.0), "");
        assert_eq!(eta(Duration::from_secs(1), f64::NAN), "");
    }

    #[test]
    fn a_requested_stop_starts_no_further_item() {
        let mut progress = Progress::silent();
        let items: Vec<u32> = (0..64).collect();
        let all = par_map_counted(&items, &mut progress, "item", |i| i * 2).unwrap();
        assert_eq!(all[63], 126);
        progress.interrupt().request();
        let ran = AtomicUsize::new(0);
        let r = par_map_counted(&items, &mut progress, "item", |_| {
            ran.fetch_add(1, Ordering::Relaxed);
        });
        assert!(matches!(r, Err(RunError::Interrupted)));
        assert_eq!(ran.load(Ordering::Relaxed), 0);
        assert!(progress.check_interrupt().is_err());
    }
}
