//! Exact real-root isolation (Sturm sequences and bisection with rational endpoints) and real
//! algebraic numbers: a square-free polynomial with an isolating interval, refined on demand.

use super::poly::{Point, Poly, count_roots};
use crate::exact::{OrderedField, Q, QExt, Rounding};
use std::cmp::Ordering;

/// A real root of `poly` (square-free, monic): the only root in the open interval (lo, hi), or
/// exactly `lo` when lo == hi. Endpoints of a proper interval are never roots.
#[derive(Clone, Debug)]
pub struct RealRoot<F> {
    pub poly: Poly<F>,
    pub lo: Q,
    pub hi: Q,
}

/// A power of two strictly larger than every |root| (Cauchy: 1 + max |a_i / a_n|).
fn root_bound<F: OrderedField>(p: &Poly<F>) -> Q {
    let n = p.degree().unwrap_or(0);
    let lead = p.lead().expect("non-zero").clone();
    let mut b = Q::int(2);
    for a in &p.coeffs()[..n] {
        let r = a.over(&lead).expect("non-zero lead");
        let r = if r.is_negative() { r.negated() } else { r };
        while F::from_q(&(&b - &Q::int(1))) <= r {
            b = &b * &Q::int(2);
        }
    }
    b
}

/// Isolates the distinct real roots of `p` (any non-zero polynomial), in increasing order.
pub fn isolate<F: OrderedField>(p: &Poly<F>) -> Vec<RealRoot<F>> {
    let sf = p.square_free();
    if sf.degree().unwrap_or(0) == 0 {
        return Vec::new();
    }
    let seq = sf.sturm();
    let b = root_bound(&sf);
    let mut out = Vec::new();
    // Work list of open intervals (lo, hi) whose endpoints are not roots.
    let mut work = vec![(-b.clone(), b)];
    while let Some((lo, hi)) = work.pop() {
        match count_roots(&seq, &Point::At(lo.clone()), &Point::At(hi.clone())) {
            0 => {}
            1 => out.push(RealRoot { poly: sf.clone(), lo, hi }),
            _ => {
                let mid = (&lo + &hi) / Q::int(2);
                if sf.sign_at(&mid) == Ordering::Equal {
                    out.push(RealRoot { poly: sf.clone(), lo: mid.clone(), hi: mid.clone() });
                    // Keep the other roots off the new endpoints by shrinking towards mid.
                    let (l, r) = split_around(&sf, &seq, &lo, &mid, &hi);
                    work.push((lo, l));
                    work.push((r, hi));
                } else {
                    work.push((lo, mid.clone()));
                    work.push((mid, hi));
                }
            }
        }
    }
    out.sort_by(|a, b| a.lo.cmp(&b.lo));
    out
}

/// For an exact root at `mid`, points l < mid < r with no root in [l, mid) or (mid, r].
fn split_around<F: OrderedField>(sf: &Poly<F>, seq: &[Poly<F>], lo: &Q, mid: &Q, hi: &Q) -> (Q, Q) {
    let mut w = (hi - lo) / Q::int(4);
    loop {
        let (l, r) = (mid - &w, mid + &w);
        let ok = sf.sign_at(&l) != Ordering::Equal
            && sf.sign_at(&r) != Ordering::Equal
            && count_roots(seq, &Point::At(l.clone()), &Point::At(r.clone())) == 1;
        if ok {
            return (l, r);
        }
        w = w / Q::int(2);
    }
}

impl<F: OrderedField> RealRoot<F> {
    /// A rational root.
    pub fn exact(poly: Poly<F>, x: Q) -> Self {
        RealRoot { poly, lo: x.clone(), hi: x }
    }
    pub fn is_exact(&self) -> bool {
        self.lo == self.hi
    }
    pub fn width(&self) -> Q {
        &self.hi - &self.lo
    }

    /// Halves the isolating interval (or finds the root exactly at the midpoint).
    pub fn bisect(&mut self) {
        if self.is_exact() {
            return;
        }
        let mid = (&self.lo + &self.hi) / Q::int(2);
        let s = self.poly.sign_at(&mid);
        if s == Ordering::Equal {
            self.lo = mid.clone();
            self.hi = mid;
        } else if s == self.poly.sign_at(&self.lo) {
            self.lo = mid;
        } else {
            self.hi = mid;
        }
    }

    /// Refines until the interval is no wider than `w`.
    pub fn refine_to(&mut self, w: &Q) {
        while self.width() > *w {
            self.bisect();
        }
    }

    /// The sign of `q` at this root, exactly.
    pub fn sign_of(&mut self, q: &Poly<F>) -> Ordering {
        if q.is_zero() {
            return Ordering::Equal;
        }
        if self.is_exact() {
            return q.sign_at(&self.lo);
        }
        // A common root of q and poly inside (lo, hi) can only be this root.
        let g = self.poly.gcd(q);
        if g.degree().unwrap_or(0) > 0 {
            let seq = g.sturm();
            if count_roots(&seq, &Point::At(self.lo.clone()), &Point::At(self.hi.clone())) > 0 {
                return Ordering::Equal;
            }
        }
        // Otherwise refine until q has no root in [lo, hi]; then its sign there is constant.
        let qs = q.square_free();
        let seq = qs.sturm();
        loop {
            if self.is_exact() {
                return q.sign_at(&self.lo);
            }
            let s = q.sign_at(&self.lo);
            if s != Ordering::Equal
                && count_roots(&seq, &Point::At(self.lo.clone()), &Point::At(self.hi.clone())) == 0
            {
                return s;
            }
            self.bisect();
        }
    }

    /// The sign of the root itself.
    pub fn sign(&mut self) -> Ordering {
        self.sign_of(&Poly::var())
    }

    /// -x as a root of p(-t).
    pub fn negated(&self) -> Self {
        let poly = self.poly.reflect().monic();
        RealRoot { poly, lo: -&self.hi, hi: -&self.lo }
    }

    /// Whether this number lies in the isolating interval of `o` (closed if `o` is exact).
    fn within(&mut self, o: &Self) -> bool {
        loop {
            if self.is_exact() {
                return if o.is_exact() { self.lo == o.lo } else { o.lo < self.lo && self.lo < o.hi };
            }
            if o.lo <= self.lo && self.hi <= o.hi {
                return true;
            }
            if self.hi <= o.lo || o.hi <= self.lo {
                return false;
            }
            self.bisect();
        }
    }

    /// Compares two real algebraic numbers exactly: they are equal iff this one is a root of
    /// the other's polynomial lying in the other's isolating interval.
    pub fn compare(&mut self, o: &mut Self) -> Ordering {
        if self.sign_of(&o.poly) == Ordering::Equal && self.within(o) {
            return Ordering::Equal;
        }
        loop {
            if self.hi <= o.lo {
                return Ordering::Less;
            }
            if o.hi <= self.lo {
                return Ordering::Greater;
            }
            if self.width() >= o.width() { self.bisect() } else { o.bisect() }
        }
    }

    /// An enclosure [lo, hi] of width at most 10^-digits, printed with `digits` decimals rounded
    /// outwards, so the printed interval contains the root.
    pub fn decimal_enclosure(&mut self, digits: usize) -> (String, String) {
        self.refine_to(&Q::pow10(-(digits as i64)));
        (self.lo.decimal(digits, Rounding::Down), self.hi.decimal(digits, Rounding::Up))
    }

    /// Nearest f64 of the interval's midpoint (display only).
    pub fn approx(&self) -> f64 {
        ((&self.lo + &self.hi) / Q::int(2)).to_f64()
    }
}
