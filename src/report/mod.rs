//! Typed, versioned reports: what every `--json` output of the command line is, as Rust types
//! (docs/json.md).
//!
//! Each report is a struct that derives [`serde::Serialize`] and [`schemars::JsonSchema`] and
//! carries its schema name and version in its first field `schema` (e.g. `"chatter.classify/1"`).
//! A library function per command builds it (for example [`classify::classify`],
//! [`bodies::bodies`], [`simulate::single`], [`certify::certify`], [`verify::verify`]); the
//! command line only prints it, and any other front end (a Python binding) can call the same
//! function and turn the struct into a dictionary with [`to_value`].
//!
//! Conventions, the same in every report:
//! - exact numbers are canonical strings `"p/q"` (or `"p"`) beside their nearest `f64`
//!   ([`Number`]);
//! - a command's answer is a [`Verdict`], one vocabulary for every command;
//! - nothing depends on the clock unless timings were asked for (`--timings`), so the default
//!   output is byte-stable;
//! - the JSON Schemas in `docs/schema/` are generated from these types by [`schemas`]
//!   (`chatter schema --out docs/schema`).

pub mod bodies;
pub mod certify;
pub mod claims;
pub mod classify;
pub mod classify_general;
pub mod classify_orbit;
pub mod convex;
pub mod error;
pub mod finder;
pub mod largest_gamma;
pub mod map;
pub mod orbit;
pub mod prove;
pub mod refute;
pub mod simulate;
pub mod verify;

use crate::exact::{Q, QExt};
use schemars::JsonSchema;
use serde::Serialize;

/// A report of one command: a serialisable type with a schema name and version.
pub trait Report: Serialize + JsonSchema {
    /// The schema name and version, `chatter.<command>/<major>` (docs/json.md).
    const SCHEMA: &'static str;
}

/// An exact rational number: its canonical text and its nearest `f64`.
#[derive(Clone, Debug, PartialEq, Serialize, JsonSchema)]
pub struct Number {
    /// Canonical text: `p/q` in lowest terms with q > 1, or the integer `p`.
    pub exact: String,
    /// The nearest `f64` (for plotting and quick comparisons; the exact text is the value).
    pub f64: f64,
}

impl Number {
    /// `q` as canonical text and f64.
    pub fn of(q: &Q) -> Number {
        Number { exact: q.to_string(), f64: q.to_f64() }
    }

    /// A number from canonical text (`p/q`); `None` if the text is not a rational.
    pub fn parse(text: &str) -> Option<Number> {
        text.parse::<Q>().ok().map(|q| Number::of(&q))
    }
}

/// A closed interval with exact rational ends (an enclosure of an irrational number, or a
/// parameter box; `lo == hi` for a single number).
#[derive(Clone, Debug, PartialEq, Serialize, JsonSchema)]
pub struct Interval {
    pub lo: Number,
    pub hi: Number,
}

impl Interval {
    /// [lo, hi].
    pub fn of(lo: &Q, hi: &Q) -> Interval {
        Interval { lo: Number::of(lo), hi: Number::of(hi) }
    }
}

/// The answer of a command, or of one input of it: one vocabulary for every command.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, JsonSchema)]
#[serde(rename_all = "kebab-case")]
pub enum Verdict {
    /// A certificate was made and accepted by the kernel on both backends (`certify`).
    Certified,
    /// No certificate could be made (`certify`).
    NotCertified,
    /// A refutation was derived and accepted by the kernel (`refute`).
    Refuted,
    /// No refutation could be derived (`refute`).
    NotRefuted,
    /// The kernel accepts the file or proof (`verify`, `check-proof`, `prove`).
    Accepted,
    /// The kernel rejects it, for a located reason (`verify`, `check-proof`, `prove`).
    Rejected,
    /// The input could not be read, or the backends disagree (`verify`).
    Error,
}

/// Wall-clock times in milliseconds, only with `--timings` (they change from run to run).
#[derive(Clone, Debug, PartialEq, Serialize, JsonSchema)]
pub struct Timings {
    /// The float search (or the exact derivation, for `refute`).
    pub search_ms: f64,
    /// The exactifier (0 when it did not run).
    pub exactify_ms: f64,
    /// The kernel's check on the backends.
    pub kernel_ms: f64,
}

/// Milliseconds of a duration.
pub fn ms(d: std::time::Duration) -> f64 {
    d.as_secs_f64() * 1e3
}

/// The report as a JSON value (for bindings: a Python dict via serde_json).
pub fn to_value<R: Report>(report: &R) -> serde_json::Value {
    serde_json::to_value(report).expect("reports serialise (string keys, finite or null numbers)")
}

/// The report as one line of JSON text, as the command line prints it.
pub fn to_line<R: Report>(report: &R) -> String {
    serde_json::to_string(report).expect("reports serialise (string keys, finite or null numbers)")
}

/// The schema of a report type, with its name in `title` and `schema` required to be `R::SCHEMA`.
pub fn schema_of<R: Report>() -> serde_json::Value {
    let mut s = serde_json::to_value(schemars::schema_for!(R)).expect("a schema is JSON");
    s["title"] = serde_json::Value::String(R::SCHEMA.to_string());
    s["properties"]["schema"] =
        serde_json::json!({"const": R::SCHEMA, "description": "Schema name and version."});
    s
}

/// The file name of a schema in `docs/schema/`: `chatter.classify/1` -> `chatter.classify.v1.schema.json`.
pub fn schema_file_name(schema: &str) -> String {
    match schema.split_once('/') {
        Some((name, version)) => format!("{name}.v{version}.schema.json"),
        None => format!("{schema}.schema.json"),
    }
}

/// Every report's schema name and JSON Schema, for `docs/schema/` (one file per name).
pub fn schemas() -> Vec<(&'static str, serde_json::Value)> {
    fn one<R: Report>() -> (&'static str, serde_json::Value) {
        (R::SCHEMA, schema_of::<R>())
    }
    vec![
        one::<bodies::BodiesReport>(),
        one::<certify::CertifyReport>(),
        one::<prove::CheckProofReport>(),
        one::<classify::ClassifyReport>(),
        one::<crate::cover::CoverSummary>(),
        one::<error::ErrorReport>(),
        one::<largest_gamma::LargestGammaReport>(),
        one::<map::MapSummary>(),
        one::<orbit::CertifyOrbitReport>(),
        one::<prove::ProveReport>(),
        one::<refute::RefuteReport>(),
        one::<simulate::SimulateReport>(),
        one::<simulate::SimulateBatchReport>(),
        one::<verify::VerifyReport>(),
    ]
}

/// The text of a schema file: pretty JSON with a final newline.
pub fn schema_text(schema: &serde_json::Value) -> String {
    serde_json::to_string_pretty(schema).expect("a schema is JSON") + "\n"
}
