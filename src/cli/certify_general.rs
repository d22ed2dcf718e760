//! `chatter certify` for a general convex body (docs/model.md §11, issue 13): `--rectangle`,
//! `--box`, `--polygon`, `--body NAME|FILE`. The family finder and exactifier propose one cone
//! per contact; the kernel checks the version-4 certificate on both backends.

use super::certify_cmd::{CertifyArgs, ms, outcome, rest_line};
use super::convex_args::GeneralBody;
use super::{Env, Outcome, emit, emit_report, range};
use crate::bodies::inertia::Tensor;
use crate::certify::Failure;
use crate::certify::convex::{ConvexReport, ConvexRequest, certify_convex};
use crate::certify::virtual_time;
use crate::exact::Q;
use crate::report::certify::RestReport;
use crate::write::write_convex;
use chatter_kernel::exact::{ParseLimits, to_canonical};
use chatter_kernel::syntax::family::ConvexBodyText;
use chatter_kernel::verify::{Backend, Verdict, verify_convex_on};
use std::path::PathBuf;

/// Validated arguments of a general body's certification.
struct Validated {
    req: ConvexRequest,
    description: String,
    /// The full inertia tensor the body was given by, recorded in the certificate (rule K0).
    tensor: Option<Tensor>,
    output: Option<PathBuf>,
    /// `--time-to-rest FILE`.
    rest: Option<PathBuf>,
    json: bool,
    timings: bool,
}

fn validate(a: CertifyArgs, env: &Env) -> Result<Validated, String> {
    // An interval a:b asks for one certificate over every gamma in [a, b] (version 2).
    let [gamma, hi] = range("--gamma", a.body.gamma_text())?;
    if hi > Q::int(1) {
        return Err(format!("--gamma: {hi} is not accepted: gamma must lie in [0, 1]"));
    }
    let Some(GeneralBody { body, description, tensor }) = a.general.parse(&gamma, a.body.gamma.is_some())?
    else {
        return Err("no general body given (--rectangle, --box, --polygon or --body)".into());
    };
    if a.max_vertices < 3 {
        return Err("--max-vertices must be at least 3".into());
    }
    let mut req = ConvexRequest::new(body);
    req.gamma_hi = (hi != gamma).then_some(hi);
    req.claim = a.claim.choice();
    req.finder.max_iterations = a.max_iterations;
    req.finder.max_vertices = a.max_vertices;
    req.backends = env.backends;
    Ok(Validated {
        req,
        description,
        tensor,
        output: a.output,
        rest: a.time_to_rest,
        json: a.json,
        timings: a.timings,
    })
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
    let head = match &v.req.gamma_hi {
        Some(hi) => format!("{}, every gamma in [{}, {hi}]", v.description, v.req.body.gamma()),
        None => format!("{}, gamma={}", v.description, v.req.body.gamma()),
    };
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
    let mut report = certify_convex(&v.req);
    if let Some(t) = &v.tensor {
        record_tensor(&mut report, t, &v.req.backends);
    }
    if let (Ok(cert), Some(path)) = (&report.result, &v.output)
        && let Err(e) = std::fs::write(path, write_convex(cert))
    {
        return Outcome::Usage(format!("cannot write {}: {e}", path.display()));
    }
    let rest = v.rest.as_ref().map(|path| {
        let tensor = v.tensor.as_ref().map(Tensor::urdf);
        let cfg = virtual_time::Config::default();
        let made = match v.req.ends() {
            Ok(ends) => virtual_time::produce_family(&ends, tensor, &cfg, &v.req.backends),
            Err(e) => Err(virtual_time::NotProduced::Failed(e.to_string())),
        };
        (path, made)
    });
    if let Some((path, Ok(p))) = &rest
        && let Err(e) = std::fs::write(path, &p.text)
    {
        return Outcome::Usage(format!("cannot write {}: {e}", path.display()));
    }
    if v.json {
        let output = v.output.as_ref().map(|p| p.display().to_string());
        let mut r = crate::report::certify::of_convex(&v.description, &v.req, &report, output, v.timings);
        if let Some((path, result)) = &rest {
            r.time_to_rest = Some(RestReport::of(result, &path.display().to_string()));
            r.time_to_rest_bound = result.as_ref().ok().map(|p| p.bound.to_string());
        }
        emit_report(&r);
    } else {
        let lines = rest.as_ref().map_or(String::new(), |(path, r)| rest_line(path, r));
        emit(&(summary(&v, &report) + &lines));
    }
    outcome(&report.result, rest.as_ref().map(|r| &r.1))
}

/// Records the full inertia tensor in an accepted certificate and has the kernel check the file
/// again with it (rule K0: J is its J_eff, docs/model.md Proposition 11.0), so that what is
/// written is what the kernel accepted.
fn record_tensor(report: &mut ConvexReport, t: &Tensor, backends: &[Backend]) {
    let Ok(cert) = &mut report.result else { return };
    let [a, b, c, d, e, f] = t.urdf().map(|x| to_canonical(&x));
    let ConvexBodyText::ConvexPolygon { inertia_tensor, .. } = &mut cert.body;
    *inertia_tensor = Some((a, b, c, d, e, f));
    let start = std::time::Instant::now();
    let verdict = verify_convex_on(cert, ParseLimits::default(), backends);
    report.timings.kernel += start.elapsed();
    match verdict {
        Verdict::Accepted(_) => report.notes.push(
            "the certificate records the full inertia tensor; the kernel checked that J is its J_eff (rule K0)".into(),
        ),
        Verdict::Rejected(r) => report.result = Err(Failure::Kernel(r)),
        Verdict::Disagree(s) => report.result = Err(Failure::Internal(s)),
    }
}
