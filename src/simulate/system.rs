//! The falling body as the simulator sees it (docs/model.md §2-3, §7): contact covectors f_k with
//! u_k = f_k·p and h_k = f_k·q, impact kicks with p+ = p - u_k kick_k, the centre-of-mass
//! covector, the kinetic energy, and the paper's coordinates for the PCC criterion.
//!
//! Vectors always have three components. The planar rod (n = 2) lives in the first two,
//! p = (u0, u1) and q = (h0, h1); its third component is 0 in every covector and kick, so it
//! stays exactly 0 in both arithmetics and the rod never stores the redundant v = (u0 + u1)/2.

pub use super::frame::{Frame, TABLE_CONTACTS, frame_index};
use super::scalar::{Nf, SimField};
use crate::exact::{CosField, Q, QExt, QField};
use crate::model::float::FloatPolygon;
use chatter_kernel::exact::OrderedField;
use chatter_kernel::model::linalg::{Vec3, dot};
use chatter_kernel::model::{BodyError, Polygon, Rod, Shape as Body};

/// Which body falls: a tag of the kernel's [`Body`] (`chatter_kernel::model::Shape`), which is
/// the one place where the number of contacts decides between the rod and a polygon.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    /// The planar rod of docs/model.md §7: two contacts, coordinates (u0, u1).
    Rod,
    /// A flat regular n-gon: exact over Q for n in {3, 4, 6} (rational cosines), over
    /// Q(cos 2π/n) and the float model of [`crate::model::float`] for every n up to
    /// [`MAX_CONTACTS`].
    Polygon(u64),
    /// A general convex body with n contacts (docs/model.md §11, [`super::convex`]): exact over
    /// its field, coordinates already the paper's q = (φx, φy, h), p = (ωx, ωy, v).
    Convex(u64),
}

impl<F: OrderedField> From<&Body<F>> for Shape {
    fn from(body: &Body<F>) -> Shape {
        match body {
            Body::Rod(_) => Shape::Rod,
            Body::Polygon(polygon) => Shape::Polygon(polygon.n() as u64),
        }
    }
}

impl Shape {
    /// Number of contacts.
    pub fn n(self) -> usize {
        match self {
            Shape::Rod => 2,
            Shape::Polygon(n) | Shape::Convex(n) => n as usize,
        }
    }

    /// Number of generalised coordinates (3 for polygons and general bodies, 2 for the rod).
    pub fn dim(self) -> usize {
        match self {
            Shape::Rod => 2,
            Shape::Polygon(_) | Shape::Convex(_) => 3,
        }
    }

    /// Whether states are in the paper's coordinates already (general bodies, docs/model.md §11).
    pub fn is_convex(self) -> bool {
        matches!(self, Shape::Convex(_))
    }

    /// Names of the generalised coordinates (positions, then velocities).
    pub fn coordinate_names(self) -> (&'static [&'static str], &'static [&'static str]) {
        match self {
            Shape::Rod => (&["h0", "h1"], &["u0", "u1"]),
            Shape::Polygon(_) => (&["h0", "h1", "hc"], &["u0", "u1", "v"]),
            Shape::Convex(_) => (&["phix", "phiy", "h"], &["wx", "wy", "v"]),
        }
    }
}

/// Largest number of contacts of a simulated body (the float model's limit, issue 10 §1).
pub const MAX_CONTACTS: usize = crate::model::float::MAX_FLOAT_CONTACTS as usize;

/// The exact model of a falling body, over the rationals (the rod, n = 3, 4, 6) or over
/// Q(cos 2π/n) ([`System::in_field`], issue 10 §1).
#[derive(Clone, Debug)]
pub struct System<F = Q> {
    pub shape: Shape,
    pub kappa: F,
    pub gamma: F,
    /// f_k, k = 0..n-1: u_k = f_k·p, h_k = f_k·q.
    pub contacts: Vec<Vec3<F>>,
    /// kick_k = beta d_k (docs/model.md §3): an impact at k maps p to p - u_k kick_k.
    pub kicks: Vec<Vec3<F>>,
    /// c with v = c·p (centre-of-mass velocity) and hc = c·q.
    pub centre: Vec3<F>,
    /// Kinetic energy as the quadratic form T(p) = pᵀ G p / 2 (exact).
    pub gram: [[F; 3]; 3],
    /// For polygons, m_{i,i+1} (i = 0..n-1) in our coordinates (docs/model.md §4); empty for the rod.
    pub rest_points: Vec<Vec3<F>>,
    /// E = f_1·kick_0 = (1+γ)(κ + cos 2π/n)/(1+κ): how an impact at one contact changes the
    /// normal velocity of its neighbour, per unit of its own (polygons; 0 for the rod).
    pub pair_coupling: F,
    /// General bodies (docs/model.md §11.6, [`super::convex`]): whether some adjacent pair can
    /// chatter on its own; `None` for the rod and regular polygons (decided by `pair_coupling`).
    pub pair_pcc: Option<bool>,
}

fn z() -> Q {
    Q::int(0)
}

impl System<Nf> {
    /// The exact model of the regular n-gon in Q(cos 2π/n), 3 ≤ n ≤ 64 (every n, also those
    /// with a rational cosine), with rational κ and γ validated by the kernel.
    pub fn in_field(n: u64, kappa: &Q, gamma: &Q) -> Result<System<Nf>, BodyError> {
        let field = CosField::<Q>::new(n).ok_or(BodyError::UnsupportedN(n))?;
        let c1 = field.generator();
        let body = Polygon::with_cosine(n, c1, Nf::from_q(kappa), Nf::from_q(gamma))?;
        Ok(System::polygon(&body))
    }
}

impl System {
    /// Builds the model of `shape` with the given kappa and gamma (validated by the kernel).
    /// [`Shape::Convex`] is the regular n-gon given as a general body (docs/model.md §11, J = κ I),
    /// rational only for n = 4; other general bodies come from [`System::convex`].
    pub fn new(shape: Shape, kappa: Q, gamma: Q) -> Result<System, BodyError> {
        let body = match shape {
            Shape::Rod => Body::Rod(Rod::new(kappa, gamma)?),
            Shape::Polygon(n) => Body::Polygon(Polygon::new(n, kappa, gamma)?),
            Shape::Convex(n) => {
                return super::convex::regular_rational(n, kappa, gamma).map(|b| System::convex(&b));
            }
        };
        Ok(System::from_body(&body))
    }

    /// The model of a kernel body; its [`Shape`] is the body's tag.
    pub fn from_body(body: &Body<Q>) -> System {
        match body {
            Body::Rod(rod) => System::rod(rod),
            Body::Polygon(polygon) => System::polygon(polygon),
        }
    }

    /// The rod (docs/model.md §7) in the first two coordinates.
    fn rod(rod: &Rod<Q>) -> System {
        let (kappa, gamma) = (rod.kappa().clone(), rod.gamma().clone());
        let one = Q::int(1);
        let g1 = &one + &gamma;
        let cross = &g1 * &rod.coupling();
        let contacts = vec![[one.clone(), z(), z()], [z(), one.clone(), z()]];
        let kicks = vec![[g1.clone(), cross.clone(), z()], [cross, g1, z()]];
        let half = Q::new(1, 2);
        let centre = [half.clone(), half, z()];
        let energy = |p: &Vec3<Q>| {
            // T = (v^2 + kappa omega^2)/2, v = (u0 + u1)/2, omega = (u1 - u0)/2 (R = 1).
            let v = (&p[0] + &p[1]) * Q::new(1, 2);
            let w = (&p[1] - &p[0]) * Q::new(1, 2);
            (&v * &v + &kappa * &(&w * &w)) * Q::new(1, 2)
        };
        let gram = gram_of(&energy);
        let (rest_points, pair_coupling) = (vec![], z());
        let shape = Shape::Rod;
        System {
            shape,
            kappa,
            gamma,
            contacts,
            kicks,
            centre,
            gram,
            rest_points,
            pair_coupling,
            pair_pcc: None,
        }
    }

    /// The frame with the contacts `slots`: the matrix A = [f_s0; f_s1; f_s2] taking our
    /// coordinates to (h_s0, h_s1, h_s2). Three distinct vertices of a convex polygon are never
    /// collinear, so A is invertible. The rod has one frame, the identity.
    pub fn frame_matrix(&self, slots: [usize; 3]) -> [[Q; 3]; 3] {
        match self.shape {
            Shape::Rod => std::array::from_fn(|r| std::array::from_fn(|c| Q::int(i64::from(r == c)))),
            Shape::Polygon(_) | Shape::Convex(_) => slots.map(|k| self.contacts[k].clone()),
        }
    }
}

impl<F: SimField> System<F> {
    /// A regular polygon (docs/model.md §2-4) from the kernel's covectors, impact directions and
    /// rest points, in the kernel body's field.
    fn polygon(body: &Polygon<F>) -> System<F> {
        let n = body.n() as i64;
        let beta = body.beta();
        let contacts: Vec<Vec3<F>> = (0..n).map(|k| body.contact(k).clone()).collect();
        let kicks: Vec<Vec3<F>> = (0..n).map(|k| body.impact_direction(k).map(|d| beta.times(&d))).collect();
        let centre = [F::zero(), F::zero(), F::one()];
        let gram = gram_of(&|p: &Vec3<F>| crate::model::kinetic_energy(body, p));
        let rest_points = (0..n)
            .map(|i| body.rest_point(i, i + 1).expect("adjacent contacts are never opposite"))
            .collect();
        let pair_coupling = dot(&contacts[1], &kicks[0]);
        let (kappa, gamma) = (body.kappa().clone(), body.gamma().clone());
        let shape = Shape::Polygon(n as u64);
        System {
            shape,
            kappa,
            gamma,
            contacts,
            kicks,
            centre,
            gram,
            rest_points,
            pair_coupling,
            pair_pcc: None,
        }
    }

    /// Number of contacts.
    pub fn n(&self) -> usize {
        self.contacts.len()
    }

    /// Kinetic energy T = pᵀ G p / 2 (docs/model.md §2; the rod: (v² + κω²)/2).
    pub fn energy(&self, p: &Vec3<F>) -> F {
        let mut t = F::zero();
        for (r, row) in self.gram.iter().enumerate() {
            for (c, g) in row.iter().enumerate() {
                if !g.is_exactly_zero() {
                    t = t.plus(&g.times(&p[r].times(&p[c])));
                }
            }
        }
        t.times(&F::from_ratio(1, 2))
    }

    /// Height h_k = f_k·q (or normal velocity u_k = f_k·p) of contact k.
    pub fn along(&self, k: usize, x: &Vec3<F>) -> F {
        dot(&self.contacts[k], x)
    }

    /// The paper's Lemma on PCC: two neighbours can chatter on their own only if an impact at one
    /// pulls the other down (E < 0) and the pair's step map, with characteristic polynomial
    /// t² + E t + γ, has real eigenvalues (E² - 4γ ≥ 0). Its discriminant has the sign of the one
    /// of the quadratic factor of S_(n-1) S_1 (whose roots are the squares of these). False for
    /// the rod.
    pub fn pcc_possible(&self) -> bool {
        if let Some(possible) = self.pair_pcc {
            return possible;
        }
        let e = &self.pair_coupling;
        let disc = e.times(e).minus(&F::from_i64(4).times(&self.gamma));
        self.is_polygon() && e.is_negative() && !disc.is_negative()
    }

    /// Whether contacts a and b are neighbours on the polygon (never for the rod).
    pub fn adjacent(&self, a: usize, b: usize) -> bool {
        let n = self.n();
        self.is_polygon() && a != b && ((a + 1) % n == b || (b + 1) % n == a)
    }

    /// Whether the body is a polygon (contacts have neighbours), not the rod.
    pub fn is_polygon(&self) -> bool {
        matches!(self.shape, Shape::Polygon(_) | Shape::Convex(_))
    }
}

/// The symmetric matrix G with T(p) = pᵀ G p / 2, by polarisation of an exact quadratic form.
fn gram_of<F: OrderedField>(energy: &dyn Fn(&Vec3<F>) -> F) -> [[F; 3]; 3] {
    let e = |i: usize| -> Vec3<F> { std::array::from_fn(|k| F::from_i64(i64::from(k == i))) };
    std::array::from_fn(|r| {
        std::array::from_fn(|c| {
            if r == c {
                energy(&e(r)).times(&F::from_i64(2))
            } else {
                let s: Vec3<F> = std::array::from_fn(|k| F::from_i64(i64::from(k == r || k == c)));
                energy(&s).minus(&energy(&e(r))).minus(&energy(&e(c)))
            }
        })
    })
}

/// The `f64` copy of a body, laid out for the hot loop: of a [`System`] (rounded exact values),
/// or of the float model [`FloatPolygon`] where cos 2π/n is irrational.
#[derive(Clone, Debug)]
pub struct FloatSystem {
    pub shape: Shape,
    pub n: usize,
    pub f: Vec<[f64; 3]>,
    pub kick: Vec<[f64; 3]>,
    pub centre: [f64; 3],
    pub gram: [[f64; 3]; 3],
    pub gamma: f64,
    /// Unit vectors along m_{i,i+1} in the paper's coordinates (polygons only).
    pub rest_paper: Vec<[f64; 3]>,
    /// cos and sin of 2π/n (polygons; the change to the paper's coordinates, docs/model.md §2).
    pub cos1: f64,
    pub sin1: f64,
    /// [`System::pcc_possible`] (decided exactly, also for the float model).
    pub pcc_possible: bool,
    /// The length scale of the random drop (docs/model.md §11.10): 1 for the rod and regular
    /// polygons (circumradius 1), the power of two nearest to the largest contact distance for
    /// general bodies ([`super::convex::drop_scale`]).
    pub drop_scale: f64,
    /// Bit b of `adjacent[a]`: contacts a and b are neighbours on the polygon (none for the rod).
    pub adjacent: Vec<u64>,
    /// The frames of the `f64` engine, indexed by [`frame_index`], when n ≤ [`TABLE_CONTACTS`]
    /// (one frame for the rod); empty for larger n, whose engine computes its frame on a change.
    pub frames: Vec<Frame>,
}

impl FloatSystem {
    /// The rounded copy of an exact system; the frames are computed exactly, then rounded.
    pub fn new(sys: &System) -> FloatSystem {
        let v3 = |v: &Vec3<Q>| v.clone().map(|x| x.to_f64());
        let (cos1, sin1) = match sys.shape {
            Shape::Rod => (-1.0, 0.0),
            Shape::Convex(_) => (1.0, 0.0),
            Shape::Polygon(n) => {
                let th = 2.0 * std::f64::consts::PI / n as f64;
                (th.cos(), th.sin())
            }
        };
        let mut fs = FloatSystem {
            shape: sys.shape,
            n: sys.n(),
            f: sys.contacts.iter().map(v3).collect(),
            kick: sys.kicks.iter().map(v3).collect(),
            centre: v3(&sys.centre),
            gram: sys.gram.clone().map(|r| r.map(|x| x.to_f64())),
            gamma: sys.gamma.to_f64(),
            rest_paper: Vec::new(),
            cos1,
            sin1,
            pcc_possible: sys.pcc_possible(),
            drop_scale: super::convex::drop_scale(&sys.contacts),
            adjacent: Vec::new(),
            frames: Vec::new(),
        };
        let rest: Vec<[f64; 3]> = sys.rest_points.iter().map(v3).collect();
        fs.finish(&rest);
        if sys.shape == Shape::Rod {
            fs.frames.push(Frame::new(sys, [0, 1, 2]));
        } else if fs.n <= TABLE_CONTACTS {
            fs.frames = Frame::table(fs.n, |slots| Frame::new(sys, slots));
        }
        fs
    }

    /// The float model of a regular n-gon (any n from 3 to [`MAX_CONTACTS`]), with the PCC
    /// Lemma's verdict `pcc_possible` decided by the caller (exactly, in Q(cos 2π/n)).
    pub fn regular(b: &FloatPolygon, pcc_possible: bool) -> FloatSystem {
        let v3 = |v: nalgebra::Vector3<f64>| [v.x, v.y, v.z];
        let n = b.n();
        let g = b.gram();
        let mut fs = FloatSystem {
            shape: Shape::Polygon(n as u64),
            n,
            f: (0..n as i64).map(|k| v3(b.contact(k))).collect(),
            kick: (0..n as i64).map(|k| v3(b.kick(k))).collect(),
            centre: [0.0, 0.0, 1.0],
            gram: std::array::from_fn(|r| std::array::from_fn(|c| g[(r, c)])),
            gamma: b.gamma(),
            rest_paper: Vec::new(),
            cos1: b.cos(1),
            sin1: b.sin(1),
            pcc_possible,
            drop_scale: 1.0,
            adjacent: Vec::new(),
            frames: Vec::new(),
        };
        let rest: Vec<[f64; 3]> = (0..n as i64)
            .map(|i| v3(b.rest_point(i, i + 1).expect("adjacent contacts are never opposite")))
            .collect();
        fs.finish(&rest);
        if n <= TABLE_CONTACTS {
            let table = Frame::table(n, |slots| Frame::from_float(&fs, slots));
            fs.frames = table;
        }
        fs
    }

    /// The paper's rest directions from m_{i,i+1} in our coordinates, and the neighbour table.
    pub(super) fn finish(&mut self, rest_points: &[[f64; 3]]) {
        self.rest_paper = rest_points.iter().map(|m| unit(self.to_paper(m))).collect();
        let n = self.n;
        self.adjacent = vec![0; n];
        if let Shape::Polygon(_) | Shape::Convex(_) = self.shape {
            for a in 0..n {
                let b = (a + 1) % n;
                self.adjacent[a] |= 1 << b;
                self.adjacent[b] |= 1 << a;
            }
        }
    }

    /// Whether contacts a and b are neighbours on the polygon (never for the rod).
    #[inline]
    pub fn adjacent(&self, a: usize, b: usize) -> bool {
        (self.adjacent[a] >> b) & 1 == 1
    }

    /// Our coordinates (h0, h1, hc) or (u0, u1, v) to the paper's (φx, φy, h) or (ωx, ωy, v)
    /// (docs/model.md §2: ω_y = v - u0, ω_x = (u1 - v + c ω_y)/s). Polygons only; the identity
    /// for general bodies, whose states are in the paper's coordinates (docs/model.md §11).
    pub fn to_paper(&self, x: &[f64; 3]) -> [f64; 3] {
        if self.shape.is_convex() {
            return *x;
        }
        let wy = x[2] - x[0];
        let wx = (x[1] - x[2] + self.cos1 * wy) / self.sin1;
        [wx, wy, x[2]]
    }

    /// The paper's coordinates to ours: u0 = f_0·p = -ω_y + v, u1 = s ω_x - c ω_y + v (the
    /// paper's f_k = (y_k, -x_k, 1), R = 1). Polygons only; the identity for general bodies.
    pub fn from_paper(&self, x: &[f64; 3]) -> [f64; 3] {
        if self.shape.is_convex() {
            return *x;
        }
        [x[2] - x[1], self.sin1 * x[0] - self.cos1 * x[1] + x[2], x[2]]
    }

    /// Kinetic energy pᵀ G p / 2 in `f64` (of a normalised p: scale by 4^exponent).
    pub fn energy(&self, p: &[f64; 3]) -> f64 {
        let g = &self.gram;
        let mut t = 0.0;
        for r in 0..3 {
            for c in 0..3 {
                t += g[r][c] * p[r] * p[c];
            }
        }
        0.5 * t
    }
}

fn unit(x: [f64; 3]) -> [f64; 3] {
    let l = (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]).sqrt();
    x.map(|c| c / l)
}
