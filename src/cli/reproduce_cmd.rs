//! `chatter reproduce`: the paper's results regenerated into a folder, with report.md and
//! report.html (issue 12; README's first command).

use super::{self as cli, emit};
use crate::reproduce::{self, Plan, Verdict};
use clap::Args;
use std::io::IsTerminal;
use std::path::PathBuf;

/// Raw arguments of `chatter reproduce`.
#[derive(Args, Debug)]
#[command(
    after_help = "Regenerates into DIR: the bodies table, the rod theorem, the flat triangle plate, the \
PCC condition for n >= 4, the n = 3 band where drops chatter above the threshold, the three maps (n = 3, 4 with \
exact certificates, n = 5 with exact criteria in Q(cos 2pi/5)) and their simulation maps, certificates and \
their cones, and the square-case proof; then DIR/report.md and DIR/report.html, which set each result \
beside the paper's claim with \"agrees\" or \"differs\", the evidence and the command that shows it.\n\n\
Figures are SVG and PNG (PNG needs the DejaVu Sans font: Debian fonts-dejavu-core, or CHATTER_FONT).\n\
--quick: 16 x 16 maps (12 x 12 for n = 5) with 6 drops per point, about 40 s on 2 cores, most of it \
the maps' simulations (exact runs with their proofs); without --quick: 100 x 100 maps \
(80 x 80 for n = 5) with 20 drops, 39 to 44 times the points and 3.3 times the drops: at --quick's \
35 to 80 ms per point on 2 cores, about half an hour, more if the extra drops need more orbit \
certificates (an estimate, not measured; each step's time is at the end of report.md).\n\n\
Exit status 0 when the report was written (whatever the verdicts), 2 on bad input or unwritable output, \
3 on an internal error."
)]
pub struct ReproduceArgs {
    /// Output folder.
    #[arg(long, short = 'o', value_name = "DIR", default_value = "out")]
    pub out: PathBuf,
    /// Small grids and fewer drops (for CI and a first look).
    #[arg(long)]
    pub quick: bool,
}

pub fn run(a: ReproduceArgs) -> cli::Outcome {
    let tty = std::io::stderr().is_terminal();
    let start = std::time::Instant::now();
    let step = |name: &str| {
        if tty {
            eprintln!("[{:6.1} s] {name}", start.elapsed().as_secs_f64());
        }
    };
    let report = match reproduce::run(&a.out, Plan::new(a.quick), super::map_cmd::request_of, &step) {
        Ok(r) => r,
        Err(e) => return cli::Outcome::Usage(e),
    };
    for (i, it) in report.items.iter().enumerate() {
        emit(&format!("{:2}. {:<16} {}", i + 1, it.verdict.word(), it.title));
    }
    let n = |v: Verdict| report.items.iter().filter(|i| i.verdict == v).count();
    emit(&format!(
        "{} agree, {} differ, {} not checked yet; {} and {} written in {:.1} s",
        n(Verdict::Agrees),
        n(Verdict::Differs),
        n(Verdict::NotChecked),
        a.out.join("report.md").display(),
        a.out.join("report.html").display(),
        start.elapsed().as_secs_f64()
    ));
    cli::Outcome::Success
}
