//! Errors as Python exceptions: a [`Fail`] names its class in `chatter._errors` (whose exit
//! code follows `chatter`'s exit statuses), its rejection code and its message; [`run`] runs the
//! work without the GIL and turns a failure, or a panic (a bug), into that exception.

use pyo3::prelude::*;
use std::panic::{AssertUnwindSafe, catch_unwind};

/// Which exception class of `chatter._errors`.
#[derive(Clone, Copy, Debug)]
pub enum Kind {
    /// Bad input or unreadable input (exit status 2): `UsageError`, also a `ValueError`.
    Usage,
    /// A negative answer (exit status 1): `NotCertifiedError`.
    Negative,
    /// The backends disagree, or a bug (exit status 3): `InternalError`.
    Internal,
}

/// A failure: the exception class, the rejection code (e.g. "no-cone") and the message.
#[derive(Debug)]
pub struct Fail {
    pub kind: Kind,
    pub code: String,
    pub message: String,
}

impl Fail {
    pub fn usage(code: &str, message: impl Into<String>) -> Fail {
        Fail { kind: Kind::Usage, code: code.into(), message: message.into() }
    }
    pub fn negative(code: &str, message: impl Into<String>) -> Fail {
        Fail { kind: Kind::Negative, code: code.into(), message: message.into() }
    }
    pub fn internal(code: &str, message: impl Into<String>) -> Fail {
        Fail { kind: Kind::Internal, code: code.into(), message: message.into() }
    }

    /// The Python exception (`chatter._errors.<class>(message, code)`).
    fn into_py(self, py: Python<'_>) -> PyErr {
        let class = match self.kind {
            Kind::Usage => "UsageError",
            Kind::Negative => "NotCertifiedError",
            Kind::Internal => "InternalError",
        };
        let made = py
            .import("chatter._errors")
            .and_then(|m| m.getattr(class))
            .and_then(|c| c.call1((self.message, self.code)));
        match made {
            Ok(exception) => PyErr::from_value(exception),
            Err(e) => e,
        }
    }
}

/// The text of a panic's payload.
fn panic_text(payload: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        (*s).to_string()
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s.clone()
    } else {
        "unknown panic".into()
    }
}

/// Runs `work` with the GIL released (other Python threads run meanwhile) and returns its value
/// as JSON text; a failure becomes its exception, a panic an `InternalError` with code "panic".
pub fn run(
    py: Python<'_>,
    work: impl FnOnce() -> Result<serde_json::Value, Fail> + Send,
) -> PyResult<String> {
    let out = py.detach(move || catch_unwind(AssertUnwindSafe(work)).map(|r| r.map(|v| crate::text(&v))));
    match out {
        Ok(Ok(text)) => Ok(text),
        Ok(Err(fail)) => Err(fail.into_py(py)),
        Err(payload) => {
            let msg = format!("a bug in chatter (please report it): panic: {}", panic_text(&*payload));
            Err(Fail::internal("panic", msg).into_py(py))
        }
    }
}
