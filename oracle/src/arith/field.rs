//! The real number field Q(c), c = cos 2π/n (docs/certificate-format.md §12): an element is a
//! polynomial of degree < d = deg Ψ_n in c, reduced modulo Ψ_n (so equal elements have equal
//! coefficients: the zero test is exact). Signs: the element is evaluated by interval Horner on a
//! rational enclosure of c from [`super::enclosure`], refined until the interval excludes 0.
//! Inverses solve the linear system of multiplication by the element (Gaussian elimination).
//! For n = 2, 3, 4, 6 (and general bodies) the field is Q itself (d = 1).

use super::cyclotomic::cos_minimal_polynomial;
use super::enclosure::cos_bounds;
use super::rational::{Rat, ratio};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;
use std::sync::{Arc, Mutex};

/// The field Q(cos 2π/n).
#[derive(Debug)]
pub struct Field {
    /// n (0 for Q itself).
    pub n: u32,
    /// Ψ_n, monic, increasing powers (degree d); for Q, x - c_1 is not needed and this is [0, 1].
    psi: Vec<Rat>,
    /// Ψ_n times the least common denominator D of its coefficients (integers; the last is D).
    psi_integers: Vec<BigInt>,
    /// Enclosures of c computed so far, at increasing precision.
    enclosures: Mutex<Vec<(Rat, Rat)>>,
}

/// An element of a [`Field`].
#[derive(Clone, Debug)]
pub struct Num {
    /// The field.
    pub field: Arc<Field>,
    /// Coefficients a_0..a_{d-1} of a_0 + a_1 c + ... (increasing powers).
    pub coef: Vec<Rat>,
}

impl Field {
    /// Q as a field of degree 1.
    pub fn rationals() -> Arc<Field> {
        Field::with(0, vec![Rat::zero(), Rat::one()])
    }

    /// Q(cos 2π/n): Q itself where cos 2π/n is rational (n ≤ 4 or n = 6), with the field's n kept.
    pub fn cos(n: u32) -> Arc<Field> {
        let psi =
            if matches!(n, 1..=4 | 6) { vec![Rat::zero(), Rat::one()] } else { cos_minimal_polynomial(n) };
        Field::with(n, psi)
    }

    fn with(n: u32, psi: Vec<Rat>) -> Arc<Field> {
        let psi_integers = over_one_denominator(&psi).0;
        Arc::new(Field { n, psi, psi_integers, enclosures: Mutex::new(vec![]) })
    }

    /// The degree d over Q.
    pub fn degree(&self) -> usize {
        self.psi.len() - 1
    }

    /// Ψ_n (monic, increasing powers).
    pub fn minimal_polynomial(&self) -> &[Rat] {
        &self.psi
    }

    /// The k-th enclosure of c (k = 0, 1, ...: 64 · 2^k bits).
    fn enclosure(&self, k: usize) -> (Rat, Rat) {
        let mut cache = self.enclosures.lock().expect("not poisoned");
        while cache.len() <= k {
            let bits = 64u32 << cache.len();
            cache.push(cos_bounds(self.n, bits));
        }
        cache[k].clone()
    }
}

/// Interval product [a] · [b].
fn interval_mul(a: &(Rat, Rat), b: &(Rat, Rat)) -> (Rat, Rat) {
    let p = [&a.0 * &b.0, &a.0 * &b.1, &a.1 * &b.0, &a.1 * &b.1];
    let lo = p.iter().min().expect("four").clone();
    let hi = p.iter().max().expect("four").clone();
    (lo, hi)
}

impl Num {
    /// The rational `x` in `field`.
    pub fn rational(field: &Arc<Field>, x: Rat) -> Num {
        let mut coef = vec![Rat::zero(); field.degree()];
        coef[0] = x;
        Num { field: field.clone(), coef }
    }

    /// The integer `k` in `field`.
    pub fn int(field: &Arc<Field>, k: i64) -> Num {
        Num::rational(field, ratio(k, 1))
    }

    /// c = cos 2π/n itself (for d = 1 the rational cos 2π/n, n = 1, 2, 3, 4, 6).
    pub fn generator(field: &Arc<Field>) -> Num {
        if field.degree() > 1 {
            let mut coef = vec![Rat::zero(); field.degree()];
            coef[1] = Rat::one();
            return Num { field: field.clone(), coef };
        }
        let c = match field.n {
            1 => ratio(1, 1),
            2 => ratio(-1, 1),
            3 => ratio(-1, 2),
            4 => ratio(0, 1),
            6 => ratio(1, 2),
            n => panic!("cos 2π/{n} is irrational"),
        };
        Num::rational(field, c)
    }

    /// From a polynomial in c of any degree, reduced modulo Ψ_n.
    pub fn from_poly(field: &Arc<Field>, mut p: Vec<Rat>) -> Num {
        let d = field.degree();
        while p.len() > d {
            let top = p.pop().expect("longer than d");
            let k = p.len() - d;
            for (i, m) in field.psi[..d].iter().enumerate() {
                p[k + i] -= &top * m;
            }
        }
        p.resize(d, Rat::zero());
        Num { field: field.clone(), coef: p }
    }

    /// Whether this is the zero element (exact: the representation is unique).
    pub fn is_zero(&self) -> bool {
        self.coef.iter().all(Zero::is_zero)
    }

    /// The rational value, when the element is rational.
    pub fn as_rational(&self) -> Option<&Rat> {
        self.coef[1..].iter().all(Zero::is_zero).then(|| &self.coef[0])
    }

    /// Interval Horner on the k-th enclosure of c: an interval that contains the element.
    fn horner(&self, k: usize) -> (Rat, Rat) {
        let c = self.field.enclosure(k);
        let top = self.coef[self.coef.len() - 1].clone();
        let mut acc = (top.clone(), top);
        for a in self.coef.iter().rev().skip(1) {
            let m = interval_mul(&acc, &c);
            acc = (&m.0 + a, &m.1 + a);
        }
        acc
    }

    /// The sign, exactly: rational elements directly, others by refining an enclosure of c.
    pub fn signum(&self) -> Ordering {
        if let Some(x) = self.as_rational() {
            return x.cmp(&Rat::zero());
        }
        for k in 0.. {
            let acc = self.horner(k);
            if acc.0.is_positive() {
                return Ordering::Greater;
            }
            if acc.1.is_negative() {
                return Ordering::Less;
            }
        }
        unreachable!("a non-zero element has a sign")
    }

    /// A rational interval [lo, hi] that contains the element's real value, narrower than
    /// 2^-bits (a point for a rational element): interval Horner on ever finer enclosures of c.
    pub fn enclosure(&self, bits: u32) -> (Rat, Rat) {
        if let Some(x) = self.as_rational() {
            return (x.clone(), x.clone());
        }
        let width = Rat::new(One::one(), num_bigint::BigInt::one() << bits);
        (0..).map(|k| self.horner(k)).find(|(lo, hi)| hi - lo < width).expect("enclosures shrink")
    }

    /// Whether > 0.
    pub fn is_positive(&self) -> bool {
        self.signum() == Ordering::Greater
    }

    /// Whether < 0.
    pub fn is_negative(&self) -> bool {
        self.signum() == Ordering::Less
    }

    /// The inverse (panics on zero): the solution x of a·x = 1, from the d × d matrix whose
    /// column k is a·c^k, by Gauss-Jordan elimination.
    pub fn inverse(&self) -> Num {
        assert!(!self.is_zero(), "division by zero");
        if let Some(x) = self.as_rational() {
            return Num::rational(&self.field, x.recip());
        }
        let d = self.field.degree();
        let columns: Vec<Num> = (0..d)
            .map(|k| {
                let mut e = vec![Rat::zero(); k + 1];
                e[k] = Rat::one();
                self * &Num::from_poly(&self.field, e)
            })
            .collect();
        // Augmented rows [M | e_0].
        let mut m: Vec<Vec<Rat>> = (0..d)
            .map(|r| {
                let mut row: Vec<Rat> = columns.iter().map(|c| c.coef[r].clone()).collect();
                row.push(if r == 0 { Rat::one() } else { Rat::zero() });
                row
            })
            .collect();
        for col in 0..d {
            let pivot = (col..d).find(|&r| !m[r][col].is_zero()).expect("a non-zero element is invertible");
            m.swap(col, pivot);
            let inv = m[col][col].recip();
            m[col] = m[col].iter().map(|x| x * &inv).collect();
            for r in (0..d).filter(|&r| r != col) {
                let f = m[r][col].clone();
                if !f.is_zero() {
                    let pivot_row = m[col].clone();
                    m[r] = m[r].iter().zip(&pivot_row).map(|(x, p)| x - &f * p).collect();
                }
            }
        }
        Num { field: self.field.clone(), coef: m.into_iter().map(|row| row[d].clone()).collect() }
    }

    /// -self.
    pub fn neg(&self) -> Num {
        Num { field: self.field.clone(), coef: self.coef.iter().map(|x| -x).collect() }
    }
}

impl PartialEq for Num {
    fn eq(&self, other: &Num) -> bool {
        self.coef == other.coef
    }
}

impl Eq for Num {}

impl std::ops::Add for &Num {
    type Output = Num;
    fn add(self, o: &Num) -> Num {
        Num { field: self.field.clone(), coef: self.coef.iter().zip(&o.coef).map(|(a, b)| a + b).collect() }
    }
}

impl std::ops::Sub for &Num {
    type Output = Num;
    fn sub(self, o: &Num) -> Num {
        Num { field: self.field.clone(), coef: self.coef.iter().zip(&o.coef).map(|(a, b)| a - b).collect() }
    }
}

impl std::ops::Mul for &Num {
    type Output = Num;
    /// The product of the polynomials in integers over one denominator, reduced modulo Ψ_n in
    /// integers too, and each coefficient normalised once at the end (a rational product and
    /// sum per term would reduce every intermediate fraction: most of the oracle's time).
    fn mul(self, o: &Num) -> Num {
        if self.coef.len() == 1 {
            return Num { field: self.field.clone(), coef: vec![&self.coef[0] * &o.coef[0]] };
        }
        let ((a, da), (b, db)) = (over_one_denominator(&self.coef), over_one_denominator(&o.coef));
        let mut p = vec![BigInt::zero(); a.len() + b.len() - 1];
        for (i, x) in a.iter().enumerate().filter(|(_, x)| !x.is_zero()) {
            for (j, y) in b.iter().enumerate() {
                p[i + j] += x * y;
            }
        }
        let (p, scale) = reduce_integers(&self.field, p);
        let den = da * db * scale;
        Num { field: self.field.clone(), coef: p.into_iter().map(|x| Rat::new(x, den.clone())).collect() }
    }
}

/// Integer numerators over the least common denominator of `coef`.
fn over_one_denominator(coef: &[Rat]) -> (Vec<BigInt>, BigInt) {
    let den = coef.iter().fold(BigInt::one(), |l, x| l.lcm(x.denom()));
    (coef.iter().map(|x| x.numer() * (&den / x.denom())).collect(), den)
}

/// An integer polynomial P reduced modulo Ψ_n = Ψ/D (Ψ in integers, D its leading coefficient):
/// returns Q and D^k with P ≡ Q / D^k, deg Q < d. Each step multiplies by D and subtracts the
/// top coefficient times Ψ, so every number stays an integer.
fn reduce_integers(field: &Field, mut p: Vec<BigInt>) -> (Vec<BigInt>, BigInt) {
    let (d, psi) = (field.degree(), &field.psi_integers);
    let lead = &psi[d];
    let mut scale = BigInt::one();
    while p.len() > d {
        let top = p.pop().expect("longer than d");
        let k = p.len() - d;
        for x in p.iter_mut() {
            *x *= lead;
        }
        for (i, m) in psi[..d].iter().enumerate() {
            p[k + i] -= &top * m;
        }
        scale *= lead;
    }
    p.resize(d, BigInt::zero());
    (p, scale)
}

impl std::ops::Div for &Num {
    type Output = Num;
    fn div(self, o: &Num) -> Num {
        std::ops::Mul::mul(self, &o.inverse())
    }
}

impl std::ops::Neg for &Num {
    type Output = Num;
    fn neg(self) -> Num {
        Num::neg(self)
    }
}

impl PartialOrd for Num {
    fn partial_cmp(&self, o: &Num) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}

impl Ord for Num {
    fn cmp(&self, o: &Num) -> Ordering {
        (self - o).signum()
    }
}
