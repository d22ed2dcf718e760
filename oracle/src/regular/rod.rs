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

/// K for the rod: the interval [lo, hi] of s and the redundant generators (rule R1).
pub struct Interval {
    lo: Rat,
    hi: Rat,
    redundant: Vec<usize>,
}

impl Interval {
    /// Whether a velocity is 0 or lies in K.
    fn holds(&self, p: &V2) -> bool {
        p.iter().all(Zero::is_zero) || position(p).is_some_and(|x| self.lo <= x && x <= self.hi)
    }
}

/// Rule R1 for the rod: every generator has v < 0 and K has two distinct ends.
pub fn interval(gens: &[V2]) -> Checked<Interval> {
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
    Ok(Interval { lo, hi, redundant })
}

/// Rule R2 for the rod: K ∩ C_1 = K ∩ {u0 ≥ 0} is [max(lo, 0), hi] in s, whose ends (s, -1 - s)
/// map into K; returns the number of ends.
pub fn invariance(rod: &Rod, k: &Interval) -> Checked<usize> {
    let piece: Vec<Rat> = match (k.hi.cmp(&Rat::zero()), k.lo.is_positive()) {
        (std::cmp::Ordering::Less, _) => vec![],
        (std::cmp::Ordering::Equal, _) => vec![k.hi.clone()],
        (_, true) => vec![k.lo.clone(), k.hi.clone()],
        (_, false) => vec![Rat::zero(), k.hi.clone()],
    };
    let mut codes = vec![];
    for x in &piece {
        let img = rod.step(&[x.clone(), -(Rat::one() + x)]);
        if !k.holds(&img) {
            let code = if position(&img).is_none() { "image-not-below" } else { "image-outside" };
            if !codes.contains(&code) {
                codes.push(code);
            }
        }
    }
    if !codes.is_empty() {
        return Err(Fail { codes, why: "an end of K ∩ C_1 maps outside K".into() });
    }
    Ok(piece.len())
}

/// Rule R3 for the rod: I_0 of (0, -1) and (-1, 0) lie in K.
pub fn all_down(rod: &Rod, k: &Interval) -> Checked<()> {
    let m1 = -Rat::one();
    for g in [[Rat::zero(), m1.clone()], [m1.clone(), Rat::zero()]] {
        if !k.holds(&rod.impact(0, &g)) {
            return Err(Fail::new("initial-outside", "I_0 of a generator of D is not in K"));
        }
    }
    Ok(())
}

/// Rules R1 to R3 (R4 holds trivially for the rod: PCC is CC with two contacts).
pub fn check_rod(rod: &Rod, claim: Claim, gens: &[V2], bits: u64) -> Checked<Report> {
    let k = interval(gens)?;
    let pieces = invariance(rod, &k)?;
    if claim >= Claim::CcOrPccFromAllDown {
        all_down(rod, &k)?;
    }
    let m1 = -Rat::one();
    let translation = rod.impact(0, &[m1.clone(), m1]);
    Ok(Report {
        claim: claim.name().into(),
        n: 2,
        generators: Some(gens.len()),
        redundant: Some(k.redundant.clone()),
        pieces: Some(vec![pieces]),
        max_denominator_bits: Some(bits),
        pcc: None,
        contains_translation: Some(position(&translation).is_some_and(|x| k.lo <= x && x <= k.hi)),
        region: None,
        refutation: None,
        basin: None,
        rest_nodes: None,
    })
}
