//! The regular n-gon (n ≥ 3) in contact coordinates p = (u0, u1, v) (docs/model.md §2-§5),
//! derived from the physics of §2 and §11.2 rather than from the closed forms: angles by de
//! Moivre's formula, contact speeds from u_k = v + sin θ_k ω_x - cos θ_k ω_y, impacts from the
//! inverse-inertia products ⟨f_j, f_k⟩ = (κ + c_{j-k})/κ, and a step S_j as "impact at contact j,
//! then rename contact j as 0" (equal to §3's I_0 R_j by the rotational symmetry).

use crate::arith::{Field, Num};
use crate::cone3::facets;
use num_bigint::BigInt;
use std::sync::Arc;

/// A vector of the model.
pub type V3 = [Num; 3];

/// The exact model of a regular n-gon with parameters κ, γ in Q(cos 2π/n).
#[derive(Clone, Debug)]
pub struct Polygon {
    /// Number of contacts.
    pub n: usize,
    /// κ.
    pub kappa: Num,
    /// γ.
    pub gamma: Num,
    /// cos(2πm/n), m = 0..n-1.
    cosines: Vec<Num>,
    /// (a_k, b_k) with u_k = a_k u0 + b_k u1 + (1 - a_k - b_k) v, k = 0..n-1.
    speed: Vec<(Num, Num)>,
}

/// Binomial coefficient as a field element.
fn binomial(field: &Arc<Field>, m: usize, i: usize) -> Num {
    let c = (0..i).fold(BigInt::from(1), |acc, k| acc * BigInt::from(m - k) / BigInt::from(k + 1));
    Num::rational(field, crate::arith::Rat::from_integer(c))
}

/// x^k.
fn power(x: &Num, k: usize) -> Num {
    (0..k).fold(Num::int(&x.field, 1), |acc, _| &acc * x)
}

/// (cos mθ, sin mθ / sin θ) from c = cos θ by de Moivre: (c + i s)^m with s² = 1 - c².
fn de_moivre(c: &Num, m: usize) -> (Num, Num) {
    let f = &c.field;
    let s2 = &Num::int(f, 1) - &(c * c);
    let (mut re, mut im) = (Num::int(f, 0), Num::int(f, 0));
    for k in 0..=m {
        // i^k s^k: real for even k (sign (-1)^{k/2}), imaginary for odd k (s^{k-1} s).
        let sign = if (k / 2) % 2 == 0 { 1 } else { -1 };
        let term = &(&binomial(f, m, k) * &power(c, m - k)) * &power(&s2, k / 2);
        let term = if sign > 0 { term } else { term.neg() };
        if k % 2 == 0 { re = &re + &term } else { im = &im + &term }
    }
    (re, im)
}

impl Polygon {
    /// The model of the regular n-gon (3 ≤ n ≤ 64) with κ and γ in `field` = Q(cos 2π/n).
    pub fn new(n: usize, kappa: Num, gamma: Num) -> Polygon {
        let field = kappa.field.clone();
        let c = Num::generator(&field);
        let angles: Vec<(Num, Num)> = (0..n).map(|m| de_moivre(&c, m)).collect();
        // u_k = v + σ_k (u1 - v + c (v - u0)) - c_k (v - u0) with σ_k = sin kθ / sin θ (§2):
        // a_k = c_k - c σ_k, b_k = σ_k.
        let speed = angles.iter().map(|(ck, sk)| (ck - &(&c * sk), sk.clone())).collect();
        Polygon { n, kappa, gamma, cosines: angles.into_iter().map(|a| a.0).collect(), speed }
    }

    fn field(&self) -> &Arc<Field> {
        &self.kappa.field
    }

    /// cos(2πm/n) for any integer m.
    pub fn cos(&self, m: i64) -> Num {
        self.cosines[m.rem_euclid(self.n as i64) as usize].clone()
    }

    /// u_k(p), the normal speed of contact k (any integer k, modulo n).
    pub fn speed(&self, k: i64, p: &V3) -> Num {
        let (a, b) = &self.speed[k.rem_euclid(self.n as i64) as usize];
        let rest = &(&Num::int(self.field(), 1) - a) - b;
        &(&(a * &p[0]) + &(b * &p[1])) + &(&rest * &p[2])
    }

    /// The impact at contact k (§11.2 in contact coordinates): u_j changes by
    /// -(1+γ) u_k ⟨f_j, f_k⟩/N_k = -(1+γ) u_k (κ + c_{j-k})/(1+κ), v by -(1+γ) u_k κ/(1+κ).
    pub fn impact(&self, k: i64, p: &V3) -> V3 {
        let one = Num::int(self.field(), 1);
        let kick = &(&(&one + &self.gamma) * &self.speed(k, p)) / &(&one + &self.kappa);
        let du = |j: i64| &kick * &(&self.kappa + &self.cos(j - k));
        [&p[0] - &du(0), &p[1] - &du(1), &p[2] - &(&kick * &self.kappa)]
    }

    /// S_j p: impact at contact j, then contact j renamed 0: (u_j, u_{j+1}, v) after the impact.
    pub fn step(&self, j: i64, p: &V3) -> V3 {
        let after = self.impact(j, p);
        [self.speed(j, &after), self.speed(j + 1, &after), after[2].clone()]
    }

    /// m_{k,l}: the configuration (h0, h1, hc) with h_k = h_l = 0 and hc = 1 (§4), by Cramer's
    /// rule on h_k = a_k h0 + b_k h1 + (1 - a_k - b_k) hc (heights transform like speeds, §2).
    pub fn rest_point(&self, k: i64, l: i64) -> V3 {
        let f = self.field();
        let e = |i: i64| {
            let (a, b) = &self.speed[i.rem_euclid(self.n as i64) as usize];
            (a.clone(), b.clone(), (&(&Num::int(f, 1) - a) - b).neg())
        };
        let ((a1, b1, r1), (a2, b2, r2)) = (e(k), e(l));
        let det = &(&a1 * &b2) - &(&b1 * &a2);
        let h0 = &(&(&r1 * &b2) - &(&b1 * &r2)) / &det;
        let h1 = &(&(&a1 * &r2) - &(&r1 * &a2)) / &det;
        [h0, h1, Num::int(f, 1)]
    }

    /// Generators of C_j (Lemma 11.3 (11.2) with i = 0): B₋ - A₋, -A₋, -A₊, B₊ - A₊.
    pub fn next_contact_generators(&self, j: i64) -> Vec<V3> {
        let n = self.n as i64;
        let (am, ap) = (self.rest_point(n - 1, 0), self.rest_point(0, 1));
        let (bm, bp) = (self.rest_point(j - 1, j), self.rest_point(j, j + 1));
        let sub = |x: &V3, y: &V3| -> V3 { [&x[0] - &y[0], &x[1] - &y[1], &x[2] - &y[2]] };
        let neg = |x: &V3| -> V3 { [x[0].neg(), x[1].neg(), x[2].neg()] };
        vec![sub(&bm, &am), neg(&am), neg(&ap), sub(&bp, &ap)]
    }

    /// The facet covectors of C_j, found from its generators by brute force.
    pub fn next_contact_facets(&self, j: i64) -> Vec<V3> {
        facets(&self.next_contact_generators(j))
    }

    /// Generators -m_{k,k+1} of D = {u_k ≤ 0 for all k}.
    pub fn all_down(&self) -> Vec<V3> {
        (0..self.n as i64).map(|k| self.rest_point(k, k + 1).map(|x| x.neg())).collect()
    }

    /// A linear map as its matrix, from the images of the unit vectors (columns).
    pub fn matrix(&self, map: impl Fn(&V3) -> V3) -> [[Num; 3]; 3] {
        let f = self.field();
        let unit = |i: usize| std::array::from_fn(|r| Num::int(f, i64::from(r == i)));
        let cols: Vec<V3> = (0..3).map(|i| map(&unit(i))).collect();
        std::array::from_fn(|r| std::array::from_fn(|c| cols[c][r].clone()))
    }
}
