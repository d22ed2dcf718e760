//! Why a file is rejected, typed: a stable [`Code`] (for manifests and JSON), a structured
//! [`Locus`], and the few exact values that explain the failure ([`Detail`]). The rules build
//! rejections from these types only; the words of a message are rendered outside the trusted
//! path, by `crate::explain` (feature `explain`).

use crate::exact::NumberError;
use crate::model::pcc::PccExclusion;
use crate::model::polygon::BodyError;
use crate::syntax::cone::Claim;
use crate::syntax::strict::Offence;
use serde::Serialize;

#[cfg(feature = "kinds")]
#[macro_use]
mod kinds;
#[cfg(feature = "kinds")]
pub use kinds::{KindCounted, KindDetail, KindInternal, KindLocus};

/// Declares [`Code`] with its stable kebab-case names.
macro_rules! declare_codes {
    ($($(#[$doc:meta])* $name:ident = $text:literal,)*) => {
        /// Stable rejection codes; [`Code::as_str`] gives the name used in JSON and manifests.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum Code { $($(#[$doc])* $name,)* }
        impl Code {
            /// The stable kebab-case name.
            pub fn as_str(self) -> &'static str {
                match self { $(Code::$name => $text,)* }
            }
        }
    };
}

/// The codes of point certificates (below), and with the feature `kinds` those of the other kinds
/// too (`reject/kinds.rs`), declared as one [`Code`].
#[cfg(not(feature = "kinds"))]
macro_rules! codes {
    ($($t:tt)*) => { declare_codes! { $($t)* } };
}

codes! {
    /// Not RON (or JSON), or a value of the wrong type.
    Syntax = "syntax",
    /// A field the format does not have.
    UnknownField = "unknown-field",
    /// A required field is absent.
    MissingField = "missing-field",
    /// A field given twice.
    DuplicateField = "duplicate-field",
    /// An enum value the format does not have.
    UnknownVariant = "unknown-variant",
    /// `format` names no kind this build reads.
    WrongFormat = "wrong-format",
    /// A version this build does not read.
    UnsupportedVersion = "unsupported-version",
    /// A number that is not canonical text.
    BadNumber = "bad-number",
    /// A body this build cannot model exactly.
    UnsupportedBody = "unsupported-body",
    /// kappa <= 0, gamma outside [0, 1] (or outside (0, 1) for a claim about drops), an empty interval.
    ParameterOutOfRange = "parameter-out-of-range",
    /// A generator with the wrong number of coordinates, or the wrong number of cones.
    WrongArity = "wrong-arity",
    /// A generator with v >= 0.
    GeneratorNotBelow = "generator-not-below",
    /// The generators do not span a full-dimensional cone.
    DegenerateCone = "degenerate-cone",
    /// An image with v >= 0 (rule R2, K2).
    ImageNotBelow = "image-not-below",
    /// An image outside the cone (rule R2, K2).
    ImageOutside = "image-outside",
    /// An image of a generator of D outside the cone, or with v >= 0 (rule R3, K3).
    InitialOutside = "initial-outside",
    /// The PCC Lemma does not apply (rule R4, K4).
    PccNotExcluded = "pcc-not-excluded",
    /// The optional `time_to_rest_bound` is not shown (rule T1, docs/time-to-rest.md §2).
    TimeToRestNotShown = "time-to-rest-not-shown",
    /// A limit on the work a file may ask for is exceeded. No verdict on the content.
    TooLarge = "too-large",
    /// The time limit ran out. No verdict on the content.
    TimeLimit = "time-limit",
    /// The model contradicts itself or the two backends disagree: a bug in chatter.
    Internal = "internal",
}

/// Where in a file a check failed: structured, so that programs and tests can act on it
/// without parsing the message (docs/certificate-format.md §5, "Loci").
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
        /// For a box certificate, the corner: 0 to 3 for (kappa, gamma) at (lo, lo), (hi, lo),
        /// (lo, hi), (hi, hi) (omitted for a point).
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
    /// A limit on the work a file may ask for, by name, e.g. `max-generators`.
    Limit {
        /// The limit's name, as in docs/certificate-format.md §2.
        name: String,
    },
    /// Nowhere in particular (internal errors).
    Nowhere,
    /// A place in a file of another kind than point certificates, written as that place.
    #[cfg(feature = "kinds")]
    #[serde(untagged)]
    Kind(KindLocus),
}

/// A part of the boundary of K.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case", tag = "kind")]
pub enum Boundary {
    /// Edge `index` of the polygon K, between the extreme generators `from` and `to`.
    Edge {
        /// The edge's number.
        index: usize,
        /// The generator at its start.
        from: usize,
        /// The generator at its end.
        to: usize,
    },
    /// The rod's interval K ends at generator `generator`.
    End {
        /// The generator.
        generator: usize,
    },
}

/// A rejected file: the first failing check, exactly.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Rejection {
    /// The stable code.
    pub code: Code,
    /// Where the check failed.
    pub locus: Locus,
    /// The exact values that explain the failure (boxed: a rejection is passed around often,
    /// produced once).
    pub detail: Box<Detail>,
}

impl Rejection {
    /// A rejection with a code, a locus and its detail.
    pub fn new(code: Code, locus: impl Into<Locus>, detail: impl Into<Detail>) -> Self {
        Rejection { code, locus: locus.into(), detail: Box::new(detail.into()) }
    }

    /// A rejection at a field, by its path.
    pub fn at(code: Code, path: impl Into<String>, detail: impl Into<Detail>) -> Self {
        Rejection::new(code, Locus::Field { path: path.into() }, detail)
    }

    /// `time-limit` (no verdict on the content), while doing `during`.
    pub fn time_limit(during: impl Into<String>) -> Self {
        let locus = Locus::Limit { name: "time-limit".into() };
        Rejection::new(Code::TimeLimit, locus, Detail::Time(during.into()))
    }

    /// A limit `name` exceeded (`too-large`, no verdict on the content).
    pub fn limit(name: &str, count: usize, limit: usize, what: Counted) -> Self {
        let locus = Locus::Limit { name: name.into() };
        Rejection::new(Code::TooLarge, locus, Detail::Limit(count, limit, what))
    }
}

/// What a limit counted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Counted {
    /// The generators of the cone.
    Generators,
    /// The characters of all numbers of the file.
    Characters,
    /// What a limit of another kind of file than point certificates counted.
    #[cfg(feature = "kinds")]
    Kind(KindCounted),
}

/// What a version or a format needs that the file or this build does not have.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Needs {
    /// Parameter intervals need version 2.
    Intervals,
    /// Number-field elements need version 3.
    FieldElements,
    /// A kind of file this build was compiled without (the Cargo feature's name).
    Feature(&'static str),
    /// Another kind of file than the reader's (its format string).
    Kind(&'static str),
}

/// The exact values that explain a rejection, by kind of failure (the fields in the order said).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Detail {
    /// A lexical rule of the strict syntax (what, whether the file is the JSON twin).
    Lexical(Offence, bool),
    /// The RON or JSON parser's description of a schema or grammar error.
    Parser(String),
    /// A required header field is absent.
    Missing,
    /// A `format` this reader does not read (the reader's, the file's).
    Format(&'static str, Option<String>),
    /// A version this build does not read for the file's format (the file's, [lo, hi] read).
    Version(u64, [u64; 2]),
    /// The file, or this build, lacks what its content needs (what, the file's version).
    Needs(Needs, u64),
    /// A cone certificate names the orbit claim `CompleteChatterFromSet`.
    OrbitClaim,
    /// A number that is not canonical text, or too long (the text as written, why).
    Number(String, NumberError),
    /// A limit exceeded (what the file asks for, the limit, of what).
    Limit(usize, usize, Counted),
    /// A file beyond `max-file-size`, reported by the tool, which reads files (its size in
    /// words, the limit in bytes).
    FileSize(String, u64),
    /// The time limit ran out (while doing what).
    Time(String),
    /// A body of a regular polygon or rod the model rejects.
    Body(BodyError),
    /// gamma = 0 or 1 with a claim about drops (gamma, the claim, whether the body is a general
    /// convex body, Theorem 11.4, rather than a regular one).
    GammaForClaim(String, Claim, bool),
    /// A generator of the wrong length (the names of the coordinates expected, the number found).
    Arity(&'static [&'static str], usize),
    /// A generator with v >= 0, with its coordinates as written.
    NotBelow(Vec<String>),
    /// Fewer extreme rays than K's dimension (generators, distinct extreme rays, dimension).
    Degenerate(usize, usize, usize),
    /// An image (rules R2, R3, K2, K3) with v >= 0 or outside the cone.
    Image(Box<ImageFailure>),
    /// The PCC quadratic t^2 + p t + q of rule R4 (or K4) does not exclude PCC (n, [p, q,
    /// p^2 - 4q] as canonical text, which condition fails).
    Pcc(usize, Box<[String; 3]>, PccExclusion),
    /// Rule T1: the `time_to_rest_bound` B is not shown (why; B as written).
    TimeToRest(TimeToRestFailure, String),
    /// The model contradicts itself (a bug).
    Internal(Internal),
    /// The exact values of a rejection of another kind of file than point certificates.
    #[cfg(feature = "kinds")]
    Kind(KindDetail),
}

/// Why rule T1 (docs/time-to-rest.md §2) does not show the bound B.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TimeToRestFailure {
    /// Only point certificates of the rod (n = 2) may carry B: no theorem covers other bodies.
    NotRod,
    /// The claim is `EffectivelyInvariant`, which says nothing about drops.
    Claim,
    /// B <= 0.
    NotPositive,
    /// kappa >= 1, so sigma = (1 + gamma)(1 - kappa)/(1 + kappa) <= 0.
    SigmaNotPositive,
    /// sigma^2 - 4 gamma < 0: the roots lambda are not real.
    ComplexRoots,
    /// 1/B exceeds lambda_1, the larger root of lambda^2 - sigma lambda + gamma.
    TooSmall,
}

/// An image that is not in the cone: the point mapped and its image, projected to the plane of
/// the cone's cross-section (canonical text), and how far outside.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ImageFailure {
    /// n of the body (2 for the rod).
    pub n: usize,
    /// The point mapped, projected.
    pub point: Vec<String>,
    /// The image projected, when its v is < 0.
    pub image: Option<Vec<String>>,
    /// When the image has v >= 0: whether v = 0 (else v > 0).
    pub v_zero: bool,
    /// The amount outside (orient2d for a polygon, the difference in s for the rod).
    pub by: Option<String>,
    /// For a box certificate, (kappa, gamma) of the corner, canonical text.
    pub corner: Option<[String; 2]>,
}

/// A contradiction of the model with itself (never expected: a bug in chatter).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Internal {
    /// t = 1 is not a root of det(tI - S_{n-1} S_1) (rule R4): its value there, canonical text.
    NotARoot(String),
    /// A point with v < 0 outside the convex polygon K violates no edge.
    NoEdge,
    /// A contradiction in the model of another kind of file than point certificates.
    #[cfg(feature = "kinds")]
    Kind(KindInternal),
}
