//! `chatter convert`: a certificate or refutation between RON and its JSON twin
//! (docs/certificate-format.md §11).

use super::{Outcome, emit};
use crate::convert::{Target, convert};
use crate::verify::DEFAULT_MAX_FILE_SIZE;
use crate::verify::read::{Input, read_input};
use clap::{Args, ValueEnum};
use std::path::PathBuf;

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum ToArg {
    /// The JSON twin.
    Json,
    /// RON, as the kernel's writer writes it.
    Ron,
}

/// Raw arguments of `chatter convert`.
#[derive(Args, Debug)]
#[command(
    after_help = "Reads a certificate or refutation, plain or gzip'd (JSON if the name ends in .json or\n\
.json.gz, RON otherwise), with the format's strict syntax and schema, and writes it in the other\n\
encoding (or the same one, normalised). Lossless: RON -> JSON -> RON gives the kernel writer's\n\
RON byte for byte. The numbers and the cone are not checked: use `chatter verify`.\n\n\
Exit status 0 on success, 2 if the input cannot be read or is not a certificate or refutation.\n\n\
Examples:\n  chatter convert square.ron --to json -o square.json\n  chatter convert square.json --to ron"
)]
pub struct ConvertArgs {
    /// The certificate or refutation file.
    pub file: PathBuf,
    /// The encoding to write.
    #[arg(long, value_enum)]
    pub to: ToArg,
    /// Write here instead of standard output.
    #[arg(short = 'o', long)]
    pub output: Option<PathBuf>,
}

pub fn run(a: ConvertArgs) -> Outcome {
    let shown = a.file.display();
    let text = match read_input(&a.file, DEFAULT_MAX_FILE_SIZE) {
        Input::Text { text, .. } => text,
        Input::TooLarge { what } => {
            return Outcome::Usage(format!(
                "{shown}: {what}, more than the limit max-file-size = {DEFAULT_MAX_FILE_SIZE} bytes"
            ));
        }
        Input::Unreadable(why) => return Outcome::Usage(format!("{shown}: {why}")),
    };
    let target = match a.to {
        ToArg::Json => Target::Json,
        ToArg::Ron => Target::Ron,
    };
    let out = match convert(&text, crate::verify::files::encoding_of(&a.file), target) {
        Ok(out) => out,
        Err(e) => return Outcome::Usage(format!("{shown}: {e}")),
    };
    match &a.output {
        Some(path) => {
            if let Err(e) = std::fs::write(path, out) {
                let why = crate::verify::files::describe(&e);
                return Outcome::Usage(format!("cannot write {}: {why}", path.display()));
            }
        }
        None => emit(out.trim_end_matches('\n')),
    }
    Outcome::Success
}
