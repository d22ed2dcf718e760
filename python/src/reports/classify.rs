//! `classify`: the fields of `chatter classify --json`.

use crate::fail::Fail;
use crate::inputs;
use chatter::bodies::{self, Entry};
use chatter::certify::{Request, certify};
use chatter::exact::{OrderedField, Q, QExt, Ring};
use chatter::finder::{FinderConfig, Seed, find_cone};
use chatter::model::FloatBody;
use chatter::model::float::FloatPolygon;
use chatter::simulate::{Arithmetic, Model, Options, Outcome, Shape, counts, simulate_many};
use chatter::spectral::criteria::{
    Family, cc_criterion, goyal_condition, pcc_criterion, rod_cc_criterion, rod_velocity_in_cone,
};
use chatter::spectral::eigen::Spectrum;
use chatter::spectral::number_field::Nf;
use chatter_kernel::model::{Polygon, Rod, Shape as ExactShape};
use serde_json::{Value, json};

/// Random drops simulated by `classify`, and their impact budget (as the command line).
const SIM_RUNS: u64 = 20;
const SIM_BUDGET: usize = 2000;

/// The arguments as the package passes them.
pub struct Args {
    pub n: u64,
    pub kappa: String,
    pub gamma: String,
    pub velocity: Option<Vec<String>>,
    pub digits: usize,
}

struct Validated {
    n: u64,
    kappa: Q,
    gamma: Q,
    velocity: Option<[Q; 2]>,
    digits: usize,
}

fn validate(a: &Args) -> Result<Validated, Fail> {
    let bad = |m: String| Fail::usage("invalid-input", m);
    let (kappa, gamma) = (inputs::number("kappa", &a.kappa)?, inputs::number("gamma", &a.gamma)?);
    if !(2..=64).contains(&a.n) {
        return Err(bad(format!("n: {} is outside 2..=64", a.n)));
    }
    if !kappa.is_positive() {
        return Err(Fail::usage("kappa-not-positive", "kappa must be > 0"));
    }
    if gamma.is_negative() || gamma > Q::int(1) {
        return Err(Fail::usage("gamma-out-of-range", "gamma must lie in [0, 1]"));
    }
    let velocity = match &a.velocity {
        None => None,
        Some(_) if a.n != 2 => return Err(bad("velocity is for the rod (n = 2)".into())),
        Some(v) => match inputs::numbers("velocity", v)?.as_slice() {
            [u0, u1] => Some([u0.clone(), u1.clone()]),
            _ => return Err(bad(format!("velocity: expected (u0, u1), got {} numbers", v.len()))),
        },
    };
    if a.digits == 0 || a.digits > 60 {
        return Err(bad("digits must be in 1..=60".into()));
    }
    Ok(Validated { n: a.n, kappa, gamma, velocity, digits: a.digits })
}

/// The spectral evidence of one matrix.
fn evidence<F: OrderedField + std::fmt::Display>(s: &mut Spectrum<F>, digits: usize) -> Value {
    json!({"char_poly": s.char_poly.to_string(), "eigenvalues": s.describe(digits), "all_real": s.all_real()})
}

/// The CC and PCC criteria of an n-gon over the field `F`.
fn polygon<F: OrderedField + std::fmt::Display>(v: &Validated, fam: &Family<F>, out: &mut Value) {
    let body = fam.at(&v.gamma);
    let (cc, mut s1, dom) = cc_criterion(&body);
    out["cc"] = json!({"holds": cc, "dominant": dom.describe(), "evidence": evidence(&mut s1, v.digits)});
    let (pcc, mut s2) = pcc_criterion(&body);
    out["pcc"] = json!({"holds": pcc, "evidence": evidence(&mut s2, v.digits)});
}

/// Goyal's condition, the rod's CC criterion, and CC from a given velocity.
fn rod(v: &Validated, rod: &Rod<Q>, out: &mut Value) {
    let (cc, mut s, dom) = rod_cc_criterion(rod);
    out["goyal"] = json!(goyal_condition(&v.kappa, &v.gamma));
    out["cc"] = json!({"holds": cc, "dominant": dom.describe(), "evidence": evidence(&mut s, v.digits)});
    if let Some(p0) = &v.velocity {
        let inside = rod_velocity_in_cone(rod, p0);
        out["from_velocity"] =
            json!({"velocity": [p0[0].to_string(), p0[1].to_string()], "cc": inside == Some(true)});
    }
}

/// The float finder's verdicts from both seeds.
fn finder(v: &Validated, exact: Option<&Polygon<Q>>, out: &mut Value) {
    let fb = match exact {
        Some(b) => FloatBody::new(b),
        None => match FloatPolygon::new(v.n, v.kappa.to_f64(), v.gamma.to_f64()) {
            Ok(b) => FloatBody::from_float(&b),
            Err(_) => return,
        },
    };
    for (seed, key) in [(Seed::Translation, "translation"), (Seed::AllDown, "all_down")] {
        out[format!("finder_{key}")] = json!(find_cone(&fb, seed, &FinderConfig::default()).label());
    }
}

/// Outcome counts of a batch of the paper's random drops.
fn simulation(v: &Validated, out: &mut Value) {
    let shape = if v.n == 2 { Shape::Rod } else { Shape::Polygon(v.n) };
    let Ok(model) = Model::new(shape, v.kappa.clone(), v.gamma.clone()) else { return };
    let briefs = simulate_many(&model, 0, SIM_RUNS, Arithmetic::Float, &Options::new(SIM_BUDGET), &|| {});
    let names = Outcome::ALL.map(Outcome::name);
    out["simulation"] =
        Value::Object(names.iter().zip(counts(&briefs)).map(|(n, k)| (n.to_string(), json!(k))).collect());
}

/// The criteria, with the field they are decided in.
fn criteria(v: &Validated, entry: &Entry, exact: Option<&ExactShape<Q>>, out: &mut Value) {
    match exact {
        Some(ExactShape::Rod(r)) => rod(v, r, out),
        Some(ExactShape::Polygon(_)) => {
            let c1 = entry.c1.as_rational().expect("an exact polygon has a rational cosine");
            polygon(v, &Family { n: v.n, c1, kappa: v.kappa.clone() }, out);
        }
        None => {
            let fam = Family { n: v.n, c1: entry.c1.clone(), kappa: Nf::from_q(&v.kappa) };
            polygon(v, &fam, out);
        }
    }
}

/// Every exact criterion at one body, with its evidence, thresholds, the finder, simulated
/// drops and whether a certificate can be made.
pub fn value(a: &Args) -> Result<Value, Fail> {
    let v = validate(a)?;
    let entry = bodies::user(v.n, &v.kappa).map_err(|e| Fail::usage("invalid-input", e))?;
    let method = match entry.c1.as_rational() {
        Some(_) => "exact over Q".to_string(),
        None => format!("exact in Q({})", entry.c1.field_meaning().unwrap_or_default()),
    };
    let mut out =
        json!({"n": v.n, "kappa": v.kappa.to_string(), "gamma": v.gamma.to_string(), "method": method});
    let exact = ExactShape::new(v.n, v.kappa.clone(), v.gamma.clone()).ok();
    criteria(&v, &entry, exact.as_ref(), &mut out);
    let (cc_t, pcc_t) = bodies::thresholds(&entry, v.digits);
    out["cc_threshold"] = json!(cc_t);
    if let Some(p) = &pcc_t {
        out["pcc_threshold"] = json!(p);
    }
    if v.n >= 3 {
        let poly = match &exact {
            Some(ExactShape::Polygon(b)) => Some(b),
            _ => None,
        };
        finder(&v, poly, &mut out);
    }
    simulation(&v, &mut out);
    out["certificate"] = match exact {
        Some(_) => {
            let rep = certify(&Request::new(v.n, v.kappa.clone(), v.gamma.clone()));
            json!(rep.result.as_ref().ok().map(|c| c.claim.name()))
        }
        None => Value::Null,
    };
    Ok(out)
}
