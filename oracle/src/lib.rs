//! `chatter-oracle`: an independent checker of `chatter` certificates and refutations, for
//! differential testing against the trusted kernel (`chatter-kernel`), with which it shares no
//! code. It reads the files by the documented rules (docs/certificate-format.md) with its own
//! parser, parses numbers itself, and derives every map, cone and check from docs/model.md with
//! its own arithmetic (num-rational; number fields Q(cos 2π/n) of its own) and its own, simpler
//! and slower, geometry: points on the plane v = -1, gift wrapping, brute-force half-plane
//! intersection, cones from generators. What it decides for each kind, and whether the verdict is
//! two-sided or one-sided, is in oracle/README.md.
//!
//! - [`judge`]: the verdict on a file's text.
//! - [`compare`]: the comparison of a kernel verdict (as plain data) with the oracle's.
//! - [`mutate`]: structure-aware mutations of files, decoded from bytes.
#![forbid(unsafe_code)]
#![deny(missing_docs)]
#![deny(clippy::float_arithmetic)]

pub mod arith;
pub mod basin;
pub mod claim;
pub mod compare;
pub mod cone3;
pub mod convex;
pub mod isolate;
pub mod kinds;
pub mod mutate;
pub mod orbit;
pub mod plane;
pub mod read;
pub mod regular;
pub mod verdict;

use kinds::limits::Limits;
use read::header::{Reader, header};
use read::parse::{SyntaxFault, parse};
use read::{Encoding, Value};
use verdict::{Checked, Judgement, Kind, Outcome, Report, Sided};

/// The verdict on a file's text in the given encoding, with the default limits.
pub fn judge(text: &str, encoding: Encoding) -> Judgement {
    judge_with(text, encoding, &Limits::default())
}

/// The verdict on a file's text, with the given limits.
pub fn judge_with(text: &str, encoding: Encoding, limits: &Limits) -> Judgement {
    let value = match parse(text, encoding) {
        Ok(v) => v,
        Err(SyntaxFault::Syntax(at, what)) => {
            return Judgement::reject(Kind::Unread, "syntax", format!("byte {at}: expected {what}"));
        }
        Err(SyntaxFault::DuplicateKey(k)) => {
            return Judgement::reject(Kind::Unread, "duplicate-field", format!("key {k:?} given twice"));
        }
    };
    let reader = match header(&value) {
        Ok(r) => r,
        Err(f) => return unread(f),
    };
    judge_value(&value, reader, limits)
}

fn unread(f: verdict::Fail) -> Judgement {
    Judgement {
        kind: Kind::Unread,
        sided: Sided::Two,
        outcome: Outcome::Reject { codes: f.codes, why: f.why },
        time_to_rest_bound: None,
        gamma_interval: None,
    }
}

fn done(kind: Kind, sided: Sided, r: Checked<Report>) -> Judgement {
    let outcome = match r {
        Ok(report) => Outcome::Accept(Box::new(report)),
        Err(f) => Outcome::Reject { codes: f.codes, why: f.why },
    };
    Judgement { kind, sided, outcome, time_to_rest_bound: None, gamma_interval: None }
}

fn judge_value(value: &Value, reader: Reader, limits: &Limits) -> Judgement {
    match reader {
        Reader::Cone(_) => match kinds::cone::read(value) {
            Err(f) => unread(f),
            Ok(file) => match kinds::cone::checked(&file, limits) {
                Ok((kind, report, bound)) => {
                    Judgement { time_to_rest_bound: bound, ..done(kind, Sided::Two, Ok(report)) }
                }
                Err(f) => done(Kind::Cone, Sided::Two, Err(f)),
            },
        },
        Reader::Refutation => match kinds::refutation::read(value) {
            Err(f) => unread(f),
            Ok(file) => done(Kind::Refutation, Sided::Two, kinds::refutation::check(&file, limits)),
        },
        Reader::Family => match kinds::family::read(value) {
            Err(f) => unread(f),
            Ok(file) => {
                let judged = done(Kind::Family, Sided::Two, kinds::family::check(&file, limits));
                let interval = judged.accepted().then(|| file.gamma_interval()).flatten();
                Judgement { gamma_interval: interval, ..judged }
            }
        },
        Reader::Basin => match kinds::basin::read(value) {
            Err(f) => unread(f),
            Ok(file) => basin(&file, limits),
        },
        Reader::Rest => match kinds::rest::read(value) {
            Err(f) => unread(f),
            Ok(file) => match kinds::rest::check(&file, limits) {
                Ok((report, bound)) => {
                    Judgement { time_to_rest_bound: Some(bound), ..done(Kind::Rest, Sided::Two, Ok(report)) }
                }
                Err(f) => done(Kind::Rest, Sided::Two, Err(f)),
            },
        },
        Reader::RestFamily => match kinds::rest_family::read(value) {
            Err(f) => unread(f),
            Ok(file) => match kinds::rest_family::check(&file, limits) {
                Ok((report, bound)) => Judgement {
                    time_to_rest_bound: Some(bound),
                    gamma_interval: file.gamma_interval(),
                    ..done(Kind::RestFamily, Sided::Two, Ok(report))
                },
                Err(f) => done(Kind::RestFamily, Sided::Two, Err(f)),
            },
        },
        Reader::Orbit => match kinds::orbit::read(value) {
            Err(f) => unread(f),
            Ok(file) => match kinds::orbit::rules(&file, limits) {
                Err(f) => done(Kind::Orbit, Sided::Two, Err(f)),
                Ok(orbit) => {
                    let r = kinds::orbit::check(&orbit).map(|()| Report {
                        claim: "CompleteChatterFromSet".into(),
                        n: orbit.body.n as u64,
                        ..Report::default()
                    });
                    let accepted = r.is_ok();
                    let judged = done(Kind::Orbit, Sided::One, r);
                    Judgement { time_to_rest_bound: accepted.then(|| orbit.time_to_rest()), ..judged }
                }
            },
        },
    }
}

/// A basin certificate: rules B1, O1 (two-sided), then O2, B3 and B4 (one-sided overall).
fn basin(file: &kinds::basin::BasinFile, limits: &Limits) -> Judgement {
    let checked = kinds::basin::rules(file, limits).and_then(|b| kinds::basin::check(file, &b));
    match checked {
        Err(f) => done(Kind::Basin, Sided::One, Err(f)),
        Ok(found) => {
            let n = kinds::basin::n(file);
            let report = Report { n, basin: Some((found.shares, found.leaves)), ..Report::default() };
            let time = found.time.as_ref().map(kinds::basin::time_text);
            Judgement { time_to_rest_bound: time, ..done(Kind::Basin, Sided::One, Ok(report)) }
        }
    }
}
