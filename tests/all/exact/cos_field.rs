//! Tests of `exact::cos_field`, the kernel's number fields Q(c), c = cos(2 pi/n) (issue 10 §3):
//! minimal polynomials, field axioms, signs (also of elements built to be tiny but non-zero),
//! the two backends, the untrusted `spectral::number_field` as a differential reference, and the
//! canonical text.
//!
//! The reference is independent of the field code: cos(2 pi k/n) as a rational interval about
//! 2^-290 wide, from pi by Machin's formula and cos by its Taylor series, both with remainder
//! bounds, in interval arithmetic with endpoints rounded outward to multiples of 2^-320.

use chatter::exact::QField;
use chatter::exact::{
    Algebraic, CosField, MAX_N, NumberError, OrderedField, ParseLimits, Q, Ring, cos_minimal_polynomial,
    parse_canonical, to_canonical,
};
use chatter::spectral::number_field::{
    Nf, NumberField, cos_minimal_polynomial as spectral_minimal_polynomial,
};
use chatter_kernel::exact::OrderedField as _;
use malachite::Integer;
use malachite::base::num::arithmetic::traits::{Ceiling, Floor, PowerOf2};
use malachite::rational::Rational;
use num_rational::BigRational;
use proptest::prelude::*;
use std::cmp::Ordering;
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

// ---------------------------------------------------------------------------------------------
// The high-precision reference.

/// Interval endpoints are rounded outward to multiples of 2^-GRID.
const GRID: u64 = 320;

/// A closed rational interval [lo, hi].
#[derive(Clone, Debug)]
struct Iv {
    lo: Rational,
    hi: Rational,
}

fn rat(n: i64, d: i64) -> Rational {
    Rational::from_signeds(n, d)
}

fn pow2(e: i64) -> Rational {
    Rational::power_of_2(e)
}

impl Iv {
    fn exact(x: Rational) -> Iv {
        Iv { lo: x.clone(), hi: x }
    }
    fn around(x: Rational, err: &Rational) -> Iv {
        Iv { lo: &x - err, hi: &x + err }
    }
    /// Rounded outward to the grid (keeps the denominators small).
    fn rounded(self) -> Iv {
        let s = pow2(GRID as i64);
        let lo = Rational::from(Floor::floor(&self.lo * &s)) / &s;
        let hi = Rational::from(Ceiling::ceiling(&self.hi * &s)) / &s;
        Iv { lo, hi }
    }
    fn add(&self, o: &Iv) -> Iv {
        Iv { lo: &self.lo + &o.lo, hi: &self.hi + &o.hi }
    }
    fn neg(&self) -> Iv {
        Iv { lo: -&self.hi, hi: -&self.lo }
    }
    fn sub(&self, o: &Iv) -> Iv {
        self.add(&o.neg())
    }
    fn mul(&self, o: &Iv) -> Iv {
        let p = [&self.lo * &o.lo, &self.lo * &o.hi, &self.hi * &o.lo, &self.hi * &o.hi];
        let lo = p.iter().min().unwrap().clone();
        let hi = p.iter().max().unwrap().clone();
        Iv { lo, hi }.rounded()
    }
    fn width(&self) -> Rational {
        &self.hi - &self.lo
    }
    /// The sign of every point, when the interval excludes 0.
    fn sign(&self) -> Option<Ordering> {
        if self.lo > 0u32 {
            Some(Ordering::Greater)
        } else if self.hi < 0u32 {
            Some(Ordering::Less)
        } else {
            None
        }
    }
    fn contains(&self, x: &Rational) -> bool {
        self.lo <= *x && *x <= self.hi
    }
    fn meets(&self, o: &Iv) -> bool {
        self.lo <= o.hi && o.lo <= self.hi
    }
    fn mid(&self) -> Rational {
        (&self.lo + &self.hi) / rat(2, 1)
    }
}

/// atan(1/x) = sum (-1)^j / ((2j+1) x^(2j+1)), an alternating series with decreasing terms.
fn atan_inv(x: i64) -> Iv {
    let (mut sum, mut j) = (Rational::from(0u32), 0i64);
    let x2 = rat(x * x, 1);
    let mut pw = rat(1, x); // 1/x^(2j+1)
    loop {
        let term = &pw / rat(2 * j + 1, 1);
        if term < pow2(-(GRID as i64) - 10) {
            return Iv::around(sum, &term).rounded();
        }
        sum = if j % 2 == 0 { sum + term } else { sum - term };
        pw /= &x2;
        j += 1;
    }
}

/// pi = 16 atan(1/5) - 4 atan(1/239) (Machin).
fn pi() -> &'static Iv {
    static PI: OnceLock<Iv> = OnceLock::new();
    PI.get_or_init(|| {
        let a = atan_inv(5).mul(&Iv::exact(rat(16, 1)));
        let b = atan_inv(239).mul(&Iv::exact(rat(4, 1)));
        a.sub(&b)
    })
}

/// cos on an interval [tl, th] with 0 < tl: the Taylor polynomial (each power monotone in the
/// argument) plus the Lagrange remainder bound th^(2M)/(2M)!.
fn cos_interval(t: &Iv) -> Iv {
    assert!(t.lo > 0u32);
    let t2 = t.mul(t);
    let mut sum = Iv::exact(rat(1, 1));
    let mut term = Iv::exact(rat(1, 1)); // [tl^(2m)/(2m)!, th^(2m)/(2m)!]
    let mut m = 0i64;
    loop {
        let f = rat(1, (2 * m + 1) * (2 * m + 2));
        term = term.mul(&t2).mul(&Iv::exact(f));
        m += 1;
        // (The grid is 2^-GRID: a rounded-up term never gets below it.)
        if term.hi < pow2(-(GRID as i64) + 20) && m > 4 {
            let err = term.hi.clone();
            return Iv { lo: &sum.lo - &err, hi: &sum.hi + &err }.rounded();
        }
        sum = if m % 2 == 1 { sum.sub(&term) } else { sum.add(&term) };
    }
}

/// cos(2 pi k/n) for 0 < k < n, as a rational interval (cached).
fn cos_ref(k: u64, n: u64) -> Iv {
    static CACHE: OnceLock<Mutex<HashMap<(u64, u64), Iv>>> = OnceLock::new();
    let cache = CACHE.get_or_init(Default::default);
    if let Some(v) = cache.lock().unwrap().get(&(k, n)) {
        return v.clone();
    }
    assert!(0 < k && k < n);
    let k2 = if 2 * k > n { n - k } else { k }; // cos(2 pi k/n) = cos(2 pi (n - k)/n): angle in (0, pi]
    let theta = pi().mul(&Iv::exact(rat(2 * k2 as i64, n as i64)));
    let v = cos_interval(&theta);
    cache.lock().unwrap().insert((k, n), v.clone());
    v
}

fn gcd(a: u64, b: u64) -> u64 {
    if b == 0 { a } else { gcd(b, a % b) }
}

fn phi(n: u64) -> u64 {
    (1..=n).filter(|&k| gcd(k, n) == 1).count() as u64
}

/// The k in 1..=n/2 prime to n: cos(2 pi k/n) are the conjugates of c, each once.
fn conjugates(n: u64) -> Vec<u64> {
    (1..=n / 2).filter(|&k| gcd(k, n) == 1).collect()
}

fn q_to_rat(q: &Q) -> Rational {
    q.as_rational().clone()
}

fn rat_to_q(r: &Rational) -> Q {
    Q::from_rational(r.clone())
}

/// The value of a polynomial (rational coefficients, lowest first) at an interval (Horner).
fn eval_iv(coeffs: &[Q], c: &Iv) -> Iv {
    let mut acc = Iv::exact(Rational::from(0u32));
    for a in coeffs.iter().rev() {
        acc = acc.mul(c).add(&Iv::exact(q_to_rat(a)));
    }
    acc
}

/// The value of x in the embedding c -> cos(2 pi k/n).
fn value_at(x: &Algebraic<Q>, k: u64, n: u64) -> Iv {
    eval_iv(x.coeffs(), &cos_ref(k, n))
}

/// The value of x (c = cos(2 pi/n)).
fn value(x: &Algebraic<Q>, n: u64) -> Iv {
    value_at(x, 1, n)
}

#[test]
fn reference_is_accurate() {
    let p = pi();
    assert!(p.width() < pow2(-300), "pi enclosure too wide");
    // 3.14159265358979323846264338327950288419716939937510 (50 digits).
    let digits: Integer = "314159265358979323846264338327950288419716939937510".parse().unwrap();
    let d = rat(1, 10).pow_small(50);
    let lo = Rational::from(digits) * &d;
    assert!(Iv { lo: &lo - &d, hi: &lo + &d }.meets(p), "pi is not pi");
    for n in [3u64, 4, 5, 6, 7, 8, 12, 17, 64] {
        for k in 1..n {
            let v = cos_ref(k, n);
            assert!(v.width() < pow2(-290), "cos(2 pi {k}/{n}) too wide");
            let f = (2.0 * std::f64::consts::PI * k as f64 / n as f64).cos();
            let m = v.mid();
            let mf = malachite_to_f64(&m);
            assert!((mf - f).abs() < 1e-12, "cos(2 pi {k}/{n}) = {mf}, f64 says {f}");
            // cos(2x) = 2 cos^2 x - 1.
            if 2 * k % n != 0 {
                let twice = cos_ref(2 * k % n, n);
                let via = v.mul(&v).mul(&Iv::exact(rat(2, 1))).sub(&Iv::exact(rat(1, 1)));
                assert!(twice.meets(&via), "double angle fails at {k}/{n}");
            }
        }
    }
    // Exact values: cos(2 pi/6) = 1/2, cos(2 pi/4) = 0, cos(2 pi/3) = -1/2.
    assert!(cos_ref(1, 6).contains(&rat(1, 2)));
    assert!(cos_ref(1, 4).contains(&rat(0, 1)));
    assert!(cos_ref(1, 3).contains(&rat(-1, 2)));
}

fn malachite_to_f64(r: &Rational) -> f64 {
    let s = pow2(60);
    let i = Floor::floor(r * &s);
    i.to_string().parse::<f64>().unwrap() / 2f64.powi(60)
}

trait PowSmall {
    fn pow_small(&self, e: u32) -> Self;
}
impl PowSmall for Rational {
    fn pow_small(&self, e: u32) -> Self {
        (0..e).fold(Rational::from(1u32), |acc, _| acc * self)
    }
}

// ---------------------------------------------------------------------------------------------
// Helpers for elements.

fn field(n: u64) -> Arc<CosField<Q>> {
    CosField::new(n).expect("3 <= n <= 64")
}

fn field_big(n: u64) -> Arc<CosField<BigRational>> {
    CosField::new(n).expect("3 <= n <= 64")
}

fn elem(k: &Arc<CosField<Q>>, coeffs: &[(i64, i64)]) -> Algebraic<Q> {
    k.element(coeffs.iter().map(|&(a, b)| Q::new(a, b)).collect())
}

fn to_big(k: &Arc<CosField<BigRational>>, x: &Algebraic<Q>) -> Algebraic<BigRational> {
    k.element(x.coeffs().iter().map(BigRational::from_q).collect())
}

fn rational(r: &Rational) -> Algebraic<Q> {
    Algebraic::from_q(&rat_to_q(r))
}

/// Sum a_k c^k computed in the field (Horner).
fn horner<F: OrderedField>(coeffs: &[F], c: &F) -> F {
    coeffs.iter().rev().fold(F::zero(), |acc, a| acc.times(c).plus(a))
}

fn nf(n: u64, x: &Algebraic<Q>) -> Nf {
    let g = NumberField::cos_2pi_over(n as usize).generator();
    horner(&x.coeffs().iter().map(Nf::from_q).collect::<Vec<_>>(), &g)
}

fn coeff_text(c: &[Q]) -> Vec<String> {
    c.iter().map(to_canonical).collect()
}

const NS: [u64; 6] = [5, 7, 8, 9, 11, 12];

/// (n, coefficients): n from [`NS`], up to 7 small rational coefficients (reduced mod Psi_n by
/// `element`), about a third of them zero.
fn element_spec() -> impl Strategy<Value = (u64, Vec<(i64, i64)>)> {
    let coeff = prop_oneof![Just((0i64, 1i64)), (-12i64..=12, 1i64..=9)];
    (prop::sample::select(NS.to_vec()), prop::collection::vec(coeff, 0..7))
}

fn cases(n: u32) -> ProptestConfig {
    ProptestConfig { cases: n, failure_persistence: None, ..ProptestConfig::default() }
}

// ---------------------------------------------------------------------------------------------
// 1. Minimal polynomials.

#[test]
fn minimal_polynomials_have_the_right_degree_and_roots() {
    for n in 3..=MAX_N {
        let psi = cos_minimal_polynomial::<Q>(n);
        let psi_big = cos_minimal_polynomial::<BigRational>(n);
        assert_eq!(psi.len() as u64 - 1, phi(n) / 2, "deg Psi_{n} != phi({n})/2");
        assert_eq!(psi.last().unwrap(), &Q::one(), "Psi_{n} not monic");
        assert_eq!(
            coeff_text(&psi),
            psi_big.iter().map(to_canonical).collect::<Vec<_>>(),
            "backends disagree on Psi_{n}"
        );
        let k = field(n);
        assert_eq!(k.n(), n);
        assert_eq!(k.degree() as u64, phi(n) / 2);
        assert_eq!(k.minimal_polynomial(), &psi[..]);
        // Every conjugate cos(2 pi k/n), gcd(k, n) = 1, is a root; with deg = phi(n)/2 distinct
        // roots, Psi_n is their product: the minimal polynomial.
        for j in conjugates(n) {
            let v = eval_iv(&psi, &cos_ref(j, n));
            assert!(v.contains(&Rational::from(0u32)), "cos(2 pi {j}/{n}) is not a root of Psi_{n}");
            assert!(v.width() < pow2(-200), "Psi_{n}(cos 2 pi {j}/{n}) enclosure too wide");
        }
        // And cos(2 pi k/n) with gcd(k, n) > 1 is not.
        for j in (1..=n / 2).filter(|&j| gcd(j, n) > 1) {
            let v = eval_iv(&psi, &cos_ref(j, n));
            assert!(v.sign().is_some(), "cos(2 pi {j}/{n}) (not primitive) is a root of Psi_{n}");
        }
    }
}

#[test]
fn minimal_polynomials_match_spectral() {
    for n in 3..=20u64 {
        let ours = cos_minimal_polynomial::<Q>(n);
        let theirs = spectral_minimal_polynomial(n as usize);
        assert_eq!(coeff_text(&ours), coeff_text(theirs.coeffs()), "Psi_{n}");
    }
}

#[test]
fn small_minimal_polynomials_by_hand() {
    let t = |n: u64| coeff_text(&cos_minimal_polynomial::<Q>(n)).join(" ");
    assert_eq!(t(1), "-1 1");
    assert_eq!(t(2), "1 1");
    assert_eq!(t(3), "1/2 1");
    assert_eq!(t(4), "0 1");
    assert_eq!(t(5), "-1/4 1/2 1"); // c^2 + c/2 - 1/4
    assert_eq!(t(6), "-1/2 1");
    assert_eq!(t(7), "-1/8 -1/2 1/2 1"); // c^3 + c^2/2 - c/2 - 1/8
    assert_eq!(t(8), "-1/2 0 1"); // c^2 - 1/2
    assert_eq!(t(12), "-3/4 0 1"); // c^2 - 3/4
}

#[test]
fn fields_exist_exactly_for_3_to_64() {
    for n in [0u64, 1, 2, MAX_N + 1, 100, u64::MAX] {
        assert!(CosField::<Q>::new(n).is_none(), "n = {n}");
        assert!(CosField::<BigRational>::new(n).is_none(), "n = {n}");
    }
    assert_eq!(MAX_N, 64);
    // Degree-1 fields: the generator is rational.
    for (n, c) in [(3u64, "-1/2"), (4, "0"), (6, "1/2")] {
        let k = field(n);
        assert_eq!(k.degree(), 1);
        let g = k.generator();
        assert_eq!(g.to_string(), c);
        assert_eq!(g.as_rational().map(|x| to_canonical(&x)), Some(c.to_string()));
        assert_eq!(field_big(n).generator().to_string(), c);
    }
}

#[test]
fn generator_is_cos_2pi_over_n() {
    let w = rat_to_q(&pow2(-200));
    for n in 3..=MAX_N {
        let k = field(n);
        let g = k.generator();
        let (lo, hi) = g.enclose(&w);
        assert!(&hi - &lo <= w, "n = {n}");
        let r = cos_ref(1, n);
        assert!(
            Iv { lo: q_to_rat(&lo), hi: q_to_rat(&hi) }.meets(&r),
            "generator of n = {n} is not cos(2 pi/{n})"
        );
        if k.degree() > 1 {
            assert_eq!(g.to_string(), "c");
            assert_eq!(g.coeffs(), &[Q::zero(), Q::one()]);
            assert!(g.as_rational().is_none());
        }
    }
}

// ---------------------------------------------------------------------------------------------
// 2. Field axioms, and the operations against the reference at every conjugate.

/// x op y computed in the field agrees with the reference in every embedding.
fn agrees(n: u64, got: &Algebraic<Q>, f: impl Fn(u64) -> Iv, what: &str) {
    for j in conjugates(n) {
        let v = value_at(got, j, n);
        let want = f(j);
        assert!(v.meets(&want), "{what} = {got:?} disagrees with the reference at cos(2 pi {j}/{n})");
    }
}

proptest! {
    #![proptest_config(cases(48))]

    #[test]
    fn field_axioms((n, a) in element_spec(), b in prop::collection::vec((-12i64..=12, 1i64..=9), 0..5),
                    cc in prop::collection::vec((-12i64..=12, 1i64..=9), 0..5)) {
        let k = field(n);
        let (x, y, z) = (elem(&k, &a), elem(&k, &b), elem(&k, &cc));
        let (zero, one) = (Algebraic::<Q>::zero(), Algebraic::<Q>::one());
        prop_assert_eq!(x.plus(&y), y.plus(&x));
        prop_assert_eq!(x.times(&y), y.times(&x));
        prop_assert_eq!(x.plus(&y).plus(&z), x.plus(&y.plus(&z)));
        prop_assert_eq!(x.times(&y).times(&z), x.times(&y.times(&z)));
        prop_assert_eq!(x.times(&y.plus(&z)), x.times(&y).plus(&x.times(&z)));
        prop_assert_eq!(x.plus(&zero), x.clone());
        prop_assert_eq!(x.times(&one), x.clone());
        prop_assert_eq!(x.times(&zero), zero.clone());
        prop_assert_eq!(x.plus(&x.negated()), zero.clone());
        prop_assert_eq!(x.minus(&y), x.plus(&y.negated()));
        prop_assert_eq!(x.negated().negated(), x.clone());
        prop_assert!(x.coeffs().len() <= k.degree());
        prop_assert!(x.coeffs().last().is_none_or(|l| !l.is_zero()), "untrimmed {:?}", x);
        prop_assert_eq!(x.over(&zero), None);
        prop_assert_eq!(x.over(&Algebraic::<Q>::from_q(&Q::zero())), None);
        if !x.is_zero() {
            let inv = one.over(&x).unwrap();
            prop_assert_eq!(x.times(&inv), one.clone());
            prop_assert_eq!(inv.times(&x), one.clone());
            prop_assert_eq!(y.over(&x).unwrap(), y.times(&inv));
            prop_assert_eq!(y.over(&x).unwrap().times(&x), y.clone());
            prop_assert_eq!(inv.over(&inv.times(&inv)).unwrap(), x.clone());
            prop_assert_eq!(x.over(&x).unwrap(), one.clone());
            for j in conjugates(n) {
                let v = value_at(&inv, j, n).mul(&value_at(&x, j, n));
                prop_assert!(v.contains(&rat(1, 1)), "1/x wrong at cos(2 pi {}/{})", j, n);
            }
        } else {
            prop_assert!(a.iter().all(|&(p, _)| p == 0) || k.degree() < a.len());
        }
        // Against the reference in every embedding.
        agrees(n, &x.plus(&y), |j| value_at(&x, j, n).add(&value_at(&y, j, n)), "x + y");
        agrees(n, &x.minus(&y), |j| value_at(&x, j, n).sub(&value_at(&y, j, n)), "x - y");
        agrees(n, &x.times(&y), |j| value_at(&x, j, n).mul(&value_at(&y, j, n)), "x * y");
        if let Some(q) = y.over(&x) {
            // (y / x) * x = y in every embedding.
            for j in conjugates(n) {
                let back = value_at(&q, j, n).mul(&value_at(&x, j, n));
                prop_assert!(back.meets(&value_at(&y, j, n)), "y / x wrong at cos(2 pi {}/{})", j, n);
            }
        }
        // The coefficients as a polynomial, evaluated in the field, reduce to x.
        let direct = horner(&a.iter().map(|&(p, q)| Algebraic::<Q>::from_ratio(p, q)).collect::<Vec<_>>(), &k.generator());
        prop_assert_eq!(direct, x.clone());
    }
}

// ---------------------------------------------------------------------------------------------
// 3. Sign and order.

proptest! {
    #![proptest_config(cases(48))]

    #[test]
    fn sign_and_order_match_the_reference((n, a) in element_spec(), b in prop::collection::vec((-12i64..=12, 1i64..=9), 0..5)) {
        let k = field(n);
        let (x, y) = (elem(&k, &a), elem(&k, &b));
        let vx = value(&x, n);
        match vx.sign() {
            Some(s) => prop_assert_eq!(x.sign(), s, "sign of {:?}", x),
            None => prop_assert!(x.is_zero(), "reference cannot separate {:?} from 0", x),
        }
        prop_assert_eq!(x.is_zero(), x.sign() == Ordering::Equal);
        prop_assert_eq!(x.is_positive(), x.sign() == Ordering::Greater);
        prop_assert_eq!(x.is_negative(), x.sign() == Ordering::Less);
        prop_assert_eq!(x.negated().sign(), x.sign().reverse());
        prop_assert_eq!(x.cmp(&y), x.minus(&y).sign());
        prop_assert_eq!(x.cmp(&y), y.cmp(&x).reverse());
        prop_assert_eq!(x.cmp(&y) == Ordering::Equal, x == y);
        prop_assert_eq!(y.minus(&x).negated().sign(), x.cmp(&y));
        if let Some(s) = value(&x, n).sub(&value(&y, n)).sign() {
            prop_assert_eq!(x.cmp(&y), s);
            prop_assert_eq!(x < y, s == Ordering::Less);
        }
        // x^2 >= 0, and > 0 unless x = 0.
        let sq = x.times(&x);
        prop_assert_eq!(sq.sign(), if x.is_zero() { Ordering::Equal } else { Ordering::Greater });
        // Sign of a product is the product of signs.
        let s = x.times(&y).sign();
        let want = match (x.sign(), y.sign()) {
            (Ordering::Equal, _) | (_, Ordering::Equal) => Ordering::Equal,
            (p, q) if p == q => Ordering::Greater,
            _ => Ordering::Less,
        };
        prop_assert_eq!(s, want);
    }

    /// x - r for r a rational within 2^-bits of x, bits up to 200 (taken from the reference):
    /// the sign must be the reference's, never Equal.
    #[test]
    fn tiny_differences_have_the_right_sign((n, a) in element_spec(), bits in prop::sample::select(vec![40i64, 80, 120, 160, 200])) {
        let k = field(n);
        let x = elem(&k, &a);
        prop_assume!(x.as_rational().is_none());
        let vx = value(&x, n);
        // r = the midpoint rounded to the 2^-bits grid.
        let s = pow2(bits);
        let r = Rational::from(Floor::floor(&vx.mid() * &s)) / &s;
        let d = x.minus(&rational(&r));
        let vd = vx.sub(&Iv::exact(r.clone()));
        prop_assert!(vd.hi.clone() - vd.lo.clone() < pow2(-250));
        let sd = d.sign();
        prop_assert_ne!(sd, Ordering::Equal, "x - r = 0 for irrational x = {:?}", x);
        if let Some(want) = vd.sign() {
            prop_assert_eq!(sd, want, "sign of {:?} - {} (2^-{} close)", x, r, bits);
        }
        prop_assert_eq!(x.cmp(&rational(&r)), sd);
        prop_assert_eq!(rational(&r).cmp(&x), sd.reverse());

        // From the field's own enclosure: lo <= x <= hi, and x irrational, so lo < x < hi.
        let w = rat_to_q(&pow2(-100));
        let (lo, hi) = x.enclose(&w);
        prop_assert_eq!(x.minus(&Algebraic::from_q(&lo)).sign(), Ordering::Greater);
        prop_assert_eq!(Algebraic::from_q(&hi).minus(&x).sign(), Ordering::Greater);
        prop_assert!(vx.lo <= q_to_rat(&hi) && q_to_rat(&lo) <= vx.hi);

        // Products of tiny elements: sign is the product of signs, never Equal.
        let e = x.minus(&Algebraic::from_q(&lo)); // > 0, tiny
        let p = d.times(&e);
        prop_assert_eq!(p.sign(), sd);
        let p2 = d.times(&d).times(&e.negated());
        prop_assert_eq!(p2.sign(), Ordering::Less);
        prop_assert_eq!(d.times(&d).times(&d).sign(), sd);
    }
}

/// The continued-fraction convergents of every number in [lo, hi] (the partial quotients of lo
/// and hi while they agree), denominators up to 2^max_bits.
fn convergents(iv: &Iv, max_bits: u64) -> Vec<Rational> {
    let (mut a, mut b) = (iv.lo.clone(), iv.hi.clone());
    let (mut p0, mut q0, mut p1, mut q1) =
        (Integer::from(0), Integer::from(1), Integer::from(1), Integer::from(0));
    let mut out = Vec::new();
    loop {
        let (fa, fb) = (Floor::floor(&a), Floor::floor(&b));
        if fa != fb {
            return out;
        }
        let p = &fa * &p1 + &p0;
        let q = &fa * &q1 + &q0;
        out.push(Rational::from_integers(p.clone(), q.clone()));
        if q > Integer::power_of_2(max_bits) {
            return out;
        }
        (p0, q0, p1, q1) = (p1, q1, p, q);
        let (ra, rb) = (a - Rational::from(fa), b - Rational::from(fb));
        if ra == 0u32 || rb == 0u32 {
            return out;
        }
        (a, b) = (Rational::from(1u32) / rb, Rational::from(1u32) / ra);
    }
}

/// c - p/q for the convergents p/q of c (|c - p/q| < 1/q^2, down to about 2^-112), their
/// products and powers: signs right (alternating), never Equal.
#[test]
fn generator_minus_convergents() {
    for n in [5u64, 7, 8, 12, 13, 31] {
        let k = field(n);
        let c = k.generator();
        let r = cos_ref(1, n);
        let conv = convergents(&r, 56);
        assert!(conv.len() > 10, "n = {n}: only {} convergents", conv.len());
        let mut prev: Option<Algebraic<Q>> = None;
        for (i, pq) in conv.iter().enumerate() {
            let d = c.minus(&rational(pq));
            let want =
                r.sub(&Iv::exact(pq.clone())).sign().expect("reference separates c from its convergents");
            // Even convergents lie below, odd ones above.
            assert_eq!(want, if i % 2 == 0 { Ordering::Greater } else { Ordering::Less }, "n = {n}, i = {i}");
            assert_eq!(d.sign(), want, "sign of c - {pq} for n = {n}");
            assert_eq!(c.cmp(&rational(pq)), want);
            assert_eq!(d.times(&d).sign(), Ordering::Greater);
            assert_eq!(d.times(&d).times(&d).sign(), want);
            let inv = Algebraic::<Q>::one().over(&d).unwrap();
            assert_eq!(inv.sign(), want);
            assert_eq!(inv.times(&d), Algebraic::one());
            if let Some(e) = &prev {
                // Consecutive convergents lie on opposite sides.
                assert_eq!(d.times(e).sign(), Ordering::Less, "n = {n}, i = {i}");
            }
            prev = Some(d);
        }
        // A polynomial in c, tiny: Psi_n(c) + c - p/q = c - p/q written with high powers of c.
        let pq = conv.last().unwrap();
        let psi: Vec<Algebraic<Q>> = k.minimal_polynomial().iter().map(Algebraic::from_q).collect();
        let mut coeffs = psi.clone();
        coeffs[0] = coeffs[0].minus(&rational(pq));
        coeffs[1] = coeffs[1].plus(&Algebraic::one());
        let y = horner(&coeffs, &c);
        assert_eq!(y, c.minus(&rational(pq)));
    }
}

#[test]
fn zero_elements_have_sign_equal() {
    for n in 3..=MAX_N {
        let k = field(n);
        let c = k.generator();
        let psi: Vec<Algebraic<Q>> = k.minimal_polynomial().iter().map(Algebraic::from_q).collect();
        let z = horner(&psi, &c);
        assert_eq!(z, Algebraic::zero(), "Psi_{n}(c) != 0 in the field");
        assert_eq!(z.sign(), Ordering::Equal);
        assert_eq!(z.to_string(), "0");
        assert!(z.coeffs().is_empty());
        let x = c.plus(&Algebraic::from_ratio(1, 3)).times(&c);
        assert_eq!(x.minus(&x).sign(), Ordering::Equal);
        assert_eq!(x.cmp(&x), Ordering::Equal);
        if !x.is_zero() {
            let inv = Algebraic::<Q>::one().over(&x).unwrap();
            assert_eq!(x.times(&inv).minus(&Algebraic::one()).sign(), Ordering::Equal);
        }
        // On the other backend too (building its fields is slower).
        if ![5, 7, 9, 12, 13, 16].contains(&n) {
            continue;
        }
        let kb = field_big(n);
        let cb = kb.generator();
        let psib: Vec<Algebraic<BigRational>> =
            kb.minimal_polynomial().iter().map(|a| Algebraic::rational(a.clone())).collect();
        assert_eq!(horner(&psib, &cb).sign(), Ordering::Equal, "n = {n}, num backend");
    }
}

// ---------------------------------------------------------------------------------------------
// 4. Both backends agree.

fn same<T: std::fmt::Display, U: std::fmt::Display>(a: &T, b: &U) -> Result<(), TestCaseError> {
    prop_assert_eq!(a.to_string(), b.to_string());
    Ok(())
}

proptest! {
    #![proptest_config(cases(40))]

    #[test]
    fn backends_agree((n, a) in element_spec(), b in prop::collection::vec((-12i64..=12, 1i64..=9), 0..5)) {
        let (k, kb) = (field(n), field_big(n));
        let (x, y) = (elem(&k, &a), elem(&k, &b));
        let xb = kb.element(a.iter().map(|&(p, q)| BigRational::from_ratio(p, q)).collect());
        let yb = kb.element(b.iter().map(|&(p, q)| BigRational::from_ratio(p, q)).collect());
        same(&x, &xb)?;
        same(&y, &yb)?;
        same(&x.plus(&y), &xb.plus(&yb))?;
        same(&x.minus(&y), &xb.minus(&yb))?;
        same(&x.times(&y), &xb.times(&yb))?;
        same(&x.negated(), &xb.negated())?;
        prop_assert_eq!(x.over(&y).map(|v| v.to_string()), xb.over(&yb).map(|v| v.to_string()));
        prop_assert_eq!(y.over(&x).map(|v| v.to_string()), yb.over(&xb).map(|v| v.to_string()));
        prop_assert_eq!(x.sign(), xb.sign());
        prop_assert_eq!(x.cmp(&y), xb.cmp(&yb));
        let w = rat_to_q(&pow2(-80));
        prop_assert_eq!(x.enclose(&w), xb.enclose(&w));
        prop_assert_eq!(to_big(&kb, &x), xb.clone());
        same(&k.generator(), &kb.generator())?;
        // Parsing each other's text.
        let t = x.times(&y).to_string();
        same(&k.parse(&t, ParseLimits::default()).unwrap(), &kb.parse(&t, ParseLimits::default()).unwrap())?;
    }
}

// ---------------------------------------------------------------------------------------------
// 5. Differential against the untrusted `spectral::number_field`.

proptest! {
    #![proptest_config(cases(40))]

    #[test]
    fn agrees_with_spectral_number_field((n, a) in element_spec(), b in prop::collection::vec((-12i64..=12, 1i64..=9), 0..5)) {
        let k = field(n);
        let (x, y) = (elem(&k, &a), elem(&k, &b));
        let (u, v) = (nf(n, &x), nf(n, &y));
        prop_assert_eq!(coeff_text(x.coeffs()), coeff_text(u.coeffs()));
        prop_assert_eq!(coeff_text(x.times(&y).coeffs()), coeff_text(u.times(&v).coeffs()));
        prop_assert_eq!(coeff_text(x.plus(&y).coeffs()), coeff_text(u.plus(&v).coeffs()));
        prop_assert_eq!(x.over(&y).map(|z| coeff_text(z.coeffs())), u.over(&v).map(|z| coeff_text(z.coeffs())));
        prop_assert_eq!(y.over(&x).map(|z| coeff_text(z.coeffs())), v.over(&u).map(|z| coeff_text(z.coeffs())));
        prop_assert_eq!(x.sign(), u.sign());
        prop_assert_eq!(x.cmp(&y), u.cmp(&v));
        // A tiny difference: both implementations see the same sign.
        let vx = value(&x, n);
        let s = pow2(150);
        let r = Q::from_rational(Rational::from(Floor::floor(&vx.mid() * &s)) / &s);
        prop_assert_eq!(x.minus(&Algebraic::from_q(&r)).sign(), u.minus(&Nf::from_q(&r)).sign());
    }
}

// ---------------------------------------------------------------------------------------------
// 6. Canonical text.

fn parse(n: u64, s: &str) -> Result<Algebraic<Q>, NumberError> {
    let a = field(n).parse(s, ParseLimits::default());
    let b = field_big(n).parse(s, ParseLimits::default());
    match (&a, &b) {
        (Ok(x), Ok(y)) => assert_eq!(x.to_string(), y.to_string(), "backends disagree on {s:?}"),
        (Err(e), Err(f)) => assert_eq!(e, f, "backends give different errors on {s:?}"),
        _ => panic!("backends disagree on {s:?}: {a:?} vs {b:?}"),
    }
    a
}

fn not_canonical(c: &str) -> NumberError {
    NumberError::NotCanonical { canonical: c.to_string() }
}

proptest! {
    #![proptest_config(cases(64))]

    #[test]
    fn text_round_trips((n, a) in element_spec(), big in prop::collection::vec(any::<i64>(), 0..3)) {
        let k = field(n);
        let mut x = elem(&k, &a);
        for v in big {
            x = x.times(&k.generator()).plus(&Algebraic::from_ratio(v, 7));
        }
        let t = x.to_string();
        let y = parse(n, &t).unwrap();
        prop_assert_eq!(&y, &x);
        prop_assert_eq!(y.to_string(), t.clone());
        prop_assert!(!t.contains("  ") && !t.starts_with(' ') && !t.ends_with(' ') && !t.contains("+ -"));
        for term in t.trim_start_matches('-').split(" + ").flat_map(|s| s.split(" - ")).filter(|_| t != "0") {
            prop_assert!(!term.starts_with("1*") && !term.ends_with("^1") && !term.starts_with('0'), "term {:?} in {:?}", term, t);
        }
        // Text without c is a rational.
        if !t.contains('c') {
            prop_assert!(x.as_rational().is_some());
            prop_assert_eq!(t.clone(), to_canonical(&x.as_rational().unwrap()));
        }
        // Changing the text breaks it: an extra space, a doubled sign.
        for bad in [format!("{t} "), format!(" {t}"), format!("+{t}")] {
            let rejected = parse(n, &bad).is_err();
            prop_assert!(rejected, "{:?} accepted", bad);
        }
    }
}

#[test]
fn canonical_text_examples() {
    let k = field(7); // degree 3
    let c = k.generator();
    let x = Algebraic::from_ratio(-1, 4).plus(&c.times(&Algebraic::from_ratio(3, 2))).minus(&c.times(&c));
    assert_eq!(x.to_string(), "-1/4 + 3/2*c - c^2");
    assert_eq!(parse(7, "-1/4 + 3/2*c - c^2").unwrap(), x);
    assert_eq!(c.negated().to_string(), "-c");
    assert_eq!(c.times(&c).negated().to_string(), "-c^2");
    assert_eq!(c.times(&Algebraic::from_ratio(-2, 3)).to_string(), "-2/3*c");
    assert_eq!(Algebraic::<Q>::zero().to_string(), "0");
    assert_eq!(parse(7, "c^2").unwrap(), c.times(&c));
    assert_eq!(parse(7, "-c").unwrap(), c.negated());
    assert_eq!(parse(7, "1 - c").unwrap(), Algebraic::one().minus(&c));
    assert_eq!(parse(7, "5*c^2").unwrap(), c.times(&c).times(&Algebraic::from_i64(5)));
    // c^3 reduces: c^3 = -c^2/2 + c/2 + 1/8 for n = 7.
    assert_eq!(c.times(&c).times(&c).to_string(), "1/8 + 1/2*c - 1/2*c^2");
}

#[test]
fn non_canonical_spellings_are_rejected() {
    // n = 5: degree 2.
    let e = |s: &str| parse(5, s).expect_err(s);
    assert_eq!(e("1*c"), not_canonical("c"));
    assert_eq!(e("c^1"), not_canonical("c"));
    assert_eq!(e("c^0"), not_canonical("1"));
    assert_eq!(e("c + 1/2"), not_canonical("1/2 + c"));
    assert_eq!(e("1/2 + 0*c"), not_canonical("1/2"));
    assert_eq!(e("c + c"), not_canonical("2*c"));
    assert_eq!(e("c - c"), not_canonical("0"));
    assert_eq!(e("1 + c - 1"), not_canonical("c"));
    assert_eq!(e("c^01"), not_canonical("c"));
    assert_eq!(e("2/4*c"), NumberError::NotReduced { canonical: "1/2".into() });
    assert_eq!(e("3/1*c"), NumberError::UnitDenominator { canonical: "3".into() });
    assert_eq!(e("c^2"), NumberError::PowerTooHigh { power: 2, degree: 2 });
    assert_eq!(e("1/2 + c^7"), NumberError::PowerTooHigh { power: 7, degree: 2 });
    assert_eq!(e("-0"), NumberError::NegativeZero);
    assert_eq!(e(""), NumberError::Empty);
    for s in [
        "1/2+c",
        "1/2 +c",
        "1/2+ c",
        "+c",
        "1/2 - -c",
        "1/2 + -c",
        " c",
        "c ",
        "c  ",
        "1/2  + c",
        "2c",
        "c*2",
        "c^",
        "c^x",
        "c^-1",
        "c^100",
        "1/2 + ",
        "- c",
        "--c",
        "c c",
        "cc",
        "c^2^1",
        "1/2 + c +",
        "C",
        "c\n",
        "\tc",
        "1/2 + (c)",
        "c/2",
        "1/2*c*c",
    ] {
        assert!(parse(5, s).is_err(), "{s:?} accepted");
    }
    // Degree-1 fields: c is rational and has no power in the text.
    for n in [3u64, 4, 6] {
        assert_eq!(
            parse(n, "c").expect_err("c"),
            NumberError::PowerTooHigh { power: 1, degree: 1 },
            "n = {n}"
        );
        assert!(parse(n, "1/2 + c").is_err());
    }
    // Degree-3 field: c^2 fine, c^3 not.
    assert!(parse(7, "c^2").is_ok());
    assert_eq!(parse(7, "c^3").expect_err("c^3"), NumberError::PowerTooHigh { power: 3, degree: 3 });
}

/// An `InvalidCharacter` error names a character of the input.
#[test]
fn invalid_character_errors_name_a_character_of_the_input() {
    for s in ["+c", "1/2 - -c", "2c", "1/2 + (c)", "- c", "--c"] {
        if let Err(NumberError::InvalidCharacter(ch)) = parse(5, s) {
            assert!(s.contains(ch), "{s:?} rejected for the character {ch:?}, which it does not contain");
        }
    }
}

#[test]
fn rationals_parse_as_before() {
    for n in [3u64, 5, 7, 12, 64] {
        for s in ["0", "1", "-1", "1/2", "-7/3", "123456789012345678901234567891/7"] {
            let x = parse(n, s).unwrap();
            assert_eq!(x.as_rational(), Some(parse_canonical::<Q>(s, ParseLimits::default()).unwrap()));
            assert_eq!(x.to_string(), s);
        }
        for s in ["", "-0", "01", "2/4", "3/1", "+1", " 1", "1 ", "1/0", "1/", "/2", "0.5", "1e3"] {
            let want = parse_canonical::<Q>(s, ParseLimits::default()).unwrap_err();
            assert_eq!(parse(n, s).unwrap_err(), want, "{s:?}");
        }
    }
    // Limits apply to coefficients.
    let long = format!("{}*c", "9".repeat(40));
    let k = field(5);
    assert!(k.parse(&long, ParseLimits::digits(20)).is_err());
    assert!(k.parse(&long, ParseLimits::default()).is_ok());
}

// ---------------------------------------------------------------------------------------------
// 7. enclose.

proptest! {
    #![proptest_config(cases(48))]

    #[test]
    fn enclose_holds_the_value((n, a) in element_spec(), e in prop::sample::select(vec![0i64, 1, 10, 33, 64, 100, 200])) {
        let k = field(n);
        let x = elem(&k, &a);
        let w = rat_to_q(&pow2(-e));
        let (lo, hi) = x.enclose(&w);
        let v = value(&x, n);
        prop_assert!(lo <= hi);
        prop_assert!(&hi - &lo <= w, "width {} > 2^-{}", &hi - &lo, e);
        prop_assert!(q_to_rat(&lo) <= v.hi && v.lo <= q_to_rat(&hi), "[{}, {}] misses the value of {:?}", lo, hi, x);
        if let Some(r) = x.as_rational() {
            prop_assert_eq!((lo, hi), (r.clone(), r));
        } else {
            // Strict: x is irrational.
            prop_assert_eq!(Algebraic::from_q(&lo).cmp(&x), Ordering::Less);
            prop_assert_eq!(Algebraic::from_q(&hi).cmp(&x), Ordering::Greater);
        }
        let xb = to_big(&field_big(n), &x);
        prop_assert_eq!(xb.enclose(&w), x.enclose(&w));
    }
}
