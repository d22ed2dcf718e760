//! The simulation map (figure "simulations"): over the finder's background, level lines of the
//! mean number of impacts of the random drops in f64 (evidence, the paper's protocol: 25, 50,
//! 100, 150, and the 200 level above which some drops end in ICC), the lines where half of the
//! drops are *proved* not to end in ICC (CC, PCC or no-ICC-no-PCC: a certified cone proves no ICC
//! and no PCC but not the finite accumulation time of CC, issue 24) and to end in PCC (issue 22
//! §1: exact runs; evidence only when the map has no proofs, and then labelled so), the exact PCC
//! and CC boundaries. Only what is
//! drawn gets a legend entry; each level line is labelled where the label's box covers none of
//! the other curves: on the line, else beside it with a leader, else not at all (the legend then
//! names the level).

use super::contour::{contours, ranges};
use super::label::{Clear, Frame, LabelBox, Placed, box_point, place};
use super::map::{CC, LEVEL, MapChart, MapFigure, PCC, curve_entry, sub};
use super::{Entry, Sample, err};
use crate::simulate::Outcome;
use crate::sweep::curves::Polyline;
use crate::sweep::point::PAPER_BUDGET;
use crate::sweep::table::Row;
use plotters::prelude::*;

/// Level lines of the mean impact count (the last, just below the budget, separates ICC).
pub const LEVELS: [f64; 5] = [25.0, 50.0, 100.0, 150.0, PAPER_BUDGET as f64 - 0.5];

/// The quantities drawn as level lines.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Field {
    /// The mean number of impacts per drop (levels [`LEVELS`]).
    MeanImpacts,
    /// The share of the drops proved to end in PCC (level 1/2), or found to as evidence when the
    /// map has no proofs.
    PccShare,
    /// The share of the drops proved not to end in ICC: proved CC, PCC, or no ICC and no PCC
    /// (level 1/2).
    ChatterProved,
}

/// Which points.csv columns each level line is drawn from: `mean_impacts` (evidence),
/// `sim_pcc_proved / sim_runs` (or `sim_pcc_evidence` without proofs) and
/// `(sim_cc_proved + sim_pcc_proved + sim_no_icc_no_pcc_proved) / sim_runs`.
pub fn column(field: Field, r: &Row) -> Option<f64> {
    let s = r.sim.as_ref()?;
    let share = |k: u64| (s.runs > 0).then(|| k as f64 / s.runs as f64);
    let pcc = Outcome::Pcc.index();
    match (field, s.proved) {
        (Field::MeanImpacts, _) => Some(s.mean_impacts()),
        (Field::PccShare, Some(p)) => share(p[pcc]),
        (Field::PccShare, None) => share(s.counts[pcc]),
        (Field::ChatterProved, Some(p)) => {
            share([Outcome::Cc, Outcome::Pcc, Outcome::NoIccNoPcc].iter().map(|o| p[o.index()]).sum())
        }
        (Field::ChatterProved, None) => None,
    }
}

/// The legend's words for the PCC level line (they follow [`column()`]).
pub fn pcc_line(proved: bool) -> &'static str {
    if proved {
        "PCC proved in half of the drops (sim_pcc_proved / sim_runs = 1/2)"
    } else {
        "evidence: PCC found in half of the f64 drops (sim_pcc_evidence / sim_runs = 1/2)"
    }
}

/// The panel's title after the body: the drops per point, the evidence's and the proofs' budgets.
pub fn title_of(drops: u64, proof_budget: usize) -> String {
    if proof_budget == 0 {
        return format!("{drops} drops per point (f64 evidence, 200 impacts)");
    }
    format!("{drops} drops per point (f64 evidence; exact proofs ≤ {proof_budget} impacts)")
}

/// The legend's words for the line where half the drops are proved not to end in ICC (proved CC,
/// PCC, or no ICC and no PCC: CC is not claimed, as a cone entry does not prove the finite time).
pub const CHATTER_LINE: &str =
    "no ICC proved in half of the drops (proved CC, PCC, or no ICC and no PCC; exact runs, certified sets)";

/// A level's label: "200" for the level just below the budget.
fn label(level: f64) -> String {
    format!("{}", level.round())
}

/// Half the size of a label's white box, in pixels.
fn half(text: &str) -> (f64, f64) {
    (4.5 * text.len() as f64 + 3.0, 10.0)
}

/// Draws a label centred at `at`, on a white box, and its leader if it stands beside its line.
fn draw_label<DB: DrawingBackend>(
    chart: &mut MapChart<'_, '_, DB>,
    frame: &Frame,
    placed: Placed,
    text: String,
) -> Result<(), String> {
    let (hw, hh) = half(&text);
    let at = placed.at;
    if let Some(on) = placed.leader {
        // In the label's colour, 2 px, with a dot where it meets its line: visible on the grey
        // and white backgrounds alike, and telling which line the label names.
        let end = frame.data(box_point(frame.px(on), frame.px(at), (hw, hh)));
        chart.draw_series(LineSeries::new([on, end], LEVEL.stroke_width(2))).map_err(err)?;
        chart.draw_series(std::iter::once(Circle::new(on, 3, LEVEL.filled()))).map_err(err)?;
    }
    let style = (super::FONT, 16).into_font().color(&LEVEL);
    let tag = EmptyElement::at(at)
        + Rectangle::new([(-hw as i32, -hh as i32), (hw as i32, hh as i32)], WHITE.filled())
        + Text::new(text, (-hw as i32 + 3, -hh as i32 + 1), style);
    chart.draw_series(std::iter::once(tag)).map_err(err).map(|_| ())
}

/// The plotting area of the chart as a label [`Frame`].
fn frame<DB: DrawingBackend>(fig: &MapFigure, chart: &MapChart<'_, '_, DB>) -> Frame {
    let ((x0, x1), (g0, g1)) = ranges(&fig.grid);
    let (w, h) = chart.plotting_area().dim_in_pixel();
    Frame { x: (x0, x1), y: (g0, g1), pixels: (w as f64, h as f64) }
}

/// Draws the simulations panel's curves and returns the legend entries of what was drawn: the
/// level lines, their labels, then the proved and exact curves (which no label box covers; a
/// label without room on or beside its line is left out and its level named in the legend).
pub fn draw<DB: DrawingBackend>(
    fig: &MapFigure,
    chart: &mut MapChart<'_, '_, DB>,
) -> Result<Vec<Entry>, String> {
    let levels = contours(&fig.grid, &fig.rows, |r| column(Field::MeanImpacts, r), &LEVELS);
    let half = |field: Field| -> Vec<Polyline> {
        contours(&fig.grid, &fig.rows, |r| column(field, r), &[0.5]).into_iter().map(|(_, l)| l).collect()
    };
    let found = half(Field::PccShare);
    let chatter = half(Field::ChatterProved);
    let proved = fig.rows.iter().any(|r| r.sim.as_ref().is_some_and(|s| s.proved.is_some()));
    let avoid: Vec<&Polyline> =
        found.iter().chain(&chatter).chain(&fig.curves.pcc).chain(&fig.curves.cc).collect();
    let frame = frame(fig, chart);
    let (labels, unlabelled) = label_levels(&frame, &levels, &avoid);
    let mut e = draw_levels(chart, &levels, &unlabelled)?;
    for (p, text) in labels {
        draw_label(chart, &frame, p, text)?;
    }
    e.extend(curve_entry(chart, &chatter, Sample::Line(CC, 3), CHATTER_LINE.into())?);
    e.extend(curve_entry(chart, &found, Sample::Line(PCC, 3), pcc_line(proved).into())?);
    let m = sub(fig.grid.n - 1);
    let pcc = format!("exact: PCC possible (S{m}S₁ has real eigenvalues)");
    e.extend(curve_entry(chart, &fig.curves.pcc, Sample::Dashed(PCC, 3), pcc)?);
    let cc = "exact: CC criterion boundary (conjectured CC/ICC divide)".to_string();
    e.extend(curve_entry(chart, &fig.curves.cc, Sample::Dashed(CC, 3), cc)?);
    Ok(e)
}

/// Draws the level lines of the mean impact count (the 200 level thick) and returns their
/// legend entries, which name the levels whose lines found no place for a label.
fn draw_levels<DB: DrawingBackend>(
    chart: &mut MapChart<'_, '_, DB>,
    levels: &[(f64, Polyline)],
    unlabelled: &[f64],
) -> Result<Vec<Entry>, String> {
    type Levels<'a> = Vec<&'a (f64, Polyline)>;
    let (thin, thick): (Levels, Levels) =
        levels.iter().filter(|(_, l)| l.len() >= 2).partition(|(level, _)| *level < LEVELS[4]);
    let mut e = Vec::new();
    let thin_lines: Vec<Polyline> = thin.iter().map(|(_, l)| l.clone()).collect();
    let mut shown: Vec<String> =
        LEVELS[..4].iter().filter(|v| thin.iter().any(|(level, _)| level == *v)).map(|v| label(*v)).collect();
    shown.dedup();
    let mut missing: Vec<String> =
        LEVELS[..4].iter().filter(|v| unlabelled.contains(v)).map(|v| label(*v)).collect();
    missing.dedup();
    let note = match missing.len() {
        0 => String::new(),
        _ => format!("; not labelled for want of room: {}", missing.join(", ")),
    };
    let text = format!(
        "evidence: mean number of impacts per f64 drop (level{}: {}{note})",
        plural(&shown),
        shown.join(", ")
    );
    e.extend(curve_entry(chart, &thin_lines, Sample::Line(LEVEL, 1), text)?);
    let thick_lines: Vec<Polyline> = thick.iter().map(|(_, l)| l.clone()).collect();
    let mut text = "evidence: level 200, above it some f64 drops end in ICC".to_string();
    if unlabelled.contains(&LEVELS[4]) {
        text.push_str(" (not labelled for want of room)");
    }
    e.extend(curve_entry(chart, &thick_lines, Sample::Line(LEVEL, 3), text)?);
    Ok(e)
}

fn plural(shown: &[String]) -> &'static str {
    if shown.len() == 1 { "" } else { "s" }
}

/// Labels each level line of six points or more on a place whose box covers none of the `avoid`
/// curves (and, where it can, no other level line), spread along the lines, or beside it with a
/// leader: the labels' places and texts, and the levels of the lines left without a label (no
/// free place near them).
fn label_levels(frame: &Frame, levels: &[(f64, Polyline)], avoid: &[&Polyline]) -> (Labels, Vec<f64>) {
    let mut labels = Vec::new();
    let mut placed: Vec<LabelBox> = Vec::new();
    let mut unlabelled = Vec::new();
    for (i, (level, line)) in levels.iter().enumerate().filter(|(_, (_, l))| l.len() >= 6) {
        let soft: Vec<&Polyline> =
            levels.iter().enumerate().filter(|(j, _)| *j != i).map(|(_, (_, l))| l).collect();
        // Spread along the lines: 25 near one end, 200 near the other.
        let at = LEVELS.iter().position(|l| l == level).unwrap_or(0) as f64;
        let text = label(*level);
        let clear = Clear { hard: avoid, soft: &soft, placed: &placed };
        match place(frame, line, &clear, half(&text), 0.15 + 0.17 * at) {
            Some(p) => {
                placed.push(LabelBox { at: p.at, half: half(&text) });
                labels.push((p, text));
            }
            None => unlabelled.push(*level),
        }
    }
    (labels, unlabelled)
}

/// Labels' places and texts.
type Labels = Vec<(Placed, String)>;
