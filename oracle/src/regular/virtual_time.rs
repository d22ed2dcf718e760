//! The virtual-time graph of a time-to-rest certificate (docs/time-to-rest.md §5, Theorem 5.1;
//! rules G1-G5 and R4 of docs/certificate-format.md §16): each node's cone K_r on the plane
//! v = -1 (the oracle's hull), the pieces K_r ∩ C_j by its brute-force half-plane intersection,
//! the virtual time Φ_r(q, p) = (a_r·q)/(-b_r·p) (a_r = c_r b_r in version 1) compared through its
//! cross-multiplied form.

use super::model::{Polygon, V3};
use super::pcc::pcc_quadratic;
use super::rules::{Polygon2, all_down, cone_polygon, misses};
use crate::arith::Num;
use crate::claim::Claim;
use crate::cone3::dot;
use crate::plane::{HalfPlane, clip_vertices, lift};
use crate::verdict::{Checked, Fail};

/// A node r of the graph: K_r's generators, the covector b_r, the numerator a_r (c_r b_r in
/// version 1, with its scale c_r) and the pairs (j, s) of `next`.
pub struct Node {
    /// Generators of K_r, (u0, u1, v).
    pub cone: Vec<V3>,
    /// b_r, applied to velocities (u0, u1, v).
    pub weight: V3,
    /// a_r, applied to configurations (h0, h1, hc).
    pub numerator: V3,
    /// c_r (version 1 only).
    pub scale: Option<Num>,
    /// (j, s): after step j the velocity is assigned to node s.
    pub next: Vec<(u64, u64)>,
}

/// -x.
fn minus(x: &Num) -> Num {
    x.neg()
}

/// R_j q: the configuration in the frame renamed so that contact j is 0 (heights transform like
/// speeds, docs/model.md §2): (h_j, h_{j+1}, hc).
fn renamed(b: &Polygon, j: i64, q: &V3) -> V3 {
    [b.speed(j, q), b.speed(j + 1, q), q[2].clone()]
}

/// m_{0,1} and m_{n-1,0}: the generators of the configurations after an impact.
fn after_impact(b: &Polygon) -> [V3; 2] {
    [b.rest_point(0, 1), b.rest_point(b.n as i64 - 1, 0)]
}

/// G1, G2 and F on node r: v < 0 at every generator and an interior (its polygon), -b_r·g > 0 at
/// every generator g, a_r·m_{0,1} ≥ 0, a_r·m_{n-1,0} ≥ 0 (in version 1 b_r·m and c_r ≥ 1), and
/// a_r·g ≤ b_r·g at every generator (F: Φ falls at least as fast as time in flight). The kernel checks the
/// rules node after node, reading each node's numbers just before (the mutation tests show it; the
/// documents leave the order open).
pub fn node_rules(b: &Polygon, r: usize, node: &Node) -> Checked<Polygon2> {
    let k = cone_polygon(&node.cone).map_err(|f| Fail { why: format!("node {r}: {}", f.why), ..f })?;
    node_forms(r, node, &after_impact(b))?;
    Ok(k)
}

/// G1, G2 and F on node r (its cone's rule R1 checked): -b_r·g > 0 at every generator g,
/// a_r·m ≥ 0 at both rest points `heights` of the configurations after the node's impact (in
/// version 1 b_r·m, and c_r ≥ 1), and a_r·g ≤ b_r·g at every generator.
pub fn node_forms(r: usize, node: &Node, heights: &[V3; 2]) -> Checked<()> {
    if let Some(i) = node.cone.iter().position(|g| !minus(&dot(&node.weight, g)).is_positive()) {
        return Err(Fail::new(
            "virtual-time-not-positive",
            format!("node {r}: -b·g <= 0 at generator {i} (G1)"),
        ));
    }
    let height = if node.scale.is_some() { &node.weight } else { &node.numerator };
    let positive = heights.iter().all(|m| !dot(height, m).is_negative());
    let below_one = |c: &Num| (c - &Num::int(&c.field, 1)).is_negative();
    if !positive || node.scale.as_ref().is_some_and(below_one) {
        return Err(Fail::new("virtual-time-not-positive", format!("node {r}: a·m < 0 or c < 1 (G2)")));
    }
    if let Some(i) = node.cone.iter().position(|g| dot(&node.numerator, g) > dot(&node.weight, g)) {
        return Err(Fail::new(
            "virtual-time-increases",
            format!("node {r}: a·g > b·g at generator {i}: Φ falls slower than time in flight (F)"),
        ));
    }
    Ok(())
}

/// The node `next` names for step j of node r, `missing-successor` when it names none (or a node
/// that does not exist); the first pair for j counts.
fn successor(node: &Node, r: usize, j: i64, count: usize) -> Checked<usize> {
    let s = node.next.iter().find(|(step, _)| *step == j as u64).map(|(_, s)| *s);
    let s = s.and_then(|s| usize::try_from(s).ok()).filter(|&s| s < count);
    s.ok_or_else(|| Fail::new("missing-successor", format!("node {r}, step {j}: `next` names no node (G3)")))
}

/// G3's inequality at a vertex p of K_r ∩ C_j and q ∈ {m_{j-1,j}, m_{j,j+1}}:
/// (a_s·R_j q)(-b_r·p) ≤ (a_r·q)(-b_s·S_j p).
fn decreases(b: &Polygon, j: i64, (r, s): (&Node, &Node), p: &V3, image: &V3) -> bool {
    [b.rest_point(j - 1, j), b.rest_point(j, j + 1)].iter().all(|q| {
        let lhs = &dot(&s.numerator, &renamed(b, j, q)) * &minus(&dot(&r.weight, p));
        let rhs = &dot(&r.numerator, q) * &minus(&dot(&s.weight, image));
        lhs <= rhs
    })
}

/// G3 for node r and step j: the codes of every vertex of K_r ∩ C_j that fails (the kernel's
/// clipping may list the vertices in another order, so any of them may be the first).
fn g3_step(b: &Polygon, nodes: &[Node], ks: &[Polygon2], r: usize, j: i64) -> Checked<()> {
    let cj: Vec<HalfPlane> = b.next_contact_facets(j).iter().map(HalfPlane::of_covector).collect();
    let piece = clip_vertices(&ks[r].vertices, &cj);
    if piece.is_empty() {
        return Ok(());
    }
    let s = successor(&nodes[r], r, j, nodes.len())?;
    let mut codes = vec![];
    for p in piece.iter().map(lift) {
        let image = b.step(j, &p);
        let code = match misses(&ks[s], &image) {
            Some(true) => Some("image-not-below"),
            Some(false) => Some("image-outside"),
            None if !decreases(b, j, (&nodes[r], &nodes[s]), &p, &image) => Some("virtual-time-increases"),
            None => None,
        };
        codes.extend(code.filter(|c| !codes.contains(c)));
    }
    if codes.is_empty() {
        return Ok(());
    }
    Err(Fail {
        codes, why: format!("node {r}, step {j} to node {s}: a vertex of K_{r} ∩ C_{j} fails (G3)")
    })
}

/// G3 on every node and step j = 1..n-1.
fn g3(b: &Polygon, nodes: &[Node], ks: &[Polygon2]) -> Checked<()> {
    for r in 0..nodes.len() {
        for j in 1..b.n as i64 {
            g3_step(b, nodes, ks, r, j)?;
        }
    }
    Ok(())
}

/// G5: B (-b_0·I_0(-m_{k,k+1})) ≥ a_0·m for every k and m ∈ {m_{0,1}, m_{n-1,0}}.
fn g5(b: &Polygon, node: &Node, bound: &Num) -> Checked<()> {
    for (k, g) in b.all_down().iter().enumerate() {
        let speed = minus(&dot(&node.weight, &b.impact(0, g)));
        for m in after_impact(b) {
            if bound * &speed < dot(&node.numerator, &m) {
                return Err(Fail::new(
                    "bound-too-small",
                    format!("node 0: B too small at generator {k} of D (G5)"),
                ));
            }
        }
    }
    Ok(())
}

/// Rules G3 and G4, after G1 and G2 on every node (`ks`: the nodes' polygons). Node 0 is entered
/// at the first impact; a graph without nodes has no node for it (`missing-successor`).
pub fn graph_rules(b: &Polygon, nodes: &[Node], ks: &[Polygon2]) -> Checked<()> {
    g3(b, nodes, ks)?;
    let Some(k0) = ks.first() else {
        return Err(Fail::new("missing-successor", "no node 0 for the first impact"));
    };
    all_down(b, k0)
}

/// Rule G5 on node 0 and, for `CompleteChatterFromAllDown`, R4.
pub fn bound_rules(b: &Polygon, claim: Claim, bound: &Num, node0: &Node) -> Checked<()> {
    g5(b, node0, bound)?;
    if claim >= Claim::CompleteChatterFromAllDown && !pcc_quadratic(b).excludes_pcc() {
        return Err(Fail::new("pcc-not-excluded", "the PCC quadratic has real roots or q >= 1"));
    }
    Ok(())
}
