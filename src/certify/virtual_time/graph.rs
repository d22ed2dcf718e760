//! The virtual-time graph's nodes and successors in `f64` (docs/time-to-rest.md §5, "a graph
//! built from the images of I_0(D)"): the entry nodes are the hulls of I_i(D) (node 0 = I_0(D)
//! for a regular polygon; nodes 0..n-1 for a general body); each image S_j(K_r ∩ C_j) goes to
//! the smallest node of its label that contains it, or becomes a new node, enlarged, or (in a
//! merged graph) enlarges the node of its label it grows least, which is then searched again.
//! Untrusted.

use super::Config;
use super::frames::FloatFrames;
use crate::finder::geometry::{P2, clip, hull, lift, outside_distance, project};
use std::collections::VecDeque;

/// An edge r --j--> s(r, j), with the float piece K_r ∩ C_j that it maps.
pub struct Edge {
    pub from: usize,
    pub step: usize,
    pub to: usize,
    pub piece: Vec<P2>,
}

/// The float graph: cones K_r on the plane v = -1, their labels and the edges; `closed` when
/// every image found a node within the node cap. Nodes 0..entries are the entry nodes, in the
/// order of [`FloatFrames::entries`].
pub struct Graph {
    pub nodes: Vec<Vec<P2>>,
    pub label: Vec<usize>,
    pub edges: Vec<Edge>,
    pub closed: bool,
}

/// S_j of the piece's vertices for every body (the corners of a box: each image is affine in γ
/// and, times 1 + κ, in κ, so the hull of the corners' images holds the images of the whole box),
/// on the plane v = -1; `None` if an image is not below v = 0.
fn image(bodies: &[FloatFrames], j: usize, piece: &[P2]) -> Option<Vec<P2>> {
    let mut out = Vec::with_capacity(bodies.len() * piece.len());
    for body in bodies {
        let s = body.step(j);
        for x in piece.iter().map(|p| s * lift(p)) {
            out.push((x.z < 0.0).then(|| project(&x))?);
        }
    }
    Some(out)
}

/// The hull of P scaled by 1 + d about its vertex centroid, with a square of half-side `pad` at
/// each vertex, so that images inside stay inside after rounding to rationals.
fn enlarge(p: &[P2], d: f64, pad: f64) -> Vec<P2> {
    let c = p.iter().fold(P2::zeros(), |a, x| a + x) / p.len() as f64;
    let corners = [P2::new(-pad, -pad), P2::new(pad, -pad), P2::new(pad, pad), P2::new(-pad, pad)];
    let pts: Vec<P2> = p.iter().flat_map(|x| corners.map(|e| c + (x - c) * (1.0 + d) + e)).collect();
    hull(&pts, 1e-15)
}

/// Area of a convex polygon (shoelace).
fn area(p: &[P2]) -> f64 {
    let m = p.len();
    0.5 * (0..m).map(|i| p[i].x * p[(i + 1) % m].y - p[(i + 1) % m].x * p[i].y).sum::<f64>().abs()
}

/// The node of label `at` and smallest area that contains every point of `img`.
fn smallest_containing(g: &Graph, at: usize, img: &[P2]) -> Option<usize> {
    let inside = |k: &[P2]| img.iter().all(|q| outside_distance(k, q) <= 1e-12);
    (0..g.nodes.len())
        .filter(|&s| g.label[s] == at && inside(&g.nodes[s]))
        .min_by(|&a, &b| area(&g.nodes[a]).total_cmp(&area(&g.nodes[b])))
}

/// Builds the graph breadth first from the entry nodes I_i(D) (padded by `pad`; of every body:
/// the corners of a box, whose C_j are the same), at most `cfg.max_nodes` nodes (and, merging,
/// at most 20 times as many node searches). With `merge` = Some(t), an image that no node of its
/// label contains is first merged into the node of that label whose hull with the image's
/// enlarged hull has the least area, if that area is at most t times the larger of the two (the
/// node is then searched again); else it becomes a new node.
pub fn build(bodies: &[FloatFrames], cfg: &Config, pad: f64, merge: Option<f64>) -> Graph {
    let body = &bodies[0];
    let mut g = Graph { nodes: Vec::new(), label: Vec::new(), edges: vec![], closed: false };
    for (e, &at) in body.entries().iter().enumerate() {
        let first: Vec<P2> = (bodies.iter())
            .flat_map(|b| b.all_down().iter().map(|d| project(&(b.impact(e) * d))).collect::<Vec<_>>())
            .collect();
        g.nodes.push(enlarge(&hull(&first, 1e-15), 0.0, pad));
        g.label.push(at);
    }
    let mut todo: VecDeque<usize> = (0..g.nodes.len()).collect();
    for _ in 0..20 * cfg.max_nodes {
        let Some(r) = todo.pop_front() else {
            g.closed = true;
            return g;
        };
        g.edges.retain(|e| e.from != r);
        for (j, at, cov) in body.steps(g.label[r]) {
            let piece = cov.iter().fold(g.nodes[r].clone(), |p, l| clip(&p, l));
            if piece.len() < 3 {
                continue;
            }
            let Some(img) = image(bodies, *j, &piece) else { return g };
            let Some(to) = place(&mut g, &mut todo, (&img, *at), (cfg, pad, merge)) else { return g };
            g.edges.push(Edge { from: r, step: *j, to, piece });
        }
    }
    g
}

/// The node an image of label `at` goes to: the smallest of that label that contains it, else
/// (merging) the node it is merged into, else a new node; `None` at the node cap.
fn place(
    g: &mut Graph,
    todo: &mut VecDeque<usize>,
    (img, at): (&[P2], usize),
    (cfg, pad, merge): (&Config, f64, Option<f64>),
) -> Option<usize> {
    if let Some(s) = smallest_containing(g, at, img) {
        return Some(s);
    }
    let new = enlarge(&hull(img, 1e-15), cfg.enlarge, pad);
    if let Some((s, m)) = merge.and_then(|t| merged(g, at, &new, t)) {
        g.nodes[s] = m;
        if !todo.contains(&s) {
            todo.push_back(s);
        }
        return Some(s);
    }
    if g.nodes.len() >= cfg.max_nodes {
        return None;
    }
    g.nodes.push(new);
    g.label.push(at);
    todo.push_back(g.nodes.len() - 1);
    Some(g.nodes.len() - 1)
}

/// The node of label `at` whose hull with `new` has the least area, and that hull, if its area
/// is at most `t` times the larger of the node's and `new`'s.
fn merged(g: &Graph, at: usize, new: &[P2], t: f64) -> Option<(usize, Vec<P2>)> {
    let joined = |k: &[P2]| hull(&[k, new].concat(), 1e-15);
    let (s, m) = (0..g.nodes.len())
        .filter(|&s| g.label[s] == at)
        .map(|s| (s, joined(&g.nodes[s])))
        .min_by(|a, b| area(&a.1).total_cmp(&area(&b.1)))?;
    (area(&m) <= t * area(&g.nodes[s]).max(area(new))).then_some((s, m))
}
