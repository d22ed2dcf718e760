//! The oracle's verdict on a file: accepted with a report, or rejected with the rejection codes
//! that the first failing rule can give (docs/certificate-format.md §7), and how far the verdict
//! goes: two-sided (accepted exactly when every rule holds) or one-sided (a rejection is proved,
//! an acceptance only means that no counterexample was found).

/// What the oracle decides for a kind of file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sided {
    /// Accepted exactly when every documented rule holds.
    Two,
    /// A rejection is a proof that a rule fails; an acceptance is "no counterexample found".
    One,
}

/// The kind of file the oracle read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// Not read past the syntax, the header or the schema.
    Unread,
    /// A cone certificate of a regular polygon at a point (versions 1 to 3, rational or field).
    Cone,
    /// A cone certificate of the rod (n = 2).
    Rod,
    /// A box certificate (version 2 with an interval).
    Box,
    /// A family certificate of a general convex body (version 4).
    Family,
    /// An orbit certificate (version 5).
    Orbit,
    /// A refutation.
    Refutation,
    /// A basin certificate.
    Basin,
    /// A time-to-rest certificate (a virtual-time graph).
    Rest,
    /// A time-to-rest certificate of a general convex body (nodes carry a contact).
    RestFamily,
}

/// What an accepted file established, for comparison with the kernel's report.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Report {
    /// The claim's name.
    pub claim: String,
    /// Number of contacts.
    pub n: u64,
    /// Number of generators in the file (cone certificates).
    pub generators: Option<usize>,
    /// Generators that are not extreme rays or repeat an earlier one (cone certificates).
    pub redundant: Option<Vec<usize>>,
    /// Distinct vertices of each piece K ∩ C_j (or K_i ∩ C_ij).
    pub pieces: Option<Vec<usize>>,
    /// Largest denominator of a generator coordinate, in bits (rational cones).
    pub max_denominator_bits: Option<u64>,
    /// (p, q, p² - 4q) of the PCC quadratic, canonical text (point certificates claiming CC).
    pub pcc: Option<[String; 3]>,
    /// Whether K contains the post-impact velocity of a pure translation (cone certificates).
    pub contains_translation: Option<bool>,
    /// [lo, hi] of κ and γ for a box.
    pub region: Option<[[String; 2]; 2]>,
    /// For a refutation: the number of points, the last point's text and whether its v > 0.
    pub refutation: Option<(usize, Vec<String>, bool)>,
    /// For a basin certificate: the shares of the box (CC, ICC, undecided; canonical text) and
    /// the leaves of each kind.
    pub basin: Option<([String; 3], [usize; 3])>,
    /// For a time-to-rest certificate: the number of nodes of its virtual-time graph.
    pub rest_nodes: Option<usize>,
}

/// The oracle's verdict.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// Every rule holds (for a one-sided kind: no counterexample was found).
    Accept(Box<Report>),
    /// A rule fails: the codes the first failing rule may be reported with, and why.
    Reject {
        /// Rejection codes (kebab-case, docs/certificate-format.md §7) of the first failing rule.
        codes: Vec<&'static str>,
        /// What fails, for messages.
        why: String,
    },
}

/// The oracle's judgement of one file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Judgement {
    /// What was read.
    pub kind: Kind,
    /// How far the verdict goes.
    pub sided: Sided,
    /// The verdict.
    pub outcome: Outcome,
    /// The bound B on the time to rest, T ≤ B h/|v| (canonical text), of an accepted file: for a
    /// rod point certificate, its `time_to_rest_bound` as rule T1 shows it; for an orbit
    /// certificate T̄/(1 - ρ) (docs/certificate-format.md §5); for a time-to-rest certificate, its `bound`
    /// (rule G5, §16, and §17 for a general body); for a basin certificate, the largest
    /// exact (time to rest)/h over the drops the oracle followed into X, a lower bound of the
    /// kernel's bound. Kept beside the [`Report`], whose
    /// fields other crates fill in literally.
    pub time_to_rest_bound: Option<String>,
    /// [γ_lo, γ_hi] (canonical text) of an accepted family certificate whose γ is an interval
    /// (version 2, docs/certificate-format.md §13), as the kernel's `gamma_interval`; beside the
    /// [`Report`] for the same reason.
    pub gamma_interval: Option<[String; 2]>,
}

impl Judgement {
    /// A two-sided rejection with one code.
    pub fn reject(kind: Kind, code: &'static str, why: impl Into<String>) -> Judgement {
        let outcome = Outcome::Reject { codes: vec![code], why: why.into() };
        Judgement { kind, sided: Sided::Two, outcome, time_to_rest_bound: None, gamma_interval: None }
    }

    /// Whether the oracle accepts.
    pub fn accepted(&self) -> bool {
        matches!(self.outcome, Outcome::Accept(_))
    }

    /// The codes of a rejection (empty when accepted).
    pub fn codes(&self) -> &[&'static str] {
        match &self.outcome {
            Outcome::Accept(_) => &[],
            Outcome::Reject { codes, .. } => codes,
        }
    }
}

/// A rule failure inside the oracle's checks: the codes of the failing rule and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Fail {
    /// Possible codes of the failing rule.
    pub codes: Vec<&'static str>,
    /// What fails.
    pub why: String,
}

impl Fail {
    /// A failure with one code.
    pub fn new(code: &'static str, why: impl Into<String>) -> Fail {
        Fail { codes: vec![code], why: why.into() }
    }
}

/// The result of a check step.
pub type Checked<T> = Result<T, Fail>;
