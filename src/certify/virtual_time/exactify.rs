//! The exact graph (docs/time-to-rest.md §5): cones rounded to dyadic rationals (hull taken
//! exactly), representatives' covectors rounded, balanced and transported exactly to their tied
//! nodes ([`tie`]), the pieces K_r ∩ C_j clipped exactly and their images checked in K_s,
//! and (G1), (G2), (G4) checked exactly. Untrusted: the kernel checks the file.

use super::Num;
use super::frames::Frames;
use super::graph::Graph;
use super::tie::{self, Ties};
use crate::exact::{Q, QExt};
use crate::exact::{QField as _, Ring as _};
use crate::finder::geometry::P2;
use chatter_kernel::geometry::{ConvexPolygon, clip, hull};
use chatter_kernel::model::linalg::{Vec3, dot, is_zero, mat_vec};
use nalgebra::Vector3;

/// Bits of the dyadic rounding of cones and covectors.
const BITS: u64 = 24;

/// A node made exact: its label, K_r (its extreme generators, counter-clockwise: rationals, in
/// the body's field) and b_r.
pub struct Node<E> {
    pub label: usize,
    pub cone: ConvexPolygon<E>,
    pub weight: Vec3<E>,
}

/// The exact nodes and edges of a graph.
pub type Exact<'a, E> = (&'a [Node<E>], &'a [Edge<E>]);

/// An exact edge: r --j--> s with the exact piece K_r ∩ C_j (nonzero).
pub struct Edge<E> {
    pub from: usize,
    pub step: usize,
    pub to: usize,
    pub piece: Vec<Vec3<E>>,
}

fn rat(x: f64) -> Result<Q, String> {
    Q::from_f64_exact(x)
        .map(|q| q.floor_dyadic(BITS))
        .ok_or_else(|| format!("a float search value {x} is not finite"))
}

/// K_r with generators (x, y, -1) rounded to 2^-24, its exact hull.
fn cone<E: Num>(node: &[P2], r: usize) -> Result<ConvexPolygon<E>, String> {
    let gens: Vec<Vec3<Q>> = node
        .iter()
        .map(|p| -> Result<Vec3<Q>, String> { Ok([rat(p.x)?, rat(p.y)?, Q::int(-1)]) })
        .collect::<Result<_, _>>()?;
    let idx = hull(&gens);
    if idx.len() < 3 {
        return Err(format!("node {r}'s cone is degenerate after rounding"));
    }
    Ok(ConvexPolygon::new(idx.into_iter().map(|i| gens[i].clone().map(|x| E::from_q(&x))).collect()))
}

/// The rounded covector of a representative, scaled to largest |component| 1.
fn rounded(b: &Vector3<f64>) -> Result<Vec3<Q>, String> {
    let m = b.amax();
    if m.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
        return Err("a covector of the float search is zero".into());
    }
    Ok([rat(b.x / m)?, rat(b.y / m)?, rat(b.z / m)?])
}

/// The exact nodes, with (G1) checked ((G2) is on the numerators, [`super::numerator`], or on
/// b_r where a_r = c_r b_r, [`super::scale`]).
pub fn nodes<B: Frames>(
    bodies: &[B],
    g: &Graph,
    t: &Ties,
    reps: &[Vector3<f64>],
) -> Result<Vec<Node<B::E>>, String> {
    let body = &bodies[0];
    let zero = B::E::zero;
    let mut balanced = vec![[zero(), zero(), zero()]; g.nodes.len()];
    for k in t.reps() {
        balanced[k] = tie::balanced(bodies, g, t, k, rounded(&reps[k])?.map(|x| B::E::from_q(&x)))?;
    }
    let mut out = Vec::with_capacity(g.nodes.len());
    for (r, node) in g.nodes.iter().enumerate() {
        let weight = tie::transported(body, &t.path[r], balanced[t.rep[r]].clone())?;
        let cone = cone(node, r)?;
        if let Some(i) = cone.vertices.iter().position(|v| !dot(&weight, v).is_negative()) {
            return Err(format!("(G1) fails exactly at node {r}, generator {i}: -b_r·g <= 0"));
        }
        out.push(Node { label: g.label[r], cone, weight });
    }
    Ok(out)
}

/// Whether x (nonzero) lies in K with v < 0.
pub fn inside<E: Num>(k: &ConvexPolygon<E>, x: &Vec3<E>) -> bool {
    x[2].is_negative() && k.contains(x)
}

/// The exact edges: for each node r and step j with K_r ∩ C_j ≠ {0}, the float successor, or
/// (where the float piece was degenerate) the first node of the step's label that contains the
/// exact images; every image of a vertex, under every body's S_j (the corners of a box), lies in
/// K_s (else an error naming it).
pub fn edges<B: Frames>(bodies: &[B], g: &Graph, nodes: &[Node<B::E>]) -> Result<Vec<Edge<B::E>>, String> {
    let body = &bodies[0];
    let mut out = Vec::new();
    for (r, node) in nodes.iter().enumerate() {
        for (j, at) in body.steps(node.label) {
            let cov = body.next_cone(node.label, j);
            let piece: Vec<Vec3<B::E>> = cov.iter().fold(node.cone.vertices.clone(), |p, l| clip(&p, l));
            if piece.iter().all(is_zero) {
                continue;
            }
            let images: Vec<Vec3<B::E>> = (bodies.iter())
                .flat_map(|b| piece.iter().map(|p| mat_vec(&b.step(j), p)).collect::<Vec<_>>())
                .collect();
            let fits = |s: usize| {
                nodes[s].label == at && images.iter().all(|x| is_zero(x) || inside(&nodes[s].cone, x))
            };
            let float = g.edges.iter().find(|e| e.from == r && e.step == j).map(|e| e.to);
            let to = float.filter(|&s| fits(s)).or_else(|| (0..nodes.len()).find(|&s| fits(s)));
            let Some(to) = to else {
                return Err(format!(
                    "an exact image S_{j}(K_{r} ∩ C_{j}) lies in no node (float successor {float:?}): the rounding moved it out"
                ));
            };
            out.push(Edge { from: r, step: j, to, piece });
        }
    }
    Ok(out)
}

/// (G4): I_i(−m_{k,k+1}) ∈ K_e for every entry node e (of contact i) and every k.
pub fn initial_inside<B: Frames>(bodies: &[B], nodes: &[Node<B::E>]) -> Result<(), String> {
    for body in bodies {
        for (e, i) in body.entries().into_iter().enumerate() {
            let map = body.impact(i);
            if let Some(k) = body.all_down().iter().position(|g| !inside(&nodes[e].cone, &mat_vec(&map, g))) {
                return Err(format!(
                    "(G4) fails exactly: I_{i}(-m_{{{k},{}}}) is outside node {e}",
                    (k + 1) % body.n()
                ));
            }
        }
    }
    Ok(())
}
