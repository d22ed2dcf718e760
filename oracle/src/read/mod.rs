//! Reading certificate and refutation files by the documented rules (docs/certificate-format.md
//! §2 "Strict syntax", §11 "Strict JSON syntax"), with the oracle's own recursive-descent parser
//! (the kernel uses ron, serde_json and serde's derived schema): the text becomes a [`Value`]
//! tree, then each kind's schema is checked by hand on the tree.

pub mod header;
pub mod parse;
pub mod schema;
pub mod value;
pub mod write;

pub use value::Value;

/// The encoding of a file: RON or its JSON twin (§11).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Encoding {
    /// RON, the strict subset of §2.
    Ron,
    /// JSON, the strict subset of §11.
    Json,
}

impl Encoding {
    /// By the file name: `*.json` or `*.json.gz` in any letter case is JSON, anything else RON.
    pub fn of_name(name: &str) -> Encoding {
        let lower = name.to_ascii_lowercase();
        if lower.ends_with(".json") || lower.ends_with(".json.gz") { Encoding::Json } else { Encoding::Ron }
    }
}
