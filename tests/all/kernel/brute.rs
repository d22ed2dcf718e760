//! An independent brute-force evaluator of certificates, written in rationals on the projection
//! plane v = -1, for cross-checking `chatter_kernel::check`.
//!
//! It deliberately shares nothing with `chatter_kernel::geometry` or `chatter_kernel::check`: no homogeneous
//! integer vectors, no hull algorithm, no clipping. K is the intersection of every supporting
//! half-plane through two projected generators, the vertices of K ∩ C_j are all pairwise
//! intersections of constraint lines that satisfy every constraint, and the PCC quadratic is
//! recomputed from the matrix S_{n-1} S_1 by hand. Only the model maps (`Body::step`,
//! `Body::impact`, `Body::next_contact_cone`, `Body::all_down_generators`) come from the kernel;
//! they are tested in kernel/impact.rs and kernel/cones.rs.
//!
//! The tests at the bottom check the evaluator itself on small hand-made cases.
#![allow(dead_code)]

use crate::common::{GAMMAS, KAPPAS, NS, body, q};
use chatter::exact::Q;
use chatter_kernel::certificate::{Body as CertBody, Certificate, Claim, Code};
use chatter_kernel::model::Polygon as Body;

/// A point of the projection plane: (u0, u1) / (-v).
pub type Pt = (Q, Q);

pub fn zero() -> Q {
    Q::int(0)
}

pub fn sub(a: &Pt, b: &Pt) -> Pt {
    (&a.0 - &b.0, &a.1 - &b.1)
}

/// orient2d(a, b, c) = cross(b - a, c - a): > 0 when a, b, c turn counter-clockwise.
pub fn orient2(a: &Pt, b: &Pt, c: &Pt) -> Q {
    let (u, w) = (sub(b, a), sub(c, a));
    &u.0 * &w.1 - &u.1 * &w.0
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
    pub a: Q,
    pub b: Q,
    pub c: Q,
}

impl HalfPlane {
    pub fn eval(&self, p: &Pt) -> Q {
        &self.a * &p.0 + &self.b * &p.1 + &self.c
    }
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

/// The vertices of a bounded intersection of half-planes: every intersection of two constraint
/// lines that satisfies all constraints (distinct, in no particular order). Lines with a = b = 0
/// are constant constraints and take part only in the satisfaction test.
pub fn polygon_vertices(hps: &[HalfPlane]) -> Vec<Pt> {
    let mut out: Vec<Pt> = Vec::new();
    for i in 0..hps.len() {
        for j in i + 1..hps.len() {
            let (h, k) = (&hps[i], &hps[j]);
            let det = &h.a * &k.b - &h.b * &k.a;
            if det == zero() {
                continue;
            }
            // a x + b y = -c for both lines (Cramer).
            let x = (&h.b * &k.c - &k.b * &h.c) / &det;
            let y = (&k.a * &h.c - &h.a * &k.c) / &det;
            let p = (x, y);
            if hps.iter().all(|l| l.contains(&p)) && !out.contains(&p) {
                out.push(p);
            }
        }
    }
    out
}

pub fn mat_vec(m: &[[Q; 3]; 3], x: &[Q; 3]) -> [Q; 3] {
    std::array::from_fn(|r| &m[r][0] * &x[0] + &m[r][1] * &x[1] + &m[r][2] * &x[2])
}

pub fn mat_mul(a: &[[Q; 3]; 3], b: &[[Q; 3]; 3]) -> [[Q; 3]; 3] {
    std::array::from_fn(|r| std::array::from_fn(|c| (0..3).fold(zero(), |s, k| s + &a[r][k] * &b[k][c])))
}

/// The PCC quadratic t^2 + p t + q of det(tI - S_{n-1} S_1) = (t - 1)(t^2 + p t + q), with its
/// discriminant, recomputed from the matrix (Sarrus for the determinant, synthetic division).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Quadratic {
    pub p: Q,
    pub q: Q,
    pub discriminant: Q,
}

impl Quadratic {
    pub fn excludes_pcc(&self) -> bool {
        self.discriminant < zero() && self.q < Q::int(1)
    }
}

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
    /// Every failing category found (in the kernel's order, without repeats).
    pub failing: Vec<Code>,
    /// The categories of the first failing stage in the kernel's order of checks (generators,
    /// dimension, S_1, ..., S_{n-1}, I_0(D), PCC): the kernel's code must be one of these.
    pub first_stage: Vec<Code>,
    /// Generators whose projection is not a vertex of K, or repeats an earlier generator's.
    pub redundant: Vec<usize>,
    /// The number of distinct vertices of K ∩ C_j, j = 1..n-1.
    pub pieces: Vec<usize>,
    /// Vertices of K in counter-clockwise order from the lexicographically smallest.
    pub k_ccw: Vec<Pt>,
    pub max_denominator_bits: u64,
    pub pcc: Option<Quadratic>,
    /// Whether K contains I_0(-1, -1, -1) (informational, not a rule).
    pub contains_translation: bool,
}

impl Verdict {
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

/// Evaluates a certificate whose numbers are canonical and whose generators have 3 coordinates.
pub fn evaluate(cert: &Certificate) -> Verdict {
    let CertBody::RegularPolygon { n, kappa, gamma } = &cert.body;
    let gens: Vec<[Q; 3]> = cert
        .cone
        .iter()
        .map(|g| {
            assert_eq!(g.0.len(), 3, "the brute force needs 3 coordinates");
            std::array::from_fn(|i| q(&g.0[i]))
        })
        .collect();
    evaluate_parts(&body(*n, kappa, gamma), cert.claim, &gens)
}

pub fn evaluate_parts(b: &Body<Q>, claim: Claim, gens: &[[Q; 3]]) -> Verdict {
    let max_denominator_bits = gens.iter().flatten().map(Q::denominator_bits).max().unwrap_or(0);
    let mut v = Verdict {
        failing: vec![],
        first_stage: vec![],
        redundant: vec![],
        pieces: vec![],
        k_ccw: vec![],
        max_denominator_bits,
        pcc: None,
        contains_translation: false,
    };
    let stage = |v: &mut Verdict, codes: Vec<Code>| {
        if v.first_stage.is_empty() {
            v.first_stage = codes.clone();
        }
        for c in codes {
            if !v.failing.contains(&c) {
                v.failing.push(c);
            }
        }
    };

    // The claims about drops need 0 < gamma < 1 (docs/kernel-soundness.md).
    if claim > Claim::EffectivelyInvariant && (*b.gamma() == Q::int(0) || *b.gamma() == Q::int(1)) {
        stage(&mut v, vec![Code::ParameterOutOfRange]);
        return v;
    }
    let pts: Vec<Pt> = match gens.iter().map(project).collect::<Option<Vec<Pt>>>() {
        Some(p) => p,
        None => {
            stage(&mut v, vec![Code::GeneratorNotBelow]);
            return v;
        }
    };
    if !full_dimensional(&pts) {
        stage(&mut v, vec![Code::DegenerateCone]);
        return v;
    }
    // K: every supporting half-plane through two generators; its vertices are the extreme
    // generators (Carathéodory's `extreme_points` is too slow for 50 generators).
    let k = supporting_half_planes(&pts);
    let ext = polygon_vertices(&k);
    assert!(ext.iter().all(|p| pts.contains(p)), "a vertex of K is a generator");
    v.redundant = (0..pts.len()).filter(|&i| !ext.contains(&pts[i]) || pts[..i].contains(&pts[i])).collect();
    v.k_ccw = ccw_order(&ext);
    let down = mat_vec(&b.impact(0), &[Q::int(-1), Q::int(-1), Q::int(-1)]);
    v.contains_translation = project(&down).is_some_and(|p| k.iter().all(|h| h.contains(&p)));

    for j in 1..b.n() as i64 {
        let s = b.step(j);
        let mut cons = k.clone();
        // The four covectors of C_j; "v <= 0" becomes the constant constraint 1 >= 0.
        cons.extend(b.next_contact_cone(j).iter().map(HalfPlane::from_covector));
        let verts = polygon_vertices(&cons);
        v.pieces.push(verts.len());
        let mut codes = vec![];
        for p in &verts {
            if let Some(c) = image_status(&k, &mat_vec(&s, &lift(p)), Code::ImageOutside, Code::ImageNotBelow)
            {
                if !codes.contains(&c) {
                    codes.push(c);
                }
            }
        }
        if !codes.is_empty() {
            stage(&mut v, codes);
        }
    }

    if claim >= Claim::CcOrPccFromAllDown {
        let i0 = b.impact(0);
        let bad = b.all_down_generators().iter().any(|g| {
            image_status(&k, &mat_vec(&i0, g), Code::InitialOutside, Code::InitialOutside).is_some()
        });
        if bad {
            stage(&mut v, vec![Code::InitialOutside]);
        }
    }

    if claim >= Claim::CompleteChatterFromAllDown {
        let quad = pcc_quadratic(b);
        if !quad.excludes_pcc() {
            stage(&mut v, vec![Code::PccNotExcluded]);
        }
        v.pcc = Some(quad);
    }
    v
}

// ---------------------------------------------------------------------------------------------
// Tests of the evaluator itself.

fn pt(x: &str, y: &str) -> Pt {
    (q(x), q(y))
}

fn sorted(mut v: Vec<Pt>) -> Vec<Pt> {
    v.sort();
    v
}

#[test]
fn hull_primitives_on_a_square_with_extra_points() {
    let sq = [pt("0", "0"), pt("2", "0"), pt("2", "2"), pt("0", "2")];
    let mut pts = sq.to_vec();
    pts.extend([pt("1", "1"), pt("1", "0"), pt("2", "2"), pt("1/2", "3/2")]);
    assert_eq!(sorted(extreme_points(&pts)), sorted(sq.to_vec()));
    assert_eq!(ccw_hull(&pts), sq.to_vec());
    assert_eq!(twice_area(&ccw_hull(&pts)), q("8"));
    assert!(in_hull(&pt("2", "1"), &sq));
    assert!(in_hull(&pt("0", "0"), &sq));
    assert!(!in_hull(&pt("2", "3"), &sq));
    assert!(!in_hull(&pt("-1/1000", "1"), &sq));
    assert!(full_dimensional(&pts));
    assert!(!full_dimensional(&[pt("0", "0"), pt("1", "1"), pt("3", "3"), pt("1", "1")]));
    assert!(!full_dimensional(&[pt("0", "0"), pt("0", "0"), pt("0", "0")]));
    // The supporting half-planes are the four edges; their vertices are the square.
    let hp = supporting_half_planes(&pts);
    assert_eq!(hp.len(), 4, "{hp:?}");
    assert_eq!(sorted(polygon_vertices(&hp)), sorted(sq.to_vec()));
    // Clip by x + y <= 1 (a x + b y + c >= 0 with a = b = -1, c = 1): the triangle 0, (1,0), (0,1).
    let mut cons = hp.clone();
    cons.push(HalfPlane { a: q("-1"), b: q("-1"), c: q("1") });
    assert_eq!(sorted(polygon_vertices(&cons)), sorted(vec![pt("0", "0"), pt("1", "0"), pt("0", "1")]));
    // A constant false constraint empties it; a constant true one changes nothing.
    let mut empty = hp.clone();
    empty.push(HalfPlane { a: q("0"), b: q("0"), c: q("-1") });
    assert!(polygon_vertices(&empty).is_empty());
    let mut same = hp;
    same.push(HalfPlane { a: q("0"), b: q("0"), c: q("1") });
    assert_eq!(sorted(polygon_vertices(&same)), sorted(sq.to_vec()));
}

#[test]
fn collinear_and_tiny_sets() {
    let line = [pt("0", "0"), pt("3", "3"), pt("1", "1"), pt("3", "3")];
    assert_eq!(sorted(extreme_points(&line)), vec![pt("0", "0"), pt("3", "3")]);
    assert_eq!(extreme_points(&[pt("1", "2"), pt("1", "2")]), vec![pt("1", "2")]);
    assert!(extreme_points(&[]).is_empty());
    assert_eq!(orient2(&pt("0", "0"), &pt("1", "0"), &pt("0", "1")), q("1"));
    assert!(on_segment(&pt("1/2", "1/2"), &pt("0", "0"), &pt("1", "1")));
    assert!(!on_segment(&pt("2", "2"), &pt("0", "0"), &pt("1", "1")));
}

#[test]
fn pcc_quadratic_matches_the_kernel_and_fixes_one() {
    for n in NS {
        for kappa in KAPPAS {
            for gamma in GAMMAS {
                let b = body(n, kappa, gamma);
                let mine = pcc_quadratic(&b);
                let theirs = chatter_kernel::model::pcc_quadratic(&b).expect("1 is an eigenvalue");
                assert_eq!(
                    (&mine.p, &mine.q, &mine.discriminant),
                    (&theirs.p, &theirs.q, &theirs.discriminant)
                );
                assert_eq!(mine.excludes_pcc(), theirs.excludes_pcc(), "n={n} kappa={kappa} gamma={gamma}");
            }
        }
    }
    // The two cases used in kernel::check: PCC possible for the triangle at kappa = 1/8.
    let tri = pcc_quadratic(&body(3, "1/8", "1/100"));
    assert_eq!((tri.p.to_string(), tri.q.to_string()), ("-8401/90000".into(), "1/10000".into()));
    assert!(!tri.excludes_pcc());
    assert!(pcc_quadratic(&body(4, "1/6", "1/100")).excludes_pcc());
}

/// Generators (x, y, -1) of a projected polygon.
pub fn lifted(pts: &[Pt]) -> Vec<[Q; 3]> {
    pts.iter().map(lift).collect()
}

#[test]
fn evaluator_categories_on_hand_made_cones() {
    let b = body(4, "1/6", "1/100");
    // Generators with v >= 0 and collinear generators stop the evaluation early.
    let above = vec![[q("0"), q("0"), q("-1")], [q("1"), q("0"), q("0")], [q("0"), q("1"), q("-1")]];
    let v = evaluate_parts(&b, Claim::EffectivelyInvariant, &above);
    assert_eq!(
        (v.failing.clone(), v.first_stage.clone()),
        (vec![Code::GeneratorNotBelow], vec![Code::GeneratorNotBelow])
    );
    let flat = lifted(&[pt("0", "0"), pt("1", "1"), pt("2", "2")]);
    assert_eq!(evaluate_parts(&b, Claim::EffectivelyInvariant, &flat).failing, vec![Code::DegenerateCone]);
    // A huge triangle: some images leave v < 0 or K, and I_0(D) is checked only when claimed.
    let big = lifted(&[pt("-100", "-100"), pt("100", "-100"), pt("0", "100")]);
    let weak = evaluate_parts(&b, Claim::EffectivelyInvariant, &big);
    assert!(!weak.accepted());
    assert!(!weak.failing.contains(&Code::InitialOutside) && weak.pcc.is_none());
    // A tiny triangle far from the post-impact velocities fails I_0(D) ⊆ K.
    let tiny = lifted(&[pt("10", "10"), pt("11", "10"), pt("10", "11")]);
    let strong = evaluate_parts(&b, Claim::CompleteChatterFromAllDown, &tiny);
    assert!(strong.failing.contains(&Code::InitialOutside), "{strong:?}");
    assert!(!strong.failing.contains(&Code::PccNotExcluded), "PCC is excluded for the square plate");
    assert!(strong.pcc.as_ref().is_some_and(Quadratic::excludes_pcc));
    // Redundant: an interior point and a later duplicate.
    let mut with_extra = lifted(&[pt("0", "0"), pt("1/2", "1/2"), pt("2", "0"), pt("0", "2")]);
    with_extra.push([q("4"), q("0"), q("-2")]);
    let v = evaluate_parts(&b, Claim::EffectivelyInvariant, &with_extra);
    assert_eq!(v.redundant, vec![1, 4]);
    assert_eq!(v.k_ccw, vec![pt("0", "0"), pt("2", "0"), pt("0", "2")]);
}
