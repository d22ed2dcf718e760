//! How many of a map's drops were decided with a proof, overall and away from the thresholds,
//! and the exact engine's wall time per decided drop (issue 22 §3; docs/map.md "Proof shares").
//! Printed by `chatter map`, never written to its folder (the times depend on the machine).

use super::Done;
use super::point::criteria;
use crate::exact::Q;
use crate::simulate::Outcome;

/// Whether a point lies in the band of half-width `half` in γ around a threshold: the exact CC
/// criterion or the exact PCC criterion at (κ, γ − half) or (κ, γ + half) differs from its value
/// at (κ, γ) (a side outside (0, 1) is not looked at).
pub fn near_threshold(n: u64, kappa: &Q, gamma: &Q, half: &Q) -> bool {
    let here = criteria(n, kappa, gamma);
    [gamma - half, gamma + half]
        .iter()
        .filter(|g| **g > Q::int(0) && **g < Q::int(1))
        .any(|g| criteria(n, kappa, g) != here)
}

/// Whether a drop's outcome is decided with a proof: CC, PCC, ICC or simultaneous impacts
/// proved (no-ICC-no-PCC, proved by a cone alone, is not a decided outcome).
pub fn decided(o: Outcome) -> bool {
    matches!(o, Outcome::Cc | Outcome::Pcc | Outcome::Icc | Outcome::Simultaneous)
}

/// Drop counts of one part of a map.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Share {
    /// Drops run with proofs.
    pub drops: u64,
    /// Drops decided with a proof ([`decided`]).
    pub decided: u64,
    /// Drops proved no-ICC-no-PCC only.
    pub no_icc_no_pcc: u64,
}

impl Share {
    fn add(&mut self, o: Outcome) {
        self.drops += 1;
        self.decided += decided(o) as u64;
        self.no_icc_no_pcc += (o == Outcome::NoIccNoPcc) as u64;
    }

    /// The decided share in percent (0 with no drops).
    pub fn percent(&self) -> f64 {
        if self.drops == 0 { 0.0 } else { 100.0 * self.decided as f64 / self.drops as f64 }
    }
}

/// The shares of a map's drops and the wall times of the decided ones.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ProofShares {
    /// Every drop.
    pub all: Share,
    /// The drops at points outside the band ([`near_threshold`]).
    pub off_band: Share,
    /// Points in the band.
    pub band_points: u64,
    /// Wall time of the exact run(s) of each decided drop, seconds, sorted.
    pub seconds: Vec<f64>,
}

impl ProofShares {
    /// The median of [`ProofShares::seconds`] (mean of the middle two for an even count).
    pub fn median_seconds(&self) -> Option<f64> {
        let s = &self.seconds;
        let m = s.len() / 2;
        match s.len() {
            0 => None,
            k if k % 2 == 1 => Some(s[m]),
            _ => Some((s[m - 1] + s[m]) / 2.0),
        }
    }
}

/// The shares over the points of a map evaluated with proofs; `half` the band's half-width.
pub fn shares(n: u64, done: &[Done], half: &Q) -> ProofShares {
    let mut out = ProofShares::default();
    for d in done.iter().filter(|d| !d.proof_times.is_empty()) {
        let near = near_threshold(n, &d.row.kappa, &d.row.gamma, half);
        out.band_points += near as u64;
        for (o, secs) in &d.proof_times {
            out.all.add(*o);
            if !near {
                out.off_band.add(*o);
            }
            if decided(*o) {
                out.seconds.push(*secs);
            }
        }
    }
    out.seconds.sort_by(f64::total_cmp);
    out
}

/// The lines `map` prints about the proofs (none when no proofs were run).
pub fn lines(n: u64, done: &[Done]) -> Vec<String> {
    let s = shares(n, done, &Q::new(1, 200));
    if s.all.drops == 0 {
        return Vec::new();
    }
    let part = |name: &str, p: &Share| {
        format!(
            "  proofs {name}: {} of {} drops decided with a proof ({:.1}%), {} no-ICC-no-PCC only",
            p.decided,
            p.drops,
            p.percent(),
            p.no_icc_no_pcc
        )
    };
    let mut out = vec![
        part("overall", &s.all),
        part(
            &format!("off the band |gamma - threshold| < 0.005 ({} points in it)", s.band_points),
            &s.off_band,
        ),
    ];
    if let Some(m) = s.median_seconds() {
        let max = s.seconds.last().copied().unwrap_or(0.0);
        out.push(format!(
            "  proofs: exact wall time per decided drop: median {:.3} ms, max {:.1} ms (certificates made once per point not included)",
            m * 1e3,
            max * 1e3
        ));
    }
    out
}
