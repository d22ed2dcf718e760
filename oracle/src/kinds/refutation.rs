//! Refutations (docs/certificate-format.md §10): the derivation is recomputed from the body with
//! the oracle's model (seeds, non-negative combinations, images S_j P of points in C_j), and the
//! last point must be non-zero with v ≥ 0. C_j membership is tested against the facets the oracle
//! derives from C_j's generators (§4 / Lemma 11.3), not the kernel's covectors.

use super::limits::Limits;
use super::numbers::rational;
use crate::arith::rational::rational_text;
use crate::arith::{Field, Num, Rat};
use crate::claim::Claim;
use crate::cone3::dot;
use crate::read::Value;
use crate::read::schema::{
    integer, list, param, regular_polygon, string, tuple, unit_variant, variant, walk,
};
use crate::regular::model::Polygon;
use crate::regular::rod::Rod;
use crate::verdict::{Checked, Fail, Report};
use num_traits::{One, Signed, Zero};

/// One entry of `points`.
#[derive(Clone, Debug)]
pub enum Step<'a> {
    /// Seed(index).
    Seed(u64),
    /// Combination(terms).
    Combination(Vec<(u64, &'a str)>),
    /// Image(step, of).
    Image(u64, u64),
}

/// A refutation as read.
pub struct RefutationFile<'a> {
    n: u64,
    kappa: Vec<&'a str>,
    gamma: Vec<&'a str>,
    claim: Claim,
    points: Vec<Step<'a>>,
}

fn step(v: &Value) -> Checked<Step<'_>> {
    let (name, fields) = variant(v)?;
    let known = ["Seed", "Combination", "Image"];
    if !known.contains(&name) {
        return Err(Fail::new("unknown-variant", format!("unknown step `{name}`")));
    }
    let fields = fields.ok_or_else(|| Fail::new("syntax", "a step needs its fields"))?;
    let (mut a, mut b, mut terms) = (0, 0, vec![]);
    let spec: &[(&str, bool)] = match name {
        "Seed" => &[("index", true)],
        "Image" => &[("step", true), ("of", true)],
        _ => &[("terms", true)],
    };
    walk(fields, spec, |f, value| {
        match f {
            "index" | "step" => a = integer(value)?,
            "of" => b = integer(value)?,
            _ => {
                for t in list(value)? {
                    let t = tuple(t)?;
                    if t.len() != 2 {
                        return Err(Fail::new("syntax", "a term is (point, coefficient)"));
                    }
                    terms.push((integer(&t[0])?, string(&t[1])?));
                }
            }
        }
        Ok(())
    })?;
    Ok(match name {
        "Seed" => Step::Seed(a),
        "Image" => Step::Image(a, b),
        _ => Step::Combination(terms),
    })
}

/// The schema of §10.
pub fn read(v: &Value) -> Checked<RefutationFile<'_>> {
    let mut r = RefutationFile {
        n: 0,
        kappa: vec![],
        gamma: vec![],
        claim: Claim::EffectivelyInvariant,
        points: vec![],
    };
    let fields = [
        ("format", true),
        ("version", true),
        ("body", true),
        ("coordinates", true),
        ("refutes", true),
        ("points", true),
        ("producer", false),
    ];
    walk(v, &fields, |name, value| {
        match name {
            "format" | "producer" => drop(string(value)?),
            "version" => drop(integer(value)?),
            "body" => {
                regular_polygon(value, |k, v| {
                    match k {
                        "n" => r.n = integer(v)?,
                        "kappa" => r.kappa = param(v)?,
                        _ => r.gamma = param(v)?,
                    }
                    Ok(())
                })?;
            }
            "coordinates" => drop(unit_variant(value, &[("ContactVelocities", true)])?),
            "refutes" => {
                let known: Vec<(&str, bool)> = Claim::ALL.iter().map(|(_, n)| (*n, true)).collect();
                r.claim = Claim::of_name(unit_variant(value, &known)?).expect("listed");
            }
            _ => r.points = list(value)?.iter().map(step).collect::<Checked<_>>()?,
        }
        Ok(())
    })?;
    Ok(r)
}

/// The model the derivation runs in: the rod's or a polygon's, with seeds, steps and C_j tests.
enum Model {
    Rod(Rod),
    Polygon(Polygon),
}

impl Model {
    fn steps(&self) -> u64 {
        match self {
            Model::Rod(_) => 1,
            Model::Polygon(b) => b.n as u64 - 1,
        }
    }

    /// The seeds: I_0 of the downward translation, or of the generators of D (§10).
    fn seeds(&self, claim: Claim) -> Vec<Vec<Num>> {
        let q = Field::rationals();
        match self {
            Model::Rod(rod) => {
                let to = |p: [Rat; 2]| p.iter().map(|x| Num::rational(&q, x.clone())).collect();
                let m1 = -Rat::one();
                let down = if claim == Claim::EffectivelyInvariant {
                    vec![[m1.clone(), m1.clone()]]
                } else {
                    vec![[Rat::zero(), m1.clone()], [m1, Rat::zero()]]
                };
                down.iter().map(|g| to(rod.impact(0, g))).collect()
            }
            Model::Polygon(b) => {
                let f = &b.kappa.field;
                let down = if claim == Claim::EffectivelyInvariant {
                    vec![[Num::int(f, -1), Num::int(f, -1), Num::int(f, -1)]]
                } else {
                    b.all_down()
                };
                down.iter().map(|g| b.impact(0, g).to_vec()).collect()
            }
        }
    }

    /// S_j p, when p lies in C_j (else `None`).
    fn image(&self, j: u64, p: &[Num]) -> Option<Vec<Num>> {
        match self {
            Model::Rod(rod) => {
                // C_1 = {u0 ≥ 0, v ≤ 0}.
                if p[0].is_negative() || (&p[0] + &p[1]).is_positive() {
                    return None;
                }
                let r = |x: &Num| x.as_rational().expect("rational").clone();
                let img = rod.step(&[r(&p[0]), r(&p[1])]);
                let q = &p[0].field;
                Some(img.iter().map(|x| Num::rational(q, x.clone())).collect())
            }
            Model::Polygon(b) => {
                let x: [Num; 3] = [p[0].clone(), p[1].clone(), p[2].clone()];
                if b.next_contact_facets(j as i64).iter().any(|l| dot(l, &x).is_negative()) {
                    return None;
                }
                Some(b.step(j as i64, &x).to_vec())
            }
        }
    }

    /// v of a point: (u0 + u1)/2 for the rod.
    fn v(&self, p: &[Num]) -> Num {
        match self {
            Model::Rod(_) => &p[0] + &p[1],
            Model::Polygon(_) => p[2].clone(),
        }
    }
}

fn model(r: &RefutationFile, limits: &Limits) -> Checked<Model> {
    if r.kappa.len() != 1 || r.gamma.len() != 1 {
        return Err(Fail::new("parameter-out-of-range", "a refutation is made at a point"));
    }
    if r.points.len() > limits.max_generators {
        return Err(Fail::new("too-large", "more points than max-generators"));
    }
    let kappa = rational("body.kappa", r.kappa[0], limits)?;
    let gamma = rational("body.gamma", r.gamma[0], limits)?;
    let out = |why: String| Err(Fail::new("parameter-out-of-range", why));
    if !matches!(r.n, 2 | 3 | 4 | 6) {
        return out(format!("n = {}", r.n));
    }
    if !kappa.is_positive() || gamma.is_negative() || gamma > Rat::one() {
        return out("kappa > 0 and 0 <= gamma <= 1".into());
    }
    if r.n == 2 {
        return Ok(Model::Rod(Rod { kappa, gamma }));
    }
    let f = Field::cos(r.n as u32);
    Ok(Model::Polygon(Polygon::new(r.n as usize, Num::rational(&f, kappa), Num::rational(&f, gamma))))
}

fn failed(index: usize, why: String) -> Fail {
    Fail::new("step-failed", format!("point {index}: {why}"))
}

/// Every rule of a refutation after its schema.
pub fn check(r: &RefutationFile, limits: &Limits) -> Checked<Report> {
    let m = model(r, limits)?;
    let seeds = m.seeds(r.claim);
    let mut pts: Vec<Vec<Num>> = vec![];
    for (index, s) in r.points.iter().enumerate() {
        let earlier = |i: u64| pts.get(i as usize).filter(|_| (i as usize) < index).cloned();
        let p = match s {
            Step::Seed(i) => {
                seeds.get(*i as usize).cloned().ok_or_else(|| failed(index, format!("no seed {i}")))?
            }
            Step::Combination(terms) => {
                if terms.is_empty() {
                    return Err(failed(index, "no terms".into()));
                }
                let mut sum: Option<Vec<Num>> = None;
                for (i, c) in terms {
                    let c = crate::arith::rational::parse_rational(c, limits.max_digits)
                        .map_err(|_| failed(index, format!("{c:?} is not canonical")))?;
                    if c.is_negative() {
                        return Err(failed(index, "a negative coefficient".into()));
                    }
                    let x = earlier(*i).ok_or_else(|| failed(index, format!("{i} is not earlier")))?;
                    let c = Num::rational(&x[0].field, c);
                    let term: Vec<Num> = x.iter().map(|b| &c * b).collect();
                    sum = Some(match sum {
                        None => term,
                        Some(s) => s.iter().zip(&term).map(|(a, b)| a + b).collect(),
                    });
                }
                sum.expect("at least one term")
            }
            Step::Image(j, of) => {
                if *j < 1 || *j > m.steps() {
                    return Err(failed(index, format!("S_{j} does not exist")));
                }
                let x = earlier(*of).ok_or_else(|| failed(index, format!("{of} is not earlier")))?;
                m.image(*j, &x).ok_or_else(|| failed(index, format!("point {of} is not in C_{j}")))?
            }
        };
        pts.push(p);
    }
    let last = pts.last().ok_or_else(|| Fail::new("step-failed", "no points"))?;
    let v = m.v(last);
    if v.is_negative() || last.iter().all(Num::is_zero) {
        return Err(Fail::new("step-failed", "the last point is zero or has v < 0"));
    }
    let text = |x: &Num| rational_text(x.as_rational().expect("rational"));
    Ok(Report {
        claim: r.claim.name().into(),
        n: r.n,
        refutation: Some((pts.len(), last.iter().map(text).collect(), v.is_positive())),
        ..Report::default()
    })
}
