//! Positivity certificates as the producer builds them: `sum c_i * product of atoms / product of
//! atoms`, and the one automatic method, for expressions linear in e1 and e2 with constant
//! coefficients on the region e1 > e2 > 1.

use crate::exact::{Q, Ring};
use chatter_kernel::proof::{Frac, Poly};
use std::cmp::Ordering;

/// A certificate: positive coefficients times products of atoms, over a product of atoms.
#[derive(Clone, Debug, PartialEq)]
pub struct Cert {
    pub terms: Vec<(Q, Vec<String>)>,
    pub over: Vec<String>,
}

impl Cert {
    /// `1 * a * b * ...`.
    pub fn atoms(names: &[&str]) -> Cert {
        Cert { terms: vec![(Q::int(1), names.iter().map(|s| s.to_string()).collect())], over: vec![] }
    }

    /// From (coefficient, atoms) pairs.
    pub fn sum(terms: &[(i64, &[&str])]) -> Cert {
        let terms =
            terms.iter().map(|(c, a)| (Q::int(*c), a.iter().map(|s| s.to_string()).collect())).collect();
        Cert { terms, over: vec![] }
    }

    /// The same certificate divided by the given polynomial atoms.
    pub fn over(mut self, atoms: &[&str]) -> Cert {
        self.over.extend(atoms.iter().map(|s| s.to_string()));
        self
    }

    /// Every term multiplied by the given atoms.
    pub fn times(mut self, atoms: &[&str]) -> Cert {
        for t in &mut self.terms {
            t.1.extend(atoms.iter().map(|s| s.to_string()));
        }
        self
    }

    /// The sum of two certificates with the same denominator.
    pub fn plus(mut self, o: Cert) -> Cert {
        assert_eq!(self.over, o.over, "certificates added must share their denominator");
        self.terms.extend(o.terms);
        self
    }

    /// The terms as the proof file writes them.
    pub fn text_terms(&self) -> Vec<(String, Vec<String>)> {
        self.terms.iter().map(|(c, a)| (c.to_string(), a.clone())).collect()
    }
}

/// Indices of the variables the linear method reads.
#[derive(Clone, Copy, Debug)]
pub struct LinearVars {
    pub l: usize,
    pub e1: usize,
    pub e2: usize,
}

/// `p` with every monomial `e1 l m` rewritten as `e2 m` (the definition e2 = lambda e1).
fn fold_e2(p: &Poly<Q>, v: LinearVars) -> Poly<Q> {
    let n = p.nvars();
    p.terms().fold(Poly::zero(n), |acc, (e, c)| {
        let mut e = e.clone();
        while e[v.e1] > 0 && e[v.l] > 0 {
            e[v.e1] -= 1;
            e[v.l] -= 1;
            e[v.e2] += 1;
        }
        let mono = (0..n).fold(Poly::constant(n, c.clone()), |m, i| m.mul(&Poly::var(n, i).pow(e[i])));
        acc.add(&mono)
    })
}

/// The sign of an expression whose numerator is (after e1 l -> e2) a + b e1 + c e2 with rational
/// a, b, c, and a certificate of it (or of its negative): with e1 > e2 > 1,
/// a + b e1 + c e2 = b (e1 - e2) + (b + c)(e2 - 1) + (a + b + c).
/// `None` when the form is not linear or the sign is not decided this way.
pub fn linear(f: &Frac<Q>, v: LinearVars) -> Option<(Ordering, Cert)> {
    let p = fold_e2(&f.num, v);
    let (mut a, mut b, mut c) = (Q::int(0), Q::int(0), Q::int(0));
    for (e, x) in p.terms() {
        let degree: u32 = e.iter().sum();
        match (degree, e[v.e1], e[v.e2]) {
            (0, _, _) => a = x.clone(),
            (1, 1, _) => b = x.clone(),
            (1, _, 1) => c = x.clone(),
            _ => return None,
        }
    }
    let (alpha, beta, delta) = (b.clone(), &b + &c, &(&a + &b) + &c);
    let zero = Q::int(0);
    let sign = if alpha >= zero && beta >= zero && delta >= zero {
        Ordering::Greater
    } else if alpha <= zero && beta <= zero && delta <= zero {
        Ordering::Less
    } else {
        return None;
    };
    let s = if sign == Ordering::Less { Q::int(-1) } else { Q::int(1) };
    let terms: Vec<(Q, Vec<String>)> =
        [(alpha, vec!["e1-e2".to_string()]), (beta, vec!["e2-1".to_string()]), (delta, vec![])]
            .into_iter()
            .map(|(x, a)| (&x * &s, a))
            .filter(|(x, _)| x.is_positive())
            .collect();
    if terms.is_empty() {
        return None;
    }
    Some((sign, Cert { terms, over: f.den.clone() }))
}
