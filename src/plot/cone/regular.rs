//! The cone of a regular polygon's certificate (versions 1-3) on the plane v = -1: K, the cones
//! C_j, the images S_j(K ∩ C_j), I_0(D) and the dominant eigenvectors of S_1 and S_{n-1}. Every
//! n from 3 to 64: numbers of Q(cos 2π/n) are drawn through their f64 enclosures, on the float
//! model of the n-gon.

use super::{ConeFigure, Mark, Marker, Panel, Region, colour, s, window};
use crate::exact::{GENERATOR, Q, QExt};
use crate::finder::geometry::{P2, clip, hull, lift, project};
use crate::model::FloatBody;
use crate::model::float::FloatPolygon;
use crate::plot::map::body_name;
use chatter_kernel::certificate::{Body as CertBody, Encoding, read_in};
use crate::exact::QField;
use chatter_kernel::exact::{CosField, ParseLimits};
use nalgebra::{Matrix3, Vector3};

/// A number of the certificate as f64: a rational, or an element of Q(cos 2π/n) through a
/// rational enclosure of width 2^-60.
pub fn number(n: u64, text: &str) -> Result<f64, String> {
    if !text.contains(GENERATOR) {
        return text.parse::<Q>().map(|q| q.to_f64()).map_err(|e| format!("{text:?}: {e}"));
    }
    let field = CosField::<Q>::new(n).ok_or_else(|| format!("{text:?}: no number field for n = {n}"))?;
    let x = field.parse(text, ParseLimits::default()).map_err(|e| format!("{text:?}: {e}"))?;
    let (lo, hi) = x.enclose(&Q::new(1, 1 << 60));
    Ok(((&lo + &hi) / Q::int(2)).to_f64())
}

/// The eigenvector of `m` for the real eigenvalue `l`: a cross product of two rows of M - lI.
fn eigenvector(m: &Matrix3<f64>, l: f64) -> Vector3<f64> {
    let a = m - Matrix3::identity() * l;
    let rows = [a.row(0).transpose(), a.row(1).transpose(), a.row(2).transpose()];
    [(0, 1), (0, 2), (1, 2)]
        .iter()
        .map(|&(i, j)| rows[i].cross(&rows[j]))
        .max_by(|x, y| x.norm().total_cmp(&y.norm()))
        .expect("three pairs")
}

/// The dominant eigenvalue of `m` when it is real and positive (f64, for display).
fn dominant(m: &Matrix3<f64>) -> Option<f64> {
    let ev = m.complex_eigenvalues();
    let top = ev.iter().max_by(|a, b| a.norm().total_cmp(&b.norm()))?;
    let ties = ev.iter().filter(|e| (e.norm() - top.norm()).abs() <= 1e-12 * top.norm() && *e != top).count();
    (top.im.abs() <= 1e-12 * top.norm() && top.re > 0.0 && ties == 0).then_some(top.re)
}

/// A velocity on the plane v = -1, if it points down.
pub fn on_plane(v: &Vector3<f64>) -> Option<P2> {
    let v = if v.z > 0.0 { -v } else { *v };
    (v.z < -1e-12).then(|| project(&v))
}

/// The frame of a window as a polygon (for clipping the cones C_j).
pub fn frame((lo, hi): (P2, P2)) -> Vec<P2> {
    vec![P2::new(lo.x, lo.y), P2::new(hi.x, lo.y), P2::new(hi.x, hi.y), P2::new(lo.x, hi.y)]
}

/// Whether the legend names the C_j together (more colours than the palette has).
fn many(n: u64) -> bool {
    n - 1 > super::STEP.len() as u64
}

/// The marks p_max of S_1 and S_{n-1}.
fn eigen_marks(fb: &FloatBody) -> Vec<Mark> {
    let n = fb.n;
    let steps = [(1, fb.steps.first(), Marker::Cross), (n - 1, fb.steps.last(), Marker::Square)];
    let mut marks = Vec::new();
    for (j, m, marker) in steps {
        let Some(m) = m else { continue };
        if let Some(p) = dominant(m).and_then(|l| on_plane(&eigenvector(m, l))) {
            let label = format!("p_max(S{})", s(j));
            let legend = format!("{label}: eigenvector of S{} for its dominant eigenvalue", s(j));
            marks.push(Mark { label, at: p, marker, legend });
        }
    }
    marks
}

/// The figure of a certificate of versions 1-3.
pub fn figure(text: &str, encoding: Encoding) -> Result<ConeFigure, String> {
    let cert = read_in(text, encoding).map_err(|r| format!("not a readable certificate: {}", r.message()))?;
    let CertBody::RegularPolygon { n, kappa, gamma } = &cert.body;
    let n = *n;
    if n == 2 {
        return Err("the rod's cone is a pair of rays on a line (n = 2): nothing to draw on a plane".into());
    }
    // A box certificate is drawn at its lower corner (kappa_lo, gamma_lo).
    let (kt, gt) = (kappa.texts()[0], gamma.texts()[0]);
    let fp = FloatPolygon::new(n, number(n, kt)?, number(n, gt)?).map_err(|e| e.to_string())?;
    let fb = FloatBody::from_float(&fp);
    let gens: Vec<Vector3<f64>> = cert
        .cone
        .iter()
        .map(|g| {
            let c: Vec<f64> = g.0.iter().map(|t| number(n, t)).collect::<Result<_, _>>()?;
            (c.len() == 3)
                .then(|| Vector3::new(c[0], c[1], c[2]))
                .ok_or("a generator has 3 coordinates".to_string())
        })
        .collect::<Result<_, String>>()?;
    let k = hull(&gens.iter().filter_map(on_plane).collect::<Vec<_>>(), 0.0);
    let mut images = Vec::new();
    for (j, (m, c)) in fb.steps.iter().zip(&fb.cones).enumerate() {
        let piece = c.iter().fold(k.clone(), |p, l| clip(&p, l));
        let img = hull(&piece.iter().filter_map(|p| on_plane(&(m * lift(p)))).collect::<Vec<_>>(), 0.0);
        let legend = if many(n) {
            "S_j(K ∩ C_j) ⊆ K, in the colour of C_j".to_string()
        } else {
            format!("S{0}(K ∩ C{0}) ⊆ K", s(j + 1))
        };
        images.push(Region { name: String::new(), colour: colour(j), polygon: img, legend });
    }
    let seeds: Vec<P2> = fb.all_down.iter().filter_map(|g| on_plane(&(fb.impact0 * g))).collect();
    let marks = eigen_marks(&fb);
    let all: Vec<P2> = k
        .iter()
        .chain(images.iter().flat_map(|r| &r.polygon))
        .chain(&seeds)
        .chain(marks.iter().map(|m| &m.at))
        .copied()
        .collect();
    let (lo, hi, stretch) = window::fit(&all, window::pixels(1));
    let regions = fb
        .cones
        .iter()
        .enumerate()
        .map(|(j, c)| Region {
            name: format!("C{}", s(j + 1)),
            colour: colour(j),
            polygon: c.iter().fold(frame((lo, hi)), |p, l| clip(&p, l)),
            legend: if many(n) {
                "C_j: contact j hits next (each named on the plot)".to_string()
            } else {
                format!("C{}: contact {} hits next", s(j + 1), j + 1)
            },
        })
        .collect();
    let corner = if kappa.texts().len() > 1 || gamma.texts().len() > 1 {
        " (box certificate, at its lower corner)"
    } else {
        ""
    };
    let title = format!(
        "n = {n} ({}), κ = {}, γ = {gt}{corner}: K on the plane v = −1 ({}, {} generators)",
        body_name(n),
        kt.replace('*', "·"),
        cert.claim.name(),
        cert.cone.len()
    );
    let mut notes = vec!["hatched: where two C_j overlap, both hatchings show".to_string()];
    if kt.contains(GENERATOR) || cert.cone.iter().flat_map(|g| &g.0).any(|t| t.contains(GENERATOR)) {
        notes.push(format!("c = cos(2π/{n}); numbers of Q(c) drawn at their f64 values"));
    }
    let panel = Panel {
        title: String::new(),
        k,
        k_legend: "K, the certified cone".into(),
        regions,
        images,
        seeds,
        seeds_legend: "I₀(D): velocities after the first impact of all-down drops".into(),
        marks,
        window: (lo, hi),
        stretch,
    };
    Ok(ConeFigure {
        title, axes: ("u₀ / (−v)".into(), "u₁ / (−v)".into()), panels: vec![panel], notes
    })
}
