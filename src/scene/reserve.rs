//! Fallible reservations for results whose size a scene sets: a failed
//! reservation is an error naming the `[limits]` key that bounds the size
//! ([`ReserveError`]), never the abort of a failed allocation. Re-exported
//! by [`super::limits`].
//!
//! ```
//! use pegdyn::scene::limits::try_with_capacity;
//! let v: Vec<f64> = try_with_capacity(1000, "output samples", "max_output_samples").unwrap();
//! assert!(v.capacity() >= 1000);
//! let e = try_with_capacity::<f64>(usize::MAX, "output samples", "max_output_samples").unwrap_err();
//! assert!(e.to_string().contains("max_output_samples"), "{e}");
//! ```

/// Memory for a result whose size the scene sets could not be reserved:
/// the limits were raised past what the machine (or the process's memory
/// cap) has. Returned instead of the abort of a failed allocation.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error(
    "cannot reserve memory for {count} {what} (about {mib:.3e} MiB; bounded by `[limits] {limit}`, \
     raised past what this machine can hold): lower `--limit {limit}=...` or the scene's size",
    mib = bytes / (1024.0 * 1024.0)
)]
pub struct ReserveError {
    /// What was to be stored, e.g. `output samples`.
    pub what: &'static str,
    /// How many.
    pub count: usize,
    /// Bytes asked for.
    pub bytes: f64,
    /// The `[limits]` key that bounds the count.
    pub limit: &'static str,
}

/// An empty vector with room for `count` items, or a [`ReserveError`]
/// naming `what` and the `limit` that bounds `count` when the memory is not
/// there (instead of the process aborting).
///
/// # Errors
/// The reservation failed.
pub fn try_with_capacity<T>(
    count: usize,
    what: &'static str,
    limit: &'static str,
) -> Result<Vec<T>, ReserveError> {
    let mut v = Vec::new();
    v.try_reserve_exact(count).map_err(|_| ReserveError {
        what,
        count,
        bytes: count as f64 * std::mem::size_of::<T>() as f64,
        limit,
    })?;
    Ok(v)
}
