//! Brute-force references of the kernel tests, sharing nothing with the kernel: plain 2-D
//! geometry on rational points (for polygon.rs, which tests `chatter_kernel::geometry`), and the
//! independent oracle (`chatter-oracle`, oracle/) seen as a verdict on a certificate (for
//! check.rs). The oracle derives its maps and cones from docs/model.md with its own code.

use chatter::exact::Q;
use chatter::write::write;
use chatter_kernel::certificate::{Certificate, Code};
use chatter_oracle::arith::Num;
use chatter_oracle::arith::text::element_text;
use chatter_oracle::kinds::cone::{Parts, prepare, read};
use chatter_oracle::kinds::limits::Limits;
use chatter_oracle::read::{Encoding, parse::parse};
use chatter_oracle::regular::model::Polygon;

/// A point of the plane v = -1.
pub type Pt = (Q, Q);

fn zero() -> Q {
    Q::int(0)
}

fn sub(a: &Pt, b: &Pt) -> Pt {
    (&a.0 - &b.0, &a.1 - &b.1)
}

/// orient2(a, b, c) = cross(b - a, c - a).
pub fn orient2(a: &Pt, b: &Pt, c: &Pt) -> Q {
    let (u, w) = (sub(b, a), sub(c, a));
    &u.0 * &w.1 - &u.1 * &w.0
}

/// The projection of a vector with v < 0.
pub fn project(g: &[Q; 3]) -> Option<Pt> {
    if g[2] >= zero() {
        return None;
    }
    let w = -&g[2];
    Some((&g[0] / &w, &g[1] / &w))
}

/// `m x`.
pub fn mat_vec(m: &[[Q; 3]; 3], x: &[Q; 3]) -> [Q; 3] {
    std::array::from_fn(|r| &m[r][0] * &x[0] + &m[r][1] * &x[1] + &m[r][2] * &x[2])
}

/// Whether p lies on the closed segment [a, b].
pub fn on_segment(p: &Pt, a: &Pt, b: &Pt) -> bool {
    let (pa, pb) = (sub(a, p), sub(b, p));
    orient2(a, b, p) == zero() && &pa.0 * &pb.0 + &pa.1 * &pb.1 <= zero()
}

/// Whether p lies in the hull of `pts` (a point, a segment or a triangle of them: Carathéodory).
pub fn in_hull(p: &Pt, pts: &[Pt]) -> bool {
    let m = pts.len();
    (0..m).any(|i| {
        &pts[i] == p
            || (i + 1..m).any(|j| {
                on_segment(p, &pts[i], &pts[j])
                    || (j + 1..m).any(|k| {
                        let (a, b, c) = (&pts[i], &pts[j], &pts[k]);
                        let s = [orient2(a, b, p), orient2(b, c, p), orient2(c, a, p)];
                        orient2(a, b, c) != zero()
                            && (s.iter().all(|x| *x >= zero()) || s.iter().all(|x| *x <= zero()))
                    })
            })
    })
}

/// The distinct points in first-occurrence order.
pub fn distinct(pts: &[Pt]) -> Vec<Pt> {
    let mut out: Vec<Pt> = vec![];
    for p in pts {
        if !out.contains(p) {
            out.push(p.clone());
        }
    }
    out
}

/// The distinct points not in the hull of the others.
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

/// Whether some three points are not collinear.
pub fn full_dimensional(pts: &[Pt]) -> bool {
    let d = distinct(pts);
    d.len() >= 3 && d[2..].iter().any(|p| orient2(&d[0], &d[1], p) != zero())
}

/// The extreme points counter-clockwise from the lexicographically smallest (gift wrapping).
pub fn ccw_hull(pts: &[Pt]) -> Vec<Pt> {
    let ext = extreme_points(pts);
    if ext.len() < 3 {
        let mut e = ext;
        e.sort();
        return e;
    }
    let start = ext.iter().min().expect("non-empty").clone();
    let mut out = vec![start.clone()];
    loop {
        let cur = out.last().expect("non-empty").clone();
        let next = ext
            .iter()
            .find(|c| {
                **c != cur && ext.iter().all(|p| *p == cur || *p == **c || orient2(&cur, c, p) > zero())
            })
            .expect("a next vertex")
            .clone();
        if next == start {
            return out;
        }
        out.push(next);
    }
}

/// Twice the signed area (shoelace).
pub fn twice_area(poly: &[Pt]) -> Q {
    let m = poly.len();
    (0..m).fold(zero(), |s, i| {
        let (a, b) = (&poly[i], &poly[(i + 1) % m]);
        s + (&a.0 * &b.1 - &a.1 * &b.0)
    })
}

/// The half-plane a x + b y + c ≥ 0.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HalfPlane {
    /// Coefficient of x.
    pub a: Q,
    /// Coefficient of y.
    pub b: Q,
    /// Constant.
    pub c: Q,
}

impl HalfPlane {
    /// a x + b y + c.
    pub fn eval(&self, p: &Pt) -> Q {
        &self.a * &p.0 + &self.b * &p.1 + &self.c
    }
    /// Whether a x + b y + c ≥ 0.
    pub fn contains(&self, p: &Pt) -> bool {
        self.eval(p) >= zero()
    }
    /// The left of p → q.
    pub fn left_of(p: &Pt, q: &Pt) -> HalfPlane {
        let d = sub(q, p);
        let (a, b) = (-&d.1, d.0.clone());
        let c = -(&a * &p.0 + &b * &p.1);
        HalfPlane { a, b, c }
    }
    /// The section of l · p ≥ 0 by v = -1.
    pub fn from_covector(l: &[Q; 3]) -> HalfPlane {
        HalfPlane { a: l[0].clone(), b: l[1].clone(), c: -&l[2] }
    }
    fn normalized(&self) -> HalfPlane {
        let s = if self.a != zero() { self.a.clone() } else { self.b.clone() };
        let s = if s < zero() { -s } else { s };
        HalfPlane { a: &self.a / &s, b: &self.b / &s, c: &self.c / &s }
    }
}

/// Every supporting half-plane through two distinct points (the edges of the hull).
pub fn supporting_half_planes(pts: &[Pt]) -> Vec<HalfPlane> {
    let d = distinct(pts);
    let mut out: Vec<HalfPlane> = vec![];
    for i in 0..d.len() {
        for j in (0..d.len()).filter(|&j| j != i) {
            let h = HalfPlane::left_of(&d[i], &d[j]);
            if d.iter().all(|p| h.contains(p)) && !out.contains(&h.normalized()) {
                out.push(h.normalized());
            }
        }
    }
    out
}

/// The vertices of a bounded intersection of half-planes: the meeting points of two lines that
/// satisfy every constraint.
pub fn polygon_vertices(hps: &[HalfPlane]) -> Vec<Pt> {
    let mut out: Vec<Pt> = vec![];
    for (i, h) in hps.iter().enumerate() {
        for k in &hps[i + 1..] {
            let det = &h.a * &k.b - &h.b * &k.a;
            if det == zero() {
                continue;
            }
            let p = ((&h.b * &k.c - &k.b * &h.c) / &det, (&k.a * &h.c - &h.a * &k.c) / &det);
            if hps.iter().all(|l| l.contains(&p)) && !out.contains(&p) {
                out.push(p);
            }
        }
    }
    out
}

// ---------------------------------------------------------------------------------------------
// The independent oracle on a certificate.

fn q_of(x: &Num) -> Q {
    element_text(x).parse().expect("a rational")
}

fn pt_of(p: &(Num, Num)) -> Pt {
    (q_of(&p.0), q_of(&p.1))
}

/// The oracle's verdict on a certificate of a regular polygon.
#[derive(Clone, Debug)]
pub struct Verdict {
    /// Every failing content rule, each evaluated on its own (`chatter_oracle::isolate`); or the
    /// first failing rule of the file.
    pub failing: Vec<Code>,
    /// The codes the first failing rule can give (the kernel's code must be one of them).
    pub first_stage: Vec<Code>,
    /// The oracle's report when it accepts.
    pub report: Option<chatter_oracle::verdict::Report>,
}

impl Verdict {
    /// Whether the oracle accepts.
    pub fn accepted(&self) -> bool {
        self.report.is_some()
    }
}

/// The kernel's code of a kebab-case name.
fn code(name: &str) -> Code {
    use Code::*;
    let all = [
        Syntax,
        UnknownField,
        MissingField,
        DuplicateField,
        UnknownVariant,
        WrongFormat,
        UnsupportedVersion,
        BadNumber,
        UnsupportedBody,
        ParameterOutOfRange,
        WrongArity,
        GeneratorNotBelow,
        DegenerateCone,
        ImageNotBelow,
        ImageOutside,
        InitialOutside,
        PccNotExcluded,
        TooLarge,
        TimeLimit,
        StepFailed,
    ];
    all.into_iter().find(|c| c.as_str() == name).unwrap_or(Internal)
}

/// The oracle's verdict on `cert` (written by the kernel's writer, read by the oracle's reader).
pub fn evaluate(cert: &Certificate) -> Verdict {
    let text = write(cert);
    let j = chatter_oracle::judge(&text, Encoding::Ron);
    let report = match &j.outcome {
        chatter_oracle::verdict::Outcome::Accept(r) => Some((**r).clone()),
        _ => None,
    };
    Verdict {
        failing: chatter_oracle::isolate::every_failure(&text, Encoding::Ron)
            .iter()
            .map(|c| code(c))
            .collect(),
        first_stage: j.codes().iter().map(|c| code(c)).collect(),
        report,
    }
}

/// The oracle's model and cone polygon of a point certificate of a regular polygon (n ≥ 3).
fn parts(cert: &Certificate) -> (Polygon, chatter_oracle::regular::rules::Polygon2) {
    let text = write(cert);
    let value = parse(&text, Encoding::Ron).expect("the kernel's writer writes the strict syntax");
    let file = read(&value).expect("the schema");
    let (Parts::Point(b, gens), _) = prepare(&file, &Limits::default()).expect("the file's rules") else {
        panic!("a point certificate of a regular polygon")
    };
    let k = chatter_oracle::regular::rules::cone_polygon(&gens).expect("rule R1");
    (b, k)
}

/// The oracle's K: vertices counter-clockwise from the lexicographically smallest.
pub fn k_ccw(cert: &Certificate) -> Vec<Pt> {
    parts(cert).1.vertices.iter().map(pt_of).collect()
}

/// The oracle's vertices of K ∩ C_j and their images under S_j (`None` when v ≥ 0).
pub fn piece(cert: &Certificate, j: i64) -> Vec<(Pt, Option<Pt>)> {
    use chatter_oracle::plane::{HalfPlane as H, clip_vertices, lift, project};
    let (b, k) = parts(cert);
    let cj: Vec<H> = b.next_contact_facets(j).iter().map(H::of_covector).collect();
    clip_vertices(&k.vertices, &cj)
        .iter()
        .map(|p| (pt_of(p), project(&b.step(j, &lift(p))).map(|q| pt_of(&q))))
        .collect()
}

/// The oracle's PCC quadratic (p, q, p² - 4q) of a point certificate's body.
pub fn pcc(cert: &Certificate) -> (Q, Q, Q) {
    let quad = chatter_oracle::regular::pcc::pcc_quadratic(&parts(cert).0);
    (q_of(&quad.p), q_of(&quad.q), q_of(&quad.discriminant))
}

// ---------------------------------------------------------------------------------------------
// Tests of the 2-D helpers themselves.

fn pt(x: &str, y: &str) -> Pt {
    (crate::common::q(x), crate::common::q(y))
}

fn sorted(mut v: Vec<Pt>) -> Vec<Pt> {
    v.sort();
    v
}

#[test]
fn hull_primitives_on_a_square_with_extra_points() {
    let q = crate::common::q;
    let sq = [pt("0", "0"), pt("2", "0"), pt("2", "2"), pt("0", "2")];
    let mut pts = sq.to_vec();
    pts.extend([pt("1", "1"), pt("1", "0"), pt("2", "2"), pt("1/2", "3/2")]);
    assert_eq!(sorted(extreme_points(&pts)), sorted(sq.to_vec()));
    assert_eq!(ccw_hull(&pts), sq.to_vec());
    assert_eq!(twice_area(&ccw_hull(&pts)), q("8"));
    assert!(in_hull(&pt("2", "1"), &sq) && in_hull(&pt("0", "0"), &sq));
    assert!(!in_hull(&pt("2", "3"), &sq) && !in_hull(&pt("-1/1000", "1"), &sq));
    assert!(full_dimensional(&pts));
    assert!(!full_dimensional(&[pt("0", "0"), pt("1", "1"), pt("3", "3"), pt("1", "1")]));
    let hp = supporting_half_planes(&pts);
    assert_eq!(hp.len(), 4, "{hp:?}");
    assert_eq!(sorted(polygon_vertices(&hp)), sorted(sq.to_vec()));
    let mut cons = hp.clone();
    cons.push(HalfPlane { a: q("-1"), b: q("-1"), c: q("1") });
    assert_eq!(sorted(polygon_vertices(&cons)), sorted(vec![pt("0", "0"), pt("1", "0"), pt("0", "1")]));
    let mut empty = hp;
    empty.push(HalfPlane { a: q("0"), b: q("0"), c: q("-1") });
    assert!(polygon_vertices(&empty).is_empty());
}

#[test]
fn collinear_and_tiny_sets() {
    let line = [pt("0", "0"), pt("3", "3"), pt("1", "1"), pt("3", "3")];
    assert_eq!(sorted(extreme_points(&line)), vec![pt("0", "0"), pt("3", "3")]);
    assert_eq!(extreme_points(&[pt("1", "2"), pt("1", "2")]), vec![pt("1", "2")]);
    assert!(extreme_points(&[]).is_empty());
    assert_eq!(orient2(&pt("0", "0"), &pt("1", "0"), &pt("0", "1")), crate::common::q("1"));
    assert!(on_segment(&pt("1/2", "1/2"), &pt("0", "0"), &pt("1", "1")));
    assert!(!on_segment(&pt("2", "2"), &pt("0", "0"), &pt("1", "1")));
}
