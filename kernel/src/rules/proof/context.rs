//! What a proof has established so far, and the exact tests on expressions: an identity holds
//! when the numerator of the difference, with every definition substituted (denominators cleared,
//! each proved positive), has pseudo-remainder zero by chi in lambda (docs/kernel-soundness.md).

use super::failure::{ExprError, Failure};
use super::poly::{MAX_TOTAL_DEGREE, Poly};
use crate::exact::{Field, ParseLimits};
use std::collections::BTreeMap;

/// Largest degree in lambda before the reduction by chi (the pseudo-remainder costs grow with it).
pub const MAX_LAMBDA_DEGREE: u32 = 32;
/// Largest number of variables of a proof.
pub const MAX_VARIABLES: usize = 16;

/// An expression: a polynomial over a product of polynomial atoms (each proved positive).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Frac<F> {
    /// The numerator.
    pub num: Poly<F>,
    /// Names of polynomial atoms whose product is the denominator.
    pub den: Vec<String>,
}

impl<F: Field> Frac<F> {
    /// A polynomial.
    pub fn poly(num: Poly<F>) -> Self {
        Frac { num, den: Vec::new() }
    }

    /// `-self`.
    pub fn neg(&self) -> Self {
        Frac { num: self.num.neg(), den: self.den.clone() }
    }
}

/// The state of a proof being checked.
#[derive(Clone)]
pub struct Context<F> {
    /// Variable names.
    pub names: Vec<String>,
    /// Limits on numbers in the text.
    pub limits: ParseLimits,
    /// Index of lambda.
    pub lambda: usize,
    /// chi, whose roots lambda ranges over.
    pub chi: Poly<F>,
    /// Definitions (variable, numerator, denominator), in order.
    defs: Vec<(usize, Poly<F>, Poly<F>)>,
    /// Atoms: expressions proved (or assumed) positive.
    atoms: BTreeMap<String, Frac<F>>,
}

impl<F: Field> Context<F> {
    /// A context with variables, lambda's index and chi.
    pub fn new(names: Vec<String>, limits: ParseLimits, lambda: usize, chi: Poly<F>) -> Self {
        Context { names, limits, lambda, chi, defs: Vec::new(), atoms: BTreeMap::new() }
    }

    /// Number of variables.
    pub fn nvars(&self) -> usize {
        self.names.len()
    }

    /// The index of a variable.
    pub fn var(&self, name: &str) -> Result<usize, Failure> {
        self.names.iter().position(|n| n == name).ok_or_else(|| Failure::UnknownVariable(name.to_string()))
    }

    /// A constant polynomial.
    pub fn constant(&self, c: F) -> Poly<F> {
        Poly::constant(self.nvars(), c)
    }

    /// Parses a canonical polynomial.
    pub fn poly(&self, text: &str) -> Result<Poly<F>, Failure> {
        Poly::parse(text, &self.names, self.limits)
    }

    /// Parses `N` or `(N) / [a] [b] ...` (every atom known and polynomial).
    pub fn frac(&self, text: &str) -> Result<Frac<F>, Failure> {
        let Some(rest) = text.strip_prefix('(') else { return Ok(Frac::poly(self.poly(text)?)) };
        let bad = |e: ExprError| Failure::Expression(text.to_string(), e);
        let (num, den) = rest.split_once(") / ").ok_or_else(|| bad(ExprError::NotFraction))?;
        let mut atoms = Vec::new();
        for tok in den.split(' ') {
            let name = tok
                .strip_prefix('[')
                .and_then(|t| t.strip_suffix(']'))
                .ok_or_else(|| bad(ExprError::NotAtom(tok.to_string())))?;
            self.polynomial_atom(name)?;
            atoms.push(name.to_string());
        }
        Ok(Frac { num: self.poly(num)?, den: atoms })
    }

    /// The canonical text of an expression.
    pub fn text(&self, f: &Frac<F>) -> String {
        let num = f.num.text(&self.names);
        if f.den.is_empty() {
            return num;
        }
        let den: Vec<String> = f.den.iter().map(|a| format!("[{a}]")).collect();
        format!("({num}) / {}", den.join(" "))
    }

    /// Registers an atom (a name for an expression known to be positive).
    pub fn add_atom(&mut self, name: &str, f: Frac<F>) -> Result<(), Failure> {
        if self.atoms.contains_key(name) {
            return Err(Failure::DuplicateAtom(name.to_string()));
        }
        self.atoms.insert(name.to_string(), f);
        Ok(())
    }

    /// An atom's expression.
    pub fn atom(&self, name: &str) -> Result<&Frac<F>, Failure> {
        self.atoms.get(name).ok_or_else(|| Failure::UnknownAtom(name.to_string()))
    }

    /// An atom without denominator (usable as a denominator).
    pub fn polynomial_atom(&self, name: &str) -> Result<&Poly<F>, Failure> {
        let a = self.atom(name)?;
        if a.den.is_empty() { Ok(&a.num) } else { Err(Failure::AtomDenominator(name.to_string())) }
    }

    /// Registers a definition `v = num / den` (`den` proved positive by the caller). `num` and
    /// `den` may involve only `allowed` variables (the parameters and lambda) and variables defined
    /// before, so the definitions are explicit functions of the parameters and lambda.
    pub fn define(&mut self, v: usize, num: Poly<F>, den: Poly<F>, allowed: &[usize]) -> Result<(), Failure> {
        if v == self.lambda || allowed.contains(&v) || self.defs.iter().any(|(d, _, _)| *d == v) {
            return Err(Failure::CannotDefine(self.names[v].clone()));
        }
        let known =
            |x: usize| allowed.contains(&x) || x == self.lambda || self.defs.iter().any(|(d, _, _)| *d == x);
        if let Some(x) =
            (0..self.nvars()).find(|&x| (num.degree_in(x) > 0 || den.degree_in(x) > 0) && !known(x))
        {
            return Err(Failure::UsesUndefined(self.names[x].clone()));
        }
        self.defs.push((v, num, den));
        Ok(())
    }

    /// Whether a variable has been defined.
    pub fn is_defined(&self, v: usize) -> bool {
        self.defs.iter().any(|(d, _, _)| *d == v)
    }

    /// The product of the atoms of a denominator.
    fn den_poly(&self, f: &Frac<F>) -> Result<Poly<F>, Failure> {
        let mut acc = self.constant(F::one());
        for a in &f.den {
            acc = acc.try_mul(self.polynomial_atom(a)?)?;
        }
        Ok(acc)
    }

    /// Whether a polynomial vanishes at every point of the region: definitions substituted
    /// (latest first, denominators cleared), then the pseudo-remainder by chi in lambda is zero.
    /// An error when the polynomials would exceed the size limits.
    pub fn vanishes(&self, p: &Poly<F>) -> Result<bool, Failure> {
        let mut p = p.clone();
        for (v, n, d) in self.defs.iter().rev() {
            let k = p.degree_in(*v);
            let predicted = p.total_degree() + k * n.total_degree().max(d.total_degree());
            if predicted > MAX_TOTAL_DEGREE {
                return Err(Failure::Substitution(self.names[*v].clone(), predicted));
            }
            p = p.subst_fraction(*v, n, d)?;
        }
        if p.degree_in(self.lambda) > MAX_LAMBDA_DEGREE {
            return Err(Failure::LambdaDegree(p.degree_in(self.lambda)));
        }
        Ok(p.pseudo_remainder(&self.chi, self.lambda)?.is_zero())
    }

    /// `a b`, within the size limits.
    pub fn mul(&self, a: &Frac<F>, b: &Frac<F>) -> Result<Frac<F>, Failure> {
        let num = a.num.try_mul(&b.num)?;
        let den = if num.is_zero() { Vec::new() } else { a.den.iter().chain(&b.den).cloned().collect() };
        Ok(Frac { num, den })
    }

    /// `a + b` (denominators multiplied unless equal), within the size limits.
    pub fn add(&self, a: &Frac<F>, b: &Frac<F>) -> Result<Frac<F>, Failure> {
        if a.num.is_zero() {
            return Ok(b.clone());
        }
        if b.num.is_zero() {
            return Ok(a.clone());
        }
        if a.den == b.den {
            return Ok(Frac { num: a.num.add(&b.num), den: a.den.clone() });
        }
        let num = a.num.try_mul(&self.den_poly(b)?)?.add(&b.num.try_mul(&self.den_poly(a)?)?);
        Ok(Frac { num, den: a.den.iter().chain(&b.den).cloned().collect() })
    }

    /// `a . b` for a covector and a point of expressions.
    pub fn dot(&self, a: &[Frac<F>; 3], b: &[Frac<F>; 3]) -> Result<Frac<F>, Failure> {
        let mut acc = self.mul(&a[0], &b[0])?;
        for i in 1..3 {
            acc = self.add(&acc, &self.mul(&a[i], &b[i])?)?;
        }
        Ok(acc)
    }

    /// `m p` for a matrix of polynomials.
    pub fn image(&self, m: &[[Poly<F>; 3]; 3], p: &[Frac<F>; 3]) -> Result<[Frac<F>; 3], Failure> {
        let row = |r: usize| self.dot(&m[r].clone().map(Frac::poly), p);
        Ok([row(0)?, row(1)?, row(2)?])
    }

    /// Whether `a = b` at every point of the region.
    pub fn equal(&self, a: &Frac<F>, b: &Frac<F>) -> Result<bool, Failure> {
        self.vanishes(&a.num.try_mul(&self.den_poly(b)?)?.sub(&b.num.try_mul(&self.den_poly(a)?)?))
    }

    /// Whether `a = 0` at every point of the region.
    pub fn is_zero(&self, a: &Frac<F>) -> Result<bool, Failure> {
        self.vanishes(&a.num)
    }
}
