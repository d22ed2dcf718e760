//! A small proof checker: every step is an exact identity (modulo chi), a positivity
//! certificate (a positive combination of products of atoms, each atom proved positive by an
//! earlier step), or a fact derived from earlier steps. Failed steps are recorded, not hidden.

use super::mpoly::{E1, E2, MPoly};
use super::ratfn::{RatFn, zero_mod_chi};
use crate::exact::Q;
use serde::Serialize;

/// One checked step.
#[derive(Clone, Debug, Serialize)]
pub struct Step {
    pub id: String,
    pub lemma: String,
    pub statement: String,
    pub method: String,
    /// Named expressions involved, as text.
    pub expressions: Vec<(String, String)>,
    /// Steps this one relies on.
    pub uses: Vec<String>,
    pub ok: bool,
    /// Why it failed, or extra information.
    pub detail: String,
}

/// An expression proved positive on the region, usable in later certificates.
#[derive(Clone, Debug)]
pub struct Atom {
    pub name: String,
    pub expr: RatFn,
    pub step: String,
}

/// A term c * prod of atoms (names repeated for powers).
pub type Term<'a> = (Q, &'a [&'a str]);

/// The proof under construction.
pub struct Proof {
    pub steps: Vec<Step>,
    atoms: Vec<Atom>,
    chi: MPoly,
    /// e1 and e2 as rational functions in (g, k, l), substituted for the formal variables.
    e1: RatFn,
    e2: RatFn,
    lemma: String,
}

impl Proof {
    pub fn new(chi: MPoly, e1: RatFn, e2: RatFn) -> Self {
        Proof { steps: Vec::new(), atoms: Vec::new(), chi, e1, e2, lemma: String::new() }
    }

    pub fn lemma(&mut self, name: &str) {
        self.lemma = name.to_string();
    }

    pub fn chi(&self) -> &MPoly {
        &self.chi
    }

    /// Replaces the formal e1, e2 by their definitions.
    pub fn concrete(&self, e: &RatFn) -> RatFn {
        e.subst(E1, &self.e1).subst(E2, &self.e2)
    }

    /// Records a step (its lemma is the current one) and returns whether it checked.
    fn push(&mut self, mut step: Step) -> bool {
        step.lemma = self.lemma.clone();
        let ok = step.ok;
        self.steps.push(step);
        ok
    }

    fn step(id: &str, statement: &str, method: &str, uses: &[&str]) -> Step {
        Step {
            id: id.into(),
            lemma: String::new(),
            statement: statement.into(),
            method: method.into(),
            expressions: Vec::new(),
            uses: uses.iter().map(|s| s.to_string()).collect(),
            ok: false,
            detail: String::new(),
        }
    }

    /// A hypothesis or definition (recorded, nothing to check).
    pub fn assume(&mut self, id: &str, statement: &str) {
        self.push(Step { ok: true, ..Self::step(id, statement, "hypothesis", &[]) });
    }

    /// Registers an atom proved positive by step `step` (which must have succeeded).
    pub fn atom(&mut self, name: &str, expr: RatFn, step: &str) {
        let ok = self.steps.iter().any(|s| s.id == step && s.ok);
        if ok {
            self.atoms.push(Atom { name: name.into(), expr, step: step.into() });
        }
    }

    fn atom_expr(&self, name: &str) -> Option<&Atom> {
        self.atoms.iter().find(|a| a.name == name)
    }

    /// lhs = rhs exactly (as rational functions), or at every root of chi when `modulo_chi`.
    pub fn identity(
        &mut self,
        id: &str,
        statement: &str,
        lhs: &RatFn,
        rhs: &RatFn,
        modulo_chi: bool,
        uses: &[&str],
    ) -> bool {
        let diff = self.concrete(&lhs.sub(rhs));
        let (ok, method) = if modulo_chi {
            (
                zero_mod_chi(&diff, &self.chi),
                "identity modulo chi(lambda): pseudo-remainder in lambda is zero",
            )
        } else {
            (diff.is_zero(), "identity of rational functions")
        };
        let detail = if ok { String::new() } else { format!("the difference is {diff}, not zero") };
        let expressions = vec![("lhs".into(), lhs.to_string()), ("rhs".into(), rhs.to_string())];
        self.push(Step { expressions, ok, detail, ..Self::step(id, statement, method, uses) })
    }

    /// expr > 0 on the region, by the certificate expr = sum c_i prod(atoms_i) / prod(den) with
    /// every c_i > 0 (checked exactly modulo chi). The atoms' own steps are cited.
    pub fn positive(
        &mut self,
        id: &str,
        statement: &str,
        expr: &RatFn,
        terms: &[Term<'_>],
        den: &[&str],
        uses: &[&str],
    ) -> bool {
        let mut cited: Vec<String> = uses.iter().map(|s| s.to_string()).collect();
        let mut missing = Vec::new();
        let mut product = |names: &[&str]| -> RatFn {
            names.iter().fold(RatFn::int(1), |acc, n| match self.atom_expr(n) {
                Some(a) => {
                    if !cited.contains(&a.step) {
                        cited.push(a.step.clone());
                    }
                    acc.mul(&a.expr)
                }
                None => {
                    missing.push(n.to_string());
                    acc
                }
            })
        };
        let mut sum = RatFn::int(0);
        let mut text = Vec::new();
        for (c, names) in terms {
            sum = sum.add(&product(names).mul(&RatFn::q(c.clone())));
            text.push(if names.is_empty() { c.to_string() } else { format!("{c}*{}", names.join("*")) });
        }
        let d = product(den);
        let cert = sum.div(&d);
        let signs_ok = !terms.is_empty() && terms.iter().all(|(c, _)| *c > Q::int(0));
        let identity_ok = missing.is_empty() && zero_mod_chi(&self.concrete(&expr.sub(&cert)), &self.chi);
        let ok = signs_ok && identity_ok;
        let den_text = if den.is_empty() { String::new() } else { format!(" / ({})", den.join("*")) };
        let method = format!(
            "positive combination of atoms: ({}){den_text}, identity checked modulo chi",
            text.join(" + ")
        );
        let detail = if !missing.is_empty() {
            format!("unknown atoms {missing:?}")
        } else if !signs_ok {
            "a coefficient is not positive".into()
        } else if !identity_ok {
            "the certificate does not equal the expression".into()
        } else {
            String::new()
        };
        let expressions = vec![("expression".into(), expr.to_string())];
        let uses: Vec<&str> = cited.iter().map(String::as_str).collect();
        self.push(Step { expressions, ok, detail, ..Self::step(id, statement, &method, &uses) })
    }

    /// A fact that follows from earlier steps by the stated argument; `ok` is the result of the
    /// caller's exact check (e.g. all cited steps succeeded and a combinatorial match held).
    pub fn fact(
        &mut self,
        id: &str,
        statement: &str,
        method: &str,
        ok: bool,
        detail: String,
        uses: &[&str],
    ) -> bool {
        let cited_ok = uses.iter().all(|u| self.steps.iter().any(|s| s.id == *u && s.ok));
        let detail = if cited_ok { detail } else { format!("a cited step failed; {detail}") };
        self.push(Step { ok: ok && cited_ok, detail, ..Self::step(id, statement, method, uses) })
    }

    pub fn all_ok(&self) -> bool {
        self.steps.iter().all(|s| s.ok)
    }
}
