//! The planar rod (MODEL §7, the paper's section "The falling rod revisited"): contacts at
//! x = ±1, velocities p = (u0, u1) of the two ends, v = (u0 + u1)/2.

use super::impact::BodyError;
use crate::exact::OrderedField;

pub type Vec2<F> = [F; 2];
pub type Mat2<F> = [[F; 2]; 2];

pub fn mat2_vec<F: OrderedField>(m: &Mat2<F>, x: &Vec2<F>) -> Vec2<F> {
    [m[0][0].times(&x[0]).plus(&m[0][1].times(&x[1])), m[1][0].times(&x[0]).plus(&m[1][1].times(&x[1]))]
}

pub fn mat2_mul<F: OrderedField>(a: &Mat2<F>, b: &Mat2<F>) -> Mat2<F> {
    let e = |i: usize, j: usize| a[i][0].times(&b[0][j]).plus(&a[i][1].times(&b[1][j]));
    [[e(0, 0), e(0, 1)], [e(1, 0), e(1, 1)]]
}

/// A uniform-or-not rod: kappa = rho^2 / R^2 (R = half-length), restitution gamma.
#[derive(Clone, Debug)]
pub struct Rod<F> {
    pub kappa: F,
    pub gamma: F,
}

impl<F: OrderedField> Rod<F> {
    pub fn new(kappa: F, gamma: F) -> Result<Self, BodyError> {
        if !kappa.is_positive() {
            return Err(BodyError::KappaNotPositive);
        }
        if gamma.is_negative() || gamma > F::one() {
            return Err(BodyError::GammaOutOfRange);
        }
        Ok(Rod { kappa, gamma })
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
