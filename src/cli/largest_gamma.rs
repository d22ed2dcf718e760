//! `chatter certify ... --largest-gamma` (issue 13 §4): the largest gamma that certifies, by
//! exact bisection ([`crate::certify::bisect`]), for a regular body (n, kappa) or a general one,
//! with 100 simulated drops just above it.

use super::certify_cmd::{CertifyArgs, is_general};
use super::map_cmd::progress;
use super::{Env, Outcome, emit, emit_report};
use crate::certify::bisect::{default_interval, largest_certified_gamma};
use crate::certify::convex::{ConvexRequest, TRANSPORT_FAILED, certify_convex};
use crate::certify::transport::regular_preimage;
use crate::certify::{ClaimChoice, Request, certify};
use crate::exact::Q;
use crate::report::convex::GeneralBodyReport;
use crate::report::largest_gamma::{BodyInfo, LargestGammaReport, ThresholdOf, drops};
use crate::simulate::{Model, Shape};
use chatter_kernel::certificate::Claim;
use chatter_kernel::model::ConvexBody;

/// Largest number of bisection steps.
pub const MAX_STEPS: usize = 60;

/// The claim to bisect for: the strongest about drops unless one is named.
fn choice(a: &CertifyArgs) -> ClaimChoice {
    match a.claim.choice() {
        ClaimChoice::Strongest => ClaimChoice::StrongestAboutDrops,
        c => c,
    }
}

/// The body with another gamma.
fn with_gamma(body: &ConvexBody<Q>, g: &Q) -> ConvexBody<Q> {
    ConvexBody::new(body.contacts().to_vec(), body.inertia().clone(), g.clone()).expect("the same valid body")
}

/// A body to bisect: what it is, the pipeline at a gamma, and the simulation model at a gamma.
type Pipeline = Box<dyn Fn(&Q) -> Result<Claim, String>>;
type Simulation = Box<dyn Fn(&Q) -> Result<Model, String>>;

fn general(a: &CertifyArgs, env: &Env) -> Result<(BodyInfo, Pipeline, Simulation), String> {
    let g0 = default_interval().0;
    let Some(gb) = a.general.parse(&g0, true)? else { return Err("no general body given".into()) };
    let info = BodyInfo {
        description: gb.description.clone(),
        n: gb.body.n() as u64,
        kappa: Q::int(0),
        general: Some(GeneralBodyReport::of(&gb.description, &gb.body)),
        threshold: Some(match regular_preimage(&gb.body) {
            Some(p) => ThresholdOf::regular(p.n as u64, &p.kappa),
            None => ThresholdOf::product(&gb.body),
        }),
    };
    let (body, sim_body) = (gb.body.clone(), gb.body);
    let (claim, finder, backends) = (choice(a), (a.max_iterations, a.max_vertices), env.backends);
    let pipeline: Pipeline = Box::new(move |g| {
        let mut req = ConvexRequest::new(with_gamma(&body, g));
        (req.claim, req.backends) = (claim, backends);
        (req.finder.max_iterations, req.finder.max_vertices) = finder;
        let r = certify_convex(&req);
        let transport: String =
            r.notes.iter().filter(|n| n.starts_with(TRANSPORT_FAILED)).map(|n| format!("; {n}")).collect();
        r.result.map(|c| c.claim).map_err(|e| format!("{e}{transport}"))
    });
    let sim: Simulation = Box::new(move |g| Ok(Model::convex(&with_gamma(&sim_body, g))));
    Ok((info, pipeline, sim))
}

fn regular(a: &CertifyArgs, env: &Env) -> Result<(BodyInfo, Pipeline, Simulation), String> {
    if a.general.body.is_some()
        || a.body.kappa.contains(':')
        || a.body.kappa.contains(crate::exact::GENERATOR)
    {
        return Err(
            "--largest-gamma takes a regular body by --n and a rational --kappa, or a general body".into()
        );
    }
    let (n, kappa, _) = super::BodyArgs { gamma: Some("0".into()), ..a.body.clone() }.parse()?;
    crate::certify::check_body(n, &kappa, &Q::int(0)).map_err(|e| format!("--n/--kappa: {e}"))?;
    let info = BodyInfo {
        description: format!("n={n} kappa={kappa}"),
        n,
        kappa: kappa.clone(),
        general: None,
        threshold: Some(ThresholdOf::regular(n, &kappa)),
    };
    let (k, claim, finder, backends) =
        (kappa.clone(), choice(a), (a.max_iterations, a.max_vertices), env.backends);
    let pipeline: Pipeline = Box::new(move |g| {
        let mut req = Request::new(n, k.clone(), g.clone());
        (req.claim, req.backends) = (claim, backends);
        (req.finder.max_iterations, req.finder.max_vertices) = finder;
        certify(&req).result.map(|c| c.claim).map_err(|e| e.to_string())
    });
    let shape = if n == 2 { Shape::Rod } else { Shape::Polygon(n) };
    let sim: Simulation =
        Box::new(move |g| Model::new(shape, kappa.clone(), g.clone()).map_err(|e| e.to_string()));
    Ok((info, pipeline, sim))
}

/// Runs the bisection and prints the report.
pub fn run(a: CertifyArgs, env: &Env) -> Outcome {
    if !(1..=MAX_STEPS).contains(&a.steps) {
        return Outcome::Usage(format!("--steps must be in 1..={MAX_STEPS}"));
    }
    if a.output.is_some() {
        return Outcome::Usage("--largest-gamma writes no certificate: drop -o".into());
    }
    let built = if is_general(&a) { general(&a, env) } else { regular(&a, env) };
    let (info, pipeline, sim) = match built {
        Ok(b) => b,
        Err(e) => return Outcome::Usage(e),
    };
    let interval = default_interval();
    let bar = progress(a.steps as u64 + 2, "pipeline runs");
    let b = largest_certified_gamma(pipeline, interval.clone(), a.steps, &|| bar.inc(1));
    bar.finish_and_clear();
    let drops_above = match b.failed.as_ref().filter(|_| b.certified.is_some()).map(|(g, _)| sim(g)) {
        Some(Ok(model)) => Some(drops(&model)),
        Some(Err(e)) => return Outcome::Internal(format!("no simulation model: {e}")),
        None => None,
    };
    let report = LargestGammaReport::of(info, &interval, a.steps, &b, drops_above, a.timings);
    if a.json {
        emit_report(&report);
    } else {
        report.lines().iter().for_each(|l| emit(l));
    }
    Outcome::Success
}
