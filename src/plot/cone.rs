//! An effectively invariant cone on the plane v = -1 (figure "sajatertekek", right; docs/model.md
//! §5): the polygon K, the cones C_j of velocities from which contact j hits next, the images
//! S_j(K ∩ C_j) that must lie in K, the velocities I_0(D) after the first impact of the all-down
//! drops, and the eigenvectors p_max of S_1 and S_{n-1} for the dominant eigenvalue.

use super::map::sub;
use super::{Entry, Figure, LABEL, Sample, TICKS, TITLE, err, legend};
use crate::exact::{Q, QExt};
use crate::finder::geometry::{P2, clip, hull, lift, project};
use crate::model::FloatBody;
use crate::spectral::criteria::cc_criterion;
use chatter_kernel::certificate::{Body as CertBody, Certificate};
use chatter_kernel::model::Polygon as Body;
use chatter_kernel::syntax::{Encoding, read};
use nalgebra::{Matrix3, Vector3};
use plotters::coord::Shift;
use plotters::prelude::*;

/// Colours of C_j and S_j(K ∩ C_j), j = 1..5.
const STEP: [RGBColor; 5] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
];

/// The drawing of one certificate's cone.
pub struct ConeFigure {
    pub title: String,
    pub n: usize,
    /// K on the plane.
    pub k: Vec<P2>,
    /// Per j = 1..n-1: the region of C_j in the view window, and S_j(K ∩ C_j).
    pub regions: Vec<Vec<P2>>,
    pub images: Vec<Vec<P2>>,
    /// I_0 of the generators of D (all contacts moving down).
    pub seeds: Vec<P2>,
    /// p_max of S_1 and of S_{n-1} (None when the dominant eigenvalue is not real and positive
    /// or the eigenvector has v = 0).
    pub eigenvectors: [Option<P2>; 2],
    pub window: (P2, P2),
}

/// The eigenvector of `m` for the real eigenvalue `l`: a cross product of two rows of M - lI.
fn eigenvector(m: &Matrix3<f64>, l: f64) -> Vector3<f64> {
    let a = m - Matrix3::identity() * l;
    let rows = [a.row(0).transpose(), a.row(1).transpose(), a.row(2).transpose()];
    let pairs = [(0, 1), (0, 2), (1, 2)];
    pairs
        .iter()
        .map(|&(i, j)| rows[i].cross(&rows[j]))
        .max_by(|x, y| x.norm().total_cmp(&y.norm()))
        .expect("three pairs")
}

/// The dominant real eigenvalue of S_1 as f64, when it is real and positive (decided exactly).
fn dominant(b: &Body<Q>) -> Option<f64> {
    let (holds, spectrum, _) = cc_criterion(b);
    if !holds {
        return None;
    }
    let (root, _) = spectrum.real.last()?;
    let mut r = root.clone();
    while !r.is_exact() && r.width() > Q::new(1, 1 << 40) {
        r.bisect();
    }
    Some(((&r.lo + &r.hi) / Q::int(2)).to_f64())
}

fn on_plane(v: &Vector3<f64>) -> Option<P2> {
    let v = if v.z > 0.0 { -v } else { *v };
    (v.z < -1e-12).then(|| project(&v))
}

impl ConeFigure {
    /// Reads a certificate (n = 3, 4, 6) and computes the drawing in f64 (for display only).
    pub fn from_certificate(text: &str) -> Result<ConeFigure, String> {
        let cert: Certificate =
            read(text, Encoding::Ron).map_err(|r| format!("not a readable certificate: {r}"))?;
        let CertBody::RegularPolygon { n, kappa, gamma } = &cert.body;
        let q = |s: &str| s.parse::<Q>().map_err(|e| format!("{s:?}: {e}"));
        // A box certificate is drawn with the maps at its lower corner (kappa_lo, gamma_lo).
        let (kappa, gamma) = (q(kappa.texts()[0])?, q(gamma.texts()[0])?);
        if *n == 2 {
            return Err(
                "the rod's cone is a pair of rays on a line (n = 2): nothing to draw on a plane".into()
            );
        }
        let body = Body::new(*n, kappa.clone(), gamma.clone()).map_err(|e| e.to_string())?;
        let gens: Vec<Vector3<f64>> = cert
            .cone
            .iter()
            .map(|g| {
                let c: Vec<f64> = g.0.iter().map(|s| q(s).map(|x| x.to_f64())).collect::<Result<_, _>>()?;
                Ok(Vector3::new(c[0], c[1], c[2]))
            })
            .collect::<Result<_, String>>()?;
        let k = hull(&gens.iter().filter_map(on_plane).collect::<Vec<_>>(), 0.0);
        let fb = FloatBody::new(&body);
        let mut images = Vec::new();
        for (s, c) in fb.steps.iter().zip(&fb.cones) {
            let piece = c.iter().fold(k.clone(), |p, l| clip(&p, l));
            images
                .push(hull(&piece.iter().filter_map(|p| on_plane(&(s * lift(p)))).collect::<Vec<_>>(), 0.0));
        }
        let seeds: Vec<P2> = fb.all_down.iter().filter_map(|g| on_plane(&(fb.impact0 * g))).collect();
        let eigenvectors = match dominant(&body) {
            Some(l) => {
                [fb.steps.first(), fb.steps.last()].map(|s| s.and_then(|s| on_plane(&eigenvector(s, l))))
            }
            None => [None, None],
        };
        let all: Vec<&P2> = k
            .iter()
            .chain(images.iter().flatten())
            .chain(&seeds)
            .chain(eigenvectors.iter().flatten())
            .collect();
        let (mut lo, mut hi) =
            (P2::new(f64::INFINITY, f64::INFINITY), P2::new(f64::NEG_INFINITY, f64::NEG_INFINITY));
        for p in all {
            lo = lo.inf(p);
            hi = hi.sup(p);
        }
        let pad = (hi - lo).map(|d| d * 0.12 + 1e-3);
        let (lo, hi) = (lo - pad, hi + pad);
        let frame = vec![P2::new(lo.x, lo.y), P2::new(hi.x, lo.y), P2::new(hi.x, hi.y), P2::new(lo.x, hi.y)];
        let regions = fb.cones.iter().map(|c| c.iter().fold(frame.clone(), |p, l| clip(&p, l))).collect();
        let title = format!(
            "n = {n}, κ = {kappa}, γ = {gamma}: K on the plane v = −1 ({}, {} generators)",
            cert.claim.name(),
            cert.cone.len()
        );
        Ok(ConeFigure { title, n: *n as usize, k, regions, images, seeds, eigenvectors, window: (lo, hi) })
    }

    fn entries(&self) -> Vec<Entry> {
        let mut e = vec![Entry::new(Sample::Line(BLACK, 3), "K, the certified cone")];
        for j in 1..self.n {
            let c = STEP[(j - 1) % STEP.len()];
            e.push(Entry::new(
                Sample::Fill(c.mix_rgb(0.14)),
                format!("C{}: contact {j} can hit next (overlaps blend)", sub(j as u64)),
            ));
            e.push(Entry::new(Sample::Line(c, 2), format!("S{0}(K ∩ C{0}), inside K", sub(j as u64))));
        }
        e.push(Entry::new(
            Sample::Dot(RGBColor(90, 90, 90)),
            "I₀(D): after the first impact of all-down drops",
        ));
        if self.eigenvectors.iter().any(Option::is_some) {
            e.push(Entry::new(
                Sample::Star(BLACK),
                format!(
                    "p_max: eigenvectors of S₁ and S{} for the dominant eigenvalue",
                    sub(self.n as u64 - 1)
                ),
            ));
        }
        e
    }
}

trait Mix {
    fn mix_rgb(self, a: f64) -> RGBColor;
}

impl Mix for RGBColor {
    /// The colour blended with white (opaque, so SVG and PNG agree).
    fn mix_rgb(self, a: f64) -> RGBColor {
        let f = |c: u8| (255.0 - (255.0 - c as f64) * a).round() as u8;
        RGBColor(f(self.0), f(self.1), f(self.2))
    }
}

impl Figure for ConeFigure {
    fn size(&self) -> (u32, u32) {
        (1250, 820)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), String> {
        root.fill(&WHITE).map_err(err)?;
        let (left, right) = root.split_horizontally(840);
        let (lo, hi) = self.window;
        let mut chart = ChartBuilder::on(&left)
            .caption(&self.title, (super::FONT, TITLE - 4))
            .margin(18)
            .x_label_area_size(62)
            .y_label_area_size(80)
            .build_cartesian_2d(lo.x..hi.x, lo.y..hi.y)
            .map_err(err)?;
        chart
            .configure_mesh()
            .light_line_style(RGBColor(235, 235, 235))
            .x_desc("u₀ / (−v)")
            .y_desc("u₁ / (−v)")
            .axis_desc_style((super::FONT, LABEL))
            .label_style((super::FONT, TICKS))
            .draw()
            .map_err(err)?;
        let closed =
            |p: &[P2]| -> Vec<(f64, f64)> { p.iter().chain(p.first()).map(|v| (v.x, v.y)).collect() };
        for (j, region) in self.regions.iter().enumerate() {
            let c = STEP[j % STEP.len()];
            let pts: Vec<(f64, f64)> = region.iter().map(|v| (v.x, v.y)).collect();
            chart.draw_series(std::iter::once(Polygon::new(pts, c.mix(0.14).filled()))).map_err(err)?;
        }
        for (j, img) in self.images.iter().enumerate() {
            let c = STEP[j % STEP.len()];
            let pts: Vec<(f64, f64)> = img.iter().map(|v| (v.x, v.y)).collect();
            chart.draw_series(std::iter::once(Polygon::new(pts, c.mix_rgb(0.35).filled()))).map_err(err)?;
            chart.draw_series(LineSeries::new(closed(img), c.stroke_width(2))).map_err(err)?;
        }
        chart.draw_series(LineSeries::new(closed(&self.k), BLACK.stroke_width(3))).map_err(err)?;
        chart
            .draw_series(self.seeds.iter().map(|p| Circle::new((p.x, p.y), 5, RGBColor(90, 90, 90).filled())))
            .map_err(err)?;
        for p in self.eigenvectors.iter().flatten() {
            chart
                .draw_series(std::iter::once(Cross::new((p.x, p.y), 9, BLACK.stroke_width(3))))
                .map_err(err)?;
            let tag = EmptyElement::at((p.x, p.y))
                + Text::new("p_max", (12, -24), (super::FONT, LABEL).into_font());
            chart.draw_series(std::iter::once(tag)).map_err(err)?;
        }
        legend(&right.margin(70, 10, 0, 10), &self.entries())
    }
}
