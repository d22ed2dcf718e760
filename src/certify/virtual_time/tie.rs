//! Tied nodes (docs/time-to-rest.md §5, "nodes linked both ways by j and n − j share their
//! covector up to relabelling"): where r --j--> s and s --(n−j)--> r, b_s = b_r R_j^{-1} and
//! c_s = c_r, so that (G3) holds with equality at the vertices with u_j = 0. Then b_s·S_j p =
//! b_r·I_j p = b_r·p − β u_j(p) (b_r·d_j), so (G3) on the edges r -> s and s -> r holds at every
//! vertex only if b_r·d_j = 0 (the two edges ask for opposite signs, the pattern of PCC with its
//! eigenvalue 1 of S_{n−j} S_j): the exact covectors are balanced to meet it exactly. For a
//! general body (no relabelling) the tie is r --j--> s and s --i(r)--> r with b_s = b_r and the
//! kick w_j ([`super::frames`]). Untrusted.

use super::Num;
use super::frames::{Frames, apply, relabel_inverse};
use super::graph::{Edge, Graph};
use crate::exact::Ring;
use chatter_kernel::model::linalg::{Vec3, dot};

/// Each node's representative and the steps j_1, j_2, ... from it: b = b_rep R_{j_1}^{-1} R_{j_2}^{-1} ...
pub struct Ties {
    pub rep: Vec<usize>,
    pub path: Vec<Vec<usize>>,
}

impl Ties {
    /// The representatives, in increasing order.
    pub fn reps(&self) -> Vec<usize> {
        (0..self.rep.len()).filter(|&r| self.rep[r] == r).collect()
    }

    /// The nodes tied to the representative `k` (itself included).
    pub fn members(&self, k: usize) -> Vec<usize> {
        (0..self.rep.len()).filter(|&r| self.rep[r] == k).collect()
    }
}

/// The components of the "linked both ways" relation (r --j--> s and s --back(r, j)--> r, with
/// `back` the step of the edge back: n − j, or r's label for adjacent contacts), explored depth
/// first from the lowest node.
pub fn ties(back: &dyn Fn(usize, usize) -> Option<usize>, nodes: usize, edges: &[Edge]) -> Ties {
    let linked = |r: usize, s: usize, j: usize| {
        back(r, j).is_some_and(|b| edges.iter().any(|e| (e.from, e.step, e.to) == (s, b, r)))
    };
    let mut adj: Vec<Vec<(usize, usize)>> = vec![Vec::new(); nodes];
    for e in edges.iter().filter(|e| e.to != e.from && linked(e.from, e.to, e.step)) {
        adj[e.from].push((e.to, e.step));
    }
    let (mut rep, mut path) = ((0..nodes).collect::<Vec<_>>(), vec![Vec::new(); nodes]);
    let mut seen = vec![false; nodes];
    for r0 in 0..nodes {
        if seen[r0] {
            continue;
        }
        seen[r0] = true;
        let mut stack = vec![r0];
        while let Some(r) = stack.pop() {
            for &(s, j) in &adj[r] {
                if !seen[s] {
                    seen[s] = true;
                    rep[s] = r0;
                    path[s] = [path[r].clone(), vec![j]].concat();
                    stack.push(s);
                }
            }
        }
    }
    Ties { rep, path }
}

/// Whether the edge x --i--> y joins a node to its parent or child in the tie tree, where
/// b_y = b_x R_i^{-1} holds exactly (R_{n-i} = R_i^{-1}; `back` as for [`ties`]); other edges
/// inside a component are ordinary ones.
pub fn along_tree(t: &Ties, back: &dyn Fn(usize, usize) -> Option<usize>, e: &Edge) -> bool {
    let (px, py) = (&t.path[e.from], &t.path[e.to]);
    let child =
        |a: &[usize], b: &[usize], j: usize| a.len() == b.len() + 1 && a[..b.len()] == *b && a[b.len()] == j;
    t.rep[e.from] == t.rep[e.to]
        && e.from != e.to
        && (child(py, px, e.step) || back(e.from, e.step).is_some_and(|b| child(px, py, b)))
}

/// b transported along a tie path, exactly: b R_{j_1}^{-1} R_{j_2}^{-1} ... as a covector (b
/// itself for a general body).
pub fn transported<B: Frames>(body: &B, path: &[usize], b: Vec3<B::E>) -> Result<Vec3<B::E>, String> {
    path.iter().try_fold(b, |b, &j| -> Result<Vec3<B::E>, String> {
        let Some(inv) = relabel_inverse(body, j)? else { return Ok(b) };
        Ok(std::array::from_fn(|c| (0..3).fold(B::E::zero(), |s, r| s.plus(&b[r].times(&inv[r][c])))))
    })
}

/// The vector a with b_rep·a = b_r·d_j for the tied edge r --j--> (the kick direction d_j of
/// an impact at contact j in r's frame, carried back along r's tie path).
fn kick_at_rep<B: Frames>(body: &B, path: &[usize], j: usize) -> Result<Vec3<B::E>, String> {
    let d = body.kick(j);
    path.iter().rev().try_fold(d, |d, &i| Ok(apply(relabel_inverse(body, i)?.as_ref(), &d)))
}

/// b minus its exact orthogonal projection on the span of the tied edges' kick directions (of
/// every body: d_j is affine in κ, so b_r·d_j = 0 at the corners of a box holds on the box), so
/// that b_r·d_j = 0 exactly on every tied edge of the component of `k`.
pub fn balanced<B: Frames>(
    bodies: &[B],
    g: &Graph,
    t: &Ties,
    k: usize,
    b: Vec3<B::E>,
) -> Result<Vec3<B::E>, String> {
    let back = |r: usize, j: usize| bodies[0].back(g.label[r], j);
    let tied = |e: &&Edge| t.rep[e.from] == k && along_tree(t, &back, e);
    let mut basis: Vec<Vec3<B::E>> = Vec::new();
    for e in g.edges.iter().filter(tied) {
        for body in bodies {
            let mut a = kick_at_rep(body, &t.path[e.from], e.step)?;
            for u in &basis {
                a = minus_along(&a, u);
            }
            if a.iter().any(|x| !x.is_zero()) {
                basis.push(a);
            }
        }
    }
    let b = basis.iter().fold(b, |b, u| minus_along(&b, u));
    if b.iter().all(Ring::is_zero) {
        return Err(format!("the tied edges of node {k}'s component leave no covector"));
    }
    Ok(b)
}

/// x minus its component along u (u ≠ 0), exactly.
fn minus_along<E: Num>(x: &Vec3<E>, u: &Vec3<E>) -> Vec3<E> {
    let f = dot(x, u).over(&dot(u, u)).unwrap_or_else(E::zero);
    std::array::from_fn(|i| x[i].minus(&f.times(&u[i])))
}
