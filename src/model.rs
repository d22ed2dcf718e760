//! Untrusted helpers around the exact model of [`chatter_kernel::model`]: the body built from
//! user numbers, kinetic energy, the paper's coordinates, and `f64` copies of the maps for the
//! numerical search; [`float`]: the float model of a regular n-gon for every n.

pub mod affine;
pub mod float;

use crate::exact::{OrderedField, Q};
use chatter_kernel::model::Polygon as Body;
use chatter_kernel::model::linalg::{Mat3, Vec3, neg, sub};
use nalgebra::{Matrix3, Vector3};

/// sin^2(2 pi / n) = 1 - c_1^2, rational whenever c_1 is.
fn sin2<F: OrderedField>(b: &Body<F>) -> F {
    F::one().minus(&b.cos(1).times(b.cos(1)))
}

/// Kinetic energy T = kappa |omega|^2 / 2 + v^2 / 2 (mass 1, R = 1) of p = (u0, u1, v), exact.
/// With s = sin(2 pi/n), c = cos(2 pi/n): omega_y = v - u0, omega_x = (u1 - v + c omega_y) / s.
pub fn kinetic_energy<F: OrderedField>(b: &Body<F>, p: &Vec3<F>) -> F {
    let wy = p[2].minus(&p[0]);
    let sx = p[1].minus(&p[2]).plus(&b.cos(1).times(&wy)); // s * omega_x
    let wx2 = sx.times(&sx).over(&sin2(b)).expect("sin(2 pi/n) != 0 for n >= 3");
    let half = F::from_ratio(1, 2);
    half.times(&b.kappa().times(&wx2.plus(&wy.times(&wy))).plus(&p[2].times(&p[2])))
}

/// For the square (n = 4): the matrix M with p_contact = M p_paper, p_paper = (omega_x, omega_y, v).
/// Rows are the paper's f_0 = (y_0, -x_0, 1) = (0, -1, 1), f_1 = (1, 0, 1) and (0, 0, 1).
pub fn square_paper_to_contact<F: OrderedField>() -> Mat3<F> {
    let (z, o) = (F::zero(), F::one());
    [[z.clone(), o.negated(), o.clone()], [o.clone(), z.clone(), o.clone()], [z.clone(), z, o]]
}

/// `f64` copy of an exact matrix.
pub fn mat_f64<E: OrderedField>(m: &Mat3<E>) -> Matrix3<f64> {
    Matrix3::from_fn(|r, c| m[r][c].nearest_f64())
}

/// `f64` copy of an exact vector.
pub fn vec_f64<E: OrderedField>(v: &Vec3<E>) -> Vector3<f64> {
    Vector3::new(v[0].nearest_f64(), v[1].nearest_f64(), v[2].nearest_f64())
}

/// The maps and cones of a body in `f64`, for the untrusted search.
#[derive(Clone, Debug)]
pub struct FloatBody {
    pub n: usize,
    /// steps[j - 1] = S_j, j = 1..n-1.
    pub steps: Vec<Matrix3<f64>>,
    /// cones[j - 1] = the four covectors of C_j.
    pub cones: Vec<[Vector3<f64>; 4]>,
    pub impact0: Matrix3<f64>,
    pub all_down: Vec<Vector3<f64>>,
    /// For a box of parameters: I_0 at the other corners (seeds are taken at every corner).
    pub more_impacts: Vec<Matrix3<f64>>,
}

impl FloatBody {
    pub fn new<E: OrderedField>(b: &Body<E>) -> Self {
        let js = 1..b.n() as i64;
        FloatBody {
            n: b.n(),
            steps: js.clone().map(|j| mat_f64(&b.step(j))).collect(),
            cones: js.map(|j| b.next_contact_cone(j).map(|l| vec_f64(&l))).collect(),
            impact0: mat_f64(&b.impact(0)),
            all_down: b.all_down_generators().iter().map(vec_f64).collect(),
            more_impacts: Vec::new(),
        }
    }

    /// The maps of the float model (any n from 3 to 64; issue 10 §1), so that the finder runs
    /// where cos 2π/n is irrational.
    pub fn from_float(b: &float::FloatPolygon) -> Self {
        let js = 1..b.n() as i64;
        FloatBody {
            n: b.n(),
            steps: js.clone().map(|j| b.step(j)).collect(),
            cones: js.map(|j| b.next_contact_cone(j)).collect(),
            impact0: b.impact(0),
            all_down: b.all_down_generators(),
            more_impacts: Vec::new(),
        }
    }

    /// The maps of several bodies with the same n (the corners of a box of parameters) as one:
    /// a cone is invariant under all of them iff it is for every point of the box
    /// (docs/kernel-soundness.md §2, "Boxes"). Steps are listed corner by corner.
    pub fn corners<E: OrderedField>(bodies: &[Body<E>]) -> Self {
        let mut all = FloatBody::new(&bodies[0]);
        for b in &bodies[1..] {
            let f = FloatBody::new(b);
            all.steps.extend(f.steps);
            all.cones.extend(f.cones);
            all.more_impacts.push(f.impact0);
        }
        all
    }
}

/// Pure downward translation (every contact and the centre of mass at velocity -1).
pub fn translation_down() -> Vec3<Q> {
    [Q::int(-1), Q::int(-1), Q::int(-1)]
}

/// The four generators of C_j from the paper's Lemma on C_j: m_{j-1,j} - m_{n-1,0}, -m_{n-1,0},
/// -m_{0,1}, m_{j,j+1} - m_{0,1} (used to test the kernel's inequalities for C_j).
pub fn next_contact_generators<F: OrderedField>(b: &Body<F>, j: i64) -> [Vec3<F>; 4] {
    let m = |k: i64| b.rest_point(k, k + 1).expect("adjacent contacts are never opposite");
    let (m01, m_last) = (m(0), m(-1));
    [sub(&m(j - 1), &m_last), neg(&m_last), neg(&m01), sub(&m(j), &m01)]
}
