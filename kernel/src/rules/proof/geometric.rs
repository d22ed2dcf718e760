//! The geometric rules. They carry no verdict: the checker computes the model's maps and cones
//! (in the proof's coordinates), runs the certificate kernel's clipping on named points, and
//! requires, for every sign it needs, either an exact zero, a non-zero constant, or the step
//! with the key it names (a `Positive` step proving the expression or its negative).

use super::check::Checker;
use super::clip::{Oracle, Point, clip, parallel};
use super::context::Frac;
use super::failure::Failure;
use crate::exact::Field;
use std::cmp::Ordering;

/// The checker's oracle: signs from the steps with the keys `{key}.{point}`, crossings from the
/// list in the step, each checked to be parallel to the crossing computed.
struct Lookup<'c, 'a, 'i, F> {
    checker: &'c Checker<'a, F>,
    key: String,
    crossings: &'c mut std::slice::Iter<'i, String>,
}

impl<F: Field> Oracle<F> for Lookup<'_, '_, '_, F> {
    fn sign(&mut self, point: &str, value: &Frac<F>) -> Result<Ordering, Failure> {
        self.checker.sign_of(&format!("{}.{point}", self.key), value)
    }

    fn crossing(&mut self, x: &Point<F>, from: &str, to: &str) -> Result<String, Failure> {
        let w = self.crossings.next().ok_or(Failure::FewerCrossings)?;
        if parallel(&self.checker.ctx, x, self.checker.named(w)?)? {
            Ok(w.clone())
        } else {
            Err(Failure::NotTheCrossing(from.to_string(), to.to_string(), self.key.clone(), w.clone()))
        }
    }

    fn point(&self, name: &str) -> Result<&Point<F>, Failure> {
        self.checker.named(name)
    }
}

/// A cone declared by a `Cone` step: vertices (named points) and facets (name, covector).
pub struct ConeDecl<F> {
    vertices: Vec<String>,
    facets: Vec<(String, [Frac<F>; 3])>,
}

impl<F: Field> Checker<'_, F> {
    fn named(&self, p: &str) -> Result<&[Frac<F>; 3], Failure> {
        self.points.get(p).ok_or_else(|| Failure::UnknownPoint(p.to_string()))
    }

    /// The sign of `e`: zero, a constant, or proved by the `Positive` step `key`.
    pub(super) fn sign_of(&self, key: &str, e: &Frac<F>) -> Result<Ordering, Failure> {
        if self.ctx.is_zero(e)? {
            return Ok(Ordering::Equal);
        }
        if let Some(c) = e.num.as_constant() {
            return Ok(c.sign()); // the denominator is a product of positive atoms
        }
        let atom = self.ctx.atom(key).map_err(|_| Failure::NoStep(key.to_string(), self.ctx.text(e)))?;
        if self.ctx.equal(atom, e)? {
            Ok(Ordering::Greater)
        } else if self.ctx.equal(atom, &e.neg())? {
            Ok(Ordering::Less)
        } else {
            Err(Failure::StepDoesNotProve(key.to_string(), self.ctx.text(e)))
        }
    }

    /// Requires `e >= 0` (by `sign_of`).
    fn non_negative(&self, key: &str, e: &Frac<F>) -> Result<(), Failure> {
        match self.sign_of(key, e)? {
            Ordering::Less => Err(Failure::Negative(self.ctx.text(e), key.to_string())),
            _ => Ok(()),
        }
    }

    /// `map(point) = sum of c_i w_i` (maps scaled by 1 + kappa on both sides).
    pub(super) fn image_step(
        &mut self,
        map: &str,
        point: &str,
        equals: &[(String, String)],
    ) -> Result<(), Failure> {
        let m = match (1..self.model.n).find(|j| map == format!("S{j}")) {
            Some(j) => &self.model.steps[j - 1],
            None if map == "I0" => &self.model.impact,
            None => return Err(Failure::NotAMap(map.to_string(), self.model.n)),
        };
        let img = self.ctx.image(m, self.named(point)?)?;
        let nv = self.ctx.nvars();
        let one_k = Frac::poly(self.ctx.constant(F::one()).add(&super::poly::Poly::var(nv, self.params.1)));
        let zero = Frac::poly(super::poly::Poly::zero(nv));
        let mut sum = [zero.clone(), zero.clone(), zero];
        for (c, w) in equals {
            let c = self.ctx.mul(&one_k, &self.ctx.frac(c)?)?;
            let w = self.named(w)?;
            for i in 0..3 {
                sum[i] = self.ctx.add(&sum[i], &self.ctx.mul(&c, &w[i])?)?;
            }
        }
        for i in 0..3 {
            if !self.ctx.equal(&img[i], &sum[i])? {
                return Err(Failure::NotCombination(map.to_string(), point.to_string()));
            }
        }
        Ok(())
    }

    /// A cone over a polygon of named points, with its facets.
    pub(super) fn cone(
        &mut self,
        id: &str,
        vertices: &[String],
        facets: &[(String, [String; 3])],
    ) -> Result<(), Failure> {
        let m = vertices.len();
        if m < 3 || facets.len() != m {
            return Err(Failure::ConeShape);
        }
        let distinct = |names: Vec<&String>| {
            names.iter().collect::<std::collections::BTreeSet<_>>().len() == names.len()
        };
        if !distinct(vertices.iter().collect()) || !distinct(facets.iter().map(|f| &f.0).collect()) {
            return Err(Failure::NotDistinct);
        }
        if facets.iter().any(|f| f.0.is_empty() || f.0.contains(['.', ' '])) {
            return Err(Failure::FacetName);
        }
        let mut fs = Vec::with_capacity(m);
        for (name, cov) in facets {
            fs.push((
                name.clone(),
                [self.ctx.frac(&cov[0])?, self.ctx.frac(&cov[1])?, self.ctx.frac(&cov[2])?],
            ));
        }
        for (i, (name, f)) in fs.iter().enumerate() {
            for (k, v) in vertices.iter().enumerate() {
                let value = self.ctx.dot(f, self.named(v)?)?;
                let on_edge = k == i || k == (i + 1) % m;
                if on_edge && !self.ctx.is_zero(&value)? {
                    return Err(Failure::FacetNotZero(name.clone(), v.clone(), i));
                }
                if !on_edge && !self.sign_of(&format!("{id}.{name}.{v}"), &value)?.is_gt() {
                    return Err(Failure::FacetNotPositive(name.clone(), v.clone()));
                }
            }
        }
        if self.cones.insert(id.to_string(), ConeDecl { vertices: vertices.to_vec(), facets: fs }).is_some() {
            return Err(Failure::DuplicateCone(id.to_string()));
        }
        Ok(())
    }

    /// S_j(K ∩ C_j) ⊆ K.
    pub(super) fn invariant(&mut self, cone: &str, j: u64, crossings: &[String]) -> Result<(), Failure> {
        let k = self.cones.get(cone).ok_or_else(|| Failure::UnknownCone(cone.to_string()))?;
        if j == 0 || j as usize >= self.model.n {
            return Err(Failure::NoMap(j, self.model.n));
        }
        let mut poly = k.vertices.clone();
        let mut it = crossings.iter();
        for (m, l) in self.model.cones[j as usize - 1].iter().enumerate() {
            let mut oracle = Lookup { checker: self, key: format!("{cone}.C{j}.h{m}"), crossings: &mut it };
            poly = clip(&self.ctx, &poly, &l.clone().map(Frac::poly), &mut oracle)?;
        }
        if let Some(w) = it.next() {
            return Err(Failure::CrossingNeverCreated(w.clone()));
        }
        let s = &self.model.steps[j as usize - 1];
        for w in &poly {
            let img = self.ctx.image(s, self.named(w)?)?;
            for (name, f) in &k.facets {
                self.non_negative(&format!("{cone}.S{j}.{w}.{name}"), &self.ctx.dot(f, &img)?)?;
            }
        }
        self.conclusions.push(format!(
            "S_{j}({cone} ∩ C_{j}) ⊆ {cone}: {cone} ∩ C_{j} is the polygon {}, and every facet is non-negative on the images",
            poly.join(", ")
        ));
        self.invariant.entry(cone.to_string()).or_default().insert(j);
        Ok(())
    }

    /// I_0(D) ⊆ K.
    pub(super) fn all_down(&mut self, cone: &str) -> Result<(), Failure> {
        let k = self.cones.get(cone).ok_or_else(|| Failure::UnknownCone(cone.to_string()))?;
        for (m, g) in self.model.all_down.iter().enumerate() {
            let img = self.ctx.image(&self.model.impact, &g.clone().map(Frac::poly))?;
            for (name, f) in &k.facets {
                self.non_negative(&format!("{cone}.I0.{m}.{name}"), &self.ctx.dot(f, &img)?)?;
            }
        }
        self.conclusions.push(format!(
            "I_0(D) ⊆ {cone}: every drop with all contacts moving down has its velocity after the first impact in {cone}"
        ));
        Ok(())
    }
}
