//! A throttled progress line on stderr for long runs, and one line saying
//! why when a run is unusually slow.
//!
//! The progress line is shown when stderr is a terminal and the user did
//! not pass `--quiet`, at most ten updates per second. The slow-run notice
//! is printed once, also with `--quiet` and on a pipe (a run that takes
//! minutes in silence looks hung), when the run has taken
//! [`SLOW_STEPS`] accepted steps (a count, the same on every machine) or
//! [`SLOW_AFTER`] of wall time: how far it is, the steps it took and
//! those it will take at this rate, the time left and the fastest time
//! scale of the scene, which sets the step ([`crate::scene::timescales`]).
//! [`Progress::silent`] prints neither (in-process runs, sweeps' inner
//! runs).

use std::io::{IsTerminal, Write};
use std::time::{Duration, Instant};

use crate::error::RunError;
use crate::integrate::Interrupt;
use crate::scene::numbers::significant;
use crate::scene::timescales::TimeScales;

/// Progress reporter handed to a running scene via its run context; it
/// also carries the run's stop request ([`Interrupt`]), which the
/// integrations of the run (`scene::simulate`) and its loops over
/// many runs ([`par_map_counted`]) look at.
#[derive(Debug)]
pub struct Progress {
    interrupt: Interrupt,
    enabled: bool,
    notices: bool,
    t0: f64,
    t_end: f64,
    last: Option<Instant>,
    shown: bool,
    started: Option<Instant>,
    /// Accepted steps reported since the span was set.
    steps: u64,
    noticed: bool,
    /// The scene's time scales and tolerances (what makes a run slow).
    scales: Option<TimeScales>,
}

/// Accepted steps after which a run is called unusually slow: the shipped
/// scenes take below 10⁴; 10⁵ steps of the compliant 3-D peg are some
/// tens of seconds.
pub const SLOW_STEPS: u64 = 100_000;

/// Wall time after which a run is called unusually slow (an implicit
/// method's steps cost far more than an explicit one's).
pub const SLOW_AFTER: Duration = Duration::from_secs(30);

/// The slow-run notice of a run that took `steps` accepted steps (or
/// `elapsed` of wall time) to reach simulated time `t` of `[t0, t_end]`;
/// `cause` is what sets the steps, in words ([`TimeScales::slow_cause`]). `None` until the
/// run is unusually slow ([`SLOW_STEPS`], [`SLOW_AFTER`]).
pub fn slow_notice(
    steps: u64,
    (t0, t, t_end): (f64, f64, f64),
    elapsed: Duration,
    cause: Option<&str>,
) -> Option<String> {
    if steps < SLOW_STEPS && elapsed < SLOW_AFTER {
        return None;
    }
    let span = t_end - t0;
    let fraction = if span > 0.0 {
        ((t - t0) / span).clamp(0.0, 1.0)
    } else {
        1.0
    };
    let rate = if fraction > 0.0 {
        let total = steps as f64 / fraction;
        format!(
            "; at this rate about {} steps in all (mean step {} s{})",
            significant(total.round()),
            significant((t - t0) / steps.max(1) as f64),
            eta(elapsed, fraction)
        )
    } else {
        "; the simulated time has not advanced".to_owned()
    };
    let why = cause.map_or_else(String::new, |c| format!("; what sets the steps: {c}"));
    Some(format!(
        "note: slow run: {steps} steps in {} s of wall time to t = {} s of {} s ({:.1}%){rate}{why}",
        elapsed.as_secs(),
        significant(t),
        significant(t_end),
        100.0 * fraction
    ))
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
    /// A reporter whose progress line prints only if `!quiet` and stderr
    /// is a terminal; the slow-run notice prints in any case.
    pub fn new(quiet: bool) -> Self {
        Progress {
            interrupt: Interrupt::new(),
            enabled: !quiet && std::io::stderr().is_terminal(),
            notices: true,
            t0: 0.0,
            t_end: 1.0,
            last: None,
            shown: false,
            started: None,
            steps: 0,
            noticed: false,
            scales: None,
        }
    }

    /// A reporter that never prints.
    pub fn silent() -> Self {
        let mut p = Progress::new(true);
        p.notices = false;
        p
    }

    /// Gives the slow-run notice the scene's time scales and tolerances:
    /// it names the tolerances when the steps are far below the fastest
    /// scale, else that scale ([`TimeScales::slow_cause`]).
    pub fn explain(&mut self, scales: Option<&TimeScales>) {
        self.scales = scales.cloned();
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
        self.steps = 0;
    }

    /// Reports simulated time `t`, s, after an accepted step (throttled;
    /// the slow-run notice once).
    pub fn update(&mut self, t: f64) {
        self.steps += 1;
        if self.notices && !self.noticed && self.steps % 64 == 0 {
            let elapsed = self.started.map_or(Duration::ZERO, |s| s.elapsed());
            let mean = (t - self.t0) / self.steps as f64;
            let cause = self.scales.as_ref().map(|s| s.slow_cause(mean));
            let span = (self.t0, t, self.t_end);
            if let Some(text) = slow_notice(self.steps, span, elapsed, cause.as_deref()) {
                self.print_notice(&text);
            }
        }
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

    /// Prints `text` on its own line (once), clearing the progress line.
    fn print_notice(&mut self, text: &str) {
        self.noticed = true;
        let mut err = std::io::stderr().lock();
        let clear = if self.shown { "\r" } else { "" };
        // Best effort, as the progress line.
        let _ = writeln!(err, "{clear}{text:80}");
        let _ = err.flush();
    }

    /// Reports `done` of `total` work items, e.g. runs of a sweep
    /// (throttled; the last one is always shown). After `SLOW_AFTER` of
    /// wall time with work left, one line says how far the work is.
    pub fn update_count(&mut self, done: usize, total: usize, what: &str) {
        let last = done >= total;
        if self.notices && !self.noticed && !last {
            let elapsed = self.started.map_or(Duration::ZERO, |s| s.elapsed());
            if elapsed >= SLOW_AFTER {
                let fraction = done as f64 / total.max(1) as f64;
                let text = format!(
                    "note: slow run: {done} of {total} {what}s done in {} s of wall time{}",
                    elapsed.as_secs(),
                    eta(elapsed, fraction)
                );
                self.print_notice(&text);
            }
        }
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
