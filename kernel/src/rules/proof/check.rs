//! The proof checker's driver: the header (variables, coordinates, chi against the model,
//! hypotheses), then every step in order. The first failing step is reported with its locus.

use super::context::{Context, Frac, MAX_VARIABLES};
use super::failure::Failure;
use super::geometric::ConeDecl;
use super::model::{PMat, SymbolicModel, det};
use super::poly::Poly;
use crate::exact::{Field, ParseLimits, parse_canonical};
use crate::model::linalg::{Mat3, det3};
use crate::reject::{Code, KindDetail, KindLocus, Rejection};
use crate::syntax::numbers::in_time;
use crate::syntax::proof::{ProofBody, ProofFile, Step};
use crate::syntax::{Kind, expect};
use std::collections::{BTreeMap, BTreeSet};

/// What a checked proof established.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Checked {
    /// The proof's name.
    pub name: String,
    /// Number of steps checked.
    pub steps: usize,
    /// The hypotheses, e.g. "g > 0", and the eigenvalue assumption.
    pub hypotheses: Vec<String>,
    /// What the rules established, in order.
    pub conclusions: Vec<String>,
    /// Whether a `Witness` showed that the region is not empty (else every conclusion may be
    /// vacuous, e.g. under contradictory hypotheses).
    pub nonempty: bool,
}

/// The checker's state.
pub(super) struct Checker<'a, F> {
    pub ctx: Context<F>,
    pub model: SymbolicModel<F>,
    pub file: &'a ProofFile,
    /// Indices of gamma and kappa.
    pub params: (usize, usize),
    pub points: BTreeMap<String, [Frac<F>; 3]>,
    pub cones: BTreeMap<String, ConeDecl<F>>,
    /// For each cone, the maps j with S_j(K ∩ C_j) ⊆ K established.
    pub invariant: BTreeMap<String, BTreeSet<u64>>,
    pub conclusions: Vec<String>,
    /// Whether a witness showed the region to be non-empty.
    pub nonempty: bool,
}

/// A failure of the header at `path` (`invalid-header`).
fn header_error(path: &str, f: Failure) -> Rejection {
    Rejection::at(Code::InvalidHeader, path, KindDetail::Proof(f))
}

/// M, p_model = M p_proof: invertible, with third row (0, 0, 1).
fn coordinates<F: Field>(rows: &[[String; 3]; 3], limits: ParseLimits) -> Result<Mat3<F>, Failure> {
    let mut m: Mat3<F> = std::array::from_fn(|_| std::array::from_fn(|_| F::zero()));
    for (r, row) in rows.iter().enumerate() {
        for (c, x) in row.iter().enumerate() {
            m[r][c] = parse_canonical(x, limits).map_err(|e| Failure::Number(x.clone(), e))?;
        }
    }
    if m[2] != [F::zero(), F::zero(), F::one()] {
        return Err(Failure::ThirdRow);
    }
    if det3(&m[0], &m[1], &m[2]).is_zero() {
        return Err(Failure::Singular);
    }
    Ok(m)
}

impl<'a, F: Field> Checker<'a, F> {
    /// Reads the header and builds the model.
    fn new(file: &'a ProofFile, limits: ParseLimits) -> Result<Self, Rejection> {
        expect(&file.format, file.version, Kind::Proof)?;
        let names = file.variables.clone();
        let distinct: BTreeSet<&String> = names.iter().collect();
        let good = |n: &String| {
            n.chars().next().is_some_and(|c| c.is_ascii_alphabetic())
                && n.chars().all(|c| c.is_ascii_alphanumeric())
        };
        if names.len() > MAX_VARIABLES {
            return Err(header_error("variables", Failure::TooManyVariables));
        }
        if distinct.len() != names.len() || !names.iter().all(good) {
            return Err(header_error("variables", Failure::BadVariables));
        }
        let var = |path: &str, n: &str| {
            names
                .iter()
                .position(|x| x == n)
                .ok_or_else(|| header_error(path, Failure::NotAVariable(n.to_string())))
        };
        let gamma = var("parameters.gamma", &file.parameters.gamma)?;
        let kappa = var("parameters.kappa", &file.parameters.kappa)?;
        let lambda = var("eigenvalue.variable", &file.eigenvalue.variable)?;
        if gamma == kappa || lambda == gamma || lambda == kappa {
            return Err(header_error("parameters", Failure::SameParameters));
        }
        let m = coordinates::<F>(&file.coordinates, limits).map_err(|e| header_error("coordinates", e))?;
        let ProofBody::RegularPolygon { n } = file.body;
        let model =
            SymbolicModel::new(n, names.len(), gamma, kappa, &m).map_err(|e| header_error("body.n", e))?;
        let chi = Poly::parse(&file.eigenvalue.chi, &names, limits)
            .map_err(|e| header_error("eigenvalue.chi", e))?;
        let ctx = Context::new(names, limits, lambda, chi);
        let mut c = Checker {
            ctx,
            model,
            file,
            params: (gamma, kappa),
            points: BTreeMap::new(),
            cones: BTreeMap::new(),
            invariant: BTreeMap::new(),
            conclusions: Vec::new(),
            nonempty: false,
        };
        c.eigenvalue().map_err(|e| header_error("eigenvalue", e))?;
        c.hypotheses()?;
        // lc(chi) in lambda is 1 + kappa (the eigenvalue check), positive (kappa > 0 is a
        // hypothesis): pseudo-remainders by chi decide identities at every root.
        Ok(c)
    }

    /// chi is (kappa + 1) det(lambda I - S_map): (1 + kappa)^2 chi = det((1 + kappa) lambda I - (1 + kappa) S_map).
    fn eigenvalue(&self) -> Result<(), Failure> {
        let j = self.file.eigenvalue.map;
        if j == 0 || j as usize >= self.model.n {
            return Err(Failure::NoMap(j, self.model.n));
        }
        let nv = self.ctx.nvars();
        let one_k = Poly::constant(nv, F::one()).add(&Poly::var(nv, self.params.1));
        let l = Poly::var(nv, self.ctx.lambda);
        let s = &self.model.steps[j as usize - 1];
        let char_m: PMat<F> = std::array::from_fn(|r| {
            std::array::from_fn(|c| {
                let diag = if r == c { one_k.mul(&l) } else { Poly::zero(nv) };
                diag.sub(&s[r][c])
            })
        });
        if det(&char_m) != one_k.pow(2).mul(&self.ctx.chi) {
            return Err(Failure::NotCharacteristic(j));
        }
        Ok(())
    }

    /// The hypotheses: polynomials in gamma, kappa and lambda only (a hypothesis about a variable
    /// defined later would constrain the definition), one of them kappa itself (the maps are
    /// scaled by 1 + kappa, which must be positive).
    fn hypotheses(&mut self) -> Result<(), Rejection> {
        let allowed = [self.params.0, self.params.1, self.ctx.lambda];
        let mut kappa_positive = false;
        for (i, h) in self.file.hypotheses.iter().enumerate() {
            let path = format!("hypotheses[{i}]");
            let p = self.ctx.poly(&h.expr).map_err(|e| header_error(&path, e))?;
            if let Some(v) = (0..self.ctx.nvars()).find(|v| !allowed.contains(v) && p.degree_in(*v) > 0) {
                return Err(header_error(&path, Failure::HypothesisVariable(self.ctx.names[v].clone())));
            }
            kappa_positive |= p == Poly::var(self.ctx.nvars(), self.params.1);
            if self.ctx.is_zero(&Frac::poly(p.clone())).map_err(|e| header_error(&path, e))? {
                return Err(header_error(&path, Failure::HypothesisVanishes));
            }
            self.ctx.add_atom(&h.name, Frac::poly(p)).map_err(|e| header_error(&path, e))?;
        }
        if !kappa_positive {
            return Err(header_error("hypotheses", Failure::KappaHypothesis));
        }
        Ok(())
    }

    /// The hypotheses as text.
    fn hypothesis_text(&self) -> Vec<String> {
        let mut out: Vec<String> = self.file.hypotheses.iter().map(|h| format!("{} > 0", h.expr)).collect();
        out.push(format!(
            "{} is a root of chi = {} (kappa + 1 times the characteristic polynomial of S_{})",
            self.file.eigenvalue.variable, self.file.eigenvalue.chi, self.file.eigenvalue.map
        ));
        out
    }

    fn step(&mut self, s: &Step) -> Result<(), Failure> {
        match s {
            Step::Positive { id, expr, terms, over } => self.positive(id, expr, terms, over),
            Step::Identity { lhs, rhs, .. } => self.identity(lhs, rhs),
            Step::Define { id, num, den, positive } => self.define(id, num, den, positive.as_deref()),
            Step::Point { id, x, y } => self.point(id, x, y),
            Step::Image { map, point, equals, .. } => self.image_step(map, point, equals),
            Step::RootBound { id, below, variable } => self.root_bound(id, below, variable),
            Step::Cone { id, vertices, facets } => self.cone(id, vertices, facets),
            Step::Invariant { cone, map, crossings, .. } => self.invariant(cone, *map, crossings),
            Step::AllDown { cone, .. } => self.all_down(cone),
            Step::Pcc { variable, p, q, .. } => self.pcc(variable, p, q),
            Step::Witness { at, interval, sequence, roots, positive, .. } => {
                self.witness(at, interval, sequence, *roots, positive)
            }
        }
    }

    /// The conclusions about effective invariance, once every map has been checked.
    fn summary(&mut self) {
        let n = self.model.n as u64;
        for (cone, maps) in &self.invariant {
            if (1..n).all(|j| maps.contains(&j)) {
                self.conclusions.push(format!(
                    "{cone} satisfies conditions 1 and 2 of the paper's Theorem on effectively invariant cones (v <= 0 on {cone}, S_j({cone} ∩ C_j) ⊆ {cone} for j = 1..{})",
                    n - 1
                ));
            }
        }
    }
}

/// Checks a proof exactly over the field `F`; the first failing step is reported.
pub fn check<F: Field>(file: &ProofFile, limits: ParseLimits) -> Result<Checked, Rejection> {
    let mut c = Checker::<F>::new(file, limits)?;
    let mut ids = BTreeSet::new();
    for (index, s) in file.steps.iter().enumerate() {
        let id = s.id().to_string();
        let fail = |f: Failure| {
            Rejection::new(f.code(), KindLocus::Step { index, id: id.clone() }, KindDetail::Proof(f))
        };
        if !ids.insert(id.clone()) {
            return Err(fail(Failure::DuplicateId));
        }
        in_time(limits, &format!("checking step {index} `{id}`"))?;
        c.step(s).map_err(fail)?;
    }
    c.summary();
    Ok(Checked {
        name: file.name.clone(),
        steps: file.steps.len(),
        hypotheses: c.hypothesis_text(),
        conclusions: c.conclusions,
        nonempty: c.nonempty,
    })
}
