//! `chatter basin`: a basin certificate (docs/basin-certificates.md): which drops of a box are
//! proved to end in complete chatter, which to reach v > 0, as exact shares of the box.

use super::orbit_cmd::OrbitBody;
use super::{Env, Outcome, emit};
use crate::basin::{BasinRequest, produce, write_basin};
use crate::exact::{Q, parse_user_number};
use chatter_kernel::basin::drop::DIMS;
use chatter_kernel::exact::ParseLimits;
use chatter_kernel::verify::{Verdict, verify_basin};
use clap::Args;
use std::path::PathBuf;
use std::time::Instant;

/// Raw arguments of `chatter basin`.
#[derive(Args, Debug)]
#[command(after_help = "Numbers are read exactly: 1/8, 0.15 (= 3/20).\n\n\
The box of drops is in the paper's coordinates before the first impact: velocity\n\
(omega_x, omega_y, -1), position (phi_x, phi_y, h); the default is the paper's random drops\n\
(omega, phi in [0, 1/10]^2, h in [1, 11/10]). CC is counted only for drops proved to enter the\n\
set X of an orbit certificate, or the cone of a node of a time-to-rest certificate (then with a\n\
bound on the time to rest; tried unless --no-rest), both made first and embedded in the file\n\
(docs/basin-certificates.md). Where two contacts land in either order inside a sub-box (a surface\n\
of simultaneous impacts crosses it), the sub-box may be proved by a tree of impact prefixes (a Tree\n\
leaf, format version 2); its drops that meet a simultaneous impact have volume zero and are in no\n\
share.\n\n\
Example:\n  chatter basin --n 3 --kappa 1/8 --gamma 3/20 --depth 20 -o basin.ron")]
pub struct BasinArgs {
    #[command(flatten)]
    pub body: OrbitBody,
    /// The box of drops: ten numbers "lo1,..,lo5:hi1,..,hi5" for (omega_x, omega_y, phi_x, phi_y, h).
    #[arg(long = "box", allow_hyphen_values = true)]
    pub drop_box: Option<String>,
    /// The deepest bisection of the box (each halves one coordinate).
    #[arg(long, default_value_t = 20)]
    pub depth: usize,
    /// The longest impact prefix tried per sub-box.
    #[arg(long, default_value_t = 400)]
    pub max_prefix: usize,
    /// A CC prefix ends once the sub-box centre's state lies within this share of X's delta
    /// (smaller: longer prefixes, larger leaves).
    #[arg(long, default_value_t = 0.25)]
    pub entry: f64,
    /// The orbit certificate's deepest subdivision of X (larger X, slower checks).
    #[arg(long, default_value_t = 2)]
    pub orbit_depth: u64,
    /// Write the certificate here.
    #[arg(short = 'o', long)]
    pub output: Option<PathBuf>,
    /// Do not try a time-to-rest certificate (below the CC threshold it proves the drops that
    /// enter its graph CC, usually at their first impact).
    #[arg(long)]
    pub no_rest: bool,
    /// Skip the final check of the whole file on both backends (the leaves are checked on
    /// malachite while produced).
    #[arg(long)]
    pub no_verify: bool,
}

/// `--box` text: ten numbers.
pub(super) fn parse_box(text: &str) -> Result<([Q; DIMS], [Q; DIMS]), String> {
    let Some((a, b)) = text.split_once(':') else {
        return Err(format!("--box: {text:?}: write lo1,..,lo5:hi1,..,hi5"));
    };
    let corner = |s: &str| -> Result<[Q; DIMS], String> {
        let v: Vec<Q> = s
            .split(',')
            .map(|x| parse_user_number(x.trim()).map_err(|e| format!("--box: {e}")))
            .collect::<Result<_, _>>()?;
        v.try_into().map_err(|v: Vec<Q>| format!("--box: {} numbers in a corner, need {DIMS}", v.len()))
    };
    Ok((corner(a)?, corner(b)?))
}

/// The checks `basin` and `basin-map` share: every coordinate of the box has lo < hi, h > 0, and
/// depth and prefix within the kernel's limits.
pub(super) fn check_box_and_limits(
    lo: &[Q; DIMS],
    hi: &[Q; DIMS],
    depth: usize,
    max_prefix: usize,
) -> Result<(), String> {
    if let Some(k) = (0..DIMS).find(|&k| lo[k] >= hi[k]) {
        return Err(format!("--box: coordinate {} has lo >= hi", k + 1));
    }
    if lo[4] <= Q::int(0) {
        return Err("--box: h must be > 0".into());
    }
    if depth > chatter_kernel::basin::MAX_PATH || max_prefix > chatter_kernel::basin::MAX_PREFIX {
        return Err(format!(
            "--depth at most {}, --max-prefix at most {}",
            chatter_kernel::basin::MAX_PATH,
            chatter_kernel::basin::MAX_PREFIX
        ));
    }
    Ok(())
}

fn validate(a: &BasinArgs) -> Result<BasinRequest, String> {
    let orbit = a.body.request(200, a.orbit_depth.min(4))?;
    let (lo, hi) = match &a.drop_box {
        Some(t) => parse_box(t)?,
        None => BasinRequest::paper_box(),
    };
    check_box_and_limits(&lo, &hi, a.depth, a.max_prefix)?;
    if !(a.entry > 0.0 && a.entry <= 1.0) {
        return Err(format!("--entry: {} is not in (0, 1]", a.entry));
    }
    let rest = (!a.no_rest).then(crate::certify::virtual_time::Config::default);
    Ok(BasinRequest { orbit, lo, hi, depth: a.depth, max_prefix: a.max_prefix, entry: a.entry, rest })
}

pub fn run(a: BasinArgs, env: &Env) -> Outcome {
    let req = match validate(&a) {
        Ok(r) => r,
        Err(e) => return Outcome::Usage(e),
    };
    let bar = indicatif::ProgressBar::new(10_000);
    if let Ok(style) =
        indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} of the box decided {elapsed}")
    {
        bar.set_style(style);
    }
    let start = Instant::now();
    let progress = |share: f64| bar.set_position((share * 10_000.0) as u64);
    let produced = match produce(&req, &env.backends, &progress) {
        Ok(p) => p,
        Err(e) => {
            bar.finish_and_clear();
            emit(&format!("NOT CERTIFIED: {e}"));
            return Outcome::Negative;
        }
    };
    bar.finish_and_clear();
    let made = start.elapsed().as_secs_f64();
    if let Some(path) = &a.output
        && let Err(e) = std::fs::write(path, write_basin(&produced.certificate))
    {
        return Outcome::Usage(format!("cannot write {}: {e}", path.display()));
    }
    let [cc, icc, und] = produced.leaves;
    let [scc, sicc, sund] = produced.shares;
    let orbit = match &produced.orbit {
        Ok(f) => format!("orbit pattern {:?}, delta {:e}", f.pattern, f.delta),
        Err(e) => format!("no orbit certificate ({e})"),
    };
    let rest = match &produced.rest {
        None => "no time-to-rest certificate tried".to_string(),
        Some(Ok((nodes, b))) => format!(
            "time-to-rest certificate of {nodes} nodes, B = {:.4} (the drops of a CC leaf that enter its cone and reach a simultaneous impact later, where the model stops, have volume zero)",
            crate::exact::QExt::to_f64(b)
        ),
        Some(Err(e)) => format!("no time-to-rest certificate ({e})"),
    };
    let head = format!(
        "n={} kappa={} gamma={}: {} leaves (CC {cc}, ICC {icc}, undecided {und}); shares CC {scc:.4}, ICC {sicc:.4}, undecided {sund:.4}; {orbit}; {rest}; produced in {made:.1} s",
        req.orbit.n,
        req.orbit.kappa,
        req.orbit.gamma,
        cc + icc + und,
    );
    if a.no_verify {
        emit(&format!("PRODUCED (leaves checked on {} only) {head}", env.backends[0].name));
        return Outcome::Success;
    }
    let t = Instant::now();
    let verdict = verify_basin(&produced.certificate, ParseLimits::default(), &env.backends);
    let secs = t.elapsed().as_secs_f64();
    match verdict {
        Verdict::Accepted(r) => {
            emit(&format!(
                "CERTIFIED {head}; kernel on both backends {secs:.1} s: cc_share {}, icc_share {}, undecided_share {}, time to rest <= {} h/|v| on every CC leaf",
                r.cc_share,
                r.icc_share,
                r.undecided_share,
                r.time_to_rest_bound.as_deref().map_or("-".into(), |b| {
                    use crate::exact::QExt;
                    crate::exact::parse_user_number(b).map_or(b.to_string(), |q| format!("{:.4}", q.to_f64()))
                })
            ));
            Outcome::Success
        }
        Verdict::Rejected(r) => Outcome::Internal(format!("the producer's certificate is rejected: {r}")),
        Verdict::Disagree(s) => Outcome::Internal(s),
    }
}
