//! kappa of homogeneous bodies from their geometry, exactly: polygon plates and prisms from the
//! polygon's second moments, Platonic solids from a decomposition into tetrahedra.

use crate::exact::OrderedField;
use chatter_kernel::model::linalg::{Vec3, dot, sub};

/// Second moments of the unit-circumradius regular n-gon plate per unit area, from the polygon
/// formula  int x^2 dA = 1/12 sum (x_i y_{i+1} - x_{i+1} y_i)(x_i^2 + x_i x_{i+1} + x_{i+1}^2):
/// the cross terms all equal sin(2 pi/n) and cancel against the area (n/2) sin(2 pi/n), leaving
/// (1/(6n)) sum (x_i^2 + x_i x_{i+1} + x_{i+1}^2), and likewise for y. With x_k = cos(2 pi k/n),
/// y_k^2 = 1 - x_k^2 and y_k y_{k+1} = (c_1 - cos(2 pi (2k+1)/n))/2, both are exact in Q(c_1).
/// Returns (int x^2 dA / A, int y^2 dA / A).
pub fn plate_second_moments<F: OrderedField>(n: usize, c1: &F) -> (F, F) {
    // cos(2 pi m / n) = T_m(c1) for m = 0..2n.
    let mut t = vec![F::one(), c1.clone()];
    while t.len() < 2 * n + 2 {
        let m = t.len();
        t.push(F::from_i64(2).times(c1).times(&t[m - 1]).minus(&t[m - 2]));
    }
    let x = |k: usize| &t[k % n];
    let (mut sx, mut sy) = (F::zero(), F::zero());
    let half = F::from_ratio(1, 2);
    for k in 0..n {
        let (a, b) = (x(k), x(k + 1));
        sx = sx.plus(&a.times(a)).plus(&a.times(b)).plus(&b.times(b));
        let (ya2, yb2) = (F::one().minus(&a.times(a)), F::one().minus(&b.times(b)));
        let yab = half.times(&c1.minus(&t[(2 * k + 1) % n]));
        sy = sy.plus(&ya2).plus(&yab).plus(&yb2);
    }
    let norm = F::from_ratio(1, 6 * n as i64);
    (sx.times(&norm), sy.times(&norm))
}

/// kappa of a homogeneous prism over the regular n-gon (circumradius 1) of height h landing on
/// its base: the plate's rho^2 plus h^2/12 from the thickness (h = 0 is the flat plate).
pub fn prism_kappa<F: OrderedField>(n: usize, c1: &F, h: &F) -> Result<F, String> {
    let (mx, my) = plate_second_moments(n, c1);
    if mx != my {
        return Err("the plate's second moments are not isotropic".into());
    }
    Ok(mx.plus(&h.times(h).over(&F::from_i64(12)).expect("12 != 0")))
}

fn abs<F: OrderedField>(x: F) -> F {
    if x.is_negative() { x.negated() } else { x }
}

/// A convex polyhedron centred at the origin landing on one face: kappa = rho^2 / R^2 with rho
/// the radius of gyration about a horizontal axis through the centre of mass (the inertia must
/// be isotropic) and R the circumradius of the face. Faces are the vertex sets maximising d . v
/// for the outward face directions `faces` (the dual's vertices).
#[derive(Clone, Debug)]
pub struct SolidKappa<F> {
    /// Vertices of the landing face.
    pub face_vertices: usize,
    pub kappa: F,
    /// rho^2 = I / m.
    pub rho2: F,
    /// R^2 of the face.
    pub face_r2: F,
    /// Edge length squared.
    pub edge2: F,
    pub volume: F,
}

pub fn solid_kappa<F: OrderedField>(verts: &[Vec3<F>], faces: &[Vec3<F>]) -> Result<SolidKappa<F>, String> {
    let norm2 = |v: &Vec3<F>| dot(v, v);
    let mut edge2: Option<F> = None;
    for (i, a) in verts.iter().enumerate() {
        for b in &verts[i + 1..] {
            let d = norm2(&sub(a, b));
            if edge2.as_ref().is_none_or(|e| d < *e) {
                edge2 = Some(d);
            }
        }
    }
    let edge2 = edge2.ok_or("no vertices")?;
    let mut volume = F::zero();
    let mut m: [[F; 3]; 3] = std::array::from_fn(|_| std::array::from_fn(|_| F::zero()));
    let mut first_face = None;
    for d in faces {
        let top = verts.iter().map(|v| dot(d, v)).max().ok_or("no vertices")?;
        let face: Vec<&Vec3<F>> = verts.iter().filter(|v| dot(d, v) == top).collect();
        if face.len() < 3 {
            return Err("a face direction selects fewer than three vertices".into());
        }
        let inv = F::one().over(&F::from_i64(face.len() as i64)).expect("non-zero");
        let c: Vec3<F> =
            std::array::from_fn(|k| face.iter().fold(F::zero(), |acc, v| acc.plus(&v[k])).times(&inv));
        if first_face.is_none() {
            first_face = Some((face.len(), norm2(&sub(face[0], &c))));
        }
        // Tetrahedra (0, c, a, b) over the face's edges: int x x^T = V/20 (sum p p^T + s s^T).
        for (i, a) in face.iter().enumerate() {
            for b in &face[i + 1..] {
                if norm2(&sub(a, b)) != edge2 {
                    continue;
                }
                let det = dot(&chatter_kernel::model::linalg::cross(&c, a), b);
                let v = abs(det).over(&F::from_i64(6)).expect("6 != 0");
                volume = volume.plus(&v);
                let s: Vec3<F> = std::array::from_fn(|k| c[k].plus(&a[k]).plus(&b[k]));
                let w = v.over(&F::from_i64(20)).expect("20 != 0");
                for (r, row) in m.iter_mut().enumerate() {
                    for (col, e) in row.iter_mut().enumerate() {
                        let pp = c[r].times(&c[col]).plus(&a[r].times(&a[col])).plus(&b[r].times(&b[col]));
                        *e = e.plus(&w.times(&pp.plus(&s[r].times(&s[col]))));
                    }
                }
            }
        }
    }
    let isotropic =
        (0..3).all(|r| (0..3).all(|c| if r == c { m[r][c] == m[0][0] } else { m[r][c].is_zero() }));
    if !isotropic {
        return Err("the inertia tensor is not isotropic; kappa about horizontal axes is not unique".into());
    }
    let (face_vertices, face_r2) = first_face.ok_or("no faces")?;
    // rho^2 about any axis u: (tr M - u^T M u) / V = 2 mu / V for M = mu I.
    let rho2 = m[0][0].plus(&m[0][0]).over(&volume).ok_or("zero volume")?;
    let kappa = rho2.over(&face_r2).ok_or("degenerate face")?;
    Ok(SolidKappa { face_vertices, kappa, rho2, face_r2, edge2, volume })
}
