//! Covectors and numerators together (docs/time-to-rest.md §5, "Numerators by a linear program"):
//! (G3)'s inequality (a_s·R_j q)(−b_r·p) ≤ (a_r·q)(−b_s·S_j p) is linear in the numerators a_r
//! when the covectors b_r are fixed, and linear in the b_r when the a_r are fixed; so are (F),
//! (G1) and (G2). Where the numerators' linear program has no solution for the covectors of the
//! float search, the largest violation t of the normalised (G3) rows is lowered by alternating
//! the two linear programs (each step keeps the other's point feasible, so t never grows) until
//! t < 0. All in `f64` and untrusted: the covectors found are made exact and checked again
//! ([`super::exactify`], [`super::numerator`]), and the kernel checks the file.

use super::Num;
use super::exactify::Exact;
use super::frames::{Frames, apply};
use super::tie::Ties;

use chatter_kernel::model::linalg::{Vec3, is_zero, mat_vec};
use microlp::{ComparisonOp, OptimizationDirection, Problem, SolveOutcome, Variable};

type V = [f64; 3];
type M = [[f64; 3]; 3];

/// Rounds of alternation at most.
const ROUNDS: usize = 30;
/// (G1) with room for the rounding of the covectors to 2^-24: −b_r·g/|g| at least this share of
/// its mean over all nodes and generators.
const G1_MARGIN: f64 = 1e-5;
/// The lowest t asked for (rows scaled to largest entry 1): a strict margin for the rounding.
const T_FLOOR: f64 = -1e-6;
/// A row whose largest entry is below this is taken as identically zero (tied edges).
const ZERO_ROW: f64 = 1e-11;

/// One (G3) inequality: nodes r -> s, the vertex p, its image S_j p, q and R_j q.
struct Pair {
    /// |p| |q|: the row's fixed divisor.
    weight: f64,
    r: usize,
    s: usize,
    p: V,
    sp: V,
    q: V,
    rq: V,
}

/// The problem in `f64`: per node its representative, its transport T_r (x_r = T_r x_rep for
/// covectors, as rows: x_r·y = x_rep·(T_r^T y)), its generators; the (G3) pairs; per
/// representative the kick directions its covector must be orthogonal to.
pub struct Data {
    rep: Vec<usize>,
    reps: usize,
    tr: Vec<M>,
    gens: Vec<Vec<V>>,
    /// Per node, the rest points of (G2).
    ms: Vec<[V; 2]>,
    pairs: Vec<Pair>,
    kicks: Vec<Vec<V>>,
}

fn f<E: Num>(x: &Vec3<E>) -> V {
    std::array::from_fn(|i| x[i].f64())
}

fn dot(a: &V, b: &V) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// T^T y.
fn pull(m: &M, y: &V) -> V {
    std::array::from_fn(|c| (0..3).map(|i| m[i][c] * y[i]).sum())
}

impl Data {
    /// The data of the exact graph (`kicks`: per node index of a representative, its tied kicks),
    /// with the (G3) pairs of every body (the corners of a box).
    pub fn new<B: Frames>(
        bodies: &[B],
        (nodes, edges): Exact<'_, B::E>,
        t: &Ties,
        kicks: Vec<Vec<V>>,
    ) -> Result<Self, String> {
        let body = &bodies[0];
        let tr = super::numerator::transports(body, t)?;
        let mut pairs = Vec::new();
        for (body, e) in bodies.iter().flat_map(|b| edges.iter().map(move |e| (b, e))) {
            let (rel, step) = (body.relabel(e.step), body.step(e.step));
            for p in e.piece.iter().filter(|p| !is_zero(p)) {
                for q in body.landing(e.step) {
                    let (p, sp, rq) = (f(p), f(&mat_vec(&step, p)), f(&apply(rel.as_ref(), &q)));
                    let q = f(&q);
                    let weight = (dot(&p, &p) * dot(&q, &q)).sqrt();
                    pairs.push(Pair { weight, r: e.from, s: e.to, p, sp, q, rq });
                }
            }
        }
        let gens = nodes.iter().map(|n| n.cone.vertices.iter().map(f).collect()).collect();
        let ms = nodes.iter().map(|x| body.heights(x.label).map(|m| f(&m))).collect();
        Ok(Data { rep: t.rep.clone(), reps: nodes.len(), tr, gens, ms, pairs, kicks })
    }

    /// x_r from the representatives' x.
    fn at(&self, x: &[V], r: usize) -> V {
        let (m, k) = (&self.tr[r], &x[self.rep[r]]);
        std::array::from_fn(|i| (0..3).map(|c| m[i][c] * k[c]).sum())
    }
}

/// A linear program over one covector per representative and t.
struct Lp {
    lp: Problem,
    x: Vec<[Variable; 3]>,
    t: Variable,
}

impl Lp {
    /// Variables in [−bound, bound].
    fn new(reps: usize, bound: f64) -> Self {
        let mut lp = Problem::new(OptimizationDirection::Minimize);
        let x = (0..reps).map(|_| std::array::from_fn(|_| lp.add_var(0.0, (-bound, bound)))).collect();
        let t = lp.add_var(1.0, (T_FLOOR, f64::INFINITY));
        Lp { lp, x, t }
    }

    /// Σ coefficient·x_rep ≤ rhs (+ t when `with_t`), the row scaled to largest entry 1 (rows
    /// that are zero are dropped).
    fn row(&mut self, terms: &[(usize, V)], rhs: f64, t_scale: Option<f64>, op: ComparisonOp) {
        let mut merged: std::collections::BTreeMap<usize, V> = std::collections::BTreeMap::new();
        for (k, c) in terms {
            let m = merged.entry(*k).or_insert([0.0; 3]);
            (0..3).for_each(|i| m[i] += c[i]);
        }
        let big = merged.values().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
        if big < ZERO_ROW {
            return;
        }
        // A row with t is divided by its pair's fixed weight, the same in both steps, so that the
        // other step's point keeps its t and t never grows; the others by their largest entry.
        let w = t_scale.unwrap_or(big);
        let mut e: Vec<(Variable, f64)> = Vec::new();
        for (k, c) in &merged {
            e.extend(self.x[*k].iter().zip(c).map(|(v, c)| (*v, c / w)));
        }
        if t_scale.is_some() {
            e.push((self.t, -1.0));
        }
        self.lp.add_constraint(e, op, rhs / w);
    }

    fn solve(self) -> Option<(Vec<V>, f64)> {
        let out = std::panic::catch_unwind(move || {
            let sol = match self.lp.solve() {
                Ok(SolveOutcome::Solution(s)) => s,
                _ => return None,
            };
            let x = self.x.iter().map(|v| v.map(|x| sol.var_value(x))).collect();
            Some((x, sol.var_value(self.t)))
        });
        out.ok().flatten()
    }
}

/// Σ_r Σ_g −x_r·g/|g| as a row on the representatives: the scale kept fixed in a step, so that
/// t is measured alike in both steps.
fn size_row(d: &Data) -> Vec<(usize, V)> {
    let mut terms = Vec::new();
    for r in 0..d.reps {
        for g in &d.gens[r] {
            let n = dot(g, g).sqrt();
            terms.push((d.rep[r], pull(&d.tr[r], g).map(|c| -c / n)));
        }
    }
    terms
}

/// The size Σ_r Σ_g −x_r·g/|g| of covectors `x` (one per representative).
fn size(d: &Data, x: &[V]) -> f64 {
    (0..d.reps)
        .flat_map(|r| d.gens[r].iter().map(move |g| (r, g)))
        .map(|(r, g)| -dot(&d.at(x, r), g) / dot(g, g).sqrt())
        .sum()
}

/// The numerators for fixed covectors `b`, least t (of the size `scale` when given).
fn numerator_step(d: &Data, b: &[V], scale: Option<f64>) -> Option<(Vec<V>, f64)> {
    let mut lp = Lp::new(d.reps, 1e9);
    if let Some(c) = scale {
        lp.row(&size_row(d), c, None, ComparisonOp::Eq);
    }
    for r in 0..d.reps {
        let (k, br) = (d.rep[r], d.at(b, r));
        for g in &d.gens[r] {
            lp.row(&[(k, pull(&d.tr[r], g))], dot(&br, g), None, ComparisonOp::Le);
        }
        for m in &d.ms[r] {
            lp.row(&[(k, pull(&d.tr[r], m))], 0.0, None, ComparisonOp::Ge);
        }
    }
    for x in &d.pairs {
        let (dr, ds) = (-dot(&d.at(b, x.r), &x.p), -dot(&d.at(b, x.s), &x.sp));
        let left = pull(&d.tr[x.s], &x.rq).map(|c| c * dr);
        let right = pull(&d.tr[x.r], &x.q).map(|c| -c * ds);
        lp.row(&[(d.rep[x.s], left), (d.rep[x.r], right)], 0.0, Some(x.weight), ComparisonOp::Le);
    }
    lp.solve()
}

/// The covectors for fixed numerators `a`, least t, of the size `scale`.
fn covector_step(d: &Data, a: &[V], (scale, bound): (f64, f64)) -> Option<(Vec<V>, f64)> {
    let count = d.gens.iter().map(Vec::len).sum::<usize>().max(1) as f64;
    let least = G1_MARGIN * scale / count;
    let mut lp = Lp::new(d.reps, bound);
    lp.row(&size_row(d), scale, None, ComparisonOp::Eq);
    for r in 0..d.reps {
        let (k, ar) = (d.rep[r], d.at(a, r));
        for g in &d.gens[r] {
            let norm = dot(g, g).sqrt();
            lp.row(&[(k, pull(&d.tr[r], g))], -least * norm, None, ComparisonOp::Le);
            lp.row(&[(k, pull(&d.tr[r], g))], dot(&ar, g), None, ComparisonOp::Ge);
        }
    }
    for (k, kicks) in d.kicks.iter().enumerate() {
        for u in kicks {
            lp.row(&[(k, *u)], 0.0, None, ComparisonOp::Eq);
        }
    }
    // A row's part along a representative's tied kicks is zero on every admissible covector:
    // removed, so that the rows of the tied edges, zero there, are dropped (they hold exactly).
    let along =
        |k: usize, c: V| d.kicks[k].iter().fold(c, |c, u| std::array::from_fn(|i| c[i] - dot(&c, u) * u[i]));
    for x in &d.pairs {
        let (after, before) = (dot(&d.at(a, x.s), &x.rq), dot(&d.at(a, x.r), &x.q));
        let left = pull(&d.tr[x.r], &x.p).map(|c| -c * after);
        let right = pull(&d.tr[x.s], &x.sp).map(|c| c * before);
        let (kr, ks) = (d.rep[x.r], d.rep[x.s]);
        let mut merged = [(kr, left), (ks, right)];
        if kr == ks {
            merged = [(kr, std::array::from_fn(|i| left[i] + right[i])), (ks, [0.0; 3])];
        }
        let terms = merged.map(|(k, c)| (k, along(k, c)));
        lp.row(&terms, 0.0, Some(x.weight), ComparisonOp::Le);
    }
    lp.solve()
}

/// Covectors (one per representative, indexed by node) whose numerators' program is feasible
/// with room, by alternation from `b`; `None` when t stops falling above 0 (with `pace`, also
/// when it falls too slowly to pass 0 in the rounds left: [`hopeless`]).
pub fn improve(d: &Data, b: Vec<V>, pace: bool) -> Option<Vec<V>> {
    let (mut b, mut last, mut scale_a) = (b, f64::INFINITY, None);
    // The covectors keep their size and their components within 4 times the largest at the start
    // (the exact rounding is relative to the largest component: (G1) must keep its margin).
    let scale_b = (size(d, &b), 4.0 * b.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs())));
    for round in 1..=ROUNDS {
        let (a, t) = numerator_step(d, &b, scale_a)?;
        scale_a = scale_a.or(Some(size(d, &a)));
        if t < T_FLOOR / 2.0 {
            return Some(b);
        }
        let (nb, t2) = covector_step(d, &a, scale_b)?;
        if t2 < T_FLOOR / 2.0 {
            return Some(nb);
        }
        if t2 > 0.0 && (t2 > last * (1.0 - 1e-6) || pace && hopeless(last, t2, ROUNDS - round)) {
            return None;
        }
        (b, last) = (nb, t2.min(t));
    }
    None
}

/// At the pace of the last round (from `last` to `t`), t would not pass 0 in the rounds left.
fn hopeless(last: f64, t: f64, left: usize) -> bool {
    t > (last - t) * left as f64
}
