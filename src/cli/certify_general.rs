//! `chatter certify` for a general convex body (docs/model.md §11, issue 13): `--rectangle`,
//! `--box`, `--polygon`, `--body NAME|FILE`. The family finder and exactifier propose one cone
//! per contact; the kernel checks the version-4 certificate on both backends.

use super::certify_cmd::{CertifyArgs, ms};
use super::convex_args::GeneralBody;
use super::{Env, Outcome, emit, emit_report};
use crate::certify::Failure;
use crate::certify::convex::{ConvexReport, ConvexRequest, certify_convex};
use crate::exact::parse_user_number;
use crate::write::write_convex;
use std::path::PathBuf;

/// Validated arguments of a general body's certification.
struct Validated {
    req: ConvexRequest,
    description: String,
    output: Option<PathBuf>,
    json: bool,
    timings: bool,
}

fn validate(a: CertifyArgs, env: &Env) -> Result<Validated, String> {
    if a.body.gamma_text().contains(':') {
        return Err("--gamma: intervals (box certificates) are for regular polygons; give one number".into());
    }
    let gamma = parse_user_number(a.body.gamma_text()).map_err(|e| format!("--gamma: {e}"))?;
    let Some(GeneralBody { body, description }) = a.general.parse(&gamma, a.body.gamma.is_some())? else {
        return Err("no general body given (--rectangle, --box, --polygon or --body)".into());
    };
    if a.max_vertices < 3 {
        return Err("--max-vertices must be at least 3".into());
    }
    let mut req = ConvexRequest::new(body);
    req.claim = a.claim.choice();
    req.finder.max_iterations = a.max_iterations;
    req.finder.max_vertices = a.max_vertices;
    req.backends = env.backends;
    Ok(Validated { req, description, output: a.output, json: a.json, timings: a.timings })
}

/// "the family finder + exactifier" or "transport from a regular polygon certificate".
fn by(method: Option<&str>) -> String {
    match method {
        Some(m) if m != crate::certify::convex::FAMILY => m.to_string(),
        _ => format!("the {}", crate::certify::convex::FAMILY),
    }
}

fn summary(v: &Validated, r: &ConvexReport) -> String {
    let t = &r.timings;
    let head = format!("{}, gamma={}", v.description, v.req.body.gamma());
    let times = format!(
        "search {:.2} ms, exactifier {:.2} ms, kernel {:.2} ms ({} + {})",
        ms(t.finder),
        ms(t.exactify),
        ms(t.kernel),
        v.req.backends[0].name,
        v.req.backends[1].name
    );
    let notes: String = r.notes.iter().map(|n| format!("\nnote: {n}")).collect();
    match &r.result {
        Ok(c) => {
            let out = v
                .output
                .as_ref()
                .map_or(String::from(" (no -o: not written)"), |p| format!(" -> {}", p.display()));
            let sizes: Vec<String> = c.cones.iter().map(|k| k.len().to_string()).collect();
            format!(
                "CERTIFIED {head} claim={}: {} cones K_0..K_{} with {} generators, largest denominator {} bits, by {}; {times}{out}\nproves: {}{notes}",
                c.claim.name(),
                c.cones.len(),
                c.cones.len() - 1,
                sizes.join("/"),
                r.max_denominator_bits,
                by(r.method),
                crate::claims::proves(c.claim.name()).unwrap_or("?")
            )
        }
        Err(e) => format!("NOT CERTIFIED {head}: {e}; {times}{notes}"),
    }
}

/// Runs `certify` on a general body.
pub fn run(a: CertifyArgs, env: &Env) -> Outcome {
    let v = match validate(a, env) {
        Ok(v) => v,
        Err(e) => return Outcome::Usage(e),
    };
    let report = certify_convex(&v.req);
    if let (Ok(cert), Some(path)) = (&report.result, &v.output)
        && let Err(e) = std::fs::write(path, write_convex(cert))
    {
        return Outcome::Usage(format!("cannot write {}: {e}", path.display()));
    }
    if v.json {
        let output = v.output.as_ref().map(|p| p.display().to_string());
        emit_report(&crate::report::certify::of_convex(&v.description, &v.req, &report, output, v.timings));
    } else {
        emit(&summary(&v, &report));
    }
    match &report.result {
        Ok(_) => Outcome::Success,
        Err(Failure::Internal(s)) => Outcome::Internal(s.clone()),
        Err(_) => Outcome::Negative,
    }
}
