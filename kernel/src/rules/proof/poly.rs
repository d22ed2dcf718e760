//! Sparse multivariate polynomials over a field of either backend, in a proof's variables, with
//! the strict canonical text of docs/proof-format.md: terms by decreasing total degree, then by
//! decreasing exponents in the order the variables are declared, e.g. `2 g^2 k - 1/3 l + 1`.

use super::failure::{ExprError, Failure};
use crate::exact::{Field, ParseLimits, parse_canonical, to_canonical};
use std::collections::BTreeMap;

/// Largest exponent of a variable in a term of the text (keeps the arithmetic small).
pub const MAX_DEGREE: u32 = 64;
/// Largest number of terms of any polynomial the checker builds.
pub const MAX_TERMS: usize = 20_000;
/// Largest number of coefficient products in one multiplication.
pub const MAX_WORK: usize = 4_000_000;
/// Largest total degree of a polynomial after the definitions are substituted.
pub const MAX_TOTAL_DEGREE: u32 = 96;

/// A polynomial: exponent vectors (one entry per variable) to non-zero coefficients.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Poly<F> {
    nvars: usize,
    terms: BTreeMap<Vec<u32>, F>,
}

impl<F: Field> Poly<F> {
    /// The zero polynomial in `nvars` variables.
    pub fn zero(nvars: usize) -> Self {
        Poly { nvars, terms: BTreeMap::new() }
    }

    /// The constant `c`.
    pub fn constant(nvars: usize, c: F) -> Self {
        let mut p = Poly::zero(nvars);
        p.add_term(vec![0; nvars], c);
        p
    }

    /// The variable with index `i`.
    pub fn var(nvars: usize, i: usize) -> Self {
        let mut e = vec![0; nvars];
        e[i] = 1;
        let mut p = Poly::zero(nvars);
        p.add_term(e, F::one());
        p
    }

    /// Number of variables.
    pub fn nvars(&self) -> usize {
        self.nvars
    }

    /// Whether every coefficient is zero.
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    /// The value if the polynomial is constant.
    pub fn as_constant(&self) -> Option<F> {
        match self.terms.len() {
            0 => Some(F::zero()),
            1 => self.terms.get(&vec![0; self.nvars]).cloned(),
            _ => None,
        }
    }

    /// The terms, exponent vector to coefficient.
    pub fn terms(&self) -> impl Iterator<Item = (&Vec<u32>, &F)> {
        self.terms.iter()
    }

    fn add_term(&mut self, e: Vec<u32>, c: F) {
        if c.is_zero() {
            return;
        }
        let sum = match self.terms.get(&e) {
            Some(old) => old.plus(&c),
            None => c,
        };
        if sum.is_zero() {
            self.terms.remove(&e);
        } else {
            self.terms.insert(e, sum);
        }
    }

    /// `self + o`.
    pub fn add(&self, o: &Self) -> Self {
        let mut p = self.clone();
        for (e, c) in &o.terms {
            p.add_term(e.clone(), c.clone());
        }
        p
    }

    /// `self - o`.
    pub fn sub(&self, o: &Self) -> Self {
        self.add(&o.neg())
    }

    /// `-self`.
    pub fn neg(&self) -> Self {
        self.scale(&F::one().negated())
    }

    /// `c self`.
    pub fn scale(&self, c: &F) -> Self {
        if c.is_zero() {
            return Poly::zero(self.nvars);
        }
        Poly { nvars: self.nvars, terms: self.terms.iter().map(|(e, x)| (e.clone(), x.times(c))).collect() }
    }

    /// `self o`.
    pub fn mul(&self, o: &Self) -> Self {
        let mut p = Poly::zero(self.nvars);
        for (ea, ca) in &self.terms {
            for (eb, cb) in &o.terms {
                p.add_term(ea.iter().zip(eb).map(|(a, b)| a + b).collect(), ca.times(cb));
            }
        }
        p
    }

    /// `self o`, or an error when the product would exceed the size limits.
    pub fn try_mul(&self, o: &Self) -> Result<Self, Failure> {
        if self.terms.len().saturating_mul(o.terms.len()) > MAX_WORK {
            return Err(Failure::Product(self.terms.len(), o.terms.len()));
        }
        let p = self.mul(o);
        if p.terms.len() > MAX_TERMS {
            return Err(Failure::Terms(p.terms.len()));
        }
        Ok(p)
    }

    /// `self^k`.
    pub fn pow(&self, k: u32) -> Self {
        (0..k).fold(Poly::constant(self.nvars, F::one()), |acc, _| acc.mul(self))
    }

    /// The total degree (0 for the zero polynomial).
    pub fn total_degree(&self) -> u32 {
        self.terms.keys().map(|e| e.iter().sum()).max().unwrap_or(0)
    }

    /// The degree in variable `v` (0 for the zero polynomial).
    pub fn degree_in(&self, v: usize) -> u32 {
        self.terms.keys().map(|e| e[v]).max().unwrap_or(0)
    }

    /// The coefficient of `v^d`, a polynomial in the other variables.
    pub fn coeff_in(&self, v: usize, d: u32) -> Self {
        let mut p = Poly::zero(self.nvars);
        for (e, c) in self.terms.iter().filter(|(e, _)| e[v] == d) {
            let mut e = e.clone();
            e[v] = 0;
            p.add_term(e, c.clone());
        }
        p
    }

    /// `self` with `num / den` substituted for variable `v`, times `den^deg_v(self)` (a
    /// polynomial; it vanishes exactly where `self(v = num/den)` does, wherever `den != 0`), or
    /// an error beyond the size limits.
    pub fn subst_fraction(&self, v: usize, num: &Self, den: &Self) -> Result<Self, Failure> {
        let d = self.degree_in(v);
        let mut num_pow = vec![Poly::constant(self.nvars, F::one())];
        let mut den_pow = vec![Poly::constant(self.nvars, F::one())];
        for i in 1..=d as usize {
            num_pow.push(num_pow[i - 1].try_mul(num)?);
            den_pow.push(den_pow[i - 1].try_mul(den)?);
        }
        let mut acc = Poly::zero(self.nvars);
        for i in 0..=d as usize {
            let term = self.coeff_in(v, i as u32).try_mul(&num_pow[i])?.try_mul(&den_pow[d as usize - i])?;
            acc = acc.add(&term);
        }
        Ok(acc)
    }

    /// `self` with the constant `x` substituted for variable `v` (never larger than `self`).
    pub fn subst_constant(&self, v: usize, x: &F) -> Self {
        let mut out = Poly::zero(self.nvars);
        for (e, c) in &self.terms {
            let mut e = e.clone();
            let k = std::mem::take(&mut e[v]);
            let xk = (0..k).fold(F::one(), |acc, _| acc.times(x));
            out.add_term(e, c.times(&xk));
        }
        out
    }

    /// The pseudo-remainder of `self` by `m` in variable `v`: `lead(m)^e self = q m + r` with
    /// `deg_v r < deg_v m`, where `lead(m)` is the coefficient of the highest power of `v`; or an
    /// error beyond the size limits.
    pub fn pseudo_remainder(&self, m: &Self, v: usize) -> Result<Self, Failure> {
        let n = m.degree_in(v);
        let lc = m.coeff_in(v, n);
        let mut r = self.clone();
        while !r.is_zero() && r.degree_in(v) >= n {
            let d = r.degree_in(v);
            let mut shift = vec![0; self.nvars];
            shift[v] = d - n;
            let mut x = Poly::zero(self.nvars);
            x.add_term(shift, F::one());
            r = r.try_mul(&lc)?.sub(&r.coeff_in(v, d).try_mul(&x)?.try_mul(m)?);
        }
        Ok(r)
    }

    /// The canonical text, with the given variable names.
    pub fn text(&self, names: &[String]) -> String {
        if self.is_zero() {
            return "0".into();
        }
        let mut terms: Vec<(&Vec<u32>, &F)> = self.terms.iter().collect();
        terms.sort_by(|a, b| {
            let (da, db) = (a.0.iter().sum::<u32>(), b.0.iter().sum::<u32>());
            db.cmp(&da).then(b.0.cmp(a.0))
        });
        let mut out = String::new();
        for (i, (e, c)) in terms.into_iter().enumerate() {
            let abs = if c.is_negative() { c.negated() } else { c.clone() };
            let mono: Vec<String> = (0..self.nvars)
                .filter(|&v| e[v] > 0)
                .map(|v| if e[v] == 1 { names[v].clone() } else { format!("{}^{}", names[v], e[v]) })
                .collect();
            let body = match (mono.is_empty(), abs == F::one()) {
                (true, _) => to_canonical(&abs),
                (false, true) => mono.join(" "),
                (false, false) => format!("{} {}", to_canonical(&abs), mono.join(" ")),
            };
            out.push_str(match (i, c.is_negative()) {
                (0, true) => "-",
                (0, false) => "",
                (_, true) => " - ",
                (_, false) => " + ",
            });
            out.push_str(&body);
        }
        out
    }

    /// Parses the canonical text; anything that does not print back identically is rejected.
    pub fn parse(text: &str, names: &[String], limits: ParseLimits) -> Result<Self, Failure> {
        let p = parse_terms(text, names, limits).map_err(|e| Failure::Expression(text.to_string(), e))?;
        let back = p.text(names);
        if back != text {
            return Err(Failure::Expression(text.to_string(), ExprError::NotCanonical(back)));
        }
        Ok(p)
    }
}

/// Reads terms `[-]c x^e y ... (+|-) ...` without checking the order (see [`Poly::parse`]).
fn parse_terms<F: Field>(text: &str, names: &[String], limits: ParseLimits) -> Result<Poly<F>, ExprError> {
    let mut p = Poly::zero(names.len());
    let mut tokens = text.split(' ').peekable();
    let mut negative = false;
    let mut first = true;
    while let Some(tok) = tokens.next() {
        let tok = if first {
            first = false;
            match tok.strip_prefix('-') {
                Some(rest) if !rest.is_empty() => {
                    negative = true;
                    rest
                }
                _ => tok,
            }
        } else {
            tok
        };
        let mut c = F::one();
        let mut e = vec![0u32; names.len()];
        let mut cur = Some(tok);
        let mut seen_factor = false;
        while let Some(t) = cur {
            if t.starts_with(|ch: char| ch.is_ascii_digit()) {
                if seen_factor {
                    return Err(ExprError::CoefficientFirst);
                }
                c = parse_canonical(t, limits).map_err(|err| ExprError::Coefficient(t.to_string(), err))?;
            } else {
                let (name, exp) = t.split_once('^').map_or((t, Ok(1)), |(n, x)| (n, x.parse::<u32>()));
                let exp = exp
                    .ok()
                    .filter(|x| *x <= MAX_DEGREE)
                    .ok_or_else(|| ExprError::Exponent(t.to_string()))?;
                let v = names
                    .iter()
                    .position(|n| n == name)
                    .ok_or_else(|| ExprError::UnknownVariable(name.to_string()))?;
                e[v] = e[v].checked_add(exp).ok_or(ExprError::ExponentOverflow)?;
            }
            seen_factor = true;
            cur = match tokens.peek() {
                Some(&"+") | Some(&"-") | None => None,
                Some(_) => tokens.next(),
            };
        }
        p.add_term(e, if negative { c.negated() } else { c });
        match tokens.next() {
            Some("+") => negative = false,
            Some("-") => negative = true,
            Some(t) => return Err(ExprError::Unexpected(t.to_string())),
            None => break,
        }
        if tokens.peek().is_none() {
            return Err(ExprError::DanglingSign);
        }
    }
    Ok(p)
}
