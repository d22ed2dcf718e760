//! Full inertia tensors (docs/model.md §11.1, "Bodies with products of inertia"): a symmetric
//! 3×3 tensor per unit mass about the centre of mass, read in URDF's order
//! `ixx, ixy, ixz, iyy, iyz, izz` (products with the tensor's minus sign, ixy = -∫ x y dm / m),
//! checked exactly, moved by the parallel-axis theorem, assembled from parts, and reduced to the
//! planar model's J_eff = J - b bᵀ / I_zz with b = (I_xz, I_yz) (the Schur complement of I_zz:
//! the inverse of the upper-left 2×2 block of I⁻¹).

use crate::exact::{Q, Ring};
use chatter_kernel::model::Mat2;

/// A point or vector in the body's frame (x, y horizontal, z up).
pub type Vec3 = [Q; 3];

/// A symmetric inertia tensor per unit mass (m² when lengths are in m).
#[derive(Clone, Debug, PartialEq)]
pub struct Tensor(pub [[Q; 3]; 3]);

/// Why six numbers are not the inertia tensor of a rigid body.
#[derive(Clone, Debug, PartialEq)]
pub enum TensorError {
    /// A leading principal minor is <= 0 (Sylvester's criterion): `minor` of order `order`.
    NotPositiveDefinite { order: usize, minor: Q },
    /// ½ tr(I) E - I (the second moments ∫ r rᵀ dm / m) has a negative principal minor: the
    /// principal moments violate a triangle inequality (no mass distribution has them).
    NotAMassDistribution { which: String, minor: Q },
    /// A mass <= 0.
    Mass(Q),
}

impl std::fmt::Display for TensorError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            TensorError::NotPositiveDefinite { order, minor } => write!(
                f,
                "the inertia tensor is not positive definite (its leading {order}x{order} minor is {minor} <= 0)"
            ),
            TensorError::NotAMassDistribution { which, minor } => write!(
                f,
                "no mass distribution has this inertia tensor: its principal moments violate a triangle \
                 inequality (the second-moment matrix tr(I)/2 E - I has the principal minor {which} = {minor} < 0)"
            ),
            TensorError::Mass(m) => write!(f, "the mass must be > 0 (found {m})"),
        }
    }
}

fn det2(a: &Q, b: &Q, c: &Q, d: &Q) -> Q {
    a * d - b * c
}

fn det3(m: &[[Q; 3]; 3]) -> Q {
    let minor = |r: usize, c: usize| {
        let (r1, r2) = ((r + 1) % 3, (r + 2) % 3);
        let (c1, c2) = ((c + 1) % 3, (c + 2) % 3);
        det2(&m[r1][c1], &m[r1][c2], &m[r2][c1], &m[r2][c2])
    };
    (0..3).fold(Q::int(0), |acc, c| acc + &m[0][c] * &minor(0, c))
}

impl Tensor {
    /// The tensor of URDF's six numbers `ixx, ixy, ixz, iyy, iyz, izz`.
    pub fn from_urdf(v: &[Q; 6]) -> Tensor {
        let [xx, xy, xz, yy, yz, zz] = v.clone();
        Tensor([[xx, xy.clone(), xz.clone()], [xy, yy, yz.clone()], [xz, yz, zz]])
    }

    /// URDF's six numbers `ixx, ixy, ixz, iyy, iyz, izz`.
    pub fn urdf(&self) -> [Q; 6] {
        let m = &self.0;
        [&m[0][0], &m[0][1], &m[0][2], &m[1][1], &m[1][2], &m[2][2]].map(Q::clone)
    }

    /// The tensor of a point of unit mass at `d` from the reference point: |d|² E - d dᵀ.
    pub fn point(d: &Vec3) -> Tensor {
        let r2 = d.iter().fold(Q::int(0), |acc, x| acc + x * x);
        Tensor(std::array::from_fn(|i| {
            std::array::from_fn(|j| if i == j { &r2 - &(&d[i] * &d[j]) } else { -(&d[i] * &d[j]) })
        }))
    }

    /// The diagonal tensor diag(a, b, c).
    pub fn diagonal(a: Q, b: Q, c: Q) -> Tensor {
        let z = Q::int(0);
        Tensor([[a, z.clone(), z.clone()], [z.clone(), b, z.clone()], [z.clone(), z, c]])
    }

    /// A uniform box a × b × c (sides along x, y, z) about its centre: diag(b² + c², a² + c², a² + b²)/12.
    pub fn uniform_box(a: &Q, b: &Q, c: &Q) -> Tensor {
        let t = Q::new(1, 12);
        let (a2, b2, c2) = (a * a, b * b, c * c);
        Tensor::diagonal((&b2 + &c2) * &t, (&a2 + &c2) * &t, (a2 + b2) * t)
    }

    /// A uniform solid cylinder of radius r and height h, axis vertical, about its centre:
    /// diag((3r² + h²)/12, (3r² + h²)/12, r²/2).
    pub fn cylinder(r: &Q, h: &Q) -> Tensor {
        let side = (Q::int(3) * r * r + h * h) / Q::int(12);
        Tensor::diagonal(side.clone(), side, r * r / Q::int(2))
    }

    /// A thin uniform vertical rod of length l about its centre: diag(l²/12, l²/12, 0).
    pub fn vertical_rod(l: &Q) -> Tensor {
        let side = l * l / Q::int(12);
        Tensor::diagonal(side.clone(), side, Q::int(0))
    }

    fn map2(&self, o: &Tensor, f: impl Fn(&Q, &Q) -> Q) -> Tensor {
        Tensor(std::array::from_fn(|i| std::array::from_fn(|j| f(&self.0[i][j], &o.0[i][j]))))
    }

    /// Entry-wise `self + o`.
    pub fn plus(&self, o: &Tensor) -> Tensor {
        self.map2(o, |a, b| a + b)
    }

    /// Entry-wise `s * self`.
    pub fn scaled(&self, s: &Q) -> Tensor {
        Tensor(self.0.clone().map(|row| row.map(|x| x * s)))
    }

    /// The parallel-axis theorem per unit mass: given about a point p, the tensor about the centre
    /// of mass c is I_p - (|d|² E - d dᵀ) with d = c - p.
    pub fn to_centre(&self, d: &Vec3) -> Tensor {
        self.map2(&Tensor::point(d), |a, b| a - b)
    }

    /// The horizontal 2×2 block J = [[I_xx, I_xy], [I_xy, I_yy]].
    pub fn horizontal(&self) -> Mat2<Q> {
        let m = &self.0;
        [[m[0][0].clone(), m[0][1].clone()], [m[1][0].clone(), m[1][1].clone()]]
    }

    /// The planar model's effective horizontal inertia J_eff = J - b bᵀ / I_zz, b = (I_xz, I_yz):
    /// the inverse of the upper-left 2×2 block of I⁻¹ (docs/model.md §11.1). `None` if I_zz = 0.
    pub fn effective(&self) -> Option<Mat2<Q>> {
        let m = &self.0;
        let izz = &m[2][2];
        if izz.is_zero() {
            return None;
        }
        let b = [&m[0][2], &m[1][2]];
        Some(std::array::from_fn(|i| std::array::from_fn(|j| &m[i][j] - &(b[i] * b[j] / izz))))
    }

    /// Checks that the tensor is that of a rigid body: positive definite (Sylvester's criterion,
    /// exact) and its second moments S = tr(I)/2 E - I positive semidefinite (every principal
    /// minor >= 0), which is the triangle inequalities of the principal moments.
    pub fn check(&self) -> Result<(), TensorError> {
        let m = &self.0;
        let leading = [m[0][0].clone(), det2(&m[0][0], &m[0][1], &m[1][0], &m[1][1]), det3(m)];
        if let Some((k, minor)) = leading.iter().enumerate().find(|(_, x)| !x.is_positive()) {
            return Err(TensorError::NotPositiveDefinite { order: k + 1, minor: minor.clone() });
        }
        let half_trace = (&m[0][0] + &m[1][1] + &m[2][2]) / Q::int(2);
        let s = Tensor::diagonal(half_trace.clone(), half_trace.clone(), half_trace).map2(self, |a, b| a - b);
        let s = &s.0;
        let axes = ["x", "y", "z"];
        let mut minors: Vec<(String, Q)> =
            (0..3).map(|i| (format!("S_{0}{0}", axes[i]), s[i][i].clone())).collect();
        for (i, j) in [(0, 1), (0, 2), (1, 2)] {
            let d = det2(&s[i][i], &s[i][j], &s[j][i], &s[j][j]);
            minors.push((format!("det S[{}{}]", axes[i], axes[j]), d));
        }
        minors.push(("det S".into(), det3(s)));
        match minors.into_iter().find(|(_, x)| x.is_negative()) {
            Some((which, minor)) => Err(TensorError::NotAMassDistribution { which, minor }),
            None => Ok(()),
        }
    }
}

/// A part of a body: its mass, its centre of mass, and its own inertia tensor per unit mass about
/// that centre.
#[derive(Clone, Debug)]
pub struct Part {
    pub mass: Q,
    pub at: Vec3,
    pub own: Tensor,
}

impl Part {
    /// A point mass.
    pub fn point(mass: Q, at: Vec3) -> Part {
        let z = Q::int(0);
        Part { mass, at, own: Tensor::diagonal(z.clone(), z.clone(), z) }
    }
}

/// A body assembled from parts: its mass, its centre of mass, and its inertia tensor per unit
/// mass about that centre (Σ m_i (own_i + |d_i|² E - d_i d_iᵀ) / Σ m_i, d_i = at_i - centre).
#[derive(Clone, Debug, PartialEq)]
pub struct Assembly {
    pub mass: Q,
    pub centre: Vec3,
    pub tensor: Tensor,
}

/// Assembles `parts` (every mass > 0).
pub fn assemble(parts: &[Part]) -> Result<Assembly, TensorError> {
    if let Some(p) = parts.iter().find(|p| !p.mass.is_positive()) {
        return Err(TensorError::Mass(p.mass.clone()));
    }
    let mass = parts.iter().fold(Q::int(0), |acc, p| acc + &p.mass);
    if !mass.is_positive() {
        return Err(TensorError::Mass(mass));
    }
    let centre: Vec3 =
        std::array::from_fn(|k| parts.iter().fold(Q::int(0), |acc, p| acc + &p.mass * &p.at[k]) / &mass);
    let zero = Tensor::diagonal(Q::int(0), Q::int(0), Q::int(0));
    let total = parts.iter().fold(zero, |acc, p| {
        let d: Vec3 = std::array::from_fn(|k| &p.at[k] - &centre[k]);
        acc.plus(&p.own.plus(&Tensor::point(&d)).scaled(&p.mass))
    });
    let tensor = total.scaled(&(Q::int(1) / &mass));
    Ok(Assembly { mass, centre, tensor })
}
