//! What the rules report: an accepted certificate's facts.

use crate::syntax::cone::Claim;

/// What an accepted certificate established.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Accepted {
    /// The claim established.
    pub claim: Claim,
    /// Number of contacts.
    pub n: u64,
    /// Number of generators in the file.
    pub generators: usize,
    /// Indices of generators that are not extreme rays of K (allowed, reported).
    pub redundant: Vec<usize>,
    /// For j = 1..n-1, the number of vertices of K ∩ C_j whose images were checked.
    pub pieces: Vec<usize>,
    /// Largest denominator among the generators' coordinates, in bits.
    pub max_denominator_bits: u64,
    /// For `CompleteChatterFromAllDown` with n >= 3: (p, q, discriminant) of the PCC quadratic,
    /// canonical text.
    pub pcc: Option<[String; 3]>,
    /// Whether K contains the velocity after the first impact of a pure downward translation
    /// (informational); for a box, at every corner. False for orbit certificates (no cone).
    pub contains_translation: bool,
    /// For a box certificate: the bounds [lo, hi] of kappa and of gamma, canonical text.
    pub region: Option<[[String; 2]; 2]>,
    /// For `CompleteChatterFromAllDown` on a box: the sub-boxes of the Bernstein subdivision.
    pub pcc_boxes: Option<usize>,
    /// For an orbit certificate: the number of sub-boxes of X on which conditions 1-3 were shown.
    pub orbit_boxes: Option<usize>,
    /// Rule T1: the bound B on the time to rest, canonical text, when the file carries it.
    pub time_to_rest_bound: Option<String>,
}

impl Accepted {
    /// The facts of a cone certificate (the fields of boxes and orbits empty).
    pub fn cone(claim: Claim, n: usize, generators: usize, pieces: Vec<usize>) -> Self {
        Accepted { claim, n: n as u64, generators, pieces, ..Default::default() }
    }
}
