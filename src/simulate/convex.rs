//! General convex bodies in the simulator (docs/model.md §11, §11.10): the exact [`System`] of a
//! kernel [`ConvexBody`], its `f64` copy, and the rule deciding whether PCC is possible.
//!
//! A general body lives in the paper's coordinates p = (ωx, ωy, v), q = (φx, φy, h): the contacts
//! are the covectors f_k = (y_k, -x_k, 1), an impact at k maps p to p - u_k (1 + γ) w_k
//! (w_k = M⁻¹ f_k / (f_kᵀ M⁻¹ f_k), M = diag(J, 1)), the centre-of-mass covector is (0, 0, 1), the
//! Gram matrix of T = pᵀ G p / 2 is M and the rest points are the kernel's m_{k,k+1}. The
//! change to the paper's coordinates is the identity ([`FloatSystem::to_paper`]).

use super::scalar::SimField;
use super::system::{FloatSystem, Frame, Shape, System, TABLE_CONTACTS};
use crate::exact::{Q, Ring};
use chatter_kernel::model::linalg::Vec3;
use chatter_kernel::model::{BodyError, ConvexBody};

/// Whether the adjacent pair (k, k+1) of `body` can chatter on its own (docs/model.md §11.6,
/// §11.10): an impact at one contact must pull the other down, <f_k, f_{k+1}> < 0 (the sign of
/// both couplings f_{k+1}·kick_k and f_k·kick_{k+1}), and the pair map I_k I_{k+1} must have
/// real eigenvalues besides 1 (the kernel's PCC quadratic has a discriminant ≥ 0). For the regular
/// n-gon this is the paper's Lemma on PCC ([`System::pcc_possible`]): E = (1+γ)<f_0, f_1>/N and
/// the quadratic's discriminant is E²(E² - 4γ).
pub fn pair_pcc_possible<F: SimField>(body: &ConvexBody<F>, k: i64) -> bool {
    let pulls_down = body.inverse_inertia_product(k, k + 1).is_negative();
    let real = body.pair_pcc_quadratic(k).map(|q| !q.discriminant.is_negative()).unwrap_or(true);
    pulls_down && real
}

/// Whether some adjacent pair can chatter on its own ([`pair_pcc_possible`]); where no pair can,
/// the classification counts the paper's PCC criterion as overruled, as for regular polygons.
pub fn pcc_possible<F: SimField>(body: &ConvexBody<F>) -> bool {
    (0..body.n() as i64).any(|k| pair_pcc_possible(body, k))
}

/// The length scale R of the paper's random drop for a body with covectors `contacts`
/// (docs/model.md §11.10): the paper's bodies have circumradius 1, so a general body is dropped
/// as if scaled to size about 1, with angular velocity (R1, R2)/R and tilt (R3, R4)/R. R is the
/// power of two nearest (in log scale) to the largest contact distance, so that dividing is exact
/// in `f64` and a regular polygon given as a general body (R = 1) is dropped exactly as the
/// paper does. 1 for the rod and regular polygons (not covectors (y, -x, 1) of general bodies).
pub fn drop_scale<F: SimField>(contacts: &[Vec3<F>]) -> f64 {
    let is_general = contacts.iter().all(|f| f[2] == F::one());
    let r2 = contacts.iter().map(|f| f[0].approx().powi(2) + f[1].approx().powi(2)).fold(0.0, f64::max);
    if !(is_general && r2.is_finite() && r2 > 0.0) {
        return 1.0;
    }
    (0.5 * r2.log2()).round().exp2()
}

impl<F: SimField> System<F> {
    /// The exact system of a general convex body (docs/model.md §11), in the body's field.
    /// `kappa` is not a parameter of a general body and is set to 0; `pair_coupling` is unused
    /// (the PCC rule is [`pcc_possible`], stored in `pair_pcc`).
    pub fn convex(body: &ConvexBody<F>) -> System<F> {
        let n = body.n() as i64;
        let g1 = F::one().plus(body.gamma());
        let contacts: Vec<Vec3<F>> = (0..n).map(|k| body.covector(k).clone()).collect();
        let kicks = (0..n).map(|k| body.impact_direction(k).clone().map(|w| g1.times(&w))).collect();
        let j = body.inertia();
        let (z, o) = (F::zero(), F::one());
        let gram = [
            [j[0][0].clone(), j[0][1].clone(), z.clone()],
            [j[1][0].clone(), j[1][1].clone(), z.clone()],
            [z.clone(), z.clone(), o.clone()],
        ];
        System {
            shape: Shape::Convex(n as u64),
            kappa: z.clone(),
            gamma: body.gamma().clone(),
            contacts,
            kicks,
            centre: [z.clone(), z.clone(), o],
            gram,
            rest_points: (0..n).map(|k| body.edge_rest_point(k).clone()).collect(),
            pair_coupling: z,
            pair_pcc: Some(pcc_possible(body)),
        }
    }
}

impl FloatSystem {
    /// The `f64` copy of an exact system in any field (general bodies in Q(√3), say), its frames
    /// computed in `f64` ([`Frame::from_float`]). Rational systems use [`FloatSystem::new`],
    /// whose frames are exact before rounding.
    pub fn rounded<F: SimField>(sys: &System<F>) -> FloatSystem {
        let v3 = |v: &Vec3<F>| v.clone().map(|x| x.approx());
        let mut fs = FloatSystem {
            shape: sys.shape,
            n: sys.n(),
            f: sys.contacts.iter().map(v3).collect(),
            kick: sys.kicks.iter().map(v3).collect(),
            centre: v3(&sys.centre),
            gram: sys.gram.clone().map(|r| r.map(|x| x.approx())),
            gamma: sys.gamma.approx(),
            rest_paper: Vec::new(),
            cos1: 1.0,
            sin1: 0.0,
            pcc_possible: sys.pcc_possible(),
            drop_scale: drop_scale(&sys.contacts),
            adjacent: Vec::new(),
            frames: Vec::new(),
        };
        let rest: Vec<[f64; 3]> = sys.rest_points.iter().map(v3).collect();
        fs.finish(&rest);
        if fs.n <= TABLE_CONTACTS {
            let table = Frame::table(fs.n, |slots| Frame::from_float(&fs, slots));
            fs.frames = table;
        }
        fs
    }
}

/// The regular n-gon (circumradius 1, contact k at angle 2πk/n, J = κ I) as a rational general
/// body: n = 4 only (the square), the other exact regular polygons need Q(√3)
/// (`crate::bodies::convex::regular_polygon_exact`).
pub fn regular_rational(n: u64, kappa: Q, gamma: Q) -> Result<ConvexBody<Q>, BodyError> {
    if n != 4 {
        return Err(BodyError::UnsupportedN(n));
    }
    if !kappa.is_positive() {
        return Err(BodyError::KappaNotPositive);
    }
    let (o, z) = (|| Q::int(1), || Q::int(0));
    let contacts = vec![[o(), z()], [z(), o()], [Q::int(-1), z()], [z(), Q::int(-1)]];
    let j = [[kappa.clone(), z()], [z(), kappa]];
    ConvexBody::new(contacts, j, gamma).map_err(|_| BodyError::GammaOutOfRange)
}
