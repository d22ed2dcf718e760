//! The figure of a basin map (`chatter plot basin-map DIR`): one cell per grid point, filled
//! from the bottom in proportion to the kernel-checked shares of the box of drops: proved CC
//! (the certified share), proved ICC, undecided; with the exact CC criterion's boundary
//! (docs/basin-certificates.md §6).

use super::basin::ICC;
use super::cover::UNDECIDED;
use super::map::{CC, COMPLETE, body_name, curve_entry};
use super::{Entry, Figure, Sample, err, legend};
use crate::exact::{Q, QExt};
use crate::sweep::curves::Curves;
use crate::sweep::grid::{Axis, Variable};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// One point of the map: its cell and its three shares (as `f64`, for drawing).
#[derive(Clone, Debug)]
pub struct Cell {
    pub ix: u32,
    pub ig: u32,
    /// CC, ICC, undecided.
    pub shares: [f64; 3],
}

/// A basin map figure.
pub struct BasinMapFigure {
    pub n: u64,
    pub variable: Variable,
    pub x: Axis,
    pub gamma: Axis,
    pub cells: Vec<Cell>,
    pub curves: Curves,
    pub title: String,
    /// The box of drops, for the legend.
    pub drops: String,
}

/// Reads DIR/summary.json as `chatter basin-map` writes it; its exact curve is computed along
/// `lines` columns.
pub fn read(dir: &Path, lines: u32) -> Result<BasinMapFigure, String> {
    let path = dir.join("summary.json");
    let text = std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    let s: serde_json::Value = serde_json::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))?;
    let bad = |what: &str| format!("{}: {what} (not the summary of chatter basin-map?)", path.display());
    if s["schema"] != "chatter.basin-map/1" {
        return Err(bad("schema is not chatter.basin-map/1"));
    }
    let n = s["n"].as_u64().filter(|n| (3..=6).contains(n)).ok_or_else(|| bad("bad n"))?;
    let axis =
        |k: &str| s[k].as_str().and_then(|t| Axis::parse(t).ok()).ok_or_else(|| bad(&format!("bad {k}")));
    let (x, gamma) = (axis("x")?, axis("gamma")?);
    let variable = if s["variable"] == "rho" { Variable::Rho } else { Variable::Kappa };
    let per = gamma.steps as usize;
    let mut cells = Vec::new();
    for p in s["points"].as_array().ok_or_else(|| bad("no points"))? {
        let index = p["index"].as_u64().ok_or_else(|| bad("a point without index"))? as usize;
        let share = |k: &str| {
            p[k].as_str()
                .and_then(|t| t.parse::<Q>().ok())
                .map(|q| q.to_f64())
                .ok_or_else(|| bad(&format!("bad {k}")))
        };
        let shares = [share("cc_share")?, share("icc_share")?, share("undecided_share")?];
        cells.push(Cell { ix: (index / per) as u32, ig: (index % per) as u32, shares });
    }
    let corner = |k: &str| {
        s["box"][k].as_array().map(|v| v.iter().filter_map(|x| x.as_str()).collect::<Vec<_>>().join(", "))
    };
    let drops = format!(
        "box of drops: ({}) to ({}) in (ω_x, ω_y, φ_x, φ_y, h); depth {}",
        corner("lo").unwrap_or_default(),
        corner("hi").unwrap_or_default(),
        s["depth"]
    );
    let curves = crate::sweep::curves::curves(n, variable, (&x.lo, &x.hi), (&gamma.lo, &gamma.hi), lines);
    let title = format!("n = {n} ({}): certified share of the box of drops, per point", body_name(n));
    Ok(BasinMapFigure { n, variable, x, gamma, cells, curves, title, drops })
}

impl BasinMapFigure {
    fn legend_entries(&self, curve: Option<Entry>) -> Vec<Entry> {
        let kinds = [
            (0, COMPLETE, "certified share: proved CC (complete chatter), from the bottom of each cell"),
            (1, ICC, "certified share: proved ICC (v > 0)"),
            (2, UNDECIDED, "undecided share (no verdict), at the top of each cell"),
        ];
        let mut e: Vec<Entry> = kinds
            .into_iter()
            .filter(|(k, ..)| self.cells.iter().any(|c| c.shares[*k] > 0.0))
            .map(|(_, c, t)| Entry::new(Sample::Fill(c), t))
            .collect();
        e.extend(curve);
        if self.cells.iter().any(|c| c.shares[0] > 0.0) {
            let cc = "proved CC: the drops enter an orbit certificate's X, or a node's cone of a time-to-rest certificate (the drops that meet a simultaneous impact, where the model stops, after a cone or inside a tree of prefixes, have volume zero and are in no share)";
            e.push(Entry::new(Sample::Note, cc));
        }
        e.push(Entry::new(
            Sample::Note,
            "a cell stands for its point's whole box of drops: the coloured heights are the shares of the box's volume, checked by the kernel on both backends",
        ));
        e.push(Entry::new(Sample::Note, self.drops.clone()));
        e
    }
}

impl Figure for BasinMapFigure {
    fn size(&self) -> (u32, u32) {
        (1250, 820)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), String> {
        root.fill(&WHITE).map_err(err)?;
        let (left, right) = root.split_horizontally(840);
        let (x0, x1) = (self.x.lo.to_f64(), self.x.hi.to_f64());
        let (g0, g1) = (self.gamma.lo.to_f64(), self.gamma.hi.to_f64());
        let x_desc = if self.variable == Variable::Rho { "ρ = √κ" } else { "κ" };
        let mut chart = super::map::plane_chart(&left, &self.title, (x0, x1), (g0, g1), x_desc)?;
        let (dx, dg) = ((x1 - x0) / f64::from(self.x.steps), (g1 - g0) / f64::from(self.gamma.steps));
        let mut bars = Vec::new();
        for c in &self.cells {
            let (a, b) = (x0 + f64::from(c.ix) * dx, g0 + f64::from(c.ig) * dg);
            let mut y = b;
            for (k, colour) in [COMPLETE, ICC, UNDECIDED].into_iter().enumerate() {
                let top = y + c.shares[k] * dg;
                if c.shares[k] > 0.0 {
                    bars.push(Rectangle::new([(a, y), (a + dx, top)], colour.filled()));
                }
                y = top;
            }
            bars.push(Rectangle::new([(a, b), (a + dx, b + dg)], WHITE.stroke_width(1)));
        }
        chart.draw_series(bars).map_err(err)?;
        let cc = "exact: CC criterion boundary (real positive dominant eigenvalue below)";
        let lines = super::cover::inside(&self.curves.cc, [x0, x1], [g0, g1]);
        let curve = curve_entry(&mut chart, &lines, Sample::Dashed(CC, 3), cc.into())?;
        legend(&right.margin(70, 10, 0, 10), &self.legend_entries(curve))
    }
}
