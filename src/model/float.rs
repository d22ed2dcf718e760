//! The float model of a regular n-gon (issue 10 §1): the maps of docs/model.md §2-4 in `f64`,
//! built from cos and sin of 2πm/n for every n ≥ 3, so that the untrusted tools (the simulator,
//! the float finder) need no exact rational cosine. It mirrors the kernel's `Polygon` method by
//! method (contact covectors, impact directions, rest points, step maps, the cones C_j and D)
//! and agrees with it to rounding where the kernel applies (n = 3, 4, 6; tested).

use chatter_kernel::model::BodyError;
use nalgebra::{Matrix3, Vector3};

/// Largest number of contacts of the float model (a contact index fits a bit of a `u64`).
pub const MAX_FLOAT_CONTACTS: u64 = 64;

/// cos and sin of 2πm/n, reduced to a quarter turn first, so that quarter turns are exact
/// (cos π/2 = 0, not 6e-17) and c_m = c_{-m}, s_m = -s_{-m} hold exactly.
pub fn cos_sin_turn(m: i64, n: u64) -> (f64, f64) {
    let n = n as i64;
    let four_m = 4 * m.rem_euclid(n);
    let (quadrant, rest) = (four_m / n, four_m % n);
    let a = std::f64::consts::FRAC_PI_2 * rest as f64 / n as f64;
    let (c, s) = (a.cos(), a.sin());
    match quadrant {
        0 => (c, s),
        1 => (-s, c),
        2 => (-c, -s),
        _ => (s, -c),
    }
}

/// A flat regular n-gon in `f64` (docs/model.md §1-4): contacts at angles 2πk/n, κ = ρ²/R², γ.
#[derive(Clone, Debug)]
pub struct FloatPolygon {
    n: usize,
    kappa: f64,
    gamma: f64,
    /// (c_m, s_m) = (cos, sin)(2πm/n), m = 0..n-1.
    trig: Vec<(f64, f64)>,
    /// Contact covectors f_k with u_k = f_k·p (docs/model.md §2).
    contacts: Vec<Vector3<f64>>,
}

impl FloatPolygon {
    /// The body with 3 ≤ n ≤ 64, κ > 0 and γ in [0, 1] (the kernel's rules and errors).
    pub fn new(n: u64, kappa: f64, gamma: f64) -> Result<FloatPolygon, BodyError> {
        if !(3..=MAX_FLOAT_CONTACTS).contains(&n) {
            return Err(BodyError::UnsupportedN(n));
        }
        if !(kappa > 0.0 && kappa.is_finite()) {
            return Err(BodyError::KappaNotPositive);
        }
        if !(0.0..=1.0).contains(&gamma) {
            return Err(BodyError::GammaOutOfRange);
        }
        let trig: Vec<(f64, f64)> = (0..n as i64).map(|m| cos_sin_turn(m, n)).collect();
        let s1 = trig[1].1;
        // a_k = -sin θ_{k-1} / sin θ_1, b_k = sin θ_k / sin θ_1 (docs/model.md §2); contacts 0
        // and 1 are set exactly.
        let contacts = (0..n as usize)
            .map(|k| match k {
                0 => Vector3::new(1.0, 0.0, 0.0),
                1 => Vector3::new(0.0, 1.0, 0.0),
                _ => {
                    let (a, b) = (-trig[k - 1].1 / s1, trig[k].1 / s1);
                    Vector3::new(a, b, 1.0 - a - b)
                }
            })
            .collect();
        Ok(FloatPolygon { n: n as usize, kappa, gamma, trig, contacts })
    }

    /// Number of contacts.
    pub fn n(&self) -> usize {
        self.n
    }

    /// κ = ρ²/R².
    pub fn kappa(&self) -> f64 {
        self.kappa
    }

    /// The coefficient of restitution.
    pub fn gamma(&self) -> f64 {
        self.gamma
    }

    fn index(&self, m: i64) -> usize {
        m.rem_euclid(self.n as i64) as usize
    }

    /// c_m = cos(2πm/n) for any integer m.
    pub fn cos(&self, m: i64) -> f64 {
        self.trig[self.index(m)].0
    }

    /// s_m = sin(2πm/n) for any integer m.
    pub fn sin(&self, m: i64) -> f64 {
        self.trig[self.index(m)].1
    }

    /// Covector f_k of contact k (docs/model.md §2).
    pub fn contact(&self, k: i64) -> Vector3<f64> {
        self.contacts[self.index(k)]
    }

    /// β = (1 + γ)/(1 + κ), the impulse factor of every impact (docs/model.md §3).
    pub fn beta(&self) -> f64 {
        (1.0 + self.gamma) / (1.0 + self.kappa)
    }

    /// d_k = (κ + c_k, κ + c_{k-1}, κ) (docs/model.md §3).
    pub fn impact_direction(&self, k: i64) -> Vector3<f64> {
        let kp = self.kappa;
        Vector3::new(kp + self.cos(k), kp + self.cos(k - 1), kp)
    }

    /// The kick of an impact at k: p+ = p - u_k kick_k, kick_k = β d_k.
    pub fn kick(&self, k: i64) -> Vector3<f64> {
        self.beta() * self.impact_direction(k)
    }

    /// Impact map I_k = I - β d_k f_kᵀ (the paper's equation for U_i).
    pub fn impact(&self, k: i64) -> Matrix3<f64> {
        Matrix3::identity() - self.kick(k) * self.contact(k).transpose()
    }

    /// Relabelling R_j, rows f_j, f_{j+1}, (0, 0, 1).
    pub fn relabel(&self, j: i64) -> Matrix3<f64> {
        let (a, b) = (self.contact(j), self.contact(j + 1));
        Matrix3::from_rows(&[a.transpose(), b.transpose(), Vector3::z().transpose()])
    }

    /// Step map S_j = I_0 R_j, the paper's U_0 P_{-2jπ/n} (equation U0).
    pub fn step(&self, j: i64) -> Matrix3<f64> {
        self.impact(0) * self.relabel(j)
    }

    /// m_{k,l} = (h0, h1, 1) with h_k = h_l = 0 (Cramer's rule, as the kernel), `None` when
    /// k and l are opposite.
    pub fn rest_point(&self, k: i64, l: i64) -> Option<Vector3<f64>> {
        let (fk, fl) = (self.contact(k), self.contact(l));
        let det = fk.x * fl.y - fl.x * fk.y;
        if det.abs() < 1e-12 {
            return None;
        }
        let h0 = (fl.z * fk.y - fk.z * fl.y) / det;
        let h1 = (fk.z * fl.x - fl.z * fk.x) / det;
        Some(Vector3::new(h0, h1, 1.0))
    }

    fn adjacent_rest_point(&self, k: i64) -> Vector3<f64> {
        self.rest_point(k, k + 1).expect("adjacent contacts of a polygon are never opposite")
    }

    /// The covectors of the cone C_j (docs/model.md §4), in the kernel's order.
    pub fn next_contact_cone(&self, j: i64) -> [Vector3<f64>; 4] {
        let m01 = self.adjacent_rest_point(0);
        let m_last = self.adjacent_rest_point(-1);
        [
            Vector3::x(),
            -Vector3::z(),
            self.adjacent_rest_point(j).cross(&m01),
            m_last.cross(&self.adjacent_rest_point(j - 1)),
        ]
    }

    /// Generators -m_{k,k+1}, k = 0..n-1, of the all-down cone D (docs/model.md §5).
    pub fn all_down_generators(&self) -> Vec<Vector3<f64>> {
        (0..self.n as i64).map(|k| -self.adjacent_rest_point(k)).collect()
    }

    /// G with T(p) = pᵀ G p / 2, T = κ|ω|²/2 + v²/2 (docs/model.md §2): ω = L p with rows
    /// ω_x = (u1 - v + c_1 (v - u0))/s_1 and ω_y = v - u0.
    pub fn gram(&self) -> Matrix3<f64> {
        let (c, s) = (self.cos(1), self.sin(1));
        let wx = Vector3::new(-c / s, 1.0 / s, (c - 1.0) / s);
        let wy = Vector3::new(-1.0, 0.0, 1.0);
        let l = Matrix3::from_rows(&[wx.transpose(), wy.transpose(), Vector3::zeros().transpose()]);
        self.kappa * l.transpose() * l + Vector3::z() * Vector3::z().transpose()
    }
}
