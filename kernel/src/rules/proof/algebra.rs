//! The algebraic steps: positivity certificates, identities, definitions, points, root bounds,
//! the PCC factorisation and witnesses at rational points.

use super::check::Checker;
use super::context::Frac;
use super::failure::Failure;
use super::model::{PMat, det};
use super::poly::Poly;
use crate::exact::univariate::{Coeffs, count_roots, positive_on};
use crate::exact::{Field, parse_canonical, to_canonical};
use std::collections::BTreeMap;

/// An expression's text for a conclusion, abbreviated when long.
fn short(s: String) -> String {
    if s.chars().count() <= 120 {
        return s;
    }
    let head: String = s.chars().take(100).collect();
    format!("{head}... ({} characters)", s.chars().count())
}

impl<F: Field> Checker<'_, F> {
    /// A rational number of the text.
    pub(super) fn rational(&self, s: &str) -> Result<F, Failure> {
        parse_canonical(s, self.ctx.limits).map_err(|e| Failure::Number(s.to_string(), e))
    }

    /// `expr > 0` by a positive combination of products of atoms over a product of atoms.
    pub(super) fn positive(
        &mut self,
        id: &str,
        expr: &str,
        terms: &[(String, Vec<String>)],
        over: &[String],
    ) -> Result<(), Failure> {
        let e = self.ctx.frac(expr)?;
        if terms.is_empty() {
            return Err(Failure::NoTerms);
        }
        let mut sum: Option<Frac<F>> = None;
        for (c, atoms) in terms {
            let c = self.rational(c)?;
            if !c.is_positive() {
                return Err(Failure::CoefficientNotPositive(to_canonical(&c)));
            }
            let mut t = Frac::poly(self.ctx.constant(c));
            for a in atoms {
                t = self.ctx.mul(&t, self.ctx.atom(a)?)?;
            }
            sum = Some(match sum {
                None => t,
                Some(s) => self.ctx.add(&s, &t)?,
            });
        }
        let mut cert = sum.expect("non-empty");
        for a in over {
            self.ctx.polynomial_atom(a)?;
            cert.den.push(a.clone());
        }
        if !self.ctx.equal(&e, &cert)? {
            return Err(Failure::NotItsCertificate(self.ctx.text(&e), self.ctx.text(&cert)));
        }
        if self.ctx.is_zero(&e)? {
            // 0 > 0 would mean that the region is empty: refuse it rather than prove anything.
            return Err(Failure::VanishesOnRegion);
        }
        self.ctx.add_atom(id, e)
    }

    /// `lhs = rhs` at every point of the region.
    pub(super) fn identity(&mut self, lhs: &str, rhs: &str) -> Result<(), Failure> {
        let (a, b) = (self.ctx.frac(lhs)?, self.ctx.frac(rhs)?);
        if self.ctx.equal(&a, &b)? {
            Ok(())
        } else {
            Err(Failure::NotIdentity(lhs.to_string(), rhs.to_string()))
        }
    }

    /// Defines a variable as num / den, den proved positive by the step `positive`.
    pub(super) fn define(
        &mut self,
        id: &str,
        num: &str,
        den: &str,
        positive: Option<&str>,
    ) -> Result<(), Failure> {
        let v = self.ctx.var(id)?;
        if v == self.params.0 || v == self.params.1 {
            return Err(Failure::ParameterDefined(id.to_string()));
        }
        let (n, d) = (self.ctx.poly(num)?, self.ctx.poly(den)?);
        let proved = match positive {
            None => d.as_constant().is_some_and(|c| c.is_positive()),
            Some(step) => self.ctx.equal(self.ctx.atom(step)?, &Frac::poly(d.clone()))?,
        };
        if !proved {
            return Err(Failure::DenominatorNotPositive(den.to_string()));
        }
        self.ctx.define(v, n, d, &[self.params.0, self.params.1])
    }

    /// Names the point (x, y, -1).
    pub(super) fn point(&mut self, id: &str, x: &str, y: &str) -> Result<(), Failure> {
        let p = [self.ctx.frac(x)?, self.ctx.frac(y)?, Frac::poly(self.ctx.constant(F::one().negated()))];
        if self.points.insert(id.to_string(), p).is_some() {
            return Err(Failure::DuplicatePoint(id.to_string()));
        }
        Ok(())
    }

    /// Every root of chi is below b: the coefficients of chi(b + s) in s are positive.
    pub(super) fn root_bound(&mut self, id: &str, below: &str, variable: &str) -> Result<(), Failure> {
        let b = self.rational(below)?;
        let s = self.ctx.var(variable)?;
        let l = self.ctx.lambda;
        if s == l
            || s == self.params.0
            || s == self.params.1
            || self.ctx.is_defined(s)
            || self.ctx.chi.degree_in(s) > 0
        {
            return Err(Failure::NotFree(variable.to_string()));
        }
        let nv = self.ctx.nvars();
        let shifted = self.ctx.chi.subst_fraction(
            l,
            &self.ctx.constant(b.clone()).add(&Poly::var(nv, s)),
            &self.ctx.constant(F::one()),
        )?;
        for d in 0..=shifted.degree_in(s) {
            let c = Frac::poly(shifted.coeff_in(s, d));
            let sign = self.sign_of(&format!("{id}.{d}"), &c)?;
            if sign.is_lt() || (d == 0 && sign.is_eq()) {
                return Err(Failure::RootCoefficient(variable.to_string(), d, below.to_string()));
            }
        }
        let atom = self.ctx.constant(b).sub(&Poly::var(nv, l));
        self.conclusions.push(format!("every real root of chi is below {below} (atom `{id}`)"));
        self.ctx.add_atom(id, Frac::poly(atom))
    }

    /// det(t I - S_{n-1} S_1) = (t - 1)(t^2 + p t + q), as polynomials.
    pub(super) fn pcc(&mut self, variable: &str, p: &str, q: &str) -> Result<(), Failure> {
        let t = self.ctx.var(variable)?;
        if t == self.ctx.lambda || t == self.params.0 || t == self.params.1 || self.ctx.is_defined(t) {
            return Err(Failure::NotFree(variable.to_string()));
        }
        let (p, q) = (self.ctx.frac(p)?, self.ctx.frac(q)?);
        let params = [self.params.0, self.params.1];
        for f in [&p, &q] {
            let mut polys = vec![&f.num];
            for a in &f.den {
                polys.push(self.ctx.polynomial_atom(a)?);
            }
            let nv = self.ctx.nvars();
            if polys.iter().any(|x| (0..nv).any(|v| !params.contains(&v) && x.degree_in(v) > 0)) {
                return Err(Failure::PqVariables);
            }
        }
        let nv = self.ctx.nvars();
        let one = self.ctx.constant(F::one());
        let one_k2 = one.add(&Poly::var(nv, self.params.1)).pow(2);
        let n = self.model.n;
        let prod = super::model::mat_mul(&self.model.steps[n - 2], &self.model.steps[0]);
        let tv = Poly::var(nv, t);
        let char_m: PMat<F> = std::array::from_fn(|r| {
            std::array::from_fn(|c| {
                let diag = if r == c { one_k2.mul(&tv) } else { Poly::zero(nv) };
                diag.sub(&prod[r][c])
            })
        });
        let den = |f: &Frac<F>| -> Result<Poly<F>, Failure> {
            let mut acc = one.clone();
            for a in &f.den {
                acc = acc.try_mul(self.ctx.polynomial_atom(a)?)?;
            }
            Ok(acc)
        };
        let (dp, dq) = (den(&p)?, den(&q)?);
        let quad = tv
            .pow(2)
            .try_mul(&dp)?
            .try_mul(&dq)?
            .add(&p.num.try_mul(&dq)?.try_mul(&tv)?)
            .add(&q.num.try_mul(&dp)?);
        let rhs = one_k2.pow(3).try_mul(&tv.sub(&one))?.try_mul(&quad)?;
        if det(&char_m).try_mul(&dp)?.try_mul(&dq)? != rhs {
            return Err(Failure::NotPccFactorisation);
        }
        self.conclusions.push(format!(
            "det({variable} I - S_{} S_1) = ({variable} - 1)({variable}^2 + p {variable} + q) with p = {}, q = {}: the paper's Lemma on PCC excludes PCC where p^2 - 4q < 0 and q < 1",
            n - 1,
            short(self.ctx.text(&p)),
            short(self.ctx.text(&q))
        ));
        Ok(())
    }

    /// A polynomial with constants substituted, as univariate coefficients in `v`.
    fn univariate(
        &self,
        p: &Poly<F>,
        at: &BTreeMap<usize, F>,
        v: Option<usize>,
    ) -> Result<Coeffs<F>, Failure> {
        let p = at.iter().fold(p.clone(), |acc, (x, val)| acc.subst_constant(*x, val));
        let deg = v.map_or(0, |v| p.degree_in(v));
        let mut out = Vec::new();
        for d in 0..=deg {
            let c = v.map_or(p.clone(), |v| p.coeff_in(v, d));
            out.push(c.as_constant().ok_or(Failure::OtherVariables)?);
        }
        while out.last().is_some_and(F::is_zero) {
            out.pop();
        }
        Ok(out)
    }

    /// At a rational parameter point: a root count by a Sturm sequence, and positive values.
    pub(super) fn witness(
        &mut self,
        at: &[(String, String)],
        interval: &(String, String),
        sequence: &[String],
        roots: usize,
        positive: &[String],
    ) -> Result<(), Failure> {
        let mut point = BTreeMap::new();
        for (name, value) in at {
            let v = self.ctx.var(name)?;
            if v != self.params.0 && v != self.params.1 {
                return Err(Failure::NotParameter(name.clone()));
            }
            if point.insert(v, self.rational(value)?).is_some() {
                return Err(Failure::GivenTwice(name.clone()));
            }
        }
        let value = |c: &Coeffs<F>| c.first().cloned().unwrap_or_else(F::zero);
        let (lo, hi) = (self.rational(&interval.0)?, self.rational(&interval.1)?);
        // Every hypothesis holds at the point: those free of lambda there, those with lambda on the
        // whole interval (then every root of chi in it is a point of the region).
        let mut all_hold_on_interval = true;
        for h in &self.file.hypotheses {
            let p = self.ctx.poly(&h.expr)?;
            if p.degree_in(self.ctx.lambda) == 0 {
                if !value(&self.univariate(&p, &point, None)?).is_positive() {
                    return Err(Failure::HypothesisFails(h.expr.clone()));
                }
            } else {
                let on = self.univariate(&p, &point, Some(self.ctx.lambda))?;
                all_hold_on_interval &= positive_on(&on, &lo, &hi);
            }
        }
        let l = Some(self.ctx.lambda);
        let chi = self.univariate(&self.ctx.chi, &point, l)?;
        let seq = sequence
            .iter()
            .map(|s| self.univariate(&self.ctx.poly(s)?, &BTreeMap::new(), l))
            .collect::<Result<Vec<_>, _>>()?;
        let count = count_roots(&chi, &seq, &lo, &hi).map_err(Failure::Sturm)?;
        if count != roots {
            return Err(Failure::RootCount(count, roots));
        }
        let mut values = Vec::new();
        for e in positive {
            let f = self.ctx.frac(e)?;
            let num = value(&self.univariate(&f.num, &point, None)?);
            let mut den = F::one();
            for a in &f.den {
                den = den.times(&value(&self.univariate(self.ctx.polynomial_atom(a)?, &point, None)?));
            }
            let v = num.over(&den).ok_or(Failure::DenominatorVanishes)?;
            if !v.is_positive() {
                return Err(Failure::NotPositiveAt(e.clone()));
            }
            values.push(to_canonical(&v));
        }
        let at_text: Vec<String> = at.iter().map(|(n, v)| format!("{n} = {v}")).collect();
        let values = if values.is_empty() {
            String::new()
        } else {
            format!("; the expressions listed are positive there: {}", values.join(", "))
        };
        self.conclusions.push(format!(
            "at {}: chi has {roots} root(s) in ({}, {}]{values}",
            at_text.join(", "),
            interval.0,
            interval.1
        ));
        if roots > 0 && all_hold_on_interval && !self.nonempty {
            self.nonempty = true;
            self.conclusions.push(format!(
                "the region is not empty: every hypothesis holds at {} with lambda any of these roots, so the conclusions are not vacuous",
                at_text.join(", ")
            ));
        }
        Ok(())
    }
}
