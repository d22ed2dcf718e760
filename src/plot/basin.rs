//! The figure of a basin certificate (`chatter plot basin FILE`, docs/basin-certificates.md §5):
//! a slice of its box of drops along two of the five drop coordinates (ω_x, ω_y, φ_x, φ_y, h),
//! the other three fixed; every leaf whose closed box meets the slice is drawn as a rectangle
//! filled by its verdict (proved CC, proved ICC, undecided). Undecided leaves are drawn first, so
//! on a boundary shared by two leaves the decided one shows (each verdict holds on its whole
//! closed leaf, §3).

use super::cover::UNDECIDED;
use super::map::{COMPLETE, body_name};
use super::{Entry, Figure, LABEL, Sample, TICKS, err, legend};
use crate::exact::{Q, QExt};
use chatter_kernel::basin::drop::DIMS;
use chatter_kernel::rules::basin::{BasinReport, leaf_box};
use chatter_kernel::syntax::basin::{BasinCertificate, LeafVerdict, Then};
use chatter_kernel::syntax::orbit::OrbitBody;
use malachite::rational::Rational;
use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;

/// Fill of the leaves proved ICC (v > 0 after their prefix).
pub const ICC: RGBColor = RGBColor(200, 60, 50);

/// The drop coordinates' names on the command line, in the certificate's order.
pub const NAMES: [&str; DIMS] = ["omega_x", "omega_y", "phi_x", "phi_y", "h"];

/// The drop coordinates as the paper writes them (velocity (ω_x, ω_y, −1), position (φ_x, φ_y, h)).
pub const SYMBOLS: [&str; DIMS] = ["ω_x", "ω_y", "φ_x", "φ_y", "h"];

/// The slice's chart (data coordinates: the two drawn drop coordinates).
type SliceChart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// A leaf's verdict, as drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// `Cc`: the drops enter an orbit certificate's X.
    Cc,
    /// `Rest`: the drops enter a node's cone of the time-to-rest certificate (CC too).
    Rest,
    Icc,
    Undecided,
}

/// A drawn leaf: its kind and its extent along the two axes.
#[derive(Clone, Debug)]
pub struct Rect {
    pub kind: Kind,
    pub x: [f64; 2],
    pub y: [f64; 2],
}

/// A slice of a basin certificate.
pub struct BasinFigure {
    pub title: String,
    /// The two coordinates drawn (indices into [`NAMES`]).
    pub axes: [usize; 2],
    /// The box's extent along them.
    pub x: [f64; 2],
    pub y: [f64; 2],
    /// The leaves meeting the slice, undecided first.
    pub rects: Vec<Rect>,
    /// "φ_x = 1/20, ..." : where the other coordinates are fixed.
    pub fixed: String,
    /// How many of the leaves meeting the slice are trees (version 2).
    pub trees: usize,
}

fn f(x: &Rational) -> f64 {
    Q::from_rational(x.clone()).to_f64()
}

/// A coordinate's index by its name (`omega_x` ... `h`).
pub fn axis_index(name: &str) -> Result<usize, String> {
    NAMES
        .iter()
        .position(|n| *n == name.trim())
        .ok_or_else(|| format!("{name:?} is not a drop coordinate: give one of {}", NAMES.join(", ")))
}

impl BasinFigure {
    /// The slice of `cert` (accepted by the kernel with `report`) along `axes`, the other
    /// coordinates at `at` (None: the box's centre). Exact: a leaf is drawn when its closed box
    /// contains the fixed values.
    pub fn new(
        cert: &BasinCertificate,
        report: &BasinReport,
        axes: [usize; 2],
        at: &[Option<Q>; DIMS],
    ) -> Result<BasinFigure, String> {
        if axes[0] == axes[1] || axes.iter().any(|&a| a >= DIMS) {
            return Err("--axes: give two different drop coordinates".into());
        }
        let num = |s: &String| {
            chatter_kernel::exact::parse_canonical::<Rational>(s, Default::default())
                .map_err(|e| format!("a number of the box: {e}"))
        };
        let lo: [Rational; DIMS] = read5(&cert.drops.lo, num)?;
        let hi: [Rational; DIMS] = read5(&cert.drops.hi, num)?;
        let mut fixed = Vec::new();
        let mut value: [Rational; DIMS] = std::array::from_fn(|k| (&lo[k] + &hi[k]) / Rational::from(2));
        for k in (0..DIMS).filter(|k| !axes.contains(k)) {
            if let Some(q) = &at[k] {
                let r = q.as_rational().clone();
                if r < lo[k] || r > hi[k] {
                    return Err(format!(
                        "--at {}={q}: outside the box [{}, {}]",
                        NAMES[k], cert.drops.lo[k], cert.drops.hi[k]
                    ));
                }
                value[k] = r;
            }
            fixed.push(format!("{} = {}", SYMBOLS[k], Q::from_rational(value[k].clone())));
        }
        let (mut rects, mut trees) = (Vec::new(), 0);
        for leaf in &cert.leaves {
            let (l, h) = leaf_box(&lo, &hi, &leaf.path);
            if (0..DIMS).any(|k| !axes.contains(&k) && (value[k] < l[k] || value[k] > h[k])) {
                continue;
            }
            let kind = match &leaf.verdict {
                LeafVerdict::Cc { .. } => Kind::Cc,
                LeafVerdict::Rest { .. } => Kind::Rest,
                LeafVerdict::Icc { .. } => Kind::Icc,
                LeafVerdict::Undecided => Kind::Undecided,
                LeafVerdict::Tree { next } => match crate::basin::tree::first_end(next) {
                    Some(Then::Icc) => Kind::Icc,
                    Some(Then::Rest { .. }) => Kind::Rest,
                    _ => Kind::Cc,
                },
            };
            trees += usize::from(matches!(leaf.verdict, LeafVerdict::Tree { .. }));
            let [a, b] = axes;
            rects.push(Rect { kind, x: [f(&l[a]), f(&h[a])], y: [f(&l[b]), f(&h[b])] });
        }
        rects.sort_by_key(|r| r.kind != Kind::Undecided);
        let OrbitBody::RegularPolygon { n, kappa, gamma } = &cert.body;
        let title = format!(
            "n = {n} ({}), κ = {kappa}, γ = {gamma}: kernel's shares of the box: CC {}, ICC {}, undecided {}",
            body_name(*n),
            report.cc_share,
            report.icc_share,
            report.undecided_share
        );
        let [a, b] = axes;
        Ok(BasinFigure {
            title,
            axes,
            x: [f(&lo[a]), f(&hi[a])],
            y: [f(&lo[b]), f(&hi[b])],
            rects,
            fixed: fixed.join(", "),
            trees,
        })
    }

    fn legend_entries(&self) -> Vec<Entry> {
        let kinds = [
            (
                Kind::Cc,
                COMPLETE,
                "proved CC: every drop enters the orbit certificate's set X (complete chatter)",
            ),
            (
                Kind::Rest,
                COMPLETE,
                "proved CC: every drop enters a node's cone of the time-to-rest certificate (complete chatter unless a later impact is simultaneous)",
            ),
            (Kind::Icc, ICC, "proved ICC: every drop reaches v > 0 (never comes to rest)"),
            (Kind::Undecided, UNDECIDED, "undecided: no verdict is claimed"),
        ];
        let mut e: Vec<Entry> = kinds
            .into_iter()
            .filter(|(k, ..)| self.rects.iter().any(|r| r.kind == *k))
            .map(|(_, c, text)| Entry::new(Sample::Fill(c), text))
            .collect();
        if self.trees > 0 {
            let note = "tree leaves (a prefix for each order in which contacts land): their drops that meet a simultaneous impact, where the model stops, have volume zero and are not claimed";
            e.push(Entry::new(Sample::Note, note));
        }
        e.push(Entry::new(Sample::Note, format!("slice at {}", self.fixed)));
        e.push(Entry::new(
            Sample::Note,
            "drops before the first impact: velocity (ω_x, ω_y, −1), position (φ_x, φ_y, h) (the paper's coordinates); the shares are of the whole five-dimensional box",
        ));
        e
    }

    /// The chart's area on a root of the figure's size (the same layout as drawn), and the
    /// legend's area.
    fn chart<'a, DB: DrawingBackend>(
        &self,
        root: &'a DrawingArea<DB, Shift>,
    ) -> Result<(SliceChart<'a, DB>, DrawingArea<DB, Shift>), String> {
        let body = root.titled(&self.title, (super::FONT, LABEL)).map_err(err)?;
        let (left, right) = body.split_horizontally(820);
        let chart = ChartBuilder::on(&left)
            .margin(18)
            .x_label_area_size(62)
            .y_label_area_size(90)
            .build_cartesian_2d(self.x[0]..self.x[1], self.y[0]..self.y[1])
            .map_err(err)?;
        Ok((chart, right))
    }

    /// Where a point (x, y) of the slice is drawn, in SVG units (PNG pixels / `PNG_SCALE`).
    pub fn pixel(&self, x: f64, y: f64) -> Result<(i32, i32), String> {
        let mut out = String::new();
        let root = SVGBackend::with_string(&mut out, self.size()).into_drawing_area();
        let (chart, _) = self.chart(&root)?;
        Ok(chart.backend_coord(&(x, y)))
    }
}

fn read5(
    v: &[String],
    num: impl Fn(&String) -> Result<Rational, String>,
) -> Result<[Rational; DIMS], String> {
    let v: Vec<Rational> = v.iter().map(num).collect::<Result<_, _>>()?;
    v.try_into().map_err(|_| "the box has not five coordinates".to_string())
}

fn fill(k: Kind) -> RGBColor {
    match k {
        Kind::Cc | Kind::Rest => COMPLETE,
        Kind::Icc => ICC,
        Kind::Undecided => UNDECIDED,
    }
}

impl Figure for BasinFigure {
    fn size(&self) -> (u32, u32) {
        (1250, 840)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), String> {
        root.fill(&WHITE).map_err(err)?;
        let (mut chart, right) = self.chart(root)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(SYMBOLS[self.axes[0]])
            .y_desc(SYMBOLS[self.axes[1]])
            .axis_desc_style((super::FONT, LABEL))
            .label_style((super::FONT, TICKS))
            .draw()
            .map_err(err)?;
        let corners = |r: &Rect| [(r.x[0], r.y[0]), (r.x[1], r.y[1])];
        chart
            .draw_series(self.rects.iter().map(|r| Rectangle::new(corners(r), fill(r.kind).filled())))
            .map_err(err)?;
        let (w, h) = (self.x[1] - self.x[0], self.y[1] - self.y[0]);
        let big = |r: &Rect| (r.x[1] - r.x[0]) / w * 700.0 > 6.0 && (r.y[1] - r.y[0]) / h * 700.0 > 6.0;
        chart
            .draw_series(
                self.rects
                    .iter()
                    .filter(|r| big(r))
                    .map(|r| Rectangle::new(corners(r), WHITE.stroke_width(1))),
            )
            .map_err(err)?;
        legend(&right.margin(40, 10, 0, 10), &self.legend_entries())
    }
}
