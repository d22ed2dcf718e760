//! Regular n-gons whose cos 2π/n is irrational (n = 5, 7, 8, 9, ...; issue 10 §1): the `f64`
//! model. The `f64` simulation runs on the float model ([`crate::model::float::FloatPolygon`]);
//! whether the PCC Lemma allows PCC is still decided exactly, in the number field Q(cos 2π/n) of
//! [`crate::spectral::number_field`]. (The exact simulation of these n runs on
//! [`super::System::in_field`], with the kernel's field arithmetic.)

use super::system::FloatSystem;
use crate::bodies::cosine;
use crate::exact::{Q, QExt, QField, Ring};
use crate::model::float::FloatPolygon;
use crate::spectral::number_field::Nf;
use chatter_kernel::model::BodyError;

/// Checks κ > 0 and γ in [0, 1] exactly (the kernel's rules), before rounding them.
fn check_parameters(kappa: &Q, gamma: &Q) -> Result<(), BodyError> {
    if !kappa.is_positive() {
        return Err(BodyError::KappaNotPositive);
    }
    if gamma.is_negative() || *gamma > Q::int(1) {
        return Err(BodyError::GammaOutOfRange);
    }
    Ok(())
}

/// The `f64` system of the float model of the regular n-gon, 3 ≤ n ≤ 64.
pub fn float_system(n: u64, kappa: &Q, gamma: &Q) -> Result<FloatSystem, BodyError> {
    check_parameters(kappa, gamma)?;
    let body = FloatPolygon::new(n, kappa.to_f64(), gamma.to_f64())?;
    Ok(FloatSystem::regular(&body, pcc_possible(n, kappa, gamma)))
}

/// [`super::System::pcc_possible`] decided exactly in Q(cos 2π/n): the pair coupling
/// E = β(κ + c_1) (docs/model.md §3) must be negative with E² - 4γ ≥ 0 (the paper's Lemma on PCC).
pub fn pcc_possible(n: u64, kappa: &Q, gamma: &Q) -> bool {
    let one = Q::int(1);
    let beta = (&one + gamma) / (&one + kappa);
    let e = Nf::from_q(&beta).times(&Nf::from_q(kappa).plus(&cosine(n as usize)));
    e.is_negative() && !e.times(&e).minus(&Nf::from_q(&(Q::int(4) * gamma))).is_negative()
}
