//! The body's constants of the return map as rational enclosures (docs/kernel-soundness.md §7.1):
//! exact points where cos 2π/n is rational (n = 3, 4, 6), otherwise (feature `field`) the exact
//! elements of Q(cos 2π/n) that the model builds (contact covectors f_k, impact map I_0),
//! each enclosed by a rational interval from [`crate::exact::Algebraic::bounds`].

use super::interval::Iv;
use super::map::Maps;
use crate::exact::Field;
use crate::model::polygon::{BodyError, Polygon, rational_cos};

/// Enclosures of irrational constants are narrower than 2^-WIDTH_BITS before outward rounding.
pub const WIDTH_BITS: u32 = 96;

/// The constants of the regular n-gon (κ, γ) as enclosures: exact points for rational cos 2π/n,
/// enclosures of the exact elements of Q(cos 2π/n) otherwise.
pub fn enclosed_maps<F: Field>(n: u64, kappa: F, gamma: F) -> Result<Maps<Iv<F>>, BodyError> {
    if let Some(c) = rational_cos::<F>(n) {
        let body = Polygon::with_cosine(n, c, kappa, gamma)?;
        return Ok(Maps::new(&body).map(Iv::exact));
    }
    field_maps(n, kappa, gamma)
}

/// The constants in Q(cos 2π/n), 3 <= n <= MAX_N, enclosed ([`enclose`]).
#[cfg(feature = "field")]
pub fn field_maps<F: Field>(n: u64, kappa: F, gamma: F) -> Result<Maps<Iv<F>>, BodyError> {
    use crate::exact::{Algebraic, CosField};
    let field = CosField::<F>::new(n).ok_or(BodyError::UnsupportedN(n))?;
    let (kappa, gamma) = (Algebraic::rational(kappa), Algebraic::rational(gamma));
    let body = Polygon::with_cosine(n, field.generator(), kappa, gamma)?;
    Ok(Maps::new(&body).map(enclose))
}

/// Without the feature `field` only rational cos 2π/n is modelled.
#[cfg(not(feature = "field"))]
pub fn field_maps<F: Field>(n: u64, _kappa: F, _gamma: F) -> Result<Maps<Iv<F>>, BodyError> {
    Err(BodyError::UnsupportedN(n))
}

/// A rational enclosure of an element of Q(cos 2π/n): the element itself when it is rational,
/// else Horner's scheme in interval arithmetic over an isolating interval of c, narrower than
/// 2^-[`WIDTH_BITS`], rounded outward.
#[cfg(feature = "field")]
pub fn enclose<F: Field>(x: &crate::exact::Algebraic<F>) -> Iv<F> {
    if let Some(r) = x.as_rational() {
        return Iv::exact(&r);
    }
    let width = F::from_fraction(
        &crate::exact::Ring::one(),
        &<F::Int as crate::exact::Int>::pow2(u64::from(WIDTH_BITS)),
    );
    let (lo, hi) = x.bounds(&width);
    Iv::new(lo, hi)
}
