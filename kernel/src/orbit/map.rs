//! The return map R_P of a pattern P on the section Σ (docs/orbit-certificates.md §2), written
//! once over any arithmetic ([`Num`]): exact scalars (the return map at an exact point) or
//! intervals with gradients ([`Centred`], enclosures over a box). Every quantity whose sign a
//! condition needs is handed to the caller's `check` before it is used, in a fixed order.

use super::interval::{Centred, Iv};
use crate::exact::{Field, OrderedField};
use crate::model::linalg::Mat3;
use crate::model::polygon::Polygon;

/// The arithmetic the return map is written in, with constants of type `K`: exact scalars
/// (`K` itself, rationals or elements of Q(cos 2π/n)), or enclosures over a box ([`Centred`])
/// with the body's constants known by rational enclosures (`K` = [`Iv`]).
pub trait Num<K>: Clone {
    /// A constant.
    fn cst(c: &K) -> Self;
    /// An integer constant.
    fn int(v: i64) -> Self;
    /// Sum.
    fn add(&self, o: &Self) -> Self;
    /// Difference.
    fn sub(&self, o: &Self) -> Self;
    /// Product.
    fn mul(&self, o: &Self) -> Self;
    /// Product with a constant.
    fn scale(&self, c: &K) -> Self;
    /// Quotient, `None` when the divisor is (or may be) 0.
    fn div(&self, o: &Self) -> Option<Self>;
}

impl<K: OrderedField> Num<K> for K {
    fn cst(c: &K) -> Self {
        c.clone()
    }
    fn int(v: i64) -> Self {
        K::from_i64(v)
    }
    fn add(&self, o: &Self) -> Self {
        self.plus(o)
    }
    fn sub(&self, o: &Self) -> Self {
        self.minus(o)
    }
    fn mul(&self, o: &Self) -> Self {
        self.times(o)
    }
    fn scale(&self, c: &K) -> Self {
        self.times(c)
    }
    fn div(&self, o: &Self) -> Option<Self> {
        self.over(o)
    }
}

impl<F: Field, const D: usize> Num<Iv<F>> for Centred<F, D> {
    fn cst(c: &Iv<F>) -> Self {
        Centred::enclosed(c)
    }
    fn int(v: i64) -> Self {
        Centred::constant(&F::from_i64(v))
    }
    fn add(&self, o: &Self) -> Self {
        self.plus(o)
    }
    fn sub(&self, o: &Self) -> Self {
        self.minus(o)
    }
    fn mul(&self, o: &Self) -> Self {
        self.times(o)
    }
    fn scale(&self, c: &Iv<F>) -> Self {
        self.scaled_by(c)
    }
    fn div(&self, o: &Self) -> Option<Self> {
        self.over(o)
    }
}

/// A quantity that must be positive (`strict`) or non-negative on all of X.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Quantity {
    /// Condition 1: -u_j > 0 at step `step` (the target contact approaches).
    Approach {
        /// The step (from 0).
        step: usize,
        /// The target contact j.
        contact: usize,
    },
    /// Condition 1: h_j > 0 at step `step` (the target contact is up).
    Up {
        /// The step (from 0).
        step: usize,
        /// The target contact j.
        contact: usize,
    },
    /// Condition 1: h_k(-u_j) + h_j u_k > 0 (contact k is still up when j lands).
    Clear {
        /// The step (from 0).
        step: usize,
        /// The other contact k.
        contact: usize,
    },
    /// Condition 2: alpha = hc(q_m) > 0.
    PositionScale,
    /// Condition 2: beta = -v(p_m) > 0.
    VelocityScale,
    /// Condition 2: delta - y'_i >= 0 (`upper`) or y'_i + delta >= 0, for y' = A^-1 (R_P(x) - x*).
    Inside {
        /// The coordinate i.
        coordinate: usize,
        /// Which end.
        upper: bool,
    },
    /// Condition 3: lambda - beta >= 0.
    VelocityBound,
    /// Condition 3: rho beta - alpha >= 0 (alpha/beta <= rho).
    RatioBound,
    /// Condition 3: lambda - alpha >= 0.
    PositionBound,
    /// Condition 3: period - T >= 0.
    TimeBound,
}

impl Quantity {
    /// Whether the quantity must be strictly positive.
    pub fn strict(self) -> bool {
        matches!(
            self,
            Quantity::Approach { .. }
                | Quantity::Up { .. }
                | Quantity::Clear { .. }
                | Quantity::PositionScale
                | Quantity::VelocityScale
        )
    }

    /// The condition of docs/orbit-certificates.md §3 (1, 2 or 3).
    pub fn condition(self) -> u8 {
        match self {
            Quantity::Approach { .. } | Quantity::Up { .. } | Quantity::Clear { .. } => 1,
            Quantity::PositionScale | Quantity::VelocityScale | Quantity::Inside { .. } => 2,
            _ => 3,
        }
    }

    /// (step, contact) for condition 1.
    pub fn step_contact(self) -> (Option<usize>, Option<usize>) {
        match self {
            Quantity::Approach { step, contact }
            | Quantity::Up { step, contact }
            | Quantity::Clear { step, contact } => (Some(step), Some(contact)),
            _ => (None, None),
        }
    }
}

/// Why the computation of R_P stopped.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stop {
    /// The caller's check failed on this quantity.
    Failed(Quantity),
    /// A division by this quantity was impossible (its enclosure contains 0).
    Division(Quantity),
}

/// The body's constants the return map needs, exact or enclosed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Maps<K> {
    /// n.
    pub n: usize,
    /// Contact covectors f_0..f_{n-1}.
    pub contacts: Vec<[K; 3]>,
    /// The impact map I_0.
    pub impact0: Mat3<K>,
}

impl<K: Clone> Maps<K> {
    /// The constants of a regular polygon, exact.
    pub fn new(body: &Polygon<K>) -> Self
    where
        K: OrderedField,
    {
        let n = body.n();
        Maps {
            n,
            contacts: (0..n).map(|k| body.contact(k as i64).clone()).collect(),
            impact0: body.impact(0),
        }
    }

    /// The same maps with every constant replaced by `f` of it (e.g. its enclosure).
    pub fn map<L>(&self, f: impl Fn(&K) -> L) -> Maps<L> {
        let row = |r: &[K; 3]| r.each_ref().map(&f);
        Maps {
            n: self.n,
            contacts: self.contacts.iter().map(row).collect(),
            impact0: self.impact0.each_ref().map(row),
        }
    }

    fn dot<T: Num<K>>(&self, f: &[K; 3], x: &[T; 3]) -> T {
        x[0].scale(&f[0]).add(&x[1].scale(&f[1])).add(&x[2].scale(&f[2]))
    }
}

/// One period: the normalised state after it, the scales and the flight time.
#[derive(Clone, Debug)]
pub struct Period<T> {
    /// R_P(x) = (a', b', c').
    pub next: [T; 3],
    /// alpha = hc(q_m).
    pub alpha: T,
    /// beta = -v(p_m).
    pub beta: T,
    /// T = t_1 + ... + t_m.
    pub time: T,
    /// The states (q_s, p_s) before each step and after the last, unnormalised.
    pub states: Vec<([T; 3], [T; 3])>,
}

/// The return map of `pattern` at x = (a, b, c) ∈ Σ; `check` sees every quantity of conditions 1
/// and 2 whose sign is needed, in order, before it is used as a divisor.
pub fn period<K: Clone, T: Num<K>>(
    maps: &Maps<K>,
    pattern: &[usize],
    x: &[T; 3],
    check: &mut dyn FnMut(Quantity, &T) -> Result<(), Stop>,
) -> Result<Period<T>, Stop> {
    let (zero, one) = (T::int(0), T::int(1));
    let mut q = [zero.clone(), x[0].clone(), one.clone()];
    let mut p = [x[1].clone(), x[2].clone(), zero.sub(&one)];
    let mut time = zero.clone();
    let mut states = Vec::with_capacity(pattern.len() + 1);
    for (s, &j) in pattern.iter().enumerate() {
        states.push((q.clone(), p.clone()));
        let (t, q1, p1) = step(maps, s, j, &q, &p, check)?;
        time = time.add(&t);
        (q, p) = (q1, p1);
    }
    states.push((q.clone(), p.clone()));
    let alpha = q[2].clone();
    let beta = zero.sub(&p[2]);
    check(Quantity::PositionScale, &alpha)?;
    check(Quantity::VelocityScale, &beta)?;
    let a = q[1].div(&alpha).ok_or(Stop::Division(Quantity::PositionScale))?;
    let b = p[0].div(&beta).ok_or(Stop::Division(Quantity::VelocityScale))?;
    let c = p[1].div(&beta).ok_or(Stop::Division(Quantity::VelocityScale))?;
    Ok(Period { next: [a, b, c], alpha, beta, time, states })
}

/// One impact (docs/orbit-certificates.md §3, condition 1, step `s`): from the state (q, p),
/// contact `j` lands first, after t = h_j/(-u_j), every other contact strictly up then; returns
/// t and the state right after the impact, relabelled so that the landed contact is contact 0.
/// `check` sees -u_j, h_j and h_k(-u_j) + h_j u_k for every k != j, in that order.
pub fn step<K: Clone, T: Num<K>>(
    maps: &Maps<K>,
    s: usize,
    j: usize,
    q: &[T; 3],
    p: &[T; 3],
    check: &mut dyn FnMut(Quantity, &T) -> Result<(), Stop>,
) -> Result<(T, [T; 3], [T; 3]), Stop> {
    let n = maps.n;
    let zero = T::int(0);
    let hj = maps.dot(&maps.contacts[j], q);
    let uj = maps.dot(&maps.contacts[j], p);
    let nu = zero.sub(&uj);
    let approach = Quantity::Approach { step: s, contact: j };
    check(approach, &nu)?;
    check(Quantity::Up { step: s, contact: j }, &hj)?;
    for k in (0..n).filter(|&k| k != j) {
        let hk = maps.dot(&maps.contacts[k], q);
        let uk = maps.dot(&maps.contacts[k], p);
        check(Quantity::Clear { step: s, contact: k }, &hk.mul(&nu).add(&hj.mul(&uk)))?;
    }
    let t = hj.div(&nu).ok_or(Stop::Division(approach))?;
    let moved: [T; 3] = std::array::from_fn(|i| q[i].add(&t.mul(&p[i])));
    let next = &maps.contacts[(j + 1) % n];
    // h_j(q + t p) = h_j + t u_j = 0 exactly: the landed contact is the new contact 0.
    let q1 = [zero.clone(), maps.dot(next, &moved), moved[2].clone()];
    let relabelled = [uj, maps.dot(next, p), p[2].clone()];
    let p1 = std::array::from_fn(|i| maps.dot(&maps.impact0[i], &relabelled));
    Ok((t, q1, p1))
}
