//! The rod (n = 2, docs/model.md §7, docs/certificate-format.md §8): contacts at x = ±1,
//! velocities (u0, u1), v = (u0 + u1)/2. Impacts from the inverse-inertia products
//! ⟨f_0, f_1⟩/N_0 = (1 - 1/κ)/(1 + 1/κ) = (κ - 1)/(κ + 1); the step S_1 is "impact at end 1, then
//! swap the names". On the line v = -1/2 a velocity is the number s = u0/(-2v) and K an interval.

use crate::arith::Rat;
use crate::claim::Claim;
use crate::verdict::{Checked, Fail, Report};
use num_traits::{One, Signed, Zero};

/// A rod velocity (u0, u1).
pub type V2 = [Rat; 2];

/// The rod's model at (κ, γ).
pub struct Rod {
    /// κ.
    pub kappa: Rat,
    /// γ.
    pub gamma: Rat,
}

impl Rod {
    /// The impact at end k: u_k ↦ -γ u_k, the other end's speed changes by
    /// -(1 + γ) u_k (κ - 1)/(κ + 1).
    pub fn impact(&self, k: usize, p: &V2) -> V2 {
        let one = Rat::one();
        let coupling = (&self.kappa - &one) / (&self.kappa + &one);
        let kick = (&one + &self.gamma) * &p[k];
        let mut out = p.clone();
        out[k] = -(&self.gamma * &p[k]);
        out[1 - k] = &p[1 - k] - &kick * &coupling;
        out
    }

    /// S_1: impact at end 1, then the ends swap names.
    pub fn step(&self, p: &V2) -> V2 {
        let after = self.impact(1, p);
        [after[1].clone(), after[0].clone()]
    }
}

/// s = u0 / (-2v) = u0 / -(u0 + u1), `None` when v ≥ 0.
pub fn position(p: &V2) -> Option<Rat> {
    let w = -(&p[0] + &p[1]);
    w.is_positive().then(|| &p[0] / &w)
}

/// Rules R1 to R3 (R4 holds trivially for the rod: PCC is CC with two contacts).
pub fn check_rod(rod: &Rod, claim: Claim, gens: &[V2], bits: u64) -> Checked<Report> {
    let mut s = vec![];
    for (i, g) in gens.iter().enumerate() {
        s.push(
            position(g)
                .ok_or_else(|| Fail::new("generator-not-below", format!("generator {i} has v >= 0")))?,
        );
    }
    let (Some(lo), Some(hi)) = (s.iter().min().cloned(), s.iter().max().cloned()) else {
        return Err(Fail::new("degenerate-cone", "no generators"));
    };
    if lo == hi {
        return Err(Fail::new("degenerate-cone", "K is a single ray"));
    }
    let ends = [s.iter().position(|x| *x == lo), s.iter().position(|x| *x == hi)];
    let redundant = (0..s.len()).filter(|i| !ends.contains(&Some(*i))).collect();
    let holds = |p: &V2| p.iter().all(Zero::is_zero) || position(p).is_some_and(|x| lo <= x && x <= hi);
    // K ∩ C_1 = K ∩ {u0 ≥ 0}: the interval [max(lo, 0), hi] of s, whose ends are (s, -1 - s).
    let piece: Vec<Rat> = match (hi.cmp(&Rat::zero()), lo.is_positive()) {
        (std::cmp::Ordering::Less, _) => vec![],
        (std::cmp::Ordering::Equal, _) => vec![hi.clone()],
        (_, true) => vec![lo.clone(), hi.clone()],
        (_, false) => vec![Rat::zero(), hi.clone()],
    };
    let mut codes = vec![];
    for x in &piece {
        let img = rod.step(&[x.clone(), -(Rat::one() + x)]);
        if !holds(&img) {
            let code = if position(&img).is_none() { "image-not-below" } else { "image-outside" };
            if !codes.contains(&code) {
                codes.push(code);
            }
        }
    }
    if !codes.is_empty() {
        return Err(Fail { codes, why: "an end of K ∩ C_1 maps outside K".into() });
    }
    let minus_one = -Rat::one();
    if claim >= Claim::CcOrPccFromAllDown {
        for g in [[Rat::zero(), minus_one.clone()], [minus_one.clone(), Rat::zero()]] {
            if !holds(&rod.impact(0, &g)) {
                return Err(Fail::new("initial-outside", "I_0 of a generator of D is not in K"));
            }
        }
    }
    let translation = rod.impact(0, &[minus_one.clone(), minus_one]);
    Ok(Report {
        claim: claim.name().into(),
        n: 2,
        generators: Some(gens.len()),
        redundant: Some(redundant),
        pieces: Some(vec![piece.len()]),
        max_denominator_bits: Some(bits),
        pcc: None,
        contains_translation: Some(position(&translation).is_some_and(|x| lo <= x && x <= hi)),
        region: None,
        refutation: None,
    })
}
