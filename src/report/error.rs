//! `chatter.error/1`: an error under `--json` (bad arguments, unreadable input, internal error),
//! printed on stdout instead of the text on stderr, with the same exit status.

use super::Report;
use schemars::JsonSchema;
use serde::Serialize;

/// What kind of error.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, JsonSchema)]
#[serde(rename_all = "kebab-case")]
pub enum ErrorKind {
    /// Bad usage or unreadable input (exit status 2).
    Usage,
    /// A bug in chatter or a bignum library, such as the two backends disagreeing (exit status 3).
    Internal,
}

/// An error report.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct ErrorReport {
    /// Always `chatter.error/1`.
    pub schema: &'static str,
    pub kind: ErrorKind,
    /// The process's exit status (2 or 3).
    pub exit_code: u8,
    /// The message the text mode prints on stderr.
    pub message: String,
}

impl Report for ErrorReport {
    const SCHEMA: &'static str = "chatter.error/1";
}

impl ErrorReport {
    /// An error of `kind` with its exit status and message.
    pub fn new(kind: ErrorKind, exit_code: u8, message: &str) -> ErrorReport {
        ErrorReport { schema: Self::SCHEMA, kind, exit_code, message: message.to_string() }
    }
}
