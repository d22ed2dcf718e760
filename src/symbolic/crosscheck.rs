//! Cross-check of the symbolic square proof at random rational parameters: evaluate the cone
//! cone(p1, p3, s1, s3) with lambda isolated to a tight rational interval, confirm with
//! guaranteed (rational interval) enclosures that it satisfies the effective-invariance
//! conditions there, and confirm that the certification pipeline certifies the same point.
//!
//! The cone has no slack where the proof's identities put images on its boundary (p1 maps to
//! lambda p1, s30 to s01, q1 to k1, s1 to lambda w1): there membership is confirmed within the
//! enclosure width; every other membership is confirmed strictly. (A uniformly padded rational
//! rectangle is not effectively invariant: its corner near the attracting eigenvector p1 can map
//! out through an edge, so the cone cannot simply be rounded outwards.)

use crate::certify::{Request, certify};
use crate::exact::{Q, QExt};
use crate::simulate::SplitMix64;
use crate::spectral::poly::Poly;
use crate::spectral::roots::isolate;
use chatter_kernel::certificate::Claim;
use serde::Serialize;
use std::cmp::Ordering;

/// One sampled point.
#[derive(Clone, Debug, Serialize, schemars::JsonSchema)]
pub struct PointCheck {
    pub gamma: String,
    pub kappa: String,
    /// Enclosure of the largest positive eigenvalue lambda.
    pub lambda: [String; 2],
    /// e1 > e2 > 1 confirmed on enclosures.
    pub inequalities: bool,
    /// Every image of a vertex of every K ∩ C_j, and of U_0 s12, U_0 s23, lies in K: strictly,
    /// or within the enclosure width where the proof's identities put it on the boundary.
    pub invariance: bool,
    /// How many of those memberships hold strictly.
    pub strict: usize,
    pub on_boundary: usize,
    /// The pipeline (`chatter certify`) certified the point (CC or PCC from all-down drops).
    pub pipeline: bool,
    pub note: String,
}

/// The summary of the cross-check.
#[derive(Clone, Debug, Serialize, schemars::JsonSchema)]
pub struct CrossCheck {
    pub seed: u64,
    pub points: usize,
    pub inequalities: usize,
    pub invariance: usize,
    pub pipeline: usize,
    /// Width of the enclosures used.
    pub width: String,
    pub disagreements: Vec<PointCheck>,
    pub samples: Vec<PointCheck>,
}

/// A closed rational interval.
#[derive(Clone, Debug)]
struct Iv {
    lo: Q,
    hi: Q,
}

impl Iv {
    fn pt(x: Q) -> Iv {
        Iv { lo: x.clone(), hi: x }
    }
    fn add(&self, o: &Iv) -> Iv {
        Iv { lo: &self.lo + &o.lo, hi: &self.hi + &o.hi }
    }
    fn neg(&self) -> Iv {
        Iv { lo: -&self.hi, hi: -&self.lo }
    }
    fn mul(&self, o: &Iv) -> Iv {
        let p = [&self.lo * &o.lo, &self.lo * &o.hi, &self.hi * &o.lo, &self.hi * &o.hi];
        Iv { lo: p.iter().min().expect("4").clone(), hi: p.iter().max().expect("4").clone() }
    }
    /// Quotient by an interval of positive numbers.
    fn div_pos(&self, o: &Iv) -> Option<Iv> {
        (o.lo > Q::int(0))
            .then(|| self.mul(&Iv { lo: Q::int(1) / o.hi.clone(), hi: Q::int(1) / o.lo.clone() }))
    }
}

/// The characteristic polynomial (kappa + 1) chi(lambda) at rational parameters.
fn chi_at(g: &Q, k: &Q) -> Poly<Q> {
    let one = Q::int(1);
    Poly::new(vec![g * &(k + &one), k - g, &(g * k) - &one, k + &one])
}

/// The paper's U_0 P_{q pi/2} at rational parameters.
fn paper_map(g: &Q, k: &Q, quarter: i64) -> [[Q; 3]; 3] {
    let one = Q::int(1);
    let a = (g + &one) / (k + &one);
    let u0 =
        [[one.clone(), Q::int(0), Q::int(0)], [Q::int(0), &one - &a, a.clone()], [Q::int(0), k * &a, &a - g]];
    let (c, s) = match quarter.rem_euclid(4) {
        0 => (1, 0),
        1 => (0, 1),
        2 => (-1, 0),
        _ => (0, -1),
    };
    let r =
        [[Q::int(c), Q::int(-s), Q::int(0)], [Q::int(s), Q::int(c), Q::int(0)], [Q::int(0), Q::int(0), one]];
    std::array::from_fn(|i| {
        std::array::from_fn(|j| (0..3).fold(Q::int(0), |acc, t| &acc + &(&u0[i][t] * &r[t][j])))
    })
}

fn check_point(g: &Q, k: &Q, width: &Q) -> Option<PointCheck> {
    let mut root =
        isolate(&chi_at(g, k)).into_iter().rev().find(|r| r.clone().sign() == Ordering::Greater)?;
    root.refine_to(width);
    let (lo, hi) = (root.lo.clone(), root.hi.clone());
    let one = Q::int(1);
    // e1 = (1 - l)/(k (1 + l^2)) is decreasing in l on (0, 1): enclosure from the ends.
    let e1f = |l: &Q| (&one - l) / (k * &(&one + &(l * l)));
    let e1 = Iv { lo: e1f(&hi), hi: e1f(&lo) };
    let e2 = Iv { lo: &lo * &e1.lo, hi: &hi * &e1.hi };
    let inequalities = hi < one && lo > Q::int(0) && e1.lo > e2.hi && e2.lo > one;
    // Vertices of K ∩ C_j (the structure proved symbolically), in the plane v = -1.
    let (m1, c) = (Iv::pt(Q::int(-1)), |x: i64| Iv::pt(Q::int(x)));
    let pieces: [(i64, Vec<(Iv, Iv)>); 3] = [
        (3, vec![(c(-1), c(-1)), (c(-1), e2.neg()), (e1.clone(), e2.neg()), (e1.clone(), c(-1))]),
        (1, vec![(c(1), c(-1)), (c(1), e2.neg()), (e1.neg(), e2.neg()), (e1.neg(), c(-1))]),
        (2, vec![(c(-1), c(-1)), (e2.neg(), e2.neg()), (e2.clone(), e2.neg()), (c(1), c(-1))]),
    ];
    let (mut strict, mut on_boundary, mut ok) = (0, 0, true);
    let slack = Q::int(64) * width.clone() * (&e1.hi + &Q::int(4)) * (&e1.hi + &Q::int(4));
    // x in [-e1, e1], y in [-e2, -1]: each side strictly, or within the slack.
    let member = |x: &Iv, y: &Iv| -> (usize, usize, bool) {
        let mut r = (0, 0, true);
        for gap in [x.add(&e1), e1.add(&x.neg()), y.add(&e2), m1.add(&y.neg())] {
            if gap.lo > Q::int(0) {
                r.0 += 1;
            } else if gap.hi >= Q::int(0) && -gap.lo.clone() <= slack {
                r.1 += 1;
            } else {
                r.2 = false;
            }
        }
        r
    };
    let image = |map: &[[Q; 3]; 3], x: &Iv, y: &Iv| -> Option<(Iv, Iv)> {
        let row = |r: usize| {
            Iv::pt(map[r][0].clone())
                .mul(x)
                .add(&Iv::pt(map[r][1].clone()).mul(y))
                .add(&Iv::pt(-map[r][2].clone()))
        };
        let w = row(2).neg();
        Some((row(0).div_pos(&w)?, row(1).div_pos(&w)?))
    };
    for (quarter, verts) in &pieces {
        let map = paper_map(g, k, 4 - quarter); // S_j = U_0 P_{-j pi/2} = U_0 P_{(4 - j) pi/2}
        for (x, y) in verts {
            let (a, b, good) = image(&map, x, y).map_or((0, 0, false), |(ix, iy)| member(&ix, &iy));
            (strict, on_boundary, ok) = (strict + a, on_boundary + b, ok && good);
        }
    }
    // Lemma l:k0: U_0 s12 and U_0 s23 lie strictly inside.
    let u0 = paper_map(g, k, 0);
    for (x, y) in [(c(1), c(1)), (c(-1), c(1))] {
        let (a, b, good) = image(&u0, &x, &y).map_or((0, 0, false), |(ix, iy)| member(&ix, &iy));
        (strict, on_boundary, ok) = (strict + a, on_boundary + b, ok && good);
    }
    let pipeline = certify(&Request::new(4, k.clone(), g.clone()))
        .result
        .is_ok_and(|c| c.claim >= Claim::CcOrPccFromAllDown);
    let note = if ok { String::new() } else { "an image leaves K beyond the enclosure width".into() };
    Some(PointCheck {
        gamma: g.to_string(),
        kappa: k.to_string(),
        lambda: [lo.decimal(15, crate::exact::Rounding::Down), hi.decimal(15, crate::exact::Rounding::Up)],
        inequalities,
        invariance: ok,
        strict,
        on_boundary,
        pipeline,
        note,
    })
}

/// Samples `points` rational (gamma, kappa) with denominators 1000 in (0, 0.4) x (0, 0.25) where
/// U_0 P_{pi/2} has a positive eigenvalue, deterministically from `seed`.
pub fn cross_check(points: usize, seed: u64) -> CrossCheck {
    let mut rng = SplitMix64::new(seed);
    let width = Q::pow10(-40);
    let mut done = Vec::new();
    let mut tries = 0;
    while done.len() < points && tries < 100 * points {
        tries += 1;
        let g = Q::new(1 + (rng.next_u64() % 399) as i64, 1000);
        let k = Q::new(1 + (rng.next_u64() % 249) as i64, 1000);
        if let Some(c) = check_point(&g, &k, &width) {
            done.push(c);
        }
    }
    let count = |f: fn(&PointCheck) -> bool| done.iter().filter(|c| f(c)).count();
    let (inequalities, invariance, pipeline) =
        (count(|c| c.inequalities), count(|c| c.invariance), count(|c| c.pipeline));
    let disagreements =
        done.iter().filter(|c| !(c.inequalities && c.invariance && c.pipeline)).cloned().collect();
    let samples = done.iter().take(5).cloned().collect();
    let width = width.to_string();
    CrossCheck { seed, points: done.len(), inequalities, invariance, pipeline, width, disagreements, samples }
}
