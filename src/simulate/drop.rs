//! Initial states: user-given states in our coordinates, and the paper's random-drop protocol
//! (section "Comparison with direct simulation") with a seeded, portable generator.

use super::scalar::SimField;
use super::system::{FloatSystem, Shape, System};
use crate::exact::{Q, QExt, Ring};
use chatter_kernel::model::linalg::Vec3;

/// An initial state in our coordinates: q = (h0, h1, hc) and p = (u0, u1, v); for the rod
/// q = (h0, h1, 0), p = (u0, u1, 0).
#[derive(Clone, Debug, PartialEq)]
pub struct Start<F> {
    pub q: [F; 3],
    pub p: [F; 3],
}

impl Start<Q> {
    /// The nearest `f64` state (exact when the rationals are dyadic, as for random drops).
    pub fn to_f64(&self) -> Start<f64> {
        Start { q: self.q.clone().map(|x| x.to_f64()), p: self.p.clone().map(|x| x.to_f64()) }
    }
}

/// Why an initial state is not a drop.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum StartError {
    /// Contact k starts below the floor (h_k < 0).
    BelowFloor { contact: usize, height: String },
    /// The velocity is zero: nothing moves.
    AtRest,
    /// The rod's states have two coordinates.
    WrongLength { expected: usize, found: usize },
}

impl std::fmt::Display for StartError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            StartError::BelowFloor { contact, height } => {
                write!(f, "contact {contact} starts below the floor (height {height} < 0)")
            }
            StartError::AtRest => write!(f, "the velocity is zero: the body does not move"),
            StartError::WrongLength { expected, found } => {
                write!(f, "expected {expected} coordinates, found {found}")
            }
        }
    }
}

impl std::error::Error for StartError {}

/// Builds a start from coordinates in our convention (3 for polygons, 2 for the rod) and checks
/// that no contact is below the floor and that the body moves.
pub fn given_start<F: SimField>(
    sys: &System<F>,
    position: &[Q],
    velocity: &[Q],
) -> Result<Start<Q>, StartError> {
    let dim = sys.shape.dim();
    for v in [position, velocity] {
        if v.len() != dim {
            return Err(StartError::WrongLength { expected: dim, found: v.len() });
        }
    }
    let pad = |v: &[Q]| -> Vec3<Q> { std::array::from_fn(|i| v.get(i).cloned().unwrap_or(Q::int(0))) };
    let start = Start { q: pad(position), p: pad(velocity) };
    check_start(sys, &start)?;
    Ok(start)
}

/// Checks h_k >= 0 for every contact (exactly, in the body's field) and p != 0.
pub fn check_start<F: SimField>(sys: &System<F>, s: &Start<Q>) -> Result<(), StartError> {
    let q = s.q.clone().map(|x| F::from_q(&x));
    for k in 0..sys.n() {
        let h = sys.along(k, &q);
        if h.is_negative() {
            return Err(StartError::BelowFloor { contact: k, height: h.to_string() });
        }
    }
    if s.p.iter().all(Ring::is_zero) {
        return Err(StartError::AtRest);
    }
    Ok(())
}

/// SplitMix64 (Steele, Lea and Flood, "Fast splittable pseudorandom number generators", 2014).
///
/// Chosen over a crate because the stream must never change: it is a few lines of wrapping
/// 64-bit integer arithmetic, identical on every platform and compiler, with no dependency whose
/// version could alter it. Its output function is a strong 64-bit mixer, so consecutive seeds
/// (run i of `--runs` uses seed S + i) give independent-looking streams; it passes BigCrush.
#[derive(Clone, Debug)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    pub fn new(seed: u64) -> SplitMix64 {
        SplitMix64(seed)
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform on the open interval (0, 1): (k + 1/2) / 2^53 for a uniform 53-bit k.
    pub fn open01(&mut self) -> f64 {
        ((self.next_u64() >> 11) as f64 + 0.5) * (1.0 / (1u64 << 53) as f64)
    }
}

/// The paper's random drop with seed `seed`: R_1..R_5 uniform on (0, 0.1), velocity
/// (ω_x, ω_y, v) = (R1, R2, -1) and position (φ_x, φ_y, h) = (R3, R4, 1 + R5) in the paper's
/// coordinates, converted to ours (docs/model.md §2) in `f64`. General bodies (docs/model.md
/// §11.10) are in the paper's coordinates already; their rotation and tilt are divided by the
/// body's length scale R ([`FloatSystem::drop_scale`], a power of two: exact), which drops the
/// body scaled to size about 1 as the paper drops its unit polygons (R = 1 for those).
///
/// The rod uses (ω, v) = (R1, -1) and (φ, h) = (R3, 1 + R5) with contacts at x = -1 (contact 0)
/// and x = +1: u0 = v - ω, u1 = v + ω, h0 = h - φ, h1 = h + φ.
///
/// Both arithmetics start from exactly this `f64` state: [`exact_drop`] takes its values as
/// dyadic rationals, so float and exact runs of one seed simulate the same body.
pub fn random_drop(fs: &FloatSystem, seed: u64) -> Start<f64> {
    let mut rng = SplitMix64::new(seed);
    let r: [f64; 5] = std::array::from_fn(|_| 0.1 * rng.open01());
    match fs.shape {
        Shape::Rod => {
            let (w, v, phi, h) = (r[0], -1.0, r[2], 1.0 + r[4]);
            Start { q: [h - phi, h + phi, 0.0], p: [v - w, v + w, 0.0] }
        }
        Shape::Convex(_) => {
            let s = fs.drop_scale;
            Start { q: [r[2] / s, r[3] / s, 1.0 + r[4]], p: [r[0] / s, r[1] / s, -1.0] }
        }
        Shape::Polygon(_) => {
            Start { q: fs.from_paper(&[r[2], r[3], 1.0 + r[4]]), p: fs.from_paper(&[r[0], r[1], -1.0]) }
        }
    }
}

/// The exact start of a random drop: the values of [`random_drop`] as exact rationals.
pub fn exact_drop(fs: &FloatSystem, seed: u64) -> Start<Q> {
    let s = random_drop(fs, seed);
    let q = |x: f64| Q::from_f64_exact(x).expect("a random drop is finite");
    Start { q: s.q.map(q), p: s.p.map(q) }
}
