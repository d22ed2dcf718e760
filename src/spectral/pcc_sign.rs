//! The sign condition behind PCC of a pair of contacts (docs/orbit-certificates.md §7.4), decided
//! exactly: M = S_{n-1} S_1 has the eigenvalue 1 (both contacts at rest); for each other real
//! eigenvalue λ the sign of u_0 u_1 on its eigenvector, in Q(√D) with D the discriminant of the
//! quadratic factor. Alternating impacts 0, 1, 0, … need u_0 > 0 > u_1 after an impact at 0, so
//! if both signs are positive no motion alternates for ever.

use crate::exact::Q;
use chatter_kernel::exact::Ring;
use chatter_kernel::model::Polygon;
use chatter_kernel::model::linalg::{Mat3, det3, mat_mul};
use std::cmp::Ordering;

/// p + q√d, d > 0 fixed by the caller.
#[derive(Clone, Debug)]
struct Surd {
    p: Q,
    q: Q,
}

impl Surd {
    fn rational(p: Q) -> Surd {
        Surd { p, q: Q::zero() }
    }

    fn minus(&self, o: &Surd) -> Surd {
        Surd { p: &self.p - &o.p, q: &self.q - &o.q }
    }

    fn times(&self, o: &Surd, d: &Q) -> Surd {
        Surd { p: &(&self.p * &o.p) + &(&(&self.q * &o.q) * d), q: &(&self.p * &o.q) + &(&self.q * &o.p) }
    }

    /// The sign of p + q√d: by the signs of p, q and, when they differ, of p² − q²d.
    fn sign(&self, d: &Q) -> Ordering {
        let (sp, sq) = (self.p.sign(), self.q.sign());
        if sq == Ordering::Equal || sp == sq {
            return if sp == Ordering::Equal { sq } else { sp };
        }
        match (&self.p * &self.p).cmp(&(&(&self.q * &self.q) * d)) {
            Ordering::Greater => sp,
            Ordering::Less => sq,
            Ordering::Equal => Ordering::Equal,
        }
    }
}

/// The eigenvalues of M = S_{n-1} S_1 other than 1 and the sign of u_0 u_1 on their eigenvectors.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PairSigns {
    /// (b, c) of the quadratic factor t² − b t + c of det(tI − M) = (t − 1)(t² − b t + c).
    pub quadratic: (Q, Q),
    /// Its discriminant b² − 4c.
    pub discriminant: Q,
    /// For λ = (b + √D)/2 and λ = (b − √D)/2, in that order: the sign of u_0 u_1 on the
    /// eigenvector (`None` if D ≤ 0: no two distinct real eigenvalues).
    pub signs: Option<[Ordering; 2]>,
}

impl PairSigns {
    /// Both eigenvectors have u_0 u_1 > 0: the alternation 0, 1, 0, … cannot go on for ever.
    pub fn blocks_alternation(&self) -> bool {
        self.signs == Some([Ordering::Greater, Ordering::Greater])
    }
}

/// Decides the signs for a polygon with rational cosines (n = 3, 4, 6); `Err` if 1 is not an
/// eigenvalue of M (it always is: a check, not an assumption).
pub fn pair_signs(body: &Polygon<Q>) -> Result<PairSigns, String> {
    let last = body.n() as i64 - 1;
    let m = mat_mul(&body.step(last), &body.step(1));
    let (b, c) = quadratic_factor(&m)?;
    let disc = &(&b * &b) - &(&Q::int(4) * &c);
    if disc.sign() != Ordering::Greater {
        return Ok(PairSigns { quadratic: (b, c), discriminant: disc, signs: None });
    }
    let half = Q::new(1, 2);
    let sign_at = |s: i64| {
        let lambda = Surd { p: &b * &half, q: &half * &Q::int(s) };
        let v = null_vector(&m, &lambda, &disc);
        v[0].times(&v[1], &disc).sign(&disc)
    };
    let signs = Some([sign_at(1), sign_at(-1)]);
    Ok(PairSigns { quadratic: (b, c), discriminant: disc, signs })
}

/// det(tI − M) = t³ + c2 t² + c1 t + c0 divided by t − 1: (b, c) with quotient t² − b t + c.
fn quadratic_factor(m: &Mat3<Q>) -> Result<(Q, Q), String> {
    let tr = &(&m[0][0] + &m[1][1]) + &m[2][2];
    let minor = |i: usize, j: usize| &(&m[i][i] * &m[j][j]) - &(&m[i][j] * &m[j][i]);
    let e2 = &(&minor(0, 1) + &minor(0, 2)) + &minor(1, 2);
    let det = det3(&m[0], &m[1], &m[2]);
    let q1 = &Q::one() - &tr;
    let q0 = &e2 + &q1;
    if !(&q0 - &det).is_zero() {
        return Err("1 is not an eigenvalue of S_{n-1} S_1".into());
    }
    Ok((-q1, q0))
}

/// A non-zero vector of the kernel of M − λI (λ a simple eigenvalue): the cross product of two
/// independent rows.
fn null_vector(m: &Mat3<Q>, lambda: &Surd, d: &Q) -> [Surd; 3] {
    let rows: Vec<[Surd; 3]> = (0..3)
        .map(|r| {
            std::array::from_fn(|c| {
                let e = Surd::rational(m[r][c].clone());
                if r == c { e.minus(lambda) } else { e }
            })
        })
        .collect();
    let cross = |a: &[Surd; 3], b: &[Surd; 3]| -> [Surd; 3] {
        std::array::from_fn(|i| {
            let (j, k) = ((i + 1) % 3, (i + 2) % 3);
            a[j].times(&b[k], d).minus(&a[k].times(&b[j], d))
        })
    };
    let zero = |v: &[Surd; 3]| v.iter().all(|x| x.sign(d) == Ordering::Equal);
    [(0, 1), (0, 2), (1, 2)]
        .iter()
        .map(|&(i, j)| cross(&rows[i], &rows[j]))
        .find(|v| !zero(v))
        .unwrap_or_else(|| std::array::from_fn(|_| Surd::rational(Q::zero())))
}
