//! The producer of refutations (untrusted; the kernel checks them: `chatter_kernel::refute`):
//! the paper's cone iteration run exactly, recording how every velocity was derived.
//!
//! Any convex cone K containing the seeds with S_j(K ∩ C_j) ⊆ K contains every point derived
//! here, so a derived velocity with v >= 0 refutes the claim. The iteration keeps only an inner
//! approximation of the growing cone (a subset is always allowed): vertices whose numbers grow
//! long are replaced by nearby short points inside the current polygon, each derived as a
//! non-negative combination of three vertices, and the polygon is kept to a bounded number of
//! vertices by dropping the least useful ones. The derivation is pruned to the points the last
//! one depends on.

use crate::exact::{Field, Int, Q, QExt};
use crate::finder::{FinderConfig, Search, Seed, find_cone};
use crate::model::FloatBody;
use chatter_kernel::certificate::{Body, Claim, Coordinates};
use chatter_kernel::geometry::hull;
use chatter_kernel::model::linalg::{Vec3, dot, mat_vec};
use chatter_kernel::model::{Rod, Shape};
use chatter_kernel::refute::{FORMAT, Refutation, Step, VERSION};
use std::collections::BTreeSet;

/// Budgets of the refutation search.
#[derive(Clone, Copy, Debug)]
pub struct RefuteConfig {
    /// Iterations of the cone iteration.
    pub max_iterations: usize,
    /// Vertices kept in the inner polygon.
    pub max_vertices: usize,
    /// Points longer than this many bits (numerator or denominator of a projected coordinate)
    /// are replaced by short ones.
    pub max_bits: u64,
}

impl Default for RefuteConfig {
    fn default() -> Self {
        RefuteConfig { max_iterations: 4000, max_vertices: 48, max_bits: 96 }
    }
}

/// Why no refutation was produced.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum NoRefutation {
    /// The body is invalid.
    Body(String),
    /// The iteration stopped growing: an effectively invariant cone exists (up to the inner
    /// approximation).
    Converged { iterations: usize },
    /// The budget ran out.
    Budget { iterations: usize },
    /// The float finder converged to a cone: a certificate is likely (`chatter certify`).
    FloatCone,
}

impl std::fmt::Display for NoRefutation {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            NoRefutation::Body(s) => write!(f, "invalid body: {s}"),
            NoRefutation::Converged { iterations } => write!(
                f,
                "the exact cone iteration stopped growing after {iterations} iterations: an effectively invariant cone contains the seeds, so the claim cannot be refuted"
            ),
            NoRefutation::Budget { iterations } => {
                write!(f, "no velocity with v >= 0 derived within {iterations} iterations")
            }
            NoRefutation::FloatCone => write!(
                f,
                "the float cone finder converged to an effectively invariant cone containing the seeds (try `chatter certify`)"
            ),
        }
    }
}

/// A derivation under construction: the steps and the exact points they give.
struct Derivation {
    steps: Vec<Step>,
    points: Vec<Vec<Q>>,
    deps: Vec<Vec<usize>>,
}

impl Derivation {
    fn push(&mut self, step: Step, point: Vec<Q>, deps: Vec<usize>) -> usize {
        self.steps.push(step);
        self.points.push(point);
        self.deps.push(deps);
        self.points.len() - 1
    }

    fn combination(&mut self, terms: &[(usize, Q)]) -> usize {
        let d = self.points[terms[0].0].len();
        let mut p = vec![Q::int(0); d];
        for (i, c) in terms {
            for (x, y) in p.iter_mut().zip(&self.points[*i]) {
                *x = &*x + &(c * y);
            }
        }
        let step = Step::Combination { terms: terms.iter().map(|(i, c)| (*i, c.to_string())).collect() };
        self.push(step, p, terms.iter().map(|t| t.0).collect())
    }

    /// The derivation of `last` alone: its ancestors, renumbered in order.
    fn pruned(&self, last: usize) -> Vec<Step> {
        let mut need = BTreeSet::from([last]);
        for i in (0..=last).rev() {
            if need.contains(&i) {
                need.extend(self.deps[i].iter().copied());
            }
        }
        let new: std::collections::BTreeMap<usize, usize> =
            need.iter().enumerate().map(|(k, &i)| (i, k)).collect();
        need.iter()
            .map(|&i| match &self.steps[i] {
                Step::Seed { index } => Step::Seed { index: *index },
                Step::Combination { terms } => {
                    Step::Combination { terms: terms.iter().map(|(j, c)| (new[j], c.clone())).collect() }
                }
                Step::Image { step, of } => Step::Image { step: *step, of: new[of] },
            })
            .collect()
    }
}

/// Refutes `claim` for the body (n, kappa, gamma) at a point, or says why not.
pub fn refute(
    n: u64,
    kappa: &Q,
    gamma: &Q,
    claim: Claim,
    cfg: &RefuteConfig,
) -> Result<Refutation, NoRefutation> {
    let shape = Shape::new(n, kappa.clone(), gamma.clone()).map_err(|e| NoRefutation::Body(e.to_string()))?;
    let mut cfg = *cfg;
    if let Shape::Polygon(b) = &shape {
        // The float iteration first: where it converges a certificate is likely; where it leaves
        // v < 0 after k iterations the exact (inner) iteration needs about as many; where it is
        // inconclusive the exact one would run to its budget for nothing.
        let seed = if claim == Claim::EffectivelyInvariant { Seed::Translation } else { Seed::AllDown };
        // Past half the budget a NoCone is declined anyway, so the float search stops there.
        let budget = FinderConfig { max_iterations: cfg.max_iterations / 2 + 1, ..FinderConfig::default() };
        match find_cone(&FloatBody::new(b), seed, &budget) {
            Search::Found { .. } => return Err(NoRefutation::FloatCone),
            Search::NoCone { iteration, .. } if 2 * iteration > cfg.max_iterations => {
                return Err(NoRefutation::Budget { iterations: iteration });
            }
            Search::NoCone { iteration, .. } => {
                cfg.max_iterations = cfg.max_iterations.min(2 * iteration + 50);
            }
            Search::Inconclusive { iterations, .. } => return Err(NoRefutation::Budget { iterations }),
        }
    }
    let cfg = &cfg;
    let mut d = Derivation { steps: Vec::new(), points: Vec::new(), deps: Vec::new() };
    let last = match &shape {
        Shape::Rod(r) => rod(r, claim, cfg, &mut d)?,
        Shape::Polygon(_) => polygon(&shape, claim, cfg, &mut d)?,
    };
    Ok(Refutation {
        format: FORMAT.into(),
        version: VERSION,
        body: Body::RegularPolygon { n, kappa: kappa.to_string().into(), gamma: gamma.to_string().into() },
        coordinates: Coordinates::ContactVelocities,
        refutes: claim,
        points: d.pruned(last),
        producer: format!("chatter {} refute (exact cone iteration)", env!("CARGO_PKG_VERSION")),
    })
}

/// v of a velocity: its third coordinate, or (u0 + u1)/2 for the rod.
fn v_of(p: &[Q]) -> Q {
    if p.len() == 2 { (&p[0] + &p[1]) / Q::int(2) } else { p[2].clone() }
}

/// A derived velocity with v >= 0 that is not zero ends the derivation.
fn refutes(p: &[Q]) -> bool {
    v_of(p) >= Q::int(0) && p.iter().any(|x| *x != Q::int(0))
}

/// The seeds of the claim: I_0 of the drops it covers.
fn seeds(shape: &Shape<Q>, claim: Claim) -> Vec<Vec<Q>> {
    match shape {
        Shape::Rod(r) => {
            let i0 = r.impact(0);
            let drops: Vec<[Q; 2]> = if claim == Claim::EffectivelyInvariant {
                vec![[Q::int(-1), Q::int(-1)]]
            } else {
                r.all_down_generators().to_vec()
            };
            drops.iter().map(|g| chatter_kernel::model::mat2_vec(&i0, g).to_vec()).collect()
        }
        Shape::Polygon(p) => {
            let i0 = p.impact(0);
            let drops = if claim == Claim::EffectivelyInvariant {
                vec![crate::model::translation_down()]
            } else {
                p.all_down_generators()
            };
            drops.iter().map(|g| mat_vec(&i0, g).to_vec()).collect()
        }
    }
}

fn v3(p: &[Q]) -> Vec3<Q> {
    [p[0].clone(), p[1].clone(), p[2].clone()]
}

/// The regular polygon: the exact iteration on the plane v = -1.
fn polygon(
    shape: &Shape<Q>,
    claim: Claim,
    cfg: &RefuteConfig,
    d: &mut Derivation,
) -> Result<usize, NoRefutation> {
    let Shape::Polygon(body) = shape else { unreachable!() };
    let mut cur: Vec<usize> = Vec::new();
    for (i, s) in seeds(shape, claim).into_iter().enumerate() {
        let at_rest = s.iter().all(|x| *x == Q::int(0));
        let k = d.push(Step::Seed { index: i }, s.clone(), vec![]);
        if refutes(&s) {
            return Ok(k);
        }
        if !at_rest {
            cur.push(k);
        }
    }
    for it in 0..cfg.max_iterations {
        let mut images = Vec::new();
        for j in 1..body.n() {
            for p in piece(d, &cur, &body.next_contact_cone(j as i64)) {
                let img = mat_vec(&body.step(j as i64), &v3(&d.points[p])).to_vec();
                let k = d.push(Step::Image { step: j, of: p }, img.clone(), vec![p]);
                if refutes(&img) {
                    return Ok(k);
                }
                if img.iter().any(|x| *x != Q::int(0)) {
                    images.push(k);
                }
            }
        }
        let all: Vec<usize> = cur.iter().chain(&images).copied().collect();
        // The hull on integer multiples of the points: the same rays, no gcd in every comparison.
        let proj: Vec<Vec3<malachite::Integer>> = all
            .iter()
            .map(|&i| {
                let z = crate::exact::scale_to_ints(&d.points[i]);
                [z[0].clone(), z[1].clone(), z[2].clone()]
            })
            .collect();
        let next: Vec<usize> = hull(&proj).into_iter().map(|h| all[h]).collect();
        if next.iter().all(|i| cur.contains(i)) && next.len() == cur.len() && it > 0 {
            return Err(NoRefutation::Converged { iterations: it });
        }
        cur = shorten(d, thin(d, next, cfg.max_vertices), cfg.max_bits);
    }
    Err(NoRefutation::Budget { iterations: cfg.max_iterations })
}

/// The vertices of the polygon `poly` (point indices, counter-clockwise) clipped by l . p >= 0
/// for each covector, crossings derived as positive combinations of the edge's ends.
fn piece(d: &mut Derivation, poly: &[usize], covectors: &[Vec3<Q>]) -> Vec<usize> {
    let mut cur = poly.to_vec();
    for l in covectors {
        let vals: Vec<Q> = cur.iter().map(|&i| dot(l, &v3(&d.points[i]))).collect();
        if vals.iter().all(|v| *v >= Q::int(0)) {
            continue;
        }
        let m = cur.len();
        let mut out = Vec::new();
        for i in 0..m {
            let (a, b) = (&vals[i], &vals[(i + 1) % m]);
            if *a >= Q::int(0) {
                out.push(cur[i]);
            }
            let crosses = (*a > Q::int(0) && *b < Q::int(0)) || (*a < Q::int(0) && *b > Q::int(0));
            if crosses && m > 1 {
                // (l.P) N - (l.N) P with P on the positive side: a positive combination on l = 0.
                let (p, n, lp, ln) = if *a > Q::int(0) {
                    (cur[i], cur[(i + 1) % m], a.clone(), b.clone())
                } else {
                    (cur[(i + 1) % m], cur[i], b.clone(), a.clone())
                };
                out.push(d.combination(&[(n, lp), (p, -ln)]));
            }
        }
        cur = out;
        if cur.is_empty() {
            break;
        }
    }
    let mut seen = BTreeSet::new();
    cur.retain(|i| seen.insert(*i));
    cur
}

/// The projection (x, y) of a polygon point (v < 0).
fn proj(p: &[Q]) -> (Q, Q) {
    let w = -&p[2];
    (&p[0] / &w, &p[1] / &w)
}

fn area2(a: &(Q, Q), b: &(Q, Q), c: &(Q, Q)) -> Q {
    &(&(&b.0 - &a.0) * &(&c.1 - &a.1)) - &(&(&b.1 - &a.1) * &(&c.0 - &a.0))
}

/// Keeps at most `max` vertices, dropping each time the vertex whose removal loses the least
/// area (an inner approximation).
fn thin(d: &Derivation, mut poly: Vec<usize>, max: usize) -> Vec<usize> {
    while poly.len() > max.max(3) {
        let m = poly.len();
        let pts: Vec<(Q, Q)> = poly.iter().map(|&i| proj(&d.points[i])).collect();
        let loss = |i: usize| area2(&pts[(i + m - 1) % m], &pts[i], &pts[(i + 1) % m]);
        let worst = (0..m).min_by(|&a, &b| loss(a).cmp(&loss(b))).expect("non-empty");
        poly.remove(worst);
    }
    poly
}

/// Replaces vertices with long numbers by short points slightly inside the polygon, each a
/// non-negative combination of three vertices (a triangle of the fan from a short vertex).
fn shorten(d: &mut Derivation, poly: Vec<usize>, max_bits: u64) -> Vec<usize> {
    let long = |p: &[Q]| {
        let (x, y) = proj(p);
        [x, y].iter().any(|c| Int::bit_length(&c.numer()).max(c.denominator_bits()) > max_bits)
    };
    if poly.len() < 3 || !poly.iter().any(|&i| long(&d.points[i])) {
        return poly;
    }
    let pts: Vec<(Q, Q)> = poly.iter().map(|&i| proj(&d.points[i])).collect();
    let m = pts.len() as i64;
    let c = (
        pts.iter().map(|p| p.0.clone()).fold(Q::int(0), |a, b| a + b) / Q::int(m),
        pts.iter().map(|p| p.1.clone()).fold(Q::int(0), |a, b| a + b) / Q::int(m),
    );
    let size = pts.iter().map(|p| p.0.abs().max(p.1.abs())).max().expect("points").to_f64().max(1e-300);
    let grid = (48.0 - size.log2().ceil()).max(0.0) as u64;
    let mut out = Vec::with_capacity(poly.len());
    for (k, &i) in poly.iter().enumerate() {
        if !long(&d.points[i]) {
            out.push(i);
            continue;
        }
        match inner_point(&pts, k, &c, grid).and_then(|q| triangle_of(d, &poly, &q)) {
            Some(terms) => out.push(d.combination(&terms)),
            None => out.push(i),
        }
    }
    out
}

/// A short point near vertex k, pulled towards the centre c by 2^-30 and rounded to 2^-grid,
/// strictly inside the polygon; `None` if rounding leaves it outside.
fn inner_point(pts: &[(Q, Q)], k: usize, c: &(Q, Q), grid: u64) -> Option<(Q, Q)> {
    let eps = Q::new(1, 1 << 30);
    let pull = |a: &Q, b: &Q| (a + &(&eps * &(b - a))).floor_dyadic(grid);
    let q = (pull(&pts[k].0, &c.0), pull(&pts[k].1, &c.1));
    let m = pts.len();
    let inside = (0..m).all(|i| area2(&pts[i], &pts[(i + 1) % m], &q) > Q::int(0));
    inside.then_some(q)
}

/// `q` (on v = -1) as a non-negative combination of vertex 0 and two consecutive vertices.
fn triangle_of(d: &Derivation, poly: &[usize], q: &(Q, Q)) -> Option<Vec<(usize, Q)>> {
    let m = poly.len();
    let p = |i: usize| v3(&d.points[poly[i]]);
    let target = [q.0.clone(), q.1.clone(), Q::int(-1)];
    for i in 1..m - 1 {
        let (a, b, c) = (p(0), p(i), p(i + 1));
        let det = chatter_kernel::model::linalg::det3(&a, &b, &c);
        if det == Q::int(0) {
            continue;
        }
        // Cramer: target = x a + y b + z c.
        let x = chatter_kernel::model::linalg::det3(&target, &b, &c) / &det;
        let y = chatter_kernel::model::linalg::det3(&a, &target, &c) / &det;
        let z = chatter_kernel::model::linalg::det3(&a, &b, &target) / &det;
        if x >= Q::int(0) && y >= Q::int(0) && z >= Q::int(0) {
            return Some(vec![(poly[0], x), (poly[i], y), (poly[i + 1], z)]);
        }
    }
    None
}

/// The rod: the interval iteration, exactly (velocities (u0, u1), s = u0 / -(u0 + u1)).
fn rod(r: &Rod<Q>, claim: Claim, cfg: &RefuteConfig, d: &mut Derivation) -> Result<usize, NoRefutation> {
    let shape = Shape::Rod(r.clone());
    let s_of = |p: &[Q]| &p[0] / &(-(&p[0] + &p[1]));
    let mut ends: Vec<usize> = Vec::new();
    for (i, s) in seeds(&shape, claim).into_iter().enumerate() {
        let at_rest = s.iter().all(|x| *x == Q::int(0));
        let k = d.push(Step::Seed { index: i }, s.clone(), vec![]);
        if refutes(&s) {
            return Ok(k);
        }
        if !at_rest {
            ends.push(k);
        }
    }
    let (cone, step) = (r.next_contact_cone(), r.step());
    for it in 0..cfg.max_iterations {
        let by_s = |a: &&usize, b: &&usize| s_of(&d.points[**a]).cmp(&s_of(&d.points[**b]));
        let (lo, hi) =
            (*ends.iter().min_by(by_s).expect("a seed"), *ends.iter().max_by(by_s).expect("a seed"));
        let (s_lo, s_hi) = (s_of(&d.points[lo]), s_of(&d.points[hi]));
        let seg = if lo == hi { vec![lo] } else { vec![lo, hi] };
        let mut grew = false;
        for p in clip_segment(d, &seg, &cone) {
            let x = &d.points[p];
            let img = chatter_kernel::model::mat2_vec(&step, &[x[0].clone(), x[1].clone()]).to_vec();
            let k = d.push(Step::Image { step: 1, of: p }, img.clone(), vec![p]);
            if refutes(&img) {
                return Ok(k);
            }
            if img.iter().any(|x| *x != Q::int(0)) {
                grew |= s_of(&img) < s_lo || s_of(&img) > s_hi;
                ends.push(k);
            }
        }
        if !grew && it > 0 {
            return Err(NoRefutation::Converged { iterations: it });
        }
        let by_s = |a: &&usize, b: &&usize| s_of(&d.points[**a]).cmp(&s_of(&d.points[**b]));
        let (lo, hi) = (*ends.iter().min_by(by_s).expect("ends"), *ends.iter().max_by(by_s).expect("ends"));
        ends = if lo == hi { vec![lo] } else { vec![lo, hi] };
    }
    Err(NoRefutation::Budget { iterations: cfg.max_iterations })
}

/// A segment of the rod's line (one or two velocities) clipped by l . p >= 0 for each covector,
/// crossings derived as positive combinations of the ends.
fn clip_segment(d: &mut Derivation, seg: &[usize], covectors: &[[Q; 2]]) -> Vec<usize> {
    let dot2 = |l: &[Q; 2], p: &[Q]| &(&l[0] * &p[0]) + &(&l[1] * &p[1]);
    let mut cur = seg.to_vec();
    for l in covectors {
        let vals: Vec<Q> = cur.iter().map(|&i| dot2(l, &d.points[i])).collect();
        let mut out: Vec<usize> =
            cur.iter().zip(&vals).filter(|(_, v)| **v >= Q::int(0)).map(|(i, _)| *i).collect();
        let zero = Q::int(0);
        if cur.len() == 2 && ((vals[0] > zero && vals[1] < zero) || (vals[0] < zero && vals[1] > zero)) {
            let (p, n, lp, ln) = if vals[0] > zero {
                (cur[0], cur[1], vals[0].clone(), vals[1].clone())
            } else {
                (cur[1], cur[0], vals[1].clone(), vals[0].clone())
            };
            out.push(d.combination(&[(n, lp), (p, -ln)]));
        }
        cur = out;
    }
    cur
}
