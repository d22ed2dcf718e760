//! A general convex body's certificate (version 4) on the plane v = -1, one panel per contact i:
//! the cone K_i of velocities right after an impact at contact i, in the paper's coordinates
//! (ω_x/(−v), ω_y/(−v)); the cones C_ik (after an impact at i, contact k hits next); the images
//! I_i(K_j ∩ C_ji) that must lie in K_i; and I_i(D), the first impacts of all-down drops at i.

use super::regular::{frame, on_plane};
use super::{ConeFigure, Panel, Region, colour, s, window};
use crate::exact::{Q, QExt};
use crate::finder::geometry::{P2, clip, hull, lift};
use chatter_kernel::certificate::{ConvexBodyText, Encoding, Param, read_convex};
use chatter_kernel::model::ConvexBody;
use chatter_kernel::model::linalg::{Mat3, Vec3};
use nalgebra::{Matrix3, Vector3};

fn v64(v: &Vec3<Q>) -> Vector3<f64> {
    Vector3::new(v[0].to_f64(), v[1].to_f64(), v[2].to_f64())
}

fn m64(m: &Mat3<Q>) -> Matrix3<f64> {
    Matrix3::from_fn(|r, c| m[r][c].to_f64())
}

fn q(text: &str) -> Result<Q, String> {
    text.parse::<Q>().map_err(|e| format!("{text:?}: {e}"))
}

/// The polygon of a cone's generators on the plane.
fn polygon(gens: &[chatter_kernel::certificate::Generator]) -> Result<Vec<P2>, String> {
    let mut pts = Vec::new();
    for g in gens {
        let c: Vec<f64> = g.0.iter().map(|t| q(t).map(|x| x.to_f64())).collect::<Result<_, _>>()?;
        if c.len() != 3 {
            return Err("a generator has 3 coordinates".into());
        }
        pts.extend(on_plane(&Vector3::new(c[0], c[1], c[2])));
    }
    Ok(hull(&pts, 0.0))
}

/// The covectors of C_ik (empty for i = k).
fn cone(b: &ConvexBody<Q>, i: usize, k: usize) -> Vec<Vector3<f64>> {
    b.next_contact_cone(i as i64, k as i64).map_or_else(Vec::new, |c| c.iter().map(v64).collect())
}

/// The figure of a version-4 certificate.
pub fn figure(text: &str, encoding: Encoding) -> Result<ConeFigure, String> {
    let cert =
        read_convex(text, encoding).map_err(|r| format!("not a readable certificate: {}", r.message()))?;
    // Over an interval of γ each image is drawn as the hull of its images at both ends, which
    // holds its images at every γ between (the maps are affine in γ, docs/kernel-soundness.md §6).
    let ends = crate::bodies::convex::of_text(&cert.body)?;
    let b = &ends[0];
    let n = b.n();
    let ks: Vec<Vec<P2>> = cert.cones.iter().map(|c| polygon(c)).collect::<Result<_, _>>()?;
    if ks.len() != n {
        return Err(format!("{} cones for {n} contacts", ks.len()));
    }
    let down: Vec<Vector3<f64>> = b.all_down_generators().iter().map(v64).collect();
    let pixels = window::pixels(n);
    let mut panels = Vec::new();
    for i in 0..n {
        let impacts: Vec<Matrix3<f64>> = ends.iter().map(|e| m64(&e.impact(i as i64))).collect();
        let images: Vec<Region> = (0..n)
            .filter(|&j| j != i)
            .map(|j| {
                let piece = cone(b, j, i).iter().fold(ks[j].clone(), |p, l| clip(&p, l));
                let at = |m: &Matrix3<f64>| {
                    piece.iter().filter_map(|p| on_plane(&(m * lift(p)))).collect::<Vec<_>>()
                };
                let img: Vec<P2> = impacts.iter().flat_map(at).collect();
                let legend =
                    format!("I_i(K{0} ∩ C{0}ᵢ): from K{0}, contact i hits next; must lie in K_i", s(j));
                Region { name: String::new(), colour: colour(j), polygon: hull(&img, 0.0), legend }
            })
            .collect();
        let seeds: Vec<P2> =
            impacts.iter().flat_map(|m| down.iter().filter_map(move |g| on_plane(&(m * g)))).collect();
        let all: Vec<P2> =
            ks[i].iter().chain(images.iter().flat_map(|r| &r.polygon)).chain(&seeds).copied().collect();
        let (lo, hi, stretch) = window::fit(&all, pixels);
        let regions = (0..n)
            .filter(|&k| k != i)
            .map(|k| Region {
                name: format!("C{}{}", s(i), s(k)),
                colour: colour(k),
                polygon: cone(b, i, k).iter().fold(frame((lo, hi)), |p, l| clip(&p, l)),
                legend: format!("C_i{}: after an impact at i, contact {k} hits next", s(k)),
            })
            .collect();
        panels.push(Panel {
            title: format!("K{}: right after an impact at contact {i}", s(i)),
            k: ks[i].clone(),
            k_legend: "K_i, the certified cone after an impact at contact i".into(),
            regions,
            images,
            seeds,
            seeds_legend: "I_i(D): after a first impact at i of an all-down drop".into(),
            marks: Vec::new(),
            window: (lo, hi),
            stretch,
        });
    }
    let ConvexBodyText::ConvexPolygon { gamma, .. } = &cert.body;
    let interval = matches!(gamma, Param::Interval(..));
    let gamma = match gamma {
        Param::Point(g) => format!("γ = {g}"),
        Param::Interval(a, b) => format!("every γ ∈ [{a}, {b}]"),
    };
    let title = format!(
        "general convex body, {n} contacts, {gamma}: the cones K_i on the plane v = −1 ({})",
        cert.claim.name()
    );
    let mut notes = vec![
        "hatched: where two C_ik overlap, both hatchings show".into(),
        "coordinates: the paper's (ω_x, ω_y, v), angular velocity over the centre's downward speed".into(),
    ];
    if interval {
        // In the notes, not the title: a title this long ran off both edges of the figure.
        notes.insert(0, "images and I_i(D) at both ends of the interval of γ".into());
    }
    Ok(ConeFigure { title, axes: ("ω_x / (−v)".into(), "ω_y / (−v)".into()), panels, notes })
}
