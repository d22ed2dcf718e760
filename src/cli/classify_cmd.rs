//! `chatter classify`: every exact criterion at one body, with its evidence.

use super::{self as cli, emit};
use crate::bodies::{self, Entry, Threshold};
use crate::certify::{Request, certify};
use crate::exact::{OrderedField, Q, QExt, Ring, parse_user_number};
use crate::finder::{FinderConfig, Seed, find_cone};
use crate::model::FloatBody;
use crate::model::float::FloatPolygon;
use crate::simulate::{Arithmetic, Model, Options, Outcome, Shape, counts, simulate_many};
use crate::spectral::criteria::{
    Family, cc_criterion, goyal_condition, pcc_criterion, rod_cc_criterion, rod_velocity_in_cone,
};
use crate::spectral::eigen::Spectrum;
use crate::spectral::number_field::Nf;
use chatter_kernel::model::{Polygon, Rod, Shape as ExactShape};
use clap::Args;

/// Random drops simulated by `classify`, and their impact budget.
const SIM_RUNS: u64 = 20;
const SIM_BUDGET: usize = 2000;
use serde_json::{Value, json};

/// Raw arguments of `chatter classify`.
#[derive(Args, Debug)]
#[command(
    after_help = "Decides the paper's spectral criteria exactly (Sturm sequences, exact number fields for\n\
n = 5, 7, 8, ...) and shows the evidence, the float finder's verdict and whether a certificate\n\
can be produced.\n\nExamples:\n  chatter classify --n 3 --kappa 3/20 --gamma 1/20\n  chatter classify --n 2 --kappa 1/3 --gamma 0.05 --velocity 0.1,-0.5"
)]
pub struct ClassifyArgs {
    #[command(flatten)]
    pub body: super::BodyArgs,
    /// Rod only: initial velocity u0,u1 of the two ends, to decide CC from it (the paper's
    /// theorem on rotating initial velocities).
    #[arg(long, allow_hyphen_values = true)]
    pub velocity: Option<String>,
    /// Decimal digits of the printed enclosures.
    #[arg(long, default_value_t = 12)]
    pub digits: usize,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

struct Validated {
    n: u64,
    kappa: Q,
    gamma: Q,
    velocity: Option<[Q; 2]>,
    digits: usize,
    json: bool,
}

fn validate(a: ClassifyArgs) -> Result<Validated, String> {
    let (n, kappa, gamma) = a.body.parse()?;
    if !(2..=64).contains(&n) {
        return Err(format!("--n: {n} is outside 2..=64"));
    }
    if !kappa.is_positive() {
        return Err("--kappa: kappa must be > 0".into());
    }
    if gamma.is_negative() || gamma > Q::int(1) {
        return Err("--gamma: gamma must lie in [0, 1]".into());
    }
    let velocity = match a.velocity {
        None => None,
        Some(_) if n != 2 => return Err("--velocity is for the rod (--n 2)".into()),
        Some(v) => {
            let parts: Vec<&str> = v.split(',').collect();
            if parts.len() != 2 {
                return Err(format!("--velocity: expected u0,u1, got {v:?}"));
            }
            let p = |s: &str| parse_user_number(s).map_err(|e| format!("--velocity: {e}"));
            Some([p(parts[0])?, p(parts[1])?])
        }
    };
    if a.digits == 0 || a.digits > 60 {
        return Err("--digits must be in 1..=60".into());
    }
    Ok(Validated { n, kappa, gamma, velocity, digits: a.digits, json: a.json })
}

/// The spectral evidence of one matrix: characteristic polynomial and eigenvalue enclosures.
fn evidence<F: OrderedField + std::fmt::Display>(s: &mut Spectrum<F>, digits: usize) -> Value {
    json!({"char_poly": s.char_poly.to_string(), "eigenvalues": s.describe(digits), "all_real": s.all_real()})
}

fn verdict(b: bool) -> &'static str {
    if b { "HOLDS" } else { "fails" }
}

fn threshold_line(t: &Threshold) -> String {
    match (t.kind, &t.decimal) {
        ("below", Some([lo, hi])) => format!("holds for gamma below a threshold in [{lo}, {hi}]"),
        ("up-to-one", _) => "holds for every gamma in (0, 1)".into(),
        _ => "never holds for gamma in (0, 1)".into(),
    }
}

/// Criteria of an n-gon body over the field `F` (Q, or a number field for irrational cosines).
fn polygon_report<F: OrderedField + std::fmt::Display>(
    v: &Validated,
    fam: &Family<F>,
    out: &mut Value,
    lines: &mut Vec<String>,
) {
    let body = fam.at(&v.gamma);
    let (cc, mut s1, dom) = cc_criterion(&body);
    let ev = evidence(&mut s1, v.digits);
    lines.push(format!("CC criterion (S_1 has a real, positive dominant eigenvalue): {}", verdict(cc)));
    lines.push(format!("  det(tI - S_1) = {}", s1.char_poly));
    lines.push(format!("  eigenvalues: {}", s1.describe(v.digits).join("; ")));
    lines.push(format!("  dominant: {}", dom.describe()));
    out["cc"] = json!({"holds": cc, "dominant": dom.describe(), "evidence": ev});
    let (pcc, mut s2) = pcc_criterion(&body);
    let last = v.n - 1;
    lines.push(format!("PCC criterion (all eigenvalues of S_{last} S_1 real): {}", verdict(pcc)));
    lines.push(format!("  det(tI - S_{last} S_1) = {}", s2.char_poly));
    lines.push(format!("  eigenvalues: {}", s2.describe(v.digits).join("; ")));
    lines.push(format!(
        "  {}",
        if pcc {
            "PCC is not excluded by the paper's Lemma"
        } else {
            "PCC is excluded by the paper's Lemma (complex eigenvalues)"
        }
    ));
    out["pcc"] = json!({"holds": pcc, "evidence": evidence(&mut s2, v.digits)});
}

/// Goyal's condition, the rod's CC criterion, and CC from a given velocity.
fn rod_report(v: &Validated, rod: &Rod<Q>, out: &mut Value, lines: &mut Vec<String>) {
    let goyal = goyal_condition(&v.kappa, &v.gamma);
    let (cc, mut s, dom) = rod_cc_criterion(rod);
    lines.push(format!(
        "Goyal's condition sqrt(kappa) <= 2/(sqrt(gamma) + 1) - 1 (decided exactly): {}",
        verdict(goyal)
    ));
    lines.push(format!("CC criterion (U_0 P has a real, positive dominant eigenvalue): {}", verdict(cc)));
    lines.push(format!("  det(tI - U_0 P) = {}", s.char_poly));
    lines.push(format!("  eigenvalues: {}; dominant: {}", s.describe(v.digits).join("; "), dom.describe()));
    out["goyal"] = json!(goyal);
    out["cc"] = json!({"holds": cc, "dominant": dom.describe(), "evidence": evidence(&mut s, v.digits)});
    let Some(p0) = &v.velocity else { return };
    let inside = rod_velocity_in_cone(rod, p0);
    let text = match inside {
        None => "ICC from every initial velocity (the condition fails)".to_string(),
        Some(true) => format!("CC: the initial velocity ({}, {}) lies in the invariant cone", p0[0], p0[1]),
        Some(false) => {
            format!("ICC: the initial velocity ({}, {}) lies outside the invariant cone", p0[0], p0[1])
        }
    };
    lines.push(format!("from the given velocity: {text}"));
    out["from_velocity"] =
        json!({"velocity": [p0[0].to_string(), p0[1].to_string()], "cc": inside == Some(true)});
}

/// The maps the float finder searches: rounded from the exact model (n = 3, 4, 6), else the
/// float model of the n-gon (issue 10 §1).
fn float_body(v: &Validated, exact: Option<&Polygon<Q>>) -> Option<FloatBody> {
    match exact {
        Some(b) => Some(FloatBody::new(b)),
        None => {
            FloatPolygon::new(v.n, v.kappa.to_f64(), v.gamma.to_f64()).ok().map(|b| FloatBody::from_float(&b))
        }
    }
}

/// The float finder's verdict from both seeds (regular polygons).
fn finder_report(fb: &FloatBody, out: &mut Value, lines: &mut Vec<String>) {
    for (seed, name, key) in
        [(Seed::Translation, "translation seed", "translation"), (Seed::AllDown, "all-down seed", "all_down")]
    {
        let o = find_cone(fb, seed, &FinderConfig::default());
        lines.push(format!("float finder, {name}: {}", o.map(Vec::len)));
        out[format!("finder_{key}")] = json!(o.label());
    }
}

/// A batch of the paper's random drops (f64 with renormalisation; the float model where
/// cos 2π/n is irrational), compared with the criterion.
fn simulation_report(model: &Model, out: &mut Value, lines: &mut Vec<String>) {
    let briefs = simulate_many(model, 0, SIM_RUNS, Arithmetic::Float, &Options::new(SIM_BUDGET), &|| {});
    let c = counts(&briefs);
    let names = Outcome::ALL.map(Outcome::name);
    let text: Vec<String> = names.iter().zip(c).map(|(n, k)| format!("{n} {k}")).collect();
    lines.push(format!(
        "simulation ({SIM_RUNS} random drops, budget {SIM_BUDGET} impacts, f64): {}",
        text.join(", ")
    ));
    out["simulation"] = Value::Object(names.iter().zip(c).map(|(n, k)| (n.to_string(), json!(k))).collect());
    let cc_holds = out["cc"]["holds"].as_bool().unwrap_or(false);
    let chatter = c[0] + c[1];
    if !cc_holds && chatter > 0 {
        lines.push(format!("note: {chatter} of {SIM_RUNS} drops chatter although the CC criterion fails: evidence against the paper's Conjecture 1 ((i) <=> (iii))"));
    }
    if cc_holds && c[2] > 0 {
        lines.push(format!("note: {} of {SIM_RUNS} drops end in ICC although the CC criterion holds (the criterion concerns suitable initial conditions)", c[2]));
    }
}

/// Whether the pipeline certifies, and which claim.
fn certificate_report(v: &Validated, out: &mut Value, lines: &mut Vec<String>) {
    let rep = certify(&Request::new(v.n, v.kappa.clone(), v.gamma.clone()));
    let text = match &rep.result {
        Ok(c) => format!("{} ({} generators; `chatter certify` writes it)", c.claim.name(), c.cone.len()),
        Err(e) => format!("none: {e}"),
    };
    lines.push(format!("certificate: {text}"));
    out["certificate"] = json!(rep.result.as_ref().ok().map(|c| c.claim.name()));
}

pub fn run(a: ClassifyArgs) -> cli::Outcome {
    let v = match validate(a) {
        Ok(v) => v,
        Err(e) => return cli::Outcome::Usage(e.to_string()),
    };
    let entry: Entry = match bodies::user(v.n, &v.kappa) {
        Ok(e) => e,
        Err(e) => return cli::Outcome::Usage(e.to_string()),
    };
    let mut out = json!({"n": v.n, "kappa": v.kappa.to_string(), "gamma": v.gamma.to_string()});
    let mut lines = Vec::new();
    let method = if entry.c1.as_rational().is_some() {
        "exact over Q".to_string()
    } else {
        format!("exact in Q({})", entry.c1.field_meaning().unwrap_or_default())
    };
    lines.push(format!("body: n = {}, kappa = {}, gamma = {} ({method})", v.n, v.kappa, v.gamma));
    out["method"] = json!(method);
    // The exact model (rod, or a polygon with rational cosines); None for n = 5, 7, 8, ...
    let exact = ExactShape::new(v.n, v.kappa.clone(), v.gamma.clone()).ok();
    match &exact {
        Some(ExactShape::Rod(rod)) => rod_report(&v, rod, &mut out, &mut lines),
        Some(ExactShape::Polygon(_)) => {
            let c1 = entry.c1.as_rational().expect("an exact polygon has a rational cosine");
            polygon_report(&v, &Family { n: v.n, c1, kappa: v.kappa.clone() }, &mut out, &mut lines);
        }
        None => {
            let fam = Family { n: v.n, c1: entry.c1.clone(), kappa: Nf::from_q(&v.kappa) };
            polygon_report(&v, &fam, &mut out, &mut lines);
        }
    }
    let (cc_t, pcc_t) = bodies::thresholds(&entry, v.digits);
    lines.push(format!("CC threshold for this kappa: {}", threshold_line(&cc_t)));
    out["cc_threshold"] = json!(cc_t);
    if let Some(p) = &pcc_t {
        lines.push(format!("PCC threshold for this kappa: {}", threshold_line(p)));
        out["pcc_threshold"] = json!(p);
    }
    let polygon = match &exact {
        Some(ExactShape::Polygon(b)) => Some(b),
        _ => None,
    };
    if v.n >= 3 {
        if let Some(fb) = float_body(&v, polygon) {
            finder_report(&fb, &mut out, &mut lines);
        }
    }
    let shape = if v.n == 2 { Shape::Rod } else { Shape::Polygon(v.n) };
    if let Ok(model) = Model::new(shape, v.kappa.clone(), v.gamma.clone()) {
        simulation_report(&model, &mut out, &mut lines);
    }
    if exact.is_some() {
        certificate_report(&v, &mut out, &mut lines);
    } else {
        lines.push("certificate: none (certificates need n in {2, 3, 4, 6}: rational cosines)".into());
        out["certificate"] = Value::Null;
    }
    if v.json {
        emit(&out.to_string());
    } else {
        for l in lines {
            emit(&l);
        }
    }
    cli::Outcome::Success
}
