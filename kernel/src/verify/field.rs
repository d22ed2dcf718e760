//! The field path for every regular polygon (feature `field`).

use crate::exact::{Field, ParseLimits};
use crate::reject::Rejection;
use crate::rules::outcome::Accepted;
use crate::rules::{cone, field};
use crate::syntax::cone::Certificate;

/// The rules of cone certificates also where cos(2 pi/n) is rational (a field of degree 1): a
/// second path for n = 3, 4, 6, against which the field path is tested (point certificates).
pub fn check_in_field<F: Field>(cert: &Certificate, limits: ParseLimits) -> Result<Accepted, Rejection> {
    cone::prelude(cert, limits)?;
    field::check::<F>(cert, limits)
}
