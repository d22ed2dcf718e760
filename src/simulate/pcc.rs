//! Two tests of partial complete chatter (PCC): two adjacent contacts chatter to rest while the
//! body keeps moving.
//!
//! 1. The paper's criterion (section "Comparison with direct simulation"): PCC ends in a state
//!    q = c·m_{i,i+1} (c > 0), p = c'·m_{i,i+1} (c' < 0), so the simulation declares PCC when
//!    |1 - cos∠(q, m)| < ε and |1 + cos∠(p, m)| < ε, the angles measured in the paper's
//!    coordinates (φx, φy, h) and (ωx, ωy, v) (docs/model.md §2 gives the change of coordinates).
//!
//! 2. An exact variant, [`prove_pair_chatter`]. While only contacts i and j hit, their heights
//!    and normal velocities form a closed two-contact system, a rod whose coupling is
//!    E = f_j·kick_i = (1+γ)(κ + cos 2π/n)/(1+κ) (docs/model.md §3). Right after an impact at i, with
//!    a = u_i ≥ 0 and b = u_j < 0, the ratio s = a/(-b) evolves by g(s) = γ/(|E| - s) and the
//!    pair keeps alternating iff every iterate stays below |E| — by the rod theorem of the paper
//!    (after Goyal et al.), iff E < 0, D = E² - 4γ > 0 and s < s₊ = (|E| + √D)/2, a rational
//!    test: 2s - |E| < 0 or (2s - |E|)² < D. The intervals then shrink by s_m/(|E| - s_m), so a
//!    rational bound T on the time left follows from a few exact steps and a geometric tail.
//!    The final velocity p* is fixed by momentum alone: p* = p - x·kick_i - y·kick_j with
//!    u_i(p*) = u_j(p*) = 0 (two linear equations, x, y ≤ 0 the accumulated pre-impact
//!    velocities). Until then every other contact k has u_k(t) ≥ U_k, the sum of u_k(p),
//!    min(0, -x f_k·kick_i) and min(0, -y f_k·kick_j), so h_k(q) + T·min(U_k, 0) > 0 proves that no other
//!    contact lands before the pair comes to rest. With v* < 0 (p* = v*·m_{i,j}) this is PCC,
//!    followed by all contacts landing at once (undecidable in this model); p* = 0 is complete
//!    chatter; v* > 0 means ICC and is not reported here.

use super::scalar::SimField;
use super::snapshot::{Scaled, Snapshot};
use super::system::{FloatSystem, System};
use crate::exact::{Q, QExt, Ring};
use chatter_kernel::model::linalg::{Vec3, dot};

/// The paper's criterion evaluated on a state, for the pair {i, i+1}.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PaperPcc {
    /// The pair (i, i+1 mod n).
    pub pair: (usize, usize),
    /// |1 - cos∠(q, m_{i,i+1})|.
    pub q_defect: f64,
    /// |1 + cos∠(p, m_{i,i+1})|.
    pub p_defect: f64,
}

impl PaperPcc {
    /// Whether both defects are below `eps`.
    pub fn holds(&self, eps: f64) -> bool {
        self.q_defect < eps && self.p_defect < eps
    }
}

fn unit(x: [f64; 3]) -> [f64; 3] {
    let l = (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]).sqrt();
    x.map(|c| c / l)
}

/// The paper's PCC criterion for the adjacent pair {a, b} on a (normalised) state.
pub fn paper_criterion(fs: &FloatSystem, s: &Snapshot, a: usize, b: usize) -> PaperPcc {
    let n = fs.n;
    let i = if (a + 1) % n == b { a } else { b };
    let m = &fs.rest_paper[i];
    let cq = unit(fs.to_paper(&s.q));
    let cp = unit(fs.to_paper(&s.p));
    let c = |x: &[f64; 3]| x[0] * m[0] + x[1] * m[1] + x[2] * m[2];
    PaperPcc { pair: (i, (i + 1) % n), q_defect: (1.0 - c(&cq)).abs(), p_defect: (1.0 + c(&cp)).abs() }
}

/// What the exact pair-chatter test established, in the body's field.
#[derive(Clone, Debug, PartialEq)]
pub struct PairProof<F = Q> {
    /// The chattering pair (the contact just hit, the other).
    pub pair: (usize, usize),
    /// An upper bound on the time until the pair's impacts accumulate.
    pub time_bound: F,
    /// The velocity at the accumulation point, p* = v*·m_{i,j}.
    pub limit_velocity: Vec3<F>,
    /// v* (< 0: PCC then a simultaneous landing; 0: the body comes to rest, CC).
    pub v_limit: F,
}

/// A [`PairProof`] as the classification reads it, in any field.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PairSummary {
    /// The chattering pair (the contact just hit, the other).
    pub pair: (usize, usize),
    /// The time bound, to `f64` precision.
    pub time_bound: Scaled,
    /// v*, to `f64` precision.
    pub v_limit: f64,
    /// Whether v* = 0 exactly (the body comes to rest: CC).
    pub at_rest: bool,
}

impl<F: SimField> PairProof<F> {
    /// The read-out for the classification.
    pub fn summary(&self) -> PairSummary {
        PairSummary {
            pair: self.pair,
            time_bound: self.time_bound.magnitude(),
            v_limit: self.v_limit.approx(),
            at_rest: self.v_limit.is_zero(),
        }
    }
}

fn min0<F: SimField>(x: F) -> F {
    if x.is_negative() { x } else { F::zero() }
}

fn half<F: SimField>() -> F {
    F::from_ratio(1, 2)
}

/// A rational d with 0 < d ≤ √x (x > 0), from the `f64` square root, checked exactly.
fn sqrt_lower(x: &Q) -> Option<Q> {
    let f = x.to_f64().sqrt() * (1.0 - 1e-9);
    let mut d = Q::from_f64_exact(f).filter(|d| d.is_positive())?;
    for _ in 0..64 {
        if &d * &d <= *x {
            return Some(d);
        }
        d = d * Q::new(1, 2);
    }
    None
}

/// The exact PCC test, right after an impact at `hit` with `other` its neighbour (module doc).
pub fn prove_pair_chatter<F: SimField>(
    sys: &System<F>,
    q: &Vec3<F>,
    p: &Vec3<F>,
    hit: usize,
    other: usize,
) -> Result<PairProof<F>, String> {
    let pair = Pair::after_impact(sys, q, p, hit, other)?;
    let disc = pair.basin(&sys.gamma)?;
    let time_bound = pair.time_bound(&sys.gamma, &disc)?;
    let (x, y, limit_velocity) = pair.limit(sys, p)?;
    let v_limit = dot(&sys.centre, &limit_velocity);
    if v_limit.is_positive() {
        return Err("the limit velocity has v > 0: the chatter of the pair ends in ICC".into());
    }
    pair.others_stay_up(sys, (q, p), (&x, &y), &time_bound)?;
    Ok(PairProof { pair: (hit, other), time_bound, limit_velocity, v_limit })
}

/// The closed two-contact system right after an impact at `hit`: a = u_hit ≥ 0, b = u_other < 0,
/// h = h_other ≥ 0, and the coupling E = f_other·kick_hit = f_hit·kick_other < 0.
struct Pair<'a, F> {
    hit: usize,
    other: usize,
    kicks: (&'a Vec3<F>, &'a Vec3<F>),
    a: F,
    b: F,
    h: F,
    e: F,
}

impl<'a, F: SimField> Pair<'a, F> {
    /// The pair if its preconditions hold: neighbours, `hit` on the floor, `other` approaching,
    /// a symmetric and negative coupling.
    fn after_impact(
        sys: &'a System<F>,
        q: &Vec3<F>,
        p: &Vec3<F>,
        hit: usize,
        other: usize,
    ) -> Result<Pair<'a, F>, String> {
        if !sys.adjacent(hit, other) {
            return Err(format!("contacts {hit} and {other} are not neighbours"));
        }
        let (fh, fo) = (&sys.contacts[hit], &sys.contacts[other]);
        let (kh, ko) = (&sys.kicks[hit], &sys.kicks[other]);
        if !dot(fh, q).is_zero() {
            return Err(format!("contact {hit} is not on the floor"));
        }
        let (a, b, h) = (dot(fh, p), dot(fo, p), dot(fo, q));
        if a.is_negative() || !b.is_negative() || h.is_negative() {
            return Err(format!("contact {other} does not approach after the impact at {hit}"));
        }
        let e = dot(fo, kh);
        if e != dot(fh, ko) {
            return Err("asymmetric pair coupling (model error)".into());
        }
        if !e.is_negative() {
            return Err(format!("coupling {e} >= 0: an impact at one contact of the pair lifts the other"));
        }
        Ok(Pair { hit, other, kicks: (kh, ko), a, b, h, e })
    }

    /// The rod theorem's basin: D = E² - 4γ > 0 and s = a/(-b) < s₊ (2s - |E| < 0 or
    /// (2s - |E|)² < D); returns D.
    fn basin(&self, gamma: &F) -> Result<F, String> {
        let disc = self.e.times(&self.e).minus(&F::from_i64(4).times(gamma));
        if !disc.is_positive() {
            return Err(format!("E^2 - 4 gamma = {disc} <= 0: the pair's step map has no real eigenvalues"));
        }
        let s = self.a.over(&self.b.negated()).expect("b < 0");
        let w = F::from_i64(2).times(&s).plus(&self.e);
        if !(w.is_negative() || w.times(&w) < disc) {
            return Err(format!("velocity ratio {} is outside the pair's basin s < s+", s.approx()));
        }
        Ok(disc)
    }

    /// An upper bound on the time until the pair's impacts accumulate: exact steps until
    /// s_m < |E|/2, then a geometric tail with ratio s_m/(|E| - s_m) (s_m at least r ≥ s₋, with
    /// r from a rational d ≤ √D).
    fn time_bound(&self, gamma: &F, disc: &F) -> Result<F, String> {
        let e_abs = self.e.negated();
        let half_e = e_abs.times(&half());
        let d = sqrt_lower(&disc.rational_below()).ok_or("no rational lower bound of sqrt(D) found")?;
        let r = e_abs.minus(&F::from_q(&d)).times(&half()); // >= s-, < |E|/2
        let (mut am, mut bm, mut hm) = (self.a.clone(), self.b.clone(), self.h.clone());
        let mut t_sum = F::zero();
        for _ in 0..64 {
            let bm_abs = bm.negated();
            let sm = am.over(&bm_abs).expect("b_m < 0");
            let tau = hm.over(&bm_abs).expect("b_m < 0");
            if sm < half_e {
                let sigma = if sm > r { sm } else { r.clone() };
                let rho = sigma.over(&e_abs.minus(&sigma)).expect("sigma < |E|/2");
                return Ok(t_sum.plus(&tau.over(&F::one().minus(&rho)).expect("rho < 1")));
            }
            t_sum = t_sum.plus(&tau);
            let next_b = am.minus(&bm_abs.times(&e_abs));
            hm = am.times(&tau);
            am = gamma.times(&bm_abs);
            bm = next_b;
            if !bm.is_negative() {
                return Err("the pair stops alternating (model error)".into());
            }
        }
        Err("velocity ratio converges too slowly to bound the remaining time".into())
    }

    /// The limit velocity from momentum, p* = p - x·kick_i - y·kick_j with u_i(p*) = u_j(p*) = 0:
    /// [[A, E], [E, A]] (x, y) = (a, b), A = f_i·kick_i = 1 + γ; returns (x, y, p*).
    fn limit(&self, sys: &System<F>, p: &Vec3<F>) -> Result<(F, F, Vec3<F>), String> {
        let (fh, fo) = (&sys.contacts[self.hit], &sys.contacts[self.other]);
        let (kh, ko) = self.kicks;
        let (a, b, e) = (&self.a, &self.b, &self.e);
        let big_a = dot(fh, kh);
        let det = big_a.times(&big_a).minus(&e.times(e));
        let x = a.times(&big_a).minus(&e.times(b)).over(&det).ok_or("singular pair (model error)")?;
        let y = big_a.times(b).minus(&e.times(a)).over(&det).ok_or("singular pair (model error)")?;
        if x.is_positive() || y.is_positive() {
            return Err("impulses of the wrong sign (model error)".into());
        }
        let limit_velocity: Vec3<F> =
            std::array::from_fn(|i| p[i].minus(&x.times(&kh[i])).minus(&y.times(&ko[i])));
        if !dot(fh, &limit_velocity).is_zero() || !dot(fo, &limit_velocity).is_zero() {
            return Err("limit velocity does not rest the pair (model error)".into());
        }
        Ok((x, y, limit_velocity))
    }

    /// Every other contact k stays up until the time bound T: h_k(q) + T·min(U_k, 0) > 0 with
    /// U_k = u_k(p) + min(0, -x f_k·kick_i) + min(0, -y f_k·kick_j).
    fn others_stay_up(
        &self,
        sys: &System<F>,
        (q, p): (&Vec3<F>, &Vec3<F>),
        (x, y): (&F, &F),
        time_bound: &F,
    ) -> Result<(), String> {
        let (kh, ko) = self.kicks;
        for k in (0..sys.n()).filter(|&k| k != self.hit && k != self.other) {
            let fk = &sys.contacts[k];
            let pushes = min0(x.times(&dot(fk, kh)).negated()).plus(&min0(y.times(&dot(fk, ko)).negated()));
            let lower_u = dot(fk, p).plus(&pushes);
            let lowest_h = dot(fk, q).plus(&time_bound.times(&min0(lower_u)));
            if !lowest_h.is_positive() {
                return Err(format!("contact {k} may land before the pair comes to rest"));
            }
        }
        Ok(())
    }
}
