//! The claims of docs/certificate-format.md §5 (and §14's orbit claim), strongest last.

/// A claim.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Claim {
    /// Conditions 1-2 of docs/model.md §5 (rules R1, R2).
    EffectivelyInvariant,
    /// CC or PCC from every all-down drop (adds R3).
    CcOrPccFromAllDown,
    /// CC from every all-down drop (adds R4).
    CompleteChatterFromAllDown,
    /// The orbit certificates' claim (§14).
    CompleteChatterFromSet,
}

impl Claim {
    /// Every claim with its name.
    pub const ALL: [(Claim, &'static str); 4] = [
        (Claim::EffectivelyInvariant, "EffectivelyInvariant"),
        (Claim::CcOrPccFromAllDown, "CcOrPccFromAllDown"),
        (Claim::CompleteChatterFromAllDown, "CompleteChatterFromAllDown"),
        (Claim::CompleteChatterFromSet, "CompleteChatterFromSet"),
    ];

    /// The claim's name in files.
    pub fn name(self) -> &'static str {
        Claim::ALL.iter().find(|(c, _)| *c == self).expect("listed").1
    }

    /// The claim of a name.
    pub fn of_name(s: &str) -> Option<Claim> {
        Claim::ALL.iter().find(|(_, n)| *n == s).map(|(c, _)| *c)
    }

    /// Whether the claim is about drops (needs 0 < γ < 1, docs/kernel-soundness.md "The range of γ").
    pub fn about_drops(self) -> bool {
        self > Claim::EffectivelyInvariant
    }
}
