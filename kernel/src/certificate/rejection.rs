//! Why a certificate is rejected: a stable code (for manifests and JSON) and a located message.

use serde::Serialize;
use std::fmt;

/// Stable rejection codes; `as_str` gives the kebab-case name used in JSON and manifests.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Code {
    /// Not RON, or a value of the wrong type.
    Syntax,
    /// A field the format does not have.
    UnknownField,
    /// A required field is absent.
    MissingField,
    /// A field given twice.
    DuplicateField,
    /// An enum value the format does not have.
    UnknownVariant,
    /// `format` is not "chatter-certificate".
    WrongFormat,
    /// A version this build does not read.
    UnsupportedVersion,
    /// A number that is not canonical `p/q` text.
    BadNumber,
    /// A body this build cannot model exactly (e.g. n = 5).
    UnsupportedBody,
    /// kappa <= 0 or gamma outside [0, 1].
    ParameterOutOfRange,
    /// A generator with the wrong number of coordinates.
    WrongArity,
    /// A generator with v >= 0.
    GeneratorNotBelow,
    /// The generators do not span a 3-D cone (empty, a ray, or a flat fan).
    DegenerateCone,
    /// An image S_j(p) with v >= 0 (condition 1 fails).
    ImageNotBelow,
    /// An image S_j(p) outside K (condition 2 fails).
    ImageOutside,
    /// An image I_0(g) of a generator g of D outside K, or with v >= 0.
    InitialOutside,
    /// The PCC Lemma does not apply (the quadratic factor has real roots, or roots of modulus >= 1).
    PccNotExcluded,
    /// The file asks for more work than a limit allows (generators, digits, file size): the
    /// limit is named. No verdict on the content.
    TooLarge,
    /// The time limit ran out before the check ended. No verdict on the content.
    TimeLimit,
    /// A proof's header is invalid (variables, coordinates, chi, hypotheses).
    InvalidHeader,
    /// A step of a proof does not check.
    StepFailed,
    /// An orbit certificate's set X is degenerate (delta <= 0, singular axes, an empty box).
    DegenerateSet,
    /// An orbit certificate's bounds are out of range (rho or lambda not in (0, 1), period <= 0)
    /// or its pattern is (empty, too long, a step outside 1..n-1).
    OrbitOutOfRange,
    /// Orbit condition 1: on a sub-box of X, the pattern's next impact is not shown to be forced.
    PatternNotForced,
    /// Orbit condition 2: on a sub-box of X, the return map is not shown to stay in X.
    SetNotInvariant,
    /// Orbit condition 3: on a sub-box of X, the scale factors or the flight time are not shown
    /// to be within the certificate's bounds.
    NoContraction,
    /// The model contradicts itself or the two backends disagree: a bug in chatter.
    Internal,
}

impl Code {
    /// The stable kebab-case name.
    pub fn as_str(self) -> &'static str {
        match self {
            Code::Syntax => "syntax",
            Code::UnknownField => "unknown-field",
            Code::MissingField => "missing-field",
            Code::DuplicateField => "duplicate-field",
            Code::UnknownVariant => "unknown-variant",
            Code::WrongFormat => "wrong-format",
            Code::UnsupportedVersion => "unsupported-version",
            Code::BadNumber => "bad-number",
            Code::UnsupportedBody => "unsupported-body",
            Code::ParameterOutOfRange => "parameter-out-of-range",
            Code::WrongArity => "wrong-arity",
            Code::GeneratorNotBelow => "generator-not-below",
            Code::DegenerateCone => "degenerate-cone",
            Code::ImageNotBelow => "image-not-below",
            Code::ImageOutside => "image-outside",
            Code::InitialOutside => "initial-outside",
            Code::PccNotExcluded => "pcc-not-excluded",
            Code::TooLarge => "too-large",
            Code::TimeLimit => "time-limit",
            Code::InvalidHeader => "invalid-header",
            Code::StepFailed => "step-failed",
            Code::DegenerateSet => "degenerate-set",
            Code::OrbitOutOfRange => "orbit-out-of-range",
            Code::PatternNotForced => "pattern-not-forced",
            Code::SetNotInvariant => "set-not-invariant",
            Code::NoContraction => "no-contraction",
            Code::Internal => "internal",
        }
    }
}

/// Where in a certificate (or proof) a check failed: structured, so that programs and tests
/// can act on it without parsing the message.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case", tag = "kind")]
pub enum Locus {
    /// A position in the text (1-based line and column): syntax and schema errors.
    Text {
        /// Line, from 1.
        line: usize,
        /// Column, from 1.
        column: usize,
    },
    /// A field, by its path, e.g. `body.kappa` or `cone[3].u1`.
    Field {
        /// The path.
        path: String,
    },
    /// Generator `index` of the cone (an index into `cone`).
    Generator {
        /// The index.
        index: usize,
    },
    /// The cone as a whole (e.g. it has no interior).
    Cone,
    /// The image under S_piece of vertex `vertex` of the piece K ∩ C_piece (rule R2).
    Piece {
        /// j of C_j and S_j.
        piece: usize,
        /// The vertex of K ∩ C_j, in the order the clipping produces them.
        vertex: usize,
        /// The part of K's boundary the image violates (`None` when its v is >= 0).
        outside: Option<Boundary>,
        /// For a box certificate, the corner whose maps fail: 0 to 3 for (kappa, gamma) at
        /// (lo, lo), (hi, lo), (lo, hi), (hi, hi) (omitted for a point).
        #[serde(skip_serializing_if = "Option::is_none")]
        corner: Option<usize>,
    },
    /// The image under I_0 of generator `generator` of the all-down cone D (rule R3).
    AllDown {
        /// The index of the generator of D.
        generator: usize,
        /// The part of K's boundary the image violates (`None` when its v is >= 0).
        outside: Option<Boundary>,
        /// For a box certificate, the corner whose map fails (see `Piece`).
        #[serde(skip_serializing_if = "Option::is_none")]
        corner: Option<usize>,
    },
    /// The PCC quadratic (rule R4).
    Pcc,
    /// Rule R4 on a box: the sub-box kappa x gamma on which PCC exclusion fails or could not
    /// be shown (a point when lo = hi).
    PccRegion {
        /// [lo, hi] of kappa, canonical text.
        kappa: Box<[String; 2]>,
        /// [lo, hi] of gamma, canonical text.
        gamma: Box<[String; 2]>,
    },
    /// Generator `index` of the cone K_`cone` of a `ConvexPolygon` certificate (rule K1).
    ConvexGenerator {
        /// i of K_i (an index into `cones`).
        cone: usize,
        /// The index into `cones[cone]`.
        index: usize,
    },
    /// The cone K_`cone` of a `ConvexPolygon` certificate as a whole (rule K1).
    ConvexCone {
        /// i of K_i.
        cone: usize,
    },
    /// The image under I_`to` of vertex `vertex` of K_`from` ∩ C_(`from`,`to`) (rule K2).
    Transition {
        /// i: the contact of the last impact, K_i.
        from: usize,
        /// j: the next contact, C_ij, I_j and K_j.
        to: usize,
        /// The vertex of K_i ∩ C_ij, in the order the clipping produces them.
        vertex: usize,
        /// The part of K_j's boundary the image violates (`None` when its v is >= 0); its
        /// generator indices are into `cones[to]`.
        outside: Option<Boundary>,
    },
    /// The image under I_`cone` of generator `generator` (-m_{k,k+1}, k = `generator`) of the
    /// all-down cone D (rule K3).
    ConvexAllDown {
        /// i of I_i and K_i.
        cone: usize,
        /// k of -m_{k,k+1}.
        generator: usize,
        /// The part of K_i's boundary the image violates (`None` when its v is >= 0).
        outside: Option<Boundary>,
    },
    /// The PCC quadratic of the adjacent pair (`pair`, `pair` + 1 mod n) (rule K4).
    PccPair {
        /// k of the pair (k, k+1).
        pair: usize,
    },
    /// Step `index` (from 0) of a proof, with its id.
    Step {
        /// Position in the list of steps.
        index: usize,
        /// The step's id.
        id: String,
    },
    /// A limit on the work a file may ask for (`too-large`, `time-limit`), by name, e.g.
    /// `max-generators`.
    Limit {
        /// The limit's name, as in docs/certificate-format.md §2.
        name: String,
    },
    /// A sub-box of an orbit certificate's set X, in the parameters y of X (x = x* + A y for a
    /// parallelepiped, x = y for a box), with the step of the pattern and the contact concerned
    /// when the failing check has them.
    OrbitBox {
        /// [lo, hi] of each coordinate of y, canonical text.
        sub_box: Box<[[String; 2]; 3]>,
        /// Bisections of X that gave the sub-box (0: all of X).
        depth: u64,
        /// The step of the pattern (from 0), for condition 1.
        #[serde(skip_serializing_if = "Option::is_none")]
        step: Option<usize>,
        /// The contact (label at that step), for condition 1.
        #[serde(skip_serializing_if = "Option::is_none")]
        contact: Option<usize>,
    },
    /// Nowhere in particular (internal errors).
    Nowhere,
}

/// A part of the boundary of K.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case", tag = "kind")]
pub enum Boundary {
    /// Edge `index` of the polygon K (counter-clockwise from its first vertex), between the
    /// extreme generators `from` and `to` (indices into `cone`).
    Edge {
        /// The edge's number.
        index: usize,
        /// The generator at its start.
        from: usize,
        /// The generator at its end.
        to: usize,
    },
    /// The rod's interval K ends at generator `generator` (an index into `cone`).
    End {
        /// The generator.
        generator: usize,
    },
}

/// A rejected certificate: the first failing check, exactly.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Rejection {
    /// The stable code.
    pub code: Code,
    /// Where the check failed.
    pub locus: Locus,
    /// What failed, in words and exact numbers (long numbers abbreviated).
    pub message: String,
}

impl Rejection {
    /// A rejection with a code, a locus and a message.
    pub fn new(code: Code, locus: Locus, message: impl Into<String>) -> Self {
        Rejection { code, locus, message: message.into() }
    }

    /// A rejection at a field.
    pub fn at_field(code: Code, path: impl Into<String>, message: impl std::fmt::Display) -> Self {
        let path = path.into();
        let message = format!("field `{path}`: {message}");
        Rejection { code, locus: Locus::Field { path }, message }
    }
}

impl Rejection {
    /// The time limit ran out (no verdict on the content).
    pub fn time_limit(during: &str) -> Self {
        let msg = format!("the time limit ran out while {during}: no verdict on the content");
        Rejection::new(Code::TimeLimit, Locus::Limit { name: "time-limit".into() }, msg)
    }

    /// Whether this rejection is a limit reached rather than a verdict on the content.
    pub fn is_limit(&self) -> bool {
        matches!(self.code, Code::TooLarge | Code::TimeLimit)
    }
}

impl fmt::Display for Rejection {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} [{}]", self.message, self.code.as_str())
    }
}

impl std::error::Error for Rejection {}
