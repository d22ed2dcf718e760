//! The exact engine: rational states and rational impact times (every impact time is
//! h_k / (-u_k) with rational h_k, u_k), so ties are decided exactly and symmetric data keep
//! their symmetry (docs/model.md §10).

use super::drop::Start;
use super::engine::{Engine, Step};
use super::pcc::{PairProof, prove_pair_chatter};
pub use super::snapshot::scaled; // formerly defined here
use super::snapshot::{Scaled, Snapshot};
use super::system::System;
use crate::exact::{Q, Ring};
use chatter_kernel::model::linalg::Vec3;

/// A rational vector as (v_m, e) with v = v_m · 2^e and the largest |component| of v_m in [1, 2).
pub fn normalised(v: &Vec3<Q>) -> ([f64; 3], i64) {
    let parts = v.clone().map(|x| (x.sign(), scaled(&x)));
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
fn dot(f: &Vec3<Q>, x: &Vec3<Q>) -> Q {
    let mut acc: Option<Q> = None;
    for (a, b) in f.iter().zip(x) {
        if a.is_zero() || b.is_zero() {
            continue;
        }
        let term = if *a == Q::int(1) {
            b.clone()
        } else if *a == Q::int(-1) {
            -b
        } else {
            a * b
        };
        acc = Some(match acc {
            None => term,
            Some(s) => s + term,
        });
    }
    acc.unwrap_or_else(|| Q::int(0))
}

/// The exact event-driven simulation of one drop.
#[derive(Clone, Debug)]
pub struct ExactEngine<'a> {
    sys: &'a System,
    q: Vec3<Q>,
    p: Vec3<Q>,
    last: Option<usize>,
    /// Time of the last impact: the sum of the exact intervals, each rounded to `f64` (an exact
    /// sum would carry the product of all denominators).
    time: f64,
}

impl<'a> ExactEngine<'a> {
    pub fn new(sys: &'a System, start: &Start<Q>) -> ExactEngine<'a> {
        ExactEngine { sys, q: start.q.clone(), p: start.p.clone(), last: None, time: 0.0 }
    }

    /// The exact state (q, p).
    pub fn state(&self) -> (&Vec3<Q>, &Vec3<Q>) {
        (&self.q, &self.p)
    }

    /// The landing time of every approaching contact (except the last to land), exactly.
    pub fn candidate_times(&self) -> Vec<(usize, Q)> {
        (0..self.sys.n())
            .filter(|&k| Some(k) != self.last)
            .filter_map(|k| {
                let u = dot(&self.sys.contacts[k], &self.p);
                u.is_negative().then(|| (k, dot(&self.sys.contacts[k], &self.q) / (-&u)))
            })
            .collect()
    }

    /// The exact kinetic energy.
    pub fn energy(&self) -> Q {
        self.sys.energy(&self.p)
    }
}

impl Engine for ExactEngine<'_> {
    fn step(&mut self) -> Step {
        let sys = self.sys;
        // (time, u_k) of the earliest approaching contacts; ties collected.
        let mut best: Option<(Q, Q)> = None;
        let mut at: Vec<usize> = Vec::new();
        for k in 0..sys.n() {
            if Some(k) == self.last {
                continue;
            }
            let u = dot(&sys.contacts[k], &self.p);
            if !u.is_negative() {
                continue;
            }
            let t = dot(&sys.contacts[k], &self.q) / (-&u);
            match &best {
                Some((bt, _)) if t > *bt => {}
                Some((bt, _)) if t == *bt => at.push(k),
                _ => {
                    best = Some((t, u));
                    at.clear();
                    at.push(k);
                }
            }
        }
        let Some((t, u)) = best else { return Step::NoApproach };
        let dt = scaled(&t);
        if at.len() > 1 {
            return Step::Tie { contacts: at, dt, exact: true };
        }
        let k = at[0];
        self.time += dt.to_f64();
        let kick = &sys.kicks[k];
        for ((q, p), k) in self.q.iter_mut().zip(self.p.iter_mut()).zip(kick) {
            if !p.is_zero() {
                *q = &*q + &(&t * &*p);
            }
            if !k.is_zero() {
                *p = &*p - &(&u * k);
            }
        }
        self.last = Some(k);
        Step::Impact { contact: k, dt }
    }

    fn v_positive(&self) -> bool {
        dot(&self.sys.centre, &self.p).is_positive()
    }

    fn at_rest(&self) -> bool {
        self.p.iter().all(Ring::is_zero)
    }

    fn time(&self) -> f64 {
        self.time
    }

    fn snapshot(&self) -> Snapshot {
        let (q, q_exp) = normalised(&self.q);
        let (p, p_exp) = normalised(&self.p);
        Snapshot { q, q_exp, p, p_exp, energy: scaled(&self.energy()) }
    }

    fn prove_pair(&self, hit: usize, other: usize) -> Option<Result<PairProof, String>> {
        Some(prove_pair_chatter(self.sys, &self.q, &self.p, hit, other))
    }

    fn is_exact(&self) -> bool {
        true
    }
}
