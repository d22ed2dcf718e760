//! The numerators a_r of the virtual time Φ_r(q, p) = (a_r·q)/(−b_r·p) (docs/time-to-rest.md §5,
//! version 2 of the file): with the covectors b_r fixed, the flight rule (F), (G2), (G3) and (G5)
//! are linear in the a_r and in B, so the least B is a linear program. It is solved in `f64`
//! with a margin on every inequality that is not identically zero, the representatives'
//! numerators are rounded to dyadic rationals and transported exactly to their tied nodes, and
//! every condition is then checked exactly. Version 1's a_r = c_r b_r is one feasible point, so
//! the program's B is never worse than the scales'. Untrusted: the kernel checks the file.

use super::Num;
use super::exactify::{Edge, Node};
use super::frames::{Frames, apply};
use super::tie::{self, Ties};
use crate::exact::{Q, QExt};
use crate::exact::{QField as _, Ring as _};
use chatter_kernel::model::linalg::{Vec3, dot, is_zero, mat_vec, neg};
use microlp::{ComparisonOp, OptimizationDirection, Problem, SolveOutcome, Variable};

/// Bits of the dyadic rounding of the numerators and of B.
const BITS: u64 = 40;
/// The margins kept by every inequality whose row is not zero (rows scaled to largest entry 1),
/// tried in turn: room for the solver's tolerance and the rounding, then none (the exact check
/// decides).
const MARGINS: [f64; 2] = [1e-7, 0.0];
/// A row whose largest entry is below this is taken as identically zero (the tied edges, where
/// (G3) holds with equality at every vertex); the exact check decides.
const ZERO_ROW: f64 = 1e-11;

/// The numerators a_r (exact) and the bound B of (G5), rounded up.
pub struct Numerators<E> {
    pub a: Vec<Vec3<E>>,
    pub bound: Q,
}

/// a_r = T_r a_rep: T_r in `f64` as the images of the unit covectors (columns).
pub(super) fn transports<B: Frames>(body: &B, t: &Ties) -> Result<Vec<[[f64; 3]; 3]>, String> {
    let unit = |i: usize| -> Vec3<B::E> { std::array::from_fn(|c| B::E::from_i64(i64::from(c == i))) };
    (0..t.rep.len())
        .map(|r| {
            let cols: Vec<Vec3<B::E>> =
                (0..3).map(|i| tie::transported(body, &t.path[r], unit(i))).collect::<Result<_, _>>()?;
            Ok(std::array::from_fn(|row| std::array::from_fn(|col| cols[col][row].f64())))
        })
        .collect()
}

/// A linear form on the representatives' numerators: (representative, coefficients) terms.
type Row = Vec<(usize, [f64; 3])>;

/// The form x ↦ a_r·x as a row on a_rep(r): T_r^T x.
fn form<E: Num>(t: &Ties, tr: &[[[f64; 3]; 3]], r: usize, x: &Vec3<E>) -> Row {
    let xf: [f64; 3] = std::array::from_fn(|i| x[i].f64());
    let m = &tr[r];
    vec![(t.rep[r], std::array::from_fn(|c| (0..3).map(|i| m[i][c] * xf[i]).sum()))]
}

fn scaled(row: Row, f: f64) -> Row {
    row.into_iter().map(|(k, c)| (k, c.map(|x| x * f))).collect()
}

/// The linear program's rows `row·a ≤ rhs`, each with the condition it stands for.
struct Rows {
    rows: Vec<(Row, f64, String)>,
}

impl Rows {
    fn push(&mut self, row: Row, rhs: f64, what: String) {
        self.rows.push((row, rhs, what));
    }
}

/// (F): a_r·g ≤ b_r·g on every generator g; (G2): a_r·m ≥ 0.
fn node_rows<B: Frames>(body: &B, nodes: &[Node<B::E>], t: &Ties, tr: &[[[f64; 3]; 3]], rows: &mut Rows) {
    for (r, node) in nodes.iter().enumerate() {
        for (i, g) in node.cone.vertices.iter().enumerate() {
            rows.push(
                form(t, tr, r, g),
                dot(&node.weight, g).f64(),
                format!("(F) at node {r}, generator {i}"),
            );
        }
        for m in body.heights(node.label) {
            rows.push(scaled(form(t, tr, r, &m), -1.0), 0.0, format!("(G2) at node {r}"));
        }
    }
}

/// (G3): (a_s·R_j q)(−b_r·p) − (a_r·q)(−b_s·S_j p) ≤ 0 at every vertex p and q.
fn edge_rows<B: Frames>(
    body: &B,
    nodes: &[Node<B::E>],
    edges: &[Edge<B::E>],
    t: &Ties,
    tr: &[[[f64; 3]; 3]],
    rows: &mut Rows,
) {
    for e in edges {
        let (rel, step) = (body.relabel(e.step), body.step(e.step));
        for (i, p) in e.piece.iter().enumerate().filter(|(_, p)| !is_zero(p)) {
            let dr = dot(&nodes[e.from].weight, &neg(p)).f64();
            let ds = dot(&nodes[e.to].weight, &neg(&mat_vec(&step, p))).f64();
            for q in body.landing(e.step) {
                let after = scaled(form(t, tr, e.to, &apply(rel.as_ref(), &q)), dr);
                let before = scaled(form(t, tr, e.from, &q), -ds);
                let what = format!("(G3) at node {}, step {}, vertex {i}", e.from, e.step);
                rows.push([after, before].concat(), 0.0, what);
            }
        }
    }
}

/// The row summed per representative and scaled to largest entry 1 (`None` if it is zero).
fn normalised(row: &Row, reps: usize) -> Option<(Vec<[f64; 3]>, f64)> {
    let mut dense = vec![[0.0; 3]; reps];
    for (k, c) in row {
        for i in 0..3 {
            dense[*k][i] += c[i];
        }
    }
    let big = dense.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    (big > ZERO_ROW).then_some((dense, big))
}

/// The least B in `f64` and the representatives' numerators, or why none was found.
fn solve(
    rows: &Rows,
    g5: &[(Vec<Row>, Vec<f64>)],
    reps: usize,
    margin: f64,
) -> Result<Vec<[f64; 3]>, String> {
    let mut lp = Problem::new(OptimizationDirection::Minimize);
    let vars: Vec<[Variable; 3]> = (0..reps)
        .map(|_| std::array::from_fn(|_| lp.add_var(0.0, (f64::NEG_INFINITY, f64::INFINITY))))
        .collect();
    let bound = lp.add_var(1.0, (0.0, f64::INFINITY));
    let expr = |dense: &[[f64; 3]], f: f64| -> Vec<(Variable, f64)> {
        let mut out = Vec::new();
        for (k, c) in dense.iter().enumerate() {
            for i in 0..3 {
                if c[i] != 0.0 {
                    out.push((vars[k][i], c[i] * f));
                }
            }
        }
        out
    };
    for (row, rhs, _) in &rows.rows {
        if let Some((dense, big)) = normalised(row, reps) {
            lp.add_constraint(expr(&dense, 1.0 / big), ComparisonOp::Le, rhs / big - margin);
        }
    }
    // (G5): a_e·m ≤ B (−b_e·I_i(−m_{k,k+1})) at every entry e (of contact i), both m, every k.
    for (heights, depth) in g5 {
        for dense in heights.iter().filter_map(|h| normalised(h, reps)).map(|(d, _)| d) {
            for d in depth {
                let mut e = expr(&dense, 1.0);
                e.push((bound, -d));
                lp.add_constraint(e, ComparisonOp::Le, 0.0);
            }
        }
    }
    let outcome = std::panic::catch_unwind(|| lp.solve())
        .map_err(|_| "the linear program's solver panicked".to_string())?
        .map_err(|e| format!("the linear program has no solution ({e:?})"))?;
    let SolveOutcome::Solution(sol) = outcome else {
        return Err("the linear program was interrupted".into());
    };
    Ok(vars.iter().map(|v| v.map(|x| sol.var_value(x))).collect())
}

/// The numerators and B, checked exactly ((F), (G2), (G3), (G5)) at every body (the corners of a
/// box: (G3) and (G5) are affine in γ and, times 1 + κ, in κ); `Err` names what failed.
pub fn numerators<B: Frames>(
    bodies: &[B],
    nodes: &[Node<B::E>],
    edges: &[Edge<B::E>],
    t: &Ties,
) -> Result<Numerators<B::E>, String> {
    let body = &bodies[0];
    let tr = transports(body, t)?;
    let mut rows = Rows { rows: Vec::new() };
    node_rows(body, nodes, t, &tr, &mut rows);
    for b in bodies {
        edge_rows(b, nodes, edges, t, &tr, &mut rows);
    }
    let g5: Vec<(Vec<Row>, Vec<f64>)> = (body.entries().into_iter().enumerate())
        .map(|(e, i)| {
            let heights = body.heights(i).iter().map(|m| form(t, &tr, e, m)).collect();
            let depth = (bodies.iter())
                .flat_map(|b| {
                    let map = b.impact(i);
                    b.all_down()
                        .iter()
                        .map(|g| -dot(&nodes[e].weight, &mat_vec(&map, g)).f64())
                        .collect::<Vec<_>>()
                })
                .collect();
            (heights, depth)
        })
        .collect();
    let mut why = Vec::new();
    for margin in MARGINS {
        match solve(&rows, &g5, t.rep.len(), margin).and_then(|sol| exact(bodies, nodes, edges, t, &sol)) {
            Ok(x) => return Ok(x),
            Err(e) => why.push(format!("margin {margin:e}: {e}")),
        }
    }
    Err(why.join(", "))
}

/// The rounded numerators transported exactly, every condition checked exactly, B computed.
fn exact<B: Frames>(
    bodies: &[B],
    nodes: &[Node<B::E>],
    edges: &[Edge<B::E>],
    t: &Ties,
    sol: &[[f64; 3]],
) -> Result<Numerators<B::E>, String> {
    let round = |x: f64| Q::from_f64_exact(x).map(|q| q.ceil_dyadic(BITS)).ok_or("a numerator is not finite");
    let mut a = Vec::with_capacity(nodes.len());
    for r in 0..nodes.len() {
        let k = t.rep[r];
        let ak: Vec3<Q> = [round(sol[k][0])?, round(sol[k][1])?, round(sol[k][2])?];
        a.push(tie::transported(&bodies[0], &t.path[r], ak.map(|x| B::E::from_q(&x)))?);
    }
    let mut most = Q::int(0);
    for body in bodies {
        check(body, nodes, edges, &a)?;
        most = most.max(super::bound::bound(body, nodes, &a, BITS)?);
    }
    Ok(Numerators { a, bound: most })
}

/// (F), (G2) and (G3) exactly.
fn check<B: Frames>(
    body: &B,
    nodes: &[Node<B::E>],
    edges: &[Edge<B::E>],
    a: &[Vec3<B::E>],
) -> Result<(), String> {
    for (r, node) in nodes.iter().enumerate() {
        if let Some(i) = node.cone.vertices.iter().position(|g| dot(&a[r], g) > dot(&node.weight, g)) {
            return Err(format!("(F) fails exactly at node {r}, generator {i}"));
        }
        if body.heights(node.label).iter().any(|m| dot(&a[r], m).is_negative()) {
            return Err(format!("(G2) fails exactly at node {r}"));
        }
    }
    for e in edges {
        let (rel, step) = (body.relabel(e.step), body.step(e.step));
        for (i, p) in e.piece.iter().enumerate().filter(|(_, p)| !is_zero(p)) {
            let dr = dot(&nodes[e.from].weight, &neg(p));
            let ds = dot(&nodes[e.to].weight, &neg(&mat_vec(&step, p)));
            for q in body.landing(e.step) {
                let l = dot(&a[e.to], &apply(rel.as_ref(), &q)).times(&dr);
                let rr = dot(&a[e.from], &q).times(&ds);
                if l > rr {
                    return Err(format!(
                        "(G3) fails exactly at node {}, step {}, vertex {i} (by {:.3e})",
                        e.from,
                        e.step,
                        l.minus(&rr).f64()
                    ));
                }
            }
        }
    }
    Ok(())
}
