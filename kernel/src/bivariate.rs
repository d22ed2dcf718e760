//! Polynomials in (kappa, gamma) and their sign on a box of parameters, by Bernstein expansion
//! with subdivision (docs/kernel-soundness.md §2, "Boxes"). A polynomial is dense: `c[i][j]` is
//! the coefficient of kappa^i gamma^j.

use crate::exact::{Field, Int, OrderedField, Ring, scale_to_ints};

/// A polynomial in (kappa, gamma) with coefficients in `F`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Bi<F> {
    /// `c[i][j]`: the coefficient of kappa^i gamma^j; every row has the same length.
    c: Vec<Vec<F>>,
}

/// A closed box [k0, k1] x [g0, g1] of parameters (k0 <= k1, g0 <= g1).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Rect<F> {
    /// kappa's interval.
    pub kappa: [F; 2],
    /// gamma's interval.
    pub gamma: [F; 2],
}

impl<F: OrderedField> Bi<F> {
    /// The constant `x`.
    pub fn constant(x: F) -> Self {
        Bi { c: vec![vec![x]] }
    }

    /// `a + b kappa + c gamma + d kappa gamma`.
    pub fn bilinear(a: F, b: F, c: F, d: F) -> Self {
        Bi { c: vec![vec![a, c], vec![b, d]] }
    }

    fn degrees(&self) -> (usize, usize) {
        (self.c.len() - 1, self.c[0].len() - 1)
    }

    /// Drops the rows and columns of zero coefficients at the top degrees (keeps one of each).
    fn trimmed(mut self) -> Self {
        while self.c.len() > 1 && self.c.last().is_some_and(|r| r.iter().all(F::is_zero)) {
            self.c.pop();
        }
        while self.c[0].len() > 1 && self.c.iter().all(|r| r.last().is_some_and(F::is_zero)) {
            self.c.iter_mut().for_each(|r| {
                r.pop();
            });
        }
        self
    }

    fn zero_of(dk: usize, dg: usize) -> Self {
        Bi { c: vec![vec![F::zero(); dg + 1]; dk + 1] }
    }

    /// `self + o`.
    pub fn plus(&self, o: &Self) -> Self {
        let (a, b) = (self.degrees(), o.degrees());
        let mut r = Self::zero_of(a.0.max(b.0), a.1.max(b.1));
        for p in [self, o] {
            for (i, row) in p.c.iter().enumerate() {
                for (j, x) in row.iter().enumerate() {
                    r.c[i][j] = r.c[i][j].plus(x);
                }
            }
        }
        r.trimmed()
    }

    /// `-self`.
    pub fn negated(&self) -> Self {
        Bi { c: self.c.iter().map(|row| row.iter().map(F::negated).collect()).collect() }
    }

    /// `self - o`.
    pub fn minus(&self, o: &Self) -> Self {
        self.plus(&o.negated())
    }

    /// `self o`.
    pub fn times(&self, o: &Self) -> Self {
        let (a, b) = (self.degrees(), o.degrees());
        let mut r = Self::zero_of(a.0 + b.0, a.1 + b.1);
        for (i, row) in self.c.iter().enumerate() {
            for (j, x) in row.iter().enumerate().filter(|(_, x)| !x.is_zero()) {
                for (k, row2) in o.c.iter().enumerate() {
                    for (l, y) in row2.iter().enumerate() {
                        r.c[i + k][j + l] = r.c[i + k][j + l].plus(&x.times(y));
                    }
                }
            }
        }
        r.trimmed()
    }

    /// Whether every coefficient is zero.
    pub fn is_zero(&self) -> bool {
        self.c.iter().flatten().all(F::is_zero)
    }

    /// The value at (kappa, gamma).
    pub fn at(&self, kappa: &F, gamma: &F) -> F {
        let row = |r: &Vec<F>| r.iter().rev().fold(F::zero(), |acc, x| acc.times(gamma).plus(x));
        self.c.iter().rev().fold(F::zero(), |acc, r| acc.times(kappa).plus(&row(r)))
    }

    /// The Bernstein coefficients on `rect`: the polynomial in (s, t) in [0, 1]^2 with
    /// kappa = k0 + (k1 - k0) s, gamma = g0 + (g1 - g0) t, in the tensor Bernstein basis of its
    /// degrees. The polynomial's values on the box lie between their least and greatest.
    pub fn bernstein(&self, rect: &Rect<F>) -> Vec<Vec<F>> {
        let (dk, dg) = self.degrees();
        let lin = |r: &[F; 2]| [r[0].clone(), r[1].minus(&r[0])];
        let (ks, gs) = (lin(&rect.kappa), lin(&rect.gamma));
        // Substitute: kappa = ks0 + ks1 s, gamma = gs0 + gs1 t, term by term.
        let mut sub = Self::zero_of(dk, dg);
        for (i, row) in self.c.iter().enumerate() {
            for (j, x) in row.iter().enumerate().filter(|(_, x)| !x.is_zero()) {
                let pk = powers_of_affine(&ks, i);
                let pg = powers_of_affine(&gs, j);
                for (a, u) in pk.iter().enumerate() {
                    for (b, w) in pg.iter().enumerate() {
                        sub.c[a][b] = sub.c[a][b].plus(&x.times(u).times(w));
                    }
                }
            }
        }
        // Power basis to Bernstein basis, in each variable: b_i = sum_{k <= i} C(i,k)/C(d,k) a_k.
        let to_b = |a: &[F], d: usize| -> Vec<F> {
            (0..=d)
                .map(|i| {
                    (0..=i).fold(F::zero(), |acc, k| {
                        let w = F::from_ratio(binomial(i, k), binomial(d, k));
                        acc.plus(&w.times(&a[k]))
                    })
                })
                .collect()
        };
        let rows: Vec<Vec<F>> = sub.c.iter().map(|r| to_b(r, dg)).collect();
        let cols: Vec<Vec<F>> =
            (0..=dg).map(|j| to_b(&rows.iter().map(|r| r[j].clone()).collect::<Vec<_>>(), dk)).collect();
        (0..=dk).map(|i| (0..=dg).map(|j| cols[j][i].clone()).collect()).collect()
    }
}

impl<F: Field> Bi<F> {
    /// Positive multiples of the Bernstein coefficients on `rect` (each of the sign of the
    /// coefficient of [`Bi::bernstein`]), in integers, so that no fraction is reduced: with
    /// kappa = (A + B t)/D, gamma = (C + E s)/G over t, s in [0, 1] and L a common denominator
    /// of the coefficients, L D^dk G^dg p is an integer polynomial in (t, s), and its Bernstein
    /// coefficients times the lcm of the binomials C(dk, k) and of C(dg, l) are integers.
    pub fn bernstein_scaled(&self, rect: &Rect<F>) -> Vec<Vec<F::Int>> {
        let (dk, dg) = self.degrees();
        let z = scale_to_ints(&self.c.iter().flatten().cloned().collect::<Vec<F>>());
        let (pk, pg) = (integer_powers(&rect.kappa, dk), integer_powers(&rect.gamma, dg));
        let mut sub = vec![vec![F::Int::zero(); dg + 1]; dk + 1];
        for (i, row) in z.chunks(dg + 1).enumerate() {
            for (j, x) in row.iter().enumerate().filter(|(_, x)| !x.is_zero()) {
                for (a, u) in pk[i].iter().enumerate() {
                    let xu = x.times(u);
                    for (b, w) in pg[j].iter().enumerate() {
                        sub[a][b] = sub[a][b].plus(&xu.times(w));
                    }
                }
            }
        }
        let rows: Vec<Vec<F::Int>> = sub.iter().map(|r| to_bernstein_scaled(r, dg)).collect();
        let cols: Vec<Vec<F::Int>> = (0..=dg)
            .map(|j| to_bernstein_scaled(&rows.iter().map(|r| r[j].clone()).collect::<Vec<_>>(), dk))
            .collect();
        (0..=dk).map(|i| (0..=dg).map(|j| cols[j][i].clone()).collect()).collect()
    }
}

/// For [lo, hi] = [a0/b0, a1/b1]: x = (A + B t)/D with D = b0 b1 > 0, and the integer
/// coefficients in t of (A + B t)^i D^(e - i), i = 0..=e.
fn integer_powers<F: Field>(r: &[F; 2], e: usize) -> Vec<Vec<F::Int>> {
    let d = r[0].denom().times(&r[1].denom());
    let a = r[0].numer().times(&r[1].denom());
    let b = r[1].numer().times(&r[0].denom()).minus(&a);
    let mut powers = vec![vec![F::Int::one()]];
    for _ in 0..e {
        let p = powers.last().expect("one");
        let mut q = vec![F::Int::zero(); p.len() + 1];
        for (k, x) in p.iter().enumerate() {
            q[k] = q[k].plus(&x.times(&a));
            q[k + 1] = q[k + 1].plus(&x.times(&b));
        }
        powers.push(q);
    }
    let mut d_pow = F::Int::one();
    for i in (0..=e).rev() {
        powers[i] = powers[i].iter().map(|x| x.times(&d_pow)).collect();
        d_pow = d_pow.times(&d);
    }
    powers
}

/// The Bernstein coefficients of degree `d` of the power coefficients `a`, times W = lcm of the
/// C(d, k): b_i W = sum_k C(i, k) (W / C(d, k)) a_k.
fn to_bernstein_scaled<Z: Int>(a: &[Z], d: usize) -> Vec<Z> {
    let gcd = |mut x: i64, mut y: i64| {
        while y != 0 {
            (x, y) = (y, x % y);
        }
        x
    };
    let w = (0..=d).fold(1i64, |l, k| l / gcd(l, binomial(d, k)) * binomial(d, k));
    (0..=d)
        .map(|i| {
            (0..=i).fold(Z::zero(), |acc, k| {
                acc.plus(&Z::from_i64(binomial(i, k) * (w / binomial(d, k))).times(&a[k]))
            })
        })
        .collect()
}

/// The coefficients of (a0 + a1 s)^e in s, lowest first.
fn powers_of_affine<F: OrderedField>(a: &[F; 2], e: usize) -> Vec<F> {
    let mut p = vec![F::one()];
    for _ in 0..e {
        let mut q = vec![F::zero(); p.len() + 1];
        for (k, x) in p.iter().enumerate() {
            q[k] = q[k].plus(&x.times(&a[0]));
            q[k + 1] = q[k + 1].plus(&x.times(&a[1]));
        }
        p = q;
    }
    p
}

/// C(n, k) for the small degrees used here.
fn binomial(n: usize, k: usize) -> i64 {
    (0..k).fold(1i64, |acc, i| acc * (n - i) as i64 / (i + 1) as i64)
}

impl<F: OrderedField> Rect<F> {
    /// The four quarters, in the order (low kappa, low gamma), (high, low), (low, high), (high, high).
    pub fn quarters(&self) -> [Rect<F>; 4] {
        let mid = |r: &[F; 2]| r[0].plus(&r[1]).over(&F::from_i64(2)).expect("2 != 0");
        let (km, gm) = (mid(&self.kappa), mid(&self.gamma));
        let k = [[self.kappa[0].clone(), km.clone()], [km, self.kappa[1].clone()]];
        let g = [[self.gamma[0].clone(), gm.clone()], [gm, self.gamma[1].clone()]];
        [(0, 0), (1, 0), (0, 1), (1, 1)].map(|(a, b)| Rect { kappa: k[a].clone(), gamma: g[b].clone() })
    }
}

/// Why a polynomial was not shown negative on a box.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum NotNegative<F> {
    /// It is >= 0 at this point (kappa, gamma): a corner of a sub-box.
    At(F, F),
    /// The subdivision limit was reached; this sub-box is still undecided.
    Undecided(Rect<F>),
}

/// Proves `p < 0` on `rect`: every Bernstein coefficient negative on every box of a subdivision
/// into quarters (breadth first, at most `max_boxes` boxes examined). Returns the number of boxes
/// examined.
pub fn negative_on<F: Field>(p: &Bi<F>, rect: &Rect<F>, max_boxes: usize) -> Result<usize, NotNegative<F>> {
    let mut queue = std::collections::VecDeque::from([rect.clone()]);
    let mut examined = 0;
    while let Some(r) = queue.pop_front() {
        examined += 1;
        let b = p.bernstein_scaled(&r);
        if b.iter().flatten().all(Ring::is_negative) {
            continue;
        }
        // The corner coefficients are the values at the corners.
        let (dk, dg) = p.degrees();
        for (i, j) in [(0, 0), (dk, 0), (0, dg), (dk, dg)] {
            if !b[i][j].is_negative() {
                let k = r.kappa[usize::from(i > 0)].clone();
                let g = r.gamma[usize::from(j > 0)].clone();
                return Err(NotNegative::At(k, g));
            }
        }
        if examined + queue.len() + 4 > max_boxes {
            return Err(NotNegative::Undecided(r));
        }
        queue.extend(r.quarters());
    }
    Ok(examined)
}
