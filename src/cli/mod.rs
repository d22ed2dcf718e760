//! The command line: raw arguments (clap) are validated into library requests (ripgrep style:
//! two layers), then a thin driver calls the library and prints. Every command returns a typed
//! [`Outcome`]; [`Outcome::exit_code`] is the one place that maps outcomes to exit statuses:
//! 0 success; 1 a negative answer (not certified, a certificate rejected, a proof step failed);
//! 2 bad usage or unreadable input; 3 internal error (the two backends disagree).

mod basin_cmd;
mod basin_map_cmd;
mod bodies_cmd;
mod certify_cmd;
mod certify_general;
mod check_proof_cmd;
mod classify_cmd;
mod convert_cmd;
mod convex_args;
mod cover_cmd;
mod largest_gamma;
mod map_cmd;
mod orbit_cmd;
mod plot_cmd;
mod prove_cmd;
mod refute_cmd;
mod reproduce_cmd;
mod schema_cmd;
mod simulate_cmd;
mod verify_cmd;

use crate::exact::{Q, parse_user_number};
use chatter_kernel::model::BodyError;
use chatter_kernel::verify::{Backend, MALACHITE, NUM};
use clap::{Args, Parser, Subcommand};
use std::process::ExitCode;

/// What a command concluded.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// The command did what was asked and the answer is positive.
    Success,
    /// A negative answer: not certified, a certificate rejected, a proof step failed.
    Negative,
    /// Bad usage or unreadable input; the message is printed on stderr.
    Usage(String),
    /// A bug in chatter or a bignum library (the backends disagree); printed on stderr.
    Internal(String),
}

impl Outcome {
    /// The documented exit status (docs/commands.md, `chatter --help`).
    pub fn exit_code(&self) -> u8 {
        match self {
            Outcome::Success => 0,
            Outcome::Negative => 1,
            Outcome::Usage(_) => 2,
            Outcome::Internal(_) => 3,
        }
    }

    /// `Success` or `Negative`.
    pub fn from_answer(positive: bool) -> Outcome {
        if positive { Outcome::Success } else { Outcome::Negative }
    }
}

/// What the commands run on: the two independent bignum backends of the kernel (a test can
/// plug in a deliberately wrong one).
#[derive(Clone, Copy)]
pub struct Env {
    /// The backends the kernel runs on (`verify --backend both`, `certify`).
    pub backends: [Backend; 2],
}

impl Default for Env {
    fn default() -> Self {
        Env { backends: [MALACHITE, NUM] }
    }
}

#[derive(Parser, Debug)]
#[command(
    name = "chatter",
    version,
    about = "Exact certificates that a rigid body dropped flat onto a floor never separates from it (complete chatter: docs/time-to-rest.md)",
    long_about = "Exact certificates about a rigid body dropped flat onto a floor chattering to rest by complete \
chatter (CC: infinitely many impacts in finite time). Cone certificates prove that the body never \
separates and its impacts never stop (v <= 0 for ever, PCC excluded where claimed; in the model, \
impacts happen one contact at a time: simultaneous impacts are outside it); that the impacts \
accumulate at a finite time is proved only by orbit certificates, by the rod's bound (rule T1) and \
by time-to-rest certificates (rules G1-G5, F, which `chatter verify` checks; docs/time-to-rest.md).\n\n\
A floating-point finder proposes a polyhedral cone of velocities, an exactifier turns it into \
rationals, and a small trusted kernel re-checks it with exact arithmetic on two independent bignum \
libraries before a RON certificate is written.\n\n\
Exit status: 0 success, 1 negative answer (not certified / rejected), 2 usage or input error, \
3 internal error."
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Regenerate the paper's results into a folder with report.md and report.html (the main job).
    Reproduce(reproduce_cmd::ReproduceArgs),
    /// Find, exactify and kernel-check an effectively invariant cone; write a certificate.
    Certify(certify_cmd::CertifyArgs),
    /// Prove complete chatter from a set of states around an attracting impact cycle (an orbit
    /// certificate, docs/orbit-certificates.md); write it.
    CertifyOrbit(orbit_cmd::OrbitArgs),
    /// Prove which drops of a box chatter to rest (enter an orbit certificate's set or a node's
    /// cone of a time-to-rest certificate) and which reach v > 0, as exact shares of the box
    /// (docs/basin-certificates.md); write the certificate.
    Basin(basin_cmd::BasinArgs),
    /// Basin certificates over a grid of (kappa, gamma): the kernel-checked shares of a box of
    /// drops proved CC, proved ICC and undecided, per point (docs/basin-certificates.md §6).
    BasinMap(basin_map_cmd::BasinMapArgs),
    /// Check certificate files (or directories of *.ron and *.json files) with the trusted kernel.
    Verify(verify_cmd::VerifyArgs),
    /// Convert a certificate or refutation between RON and its JSON twin (lossless).
    Convert(convert_cmd::ConvertArgs),
    /// Decide the paper's spectral criteria exactly at one body, with the evidence.
    Classify(classify_cmd::ClassifyArgs),
    /// The catalogue of bodies: kappa from geometry, exact CC and PCC thresholds in gamma.
    Bodies(bodies_cmd::BodiesArgs),
    /// Prove the paper's square-case lemmas; write proofs/square.ron (re-checked) and .md.
    Prove(prove_cmd::ProveArgs),
    /// Re-check proof files (e.g. proofs/square.ron) with the trusted kernel.
    CheckProof(check_proof_cmd::CheckProofArgs),
    /// Simulate drops event by event (f64 or exact) and classify them as CC, PCC or ICC.
    Simulate(simulate_cmd::SimulateArgs),
    /// Derive exactly that no effectively invariant cone exists at a point; write a refutation.
    Refute(refute_cmd::RefuteArgs),
    /// Cover a box of parameters with box certificates and refutations (adaptive subdivision).
    Cover(cover_cmd::CoverArgs),
    /// The paper's maps over (rho, gamma): criteria, finder, certificates, simulations per point.
    Map(map_cmd::MapArgs),
    /// Figures (SVG or PNG): map panels, simulation maps, a certificate's cone on v = -1, a cover.
    Plot(plot_cmd::PlotArgs),
    /// Write (or --check) the JSON Schemas of every --json output into a folder (docs/schema).
    Schema(schema_cmd::SchemaArgs),
}

impl Command {
    /// Whether the command was asked for JSON (`--json`): then errors are JSON too.
    pub fn json(&self) -> bool {
        match self {
            Command::Certify(a) => a.json,
            Command::CertifyOrbit(a) => a.json,
            Command::Verify(a) => a.json,
            Command::Classify(a) => a.json,
            Command::Bodies(a) => a.json,
            Command::Prove(a) => a.json,
            Command::CheckProof(a) => a.json,
            Command::Simulate(a) => a.json,
            Command::Refute(a) => a.json,
            Command::Reproduce(_)
            | Command::Convert(_)
            | Command::Cover(_)
            | Command::Map(_)
            | Command::Plot(_)
            | Command::Schema(_)
            | Command::Basin(_)
            | Command::BasinMap(_) => false,
        }
    }
}

/// The body as typed (raw layer), shared by certify, classify and simulate; each command
/// validates the ranges it supports.
#[derive(Args, Debug, Clone)]
pub struct BodyArgs {
    /// Number of contacts: 2 (the rod) or a regular n-gon (certify and verify: 3 to 64, in
    /// Q(cos 2 pi/n) where that cosine is irrational; the other exact models: 3, 4, 6).
    #[arg(long, default_value = "4", allow_hyphen_values = true)]
    pub n: String,
    /// kappa = rho^2 / R^2 (radius of gyration over circumradius, squared), > 0.
    #[arg(long, default_value = "1/6", allow_hyphen_values = true)]
    pub kappa: String,
    /// Coefficient of restitution, in [0, 1] [default: 1/100, or the gamma of a body file given
    /// with --body FILE; --gamma overrides the file's]. certify also takes an interval a:b: one
    /// certificate for every gamma in [a, b] (a box certificate of a regular polygon, with --kappa
    /// a number or an interval; a family certificate of a general body).
    #[arg(long, allow_hyphen_values = true)]
    pub gamma: Option<String>,
}

/// --gamma when it is not given (and no body file gives one).
pub const DEFAULT_GAMMA: &str = "1/100";

impl BodyArgs {
    /// --gamma as typed, or its default.
    pub fn gamma_text(&self) -> &str {
        self.gamma.as_deref().unwrap_or(DEFAULT_GAMMA)
    }

    /// n, kappa and gamma read exactly (decimals such as 0.01 are 1/100).
    pub fn parse(&self) -> Result<(u64, Q, Q), String> {
        let n: u64 =
            self.n.trim().parse().map_err(|_| format!("--n: {:?} is not a positive integer", self.n))?;
        let kappa = parse_user_number(&self.kappa).map_err(|e| format!("--kappa: {e}"))?;
        let gamma = parse_user_number(self.gamma_text()).map_err(|e| format!("--gamma: {e}"))?;
        Ok((n, kappa, gamma))
    }

    /// n, and kappa and gamma each as a number (`[x, x]`) or a closed interval written `a:b`.
    pub fn parse_ranges(&self) -> Result<(u64, [Q; 2], [Q; 2]), String> {
        let (n, _, _) = BodyArgs { kappa: "1".into(), gamma: Some("0".into()), ..self.clone() }.parse()?;
        Ok((n, range("--kappa", &self.kappa)?, range("--gamma", self.gamma_text())?))
    }
}

/// A body the model refuses, as a usage error naming the option, the value given and what
/// `command` accepts for n (e.g. "n = 2, 3, 4 or 6 (rational cos 2π/n)").
pub fn body_error(e: &BodyError, n: u64, kappa: &Q, gamma: &Q, ns: &str) -> String {
    match e {
        BodyError::UnsupportedN(_) => format!("--n: {n} is not supported here: give {ns}"),
        BodyError::KappaNotPositive => format!("--kappa: {kappa} is not accepted: kappa must be > 0"),
        BodyError::GammaOutOfRange => format!("--gamma: {gamma} is not accepted: gamma must lie in [0, 1]"),
    }
}

/// A number `x` (the interval [x, x]) or a closed interval `a:b` with a <= b, read exactly.
pub fn range(flag: &str, text: &str) -> Result<[Q; 2], String> {
    let num = |t: &str| parse_user_number(t).map_err(|e| format!("{flag}: {e}"));
    match text.split_once(':') {
        None => {
            let x = num(text)?;
            Ok([x.clone(), x])
        }
        Some((a, b)) => {
            let (lo, hi) = (num(a)?, num(b)?);
            if lo > hi {
                return Err(format!("{flag}: the interval {text} is empty ({lo} > {hi})"));
            }
            Ok([lo, hi])
        }
    }
}

/// Runs a parsed command line in an environment.
pub fn run(cli: Cli, env: &Env) -> Outcome {
    match cli.command {
        Command::Certify(a) => certify_cmd::run(a, env),
        Command::CertifyOrbit(a) => orbit_cmd::run(a, env),
        Command::Basin(a) => basin_cmd::run(a, env),
        Command::BasinMap(a) => basin_map_cmd::run(a, env),
        Command::Verify(a) => verify_cmd::run(a, env),
        Command::Convert(a) => convert_cmd::run(a),
        Command::Simulate(a) => simulate_cmd::run(a),
        Command::Classify(a) => classify_cmd::run(a),
        Command::Bodies(a) => bodies_cmd::run(a),
        Command::Prove(a) => prove_cmd::run(a),
        Command::CheckProof(a) => check_proof_cmd::run(a),
        Command::Refute(a) => refute_cmd::run(a, env),
        Command::Cover(a) => cover_cmd::run(a),
        Command::Map(a) => map_cmd::run(a),
        Command::Plot(a) => plot_cmd::run(a),
        Command::Reproduce(a) => reproduce_cmd::run(a),
        Command::Schema(a) => schema_cmd::run(a),
    }
}

/// Parses the process arguments, runs the command, reports errors and maps the outcome to the
/// exit status.
pub fn main() -> ExitCode {
    let cli = Cli::parse();
    let json = cli.command.json();
    let outcome = run(cli, &Env::default());
    report_error(&outcome, json);
    ExitCode::from(outcome.exit_code())
}

/// Reports a usage or internal error: under `--json`, as a `chatter.error/1` object on stdout
/// unless the command already printed its JSON report (`verify` with an unreadable input: the
/// report lists it); otherwise as text on stderr.
pub fn report_error(outcome: &Outcome, json: bool) {
    use crate::report::error::{ErrorKind, ErrorReport};
    let (kind, message) = match outcome {
        Outcome::Usage(m) => (ErrorKind::Usage, m),
        Outcome::Internal(m) => (ErrorKind::Internal, m),
        Outcome::Success | Outcome::Negative => return,
    };
    if json && !JSON_EMITTED.load(std::sync::atomic::Ordering::SeqCst) {
        emit_report(&ErrorReport::new(kind, outcome.exit_code(), message));
        return;
    }
    match kind {
        ErrorKind::Usage => eprintln!("error: {message}"),
        ErrorKind::Internal => eprintln!("internal error (a bug in chatter, please report it): {message}"),
    }
}

/// Whether a JSON report has been printed on stdout by this process.
static JSON_EMITTED: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// Prints a report as one line of JSON on stdout (see [`emit`]).
pub(crate) fn emit_report<R: crate::report::Report>(report: &R) {
    JSON_EMITTED.store(true, std::sync::atomic::Ordering::SeqCst);
    emit(&crate::report::to_line(report));
}

/// Exit status when stdout is closed early (as if killed by SIGPIPE: 128 + 13).
pub const EXIT_BROKEN_PIPE: i32 = 141;

/// Prints a line on stdout; if the reader has gone away (`chatter verify ... | head`), exits
/// quietly instead of panicking.
pub(crate) fn emit(line: &str) {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    if let Err(e) = writeln!(out, "{line}").and_then(|()| out.flush()) {
        if e.kind() == std::io::ErrorKind::BrokenPipe {
            std::process::exit(EXIT_BROKEN_PIPE);
        }
        eprintln!("error: cannot write to stdout: {e}");
        std::process::exit(i32::from(Outcome::Usage(String::new()).exit_code()));
    }
}
