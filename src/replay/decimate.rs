//! Which states of a run become frames: a bounded number, every event
//! state among them.
//!
//! Of `n` states in time order, each with a [`Keep`] priority, the kept
//! set is: every [`Keep::Always`] state and the first and last; the
//! [`Keep::Event`] states, every `k`-th of them when there are more than
//! [`Budget::max_marks`]; then every `j`-th of the remaining samples with
//! `j = ⌈remaining / room⌉`, `room` what is left of
//! [`Budget::max_frames`].
//!
//! ```
//! use pegdyn::replay::decimate::{Budget, Keep, keep};
//! let mut priority = vec![Keep::Sample; 100_000];
//! priority[12_345] = Keep::Event;
//! let kept = keep(&priority, Budget { max_frames: 1000, max_marks: 100 });
//! assert!(kept.len() <= 1000 && kept.contains(&12_345));
//! assert_eq!((kept[0], *kept.last().unwrap()), (0, 99_999));
//! ```

/// How much a state must be kept.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Keep {
    /// An output sample: kept as room allows.
    Sample,
    /// A contact transition: kept unless there are more than
    /// [`Budget::max_marks`].
    Event,
    /// A state that ends the run (a seat, a force limit, the final state):
    /// always kept.
    Always,
}

/// The bounds of a replay.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Budget {
    /// Most frames drawn.
    pub max_frames: usize,
    /// Most event marks.
    pub max_marks: usize,
}

impl Default for Budget {
    /// 2,000 frames, 1,000 events: the shipped 3-D insertion's page stays
    /// under 2 MB with its renderer.
    fn default() -> Self {
        Budget {
            max_frames: 2000,
            max_marks: 1000,
        }
    }
}

/// Every `stride`-th element of `items`, `stride = ⌈len / room⌉` (none
/// when `room` is 0).
fn spread(items: &[usize], room: usize) -> impl Iterator<Item = usize> + '_ {
    let stride = if room == 0 {
        usize::MAX
    } else {
        items.len().div_ceil(room).max(1)
    };
    items
        .iter()
        .step_by(stride.min(items.len().max(1)))
        .take(room)
        .copied()
}

/// The indices (increasing) of the states to keep, of states with
/// priorities `priority` in time order.
pub fn keep(priority: &[Keep], budget: Budget) -> Vec<usize> {
    let n = priority.len();
    if n == 0 {
        return Vec::new();
    }
    let mut kept: Vec<usize> = (0..n)
        .filter(|&i| priority[i] == Keep::Always || i == 0 || i == n - 1)
        .collect();
    let events: Vec<usize> = (0..n)
        .filter(|&i| priority[i] == Keep::Event && i != 0 && i != n - 1)
        .collect();
    let room = budget.max_marks.saturating_sub(kept.len()).max(1);
    kept.extend(spread(&events, room));
    kept.sort_unstable();
    let samples: Vec<usize> = (0..n)
        .filter(|&i| priority[i] == Keep::Sample && kept.binary_search(&i).is_err())
        .collect();
    let room = budget.max_frames.saturating_sub(kept.len());
    kept.extend(spread(&samples, room));
    kept.sort_unstable();
    kept.dedup();
    kept
}
