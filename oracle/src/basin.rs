//! Basin certificates' geometry and dynamics, written from docs/basin-certificates.md: the
//! partition of rule B3 checked top-down (the kernel rebuilds its tree path by path), and single
//! drops followed exactly through a leaf's prefix into the orbit certificate's X, to v > 0, or
//! into a node of the time-to-rest certificate's graph (rule B4 at sample points; the kernel
//! encloses whole leaves by interval arithmetic with cuts).

use crate::arith::{Num, Rat};
use crate::cone3::dot;
use crate::orbit::map::Orbit;
use crate::plane::{inside, project};
use crate::regular::model::{Polygon, V3};
use crate::regular::rules::Polygon2;
use crate::regular::virtual_time::Node;
use crate::verdict::{Checked, Fail};
use num_bigint::BigInt;
use num_traits::{One, Signed};

pub mod tree;

/// The five coordinates of a drop: ω_x, ω_y, φ_x, φ_y, h (docs/basin-certificates.md §1).
pub const DIMS: usize = 5;

fn partition_fail(why: impl Into<String>) -> Fail {
    Fail::new("not-a-partition", why)
}

/// Rule B3 (docs/basin-certificates.md §3), top-down: the paths under a node are one leaf (the
/// empty path alone), or all halve one coordinate there and both halves are again partitions.
pub fn partition(paths: &[&[u8]]) -> Checked<()> {
    if let Some(p) = paths.iter().find(|p| p.iter().any(|c| !c.is_ascii_digit())) {
        return Err(partition_fail(format!("the path {:?} has a character that is not a digit", p)));
    }
    split(paths)
}

fn split(paths: &[&[u8]]) -> Checked<()> {
    if paths.is_empty() {
        return Err(partition_fail("a part of the box is in no leaf"));
    }
    if paths.iter().any(|p| p.is_empty()) {
        return if paths.len() == 1 { Ok(()) } else { Err(partition_fail("two leaves overlap")) };
    }
    let axis = paths[0][0] / 2;
    if paths.iter().any(|p| p[0] / 2 != axis) {
        return Err(partition_fail("two coordinates are halved at one node"));
    }
    for half in 0..2 {
        let below: Vec<&[u8]> = paths.iter().filter(|p| p[0] % 2 == half).map(|p| &p[1..]).collect();
        split(&below)?;
    }
    Ok(())
}

/// The closed box of a leaf: B halved along its path (digit 2k: lower half of coordinate k).
pub fn leaf_box(lo: &[Rat; DIMS], hi: &[Rat; DIMS], path: &[u8]) -> ([Rat; DIMS], [Rat; DIMS]) {
    let (mut lo, mut hi) = (lo.clone(), hi.clone());
    let two = Rat::from_integer(BigInt::from(2));
    for c in path {
        let k = ((c - b'0') / 2) as usize;
        let mid = (&lo[k] + &hi[k]) / &two;
        if (c - b'0') % 2 == 1 { lo[k] = mid } else { hi[k] = mid }
    }
    (lo, hi)
}

/// x ≥ s·a for s = √s2 > 0, exactly (by squares where the signs agree).
fn at_least_s_times(x: &Num, a: &Rat, s2: &Num) -> bool {
    let a2 = &Num::rational(&x.field, a * a) * s2;
    match (x.is_negative(), a.is_positive()) {
        (false, false) => true,
        (true, true) => false,
        (false, true) => &(x * x) - &a2 >= Num::int(&x.field, 0),
        (true, false) => &(x * x) - &a2 <= Num::int(&x.field, 0),
    }
}

/// A number X with X/s in [lo, hi] close to s·m (m in [lo, hi]), s = √s2: the coordinate ω_x or
/// φ_x of a drop enters the state only as s ω_x or s φ_x (§2), so a drop whose ω_x is the
/// irrational X/s has a state in the field. `None` if the rational approximation of s misses.
fn times_s(m: &Rat, lo: &Rat, hi: &Rat, s2: &Num) -> Option<Num> {
    let (a, _) = s2.enclosure(80);
    let scaled = (a * Rat::from_integer(BigInt::one() << 160u32)).floor().to_integer();
    let s = Rat::new(scaled.sqrt(), BigInt::one() << 80u32);
    let x = Num::rational(&s2.field, m * &s);
    let inside = at_least_s_times(&x, lo, s2) && at_least_s_times(&x.neg(), &-hi, s2);
    inside.then_some(x)
}

/// A drop of the closed box [lo, hi] near the point m of it, as the state (q, p) in contact
/// coordinates (§2): p = (−1 − ω_y, −1 + s ω_x − c ω_y, −1), q = (h − φ_y, h + s φ_x − c φ_y, h).
pub fn drop_state(body: &Polygon, m: &[Rat; DIMS], lo: &[Rat; DIMS], hi: &[Rat; DIMS]) -> Option<(V3, V3)> {
    let f = &body.kappa.field;
    let c = body.cos(1);
    let s2 = &Num::int(f, 1) - &(&c * &c);
    let sx = times_s(&m[0], &lo[0], &hi[0], &s2)?;
    let sphi = times_s(&m[2], &lo[2], &hi[2], &s2)?;
    let r = |x: &Rat| Num::rational(f, x.clone());
    let one = Num::int(f, 1);
    let p = [(&one + &r(&m[1])).neg(), &(&sx - &one) - &(&c * &r(&m[1])), one.neg()];
    let q = [&r(&m[4]) - &r(&m[3]), &(&r(&m[4]) + &sphi) - &(&c * &r(&m[3])), r(&m[4])];
    Some((q, p))
}

/// The points of a leaf at which rule B4 is evaluated: its centre, and the points a quarter of
/// the way in from its lower and from its upper corner.
pub fn leaf_points(lo: &[Rat; DIMS], hi: &[Rat; DIMS]) -> Vec<[Rat; DIMS]> {
    let at = |t: Rat| -> [Rat; DIMS] { std::array::from_fn(|k| &lo[k] + &(&(&hi[k] - &lo[k]) * &t)) };
    let q = |a: i64| Rat::new(BigInt::from(a), BigInt::from(4));
    vec![at(q(2)), at(q(1)), at(q(3))]
}

fn not_shown(why: String) -> Fail {
    Fail::new("leaf-not-shown", why)
}

/// What a drop does at the end of its prefix.
#[derive(Clone, Copy)]
pub enum End<'a> {
    /// Enters the orbit certificate's X.
    Cc(&'a Orbit),
    /// Has v > 0.
    Icc,
    /// Enters node r of a time-to-rest certificate's virtual-time graph: hc > 0, v < 0,
    /// -b_r·p > 0 and p in K_r (the node, and its cone on the plane v = -1).
    Rest(&'a Node, &'a Polygon2),
}

/// Follows one drop (q, p) exactly through the impacts `list` (the first absolute, the later ones
/// relative to the contact that landed last, §1): every contact up at the start, each impact
/// forced (the target approaches and is up, every other contact still up when it lands), then the
/// end (`ended`).
pub fn follow(body: &Polygon, q0: V3, p0: V3, list: &[i64], end: End) -> Checked<Option<Num>> {
    all_up(body, &q0)?;
    let (mut q, mut p, mut time) = (q0.clone(), p0, Num::int(&body.kappa.field, 0));
    for (s, &j) in list.iter().enumerate() {
        let (uj, hj) = (body.speed(j, &p), body.speed(j, &q));
        if !uj.is_negative() || !hj.is_positive() {
            return Err(not_shown(format!("at impact {s}, contact {j} does not land")));
        }
        for k in (0..body.n as i64).filter(|&k| k != j) {
            if !(&(&body.speed(k, &q) * &uj.neg()) + &(&hj * &body.speed(k, &p))).is_positive() {
                return Err(not_shown(format!("at impact {s}, contact {k} is not up when {j} lands")));
            }
        }
        let (q1, p1, t) = land(body, &q, &p, j);
        (q, p, time) = (q1, p1, &time + &t);
    }
    ended(&q, &p, &time, &q0[2], end)
}

/// Rule B4 at the start of a drop: every contact strictly up.
fn all_up(body: &Polygon, q0: &V3) -> Checked<()> {
    match (0..body.n as i64).find(|&k| !body.speed(k, q0).is_positive()) {
        Some(k) => Err(not_shown(format!("contact {k} is not up at the start"))),
        None => Ok(()),
    }
}

/// The flight t = h_j/(−u_j) from (q, p) and the impact at contact j, relabelled so that j is
/// contact 0 (docs/model.md §3, as `orbit::map`): the state right after the impact, and t.
fn land(body: &Polygon, q: &V3, p: &V3, j: i64) -> (V3, V3, Num) {
    let t = &body.speed(j, q) / &body.speed(j, p).neg();
    let moved: V3 = std::array::from_fn(|i| &q[i] + &(&t * &p[i]));
    ([body.speed(j, &moved), body.speed(j + 1, &moved), moved[2].clone()], body.step(j, p), t)
}

/// The end of a prefix at the state (q, p) right after its last impact (`time`: the sum of its
/// flights, h: the drop's). For `Cc`, the time from the drop to rest bounded by the orbit
/// certificate's theorem, divided by h: (Σ t_s + B α/β)/h with B = T̄/(1 − ρ)
/// (docs/basin-certificates.md §4); for `Rest`, by Theorem 5.1 from node r on
/// (docs/time-to-rest.md §5): (Σ t_s + Φ_r(q, p))/h with Φ_r(q, p) = (a_r·q)/(−b_r·p).
fn ended(q: &V3, p: &V3, time: &Num, h: &Num, end: End) -> Checked<Option<Num>> {
    let f = &h.field;
    let orbit = match end {
        End::Icc if p[2].is_positive() => return Ok(None),
        End::Icc => return Err(not_shown("v > 0 fails after the prefix".into())),
        End::Cc(o) => Some(o),
        End::Rest(..) => None,
    };
    let (alpha, beta) = (q[2].clone(), p[2].neg());
    if !alpha.is_positive() || !beta.is_positive() {
        return Err(not_shown("hc > 0 and v < 0 fail after the prefix".into()));
    }
    let Some(orbit) = orbit else {
        let End::Rest(node, cone) = end else { unreachable!("an orbit or a node") };
        return rest_end(node, cone, q, p, time, h).map(Some);
    };
    let x = [&q[1] / &alpha, &p[0] / &beta, &p[1] / &beta];
    for row in &orbit.a_inv {
        let y = (0..3).fold(Num::int(f, 0), |acc, k| &acc + &(&row[k] * &(&x[k] - &orbit.centre[k])));
        if y > orbit.delta || y < orbit.delta.neg() {
            return Err(not_shown("the state after the prefix is not in X".into()));
        }
    }
    let b = &orbit.period / &(&Num::int(f, 1) - &orbit.rho);
    Ok(Some(&(time + &(&b * &(&alpha / &beta))) / h))
}

/// The end of a `Rest` leaf's prefix (v < 0 and hc > 0 shown by the caller): −b_r·p > 0 and p
/// in K_r (on the plane v = −1, every edge's value ≥ 0), then (Σ t_s + Φ_r(q, p))/h.
fn rest_end(node: &Node, cone: &Polygon2, q: &V3, p: &V3, time: &Num, h: &Num) -> Checked<Num> {
    let speed = dot(&node.weight, p).neg();
    if !speed.is_positive() {
        return Err(not_shown("-b_r·p > 0 fails after the prefix".into()));
    }
    if !project(p).is_some_and(|x| inside(&cone.sides, &x)) {
        return Err(not_shown("the velocity after the prefix is not in the node's cone K_r".into()));
    }
    let phi = &dot(&node.numerator, q) / &speed;
    Ok(&(time + &phi) / h)
}

/// The share 2^-d of a leaf at depth d.
pub fn share(depth: usize) -> Rat {
    Rat::new(BigInt::one(), BigInt::one() << depth)
}
