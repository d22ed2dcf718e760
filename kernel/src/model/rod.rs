//! The planar rod (docs/model.md §7, the paper's section "The falling rod revisited"): contacts at
//! x = ±1, velocities p = (u0, u1) of the two ends, v = (u0 + u1)/2.

use super::polygon::BodyError;
use crate::exact::{OrderedField, Ring};

/// A 2-vector (the rod's velocities (u0, u1)).
pub type Vec2<F> = [F; 2];
/// A 2x2 matrix.
pub type Mat2<F> = [[F; 2]; 2];

/// `m x`.
pub fn mat2_vec<R: Ring>(m: &Mat2<R>, x: &Vec2<R>) -> Vec2<R> {
    [m[0][0].times(&x[0]).plus(&m[0][1].times(&x[1])), m[1][0].times(&x[0]).plus(&m[1][1].times(&x[1]))]
}

/// `a b`.
pub fn mat2_mul<R: Ring>(a: &Mat2<R>, b: &Mat2<R>) -> Mat2<R> {
    let e = |i: usize, j: usize| a[i][0].times(&b[0][j]).plus(&a[i][1].times(&b[1][j]));
    [[e(0, 0), e(0, 1)], [e(1, 0), e(1, 1)]]
}

/// A uniform-or-not rod: kappa = rho^2 / R^2 (R = half-length), restitution gamma.
#[derive(Clone, Debug)]
pub struct Rod<F> {
    kappa: F,
    gamma: F,
}

impl<F: OrderedField> Rod<F> {
    /// The rod with kappa > 0 and gamma in [0, 1].
    pub fn new(kappa: F, gamma: F) -> Result<Self, BodyError> {
        if !kappa.is_positive() {
            return Err(BodyError::KappaNotPositive);
        }
        if gamma.is_negative() || gamma > F::one() {
            return Err(BodyError::GammaOutOfRange);
        }
        Ok(Rod { kappa, gamma })
    }

    /// kappa = rho^2 / R^2 (R the half-length).
    pub fn kappa(&self) -> &F {
        &self.kappa
    }

    /// The coefficient of restitution.
    pub fn gamma(&self) -> &F {
        &self.gamma
    }

    /// (kappa - 1)/(kappa + 1): how an impulse at one end moves the other (c_1 = cos pi = -1).
    pub fn coupling(&self) -> F {
        let one = F::one();
        self.kappa.minus(&one).over(&self.kappa.plus(&one)).expect("kappa + 1 > 0")
    }

    /// Impact at end k: u_k -> -gamma u_k, u_other -> u_other - (1 + gamma) coupling u_k.
    pub fn impact(&self, k: usize) -> Mat2<F> {
        let (z, o) = (F::zero(), F::one());
        let c = F::one().plus(&self.gamma).times(&self.coupling()).negated();
        let mut m = [[o.clone(), z.clone()], [z, o]];
        m[k][k] = self.gamma.negated();
        m[1 - k][k] = c;
        m
    }

    /// Relabelling: the ends swap names.
    pub fn relabel(&self) -> Mat2<F> {
        let (z, o) = (F::zero(), F::one());
        [[z.clone(), o.clone()], [o, z]]
    }

    /// The step map S_1 = I_0 R (the paper's U_0 P for the rod).
    pub fn step(&self) -> Mat2<F> {
        mat2_mul(&self.impact(0), &self.relabel())
    }

    /// Covectors of C_1 = { u0 >= 0, v <= 0 }: after an impact at end 0 only end 1 can hit next.
    pub fn next_contact_cone(&self) -> [Vec2<F>; 2] {
        let h = F::from_ratio(-1, 2);
        [[F::one(), F::zero()], [h.clone(), h]]
    }

    /// Generators of D = { u0 <= 0, u1 <= 0 }: one end at rest, the other moving down.
    pub fn all_down_generators(&self) -> [Vec2<F>; 2] {
        [[F::zero(), F::one().negated()], [F::one().negated(), F::zero()]]
    }
}
