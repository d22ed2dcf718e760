//! The producer's side of a proof: a builder that writes steps for the kernel's proof checker
//! (chatter_kernel::proof). It keeps the same algebra as the checker (the kernel's `Context`, so
//! that expressions are equal as the checker will test them) and checks every certificate as it
//! writes it, so that a producer bug shows up here, with the step, before the checker runs.

use super::cert::{Cert, LinearVars, linear};
use crate::exact::{ParseLimits, Q, Ring};
use chatter_kernel::proof::{
    Context, Eigenvalue, Frac, Hypothesis, Parameters, Poly, ProofBody, ProofFile, Step, SymbolicModel,
};
use std::cmp::Ordering;
use std::collections::BTreeMap;

/// A point of the plane v = -1, as expressions.
pub type Point = [Frac<Q>; 3];

/// One section of the readable account: a lemma's title and what it states.
#[derive(Clone, Debug)]
pub struct Section {
    pub title: String,
    pub steps: Vec<usize>,
}

/// The header of a proof about a regular polygon.
pub struct Header {
    pub name: String,
    pub statement: String,
    pub n: u64,
    pub variables: Vec<&'static str>,
    pub gamma: &'static str,
    pub kappa: &'static str,
    pub lambda: &'static str,
    pub map: u64,
    pub coordinates: [[i64; 3]; 3],
    pub hypotheses: Vec<(&'static str, &'static str)>,
}

/// A proof under construction.
pub struct Builder {
    pub header: Header,
    pub ctx: Context<Q>,
    pub model: SymbolicModel<Q>,
    pub points: BTreeMap<String, Point>,
    pub steps: Vec<Step>,
    /// A sentence for each step, for the readable account.
    pub notes: Vec<String>,
    pub sections: Vec<Section>,
    /// Producer-side failures (a bug in the producer): step id and reason.
    pub problems: Vec<(String, String)>,
    chi: Poly<Q>,
}

fn names(h: &Header) -> Vec<String> {
    h.variables.iter().map(|s| s.to_string()).collect()
}

impl Builder {
    /// A builder; `chi` must be (kappa + 1) det(lambda I - S_map) in the given coordinates.
    pub fn new(header: Header, chi: Poly<Q>) -> Builder {
        let nm = names(&header);
        let idx = |v: &str| nm.iter().position(|x| x == v).expect("declared variable");
        let m = header.coordinates.map(|r| r.map(Q::int));
        let model = SymbolicModel::new(header.n, nm.len(), idx(header.gamma), idx(header.kappa), &m)
            .expect("a regular polygon with rational cosines");
        let mut ctx = Context::new(nm.clone(), ParseLimits::default(), idx(header.lambda), chi.clone());
        for (name, expr) in &header.hypotheses {
            ctx.add_atom(name, Frac::poly(ctx.poly(expr).expect("hypothesis"))).expect("distinct hypotheses");
        }
        Builder {
            header,
            ctx,
            model,
            points: BTreeMap::new(),
            steps: Vec::new(),
            notes: Vec::new(),
            sections: Vec::new(),
            problems: Vec::new(),
            chi,
        }
    }

    /// `a + b` (the producer's expressions are far inside the kernel's size limits).
    pub fn add(&self, a: &Frac<Q>, b: &Frac<Q>) -> Frac<Q> {
        self.ctx.add(a, b).expect("producer: within the size limits")
    }

    /// `a b`.
    pub fn mul(&self, a: &Frac<Q>, b: &Frac<Q>) -> Frac<Q> {
        self.ctx.mul(a, b).expect("producer: within the size limits")
    }

    /// `a . b`.
    pub fn dot(&self, a: &Point, b: &Point) -> Frac<Q> {
        self.ctx.dot(a, b).expect("producer: within the size limits")
    }

    /// `m p`.
    pub fn apply(&self, m: &chatter_kernel::proof::PMat<Q>, p: &Point) -> Point {
        self.ctx.image(m, p).expect("producer: within the size limits")
    }

    /// Whether `a = b` on the region.
    pub fn equal(&self, a: &Frac<Q>, b: &Frac<Q>) -> bool {
        self.ctx.equal(a, b).expect("producer: within the size limits")
    }

    /// Whether `a = 0` on the region.
    pub fn is_zero(&self, a: &Frac<Q>) -> bool {
        self.ctx.is_zero(a).expect("producer: within the size limits")
    }

    /// The index of a variable.
    pub fn var(&self, name: &str) -> usize {
        self.ctx.var(name).expect("declared variable")
    }

    /// A polynomial from canonical text (the producer's own, so it must parse).
    pub fn poly(&self, text: &str) -> Poly<Q> {
        self.ctx.poly(text).unwrap_or_else(|e| panic!("producer: {e}"))
    }

    /// An expression from text written by hand: `N` or `(N) / [a] [b]`, the terms of N in any
    /// order (see [`super::terms::lenient`]).
    pub fn frac(&self, text: &str) -> Frac<Q> {
        let (num, den) = match text.strip_prefix('(').and_then(|r| r.split_once(") / ")) {
            Some((n, d)) => {
                (n, d.split(' ').map(|a| a.trim_matches(|c| c == '[' || c == ']').to_string()).collect())
            }
            None => (text, Vec::new()),
        };
        Frac { num: super::terms::lenient(num, &self.ctx.names), den }
    }

    /// The canonical text of an expression.
    pub fn text(&self, f: &Frac<Q>) -> String {
        self.ctx.text(f)
    }

    /// The variables the linear method reads.
    pub fn linear_vars(&self) -> LinearVars {
        LinearVars { l: self.var("l"), e1: self.var("e1"), e2: self.var("e2") }
    }

    /// Starts a section of the readable account.
    pub fn section(&mut self, title: &str) {
        self.sections.push(Section { title: title.to_string(), steps: Vec::new() });
    }

    fn push(&mut self, step: Step, note: String) {
        if let Some(s) = self.sections.last_mut() {
            s.steps.push(self.steps.len());
        }
        self.steps.push(step);
        self.notes.push(note);
    }

    fn problem(&mut self, id: &str, why: String) {
        self.problems.push((id.to_string(), why));
    }

    /// `expr > 0` with its certificate; the step becomes the atom `id`.
    pub fn positive(&mut self, id: &str, expr: &Frac<Q>, cert: &Cert, note: &str) {
        let mut sum: Option<Frac<Q>> = None;
        for (c, atoms) in &cert.terms {
            let mut t = Frac::poly(self.ctx.constant(c.clone()));
            for a in atoms {
                match self.ctx.atom(a) {
                    Ok(x) => t = self.mul(&t, x),
                    Err(e) => return self.problem(id, e.to_string()),
                }
            }
            sum = Some(sum.map_or(t.clone(), |s| self.add(&s, &t)));
        }
        let mut c = sum.unwrap_or_else(|| Frac::poly(self.ctx.constant(Q::int(0))));
        c.den.extend(cert.over.iter().cloned());
        if !self.equal(expr, &c) {
            self.problem(id, format!("{} differs from its certificate", self.text(expr)));
        }
        let _ = self.ctx.add_atom(id, expr.clone());
        let step = Step::Positive {
            id: id.into(),
            expr: self.text(expr),
            terms: cert.text_terms(),
            over: cert.over.clone(),
        };
        self.push(step, note.to_string());
    }

    /// `lhs = rhs` at every point of the region.
    pub fn identity(&mut self, id: &str, lhs: &Frac<Q>, rhs: &Frac<Q>, note: &str) {
        if !self.equal(lhs, rhs) {
            self.problem(id, "the identity does not hold".into());
        }
        self.push(Step::Identity { id: id.into(), lhs: self.text(lhs), rhs: self.text(rhs) }, note.into());
    }

    /// Defines a variable.
    pub fn define(&mut self, id: &str, num: &Poly<Q>, den: &Poly<Q>, positive: Option<&str>, note: &str) {
        let v = self.var(id);
        let params = [self.var(self.header.gamma), self.var(self.header.kappa)];
        if let Err(e) = self.ctx.define(v, num.clone(), den.clone(), &params) {
            self.problem(id, e.to_string());
        }
        let nm = &self.ctx.names;
        let step = Step::Define {
            id: id.into(),
            num: num.text(nm),
            den: den.text(nm),
            positive: positive.map(str::to_string),
        };
        self.push(step, note.into());
    }

    /// Names the point (x, y, -1).
    pub fn point(&mut self, id: &str, x: &Frac<Q>, y: &Frac<Q>) {
        let p = [x.clone(), y.clone(), Frac::poly(self.ctx.constant(Q::int(-1)))];
        self.points.insert(id.into(), p);
        let note = format!("{id} = ({}, {})", self.text(x), self.text(y));
        self.push(Step::Point { id: id.into(), x: self.text(x), y: self.text(y) }, note);
    }

    /// A named point.
    pub fn pt(&self, name: &str) -> &Point {
        self.points.get(name).unwrap_or_else(|| panic!("producer: unknown point {name}"))
    }

    /// The model's map by name ("S1", ..., "I0").
    pub fn map(&self, name: &str) -> &chatter_kernel::proof::PMat<Q> {
        match name.strip_prefix('S') {
            Some(j) => &self.model.steps[j.parse::<usize>().expect("S<j>") - 1],
            None => &self.model.impact,
        }
    }

    /// `map(point) = sum c_i w_i`, both sides scaled by 1 + kappa.
    pub fn image(&mut self, id: &str, map: &str, point: &str, equals: &[(Frac<Q>, &str)], note: &str) {
        let img = self.apply(self.map(map), self.pt(point));
        let one_k = Frac::poly(self.poly("k + 1"));
        let zero = Frac::poly(self.ctx.constant(Q::int(0)));
        let mut sum = [zero.clone(), zero.clone(), zero];
        for (c, w) in equals {
            let c = self.mul(&one_k, c);
            let w = self.pt(w).clone();
            sum = std::array::from_fn(|i| self.add(&sum[i], &self.mul(&c, &w[i])));
        }
        if !(0..3).all(|i| self.equal(&img[i], &sum[i])) {
            self.problem(id, format!("{map} {point} is not the combination given"));
        }
        let equals = equals.iter().map(|(c, w)| (self.text(c), w.to_string())).collect();
        self.push(Step::Image { id: id.into(), map: map.into(), point: point.into(), equals }, note.into());
    }

    /// Writes a sign step for `e` under `key` when the checker needs one (not zero, not a
    /// constant), by the linear method; returns the sign.
    pub fn sign_step(&mut self, key: &str, e: &Frac<Q>) -> Ordering {
        if self.is_zero(e) {
            return Ordering::Equal;
        }
        if let Some(c) = e.num.as_constant() {
            return c.sign();
        }
        let Some((sign, cert)) = linear(e, self.linear_vars()) else {
            self.problem(key, format!("no linear sign certificate for {}", self.text(e)));
            return Ordering::Equal;
        };
        let f = if sign == Ordering::Less { e.neg() } else { e.clone() };
        self.positive(key, &f, &cert, "");
        sign
    }

    /// Any other step (rules and root facts), with its note.
    pub fn raw(&mut self, step: Step, note: &str) {
        self.push(step, note.into());
    }

    /// The proof file.
    pub fn finish(&self) -> ProofFile {
        let h = &self.header;
        ProofFile {
            format: chatter_kernel::proof::FORMAT.into(),
            version: chatter_kernel::proof::VERSION,
            name: h.name.clone(),
            statement: h.statement.clone(),
            body: ProofBody::RegularPolygon { n: h.n },
            parameters: Parameters { gamma: h.gamma.into(), kappa: h.kappa.into() },
            variables: names(h),
            coordinates: h.coordinates.map(|r| r.map(|x| x.to_string())),
            eigenvalue: Eigenvalue {
                variable: h.lambda.into(),
                map: h.map,
                chi: self.chi.text(&self.ctx.names),
            },
            hypotheses: h
                .hypotheses
                .iter()
                .map(|(n, e)| Hypothesis { name: n.to_string(), expr: e.to_string() })
                .collect(),
            steps: self.steps.clone(),
        }
    }
}
