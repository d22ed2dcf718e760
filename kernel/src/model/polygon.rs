//! The exact impact model of a regular n-gon body in contact-velocity coordinates
//! p = (u0, u1, v) (docs/model.md §2-5): contact covectors, impact maps, relabelling, step maps,
//! the points m_{k,l}, the cones C_j and the all-down cone D.

use super::linalg::{Mat3, Vec3, cross, identity, mat_mul, neg};
use crate::exact::OrderedField;

/// Why a body cannot be modelled exactly.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum BodyError {
    /// No exact model for this number of contacts.
    UnsupportedN(u64),
    /// kappa <= 0.
    KappaNotPositive,
    /// gamma outside [0, 1].
    GammaOutOfRange,
}

/// Whether n is a regular polygon whose cos(2 pi/n) is irrational (n >= 5, n != 6: Niven).
pub fn is_irrational(n: u64) -> bool {
    n >= 5 && n != 6
}

/// cos(2*pi/n) for the regular polygons whose cosines are rational (Niven: n = 3, 4, 6).
pub fn rational_cos<F: OrderedField>(n: u64) -> Option<F> {
    match n {
        3 => Some(F::from_ratio(-1, 2)),
        4 => Some(F::zero()),
        6 => Some(F::from_ratio(1, 2)),
        _ => None,
    }
}

/// A flat regular n-gon body: contacts at angles 2*pi*k/n, kappa = rho^2/R^2, restitution gamma.
#[derive(Clone, Debug)]
pub struct Polygon<F> {
    n: usize,
    pub(crate) kappa: F,
    gamma: F,
    /// c_m = cos(2*pi*m/n), m = 0..n-1.
    cos: Vec<F>,
    /// Contact covectors f_k with u_k = f_k . p, k = 0..n-1.
    contacts: Vec<Vec3<F>>,
}

impl<F: OrderedField> Polygon<F> {
    /// The body with n in {3, 4, 6} (rational cos(2 pi/n)); kappa > 0 and gamma in [0, 1].
    pub fn new(n: u64, kappa: F, gamma: F) -> Result<Self, BodyError> {
        let c1: F = rational_cos(n).ok_or(BodyError::UnsupportedN(n))?;
        Self::with_cosine(n, c1, kappa, gamma)
    }

    /// A body whose cos(2*pi/n) = `c1` is given by the caller (exact in any field, e.g. a number
    /// field for n = 5): the kernel's orbit certificates use it with c = cos 2π/n in Q(c)
    /// (`orbit::constants`), every other kernel rule [`Polygon::new`].
    pub fn with_cosine(n: u64, c1: F, kappa: F, gamma: F) -> Result<Self, BodyError> {
        if n < 3 {
            return Err(BodyError::UnsupportedN(n));
        }
        if !kappa.is_positive() {
            return Err(BodyError::KappaNotPositive);
        }
        if gamma.is_negative() || gamma > F::one() {
            return Err(BodyError::GammaOutOfRange);
        }
        let n = n as usize;
        let two_c1 = c1.plus(&c1);
        // Chebyshev: c_m = T_m(c1); U_{-2} = -1, U_{-1} = 0, U_m = 2 c1 U_{m-1} - U_{m-2}.
        let mut cos = vec![F::one(), c1.clone()];
        let mut u = vec![F::one().negated(), F::zero()];
        while cos.len() < n + 1 || u.len() < n + 2 {
            let m = cos.len();
            cos.push(two_c1.times(&cos[m - 1]).minus(&cos[m - 2]));
            let k = u.len();
            u.push(two_c1.times(&u[k - 1]).minus(&u[k - 2]));
        }
        cos.truncate(n);
        // a_k = -U_{k-2}(c1), b_k = U_{k-1}(c1); u[i] holds U_{i-2}.
        let contacts = (0..n)
            .map(|k| {
                let a = u[k].negated();
                let b = u[k + 1].clone();
                let rest = F::one().minus(&a).minus(&b);
                [a, b, rest]
            })
            .collect();
        Ok(Polygon { n, kappa, gamma, cos, contacts })
    }

    /// Number of contacts.
    pub fn n(&self) -> usize {
        self.n
    }

    /// The coefficient of restitution.
    pub fn gamma(&self) -> &F {
        &self.gamma
    }

    /// c_m = cos(2*pi*m/n) for any integer m.
    pub fn cos(&self, m: i64) -> &F {
        &self.cos[m.rem_euclid(self.n as i64) as usize]
    }

    /// Covector f_k of contact k: u_k = a_k u0 + b_k u1 + (1 - a_k - b_k) v (docs/model.md §2).
    pub fn contact(&self, k: i64) -> &Vec3<F> {
        &self.contacts[k.rem_euclid(self.n as i64) as usize]
    }

    /// beta = (1 + gamma) / (1 + kappa), the impulse factor of every impact.
    pub fn beta(&self) -> F {
        let one = F::one();
        one.plus(&self.gamma).over(&one.plus(&self.kappa)).expect("1 + kappa > 0")
    }

    /// Direction d_k = (kappa + c_k, kappa + c_{k-1}, kappa) of the velocity change of an impact at k.
    pub fn impact_direction(&self, k: i64) -> Vec3<F> {
        let kp = &self.kappa;
        [kp.plus(self.cos(k)), kp.plus(self.cos(k - 1)), kp.clone()]
    }

    /// Impact map I_k: p+ = p - beta u_k d_k (docs/model.md §3, the paper's equation for U_i).
    pub fn impact(&self, k: i64) -> Mat3<F> {
        let beta = self.beta();
        let d = self.impact_direction(k);
        let f = self.contact(k);
        let mut m = identity::<F>();
        for (r, row) in m.iter_mut().enumerate() {
            for (c, e) in row.iter_mut().enumerate() {
                *e = e.minus(&beta.times(&d[r]).times(&f[c]));
            }
        }
        m
    }

    /// Relabelling R_j: (u0, u1, v) -> (u_j, u_{j+1}, v); contact j is renamed 0.
    pub fn relabel(&self, j: i64) -> Mat3<F> {
        let (z, o) = (F::zero(), F::one());
        [self.contact(j).clone(), self.contact(j + 1).clone(), [z.clone(), z, o]]
    }

    /// Step map S_j = I_0 R_j, the paper's U_0 P_{-2 j pi/n} (equation U0): after an impact at
    /// contact 0 the next impact is at contact j.
    pub fn step(&self, j: i64) -> Mat3<F> {
        mat_mul(&self.impact(0), &self.relabel(j))
    }
}

// The points m_{k,l}, the cones C_j of velocities from which contact j hits next (the paper's
// Lemma on C_j, docs/model.md §4), and the all-down cone D (docs/model.md §5).
impl<F: OrderedField> Polygon<F> {
    /// m_{k,l}: the configuration with h_k = h_l = 0 and h_c = 1 (`None` if k, l are opposite).
    pub fn rest_point(&self, k: i64, l: i64) -> Option<Vec3<F>> {
        let [ak, bk, ek] = self.contact(k);
        let [al, bl, el] = self.contact(l);
        // a h0 + b h1 = -e for both contacts (Cramer's rule).
        let det = ak.times(bl).minus(&al.times(bk));
        let h0 = el.times(bk).minus(&ek.times(bl)).over(&det)?;
        let h1 = ek.times(al).minus(&el.times(ak)).over(&det)?;
        Some([h0, h1, F::one()])
    }

    fn adjacent_rest_point(&self, k: i64) -> Vec3<F> {
        self.rest_point(k, k + 1).expect("adjacent contacts of a polygon are never opposite")
    }

    /// Covectors l with C_j = { p : l . p >= 0 for all four } (docs/model.md §4), j = 1..n-1.
    pub fn next_contact_cone(&self, j: i64) -> [Vec3<F>; 4] {
        let (z, o) = (F::zero(), F::one());
        let m01 = self.adjacent_rest_point(0);
        let m_last = self.adjacent_rest_point(-1);
        [
            [o.clone(), z.clone(), z.clone()],
            [z.clone(), z, o.negated()],
            cross(&self.adjacent_rest_point(j), &m01),
            cross(&m_last, &self.adjacent_rest_point(j - 1)),
        ]
    }

    /// Generators -m_{k,k+1} (k = 0..n-1) of D = { p : u_k <= 0 for all k } (docs/model.md §5).
    pub fn all_down_generators(&self) -> Vec<Vec3<F>> {
        (0..self.n() as i64).map(|k| neg(&self.adjacent_rest_point(k))).collect()
    }
}
