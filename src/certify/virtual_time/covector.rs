//! The covectors b_r in `f64` (docs/time-to-rest.md §5): per tied component, a direction on the
//! sphere that keeps (G1), (G2) with margin, makes the component's own edges contract and needs
//! the least scale c_r = max over outgoing edges of ratio × c_s (a pattern search, a few rounds
//! over the components). Untrusted: the scales that go into the file are exact ([`super::scale`]).

use super::frames::FloatFrames;
use super::graph::{Edge, Graph};
use super::tie::{self, Ties};
use crate::finder::geometry::{P2, lift};
use nalgebra::Vector3;

type V3 = Vector3<f64>;

/// The float model pieces the search needs: the rounded maps and the graph's labels.
pub struct Maps<'a> {
    pub body: &'a FloatFrames,
    label: Vec<usize>,
}

impl<'a> Maps<'a> {
    pub fn new(body: &'a FloatFrames, g: &Graph) -> Self {
        Maps { body, label: g.label.clone() }
    }

    /// The step of the edge back along a tie from node r reached by step j.
    pub fn back(&self, r: usize, j: usize) -> Option<usize> {
        self.body.back(self.label[r], j)
    }

    /// b transported along the steps of a tie path (docs/time-to-rest.md §5).
    pub fn transport(&self, path: &[usize], b: V3) -> V3 {
        path.iter().fold(b, |b, &j| self.body.inverse(j).transpose() * b)
    }

    /// An orthonormal basis of the kick directions d_j of the component's tie-tree edges carried
    /// to its representative (b_r·d_j = 0 is needed there: [`super::tie`]).
    pub fn tied_kicks(&self, g: &Graph, t: &Ties, k: usize) -> Vec<V3> {
        let mut basis: Vec<V3> = Vec::new();
        let back = |r: usize, j: usize| self.back(r, j);
        for e in g.edges.iter().filter(|e| t.rep[e.from] == k && tie::along_tree(t, &back, e)) {
            let d = self.body.kick(e.step);
            let a = t.path[e.from].iter().rev().fold(d, |d, &i| self.body.inverse(i) * d);
            let a = basis.iter().fold(a, |a, u| a - u * u.dot(&a));
            if a.norm() > 1e-9 {
                basis.push(a.normalize());
            }
        }
        basis
    }

    fn m(&self, k: i64) -> V3 {
        self.body.rest(k)
    }
}

/// The largest ratio Φ_s(after)/Φ_r(before) over the piece's vertices and q ∈ {m_{j−1,j},
/// m_{j,j+1}} (the float form of (G3)); infinite where a denominator is not positive.
pub fn ratio(maps: &Maps, br: &V3, bs: &V3, j: usize, piece: &[P2]) -> f64 {
    let (s, rel) = (maps.body.step(j), maps.body.relabel(j));
    // b_s·R_j q and b_r·q do not depend on the vertex.
    let terms = [maps.m(j as i64 - 1), maps.m(j as i64)].map(|q| (bs.dot(&(rel * q)), br.dot(&q)));
    let mut worst: f64 = 0.0;
    for p in piece.iter().map(lift) {
        let sp = s * p;
        let (dr, ds) = (-br.dot(&p), -bs.dot(&sp));
        if dr <= 0.0 || ds <= 0.0 {
            return f64::INFINITY;
        }
        for (a, b) in terms {
            let (after, before) = (a / ds, b / dr);
            if after <= 1e-15 && before <= 1e-15 {
                continue;
            }
            if before <= 1e-15 {
                return f64::INFINITY;
            }
            worst = worst.max(after / before);
        }
    }
    worst
}

/// (G1) and (G2) with margins on node r: b·m > 1e-9 at both rest points of its label and
/// −b·g > 1e-6 on the node.
pub fn admissible(maps: &Maps, b: &V3, g: &Graph, r: usize) -> bool {
    let [m0, m1] = maps.body.heights(g.label[r]);
    b.dot(&m0).min(b.dot(&m1)) > 1e-9 && g.nodes[r].iter().all(|p| -b.dot(&lift(p)) > 1e-6)
}

/// n × n/2 unit directions on a latitude-longitude grid.
fn sphere(n: usize) -> impl Iterator<Item = V3> {
    let half = n / 2;
    (0..n).flat_map(move |i| {
        (0..half).map(move |k| {
            let th = std::f64::consts::TAU * i as f64 / n as f64;
            let ph = std::f64::consts::PI * (k as f64 + 0.5) / half as f64;
            V3::new(ph.sin() * th.cos(), ph.sin() * th.sin(), ph.cos())
        })
    })
}

/// Coordinate pattern search on the sphere from b0, halving the step when nothing improves.
fn refine(score: &dyn Fn(&V3) -> f64, b0: V3, steps: usize) -> (V3, f64) {
    let (mut b, mut s, mut h) = (b0, score(&b0), 0.2);
    for _ in 0..steps {
        let mut improved = false;
        for d in [V3::x(), -V3::x(), V3::y(), -V3::y(), V3::z(), -V3::z()] {
            let c = (b + d * h).normalize();
            let sc = score(&c);
            if sc < s {
                (b, s, improved) = (c, sc, true);
            }
        }
        if !improved {
            h /= 2.0;
        }
    }
    (b, s)
}

/// The best direction of the grid (and `extra`), refined.
fn best(score: &dyn Fn(&V3) -> f64, grid: usize, extra: Option<V3>, steps: usize) -> (V3, f64) {
    let start = sphere(grid).chain(extra).min_by(|a, b| score(a).total_cmp(&score(b))).unwrap_or_else(V3::z);
    refine(score, start, steps)
}

/// A first covector of node k alone: its own outgoing edges contract with b_s = b_r.
fn first(maps: &Maps, g: &Graph, k: usize, grid: usize) -> V3 {
    let outs: Vec<&Edge> = g.edges.iter().filter(|e| e.from == k).collect();
    let score = |b: &V3| {
        if !admissible(maps, b, g, k) {
            return f64::INFINITY;
        }
        outs.iter().map(|e| ratio(maps, b, b, e.step, &e.piece)).fold(0.0, f64::max)
    };
    best(&score, grid, None, 60).0
}

/// The search's state: the representatives' covectors and float scales.
struct State {
    b: Vec<V3>,
    c: Vec<f64>,
    /// Per representative, [`Maps::tied_kicks`].
    kicks: Vec<Vec<V3>>,
}

/// b with its components along the tied kicks removed (the float form of [`tie::balanced`]).
fn balance(kicks: &[V3], b: &V3) -> V3 {
    kicks.iter().fold(*b, |b, u| b - u * u.dot(&b))
}

/// The scale a candidate covector `cand` of the component of `k` needs (infinite if a node of it
/// is not admissible, large if one of its internal edges does not contract).
fn required(maps: &Maps, g: &Graph, t: &Ties, st: &State, k: usize, cand: &V3) -> f64 {
    let cand = &balance(&st.kicks[k], cand);
    let bof = |r: usize| maps.transport(&t.path[r], if t.rep[r] == k { *cand } else { st.b[t.rep[r]] });
    if !t.members(k).iter().all(|&r| admissible(maps, &bof(r), g, r)) {
        return f64::INFINITY;
    }
    let mut v: f64 = 1.0;
    for e in g.edges.iter().filter(|e| t.rep[e.from] == k) {
        let x = ratio(maps, &bof(e.from), &bof(e.to), e.step, &e.piece);
        if t.rep[e.to] == k {
            if x > 1.0 + 1e-12 {
                return 1e6 * x;
            }
        } else {
            v = v.max(x * (1.0 + 1e-3) * st.c[t.rep[e.to]]);
        }
    }
    v
}

/// The representatives' covectors (indexed by node; only representatives are meaningful), or
/// the first component for which none keeps (G1) and (G2).
pub fn search(maps: &Maps, g: &Graph, t: &Ties, rounds: usize, grid: usize) -> Result<Vec<V3>, String> {
    let reps = t.reps();
    let kicks = (0..g.nodes.len())
        .map(|k| if t.rep[k] == k { maps.tied_kicks(g, t, k) } else { Vec::new() })
        .collect();
    let mut st = State { b: vec![V3::z(); g.nodes.len()], c: vec![1.0; g.nodes.len()], kicks };
    for &k in &reps {
        st.b[k] = balance(&st.kicks[k], &first(maps, g, k, grid));
    }
    for _ in 0..rounds {
        let mut delta: f64 = 0.0;
        for &k in reps.iter().rev() {
            let score = |b: &V3| required(maps, g, t, &st, k, b);
            let (b, s) = best(&score, grid, Some(st.b[k]), 40);
            if s.is_finite() {
                delta = delta.max((s - st.c[k]).abs() / st.c[k]);
                (st.b[k], st.c[k]) = (balance(&st.kicks[k], &b), s);
            }
        }
        if delta < 1e-12 {
            break;
        }
    }
    // Only a component that no covector keeps admissible stops the search here. A scale of 10^6
    // or more is no failure (the search's penalty for an edge inside a component that does not
    // contract is of that size too), and such an edge, like a cycle whose product exceeds 1, is
    // named with its exact product by the exact scales ([`super::scale`]). A component where no
    // covector keeps (G2) takes the one with the widest margin in (G1): the numerators a_r carry
    // (G2) in version 2 of the file ([`super::numerator`]).
    for &k in &reps {
        if required(maps, g, t, &st, k, &st.b[k]).is_infinite() {
            st.b[k] = widest(maps, g, t, &st, k, grid).ok_or_else(|| {
                format!(
                    "the float covector search found none for node {k}'s component of {} tied nodes that keeps (G1) with margins",
                    t.members(k).len()
                )
            })?;
        }
    }
    Ok(st.b)
}

/// The balanced direction of the grid whose least −b_r·g/|g| over the component of `k` is the
/// largest, if that is above 10^-6 ((G1) alone).
fn widest(maps: &Maps, g: &Graph, t: &Ties, st: &State, k: usize, grid: usize) -> Option<V3> {
    let margin = |b: &V3| {
        let b = balance(&st.kicks[k], b);
        let least = |r: usize| {
            let br = maps.transport(&t.path[r], b);
            g.nodes[r].iter().map(|p| -br.dot(&lift(p)) / lift(p).norm()).fold(f64::INFINITY, f64::min)
        };
        t.members(k).into_iter().map(least).fold(f64::INFINITY, f64::min)
    };
    let b = sphere(grid).max_by(|a, b| margin(a).total_cmp(&margin(b)))?;
    (margin(&b) > 1e-6).then(|| balance(&st.kicks[k], &b))
}
