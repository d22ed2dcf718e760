//! The return map R_P of docs/orbit-certificates.md §2 and conditions 1-3 of §3 at one point.
//! A state is (q, p) in contact coordinates; a step j lands contact j after t = h_j/(-u_j), then
//! renames contact j as 0: q' = (h_j, h_{j+1}, hc) of q + t p, p' = S_j p (the oracle's step:
//! impact at j, then rename). Heights transform like speeds (docs/model.md §2).

use crate::arith::Num;
use crate::arith::text::element_text;
use crate::regular::model::{Polygon, V3};
use crate::verdict::{Checked, Fail};

/// An orbit certificate's data, exact.
#[derive(Clone, Debug)]
pub struct Orbit {
    /// The body.
    pub body: Polygon,
    /// The steps j_1..j_m.
    pub pattern: Vec<i64>,
    /// x*.
    pub centre: V3,
    /// A (rows).
    pub a: [V3; 3],
    /// A⁻¹ (rows).
    pub a_inv: [V3; 3],
    /// δ.
    pub delta: Num,
    /// ρ.
    pub rho: Num,
    /// λ.
    pub lambda: Num,
    /// T̄.
    pub period: Num,
}

/// One period of the return map at a point, exactly: R_P(x), the position and velocity scales
/// α = hc(q_m) and β = -v(p_m), and the flight time T(x) (docs/orbit-certificates.md §2).
#[derive(Clone, Debug)]
pub struct Period {
    /// R_P(x).
    pub image: V3,
    /// α.
    pub alpha: Num,
    /// β.
    pub beta: Num,
    /// T.
    pub total: Num,
}

fn mat_vec(m: &[V3; 3], x: &V3) -> V3 {
    std::array::from_fn(|r| &(&(&m[r][0] * &x[0]) + &(&m[r][1] * &x[1])) + &(&m[r][2] * &x[2]))
}

fn fail(code: &'static str, why: String) -> Fail {
    Fail::new(code, why)
}

impl Orbit {
    /// The point x = x* + A y of X.
    pub fn point(&self, y: &V3) -> V3 {
        let ay = mat_vec(&self.a, y);
        std::array::from_fn(|i| &self.centre[i] + &ay[i])
    }

    /// Condition 1 at one step from (q, p): the flight time t.
    fn forced(&self, s: usize, j: i64, q: &V3, p: &V3) -> Checked<Num> {
        let b = &self.body;
        let (uj, hj) = (b.speed(j, p), b.speed(j, q));
        if !uj.is_negative() || !hj.is_positive() {
            return Err(fail("pattern-not-forced", format!("step {s}: contact {j} does not land")));
        }
        for k in (0..b.n as i64).filter(|&k| k != j) {
            let margin = &(&b.speed(k, q) * &uj.neg()) + &(&hj * &b.speed(k, p));
            if !margin.is_positive() {
                return Err(fail(
                    "pattern-not-forced",
                    format!("step {s}: contact {k} is not above the floor"),
                ));
            }
        }
        Ok(&hj / &uj.neg())
    }

    /// B = T̄/(1 - ρ) (canonical text): by the theorem of docs/orbit-certificates.md §4, period k
    /// from a state of X with scales A_0 = hc, B_0 = -v lasts at most (A_0/B_0) ρ^k T̄, so the
    /// impacts accumulate within B h/|v| (docs/certificate-format.md §5).
    pub fn time_to_rest(&self) -> String {
        let one = Num::int(&self.rho.field, 1);
        element_text(&(&self.period / &(&one - &self.rho)))
    }

    /// One period of the pattern from x = x* + A y, with condition 1 at every step and the
    /// positivity of α and β (condition 2) checked before they are divided by.
    pub fn period(&self, y: &V3) -> Checked<Period> {
        let b = &self.body;
        let f = &self.delta.field;
        let x = self.point(y);
        let (mut q, mut p): (V3, V3) =
            ([Num::int(f, 0), x[0].clone(), Num::int(f, 1)], [x[1].clone(), x[2].clone(), Num::int(f, -1)]);
        let mut total = Num::int(f, 0);
        for (s, &j) in self.pattern.iter().enumerate() {
            let t = self.forced(s + 1, j, &q, &p)?;
            let moved: V3 = std::array::from_fn(|i| &q[i] + &(&t * &p[i]));
            q = [b.speed(j, &moved), b.speed(j + 1, &moved), moved[2].clone()];
            assert!(q[0].is_zero(), "the landing contact is at height 0");
            p = b.step(j, &p);
            total = &total + &t;
        }
        let (alpha, beta) = (q[2].clone(), p[2].neg());
        if !alpha.is_positive() || !beta.is_positive() {
            return Err(fail("set-not-invariant", "alpha or beta is not positive".into()));
        }
        let image: V3 = [&q[1] / &alpha, &p[0] / &beta, &p[1] / &beta];
        Ok(Period { image, alpha, beta, total })
    }

    /// Conditions 1-3 at the point with parameters y (x = x* + A y).
    pub fn conditions(&self, y: &V3) -> Checked<()> {
        let Period { image, alpha, beta, total } = self.period(y)?;
        let diff: V3 = std::array::from_fn(|i| &image[i] - &self.centre[i]);
        let y2 = mat_vec(&self.a_inv, &diff);
        if y2.iter().any(|c| c > &self.delta || c < &self.delta.neg()) {
            return Err(fail("set-not-invariant", "R_P(x) is not in X".into()));
        }
        let contraction = [
            (beta <= self.lambda, "beta <= lambda"),
            (alpha <= &self.rho * &beta, "alpha/beta <= rho"),
            (alpha <= self.lambda, "alpha <= lambda"),
            (total <= self.period, "T <= period"),
        ];
        if let Some((_, what)) = contraction.iter().find(|(ok, _)| !ok) {
            return Err(fail("no-contraction", format!("{what} fails")));
        }
        Ok(())
    }
}
