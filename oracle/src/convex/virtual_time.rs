//! The virtual-time graph of a general convex body (docs/time-to-rest.md §5, "General bodies";
//! rules G3-G5 and K4 of docs/certificate-format.md §17). There is no relabelling: node r carries
//! the contact i(r) of the last impact, its pieces are K_r ∩ C_{i(r) j} (brute-force half-plane
//! intersection on v = -1, as for family certificates), the step to contact j is the impact I_j
//! itself, and the virtual time Φ_r(q, p) = (a_r·q)/(-b_r·p) is compared with q in the body's own
//! frame, cross-multiplied. The nodes' own rules G1, G2 and F are those of regular polygons
//! ([`crate::regular::virtual_time::node_forms`]) with the rest points of contact i(r).
//!
//! Over an interval [γ_lo, γ_hi] of γ (§17, version 2), G3-G5 and K4 are checked at both ends
//! ([`at_gamma`] with the body at each end), for reasons derived from the oracle's model
//! ([`super::model`]): the contacts, J, the rest points m_{k,l}, the pieces K_r ∩ C_{i(r) j}, D
//! and the graph are not functions of γ, and I_j(γ) p = p - (1 + γ)(f_j · p) w_j is affine in γ
//! (w_j not a function of γ). So at a fixed vertex p: the image is in the convex cone K_s with
//! v < 0 on the interval iff at both ends; (a_s·q)(-b_r·p) ≤ (a_r·q)(-b_s·I_j p) is an affine
//! inequality in γ; G4 is containment of an affine point in K_e and G5 an affine inequality in γ;
//! K4 is the family certificates' argument ([`super::rules`]). The reduction is then tested by
//! brute force at interior values of γ ([`super::rules::interior_gammas`]).

use super::model::{Body, V3};
use super::rules::{interior_gammas, pcc_excluded};
use crate::arith::Num;
use crate::cone3::dot;
use crate::plane::{HalfPlane, clip_vertices, lift};
use crate::regular::rules::{Polygon2, misses};
use crate::regular::virtual_time::Node;
use crate::verdict::{Checked, Fail};

/// A general body's graph after the file's rules and each node's G1, G2 and F.
pub struct ContactGraph {
    /// The body at its γ (at the first end of an interval of γ: the graph's rules do not depend on
    /// γ).
    pub body: Body,
    /// `entries[i]`: the node entered at a first impact at contact i (of contact i).
    pub entries: Vec<usize>,
    /// i(r) of each node, < n.
    pub contacts: Vec<usize>,
    /// The nodes' numbers.
    pub nodes: Vec<Node>,
    /// Each node's cone K_r on the plane v = -1.
    pub polygons: Vec<Polygon2>,
}

/// m_{i,i+1} and m_{i-1,i}: the rest points spanning the configurations after an impact at i.
pub fn heights(b: &Body, i: usize) -> [V3; 2] {
    let i = i as i64;
    [b.rest_point(i, i + 1), b.rest_point(i - 1, i)]
}

/// The node `next` names for contact j of node r: the first pair for j, a node of contact j
/// (`missing-successor` otherwise, also for a node that does not exist).
fn successor(g: &ContactGraph, r: usize, j: usize) -> Checked<usize> {
    let s = g.nodes[r].next.iter().find(|(step, _)| *step == j as u64).map(|(_, s)| *s);
    let s = s.and_then(|s| usize::try_from(s).ok()).filter(|&s| g.contacts.get(s) == Some(&j));
    let why = format!("node {r}, contact {j}: `next` names no node of contact {j} (G3)");
    s.ok_or_else(|| Fail::new("missing-successor", why))
}

/// G3's inequality at a vertex p of K_r ∩ C_{i(r) j} for q ∈ {m_{j-1,j}, m_{j,j+1}}:
/// (a_s·q)(-b_r·p) ≤ (a_r·q)(-b_s·I_j p).
fn decreases(b: &Body, j: usize, (r, s): (&Node, &Node), p: &V3, image: &V3) -> bool {
    let j = j as i64;
    [b.rest_point(j - 1, j), b.rest_point(j, j + 1)].iter().all(|q| {
        let lhs = &dot(&s.numerator, q) * &dot(&r.weight, p).neg();
        let rhs = &dot(&r.numerator, q) * &dot(&s.weight, image).neg();
        lhs <= rhs
    })
}

/// Where the image of vertex p of node r's piece for contact j (going to node s) fails G3 on the
/// body `b`, if it does: outside K_s, not below, or the virtual time increasing.
fn vertex_fails(
    g: &ContactGraph,
    b: &Body,
    (r, j, s): (usize, usize, usize),
    p: &V3,
) -> Option<&'static str> {
    let image = b.impact(j as i64, p);
    match misses(&g.polygons[s], &image) {
        Some(true) => Some("image-not-below"),
        Some(false) => Some("image-outside"),
        None if !decreases(b, j, (&g.nodes[r], &g.nodes[s]), p, &image) => Some("virtual-time-increases"),
        None => None,
    }
}

/// G3 for node r and contact j ≠ i(r): nothing when K_r ∩ C_{i(r) j} is {0}; else a successor
/// of contact j and every vertex's image in it with Φ not increasing. The codes of every failing
/// vertex are allowed (the kernel's clipping may list the vertices in another order).
fn g3_step(g: &ContactGraph, b: &Body, r: usize, j: usize) -> Checked<()> {
    let i = g.contacts[r];
    let c: Vec<HalfPlane> =
        b.next_contact_facets(i as i64, j as i64).iter().map(HalfPlane::of_covector).collect();
    let piece = clip_vertices(&g.polygons[r].vertices, &c);
    if piece.is_empty() {
        return Ok(());
    }
    let s = successor(g, r, j)?;
    let mut codes = vec![];
    for p in piece.iter().map(lift) {
        codes.extend(vertex_fails(g, b, (r, j, s), &p).filter(|c| !codes.contains(c)));
    }
    if codes.is_empty() {
        return Ok(());
    }
    let why = format!(
        "node {r} (contact {i}), contact {j} to node {s}: a vertex of K_{r} ∩ C_({i},{j}) fails (G3)"
    );
    Err(Fail { codes, why })
}

/// G3 on the body `b` on every node in order, and for each on the contacts j ≠ i(r) in increasing
/// order.
fn g3(g: &ContactGraph, b: &Body) -> Checked<()> {
    for (r, &i) in g.contacts.iter().enumerate() {
        for j in (0..b.n()).filter(|&j| j != i) {
            g3_step(g, b, r, j)?;
        }
    }
    Ok(())
}

/// G4 for contact i: I_i(-m_{k,k+1}) ∈ K_e for every k, e = entries[i].
fn g4(g: &ContactGraph, b: &Body, i: usize) -> Checked<()> {
    let e = g.entries[i];
    for (k, d) in b.all_down().iter().enumerate() {
        if misses(&g.polygons[e], &b.impact(i as i64, d)).is_some() {
            let why = format!("I_{i}(-m_({k},{})) is not in K_{e} of entry node {e} (G4)", k + 1);
            return Err(Fail::new("initial-outside", why));
        }
    }
    Ok(())
}

/// G5 for contact i: B (-b_e·I_i(-m_{k,k+1})) ≥ a_e·m for every k and m ∈ {m_{i,i+1}, m_{i-1,i}},
/// e = entries[i].
fn g5(g: &ContactGraph, b: &Body, i: usize, bound: &Num) -> Checked<()> {
    let e = g.entries[i];
    let node = &g.nodes[e];
    let at_rest = heights(b, i).map(|m| dot(&node.numerator, &m));
    for (k, d) in b.all_down().iter().enumerate() {
        let lhs = bound * &dot(&node.weight, &b.impact(i as i64, d)).neg();
        if at_rest.iter().any(|h| lhs < *h) {
            let why = format!("entry node {e} of contact {i}: B too small at generator {k} of D (G5)");
            return Err(Fail::new("bound-too-small", why));
        }
    }
    Ok(())
}

/// G4 then G5 contact after contact on the body `b` (the kernel's order; the documents leave it
/// open).
fn entry_rules(g: &ContactGraph, b: &Body, bound: &Num) -> Checked<()> {
    for i in 0..b.n() {
        g4(g, b, i)?;
        g5(g, b, i, bound)?;
    }
    Ok(())
}

/// The rules that depend on γ, on the body `b` (the graph's body at one γ): G3 on every node,
/// G4 and G5 contact after contact with the bound B, and K4 when `complete`
/// (`CompleteChatterFromAllDown`).
pub fn at_gamma(g: &ContactGraph, b: &Body, bound: &Num, complete: bool) -> Checked<()> {
    g3(g, b)?;
    entry_rules(g, b, bound)?;
    if complete {
        pcc(b)?;
    }
    Ok(())
}

/// The brute-force test of the reduction to the ends (the module's documentation): the rules of
/// [`at_gamma`] on the graph's body at interior values of [lo, hi]
/// ([`super::rules::interior_gammas`]); a failure there is `corner-argument-violated`.
pub fn interior(g: &ContactGraph, (lo, hi): (&Num, &Num), bound: &Num, complete: bool) -> Checked<()> {
    for gamma in interior_gammas(lo, hi) {
        if let Err(e) = at_gamma(g, &g.body.at_gamma(gamma.clone()), bound, complete) {
            return Err(super::rules::violated(&gamma, e));
        }
    }
    Ok(())
}

/// K4 for `CompleteChatterFromAllDown`: PCC excluded at every adjacent pair (k, k+1).
fn pcc(b: &Body) -> Checked<()> {
    match (0..b.n() as i64).find(|&k| !pcc_excluded(b, k)) {
        None => Ok(()),
        Some(k) => {
            Err(Fail::new("pcc-not-excluded", format!("PCC of contacts {k} and {} is possible", k + 1)))
        }
    }
}
