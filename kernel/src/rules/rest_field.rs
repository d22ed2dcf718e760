//! Time-to-rest certificates where cos(2π/n) is irrational (features `rest` and `field`;
//! docs/certificate-format.md §16, version 3; why: docs/kernel-soundness.md §10, "Number
//! fields"): the rules of [`super::rest`], run over Q(cos 2π/n). Rules before them, in order:
//!
//! - the body: n <= 64 (`unsupported-body`);
//! - version: 3 or more (`unsupported-version`);
//! - numbers: every number but B a canonical element of Q(cos 2π/n) (`bad-number`), B a canonical
//!   rational.

use super::field as field_rules;
use super::generators::Generators;
use super::rest::{FIELD_VERSION, Numbers, Rested, at_point, body, contacts, file};
use crate::exact::{Algebraic, AlgebraicInt, CosField, Field, MAX_N, ParseLimits};
use crate::model::polygon::Polygon;
use crate::reject::{Code, Detail, KindDetail, Needs, Rejection};
use crate::syntax::cone::Generator;
use crate::syntax::numbers::number;
use crate::syntax::rest::TimeToRest;
use std::sync::Arc;

/// The graph's rules over Q(cos 2π/n), n = 5, 7, 8, ..., 64: every number of the file is read
/// as an element of the field, and such a file says version [`FIELD_VERSION`] or more.
pub(super) fn in_field<F: Field>(cert: &TimeToRest, limits: ParseLimits) -> Result<Rested, Rejection> {
    if CosField::<F>::new(contacts(cert)).is_some() && cert.version < FIELD_VERSION {
        let detail = Detail::Needs(Needs::FieldElements, cert.version);
        return Err(Rejection::at(Code::UnsupportedVersion, "version", detail));
    }
    field_graph::<F>(cert, limits)
}

/// The body and the graph's rules in Q(cos 2π/n), for any n from 3 to 64.
fn field_graph<F: Field>(cert: &TimeToRest, limits: ParseLimits) -> Result<Rested, Rejection> {
    let n = contacts(cert);
    let Some(field) = CosField::<F>::new(n) else {
        return Err(Rejection::at(Code::UnsupportedBody, "body.n", KindDetail::Contacts(n, MAX_N)));
    };
    let nums = Elements(field.clone(), limits);
    at_point(&body(cert, &nums, |n, k, g| Polygon::with_cosine(n, field.generator(), k, g))?, cert, &nums)
}

/// The file's rules, then the body and the graph's in Q(cos 2π/n) also where cos(2π/n) is
/// rational (a field of degree 1, any version): a second path for n = 3, 4, 6, against which the
/// field path is tested.
pub fn check_in_field<F: Field>(cert: &TimeToRest, limits: ParseLimits) -> Result<Rested, Rejection> {
    file(cert, limits)?;
    field_graph::<F>(cert, limits)
}

/// Canonical elements of Q(cos 2π/n) over the backend `F`.
struct Elements<F: Field>(Arc<CosField<F>>, ParseLimits);

impl<F: Field> Numbers for Elements<F> {
    type E = Algebraic<F>;
    fn limits(&self) -> ParseLimits {
        self.1
    }
    fn number(&self, path: &str, text: &str) -> Result<Algebraic<F>, Rejection> {
        field_rules::element(&self.0, path, text, self.1)
    }
    fn rational(&self, path: &str, text: &str) -> Result<Algebraic<F>, Rejection> {
        number(path, text, self.1).map(Algebraic::rational)
    }
    fn vectors<'a>(
        &self,
        written: &'a [Generator],
        names: &'static [&'static str],
        path: &dyn Fn(usize) -> String,
    ) -> Result<Generators<'a, AlgebraicInt<F>>, Rejection> {
        field_rules::vectors(&self.0, written, names, path, self.1)
    }
}
