//! Rules R1 to R4 of docs/certificate-format.md §5 for a regular polygon at one point (κ, γ),
//! on the plane v = -1: K the gift-wrapped hull of the projected generators, the vertices of
//! K ∩ C_j by brute-force half-plane intersection, images by the model's steps.

use super::model::{Polygon, V3};
use super::pcc::pcc_quadratic;
use crate::arith::Num;
use crate::arith::text::element_text;
use crate::claim::Claim;
use crate::plane::{HalfPlane, Pt, clip_vertices, edges, hull, inside, lift, project, spans_plane};
use crate::verdict::{Checked, Fail, Report};

/// K as a polygon: its counter-clockwise vertices, edge half-planes, and the redundant generators.
pub struct Polygon2 {
    /// Vertices, counter-clockwise.
    pub vertices: Vec<Pt>,
    /// Edge half-planes.
    pub sides: Vec<HalfPlane>,
    /// Generators that are not hull vertices, or repeat an earlier one.
    pub redundant: Vec<usize>,
}

/// Rule R1: every generator has v < 0 and the projected points span the plane.
pub fn cone_polygon(gens: &[V3]) -> Checked<Polygon2> {
    let mut pts = vec![];
    for (i, g) in gens.iter().enumerate() {
        pts.push(
            project(g)
                .ok_or_else(|| Fail::new("generator-not-below", format!("generator {i} has v >= 0")))?,
        );
    }
    if !spans_plane(&pts) {
        return Err(Fail::new("degenerate-cone", "K is not a 3-D cone"));
    }
    let h = hull(&pts);
    let vertices: Vec<Pt> = h.iter().map(|&i| pts[i].clone()).collect();
    let redundant = (0..pts.len()).filter(|i| !h.contains(i)).collect();
    Ok(Polygon2 { sides: edges(&vertices), vertices, redundant })
}

/// Where an image lands: `None` when it is 0 or inside K, else whether it has v ≥ 0.
pub fn misses(k: &Polygon2, img: &V3) -> Option<bool> {
    if img.iter().all(Num::is_zero) {
        return None;
    }
    match project(img) {
        None => Some(true),
        Some(p) if inside(&k.sides, &p) => None,
        Some(_) => Some(false),
    }
}

/// The codes of the images that leave `k` ([`misses`]): `image-not-below`, `image-outside`, each
/// once, in the order met.
pub fn leaving(k: &Polygon2, images: impl Iterator<Item = V3>) -> Vec<&'static str> {
    let mut codes = vec![];
    for img in images {
        match misses(k, &img) {
            Some(true) if !codes.contains(&"image-not-below") => codes.push("image-not-below"),
            Some(false) if !codes.contains(&"image-outside") => codes.push("image-outside"),
            _ => {}
        }
    }
    codes
}

/// Rule R2: for every j, the images of the vertices of K ∩ C_j; returns the piece sizes.
pub fn invariance(b: &Polygon, k: &Polygon2) -> Checked<Vec<usize>> {
    let mut pieces = vec![];
    for j in 1..b.n as i64 {
        let cj: Vec<HalfPlane> = b.next_contact_facets(j).iter().map(HalfPlane::of_covector).collect();
        let piece = clip_vertices(&k.vertices, &cj);
        let codes = leaving(k, piece.iter().map(|p| b.step(j, &lift(p))));
        if !codes.is_empty() {
            return Err(Fail { codes, why: format!("an image of a vertex of K ∩ C_{j} leaves K") });
        }
        pieces.push(piece.len());
    }
    Ok(pieces)
}

/// Rule R3: I_0 of every generator of D lies in K (or is 0).
pub fn all_down(b: &Polygon, k: &Polygon2) -> Checked<()> {
    for (i, g) in b.all_down().iter().enumerate() {
        if misses(k, &b.impact(0, g)).is_some() {
            return Err(Fail::new("initial-outside", format!("I_0(-m_({i},{})) is not in K", i + 1)));
        }
    }
    Ok(())
}

/// Whether K contains I_0(-1, -1, -1) (informational).
pub fn contains_translation(b: &Polygon, k: &Polygon2) -> bool {
    let f = &b.kappa.field;
    let img = b.impact(0, &[Num::int(f, -1), Num::int(f, -1), Num::int(f, -1)]);
    project(&img).is_some_and(|p| inside(&k.sides, &p))
}

/// Rules R1 to R4 at one point (after the file's rules); `bits` is the generators' largest
/// denominator.
pub fn check_point(b: &Polygon, claim: Claim, gens: &[V3], bits: u64) -> Checked<Report> {
    let k = cone_polygon(gens)?;
    let pieces = invariance(b, &k)?;
    if claim >= Claim::CcOrPccFromAllDown {
        all_down(b, &k)?;
    }
    let mut pcc = None;
    if claim >= Claim::CompleteChatterFromAllDown {
        let quad = pcc_quadratic(b);
        if !quad.excludes_pcc() {
            return Err(Fail::new("pcc-not-excluded", "the PCC quadratic has real roots or q >= 1"));
        }
        pcc = Some([element_text(&quad.p), element_text(&quad.q), element_text(&quad.discriminant)]);
    }
    Ok(Report {
        claim: claim.name().into(),
        n: b.n as u64,
        generators: Some(gens.len()),
        redundant: Some(k.redundant.clone()),
        pieces: Some(pieces),
        max_denominator_bits: Some(bits),
        pcc,
        contains_translation: Some(contains_translation(b, &k)),
        region: None,
        refutation: None,
        basin: None,
        rest_nodes: None,
    })
}
