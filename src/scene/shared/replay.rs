//! The `[replay]` table of the kinds that write a replay page
//! (`<scene>.html`, `docs/replay.md`): whether to write it, and, for the
//! grid kinds, which run it shows.
//!
//! ```toml
//! [replay]
//! page = true           # default; false writes no page (as `pegdyn run --no-replay`)
//! run = "worst"         # rotation_assist, design_margins: "worst" | "nominal" | a grid index
//! ```

use serde::Deserialize;
use serde::de::{self, Deserializer, Unexpected, Visitor};

use crate::error::{RunError, SceneError};
use crate::output::names::Part;
use crate::scene::context::RunContext;

fn yes() -> bool {
    true
}

/// The `[replay]` table of a kind with one run (`drop_3d`, `insert_rcc`,
/// `insert_compliant`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ReplayTable {
    /// Write `<scene>.html` (default true).
    #[serde(default = "yes")]
    pub page: bool,
}

impl Default for ReplayTable {
    fn default() -> Self {
        ReplayTable { page: true }
    }
}

impl ReplayTable {
    /// Whether this run writes its page: the scene's `replay.page` and the
    /// caller's wish ([`RunContext::replay_wanted`]: not with
    /// `--no-replay`, not in a sweep).
    pub fn wanted(&self, ctx: &RunContext) -> bool {
        self.page && ctx.replay_wanted()
    }
}

/// Which run of a grid kind the page shows (`replay.run`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RunChoice {
    /// The run of the `[robot]` table as written (`"nominal"`).
    Nominal,
    /// The first grid point, in the CSV's row order, that did not seat;
    /// when every point seated, the one that took longest (`"worst"`).
    Worst,
    /// Grid point `k` (row `k` of the CSV, from 0).
    Index(usize),
}

impl RunChoice {
    /// The words a scene writes for this choice.
    pub const NAMES: &'static str =
        "\"worst\", \"nominal\" or a grid index (0 for the CSV's first row)";

    /// Checks a grid index against the grid's `points`.
    ///
    /// # Errors
    /// `replay.run` past the last point, naming the grid's size.
    pub fn check(self, points: usize) -> Result<Self, SceneError> {
        match self {
            RunChoice::Index(k) if k >= points => Err(SceneError::invalid(
                "replay.run",
                k,
                format!(
                    "the grid has {points} points: a grid index runs from 0 to {}",
                    points.saturating_sub(1)
                ),
            )),
            other => Ok(other),
        }
    }

    /// The grid point this choice picks among runs whose outcomes are
    /// `(seated, end time)` in row order, with why in words; `None` for
    /// the nominal run (and for "worst" on an empty grid).
    pub fn pick(self, runs: &[(bool, f64)]) -> Option<(usize, &'static str)> {
        match self {
            RunChoice::Nominal => None,
            RunChoice::Index(k) => Some((k, "chosen by replay.run")),
            RunChoice::Worst => match runs.iter().position(|(seated, _)| !seated) {
                Some(k) => Some((k, "the first that did not seat")),
                None => (0..runs.len())
                    .reduce(|a, b| if runs[b].1 > runs[a].1 { b } else { a })
                    .map(|k| (k, "the slowest to seat: every point seated")),
            },
        }
    }
}

impl<'de> Deserialize<'de> for RunChoice {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct Choice;
        impl Visitor<'_> for Choice {
            type Value = RunChoice;
            fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str(RunChoice::NAMES)
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<RunChoice, E> {
                match v {
                    "worst" => Ok(RunChoice::Worst),
                    "nominal" => Ok(RunChoice::Nominal),
                    _ => Err(E::invalid_value(Unexpected::Str(v), &self)),
                }
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<RunChoice, E> {
                usize::try_from(v)
                    .map(RunChoice::Index)
                    .map_err(|_| E::invalid_value(Unexpected::Unsigned(v), &self))
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<RunChoice, E> {
                usize::try_from(v)
                    .map(RunChoice::Index)
                    .map_err(|_| E::invalid_value(Unexpected::Signed(v), &self))
            }
        }
        d.deserialize_any(Choice)
    }
}

/// The `[replay]` table of a grid kind (`rotation_assist`,
/// `design_margins`): the page shows one run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GridReplayTable {
    /// Write `<scene>.html` (default true).
    #[serde(default = "yes")]
    pub page: bool,
    /// Which run (default: the kind's, see its docs).
    pub run: Option<RunChoice>,
}

impl Default for GridReplayTable {
    fn default() -> Self {
        GridReplayTable {
            page: true,
            run: None,
        }
    }
}

impl GridReplayTable {
    /// Whether this run writes its page (as [`ReplayTable::wanted`]).
    pub fn wanted(&self, ctx: &RunContext) -> bool {
        self.page && ctx.replay_wanted()
    }
}

/// Writes `html` as the run's page, `<scene>.html`.
///
/// # Errors
/// The file cannot be written, or would replace the scene file.
pub fn write(ctx: &RunContext, html: &str) -> Result<(), RunError> {
    ctx.file(Part::Main, "html", html.as_bytes())?;
    Ok(())
}
