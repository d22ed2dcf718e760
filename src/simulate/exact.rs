//! The exact engine: states and impact times in the body's field (every impact time is
//! h_k / (-u_k) with h_k, u_k in Q, or in Q(cos 2π/n) for the other n-gons, issue 10 §1), so
//! ties are decided exactly and symmetric data keep their symmetry (docs/model.md §10).

use super::drop::Start;
use super::engine::{Engine, Step};
use super::pcc::{PairSummary, prove_pair_chatter};
use super::scalar::{Nf, SimField};
pub use super::snapshot::scaled; // formerly defined here
use super::snapshot::{Scaled, Snapshot};
use super::system::System;
use crate::exact::{Q, QExt};
use chatter_kernel::model::linalg::Vec3;

/// An exact vector as (v_m, e) with v = v_m · 2^e and the largest |component| of v_m in [1, 2).
pub fn normalised<F: SimField>(v: &Vec3<F>) -> ([f64; 3], i64) {
    let parts = v.clone().map(|x| (x.sign(), x.magnitude()));
    let Some(e) = parts.iter().filter(|(_, s)| s.m > 0.0).map(|(_, s)| s.e).max() else {
        return ([0.0; 3], 0);
    };
    let mut out = [0.0; 3];
    for (o, (sign, s)) in out.iter_mut().zip(parts) {
        let mag = Scaled { m: s.m, e: s.e - e }.to_f64();
        *o = if sign == std::cmp::Ordering::Less { -mag } else { mag };
    }
    let top = out.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    if top >= 2.0 {
        // Rounding of a mantissa just below 2 up to 2.0.
        return (out.map(|x| x / 2.0), e + 1);
    }
    (out, e)
}

/// f·x, skipping the zero and unit coefficients that dominate the covectors.
fn dot<F: SimField>(f: &Vec3<F>, x: &Vec3<F>) -> F {
    let (one, minus_one) = (F::one(), F::from_i64(-1));
    let mut acc: Option<F> = None;
    for (a, b) in f.iter().zip(x) {
        if a.is_exactly_zero() || b.is_exactly_zero() {
            continue;
        }
        let term = if *a == one {
            b.clone()
        } else if *a == minus_one {
            b.negated()
        } else {
            a.times(b)
        };
        acc = Some(match acc {
            None => term,
            Some(s) => s.plus(&term),
        });
    }
    acc.unwrap_or_else(F::zero)
}

/// The exact event-driven simulation of one drop.
#[derive(Clone, Debug)]
pub struct ExactEngine<'a, F: SimField = Q> {
    sys: &'a System<F>,
    q: Vec3<F>,
    p: Vec3<F>,
    last: Option<usize>,
    /// Time of the last impact: the sum of the exact intervals, each rounded to `f64` (an exact
    /// sum would carry the product of all denominators).
    time: f64,
    /// An upper bound of the same time: the exact intervals rounded up to dyadics k/2^TIME_BITS.
    time_above: Q,
    /// At the first impact, if every contact was moving down or at rest just before it (an
    /// all-down drop): rational upper bounds of its time and of h/|v| there.
    first_drop: Option<(Q, Q)>,
}

/// Bits of the dyadics that bound each interval from above in [`ExactEngine::time_above`]: every
/// interval adds at most 2^-200 to the bound, and the bound's digits stay bounded.
const TIME_BITS: u64 = 200;

impl<'a, F: SimField> ExactEngine<'a, F> {
    /// The engine at a start given in rationals (also for a system over Q(cos 2π/n)).
    pub fn new(sys: &'a System<F>, start: &Start<Q>) -> ExactEngine<'a, F> {
        let (q, p) = (start.q.clone().map(|x| F::from_q(&x)), start.p.clone().map(|x| F::from_q(&x)));
        ExactEngine { sys, q, p, last: None, time: 0.0, time_above: Q::int(0), first_drop: None }
    }

    /// The exact state (q, p).
    pub fn state(&self) -> (&Vec3<F>, &Vec3<F>) {
        (&self.q, &self.p)
    }

    /// (h_k, -u_k) of every approaching contact k (except the last to land): it lands after
    /// h_k / (-u_k).
    fn approaching(&self) -> impl Iterator<Item = (usize, F, F)> + '_ {
        (0..self.sys.n()).filter(|&k| Some(k) != self.last).filter_map(|k| {
            let u = dot(&self.sys.contacts[k], &self.p);
            u.below_zero().then(|| (k, dot(&self.sys.contacts[k], &self.q), u.negated()))
        })
    }

    /// The landing time of every approaching contact (except the last to land), exactly.
    pub fn candidate_times(&self) -> Vec<(usize, F)> {
        self.approaching().map(|(k, h, w)| (k, h.over(&w).expect("w > 0"))).collect()
    }

    /// The exact kinetic energy.
    pub fn energy(&self) -> F {
        self.sys.energy(&self.p)
    }

    /// The earliest approaching contacts (ties collected) with the h and -u of the first; times
    /// h/w are compared as h w' against h' w, with no division.
    fn earliest(&self) -> Option<(Vec<usize>, F, F)> {
        let mut best: Option<(Vec<usize>, F, F)> = None;
        for (k, h, w) in self.approaching() {
            match &mut best {
                Some((at, bh, bw)) => match h.times(bw).minus(&bh.times(&w)).fast_sign() {
                    std::cmp::Ordering::Greater => {}
                    std::cmp::Ordering::Equal => at.push(k),
                    std::cmp::Ordering::Less => best = Some((vec![k], h, w)),
                },
                None => best = Some((vec![k], h, w)),
            }
        }
        best
    }

    /// Before the first impact, after a flight of `t`: a rational upper bound of h/|v| if every
    /// contact moves down or rests (docs/time-to-rest.md §2: the rod theorem's drops).
    fn all_down_ratio(&self, t: &F) -> Option<Q> {
        if self.sys.contacts.iter().any(|c| dot(c, &self.p).fast_sign() == std::cmp::Ordering::Greater) {
            return None;
        }
        let v = dot(&self.sys.centre, &self.p);
        let h = dot(&self.sys.centre, &self.q).plus(&t.times(&v));
        (v.below_zero() && h.fast_sign() == std::cmp::Ordering::Greater)
            .then(|| h.over(&v.negated()).expect("v < 0").rational_above())
    }

    /// Moves for time t and applies the impact at k with pre-impact normal velocity -w.
    fn apply(&mut self, k: usize, t: &F, w: &F) {
        for ((q, p), kick) in self.q.iter_mut().zip(self.p.iter_mut()).zip(&self.sys.kicks[k]) {
            if !p.is_exactly_zero() {
                *q = q.plus(&t.times(p));
            }
            if !kick.is_exactly_zero() {
                *p = p.plus(&w.times(kick));
            }
        }
        self.last = Some(k);
    }
}

impl<F: SimField> Engine for ExactEngine<'_, F> {
    fn step(&mut self) -> Step {
        let Some((at, h, w)) = self.earliest() else { return Step::NoApproach };
        let t = h.over(&w).expect("w > 0");
        let dt = t.magnitude();
        if at.len() > 1 {
            return Step::Tie { contacts: at, dt, exact: true };
        }
        self.time += dt.to_f64();
        self.time_above = &self.time_above + &t.rational_above().ceil_dyadic(TIME_BITS);
        if self.last.is_none() {
            self.first_drop = self.all_down_ratio(&t).map(|r| (self.time_above.clone(), r));
        }
        self.apply(at[0], &t, &w);
        Step::Impact { contact: at[0], dt }
    }

    fn v_positive(&self) -> bool {
        dot(&self.sys.centre, &self.p).fast_sign() == std::cmp::Ordering::Greater
    }

    fn at_rest(&self) -> bool {
        self.p.iter().all(SimField::is_exactly_zero)
    }

    fn time(&self) -> f64 {
        self.time
    }

    fn time_above(&self) -> Option<Q> {
        Some(self.time_above.clone())
    }

    fn first_drop(&self) -> Option<(Q, Q)> {
        self.first_drop.clone()
    }

    fn centre_ratio_above(&self) -> Option<Q> {
        let (h, v) = (dot(&self.sys.centre, &self.q), dot(&self.sys.centre, &self.p));
        if !v.below_zero() || h.below_zero() {
            return None;
        }
        h.over(&v.negated()).map(|r| if r.is_exactly_zero() { Q::int(0) } else { r.rational_above() })
    }

    fn snapshot(&self) -> Snapshot {
        let (q, q_exp) = normalised(&self.q);
        let (p, p_exp) = normalised(&self.p);
        Snapshot { q, q_exp, p, p_exp, energy: self.energy().magnitude() }
    }

    /// The exact pair proof assumes a symmetric pair coupling, which general bodies
    /// (docs/model.md §11) lack: for them the paper's criterion decides (`None`).
    fn prove_pair(&self, hit: usize, other: usize) -> Option<Result<PairSummary, String>> {
        if self.sys.shape.is_convex() {
            return None;
        }
        Some(prove_pair_chatter(self.sys, &self.q, &self.p, hit, other).map(|pr| pr.summary()))
    }

    fn is_exact(&self) -> bool {
        true
    }

    fn relabelled(&self) -> Option<(Vec3<Nf>, Vec3<Nf>)> {
        let k = self.last?;
        if self.sys.shape.is_convex() {
            return None;
        }
        let next = (k + 1) % self.sys.n();
        let frame = |x: &Vec3<F>| -> Vec3<Nf> {
            [self.sys.along(k, x), self.sys.along(next, x), dot(&self.sys.centre, x)].map(|e| e.to_exact())
        };
        Some((frame(&self.q), frame(&self.p)))
    }
}
