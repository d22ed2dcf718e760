//! Refutations (docs/certificate-format.md §10, docs/kernel-soundness.md §2 "Refutations"): an
//! exact derivation of velocities that every convex cone K containing the claim's seeds and
//! satisfying S_j(K ∩ C_j) ⊆ K must contain, ending in a non-zero velocity with v >= 0. No
//! certificate of the claim can then exist at this point: every non-zero vector of a
//! certificate's cone has v < 0.
//!
//! Each derived point is a seed, a non-negative combination of earlier points (K is a convex
//! cone), or the image S_j P of an earlier point P that lies in C_j. The points are computed here
//! from the body, never read from the file.

use crate::certificate::{Body, Claim, Code, Coordinates, Locus, Param, Rejection, check_header};
use crate::certificate::{Encoding, check_strict, ron_error};
use crate::exact::{Field, OrderedField, ParseLimits, parse_canonical, to_canonical};
use crate::model::Shape;
use serde::{Deserialize, Serialize};

/// Value of the `format` field.
pub const FORMAT: &str = "chatter-refutation";
/// The version this build reads and writes.
pub const VERSION: u64 = 1;

/// A refutation file.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename = "Refutation", deny_unknown_fields)]
pub struct Refutation {
    /// Always [`FORMAT`].
    pub format: String,
    /// Always [`VERSION`].
    pub version: u64,
    /// The falling body, at a point (no intervals).
    pub body: Body,
    /// The coordinates of the points.
    pub coordinates: Coordinates,
    /// The claim refuted: `EffectivelyInvariant` (seeded by the post-impact velocity of a pure
    /// translation) or an all-down claim (seeded by I_0 of the generators of D).
    pub refutes: Claim,
    /// The derivation, in order; the last point must have v >= 0 and be non-zero.
    pub points: Vec<Step>,
    /// Informational only, never trusted.
    #[serde(default)]
    pub producer: String,
}

/// How a point is derived.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Step {
    /// Seed `index`: I_0 of generator `index` of D (all-down claims), or for
    /// `EffectivelyInvariant` (index 0 only) I_0 of the pure downward translation.
    Seed {
        /// The seed's index.
        index: usize,
    },
    /// Sum of coefficient times point over the terms: each point earlier, each coefficient a
    /// canonical rational >= 0, at least one term.
    Combination {
        /// (earlier point, coefficient).
        terms: Vec<(usize, String)>,
    },
    /// S_step applied to the earlier point `of`, which must lie in C_step.
    Image {
        /// j of S_j, 1..n-1.
        step: usize,
        /// The earlier point.
        of: usize,
    },
}

impl Step {
    fn kind(&self) -> &'static str {
        match self {
            Step::Seed { .. } => "Seed",
            Step::Combination { .. } => "Combination",
            Step::Image { .. } => "Image",
        }
    }
}

/// What an accepted refutation established.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Refuted {
    /// The claim refuted (and every stronger one).
    pub claim: Claim,
    /// Number of contacts.
    pub n: u64,
    /// Number of derived points.
    pub points: usize,
    /// The last point, canonical text.
    pub last: Vec<String>,
    /// Whether its v is > 0 (else = 0): then every cone containing the seeds and invariant in the
    /// paper's sense even violates the paper's condition v <= 0.
    pub v_positive: bool,
}

#[derive(Deserialize)]
#[serde(rename = "Refutation")]
struct Header {
    format: Option<String>,
    version: Option<u64>,
}

/// Reads a refutation in the given encoding (RON or its JSON twin).
pub fn read_in(text: &str, encoding: Encoding) -> Result<Refutation, Rejection> {
    match encoding {
        Encoding::Ron => read(text),
        Encoding::Json => crate::certificate::read_json(text, FORMAT, VERSION..=VERSION),
    }
}

/// Reads a RON refutation: the strict syntax, the header, then the schema with unknown fields
/// denied.
pub fn read(text: &str) -> Result<Refutation, Rejection> {
    check_strict(text)?;
    let lenient = ron::Options::default().with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME);
    let header: Header = lenient.from_str(text).map_err(ron_error)?;
    check_header(header.format.as_deref(), header.version, FORMAT, VERSION..=VERSION)?;
    ron::Options::default().from_str(text).map_err(ron_error)
}

/// The model as matrices and covectors of the body's dimension d (2 for the rod, else 3).
struct Maps<F> {
    seeds: Vec<Vec<F>>,
    steps: Vec<Vec<Vec<F>>>,
    cones: Vec<Vec<Vec<F>>>,
    /// v as a covector: (0, 0, 1), or (1/2, 1/2) for the rod.
    v: Vec<F>,
}

fn apply<F: OrderedField>(m: &[Vec<F>], x: &[F]) -> Vec<F> {
    m.iter().map(|row| row.iter().zip(x).fold(F::zero(), |acc, (a, b)| acc.plus(&a.times(b)))).collect()
}

fn dot<F: OrderedField>(a: &[F], b: &[F]) -> F {
    a.iter().zip(b).fold(F::zero(), |acc, (x, y)| acc.plus(&x.times(y)))
}

fn maps<F: Field>(shape: &Shape<F>, claim: Claim) -> Maps<F> {
    let rows = |m: &[Vec<F>]| m.to_vec();
    let (i0, down, d, steps, cones, v) = match shape {
        Shape::Rod(r) => {
            let m2 = |m: [[F; 2]; 2]| m.iter().map(|r| r.to_vec()).collect::<Vec<_>>();
            let half = F::from_ratio(1, 2);
            (
                m2(r.impact(0)),
                vec![F::from_i64(-1); 2],
                r.all_down_generators().iter().map(|g| g.to_vec()).collect::<Vec<_>>(),
                vec![m2(r.step())],
                vec![r.next_contact_cone().iter().map(|l| l.to_vec()).collect()],
                vec![half.clone(), half],
            )
        }
        Shape::Polygon(p) => {
            let m3 = |m: [[F; 3]; 3]| m.iter().map(|r| r.to_vec()).collect::<Vec<_>>();
            let js = 1..p.n() as i64;
            (
                m3(p.impact(0)),
                vec![F::from_i64(-1); 3],
                p.all_down_generators().iter().map(|g| g.to_vec()).collect(),
                js.clone().map(|j| m3(p.step(j))).collect(),
                js.map(|j| p.next_contact_cone(j).iter().map(|l| l.to_vec()).collect()).collect(),
                vec![F::zero(), F::zero(), F::one()],
            )
        }
    };
    let drops = if claim == Claim::EffectivelyInvariant { vec![down] } else { d };
    Maps { seeds: drops.iter().map(|g| apply(&rows(&i0), g)).collect(), steps, cones, v }
}

/// Checks a refutation exactly over `F`; the first failing step is reported.
pub fn check<F: Field>(r: &Refutation, limits: ParseLimits) -> Result<Refuted, Rejection> {
    if r.format != FORMAT || r.version != VERSION {
        let msg = format!("expected {FORMAT:?} version {VERSION}");
        return Err(Rejection::at_field(Code::WrongFormat, "format", msg));
    }
    let Body::RegularPolygon { n, kappa: Param::Point(k), gamma: Param::Point(g) } = &r.body else {
        let msg = "a refutation is made at a point: kappa and gamma must be numbers";
        return Err(Rejection::at_field(Code::ParameterOutOfRange, "body", msg));
    };
    if r.points.len() > limits.max_generators {
        let msg = format!(
            "{} points, more than the limit max-generators = {}: no verdict on the content",
            r.points.len(),
            limits.max_generators
        );
        return Err(Rejection::new(Code::TooLarge, Locus::Limit { name: "max-generators".into() }, msg));
    }
    let number = |path: &str, s: &str| {
        parse_canonical::<F>(s, limits)
            .map_err(|e| Rejection::at_field(Code::BadNumber, path, format!("{s:?}: {e}")))
    };
    let shape = Shape::new(*n, number("body.kappa", k)?, number("body.gamma", g)?)
        .map_err(|e| Rejection::at_field(Code::ParameterOutOfRange, "body", e))?;
    let m = maps(&shape, r.refutes);
    let mut pts: Vec<Vec<F>> = Vec::with_capacity(r.points.len());
    for (index, s) in r.points.iter().enumerate() {
        crate::check::in_time(limits, "checking a refutation")?;
        let fail = |msg: String| {
            Rejection::new(
                Code::StepFailed,
                Locus::Step { index, id: s.kind().into() },
                format!("point {index} ({}): {msg}", s.kind()),
            )
        };
        let earlier = |i: usize| {
            pts.get(i).filter(|_| i < index).ok_or_else(|| fail(format!("point {i} is not an earlier point")))
        };
        let p = match s {
            Step::Seed { index: i } => m
                .seeds
                .get(*i)
                .cloned()
                .ok_or_else(|| fail(format!("there is no seed {i} ({} seeds)", m.seeds.len())))?,
            Step::Combination { terms } => {
                if terms.is_empty() {
                    return Err(fail("no terms".into()));
                }
                let mut sum = vec![F::zero(); m.v.len()];
                for (i, c) in terms {
                    let c: F = parse_canonical(c, limits).map_err(|e| fail(format!("{c:?}: {e}")))?;
                    if c.is_negative() {
                        return Err(fail(format!("the coefficient of point {i} is negative")));
                    }
                    let x = earlier(*i)?;
                    sum = sum.iter().zip(x).map(|(a, b)| a.plus(&c.times(b))).collect();
                }
                sum
            }
            Step::Image { step, of } => {
                let (Some(s_j), Some(c_j)) =
                    (m.steps.get(step.wrapping_sub(1)), m.cones.get(step.wrapping_sub(1)))
                else {
                    return Err(fail(format!("S_{step} does not exist (1..{})", m.steps.len())));
                };
                let x = earlier(*of)?;
                if let Some(l) = c_j.iter().position(|l| dot(l, x).is_negative()) {
                    return Err(fail(format!("point {of} is not in C_{step} (inequality {l} fails)")));
                }
                apply(s_j, x)
            }
        };
        pts.push(p);
    }
    let Some(last) = pts.last() else {
        return Err(Rejection::at_field(Code::StepFailed, "points", "no points"));
    };
    let v = dot(&m.v, last);
    if v.is_negative() || last.iter().all(|x| x.is_zero()) {
        let index = pts.len() - 1;
        let msg = if v.is_negative() {
            format!("the last point has v = {} < 0: nothing is refuted", to_canonical_text(&v))
        } else {
            "the last point is zero: nothing is refuted".to_string()
        };
        return Err(Rejection::new(
            Code::StepFailed,
            Locus::Step { index, id: r.points[index].kind().into() },
            msg,
        ));
    }
    Ok(Refuted {
        claim: r.refutes,
        n: *n,
        points: pts.len(),
        last: last.iter().map(to_canonical_text).collect(),
        v_positive: v.is_positive(),
    })
}

fn to_canonical_text<F: Field>(x: &F) -> String {
    crate::check::abbreviated(&to_canonical(x))
}

/// Writes a refutation in the strict syntax, one point per line (deterministic).
pub fn write(r: &Refutation) -> String {
    use crate::certificate::quoted;
    let Body::RegularPolygon { n, kappa, gamma } = &r.body;
    let param = |p: &Param| match p {
        Param::Point(x) => quoted(x),
        Param::Interval(a, b) => format!("[{}, {}]", quoted(a), quoted(b)),
    };
    let mut out = String::from("Refutation(\n");
    out.push_str(&format!("    format: {},\n    version: {},\n", quoted(&r.format), r.version));
    out.push_str(&format!(
        "    body: RegularPolygon(n: {n}, kappa: {}, gamma: {}),\n",
        param(kappa),
        param(gamma)
    ));
    out.push_str(&format!(
        "    coordinates: ContactVelocities,\n    refutes: {},\n    points: [\n",
        r.refutes.name()
    ));
    for s in &r.points {
        let line = match s {
            Step::Seed { index } => format!("Seed(index: {index})"),
            Step::Combination { terms } => {
                let t: Vec<String> = terms.iter().map(|(i, c)| format!("({i}, {})", quoted(c))).collect();
                format!("Combination(terms: [{}])", t.join(", "))
            }
            Step::Image { step, of } => format!("Image(step: {step}, of: {of})"),
        };
        out.push_str(&format!("        {line},\n"));
    }
    out.push_str(&format!("    ],\n    producer: {},\n)\n", quoted(&r.producer)));
    out
}
