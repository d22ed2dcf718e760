//! Regular n-gons whose cos 2π/n is irrational (n = 5, 7, 8, 9, ...; issue 10 §1). The `f64`
//! simulation runs on the float model ([`crate::model::float::FloatPolygon`]); the two decisions
//! the simulator makes before the first impact are still exact, in the number field Q(cos 2π/n)
//! of [`crate::spectral::number_field`]: whether the PCC Lemma allows PCC, and whether a given
//! start has every contact at or above the floor. (Exact simulation itself needs the field
//! arithmetic of issue 10 §2 in the engine; it is not available for these n.)

use super::drop::{Start, StartError};
use super::system::FloatSystem;
use crate::bodies::cosine;
use crate::exact::{OrderedField, Q, QExt, Ring};
use crate::model::float::FloatPolygon;
use crate::spectral::number_field::Nf;
use chatter_kernel::model::linalg::dot;
use chatter_kernel::model::{BodyError, Polygon};

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

/// Checks a start exactly: h_k = f_k·q ≥ 0 for every contact, with the covectors f_k in
/// Q(cos 2π/n), and p ≠ 0 ([`super::drop::check_start`] for the exact models).
pub fn check_start(n: u64, kappa: &Q, gamma: &Q, s: &Start<Q>) -> Result<(), StartError> {
    let field = |x: &Q| Nf::from_q(x);
    let body = Polygon::with_cosine(n, cosine(n as usize), field(kappa), field(gamma))
        .expect("parameters validated by the float model");
    let q = s.q.clone().map(|x| field(&x));
    for k in 0..n as i64 {
        let h = dot(body.contact(k), &q);
        if h.is_negative() {
            return Err(StartError::BelowFloor { contact: k as usize, height: h.to_string() });
        }
    }
    if s.p.iter().all(Ring::is_zero) {
        return Err(StartError::AtRest);
    }
    Ok(())
}
