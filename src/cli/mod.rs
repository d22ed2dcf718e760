//! The command line: raw arguments (clap) are validated into library requests (ripgrep style:
//! two layers), then a thin driver calls the library and prints.
//!
//! Exit status: 0 success; 1 a negative answer (not certified, a certificate rejected);
//! 2 bad usage or unreadable input; 3 internal error (the two backends disagree).

mod bodies_cmd;
mod certify_cmd;
mod classify_cmd;
mod prove_cmd;
mod simulate_cmd;
mod verify_cmd;

use crate::exact::{Q, parse_user_number};
use clap::{Args, Parser, Subcommand};
use std::process::ExitCode;

pub const EXIT_OK: u8 = 0;
pub const EXIT_NEGATIVE: u8 = 1;
pub const EXIT_USAGE: u8 = 2;
pub const EXIT_INTERNAL: u8 = 3;

#[derive(Parser, Debug)]
#[command(
    name = "chatter",
    version,
    about = "Exact certificates that a rigid body dropped flat onto a floor comes to rest by complete chatter",
    long_about = "Exact certificates that a rigid body dropped flat onto a floor comes to rest by complete \
chatter (infinitely many impacts in finite time).\n\n\
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
    /// Find, exactify and kernel-check an effectively invariant cone; write a certificate.
    Certify(certify_cmd::CertifyArgs),
    /// Check certificate files (or directories of *.ron files) with the trusted kernel.
    Verify(verify_cmd::VerifyArgs),
    /// Decide the paper's spectral criteria exactly at one body, with the evidence.
    Classify(classify_cmd::ClassifyArgs),
    /// The catalogue of bodies: kappa from geometry, exact CC and PCC thresholds in gamma.
    Bodies(bodies_cmd::BodiesArgs),
    /// Prove the paper's square-case lemmas symbolically; write proofs/square.md and .ron.
    Prove(prove_cmd::ProveArgs),
    /// Simulate drops event by event (f64 or exact) and classify them as CC, PCC or ICC.
    Simulate(simulate_cmd::SimulateArgs),
}

/// The body as typed (raw layer), shared by certify, classify and simulate; each command
/// validates the ranges it supports.
#[derive(Args, Debug, Clone)]
pub struct BodyArgs {
    /// Number of contacts: 2 (the rod) or a regular n-gon (exact models for 3, 4, 6).
    #[arg(long, default_value = "4", allow_hyphen_values = true)]
    pub n: String,
    /// kappa = rho^2 / R^2 (radius of gyration over circumradius, squared), > 0.
    #[arg(long, default_value = "1/6", allow_hyphen_values = true)]
    pub kappa: String,
    /// Coefficient of restitution, in [0, 1].
    #[arg(long, default_value = "1/100", allow_hyphen_values = true)]
    pub gamma: String,
}

impl BodyArgs {
    /// n, kappa and gamma read exactly (decimals such as 0.01 are 1/100).
    pub fn parse(&self) -> Result<(u64, Q, Q), String> {
        let n: u64 =
            self.n.trim().parse().map_err(|_| format!("--n: {:?} is not a positive integer", self.n))?;
        let kappa = parse_user_number(&self.kappa).map_err(|e| format!("--kappa: {e}"))?;
        let gamma = parse_user_number(&self.gamma).map_err(|e| format!("--gamma: {e}"))?;
        Ok((n, kappa, gamma))
    }
}

/// Parses the process arguments and runs the command.
pub fn main() -> ExitCode {
    let cli = Cli::parse();
    let code = match cli.command {
        Command::Certify(a) => certify_cmd::run(a),
        Command::Verify(a) => verify_cmd::run(a),
        Command::Simulate(a) => simulate_cmd::run(a),
        Command::Classify(a) => classify_cmd::run(a),
        Command::Bodies(a) => bodies_cmd::run(a),
        Command::Prove(a) => prove_cmd::run(a),
    };
    ExitCode::from(code)
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
        std::process::exit(i32::from(EXIT_USAGE));
    }
}

/// Prints a usage error and returns the usage exit status.
pub(crate) fn usage_error(msg: impl std::fmt::Display) -> u8 {
    eprintln!("error: {msg}");
    EXIT_USAGE
}
