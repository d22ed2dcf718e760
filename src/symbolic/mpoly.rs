//! Multivariate polynomials over Q (malachite rationals), sparse, in a fixed list of variables.

use crate::exact::{Q, Ring};
use std::collections::BTreeMap;
use std::fmt;

/// The variables of the square-case proofs: g = gamma, k = kappa, l = lambda, s (auxiliary, for
/// substitutions such as lambda = 1 + s), and e1, e2 (the eigenvector coordinates, kept formal in
/// the geometry and replaced by their definitions inside identity checks).
pub const VARS: [&str; 6] = ["g", "k", "l", "s", "e1", "e2"];
pub const G: usize = 0;
pub const K: usize = 1;
pub const L: usize = 2;
pub const S: usize = 3;
pub const E1: usize = 4;
pub const E2: usize = 5;
const NV: usize = VARS.len();

type Exps = [u32; NV];

/// A polynomial: exponent vectors to non-zero rational coefficients.
#[derive(Clone, PartialEq, Eq, Default)]
pub struct MPoly {
    terms: BTreeMap<Exps, Q>,
}

impl MPoly {
    pub fn zero() -> Self {
        MPoly::default()
    }
    pub fn constant(c: Q) -> Self {
        let mut p = MPoly::zero();
        if !c.is_zero() {
            p.terms.insert([0; NV], c);
        }
        p
    }
    pub fn int(c: i64) -> Self {
        MPoly::constant(Q::int(c))
    }
    pub fn var(i: usize) -> Self {
        let mut e = [0; NV];
        e[i] = 1;
        let mut p = MPoly::zero();
        p.terms.insert(e, Q::int(1));
        p
    }
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }
    /// The constant value, if the polynomial is constant.
    pub fn as_constant(&self) -> Option<Q> {
        match self.terms.len() {
            0 => Some(Q::int(0)),
            1 => self.terms.get(&[0; NV]).cloned(),
            _ => None,
        }
    }
    pub fn terms(&self) -> impl Iterator<Item = (&Exps, &Q)> {
        self.terms.iter()
    }

    fn add_term(&mut self, e: Exps, c: Q) {
        let v = self.terms.entry(e).or_insert_with(|| Q::int(0));
        *v = &*v + &c;
        if v.is_zero() {
            self.terms.remove(&e);
        }
    }

    pub fn add(&self, o: &Self) -> Self {
        let mut p = self.clone();
        for (e, c) in &o.terms {
            p.add_term(*e, c.clone());
        }
        p
    }
    pub fn sub(&self, o: &Self) -> Self {
        self.add(&o.neg())
    }
    pub fn neg(&self) -> Self {
        MPoly { terms: self.terms.iter().map(|(e, c)| (*e, -c)).collect() }
    }
    pub fn scale(&self, s: &Q) -> Self {
        if s.is_zero() {
            return MPoly::zero();
        }
        MPoly { terms: self.terms.iter().map(|(e, c)| (*e, c * s)).collect() }
    }
    pub fn mul(&self, o: &Self) -> Self {
        let mut p = MPoly::zero();
        for (ea, ca) in &self.terms {
            for (eb, cb) in &o.terms {
                let e: Exps = std::array::from_fn(|i| ea[i] + eb[i]);
                p.add_term(e, ca * cb);
            }
        }
        p
    }
    pub fn pow(&self, n: u32) -> Self {
        (0..n).fold(MPoly::int(1), |acc, _| acc.mul(self))
    }

    /// Degree in variable `v` (0 for the zero polynomial).
    pub fn degree_in(&self, v: usize) -> u32 {
        self.terms.keys().map(|e| e[v]).max().unwrap_or(0)
    }

    /// The coefficient of v^d, as a polynomial in the other variables.
    pub fn coeff_in(&self, v: usize, d: u32) -> Self {
        let mut p = MPoly::zero();
        for (e, c) in &self.terms {
            if e[v] == d {
                let mut e2 = *e;
                e2[v] = 0;
                p.add_term(e2, c.clone());
            }
        }
        p
    }

    /// Substitutes the polynomial `by` for variable `v`.
    pub fn subst(&self, v: usize, by: &Self) -> Self {
        let deg = self.degree_in(v);
        let mut powers = vec![MPoly::int(1)];
        for _ in 0..deg {
            powers.push(powers.last().expect("non-empty").mul(by));
        }
        (0..=deg).fold(MPoly::zero(), |acc, d| acc.add(&self.coeff_in(v, d).mul(&powers[d as usize])))
    }

    /// The value at rational points (one per variable).
    pub fn eval(&self, at: &[Q; NV]) -> Q {
        self.terms.iter().fold(Q::int(0), |acc, (e, c)| {
            let m = (0..NV).fold(c.clone(), |m, i| (0..e[i]).fold(m, |m, _| &m * &at[i]));
            &acc + &m
        })
    }

    /// Division by `d` as polynomials in variable `v`, when the leading coefficient of `d` in `v`
    /// is a non-zero constant: (q, r) with self = q d + r and deg_v r < deg_v d.
    pub fn div_rem_in(&self, v: usize, d: &Self) -> Option<(Self, Self)> {
        let n = d.degree_in(v);
        let lc = d.coeff_in(v, n).as_constant().filter(|c| !c.is_zero())?;
        let mut q = MPoly::zero();
        let mut r = self.clone();
        while !r.is_zero() && r.degree_in(v) >= n {
            let deg = r.degree_in(v);
            let mut e = [0; NV];
            e[v] = deg - n;
            let shift = MPoly { terms: [(e, Q::int(1))].into_iter().collect() };
            let t = r.coeff_in(v, deg).scale(&(Q::int(1) / lc.clone())).mul(&shift);
            q = q.add(&t);
            r = r.sub(&t.mul(d));
        }
        Some((q, r))
    }

    /// Whether every coefficient is positive (and the polynomial non-zero).
    pub fn all_coefficients_positive(&self) -> bool {
        !self.is_zero() && self.terms.values().all(|c| c.is_positive())
    }
}

impl fmt::Display for MPoly {
    /// Terms in decreasing order of total degree, e.g. `2 g^2 k - l + 1`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.is_zero() {
            return write!(f, "0");
        }
        let mut terms: Vec<(&Exps, &Q)> = self.terms.iter().collect();
        terms.sort_by(|a, b| {
            let (da, db) = (a.0.iter().sum::<u32>(), b.0.iter().sum::<u32>());
            db.cmp(&da).then(b.0.cmp(a.0))
        });
        for (i, (e, c)) in terms.iter().enumerate() {
            let neg = c.is_negative();
            let abs = c.abs();
            let mono: Vec<String> = (0..NV)
                .filter(|v| e[*v] > 0)
                .map(|v| if e[v] == 1 { VARS[v].to_string() } else { format!("{}^{}", VARS[v], e[v]) })
                .collect();
            let body = match (mono.is_empty(), abs == Q::int(1)) {
                (true, _) => abs.to_string(),
                (false, true) => mono.join(" "),
                (false, false) => format!("{abs} {}", mono.join(" ")),
            };
            let sign = match (i, neg) {
                (0, true) => "-",
                (0, false) => "",
                (_, true) => " - ",
                (_, false) => " + ",
            };
            write!(f, "{sign}{body}")?;
        }
        Ok(())
    }
}

impl fmt::Debug for MPoly {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{self}")
    }
}
