//! `chatter schema`: the JSON Schemas of every `--json` output, generated from the report types
//! (docs/json.md).

use super::{Outcome, emit};
use crate::report::{schema_file_name, schema_text, schemas};
use clap::Args;
use std::path::PathBuf;

/// Raw arguments of `chatter schema`.
#[derive(Args, Debug)]
#[command(
    after_help = "Writes one file per schema name, e.g. chatter.classify.v1.schema.json, generated from the\n\
Rust report types. With --check, writes nothing and exits 1 if a file is missing or differs.\n\n\
Example:\n  chatter schema --out docs/schema"
)]
pub struct SchemaArgs {
    /// The folder to write into.
    #[arg(long, default_value = "docs/schema")]
    pub out: PathBuf,
    /// Compare with the files in --out instead of writing them.
    #[arg(long)]
    pub check: bool,
}

pub fn run(a: SchemaArgs) -> Outcome {
    if !a.check
        && let Err(e) = std::fs::create_dir_all(&a.out)
    {
        return Outcome::Usage(format!("cannot create {}: {e}", a.out.display()));
    }
    let mut stale = 0;
    for (name, schema) in schemas() {
        let path = a.out.join(schema_file_name(name));
        let text = schema_text(&schema);
        if a.check {
            if std::fs::read_to_string(&path).ok().as_deref() != Some(text.as_str()) {
                emit(&format!("stale: {} (run `chatter schema --out {}`)", path.display(), a.out.display()));
                stale += 1;
            }
        } else if let Err(e) = std::fs::write(&path, text) {
            return Outcome::Usage(format!("cannot write {}: {e}", path.display()));
        } else {
            emit(&format!("{name} -> {}", path.display()));
        }
    }
    Outcome::from_answer(stale == 0)
}
