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

pub use crate::json::{
    Interval, Number, Report, Timings, Verdict, ms, schema_file_name, schema_of, schema_text, to_line,
    to_value,
};

/// Every report's schema name and JSON Schema, for `docs/schema/` (one file per name).
pub fn schemas() -> Vec<(&'static str, serde_json::Value)> {
    fn one<R: Report>() -> (&'static str, serde_json::Value) {
        (R::SCHEMA, schema_of::<R>())
    }
    vec![
        one::<crate::basin::map::BasinMapSummary>(),
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
