//! The jamming diagram as a figure in the style of the paper's Fig. 6: per
//! (c, μ) one panel in the plane (F_x/F_z, M/(r F_z)) with, per depth, the
//! exact parallelogram (solid) and Whitney's (dashed) in the same colour.

use crate::jamming::diagram::Parallelogram;
use crate::jamming::table::{CornerRow, DiagramKind};
use crate::output::plot::{Panel, Series, Style};

/// Closed polyline through a parallelogram's corners.
pub fn outline(corners: &[[f64; 2]]) -> Vec<(f64, f64)> {
    let mut pts: Vec<(f64, f64)> = corners.iter().map(|q| (q[0], q[1])).collect();
    if let Some(&first) = pts.first() {
        pts.push(first);
    }
    pts
}

/// Axis labels of the diagram.
pub const X_LABEL: &str = "F_x / F_z";
/// Vertical axis label (moment about the peg tip).
pub const Y_LABEL: &str = "M / (r F_z)";

/// One panel per (c, μ) from the corner table, depths in table order.
pub fn panels(rows: &[CornerRow]) -> Vec<Panel> {
    let mut panels: Vec<((f64, f64), Panel)> = Vec::new();
    for chunk in rows.chunks(4) {
        let row = chunk[0];
        let key = (row.c, row.mu);
        let idx = match panels.iter().position(|(k, _)| *k == key) {
            Some(i) => i,
            None => {
                let title = format!("jamming diagram, c = {}, mu = {}", row.c, row.mu);
                panels.push((key, Panel::new(&title, X_LABEL, Y_LABEL)));
                panels.len() - 1
            }
        };
        let panel = &mut panels[idx].1;
        let depth_index = depth_colour(panel, row.l);
        let corners: Vec<[f64; 2]> = chunk.iter().map(|r| r.corner).collect();
        let (name, style) = match row.kind {
            DiagramKind::Exact => (format!("l = {} mm exact", row.l * 1e3), Style::Solid),
            DiagramKind::Whitney => (format!("l = {} mm Whitney", row.l * 1e3), Style::Dashed),
        };
        panel.series.push(
            Series::line(name, outline(&corners))
                .styled(style)
                .colored(depth_index),
        );
    }
    panels.into_iter().map(|(_, p)| p).collect()
}

/// Palette index for depth `l` in `panel`: reuse the colour of an earlier
/// series of the same depth, else the next free one.
fn depth_colour(panel: &Panel, l: f64) -> usize {
    let tag = format!("l = {} mm ", l * 1e3);
    panel
        .series
        .iter()
        .find(|s| s.name.starts_with(&tag))
        .and_then(|s| s.color)
        .unwrap_or_else(|| {
            let mut used: Vec<usize> = panel.series.iter().filter_map(|s| s.color).collect();
            used.dedup();
            used.len()
        })
}

/// A parallelogram as a series (for overlaying on a sweep panel).
pub fn parallelogram_series(name: &str, g: &Parallelogram, style: Style, colour: usize) -> Series {
    Series::line(name, outline(&g.corners))
        .styled(style)
        .colored(colour)
}
