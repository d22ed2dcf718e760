//! The scales c_r, exactly (docs/time-to-rest.md §5, (G3)): each edge e = (r, j, s) and each
//! vertex p of K_r ∩ C_j and q ∈ {m_{j−1,j}, m_{j,j+1}} give, with L = (b_s·R_j q)(−b_r·p) and
//! R = (b_r·q)(−b_s·S_j p) > 0 or not, the condition c_s L ≤ c_r R: nothing when L ≤ 0 ≤ R,
//! c_r ≥ (L/R) c_s when both are positive, c_s ≥ (R/L) c_r when both are negative, and no scales
//! at all otherwise. The least c ≥ 1 meeting all of them is a longest path (Bellman-Ford); it
//! fails exactly when a cycle's product of ratios exceeds 1. Untrusted: the kernel checks.

use super::Num;
use super::exactify::{Edge, Node};
use super::frames::{Frames, apply};
use crate::exact::{Q, QExt};
use chatter_kernel::exact::{OrderedField as _, Ring as _};
use chatter_kernel::model::linalg::{Vec3, dot, is_zero, mat_vec, neg};
use std::collections::BTreeMap;

/// c_x ≥ factor · c_y.
#[derive(Clone)]
pub struct Constraint {
    pub x: usize,
    pub y: usize,
    pub factor: Q,
}

/// The conditions of (G3) on the scales, the largest factor per ordered pair (x, y).
pub fn constraints<B: Frames>(
    body: &B,
    nodes: &[Node<B::E>],
    edges: &[Edge<B::E>],
) -> Result<Vec<Constraint>, String> {
    for (r, node) in nodes.iter().enumerate() {
        if body.heights(node.label).iter().any(|m| dot(&node.weight, m).is_negative()) {
            return Err(format!("(G2) fails exactly at node {r} with a_r = c_r b_r: b_r·m < 0"));
        }
    }
    let mut by_pair: BTreeMap<(usize, usize), Constraint> = BTreeMap::new();
    for e in edges {
        for (i, p) in e.piece.iter().enumerate().filter(|(_, p)| !is_zero(p)) {
            for c in vertex(body, nodes, e, p)
                .map_err(|why| format!("(G3) at node {}, step {}, vertex {i}: {why}", e.from, e.step))?
            {
                let keep = by_pair.get(&(c.x, c.y)).is_none_or(|old| c.factor > old.factor);
                if keep {
                    by_pair.insert((c.x, c.y), c);
                }
            }
        }
    }
    Ok(by_pair.into_values().collect())
}

/// The conditions at one vertex p of K_r ∩ C_j (both q), each factor a rational upper bound on
/// the ratio (the ratio itself over Q).
fn vertex<B: Frames>(
    body: &B,
    nodes: &[Node<B::E>],
    e: &Edge<B::E>,
    p: &Vec3<B::E>,
) -> Result<Vec<Constraint>, String> {
    let (br, bs) = (&nodes[e.from].weight, &nodes[e.to].weight);
    let (sp, rel) = (mat_vec(&body.step(e.step), p), body.relabel(e.step));
    let (dr, ds) = (dot(br, &neg(p)), dot(bs, &neg(&sp)));
    let mut out = Vec::new();
    for q in body.landing(e.step) {
        let l = dot(bs, &apply(rel.as_ref(), &q)).times(&dr);
        let r = dot(br, &q).times(&ds);
        let ratio = |a: &B::E, b: &B::E| a.over(b).map_or_else(|| Q::int(0), |x| x.upper());
        let (x, y, factor) = match (l.is_positive(), r.is_positive(), l.is_negative(), r.is_negative()) {
            (false, _, _, false) => continue,
            (true, true, _, _) => (e.from, e.to, ratio(&l, &r)),
            (_, _, true, true) => (e.to, e.from, ratio(&r, &l)),
            _ => return Err(format!("no scales satisfy it (L = {l}, R = {r})")),
        };
        out.push(Constraint { x, y, factor });
    }
    Ok(out)
}

/// One relaxation pass; `bits` rounds every raised value up to a dyadic. The nodes raised.
fn pass(c: &mut [Q], pred: &mut [Option<usize>], cons: &[Constraint], bits: Option<u64>) -> Vec<usize> {
    let mut raised = Vec::new();
    for (i, k) in cons.iter().enumerate() {
        let want = &k.factor * &c[k.y];
        if want > c[k.x] {
            c[k.x] = bits.map_or(want.clone(), |b| want.ceil_dyadic(b));
            pred[k.x] = Some(i);
            raised.push(k.x);
        }
    }
    raised
}

/// The least scales c ≥ 1 (exact), or, when `bits` is given, dyadic ones slightly above; `Err`
/// holds the last node raised and the predecessors when `passes` did not settle them.
fn relax(
    n: usize,
    cons: &[Constraint],
    bits: Option<u64>,
    passes: usize,
) -> Result<Vec<Q>, (usize, Vec<Option<usize>>)> {
    let (mut c, mut pred) = (vec![Q::int(1); n], vec![None; n]);
    for _ in 0..passes {
        if pass(&mut c, &mut pred, cons, bits).is_empty() {
            return Ok(c);
        }
    }
    let last = pass(&mut c, &mut pred, cons, bits).last().copied();
    last.map_or(Ok(c), |x| Err((x, pred)))
}

/// A cycle of the predecessor graph reached from x, with its exact product of factors.
fn cycle(x: usize, pred: &[Option<usize>], cons: &[Constraint]) -> Option<(Vec<usize>, Q)> {
    let mut at = x;
    for _ in 0..pred.len() {
        at = cons[pred[at]?].y;
    }
    let (start, mut nodes, mut product) = (at, vec![at], Q::int(1));
    loop {
        let k = &cons[pred[at]?];
        product = &product * &k.factor;
        at = k.y;
        if at == start {
            return Some((nodes, product));
        }
        nodes.push(at);
    }
}

/// The scales: dyadic (2^-40) where the rounded iteration settles within 4N + 16 passes, else the
/// exact least ones (N + 1 passes); an error names a cycle whose product of ratios exceeds 1.
pub fn scales(n: usize, cons: &[Constraint]) -> Result<Vec<Q>, String> {
    if let Ok(c) = relax(n, cons, Some(40), 4 * n + 16) {
        return Ok(c);
    }
    relax(n, cons, None, n + 1).map_err(|(x, pred)| match cycle(x, &pred, cons) {
        Some((nodes, product)) => format!(
            "no scales exist: the cycle of nodes {} has the exact product of ratios {} > 1 (about {:.9})",
            nodes.iter().map(ToString::to_string).collect::<Vec<_>>().join(" -> "),
            if product.to_string().len() > 60 { "(long)".to_string() } else { product.to_string() },
            product.to_f64()
        ),
        None => format!("the scales did not settle within {} passes", n + 1),
    })
}
