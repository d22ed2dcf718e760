//! The falling body as the simulator sees it (docs/model.md §2-3, §7): contact covectors f_k with
//! u_k = f_k·p and h_k = f_k·q, impact kicks with p+ = p - u_k kick_k, the centre-of-mass
//! covector, the kinetic energy, and the paper's coordinates for the PCC criterion.
//!
//! Vectors always have three components. The planar rod (n = 2) lives in the first two,
//! p = (u0, u1) and q = (h0, h1); its third component is 0 in every covector and kick, so it
//! stays exactly 0 in both arithmetics and the rod never stores the redundant v = (u0 + u1)/2.

use crate::exact::{Q, QExt, Ring};
use chatter_kernel::exact::OrderedField;
use chatter_kernel::model::linalg::{Vec3, dot};
use chatter_kernel::model::{BodyError, Polygon, Rod, Shape as Body};

/// Which body falls: a tag of the kernel's [`Body`] (`chatter_kernel::model::Shape`), which is
/// the one place where the number of contacts decides between the rod and a polygon.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    /// The planar rod of docs/model.md §7: two contacts, coordinates (u0, u1).
    Rod,
    /// A flat regular n-gon, n in {3, 4, 6} (exact cosines).
    Polygon(u64),
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
            Shape::Polygon(n) => n as usize,
        }
    }

    /// Number of generalised coordinates (3 for polygons, 2 for the rod).
    pub fn dim(self) -> usize {
        match self {
            Shape::Rod => 2,
            Shape::Polygon(_) => 3,
        }
    }

    /// Names of the generalised coordinates (positions, then velocities).
    pub fn coordinate_names(self) -> (&'static [&'static str], &'static [&'static str]) {
        match self {
            Shape::Rod => (&["h0", "h1"], &["u0", "u1"]),
            Shape::Polygon(_) => (&["h0", "h1", "hc"], &["u0", "u1", "v"]),
        }
    }
}

/// Largest number of contacts of a supported body.
pub const MAX_CONTACTS: usize = 6;

/// The exact model of a falling body, over the rationals.
#[derive(Clone, Debug)]
pub struct System {
    pub shape: Shape,
    pub kappa: Q,
    pub gamma: Q,
    /// f_k, k = 0..n-1: u_k = f_k·p, h_k = f_k·q.
    pub contacts: Vec<Vec3<Q>>,
    /// kick_k = beta d_k (docs/model.md §3): an impact at k maps p to p - u_k kick_k.
    pub kicks: Vec<Vec3<Q>>,
    /// c with v = c·p (centre-of-mass velocity) and hc = c·q.
    pub centre: Vec3<Q>,
    /// Kinetic energy as the quadratic form T(p) = pᵀ G p / 2 (exact).
    pub gram: [[Q; 3]; 3],
    /// For polygons, m_{i,i+1} (i = 0..n-1) in our coordinates (docs/model.md §4); empty for the rod.
    pub rest_points: Vec<Vec3<Q>>,
    /// E = f_1·kick_0 = (1+γ)(κ + cos 2π/n)/(1+κ): how an impact at one contact changes the
    /// normal velocity of its neighbour, per unit of its own (polygons; 0 for the rod).
    pub pair_coupling: Q,
}

fn z() -> Q {
    Q::int(0)
}

impl System {
    /// Builds the model of `shape` with the given kappa and gamma (validated by the kernel).
    pub fn new(shape: Shape, kappa: Q, gamma: Q) -> Result<System, BodyError> {
        let body = match shape {
            Shape::Rod => Body::Rod(Rod::new(kappa, gamma)?),
            Shape::Polygon(n) => Body::Polygon(Polygon::new(n, kappa, gamma)?),
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
        System { shape, kappa, gamma, contacts, kicks, centre, gram, rest_points, pair_coupling }
    }

    /// A regular polygon (docs/model.md §2-4) from the kernel's covectors, impact directions and rest points.
    fn polygon(body: &Polygon<Q>) -> System {
        let n = body.n() as i64;
        let beta = body.beta();
        let contacts: Vec<Vec3<Q>> = (0..n).map(|k| body.contact(k).clone()).collect();
        let kicks: Vec<Vec3<Q>> = (0..n).map(|k| body.impact_direction(k).map(|d| beta.times(&d))).collect();
        let centre = [z(), z(), Q::int(1)];
        let gram = gram_of(&|p: &Vec3<Q>| crate::model::kinetic_energy(body, p));
        let rest_points = (0..n)
            .map(|i| body.rest_point(i, i + 1).expect("adjacent contacts are never opposite"))
            .collect();
        let pair_coupling = dot(&contacts[1], &kicks[0]);
        let (kappa, gamma) = (body.kappa().clone(), body.gamma().clone());
        let shape = Shape::Polygon(n as u64);
        System { shape, kappa, gamma, contacts, kicks, centre, gram, rest_points, pair_coupling }
    }

    /// Number of contacts.
    pub fn n(&self) -> usize {
        self.contacts.len()
    }

    /// Kinetic energy T = pᵀ G p / 2 (docs/model.md §2; the rod: (v² + κω²)/2).
    pub fn energy(&self, p: &Vec3<Q>) -> Q {
        let mut t = z();
        for (r, row) in self.gram.iter().enumerate() {
            for (c, g) in row.iter().enumerate() {
                if !g.is_zero() {
                    t = t + g * &(&p[r] * &p[c]);
                }
            }
        }
        t * Q::new(1, 2)
    }

    /// Height h_k = f_k·q (or normal velocity u_k = f_k·p) of contact k.
    pub fn along(&self, k: usize, x: &Vec3<Q>) -> Q {
        dot(&self.contacts[k], x)
    }

    /// The paper's Lemma on PCC: two neighbours can chatter on their own only if an impact at one
    /// pulls the other down (E < 0) and the pair's step map, with characteristic polynomial
    /// t² + E t + γ, has real eigenvalues (E² - 4γ ≥ 0). Its discriminant has the sign of the one
    /// of the quadratic factor of S_(n-1) S_1 (whose roots are the squares of these). False for
    /// the rod.
    pub fn pcc_possible(&self) -> bool {
        let e = &self.pair_coupling;
        self.is_polygon() && e.is_negative() && !(e * e - Q::int(4) * &self.gamma).is_negative()
    }

    /// The frame with the contacts `slots`: the matrix A = [f_s0; f_s1; f_s2] taking our
    /// coordinates to (h_s0, h_s1, h_s2). Three distinct vertices of a convex polygon are never
    /// collinear, so A is invertible. The rod has one frame, the identity.
    pub fn frame_matrix(&self, slots: [usize; 3]) -> [[Q; 3]; 3] {
        match self.shape {
            Shape::Rod => std::array::from_fn(|r| std::array::from_fn(|c| Q::int(i64::from(r == c)))),
            Shape::Polygon(_) => slots.map(|k| self.contacts[k].clone()),
        }
    }

    /// Whether contacts a and b are neighbours on the polygon (never for the rod).
    pub fn adjacent(&self, a: usize, b: usize) -> bool {
        let n = self.n();
        self.is_polygon() && a != b && ((a + 1) % n == b || (b + 1) % n == a)
    }

    /// Whether the body is a polygon (contacts have neighbours), not the rod.
    pub fn is_polygon(&self) -> bool {
        matches!(self.shape, Shape::Polygon(_))
    }
}

/// The symmetric matrix G with T(p) = pᵀ G p / 2, by polarisation of an exact quadratic form.
fn gram_of(energy: &dyn Fn(&Vec3<Q>) -> Q) -> [[Q; 3]; 3] {
    let e = |i: usize| -> Vec3<Q> { std::array::from_fn(|k| Q::int(i64::from(k == i))) };
    std::array::from_fn(|r| {
        std::array::from_fn(|c| {
            if r == c {
                energy(&e(r)) * Q::int(2)
            } else {
                let s: Vec3<Q> = std::array::from_fn(|k| Q::int(i64::from(k == r || k == c)));
                energy(&s) - energy(&e(r)) - energy(&e(c))
            }
        })
    })
}

/// The `f64` copy of a [`System`], laid out for the hot loop (fixed-size arrays, no allocation).
#[derive(Clone, Debug)]
pub struct FloatSystem {
    pub shape: Shape,
    pub n: usize,
    pub f: [[f64; 3]; MAX_CONTACTS],
    pub kick: [[f64; 3]; MAX_CONTACTS],
    pub centre: [f64; 3],
    pub gram: [[f64; 3]; 3],
    pub gamma: f64,
    /// Unit vectors along m_{i,i+1} in the paper's coordinates (polygons only).
    pub rest_paper: [[f64; 3]; MAX_CONTACTS],
    /// cos and sin of 2π/n (polygons; the change to the paper's coordinates, docs/model.md §2).
    pub cos1: f64,
    pub sin1: f64,
    /// [`System::pcc_possible`].
    pub pcc_possible: bool,
    /// The frames of the `f64` engine, indexed by [`frame_index`] (one frame for the rod).
    pub frames: Vec<Frame>,
}

impl FloatSystem {
    pub fn new(sys: &System) -> FloatSystem {
        let v3 = |v: &Vec3<Q>| v.clone().map(|x| x.to_f64());
        let mut f = [[0.0; 3]; MAX_CONTACTS];
        let mut kick = [[0.0; 3]; MAX_CONTACTS];
        for k in 0..sys.n() {
            f[k] = v3(&sys.contacts[k]);
            kick[k] = v3(&sys.kicks[k]);
        }
        let (cos1, sin1) = match sys.shape {
            Shape::Rod => (-1.0, 0.0),
            Shape::Polygon(n) => {
                let th = 2.0 * std::f64::consts::PI / n as f64;
                (th.cos(), th.sin())
            }
        };
        let mut fs = FloatSystem {
            shape: sys.shape,
            n: sys.n(),
            f,
            kick,
            centre: v3(&sys.centre),
            gram: sys.gram.clone().map(|r| r.map(|x| x.to_f64())),
            gamma: sys.gamma.to_f64(),
            rest_paper: [[0.0; 3]; MAX_CONTACTS],
            cos1,
            sin1,
            pcc_possible: sys.pcc_possible(),
            frames: Vec::new(),
        };
        for (i, m) in sys.rest_points.iter().enumerate() {
            fs.rest_paper[i] = unit(fs.to_paper(&v3(m)));
        }
        let n = sys.n();
        if sys.shape == Shape::Rod {
            fs.frames.push(Frame::new(sys, [0, 1, 2]));
        } else {
            fs.frames = vec![Frame::default(); MAX_CONTACTS * MAX_CONTACTS * MAX_CONTACTS];
            for a in 0..n {
                for b in (0..n).filter(|&b| b != a) {
                    for c in (0..n).filter(|&c| c != a && c != b) {
                        fs.frames[frame_index([a, b, c])] = Frame::new(sys, [a, b, c]);
                    }
                }
            }
        }
        fs
    }

    /// Our coordinates (h0, h1, hc) or (u0, u1, v) to the paper's (φx, φy, h) or (ωx, ωy, v)
    /// (docs/model.md §2: ω_y = v - u0, ω_x = (u1 - v + c ω_y)/s). Polygons only.
    pub fn to_paper(&self, x: &[f64; 3]) -> [f64; 3] {
        let wy = x[2] - x[0];
        let wx = (x[1] - x[2] + self.cos1 * wy) / self.sin1;
        [wx, wy, x[2]]
    }

    /// The paper's coordinates to ours: u0 = f_0·p = -ω_y + v, u1 = s ω_x - c ω_y + v (the
    /// paper's f_k = (y_k, -x_k, 1), R = 1). Polygons only.
    pub fn from_paper(&self, x: &[f64; 3]) -> [f64; 3] {
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

/// The index of the frame with contacts (a, b, c) in [`FloatSystem::frames`].
#[inline]
pub fn frame_index(slots: [usize; 3]) -> usize {
    (slots[0] * MAX_CONTACTS + slots[1]) * MAX_CONTACTS + slots[2]
}

/// Coordinates of the `f64` engine: the heights (h_s0, h_s1, h_s2) and normal velocities of three
/// contacts (for the rod (h0, h1, 0)), with every quantity the engine needs expressed in them.
///
/// The engine keeps the last three distinct contacts to land as the frame. When a contact outside
/// it lands, it replaces the one that landed longest ago: the two kept coordinates are copied
/// unchanged and the new one is h = 0, u = -γ u⁻ exactly, so a change of frame costs nothing and
/// loses nothing. Heights and velocities of chattering contacts are then always coordinates, not
/// differences of O(1) numbers, and keep their relative precision however small they become
/// next to the rest of the state (docs/model.md §10).
#[derive(Clone, Debug, Default)]
pub struct Frame {
    /// The contacts whose heights are the coordinates (slot 2 unused for the rod).
    pub slots: [usize; 3],
    /// Contact covectors: u_k = `f[k]`·p, h_k = `f[k]`·q in this frame.
    pub f: [[f64; 3]; MAX_CONTACTS],
    /// Impact kicks in this frame.
    pub kick: [[f64; 3]; MAX_CONTACTS],
    /// Centre covector (v, hc).
    pub centre: [f64; 3],
    /// Energy Gram matrix.
    pub gram: [[f64; 3]; 3],
    /// This frame to our coordinates.
    pub to_ours: [[f64; 3]; 3],
    /// Our coordinates to this frame.
    pub from_ours: [[f64; 3]; 3],
    /// `slot[k]`: the slot holding contact k, or 3.
    pub slot: [u8; MAX_CONTACTS],
}

impl Frame {
    fn new(sys: &System, slots: [usize; 3]) -> Frame {
        let v3 = |v: &Vec3<Q>| v.clone().map(|x| x.to_f64());
        let m3 = |m: &[[Q; 3]; 3]| m.clone().map(|r| r.map(|x| x.to_f64()));
        let a = sys.frame_matrix(slots);
        let b = inverse3(&a).expect("three vertices of a convex polygon are not collinear");
        let mut fr = Frame {
            slots,
            centre: v3(&row_times(&sys.centre, &b)),
            gram: m3(&mat_mul3(&transpose3(&b), &mat_mul3(&sys.gram, &b))),
            to_ours: m3(&b),
            from_ours: m3(&a),
            slot: [3; MAX_CONTACTS],
            ..Frame::default()
        };
        let dim = sys.shape.dim();
        for (i, &k) in slots[..dim].iter().enumerate() {
            fr.slot[k] = i as u8;
        }
        for k in 0..sys.n() {
            fr.f[k] = v3(&row_times(&sys.contacts[k], &b));
            fr.kick[k] = v3(&mat_times(&a, &sys.kicks[k]));
        }
        fr
    }
}

fn row_times(r: &Vec3<Q>, m: &[[Q; 3]; 3]) -> Vec3<Q> {
    std::array::from_fn(|c| &(&(&r[0] * &m[0][c]) + &(&r[1] * &m[1][c])) + &(&r[2] * &m[2][c]))
}

fn mat_times(m: &[[Q; 3]; 3], x: &Vec3<Q>) -> Vec3<Q> {
    std::array::from_fn(|r| dot(&m[r], x))
}

fn transpose3(m: &[[Q; 3]; 3]) -> [[Q; 3]; 3] {
    std::array::from_fn(|r| std::array::from_fn(|c| m[c][r].clone()))
}

fn mat_mul3(a: &[[Q; 3]; 3], b: &[[Q; 3]; 3]) -> [[Q; 3]; 3] {
    std::array::from_fn(|r| row_times(&a[r], b))
}

/// The exact inverse of a 3x3 matrix (adjugate over determinant), `None` if singular.
fn inverse3(m: &[[Q; 3]; 3]) -> Option<[[Q; 3]; 3]> {
    let det = chatter_kernel::model::linalg::det3(&m[0], &m[1], &m[2]);
    if det.is_zero() {
        return None;
    }
    let cof = |r: usize, c: usize| {
        let (r1, r2) = ((r + 1) % 3, (r + 2) % 3);
        let (c1, c2) = ((c + 1) % 3, (c + 2) % 3);
        &(&m[r1][c1] * &m[r2][c2]) - &(&m[r1][c2] * &m[r2][c1])
    };
    Some(std::array::from_fn(|r| std::array::from_fn(|c| &cof(c, r) / &det)))
}

fn unit(x: [f64; 3]) -> [f64; 3] {
    let l = (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]).sqrt();
    x.map(|c| c / l)
}
