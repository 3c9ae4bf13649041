//! The replay record as JSON, with each number written to the precision the
//! page needs (lengths to a nanometre, directions to 1e-4, forces to four
//! significant digits), so that a page of thousands of frames stays small.
//!
//! Layout (arrays of frames are flat, `n` frames):
//!
//! ```text
//! { "format": 1, "title", "subtitle", "view": "solid" | "section", "note",
//!   "geometry": { "peg_radius", "peg_length", "rim_fillet", "centre_height",
//!                 "hole_radius", "mouth_fillet", "bore_depth", "bottom", "compliance_height" },
//!   "exaggeration", "pairs": [names], "states": [labels],
//!   "t": [n], "centre": [3n], "orientation": [4n (x, y, z, w)],
//!   "robot": null | { "position": [3n], "orientation": [4n] },
//!   "state": [n indices into "states"],
//!   "contacts": [n arrays of 11 numbers per contact:
//!                pair, point (3), normal (3), normal force, friction (3)],
//!   "marks": [{ "t", "frame", "kind", "label" }],
//!   "series": [{ "panel", "name", "unit", "values": [n] }] }
//! ```
//!
//! The text is safe inside an HTML `<script>` element: `<` is written as
//! `\u003c`, so no `</script>` can end it early.

use super::error::ReplayError;
use super::record::{Frame, Replay};
use std::fmt::Write;

/// How a number is written.
#[derive(Clone, Copy)]
#[doc(hidden)]
pub enum Digits {
    /// A fixed number of decimals (an absolute resolution).
    Fixed(usize),
    /// A number of significant digits (a relative resolution).
    Significant(usize),
}

/// Decimals of lengths (m): a nanometre.
#[doc(hidden)]
pub const LENGTH: Digits = Digits::Fixed(9);
/// Decimals of quaternion components: 1e-9 rad.
#[doc(hidden)]
pub const ROTATION: Digits = Digits::Fixed(9);
/// Decimals of unit directions.
#[doc(hidden)]
pub const DIRECTION: Digits = Digits::Fixed(4);
/// Significant digits of forces and plotted values.
#[doc(hidden)]
pub const VALUE: Digits = Digits::Significant(5);
/// Significant digits of times: events a few ulps apart stay in order.
#[doc(hidden)]
pub const TIME: Digits = Digits::Significant(12);

/// `x` written with `digits`, trailing zeros dropped (`0` for a negative
/// zero).
#[doc(hidden)]
pub fn number(x: f64, digits: Digits) -> String {
    let s = match digits {
        Digits::Fixed(d) => {
            let s = format!("{x:.d$}");
            if s.contains('.') {
                s.trim_end_matches('0').trim_end_matches('.').to_string()
            } else {
                s
            }
        }
        Digits::Significant(n) => {
            if x == 0.0 {
                return "0".into();
            }
            let sci = format!("{:.*e}", n.saturating_sub(1), x);
            let (mantissa, exp) = sci.split_once('e').unwrap_or((&sci, "0"));
            let exp: i32 = exp.parse().unwrap_or(0);
            let trim = |s: &str| {
                if s.contains('.') {
                    s.trim_end_matches('0').trim_end_matches('.').to_string()
                } else {
                    s.to_string()
                }
            };
            // Plain decimals where they are no longer than the exponent form.
            if (-3..n as i32).contains(&exp) {
                let decimals = (n as i32 - 1 - exp).max(0) as usize;
                trim(&format!("{x:.decimals$}"))
            } else {
                format!("{}e{exp}", trim(mantissa))
            }
        }
    };
    if s == "-0" { "0".into() } else { s }
}

/// A JSON string literal of `s`, with `<` escaped.
#[doc(hidden)]
pub fn string(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '<' => out.push_str("\\u003c"),
            c if (c as u32) < 0x20 => {
                let _ = write!(out, "\\u{:04x}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// Numbers checked finite as they are written.
struct Numbers<'a> {
    out: &'a mut String,
    t: f64,
}

impl Numbers<'_> {
    fn push(&mut self, x: f64, digits: Digits, quantity: &'static str) -> Result<(), ReplayError> {
        if !x.is_finite() {
            return Err(ReplayError::NonFinite {
                quantity,
                t: self.t,
            });
        }
        if !self.out.ends_with('[') {
            self.out.push(',');
        }
        self.out.push_str(&number(x, digits));
        Ok(())
    }

    fn all<'x>(
        &mut self,
        xs: impl IntoIterator<Item = &'x f64>,
        digits: Digits,
        quantity: &'static str,
    ) -> Result<(), ReplayError> {
        xs.into_iter()
            .try_for_each(|&x| self.push(x, digits, quantity))
    }
}

/// `"key":[…]` of one number list over the frames.
fn column(
    out: &mut String,
    sep: &str,
    key: &str,
    frames: &[Frame],
    mut each: impl FnMut(&mut Numbers<'_>, &Frame) -> Result<(), ReplayError>,
) -> Result<(), ReplayError> {
    let _ = write!(out, "{sep}{}:[", string(key));
    for f in frames {
        each(&mut Numbers { out, t: f.t }, f)?;
    }
    out.push(']');
    Ok(())
}

/// The record as JSON.
///
/// # Errors
/// [`ReplayError::NoFrames`] without frames; [`ReplayError::NonFinite`]
/// naming the first non-finite number.
pub fn replay(r: &Replay) -> Result<String, ReplayError> {
    let frames = &r.frames;
    if frames.is_empty() {
        return Err(ReplayError::NoFrames);
    }
    let mut out = String::with_capacity(400 * frames.len() + 4096);
    let _ = write!(
        out,
        "{{\"format\":1,\"title\":{},\"subtitle\":{},\"view\":{},\"note\":{}",
        string(&r.title),
        string(&r.subtitle),
        string(r.view.name()),
        r.note().map_or("null".into(), |n| string(&n))
    );
    geometry(&mut out, r)?;
    let _ = write!(out, ",\"pairs\":[");
    let names: Vec<String> = r.pairs.iter().map(|p| string(p)).collect();
    out.push_str(&names.join(","));
    out.push(']');
    let mut labels: Vec<&str> = Vec::new();
    let state: Vec<f64> = frames
        .iter()
        .map(|f| {
            let i = labels
                .iter()
                .position(|l| *l == f.state)
                .unwrap_or_else(|| {
                    labels.push(&f.state);
                    labels.len() - 1
                });
            i as f64
        })
        .collect();
    let quoted: Vec<String> = labels.iter().map(|l| string(l)).collect();
    let _ = write!(out, ",\"states\":[{}]", quoted.join(","));
    column(&mut out, ",", "t", frames, |n, f| n.push(f.t, TIME, "time"))?;
    column(&mut out, ",", "centre", frames, |n, f| {
        n.all(f.centre.iter(), LENGTH, "peg position")
    })?;
    column(&mut out, ",", "orientation", frames, |n, f| {
        n.all(f.orientation.coords.iter(), ROTATION, "peg orientation")
    })?;
    robot(&mut out, frames)?;
    let mut i = 0;
    column(&mut out, ",", "state", frames, |n, _| {
        i += 1;
        n.push(state[i - 1], Digits::Fixed(0), "contact state")
    })?;
    contacts(&mut out, frames)?;
    marks(&mut out, r)?;
    series(&mut out, r)?;
    out.push('}');
    Ok(out)
}

fn geometry(out: &mut String, r: &Replay) -> Result<(), ReplayError> {
    let g = &r.geometry;
    let bad = || ReplayError::NonFinite {
        quantity: "geometry",
        t: f64::NAN,
    };
    let fields = [
        ("peg_radius", g.peg_radius),
        ("peg_length", g.peg_length),
        ("rim_fillet", g.rim_fillet),
        ("centre_height", g.centre_height),
        ("hole_radius", g.hole_radius),
        ("mouth_fillet", g.mouth_fillet),
        ("bore_depth", g.bore_depth),
    ];
    out.push_str(",\"geometry\":{");
    for (k, (name, v)) in fields.iter().enumerate() {
        if !v.is_finite() {
            return Err(bad());
        }
        let sep = if k == 0 { "" } else { "," };
        let _ = write!(out, "{sep}{}:{}", string(name), number(*v, LENGTH));
    }
    let lc = match g.compliance_height {
        Some(v) if v.is_finite() => number(v, LENGTH),
        Some(_) => return Err(bad()),
        None => "null".into(),
    };
    let _ = write!(
        out,
        ",\"bottom\":{},\"compliance_height\":{lc}}}",
        g.bore_bottom
    );
    if !r.exaggeration.is_finite() {
        return Err(bad());
    }
    let _ = write!(out, ",\"exaggeration\":{}", number(r.exaggeration, VALUE));
    Ok(())
}

fn robot(out: &mut String, frames: &[Frame]) -> Result<(), ReplayError> {
    if frames.iter().any(|f| f.robot.is_none()) {
        out.push_str(",\"robot\":null");
        return Ok(());
    }
    out.push_str(",\"robot\":{");
    column(out, "", "position", frames, |n, f| match &f.robot {
        Some((p, _)) => n.all(p.iter(), LENGTH, "robot frame position"),
        None => Ok(()),
    })?;
    column(out, ",", "orientation", frames, |n, f| match &f.robot {
        Some((_, q)) => n.all(q.coords.iter(), ROTATION, "robot frame orientation"),
        None => Ok(()),
    })?;
    out.push('}');
    Ok(())
}

fn contacts(out: &mut String, frames: &[Frame]) -> Result<(), ReplayError> {
    out.push_str(",\"contacts\":[");
    for (k, f) in frames.iter().enumerate() {
        if k > 0 {
            out.push(',');
        }
        out.push('[');
        let mut n = Numbers { out, t: f.t };
        for c in &f.contacts {
            n.push(c.pair as f64, Digits::Fixed(0), "contact pair")?;
            n.all(c.point.iter(), LENGTH, "contact point")?;
            n.all(c.normal.iter(), DIRECTION, "contact normal")?;
            n.push(c.normal_force, VALUE, "contact normal force")?;
            n.all(c.friction.iter(), VALUE, "friction force")?;
        }
        n.out.push(']');
    }
    out.push(']');
    Ok(())
}

fn marks(out: &mut String, r: &Replay) -> Result<(), ReplayError> {
    out.push_str(",\"marks\":[");
    for (k, m) in r.marks.iter().enumerate() {
        if !m.t.is_finite() {
            return Err(ReplayError::NonFinite {
                quantity: "event time",
                t: m.t,
            });
        }
        // The frame at the mark's time (the record holds one; the nearest
        // otherwise).
        let frame = r
            .frames
            .partition_point(|f| f.t < m.t)
            .min(r.frames.len() - 1);
        let sep = if k == 0 { "" } else { "," };
        let _ = write!(
            out,
            "{sep}{{\"t\":{},\"frame\":{frame},\"kind\":{},\"label\":{}}}",
            number(r.frames[frame].t, TIME),
            string(m.kind.name()),
            string(&m.label)
        );
    }
    out.push(']');
    Ok(())
}

fn series(out: &mut String, r: &Replay) -> Result<(), ReplayError> {
    out.push_str(",\"series\":[");
    for (k, s) in r.series.iter().enumerate() {
        let sep = if k == 0 { "" } else { "," };
        let _ = write!(
            out,
            "{sep}{{\"panel\":{},\"name\":{},\"unit\":{}",
            string(s.panel.name()),
            string(&s.name),
            string(s.unit)
        );
        column(out, ",", "values", &r.frames, |n, f| {
            let v = f.values.get(k).copied().unwrap_or(f64::NAN);
            n.push(v, VALUE, "plotted value")
        })?;
        out.push('}');
    }
    out.push(']');
    Ok(())
}
