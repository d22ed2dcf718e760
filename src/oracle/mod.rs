//! An independent brute-force evaluator of certificates (the *oracle*), for cross-checking the
//! trusted kernel (`chatter_kernel::check`) in tests and fuzz targets.
//!
//! It follows the acceptance rules of docs/certificate-format.md (R1 to R4, in the kernel's
//! order) but deliberately shares nothing with `chatter_kernel::geometry` or
//! `chatter_kernel::check`: no homogeneous integer vectors, no monotone chain, no clipping, no
//! canonical-number parser. Everything is computed in rationals on the projection plane
//! v = -1. K is the polygon of the extreme projected generators (gift wrapping, each edge
//! verified against every point, or in [`supporting_half_planes`] every supporting line through
//! two generators), the vertices of K ∩ C_j are the pairwise intersections of constraint lines
//! that satisfy every constraint, and the PCC quadratic is recomputed from the matrix
//! S_{n-1} S_1 by hand. For n >= 3 only the model maps (`Polygon::step`, `Polygon::impact`,
//! `Polygon::next_contact_cone`, `Polygon::all_down_generators`) come from the kernel; they are
//! tested against the paper in tests/all/kernel/impact.rs and cones.rs. The rod (n = 2,
//! docs/certificate-format.md §8) is evaluated from the formulas of docs/model.md §7 alone, on
//! the number s = u0 / (-2v).
//!
//! - [`evaluate`] / [`evaluate_with`]: the verdict on a certificate (every rule, from the header
//!   to R4), with the categories of the first failing stage;
//! - [`cross_check`]: compares a kernel result with the oracle's verdict;
//! - [`check_text_and_oracle`]: writes a certificate with the kernel's writer, verifies the text on
//!   both backends and cross-checks the oracle (what the fuzz targets and smoke tests run);
//! - [`mutation`]: structure-aware mutations of certificates, decoded from bytes.

pub mod convex;

use crate::exact::Q;
use crate::write::VersionNeeded;
use chatter_kernel::certificate::{
    Body as CertBody, Certificate, Claim, Code, FORMAT, Locus, Param, Rejection, VERSIONS,
};
use chatter_kernel::check::Accepted;
use chatter_kernel::exact::ParseLimits;
use chatter_kernel::model::Polygon as Body;
use malachite::rational::Rational;
use malachite::{Integer, Natural};
use std::fmt;
use std::str::FromStr;

/// A point of the projection plane: (u0, u1) / (-v).
pub type Pt = (Q, Q);

/// The rational 0.
pub fn zero() -> Q {
    Q::int(0)
}

/// `a - b`.
pub fn sub(a: &Pt, b: &Pt) -> Pt {
    (&a.0 - &b.0, &a.1 - &b.1)
}

/// orient2d(a, b, c) = cross(b - a, c - a): > 0 when a, b, c turn counter-clockwise.
pub fn orient2(a: &Pt, b: &Pt, c: &Pt) -> Q {
    let (u, w) = (sub(b, a), sub(c, a));
    &u.0 * &w.1 - &u.1 * &w.0
}

fn dist2(a: &Pt, b: &Pt) -> Q {
    let d = sub(b, a);
    &d.0 * &d.0 + &d.1 * &d.1
}

/// The projection of a homogeneous vector, `None` when v >= 0.
pub fn project(g: &[Q; 3]) -> Option<Pt> {
    if g[2] >= zero() {
        return None;
    }
    let w = -&g[2];
    Some((&g[0] / &w, &g[1] / &w))
}

/// The homogeneous vector (x, y, -1) of a projected point.
pub fn lift(p: &Pt) -> [Q; 3] {
    [p.0.clone(), p.1.clone(), Q::int(-1)]
}

/// Generators (x, y, -1) of projected points.
pub fn lifted(pts: &[Pt]) -> Vec<[Q; 3]> {
    pts.iter().map(lift).collect()
}

/// Whether p lies on the closed segment [a, b] (a may equal b).
pub fn on_segment(p: &Pt, a: &Pt, b: &Pt) -> bool {
    if orient2(a, b, p) != zero() {
        return false;
    }
    let (pa, pb) = (sub(a, p), sub(b, p));
    &pa.0 * &pb.0 + &pa.1 * &pb.1 <= zero()
}

/// Whether p lies in the convex hull of `pts` (Carathéodory: a point, a segment or a triangle).
pub fn in_hull(p: &Pt, pts: &[Pt]) -> bool {
    let m = pts.len();
    for i in 0..m {
        if &pts[i] == p {
            return true;
        }
        for j in i + 1..m {
            if on_segment(p, &pts[i], &pts[j]) {
                return true;
            }
            for k in j + 1..m {
                let (a, b, c) = (&pts[i], &pts[j], &pts[k]);
                let area = orient2(a, b, c);
                if area == zero() {
                    continue;
                }
                let s = [orient2(a, b, p), orient2(b, c, p), orient2(c, a, p)];
                let z = zero();
                if s.iter().all(|x| x >= &z) || s.iter().all(|x| x <= &z) {
                    return true;
                }
            }
        }
    }
    false
}

/// The distinct points in their first-occurrence order.
pub fn distinct(pts: &[Pt]) -> Vec<Pt> {
    let mut out: Vec<Pt> = Vec::new();
    for p in pts {
        if !out.contains(p) {
            out.push(p.clone());
        }
    }
    out
}

/// The extreme points of a finite set: distinct points that are not in the hull of the others.
pub fn extreme_points(pts: &[Pt]) -> Vec<Pt> {
    let d = distinct(pts);
    (0..d.len())
        .filter(|&i| {
            let others: Vec<Pt> =
                d.iter().enumerate().filter(|&(k, _)| k != i).map(|(_, p)| p.clone()).collect();
            !in_hull(&d[i], &others)
        })
        .map(|i| d[i].clone())
        .collect()
}

/// Whether the points span the plane (some triple is not collinear).
pub fn full_dimensional(pts: &[Pt]) -> bool {
    let d = distinct(pts);
    d.len() >= 3 && d[2..].iter().any(|p| orient2(&d[0], &d[1], p) != zero())
}

/// Gift wrapping: the extreme points of `pts` in counter-clockwise order, starting from the
/// lexicographically smallest (a different algorithm from the kernel's monotone chain).
pub fn ccw_hull(pts: &[Pt]) -> Vec<Pt> {
    ccw_order(&extreme_points(pts))
}

/// Gift wrapping on points that are already the extreme points of their hull.
pub fn ccw_order(ext: &[Pt]) -> Vec<Pt> {
    if ext.len() < 3 {
        let mut e = ext.to_vec();
        e.sort();
        return e;
    }
    let start = ext.iter().min().expect("non-empty").clone();
    let mut out = vec![start.clone()];
    let mut cur = start.clone();
    loop {
        // The next vertex: every other extreme point is strictly left of cur -> next.
        let next = ext
            .iter()
            .find(|c| {
                **c != cur && ext.iter().all(|p| *p == cur || *p == **c || orient2(&cur, c, p) > zero())
            })
            .expect("gift wrapping finds a next vertex")
            .clone();
        if next == start {
            break;
        }
        out.push(next.clone());
        cur = next;
        assert!(out.len() <= ext.len(), "gift wrapping does not close");
    }
    out
}

/// Jarvis march on any full-dimensional finite set: the vertices of its convex hull in
/// counter-clockwise order from the lexicographically smallest point, in O(points x vertices).
/// The result is verified (every turn strictly left, every point on the left of or on every
/// edge, so the polygon is convex, contains the set, and has only points of the set as strict
/// vertices: it is the hull), so a wrong hull panics instead of being used.
pub fn jarvis(pts: &[Pt]) -> Vec<Pt> {
    let d = distinct(pts);
    assert!(full_dimensional(&d), "jarvis needs a full-dimensional set");
    let start = d.iter().min().expect("non-empty").clone();
    let mut out = vec![start.clone()];
    let mut cur = start.clone();
    loop {
        // The most clockwise direction from cur; among collinear candidates the farthest. All
        // points lie in a cone of angle < pi at the vertex cur, where orientation orders them.
        // orient2(cur, next, p) = cross(next - cur, p - cur), with the differences computed once.
        let rel: Vec<(usize, Pt)> =
            d.iter().enumerate().filter(|(_, p)| **p != cur).map(|(i, p)| (i, sub(p, &cur))).collect();
        let mut best = &rel[0];
        for r in &rel[1..] {
            let (u, w) = (&best.1, &r.1);
            let o = &u.0 * &w.1 - &u.1 * &w.0;
            if o < zero() || (o == zero() && dist2(&cur, &d[r.0]) > dist2(&cur, &d[best.0])) {
                best = r;
            }
        }
        let next = d[best.0].clone();
        if next == start {
            break;
        }
        out.push(next.clone());
        cur = next;
        assert!(out.len() <= d.len(), "gift wrapping does not close");
    }
    let m = out.len();
    assert!(m >= 3, "a full-dimensional hull has at least 3 vertices");
    for i in 0..m {
        let (a, b) = (&out[i], &out[(i + 1) % m]);
        assert!(orient2(a, b, &out[(i + 2) % m]) > zero(), "jarvis: no strict left turn at {b:?}");
        let edge = HalfPlane::left_of(a, b);
        assert!(d.iter().all(|p| edge.contains(p)), "jarvis: a point is right of the edge {a:?} -> {b:?}");
    }
    out
}

/// Twice the signed area of a polygon given in order (shoelace).
pub fn twice_area(poly: &[Pt]) -> Q {
    let m = poly.len();
    let mut s = zero();
    for i in 0..m {
        let (a, b) = (&poly[i], &poly[(i + 1) % m]);
        s = s + (&a.0 * &b.1 - &a.1 * &b.0);
    }
    s
}

/// The half-plane a x + b y + c >= 0.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HalfPlane {
    /// Coefficient of x.
    pub a: Q,
    /// Coefficient of y.
    pub b: Q,
    /// Constant term.
    pub c: Q,
}

impl HalfPlane {
    /// a x + b y + c at p.
    pub fn eval(&self, p: &Pt) -> Q {
        &self.a * &p.0 + &self.b * &p.1 + &self.c
    }
    /// Whether p satisfies a x + b y + c >= 0.
    pub fn contains(&self, p: &Pt) -> bool {
        self.eval(p) >= zero()
    }
    /// The left side of the directed line p -> q: { x : orient2(p, q, x) >= 0 }.
    pub fn left_of(p: &Pt, q: &Pt) -> HalfPlane {
        let d = sub(q, p);
        let (a, b) = (-&d.1, d.0.clone());
        let c = -(&a * &p.0 + &b * &p.1);
        HalfPlane { a, b, c }
    }
    /// The projection of the homogeneous half-space l . p >= 0 (p = w (x, y, -1), w > 0).
    pub fn from_covector(l: &[Q; 3]) -> HalfPlane {
        HalfPlane { a: l[0].clone(), b: l[1].clone(), c: -&l[2] }
    }
    /// Scaled so that the first non-zero of (a, b) is ±1 (lines are compared this way).
    fn normalized(&self) -> HalfPlane {
        let s = if self.a != zero() { self.a.clone() } else { self.b.clone() };
        if s == zero() {
            return self.clone();
        }
        let s = if s < zero() { -s } else { s };
        HalfPlane { a: &self.a / &s, b: &self.b / &s, c: &self.c / &s }
    }
    /// Whether the boundary is a line (a or b non-zero), not a constant constraint.
    fn is_line(&self) -> bool {
        self.a != zero() || self.b != zero()
    }
}

/// K as the intersection of every supporting half-plane through two distinct projected points
/// (a pair gives an edge line when all points lie on one side of it). Needs a full-dimensional
/// set.
pub fn supporting_half_planes(pts: &[Pt]) -> Vec<HalfPlane> {
    let d = distinct(pts);
    let mut out: Vec<HalfPlane> = Vec::new();
    for i in 0..d.len() {
        for j in 0..d.len() {
            if i == j {
                continue;
            }
            let h = HalfPlane::left_of(&d[i], &d[j]);
            if d.iter().all(|p| h.contains(p)) {
                let h = h.normalized();
                if !out.contains(&h) {
                    out.push(h);
                }
            }
        }
    }
    out
}

/// The intersection point of two boundary lines, `None` when they are parallel.
fn intersection(h: &HalfPlane, k: &HalfPlane) -> Option<Pt> {
    let det = &h.a * &k.b - &h.b * &k.a;
    if det == zero() {
        return None;
    }
    // a x + b y = -c for both lines (Cramer).
    let x = (&h.b * &k.c - &k.b * &h.c) / &det;
    let y = (&k.a * &h.c - &h.a * &k.c) / &det;
    Some((x, y))
}

/// The vertices of a bounded intersection of half-planes: every intersection of two constraint
/// lines that satisfies all constraints (distinct, in no particular order). Lines with a = b = 0
/// are constant constraints and take part only in the satisfaction test.
pub fn polygon_vertices(hps: &[HalfPlane]) -> Vec<Pt> {
    let mut out: Vec<Pt> = Vec::new();
    for i in 0..hps.len() {
        for j in i + 1..hps.len() {
            if let Some(p) = intersection(&hps[i], &hps[j])
                && hps.iter().all(|l| l.contains(&p))
                && !out.contains(&p)
            {
                out.push(p);
            }
        }
    }
    out
}

/// The vertices of K ∩ {extra}, K given by its counter-clockwise vertices and edge half-planes:
/// the same set as [`polygon_vertices`] of all the constraints, with fewer candidates. Two edge
/// lines of K meet inside K only at a vertex of K, so the candidates are K's vertices and the
/// intersections of each extra line with every other line.
pub fn clipped_vertices(k_ccw: &[Pt], k: &[HalfPlane], extra: &[HalfPlane]) -> Vec<Pt> {
    // The extra constraints first: they reject most candidates, and cheaply.
    let all: Vec<&HalfPlane> = extra.iter().chain(k).collect();
    let mut candidates: Vec<Pt> = k_ccw.to_vec();
    for (i, e) in extra.iter().enumerate().filter(|(_, e)| e.is_line()) {
        for h in k.iter().chain(&extra[i + 1..]) {
            candidates.extend(intersection(e, h));
        }
    }
    let mut out: Vec<Pt> = Vec::new();
    for p in candidates {
        if !out.contains(&p) && all.iter().all(|l| l.contains(&p)) {
            out.push(p);
        }
    }
    out
}

/// `m x` for a 3x3 matrix.
pub fn mat_vec(m: &[[Q; 3]; 3], x: &[Q; 3]) -> [Q; 3] {
    std::array::from_fn(|r| &m[r][0] * &x[0] + &m[r][1] * &x[1] + &m[r][2] * &x[2])
}

/// `a b` for 3x3 matrices.
pub fn mat_mul(a: &[[Q; 3]; 3], b: &[[Q; 3]; 3]) -> [[Q; 3]; 3] {
    std::array::from_fn(|r| std::array::from_fn(|c| (0..3).fold(zero(), |s, k| s + &a[r][k] * &b[k][c])))
}

/// The PCC quadratic t^2 + p t + q of det(tI - S_{n-1} S_1) = (t - 1)(t^2 + p t + q), with its
/// discriminant, recomputed from the matrix (Sarrus for the determinant, synthetic division).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Quadratic {
    /// The linear coefficient.
    pub p: Q,
    /// The constant term.
    pub q: Q,
    /// p^2 - 4q.
    pub discriminant: Q,
}

impl Quadratic {
    /// Rule R4: complex roots of modulus < 1.
    pub fn excludes_pcc(&self) -> bool {
        self.discriminant < zero() && self.q < Q::int(1)
    }
}

/// The PCC quadratic of a regular polygon; panics if 1 is not an eigenvalue of S_{n-1} S_1.
pub fn pcc_quadratic(b: &Body<Q>) -> Quadratic {
    let m = mat_mul(&b.step(b.n() as i64 - 1), &b.step(1));
    let tr = &m[0][0] + &m[1][1] + &m[2][2];
    let minors = &m[0][0] * &m[1][1] - &m[0][1] * &m[1][0] + &m[0][0] * &m[2][2] - &m[0][2] * &m[2][0]
        + &m[1][1] * &m[2][2]
        - &m[1][2] * &m[2][1];
    let det =
        &m[0][0] * &m[1][1] * &m[2][2] + &m[0][1] * &m[1][2] * &m[2][0] + &m[0][2] * &m[1][0] * &m[2][1]
            - &m[0][2] * &m[1][1] * &m[2][0]
            - &m[0][0] * &m[1][2] * &m[2][1]
            - &m[0][1] * &m[1][0] * &m[2][2];
    // t^3 - tr t^2 + minors t - det divided by (t - 1): coefficients 1, 1 - tr, 1 - tr + minors.
    let one = Q::int(1);
    let p = &one - &tr;
    let qq = &p + &minors;
    let remainder = &qq - &det;
    assert_eq!(remainder, zero(), "S_(n-1) S_1 must fix m_(0,1): 1 is an eigenvalue");
    let discriminant = &p * &p - Q::int(4) * &qq;
    Quadratic { p, q: qq, discriminant }
}

/// The brute-force verdict.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Verdict {
    /// Every failing category found (in the kernel's order, without repeats). Evaluation stops
    /// after a failure of the header, the body, the numbers or R1, so these appear alone.
    pub failing: Vec<Code>,
    /// The categories of the first failing stage in the kernel's order of checks (header, body,
    /// claim range, generators, dimension, S_1, ..., S_{n-1}, I_0(D), PCC): the kernel's code
    /// must be one of these.
    pub first_stage: Vec<Code>,
    /// Generators whose projection is not a vertex of K, or repeats an earlier generator's.
    pub redundant: Vec<usize>,
    /// The number of distinct vertices of K ∩ C_j, j = 1..n-1 (for the rod, of K ∩ C_1).
    pub pieces: Vec<usize>,
    /// Vertices of K in counter-clockwise order from the lexicographically smallest (n >= 3).
    pub k_ccw: Vec<Pt>,
    /// For the rod: K as the interval [lo, hi] of s = u0 / (-2v).
    pub interval: Option<(Q, Q)>,
    /// Largest denominator among the generators' coordinates, in bits.
    pub max_denominator_bits: u64,
    /// The PCC quadratic, for `CompleteChatterFromAllDown` with n >= 3.
    pub pcc: Option<Quadratic>,
    /// Whether K contains I_0(-1, -1, -1) (informational, not a rule); for a box, at every corner.
    pub contains_translation: bool,
    /// For a box certificate with a `CompleteChatterFromAllDown` claim (n >= 3): how many points
    /// of a grid on the box passed rule R4. The grid cannot prove R4 on the whole box, so a kernel
    /// that fails to prove it there is not contradicted.
    pub pcc_grid: Option<usize>,
    /// For a box certificate, [lo, hi] of kappa and gamma as canonical text.
    pub region: Option<[[String; 2]; 2]>,
}

impl Verdict {
    pub(crate) fn new(max_denominator_bits: u64) -> Verdict {
        Verdict {
            failing: vec![],
            first_stage: vec![],
            redundant: vec![],
            pieces: vec![],
            k_ccw: vec![],
            interval: None,
            max_denominator_bits,
            pcc: None,
            contains_translation: false,
            pcc_grid: None,
            region: None,
        }
    }

    /// A verdict that stops at one failure of the header, the body or the numbers.
    pub(crate) fn stopped(code: Code) -> Verdict {
        let mut v = Verdict::new(0);
        v.stage(vec![code]);
        v
    }

    /// Records a failing stage.
    pub(crate) fn stage(&mut self, codes: Vec<Code>) {
        if self.first_stage.is_empty() {
            self.first_stage = codes.clone();
        }
        for c in codes {
            if !self.failing.contains(&c) {
                self.failing.push(c);
            }
        }
    }

    /// Whether every rule holds.
    pub fn accepted(&self) -> bool {
        self.failing.is_empty()
    }
}

/// Where an image of a point lands, by the certificate's rules.
fn image_status(k: &[HalfPlane], img: &[Q; 3], outside: Code, above: Code) -> Option<Code> {
    if img.iter().all(|c| *c == zero()) {
        return None;
    }
    match project(img) {
        None => Some(above),
        Some(p) if k.iter().all(|h| h.contains(&p)) => None,
        Some(_) => Some(outside),
    }
}

/// A canonical rational (docs/certificate-format.md §2 "Numbers"), parsed independently of the
/// kernel: `-?p(/q)?` with ASCII digits, no leading zeros, q > 1, gcd(p, q) = 1, not "-0", and at
/// most `max_digits` digits in p and q together. The code of the broken rule otherwise: the
/// lexical rules (`bad-number`) come before the length (`too-large`), the others after it.
pub fn parse_number_code(s: &str, limits: ParseLimits) -> Result<Q, Code> {
    let unsigned = s.strip_prefix('-').unwrap_or(s);
    let (p, q) = match unsigned.split_once('/') {
        Some((p, q)) => (p, Some(q)),
        None => (unsigned, None),
    };
    let digits_ok =
        |t: &str| !t.is_empty() && t.bytes().all(|c| c.is_ascii_digit()) && (t == "0" || !t.starts_with('0'));
    if !digits_ok(p) || q.is_some_and(|q| !digits_ok(q) || q == "0") {
        return Err(Code::BadNumber);
    }
    if p.len() + q.map_or(0, str::len) > limits.max_digits {
        return Err(Code::TooLarge);
    }
    if (s.starts_with('-') && p == "0") || q == Some("1") {
        return Err(Code::BadNumber);
    }
    let mut num = Integer::from_str(p).map_err(|_| Code::BadNumber)?;
    if s.starts_with('-') {
        num = -num;
    }
    let Some(q) = q else { return Ok(Q::from_rational(Rational::from(num))) };
    let den = Natural::from_str(q).map_err(|_| Code::BadNumber)?;
    let r = Rational::from_integers(num, Integer::from(den.clone()));
    // In lowest terms exactly when reducing leaves the denominator (so "0/5" is refused too).
    if r.to_denominator() == den { Ok(Q::from_rational(r)) } else { Err(Code::BadNumber) }
}

/// [`parse_number_code`] without the reason.
pub fn parse_number(s: &str, limits: ParseLimits) -> Option<Q> {
    parse_number_code(s, limits).ok()
}

/// The limits on the whole file (docs/certificate-format.md §2, "Limits"): generators, and the
/// characters of all numbers together.
fn too_large(cert: &Certificate, limits: ParseLimits) -> bool {
    let CertBody::RegularPolygon { kappa, gamma, .. } = &cert.body;
    let params: usize = kappa.texts().iter().chain(&gamma.texts()).map(|t| t.len()).sum();
    let chars = params + cert.cone.iter().flat_map(|g| &g.0).map(String::len).sum::<usize>();
    cert.cone.len() > limits.max_generators || chars > limits.max_total_digits
}

/// Evaluates a certificate with the default parse limits.
pub fn evaluate(cert: &Certificate) -> Verdict {
    evaluate_with(cert, ParseLimits::default())
}

/// Evaluates every rule of a certificate: header, numbers, body, the claim's range of gamma,
/// generators (arity, numbers), then R1 to R4 for the rod or the regular polygon.
pub fn evaluate_with(cert: &Certificate, limits: ParseLimits) -> Verdict {
    if cert.format != FORMAT {
        return Verdict::stopped(Code::WrongFormat);
    }
    if !VERSIONS.contains(&cert.version) {
        return Verdict::stopped(Code::UnsupportedVersion);
    }
    if too_large(cert, limits) {
        return Verdict::stopped(Code::TooLarge);
    }
    if cert.version < cert.body.version_needed() {
        return Verdict::stopped(Code::UnsupportedVersion);
    }
    let CertBody::RegularPolygon { n, kappa, gamma } = &cert.body;
    let (k, g) = match (bounds(kappa, limits), bounds(gamma, limits)) {
        (Ok(k), Ok(g)) => (k, g),
        (Err(c), _) | (_, Err(c)) => return Verdict::stopped(c),
    };
    if ![2, 3, 4, 6].contains(n) {
        return Verdict::stopped(Code::UnsupportedBody);
    }
    if k[0] <= zero() || g[0] < zero() || g[1] > Q::int(1) {
        return Verdict::stopped(Code::ParameterOutOfRange);
    }
    if claim_needs_open_gamma(cert.claim, &g[0]) || claim_needs_open_gamma(cert.claim, &g[1]) {
        return Verdict::stopped(Code::ParameterOutOfRange);
    }
    let arity = if *n == 2 { 2 } else { 3 };
    let mut gens: Vec<Vec<Q>> = Vec::with_capacity(cert.cone.len());
    for g in &cert.cone {
        if g.0.len() != arity {
            return Verdict::stopped(Code::WrongArity);
        }
        match g.0.iter().map(|c| parse_number_code(c, limits)).collect::<Result<Vec<Q>, Code>>() {
            Ok(x) => gens.push(x),
            Err(c) => return Verdict::stopped(c),
        }
    }
    let is_box = cert.body.version_needed() > 1;
    if let Some(b) = &cert.time_to_rest_bound {
        if *n != 2 || is_box {
            return Verdict::stopped(Code::TimeToRestNotShown);
        }
        let mut v = evaluate_point(*n, &k[0], &g[0], cert.claim, &gens);
        match parse_number_code(b, limits) {
            Err(c) => v.stage(vec![c]),
            Ok(b) if !rod_time_to_rest_shown(&k[0], &g[0], cert.claim, &b) => {
                v.stage(vec![Code::TimeToRestNotShown])
            }
            Ok(_) => {}
        }
        return v;
    }
    if !is_box {
        return evaluate_point(*n, &k[0], &g[0], cert.claim, &gens);
    }
    evaluate_box(*n, &k, &g, cert.claim, &gens)
}

/// Rule T1 (docs/time-to-rest.md §2), formulated independently of the kernel: B > 0, a claim about
/// drops, σ = (1 + γ)(1 − κ)/(1 + κ) > 0, Δ = σ² − 4γ ≥ 0 and λ_1 = (σ + √Δ)/2 ≥ 1/B, i.e.
/// y = 2/B − σ ≤ 0 or Δ ≥ y².
fn rod_time_to_rest_shown(kappa: &Q, gamma: &Q, claim: Claim, b: &Q) -> bool {
    if claim == Claim::EffectivelyInvariant || *b <= zero() {
        return false;
    }
    let one = Q::int(1);
    let sigma = &(&(&one + gamma) * &(&one - kappa)) / &(&one + kappa);
    let delta = &(&sigma * &sigma) - &(&Q::int(4) * gamma);
    if sigma <= zero() || delta < zero() {
        return false;
    }
    let y = &(&Q::int(2) / b) - &sigma;
    y <= zero() || delta >= &y * &y
}

/// A parameter's bounds [lo, hi] (lo = hi for a number), or the code of its first bad number (or
/// `parameter-out-of-range` for an empty interval).
fn bounds(p: &Param, limits: ParseLimits) -> Result<[Q; 2], Code> {
    let t = p.texts();
    let lo = parse_number_code(t[0], limits)?;
    let hi = parse_number_code(t[t.len() - 1], limits)?;
    if lo > hi { Err(Code::ParameterOutOfRange) } else { Ok([lo, hi]) }
}

/// Every rule at one point (kappa, gamma).
fn evaluate_point(n: u64, kappa: &Q, gamma: &Q, claim: Claim, gens: &[Vec<Q>]) -> Verdict {
    if n == 2 {
        let gens: Vec<[Q; 2]> = gens.iter().map(|g| [g[0].clone(), g[1].clone()]).collect();
        evaluate_rod_parts(kappa, gamma, claim, &gens)
    } else {
        let gens: Vec<[Q; 3]> = gens.iter().map(|g| [g[0].clone(), g[1].clone(), g[2].clone()]).collect();
        let body = Body::new(n, kappa.clone(), gamma.clone()).expect("n, kappa and gamma checked above");
        evaluate_parts(&body, claim, &gens)
    }
}

/// Points per side of the grid on which a box's rule R4 is tested.
pub const PCC_GRID: i64 = 9;

/// Every rule on a box: R1 to R3 at each corner (the kernel's reduction, docs/kernel-soundness.md
/// §2 "Boxes"), R4 on a grid of points of the box (a necessary condition only).
fn evaluate_box(n: u64, k: &[Q; 2], g: &[Q; 2], claim: Claim, gens: &[Vec<Q>]) -> Verdict {
    let weaker = claim.min(Claim::CcOrPccFromAllDown);
    let mut corners: Vec<(Q, Q)> = Vec::new();
    for (gi, ki) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
        let c = (k[ki].clone(), g[gi].clone());
        if !corners.contains(&c) {
            corners.push(c);
        }
    }
    let vs: Vec<Verdict> = corners.iter().map(|(a, b)| evaluate_point(n, a, b, weaker, gens)).collect();
    let mut v = vs[0].clone();
    let r2 = |x: &Verdict| x.failing.iter().any(|c| matches!(c, Code::ImageOutside | Code::ImageNotBelow));
    let r3 = |x: &Verdict| x.failing.contains(&Code::InitialOutside);
    let geometric = vs.iter().any(|x| r2(x) || r3(x));
    let early = v
        .first_stage
        .iter()
        .any(|c| !matches!(c, Code::ImageOutside | Code::ImageNotBelow | Code::InitialOutside));
    if early && !v.first_stage.is_empty() {
        return v; // R1 fails: the same K at every corner
    }
    v.failing = vs.iter().flat_map(|x| x.failing.clone()).fold(vec![], |mut acc, c| {
        if !acc.contains(&c) {
            acc.push(c);
        }
        acc
    });
    v.first_stage = match (vs.iter().find(|x| r2(x)), vs.iter().find(|x| r3(x))) {
        (Some(x), _) => x.first_stage.clone(),
        (None, Some(_)) => vec![Code::InitialOutside],
        (None, None) => vec![],
    };
    v.contains_translation = vs.iter().all(|x| x.contains_translation);
    v.region = Some([[k[0].to_string(), k[1].to_string()], [g[0].to_string(), g[1].to_string()]]);
    if claim == Claim::CompleteChatterFromAllDown && n >= 3 && !geometric {
        let grid = pcc_grid_failure(n, k, g);
        match grid {
            Ok(points) => v.pcc_grid = Some(points),
            Err(()) => v.stage(vec![Code::PccNotExcluded]),
        }
    }
    v
}

/// Rule R4 at the points of a PCC_GRID x PCC_GRID grid of the box (corners included): the number
/// of points, or `Err` if it fails at one.
fn pcc_grid_failure(n: u64, k: &[Q; 2], g: &[Q; 2]) -> Result<usize, ()> {
    let at = |r: &[Q; 2], i: i64| &r[0] + &(&r[1] - &r[0]) * &Q::new(i, PCC_GRID - 1);
    let mut points = 0;
    for i in 0..PCC_GRID {
        for j in 0..PCC_GRID {
            let body = Body::new(n, at(k, i), at(g, j)).expect("inside the checked box");
            if !pcc_quadratic(&body).excludes_pcc() {
                return Err(());
            }
            points += 1;
        }
    }
    Ok(points)
}

/// Whether rule R4 fails at the point (kappa, gamma) (n >= 3).
pub fn pcc_fails_at(n: u64, kappa: &Q, gamma: &Q) -> bool {
    Body::new(n, kappa.clone(), gamma.clone()).is_ok_and(|b| !pcc_quadratic(&b).excludes_pcc())
}

/// The claims about drops need 0 < gamma < 1 (docs/kernel-soundness.md, "The range of γ").
fn claim_needs_open_gamma(claim: Claim, gamma: &Q) -> bool {
    claim > Claim::EffectivelyInvariant && (*gamma == zero() || *gamma == Q::int(1))
}

pub(crate) fn max_bits<'a>(xs: impl Iterator<Item = &'a Q>) -> u64 {
    xs.map(Q::denominator_bits).max().unwrap_or(0)
}

/// Rules R1 (generators below, full dimension) to R4 for a regular polygon (n >= 3), from the
/// claim's range of gamma on.
pub fn evaluate_parts(b: &Body<Q>, claim: Claim, gens: &[[Q; 3]]) -> Verdict {
    let mut v = Verdict::new(max_bits(gens.iter().flatten()));
    if claim_needs_open_gamma(claim, b.gamma()) {
        v.stage(vec![Code::ParameterOutOfRange]);
        return v;
    }
    let pts: Vec<Pt> = match gens.iter().map(project).collect::<Option<Vec<Pt>>>() {
        Some(p) => p,
        None => {
            v.stage(vec![Code::GeneratorNotBelow]);
            return v;
        }
    };
    if !full_dimensional(&pts) {
        v.stage(vec![Code::DegenerateCone]);
        return v;
    }
    // K: the gift-wrapped hull of the projected generators and its edge half-planes.
    let ccw = jarvis(&pts);
    let m = ccw.len();
    let k: Vec<HalfPlane> = (0..m).map(|i| HalfPlane::left_of(&ccw[i], &ccw[(i + 1) % m])).collect();
    v.redundant = (0..pts.len()).filter(|&i| !ccw.contains(&pts[i]) || pts[..i].contains(&pts[i])).collect();
    let down = mat_vec(&b.impact(0), &[Q::int(-1), Q::int(-1), Q::int(-1)]);
    v.contains_translation = project(&down).is_some_and(|p| k.iter().all(|h| h.contains(&p)));

    // R2: the images of the vertices of each K ∩ C_j.
    for j in 1..b.n() as i64 {
        let s = b.step(j);
        // The four covectors of C_j; "v <= 0" becomes the constant constraint 1 >= 0.
        let cone: Vec<HalfPlane> = b.next_contact_cone(j).iter().map(HalfPlane::from_covector).collect();
        let verts = clipped_vertices(&ccw, &k, &cone);
        v.pieces.push(verts.len());
        let mut codes = vec![];
        for p in &verts {
            if let Some(c) = image_status(&k, &mat_vec(&s, &lift(p)), Code::ImageOutside, Code::ImageNotBelow)
                && !codes.contains(&c)
            {
                codes.push(c);
            }
        }
        if !codes.is_empty() {
            v.stage(codes);
        }
    }
    v.k_ccw = ccw;

    // R3: I_0(D) ⊆ K.
    if claim >= Claim::CcOrPccFromAllDown {
        let i0 = b.impact(0);
        let bad = b.all_down_generators().iter().any(|g| {
            image_status(&k, &mat_vec(&i0, g), Code::InitialOutside, Code::InitialOutside).is_some()
        });
        if bad {
            v.stage(vec![Code::InitialOutside]);
        }
    }

    // R4: PCC excluded.
    if claim >= Claim::CompleteChatterFromAllDown {
        let quad = pcc_quadratic(b);
        if !quad.excludes_pcc() {
            v.stage(vec![Code::PccNotExcluded]);
        }
        v.pcc = Some(quad);
    }
    v
}

/// Where the images of rule R2 land (n >= 3): for each j, each vertex p of K ∩ C_j and its image
/// q = S_j p, the least orient2(A, B, q) over the edges A -> B of K (counter-clockwise), the
/// kernel's "by" amount: negative outside, zero exactly on an edge. `None` when q is 0 or has
/// v >= 0. `None` overall when K is not a full-dimensional cone below v = 0.
pub fn image_margins(b: &Body<Q>, gens: &[[Q; 3]]) -> Option<Vec<(usize, Pt, Option<Q>)>> {
    let pts: Vec<Pt> = gens.iter().map(project).collect::<Option<Vec<Pt>>>()?;
    if !full_dimensional(&pts) {
        return None;
    }
    let ccw = jarvis(&pts);
    let m = ccw.len();
    let k: Vec<HalfPlane> = (0..m).map(|i| HalfPlane::left_of(&ccw[i], &ccw[(i + 1) % m])).collect();
    let mut out = Vec::new();
    for j in 1..b.n() {
        let cone: Vec<HalfPlane> =
            b.next_contact_cone(j as i64).iter().map(HalfPlane::from_covector).collect();
        for p in clipped_vertices(&ccw, &k, &cone) {
            let margin = project(&mat_vec(&b.step(j as i64), &lift(&p)))
                .map(|q| (0..m).map(|e| orient2(&ccw[e], &ccw[(e + 1) % m], &q)).min().expect("m >= 3"));
            out.push((j, p, margin));
        }
    }
    Some(out)
}

/// The rod's impact at end 0, I_0 (u0, u1) = (-gamma u0, u1 - (1 + gamma) c u0) with
/// c = (kappa - 1)/(kappa + 1) (docs/model.md §7).
pub fn rod_impact(kappa: &Q, gamma: &Q, p: &[Q; 2]) -> [Q; 2] {
    let one = Q::int(1);
    let c = (kappa - &one) / (kappa + &one);
    [-(gamma * &p[0]), &p[1] - &(&one + gamma) * &c * &p[0]]
}

/// The rod's step S_1 = I_0 R: the ends swap names, then end 0 hits.
pub fn rod_step(kappa: &Q, gamma: &Q, p: &[Q; 2]) -> [Q; 2] {
    rod_impact(kappa, gamma, &[p[1].clone(), p[0].clone()])
}

/// s = u0 / (-2v) = u0 / -(u0 + u1) of a rod velocity with v < 0, `None` when v >= 0.
pub fn rod_s(p: &[Q; 2]) -> Option<Q> {
    let w = -(&p[0] + &p[1]);
    (w > zero()).then(|| &p[0] / &w)
}

/// Rules R1 to R3 for the rod (R4 holds trivially: with two contacts PCC is CC), on the line
/// v = -1/2 where a velocity is the number s = u0 / (-2v) and K is the interval [lo, hi].
pub fn evaluate_rod_parts(kappa: &Q, gamma: &Q, claim: Claim, gens: &[[Q; 2]]) -> Verdict {
    let mut v = Verdict::new(max_bits(gens.iter().flatten()));
    if claim_needs_open_gamma(claim, gamma) {
        v.stage(vec![Code::ParameterOutOfRange]);
        return v;
    }
    let Some(s) = gens.iter().map(rod_s).collect::<Option<Vec<Q>>>() else {
        v.stage(vec![Code::GeneratorNotBelow]);
        return v;
    };
    let (Some(lo), Some(hi)) = (s.iter().min().cloned(), s.iter().max().cloned()) else {
        v.stage(vec![Code::DegenerateCone]);
        return v;
    };
    if lo == hi {
        v.stage(vec![Code::DegenerateCone]);
        return v;
    }
    // The first occurrences of the two ends are the extreme generators.
    let first_lo = s.iter().position(|x| *x == lo);
    let first_hi = s.iter().position(|x| *x == hi);
    v.redundant = (0..s.len()).filter(|&i| Some(i) != first_lo && Some(i) != first_hi).collect();
    let inside = |p: &[Q; 2]| rod_s(p).is_some_and(|x| lo <= x && x <= hi);
    let is_zero = |p: &[Q; 2]| p.iter().all(|c| *c == zero());
    v.contains_translation = inside(&rod_impact(kappa, gamma, &[Q::int(-1), Q::int(-1)]));

    // R2: K ∩ C_1 = K ∩ {u0 >= 0} = [max(lo, 0), hi] when hi >= 0; its ends are the rays
    // (s, -1 - s) (w = 1).
    let piece: Vec<Q> = if hi < zero() {
        vec![]
    } else if hi == zero() {
        vec![hi.clone()]
    } else {
        vec![if lo > zero() { lo.clone() } else { zero() }, hi.clone()]
    };
    v.pieces = vec![piece.len()];
    let mut codes = vec![];
    for x in &piece {
        let img = rod_step(kappa, gamma, &[x.clone(), -(Q::int(1) + x)]);
        let code = if is_zero(&img) || inside(&img) {
            continue;
        } else if rod_s(&img).is_none() {
            Code::ImageNotBelow
        } else {
            Code::ImageOutside
        };
        if !codes.contains(&code) {
            codes.push(code);
        }
    }
    if !codes.is_empty() {
        v.stage(codes);
    }
    // R3: I_0 of the generators (0, -1) and (-1, 0) of D.
    if claim >= Claim::CcOrPccFromAllDown {
        let d = [[zero(), Q::int(-1)], [Q::int(-1), zero()]];
        if d.iter().map(|g| rod_impact(kappa, gamma, g)).any(|img| !is_zero(&img) && !inside(&img)) {
            v.stage(vec![Code::InitialOutside]);
        }
    }
    v.interval = Some((lo, hi));
    v
}

/// A disagreement found by [`cross_check`] or [`check_text_and_oracle`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Finding {
    /// `backends-disagree`, `round-trip`, `accepted-false` (the kernel accepts, the oracle finds
    /// a failing rule), `oracle-accepts` (the kernel rejects a certificate the oracle accepts),
    /// `wrong-code` (the kernel's code is not among the oracle's first failures) or
    /// `wrong-report` (both accept, with different reports).
    pub kind: &'static str,
    /// What differs.
    pub detail: String,
}

impl fmt::Display for Finding {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.kind, self.detail)
    }
}

impl std::error::Error for Finding {}

fn finding(kind: &'static str, detail: String) -> Finding {
    Finding { kind, detail }
}

/// Compares the kernel's result on `cert` with the oracle's verdict: an accepted certificate must
/// pass every rule of the oracle with the same report (claim, size, redundant generators, piece
/// sizes up to repeated points of degenerate pieces, largest denominator, PCC quadratic,
/// translation); a rejected one must fail some rule of the oracle, with the kernel's code among
/// those of the oracle's first failing stage.
pub fn cross_check(
    cert: &Certificate,
    kernel: &Result<Accepted, Rejection>,
    limits: ParseLimits,
) -> Result<Verdict, Finding> {
    let v = evaluate_with(cert, limits);
    match kernel {
        Ok(a) => {
            if !v.accepted() {
                return Err(finding(
                    "accepted-false",
                    format!("the kernel accepts, the oracle finds {:?}", v.failing),
                ));
            }
            let CertBody::RegularPolygon { n, .. } = &cert.body;
            let pcc = v.pcc.as_ref().map(|p| [p.p.to_string(), p.q.to_string(), p.discriminant.to_string()]);
            let pieces_ok = a.pieces.len() == v.pieces.len()
                && a.pieces.iter().zip(&v.pieces).all(|(k, o)| if *o >= 3 { k == o } else { k >= o });
            let same = a.claim == cert.claim
                && a.n == *n
                && a.generators == cert.cone.len()
                && a.redundant == v.redundant
                && a.max_denominator_bits == v.max_denominator_bits
                && pieces_ok
                && a.pcc == pcc
                && a.pcc_boxes.is_some() == v.pcc_grid.is_some()
                && a.region == v.region
                && a.contains_translation == v.contains_translation;
            if !same {
                let detail = format!(
                    "kernel {:?}; oracle redundant {:?}, pieces {:?}, bits {}, pcc {pcc:?}, translation {}, region {:?}",
                    a, v.redundant, v.pieces, v.max_denominator_bits, v.contains_translation, v.region
                );
                return Err(finding("wrong-report", detail));
            }
        }
        Err(r) => {
            if v.accepted() && !box_pcc_unproven(&v, r, cert) {
                return Err(finding(
                    "oracle-accepts",
                    format!("the kernel rejects ({r}), the oracle accepts"),
                ));
            }
            if !v.accepted() && !v.first_stage.contains(&r.code) {
                let detail = format!(
                    "the kernel's code {:?} ({r}) is not among the oracle's first failures {:?} (all: {:?})",
                    r.code, v.first_stage, v.failing
                );
                return Err(finding("wrong-code", detail));
            }
        }
    }
    Ok(v)
}

/// Whether a kernel rejection of a box by rule R4 is consistent with an oracle that only tested a
/// grid: the kernel either names a point, where the oracle confirms that R4 fails, or a sub-box it
/// could not decide within its subdivision limit (the grid cannot contradict that).
fn box_pcc_unproven(v: &Verdict, r: &Rejection, cert: &Certificate) -> bool {
    let CertBody::RegularPolygon { n, .. } = &cert.body;
    match (&v.pcc_grid, r.code, &r.locus) {
        (Some(_), Code::PccNotExcluded, Locus::PccRegion { kappa, gamma })
            if kappa[0] == kappa[1] && gamma[0] == gamma[1] =>
        {
            match (Q::from_str(&kappa[0]), Q::from_str(&gamma[0])) {
                (Ok(k), Ok(g)) => pcc_fails_at(*n, &k, &g),
                _ => false,
            }
        }
        (Some(_), Code::PccNotExcluded, Locus::PccRegion { .. }) => true,
        _ => false,
    }
}

/// The whole check of the fuzz targets: writes `cert` with the kernel's writer, reads it back
/// (it must round-trip), verifies the text on both backends (they must agree) and cross-checks
/// the result with the oracle. Returns the kernel's verdict.
/// Whether the oracle models the certificate's body: it works over Q only, so regular polygons
/// whose cos(2 pi/n) is irrational (n = 5, 7, 8, ..., 64, checked by the kernel in Q(cos 2 pi/n))
/// are outside it; their kernel path is tested against the rational path on n = 3, 4, 6
/// (`chatter_kernel::check::check_in_field`) and by the field's own property tests.
pub fn covers(cert: &Certificate) -> bool {
    let CertBody::RegularPolygon { n, .. } = &cert.body;
    !(chatter_kernel::check::is_irrational(*n) && *n <= crate::exact::MAX_N)
}

pub fn check_text_and_oracle(
    cert: &Certificate,
    limits: ParseLimits,
) -> Result<Result<Accepted, Rejection>, Finding> {
    use chatter_kernel::verify::{MALACHITE, NUM, Verdict as KernelVerdict, verify_text};
    let text = crate::write::write(cert);
    match chatter_kernel::certificate::read(&text) {
        Ok(back) if back == *cert => {}
        Ok(back) => return Err(finding("round-trip", format!("written and read back as {back:?}"))),
        Err(r) => return Err(finding("round-trip", format!("the reader rejects the writer's text: {r}"))),
    }
    let kernel = match verify_text(&text, limits, &[MALACHITE, NUM]) {
        KernelVerdict::Accepted(a) => Ok(a),
        KernelVerdict::Rejected(r) => Err(r),
        KernelVerdict::Disagree(s) => return Err(finding("backends-disagree", s)),
    };
    if covers(cert) {
        cross_check(cert, &kernel, limits)?;
    }
    Ok(kernel)
}

pub mod mutation {
    //! Structure-aware mutations of certificates for the fuzz target `mutate` and the smoke
    //! tests: a byte string decodes to a choice of base certificate and a list of mutations
    //! (every byte string decodes; missing bytes read as 0), which [`apply`] performs on the
    //! certificate's fields. Numbers stay canonical (mutated values are reduced), so the kernel
    //! reaches its geometric rules. Generator indices are taken modulo the current cone size;
    //! mutations that would make the certificate huge (more than [`MAX_GENERATORS`] generators,
    //! or numbers longer than [`MAX_NUMBER_LEN`] characters) are skipped.

    use crate::exact::Q;
    use chatter_kernel::certificate::{Body, Certificate, Claim, Generator, Param};
    use malachite::Integer;
    use malachite::base::num::arithmetic::traits::Pow;
    use malachite::rational::Rational;
    use std::str::FromStr;

    /// Most mutations decoded from one input.
    pub const MAX_STEPS: usize = 12;
    /// No mutation adds a generator beyond this many.
    pub const MAX_GENERATORS: usize = 96;
    /// No mutation scales a number already longer than this.
    pub const MAX_NUMBER_LEN: usize = 400;

    /// Positive factors for [`Mutation::Scale`].
    pub const FACTORS: [(i64, i64); 10] = [
        (2, 1),
        (3, 1),
        (1, 2),
        (1, 3),
        (7, 5),
        (10, 1),
        (1, 10),
        (1_000_003, 1),
        (1, 999_983),
        (1 << 40, 3),
    ];

    /// Which number a [`Mutation::Nudge`] changes.
    #[derive(Clone, Copy, Debug, PartialEq, Eq)]
    pub enum Target {
        /// Coordinate `coordinate` (mod arity) of generator `generator` (mod cone size).
        Coordinate {
            /// Generator index (mod the cone size).
            generator: u8,
            /// Coordinate index (mod the arity).
            coordinate: u8,
        },
        /// kappa.
        Kappa,
        /// gamma.
        Gamma,
    }

    /// One structure-aware mutation.
    #[derive(Clone, Copy, Debug, PartialEq, Eq)]
    pub enum Mutation {
        /// Numerator or denominator ±1 ("one unit in the last digit"), then reduced.
        Nudge {
            /// The number.
            target: Target,
            /// The denominator rather than the numerator.
            denominator: bool,
            /// +1 rather than -1.
            up: bool,
        },
        /// A generator times a positive factor of [`FACTORS`] (the same ray).
        Scale {
            /// Generator index.
            generator: u8,
            /// Index into [`FACTORS`].
            factor: u8,
        },
        /// A generator times -1.
        Negate {
            /// Generator index.
            generator: u8,
        },
        /// Removes a generator.
        Drop {
            /// Generator index.
            generator: u8,
        },
        /// Inserts a copy of a generator (scaled by 2) at another position.
        Duplicate {
            /// Generator index.
            generator: u8,
            /// Insertion index (mod cone size + 1).
            at: u8,
        },
        /// Swaps two generators.
        Swap {
            /// First index.
            a: u8,
            /// Second index.
            b: u8,
        },
        /// Reverses the generator list.
        Reverse,
        /// Rotates the generator list left.
        Rotate {
            /// By this many places (mod cone size).
            by: u8,
        },
        /// Adds a generator whose projection is that of `generator` moved by
        /// (dx, dy) / 10^exponent (for the rod: s moved by dx / 10^exponent).
        AddNear {
            /// Generator index.
            generator: u8,
            /// In -4..=4.
            dx: i8,
            /// In -4..=4.
            dy: i8,
            /// In 1..=16.
            exponent: u8,
        },
        /// Adds (16 - t) g_a + t g_b (a point of K, on the segment of two generators).
        AddBetween {
            /// First generator.
            a: u8,
            /// Second generator.
            b: u8,
            /// In 0..=16.
            t: u8,
        },
        /// The next stronger claim (the strongest stays).
        UpgradeClaim,
        /// Any claim.
        SetClaim {
            /// Index into [`Claim::ALL`] (mod 3).
            claim: u8,
        },
        /// Another regular polygon with rational cos (n in 3, 4, 6; the rod stays a rod).
        SetN {
            /// Index into [3, 4, 6] (mod 3).
            n: u8,
        },
        /// kappa or gamma becomes an interval reaching 1/10^exponent beyond its value (up or
        /// down); the version becomes 2 unless `keep_version`.
        Widen {
            /// gamma rather than kappa.
            gamma: bool,
            /// Towards larger values.
            up: bool,
            /// In 1..=16.
            exponent: u8,
            /// Keep the certificate's version (1 for a point certificate: then invalid).
            keep_version: bool,
        },
    }

    /// Reads bytes; past the end every byte is 0.
    struct Reader<'a> {
        data: &'a [u8],
    }

    impl Reader<'_> {
        fn byte(&mut self) -> u8 {
            match self.data.split_first() {
                Some((b, rest)) => {
                    self.data = rest;
                    *b
                }
                None => 0,
            }
        }
        fn small(&mut self, lo: i8, hi: i8) -> i8 {
            let span = (hi - lo) as u8 + 1;
            lo + (self.byte() % span) as i8
        }
    }

    /// What an input asks for: a base certificate (index mod the corpus size) and mutations.
    #[derive(Clone, Debug, PartialEq, Eq)]
    pub struct Plan {
        /// Base certificate (mod the corpus size).
        pub pick: usize,
        /// The mutations, applied in order.
        pub steps: Vec<Mutation>,
    }

    /// Decodes any byte string into a plan: two bytes choose the base, then one byte per
    /// mutation kind followed by its arguments, at most [`MAX_STEPS`] mutations.
    pub fn decode(data: &[u8]) -> Plan {
        let mut r = Reader { data };
        let pick = usize::from(r.byte()) | (usize::from(r.byte()) << 8);
        let mut steps = Vec::new();
        while !r.data.is_empty() && steps.len() < MAX_STEPS {
            let kind = r.byte() % 15;
            let m = match kind {
                0 | 1 => {
                    let (generator, coordinate, flags) = (r.byte(), r.byte(), r.byte());
                    let target = Target::Coordinate { generator, coordinate };
                    Mutation::Nudge { target, denominator: flags & 1 == 1, up: flags & 2 == 2 }
                }
                2 => {
                    let flags = r.byte();
                    let target = if flags & 4 == 4 { Target::Gamma } else { Target::Kappa };
                    Mutation::Nudge { target, denominator: flags & 1 == 1, up: flags & 2 == 2 }
                }
                3 => Mutation::Scale { generator: r.byte(), factor: r.byte() },
                // Negation is one case in four: it almost always ends at rule R1.
                4 => {
                    let (generator, arg) = (r.byte(), r.byte());
                    if arg % 4 == 0 {
                        Mutation::Negate { generator }
                    } else {
                        Mutation::Scale { generator, factor: arg / 4 }
                    }
                }
                5 => Mutation::Drop { generator: r.byte() },
                6 => Mutation::Duplicate { generator: r.byte(), at: r.byte() },
                7 => Mutation::Swap { a: r.byte(), b: r.byte() },
                8 => {
                    if r.byte() % 2 == 0 {
                        Mutation::Reverse
                    } else {
                        Mutation::Rotate { by: r.byte() }
                    }
                }
                9 | 10 => Mutation::AddNear {
                    generator: r.byte(),
                    dx: r.small(-4, 4),
                    dy: r.small(-4, 4),
                    exponent: r.small(1, 16) as u8,
                },
                11 => Mutation::AddBetween { a: r.byte(), b: r.byte(), t: r.byte() % 17 },
                12 => {
                    if r.byte() % 2 == 0 {
                        Mutation::UpgradeClaim
                    } else {
                        Mutation::SetClaim { claim: r.byte() }
                    }
                }
                13 => Mutation::SetN { n: r.byte() },
                _ => {
                    let flags = r.byte();
                    let exponent = r.small(1, 16) as u8;
                    Mutation::Widen {
                        gamma: flags & 1 == 1,
                        up: flags & 2 == 2,
                        exponent,
                        keep_version: flags & 12 == 12,
                    }
                }
            };
            steps.push(m);
        }
        Plan { pick, steps }
    }

    /// The canonical text of numerator / denominator; `None` for a zero denominator.
    fn fraction(num: Integer, den: Integer) -> Option<String> {
        (den != 0u32).then(|| Q::from_rational(Rational::from_integers(num, den)).to_string())
    }

    /// The number ±1 in its numerator or denominator, reduced; `None` if the text is not a
    /// canonical number or the denominator would become 0.
    pub fn nudge(text: &str, denominator: bool, up: bool) -> Option<String> {
        let x = Q::from_str(text).ok()?;
        let r = x.as_rational();
        let (n, d) =
            (Integer::from_sign_and_abs(*r >= 0u32, r.to_numerator()), Integer::from(r.to_denominator()));
        let delta = Integer::from(if up { 1 } else { -1 });
        if denominator { fraction(n, d + delta) } else { fraction(n + delta, d) }
    }

    /// The last number of a parameter (the value, or the interval's upper end).
    fn param_text(p: &mut Param) -> &mut String {
        match p {
            Param::Point(x) => x,
            Param::Interval(_, b) => b,
        }
    }

    /// `text` ± 1/10^exponent, canonical; `None` if `text` is not a canonical number.
    fn shifted(text: &str, up: bool, exponent: u8) -> Option<String> {
        let x = Q::from_str(text).ok()?;
        let d = Q::from_rational(Rational::from_integers(
            Integer::from(1),
            Integer::from(10u32).pow(u64::from(exponent)),
        ));
        Some(if up { x + d } else { x - d }.to_string())
    }

    fn parse_all(g: &Generator) -> Option<Vec<Q>> {
        if g.0.iter().any(|c| c.len() > MAX_NUMBER_LEN) {
            return None;
        }
        g.0.iter().map(|c| Q::from_str(c).ok()).collect()
    }

    /// Performs one mutation (a no-op where it does not apply).
    pub fn apply(cert: &mut Certificate, m: &Mutation) {
        let len = cert.cone.len();
        let idx = |i: u8| usize::from(i) % len.max(1);
        let Body::RegularPolygon { n, kappa, gamma } = &mut cert.body;
        match *m {
            Mutation::Nudge { target, denominator, up } => {
                let text: &mut String = match target {
                    Target::Kappa => param_text(kappa),
                    Target::Gamma => param_text(gamma),
                    Target::Coordinate { generator, coordinate } => {
                        let Some(g) = cert.cone.get_mut(idx(generator)) else { return };
                        if g.0.is_empty() {
                            return;
                        }
                        let k = usize::from(coordinate) % g.0.len();
                        &mut g.0[k]
                    }
                };
                if let Some(t) = nudge(text, denominator, up) {
                    *text = t;
                }
            }
            Mutation::Scale { generator, factor } => {
                let (p, q) = FACTORS[usize::from(factor) % FACTORS.len()];
                let f = Q::new(p, q);
                if let Some(g) = cert.cone.get_mut(idx(generator))
                    && let Some(xs) = parse_all(g)
                {
                    *g = generator_of(&xs.iter().map(|x| x * &f).collect::<Vec<_>>());
                }
            }
            Mutation::Negate { generator } => {
                if let Some(g) = cert.cone.get_mut(idx(generator))
                    && let Some(xs) = parse_all(g)
                {
                    *g = generator_of(&xs.iter().map(|x| -x).collect::<Vec<_>>());
                }
            }
            Mutation::Drop { generator } => {
                if len > 0 {
                    cert.cone.remove(idx(generator));
                }
            }
            Mutation::Duplicate { generator, at } => {
                if len > 0
                    && len < MAX_GENERATORS
                    && let Some(xs) = parse_all(&cert.cone[idx(generator)])
                {
                    let copy = generator_of(&xs.iter().map(|x| x * &Q::int(2)).collect::<Vec<_>>());
                    cert.cone.insert(usize::from(at) % (len + 1), copy);
                }
            }
            Mutation::Swap { a, b } => {
                if len > 0 {
                    cert.cone.swap(idx(a), idx(b));
                }
            }
            Mutation::Reverse => cert.cone.reverse(),
            Mutation::Rotate { by } => {
                if len > 0 {
                    cert.cone.rotate_left(idx(by));
                }
            }
            Mutation::AddNear { generator, dx, dy, exponent } => {
                if len == 0 || len >= MAX_GENERATORS {
                    return;
                }
                let Some(xs) = parse_all(&cert.cone[idx(generator)]) else { return };
                let step = |d: i8| {
                    Q::from_rational(
                        Rational::from(i64::from(d)) / Rational::from(10u64.pow(u32::from(exponent))),
                    )
                };
                let new: Vec<Q> = match xs.len() {
                    // (u0, u1, v): the projection moves by (dx, dy) / 10^e at the weight -v (or 1).
                    3 => {
                        let w = if xs[2] < Q::int(0) { -&xs[2] } else { Q::int(1) };
                        vec![&xs[0] + &(&w * &step(dx)), &xs[1] + &(&w * &step(dy)), xs[2].clone()]
                    }
                    // (u0, u1): s = u0 / w moves by dx / 10^e, w = -(u0 + u1) kept.
                    2 => {
                        let w = -(&xs[0] + &xs[1]);
                        let w = if w > Q::int(0) { w } else { Q::int(1) };
                        let d = &w * &step(dx);
                        vec![&xs[0] + &d, &xs[1] - &d]
                    }
                    _ => return,
                };
                cert.cone.push(generator_of(&new));
            }
            Mutation::AddBetween { a, b, t } => {
                if len == 0 || len >= MAX_GENERATORS {
                    return;
                }
                let (Some(ga), Some(gb)) = (parse_all(&cert.cone[idx(a)]), parse_all(&cert.cone[idx(b)]))
                else {
                    return;
                };
                if ga.len() != gb.len() {
                    return;
                }
                let (ta, tb) = (Q::int(16 - i64::from(t)), Q::int(i64::from(t)));
                cert.cone.push(generator_of(
                    &ga.iter().zip(&gb).map(|(x, y)| &ta * x + &tb * y).collect::<Vec<_>>(),
                ));
            }
            Mutation::UpgradeClaim => {
                cert.claim = match cert.claim {
                    Claim::EffectivelyInvariant => Claim::CcOrPccFromAllDown,
                    _ => Claim::CompleteChatterFromAllDown,
                }
            }
            Mutation::SetClaim { claim } => cert.claim = Claim::ALL[usize::from(claim) % 3],
            Mutation::SetN { n: k } => {
                if *n >= 3 {
                    *n = [3, 4, 6][usize::from(k) % 3];
                }
            }
            Mutation::Widen { gamma: g, up, exponent, keep_version } => {
                let p = if g { gamma } else { kappa };
                if let Param::Point(x) = p.clone()
                    && let Some(y) = shifted(&x, up, exponent)
                {
                    *p = if up { Param::Interval(x, y) } else { Param::Interval(y, x) };
                    if !keep_version {
                        cert.version = 2;
                    }
                }
            }
        }
    }

    fn generator_of(xs: &[Q]) -> Generator {
        Generator(xs.iter().map(Q::to_string).collect())
    }

    /// Applies a plan to a copy of `base`.
    pub fn mutated(base: &Certificate, steps: &[Mutation]) -> Certificate {
        let mut c = base.clone();
        for m in steps {
            apply(&mut c, m);
        }
        c
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use chatter_kernel::certificate::{Coordinates, Generator};

    fn q(s: &str) -> Q {
        s.parse().expect("canonical")
    }

    fn rod(kappa: &str, gamma: &str, claim: Claim, gens: &[(&str, &str)]) -> Certificate {
        Certificate {
            format: FORMAT.into(),
            version: 1,
            body: CertBody::RegularPolygon { n: 2, kappa: kappa.into(), gamma: gamma.into() },
            coordinates: Coordinates::ContactVelocities,
            claim,
            cone: gens.iter().map(|(a, b)| Generator(vec![a.to_string(), b.to_string()])).collect(),
            time_to_rest_bound: None,
            producer: "test".into(),
        }
    }

    #[test]
    fn numbers_follow_the_canonical_rules() {
        let l = ParseLimits::default();
        for ok in ["0", "1", "-1", "1/2", "-3/4", "10", "123456789012345678901234567890/11"] {
            assert_eq!(parse_number(ok, l).map(|x| x.to_string()), Some(ok.to_string()), "{ok}");
        }
        for bad in [
            "", "-", "+1", "01", "-0", "1/0", "1/1", "2/4", "0/5", " 1", "1 ", "1.5", "1e3", "1/", "/2",
            "1/-2", "--1", "1/01",
        ] {
            assert_eq!(parse_number(bad, l), None, "{bad:?}");
        }
        // At most 10,000 digits (the default), numerator and denominator together.
        let long = format!("1{}/3", "0".repeat(9998));
        assert_eq!(parse_number(&long, l).map(|x| x.to_string()), Some(long.clone()));
        assert_eq!(parse_number(&format!("1{long}"), l), None);
    }

    #[test]
    fn rod_maps_follow_the_model() {
        // docs/model.md §7 at kappa = 1/3 (c = -1/2), gamma = 1/20.
        let (k, g) = (q("1/3"), q("1/20"));
        assert_eq!(rod_impact(&k, &g, &[q("-3"), q("1")]), [q("3/20"), q("-23/40")]);
        assert_eq!(rod_step(&k, &g, &[q("1"), q("-3")]), [q("3/20"), q("-23/40")]);
        assert_eq!(rod_s(&[q("1"), q("-3")]), Some(q("1/2")));
        assert_eq!(rod_s(&[q("1"), q("-1")]), None);
    }

    #[test]
    fn rod_rules() {
        // The paper's cone at kappa = 1/4, gamma = 1/9 (certificate-format.md §8).
        let ok = evaluate(&rod("1/4", "1/9", Claim::CompleteChatterFromAllDown, &[("-3", "1"), ("1", "-3")]));
        assert!(ok.accepted(), "{ok:?}");
        assert_eq!(ok.interval, Some((q("-3/2"), q("1/2"))));
        assert_eq!(
            (ok.pieces.clone(), ok.redundant.clone(), ok.contains_translation),
            (vec![2], vec![], true)
        );
        // Shrunk (tests/all/kernel/rod.rs): the image of an end leaves K.
        let small =
            evaluate(&rod("1/3", "1/20", Claim::EffectivelyInvariant, &[("0", "-2"), ("1/10", "-21/10")]));
        assert_eq!(small.first_stage, vec![Code::ImageOutside]);
        let up = evaluate(&rod("1/3", "1/20", Claim::EffectivelyInvariant, &[("0", "-2"), ("1", "1")]));
        assert_eq!(up.first_stage, vec![Code::GeneratorNotBelow]);
        let ray = evaluate(&rod("1/3", "1/20", Claim::EffectivelyInvariant, &[("1", "-3"), ("2", "-6")]));
        assert_eq!(ray.first_stage, vec![Code::DegenerateCone]);
        assert_eq!(
            evaluate(&rod("1/3", "1/20", Claim::EffectivelyInvariant, &[])).first_stage,
            vec![Code::DegenerateCone]
        );
        let mut three = rod("1/3", "1/20", Claim::EffectivelyInvariant, &[("0", "-2"), ("1", "-3")]);
        three.cone[1].0.push("-1".into());
        assert_eq!(evaluate(&three).first_stage, vec![Code::WrongArity]);
        // Vacuous: no piece, invariant, but the all-down drops are not in K.
        let vac = rod("1/3", "1/20", Claim::EffectivelyInvariant, &[("-1", "-1"), ("-3/2", "-1/2")]);
        let v = evaluate(&vac);
        assert!(v.accepted() && v.pieces == [0] && !v.contains_translation, "{v:?}");
        let mut vac = vac;
        vac.claim = Claim::CcOrPccFromAllDown;
        assert_eq!(evaluate(&vac).first_stage, vec![Code::InitialOutside]);
        // Drop claims need 0 < gamma < 1; the cone property does not.
        for gamma in ["0", "1"] {
            let c = rod("1/4", gamma, Claim::CcOrPccFromAllDown, &[("-3", "1"), ("1", "-3")]);
            assert_eq!(evaluate(&c).first_stage, vec![Code::ParameterOutOfRange]);
        }
        let c = rod("1/4", "3/2", Claim::EffectivelyInvariant, &[("-3", "1"), ("1", "-3")]);
        assert_eq!(evaluate(&c).first_stage, vec![Code::ParameterOutOfRange]);
        // Redundant generators: a repeat and an interior ray.
        let c = rod(
            "1/4",
            "1/9",
            Claim::EffectivelyInvariant,
            &[("-3", "1"), ("-6", "2"), ("0", "-1"), ("1", "-3")],
        );
        assert_eq!(evaluate(&c).redundant, vec![1, 2]);
    }

    #[test]
    fn rod_verdicts_match_the_kernel() {
        let certs = [
            rod("1/4", "1/9", Claim::CompleteChatterFromAllDown, &[("-3", "1"), ("1", "-3")]),
            rod("1/3", "1/20", Claim::CcOrPccFromAllDown, &[("0", "-2"), ("2/7", "-16/7")]),
            rod("1/3", "1/20", Claim::EffectivelyInvariant, &[("0", "-2"), ("1/10", "-21/10")]),
            rod("1/3", "1/20", Claim::CcOrPccFromAllDown, &[("-1", "-1"), ("-3/2", "-1/2")]),
            rod("1/3", "1/20", Claim::EffectivelyInvariant, &[("0", "-1"), ("1", "-2"), ("0", "-2")]),
            rod("3", "1/2", Claim::EffectivelyInvariant, &[("-1", "-1"), ("1", "-2")]),
        ];
        for c in certs {
            if let Err(f) = check_text_and_oracle(&c, ParseLimits::default()) {
                panic!("{f}\n{}", crate::write::write(&c));
            }
        }
    }

    #[test]
    fn mutations_decode_and_apply() {
        use mutation::*;
        assert_eq!(decode(&[]), Plan { pick: 0, steps: vec![] });
        let p = decode(&[1, 0, 2, 3, 5, 9, 0]);
        assert_eq!(p.pick, 1);
        assert_eq!(
            p.steps,
            vec![
                Mutation::Nudge { target: Target::Kappa, denominator: true, up: true },
                Mutation::Drop { generator: 9 },
                Mutation::Nudge {
                    target: Target::Coordinate { generator: 0, coordinate: 0 },
                    denominator: false,
                    up: false
                }
            ]
        );
        assert_eq!(nudge("1/6", false, false).as_deref(), Some("0"));
        assert_eq!(nudge("1/6", true, true).as_deref(), Some("1/7"));
        assert_eq!(nudge("3/4", true, false).as_deref(), Some("1"));
        assert_eq!(nudge("-5/4", false, true).as_deref(), Some("-1"));
        assert_eq!(nudge("2", true, false), None);
        let base = rod("1/4", "1/9", Claim::EffectivelyInvariant, &[("-3", "1"), ("1", "-3")]);
        let c = mutated(
            &base,
            &[
                Mutation::Scale { generator: 1, factor: 2 },
                Mutation::AddNear { generator: 0, dx: 1, dy: 0, exponent: 1 },
                Mutation::UpgradeClaim,
                Mutation::SetN { n: 0 },
            ],
        );
        assert_eq!(c.cone[1].0, ["1/2", "-3/2"]);
        assert_eq!(c.cone[2].0, ["-14/5", "4/5"]);
        assert_eq!(c.claim, Claim::CcOrPccFromAllDown);
        assert_eq!(c.body, base.body, "the rod stays a rod");
    }
}
