//! What the producer needs of a body, for a regular polygon (nodes in the frame of the last
//! contact, relabelled as 0: docs/time-to-rest.md §5) and for a general convex body (nodes
//! labelled by the contact of the last impact, no relabelling: "General bodies" there), exactly
//! ([`Frames`]) and rounded to `f64` ([`FloatFrames`]). A node's *label* is 0 for every node of
//! a regular polygon and the last contact i for a general body. Untrusted.

use super::Num;
use crate::exact::Q;
use crate::model::float::FloatPolygon;
use chatter_kernel::exact::{OrderedField as _, Ring as _};
use chatter_kernel::model::linalg::{Mat3, Vec3};
use chatter_kernel::model::{ConvexBody, Polygon};
use nalgebra::{Matrix3, Vector3};

/// The exact maps of one body.
pub trait Frames {
    /// The scalar.
    type E: Num;
    /// Number of contacts.
    fn n(&self) -> usize;
    /// The labels of the entry nodes, one per contact a first impact can be at in the file's
    /// frame: [0] for a regular polygon, 0..n for a general body.
    fn entries(&self) -> Vec<usize>;
    /// The steps from a node of label `at`: (j, the successor's label).
    fn steps(&self, at: usize) -> Vec<(usize, usize)>;
    /// The covectors of C_j (regular) or C_{at,j} (general).
    fn next_cone(&self, at: usize, j: usize) -> [Vec3<Self::E>; 4];
    /// The velocity map of step j: S_j = I_0 R_j, or I_j.
    fn step(&self, j: usize) -> Mat3<Self::E>;
    /// The configuration map of step j: R_j, or `None` (the identity).
    fn relabel(&self, j: usize) -> Option<Mat3<Self::E>>;
    /// m_{k,k+1} (k mod n).
    fn rest(&self, k: i64) -> Vec3<Self::E>;
    /// I_i, the map of a first impact at contact i.
    fn impact(&self, i: usize) -> Mat3<Self::E>;
    /// The generators -m_{k,k+1} of D.
    fn all_down(&self) -> Vec<Vec3<Self::E>>;
    /// The kick direction of step j (b_s·S_j p = b_r·p - β u_j(p) (b_r·kick) on a tie).
    fn kick(&self, j: usize) -> Vec3<Self::E>;
    /// The step of the edge back along a tie from a node of label `at` reached by step j:
    /// n - j, or, for a general body, the label `at` of the node left where the contacts `at`
    /// and j are adjacent (only there do the two edges share the vertex −m_{at,j}, where (G3)
    /// asks for equality); `None`: no tie.
    fn back(&self, at: usize, j: usize) -> Option<usize>;
    /// The rest points after an impact at the label's contact: m_{at,at+1}, m_{at-1,at}.
    fn heights(&self, at: usize) -> [Vec3<Self::E>; 2] {
        [self.rest(at as i64), self.rest(at as i64 - 1)]
    }
    /// The rest points of the configurations where contact j lands: m_{j-1,j}, m_{j,j+1}.
    fn landing(&self, j: usize) -> [Vec3<Self::E>; 2] {
        [self.rest(j as i64 - 1), self.rest(j as i64)]
    }
}

impl<E: Num> Frames for Polygon<E> {
    type E = E;
    fn n(&self) -> usize {
        Polygon::n(self)
    }
    fn entries(&self) -> Vec<usize> {
        vec![0]
    }
    fn steps(&self, _: usize) -> Vec<(usize, usize)> {
        (1..Polygon::n(self)).map(|j| (j, 0)).collect()
    }
    fn next_cone(&self, _: usize, j: usize) -> [Vec3<E>; 4] {
        self.next_contact_cone(j as i64)
    }
    fn step(&self, j: usize) -> Mat3<E> {
        Polygon::step(self, j as i64)
    }
    fn relabel(&self, j: usize) -> Option<Mat3<E>> {
        Some(Polygon::relabel(self, j as i64))
    }
    fn rest(&self, k: i64) -> Vec3<E> {
        self.rest_point(k, k + 1).unwrap_or_else(|| [E::zero(), E::zero(), E::zero()])
    }
    fn impact(&self, i: usize) -> Mat3<E> {
        Polygon::impact(self, i as i64)
    }
    fn all_down(&self) -> Vec<Vec3<E>> {
        self.all_down_generators()
    }
    fn kick(&self, j: usize) -> Vec3<E> {
        self.impact_direction(j as i64)
    }
    fn back(&self, _: usize, j: usize) -> Option<usize> {
        Some(Polygon::n(self) - j)
    }
}

impl Frames for ConvexBody<Q> {
    type E = Q;
    fn n(&self) -> usize {
        ConvexBody::n(self)
    }
    fn entries(&self) -> Vec<usize> {
        (0..ConvexBody::n(self)).collect()
    }
    fn steps(&self, at: usize) -> Vec<(usize, usize)> {
        (0..ConvexBody::n(self)).filter(|&j| j != at).map(|j| (j, j)).collect()
    }
    fn next_cone(&self, at: usize, j: usize) -> [Vec3<Q>; 4] {
        let zero = || [Q::int(0), Q::int(0), Q::int(0)];
        self.next_contact_cone(at as i64, j as i64).unwrap_or_else(|| std::array::from_fn(|_| zero()))
    }
    fn step(&self, j: usize) -> Mat3<Q> {
        ConvexBody::impact(self, j as i64)
    }
    fn relabel(&self, _: usize) -> Option<Mat3<Q>> {
        None
    }
    fn rest(&self, k: i64) -> Vec3<Q> {
        self.edge_rest_point(k).clone()
    }
    fn impact(&self, i: usize) -> Mat3<Q> {
        ConvexBody::impact(self, i as i64)
    }
    fn all_down(&self) -> Vec<Vec3<Q>> {
        self.all_down_generators()
    }
    fn kick(&self, j: usize) -> Vec3<Q> {
        self.impact_direction(j as i64).clone()
    }
    fn back(&self, at: usize, j: usize) -> Option<usize> {
        let n = ConvexBody::n(self);
        ((j + n - at) % n == 1 || (at + n - j) % n == 1).then_some(at)
    }
}

/// The inverse of a relabelling (`None`: the identity), exactly, by the adjugate.
pub fn relabel_inverse<B: Frames>(body: &B, j: usize) -> Result<Option<Mat3<B::E>>, String> {
    let Some(m) = body.relabel(j) else { return Ok(None) };
    let c = |i: usize, j: usize| {
        let (a, b) = ([(i + 1) % 3, (i + 2) % 3], [(j + 1) % 3, (j + 2) % 3]);
        m[a[0]][b[0]].times(&m[a[1]][b[1]]).minus(&m[a[0]][b[1]].times(&m[a[1]][b[0]]))
    };
    let det = (0..3).fold(B::E::zero(), |s, j| s.plus(&m[0][j].times(&c(0, j))));
    if det.is_zero() {
        return Err("a relabelling is singular".into());
    }
    let entry = |i: usize, j: usize| c(j, i).over(&det).unwrap_or_else(B::E::zero);
    Ok(Some(std::array::from_fn(|i| std::array::from_fn(|j| entry(i, j)))))
}

/// M x, or x where M is the identity (`None`).
pub fn apply<E: Num>(m: Option<&Mat3<E>>, x: &Vec3<E>) -> Vec3<E> {
    m.map_or_else(|| x.clone(), |m| chatter_kernel::model::linalg::mat_vec(m, x))
}

/// A step from a label: (j, the successor's label, the covectors of C).
pub type Step = (usize, usize, [Vector3<f64>; 4]);

/// The same maps, rounded to `f64` (the float graph and covector search).
pub struct FloatFrames {
    n: usize,
    entries: Vec<usize>,
    /// Per label: (j, successor label, C's covectors).
    steps: Vec<Vec<Step>>,
    step: Vec<Matrix3<f64>>,
    relabel: Vec<Matrix3<f64>>,
    inverse: Vec<Matrix3<f64>>,
    rest: Vec<Vector3<f64>>,
    impact: Vec<Matrix3<f64>>,
    all_down: Vec<Vector3<f64>>,
    kick: Vec<Vector3<f64>>,
    back: Vec<Vec<Option<usize>>>,
}

fn vf<E: Num>(v: &Vec3<E>) -> Vector3<f64> {
    Vector3::new(v[0].f64(), v[1].f64(), v[2].f64())
}

fn mf<E: Num>(m: &Mat3<E>) -> Matrix3<f64> {
    Matrix3::from_fn(|r, c| m[r][c].f64())
}

impl FloatFrames {
    /// The rounded maps of `body`.
    pub fn of<B: Frames>(body: &B) -> FloatFrames {
        let n = body.n();
        let labels = body.entries().len();
        let steps = (0..labels)
            .map(|at| {
                body.steps(at)
                    .into_iter()
                    .map(|(j, s)| (j, s, body.next_cone(at, j).map(|l| vf(&l))))
                    .collect()
            })
            .collect();
        let relabel = |j: usize| body.relabel(j).map_or_else(Matrix3::identity, |m| mf(&m));
        let inverse = |j: usize| relabel(j).try_inverse().unwrap_or_else(Matrix3::zeros);
        FloatFrames {
            n,
            entries: body.entries(),
            steps,
            step: (0..n).map(|j| mf(&body.step(j))).collect(),
            relabel: (0..n).map(relabel).collect(),
            inverse: (0..n).map(inverse).collect(),
            rest: (0..n as i64).map(|k| vf(&body.rest(k))).collect(),
            impact: body.entries().into_iter().map(|i| mf(&body.impact(i))).collect(),
            all_down: body.all_down().iter().map(vf).collect(),
            kick: (0..n).map(|j| vf(&body.kick(j))).collect(),
            back: (0..labels).map(|at| (0..n).map(|j| body.back(at, j)).collect()).collect(),
        }
    }

    /// The maps of a regular polygon computed in `f64` from (n, κ, γ) ([`FloatPolygon`]): the
    /// float search of regular polygons as it was before general bodies (its graphs depend on
    /// the last bits of the maps).
    pub fn regular(body: &FloatPolygon) -> FloatFrames {
        let n = body.n();
        let cones = |j: usize| body.next_contact_cone(j as i64);
        let inverse = |j: usize| body.relabel(j as i64).try_inverse().unwrap_or_else(Matrix3::zeros);
        FloatFrames {
            n,
            entries: vec![0],
            steps: vec![(1..n).map(|j| (j, 0, cones(j))).collect()],
            step: (0..n).map(|j| body.step(j as i64)).collect(),
            relabel: (0..n).map(|j| body.relabel(j as i64)).collect(),
            inverse: (0..n).map(inverse).collect(),
            rest: (0..n as i64).map(|k| body.rest_point(k, k + 1).unwrap_or_else(Vector3::zeros)).collect(),
            impact: vec![body.impact(0)],
            all_down: body.all_down_generators(),
            kick: (0..n).map(|j| body.impact_direction(j as i64)).collect(),
            back: vec![(0..n).map(|j| Some(n - j)).collect()],
        }
    }

    pub fn entries(&self) -> &[usize] {
        &self.entries
    }
    /// The steps from label `at`: (j, successor label, C's covectors).
    pub fn steps(&self, at: usize) -> &[Step] {
        &self.steps[at]
    }
    pub fn step(&self, j: usize) -> &Matrix3<f64> {
        &self.step[j]
    }
    pub fn relabel(&self, j: usize) -> &Matrix3<f64> {
        &self.relabel[j]
    }
    /// The inverse of the relabelling (the identity for a general body).
    pub fn inverse(&self, j: usize) -> &Matrix3<f64> {
        &self.inverse[j]
    }
    pub fn rest(&self, k: i64) -> Vector3<f64> {
        self.rest[k.rem_euclid(self.n as i64) as usize]
    }
    /// I_i of the entry of label `e` (an index into [`Self::entries`]).
    pub fn impact(&self, e: usize) -> &Matrix3<f64> {
        &self.impact[e]
    }
    pub fn all_down(&self) -> &[Vector3<f64>] {
        &self.all_down
    }
    pub fn kick(&self, j: usize) -> Vector3<f64> {
        self.kick[j]
    }
    pub fn back(&self, at: usize, j: usize) -> Option<usize> {
        self.back[at][j]
    }
    /// m_{at,at+1}, m_{at-1,at}.
    pub fn heights(&self, at: usize) -> [Vector3<f64>; 2] {
        [self.rest(at as i64), self.rest(at as i64 - 1)]
    }
}
