//! The loci and exact values of rejections of the kinds of file beyond point certificates
//! (boxes, number fields, families, orbits, basins, refutations, proofs): part of [`Locus`](super::Locus)
//! and [`Detail`](super::Detail), written as the other loci. A reviewer of point certificates
//! does not read this file.

use super::{Counted, Detail, Internal, Locus};
use serde::Serialize;

#[cfg(any(feature = "family", feature = "rest"))]
use super::Boundary;
#[cfg(feature = "family")]
use crate::model::convex::shape::ConvexBodyError;
#[cfg(feature = "basin")]
use crate::rules::basin::Failure as BasinFailure;
#[cfg(feature = "boxes")]
use crate::rules::boxes::PccPolynomial;
#[cfg(feature = "family")]
use crate::rules::family::TensorFailure;
#[cfg(feature = "orbit")]
use crate::rules::orbit::Failure as OrbitFailure;
#[cfg(feature = "proof")]
use crate::rules::proof::Failure as ProofFailure;
#[cfg(feature = "refutation")]
use crate::rules::refutation::Failure as RefutationFailure;
#[cfg(feature = "rest")]
use crate::rules::rest::Failure as RestFailure;

/// Declares [`Code`](super::Code) with the codes of point certificates (`$t`, in `reject/mod.rs`)
/// and those of the other kinds, below.
macro_rules! codes {
    ($($t:tt)*) => {
        declare_codes! {
            $($t)*
            /// A proof's header is invalid (variables, coordinates, chi, hypotheses).
            InvalidHeader = "invalid-header",
            /// A step of a refutation does not check.
            StepFailed = "step-failed",
            /// A proof's expression is not canonical text, or malformed.
            BadExpression = "bad-expression",
            /// A proof names a variable, atom, point, cone or map that does not exist.
            UnknownName = "unknown-name",
            /// A proof gives a name (id, atom, point, cone, parameter value) twice.
            DuplicateName = "duplicate-name",
            /// A proof uses a name where it is not allowed (defining a parameter, a bound variable, ...).
            MisusedName = "misused-name",
            /// A proof's identity does not hold on its region.
            NotAnIdentity = "not-an-identity",
            /// A sign a proof needs is not proved (or is wrong).
            SignNotProved = "sign-not-proved",
            /// A proof's positivity certificate is malformed.
            BadCertificate = "bad-certificate",
            /// A proof's cone or clipping data is malformed.
            BadCone = "bad-cone",
            /// A proof's witness (Sturm sequence, root count, values at a point) does not check.
            BadWitness = "bad-witness",
            /// An orbit certificate's set X is degenerate.
            DegenerateSet = "degenerate-set",
            /// An orbit certificate's bounds, claim or pattern are out of range.
            OrbitOutOfRange = "orbit-out-of-range",
            /// Orbit condition 1 is not shown on a sub-box.
            PatternNotForced = "pattern-not-forced",
            /// Orbit condition 2 is not shown on a sub-box.
            SetNotInvariant = "set-not-invariant",
            /// Orbit condition 3 is not shown on a sub-box.
            NoContraction = "no-contraction",
            /// A family certificate's J is not J_eff of its full inertia tensor (rule K0).
            InertiaNotDerived = "inertia-not-derived",
            /// A basin certificate's box, paths, prefixes or embedded orbit certificate's body are out of range.
            BasinOutOfRange = "basin-out-of-range",
            /// A basin certificate's leaves are not the leaves of one bisection tree of its box.
            NotAPartition = "not-a-partition",
            /// A basin certificate's leaf: its prefix, or where it ends, is not shown on the whole leaf.
            LeafNotShown = "leaf-not-shown",
            /// A time-to-rest node's virtual time is not defined and >= 0 (rules G1, G2).
            VirtualTimeNotPositive = "virtual-time-not-positive",
            /// A step that a time-to-rest node allows has no successor node (rule G3).
            MissingSuccessor = "missing-successor",
            /// The virtual time grows at an impact (rule G3) or falls slower than time in a flight (F).
            VirtualTimeIncreases = "virtual-time-increases",
            /// The bound B of a time-to-rest certificate is too small (rule G5).
            BoundTooSmall = "bound-too-small",
        }
    };
}

/// Where in a file of another kind a check failed (docs/certificate-format.md §5, "Loci").
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case", tag = "kind")]
pub enum KindLocus {
    /// Rule R4 on a box: the sub-box on which PCC exclusion fails or is not shown.
    #[cfg(feature = "boxes")]
    PccRegion {
        /// [lo, hi] of kappa, canonical text.
        kappa: Box<[String; 2]>,
        /// [lo, hi] of gamma, canonical text.
        gamma: Box<[String; 2]>,
    },
    /// Generator `index` of the cone K_`cone` of a family certificate (rule K1).
    #[cfg(feature = "family")]
    ConvexGenerator {
        /// i of K_i.
        cone: usize,
        /// The index into `cones[cone]`.
        index: usize,
    },
    /// The cone K_`cone` of a family certificate as a whole (rule K1).
    #[cfg(feature = "family")]
    ConvexCone {
        /// i of K_i.
        cone: usize,
    },
    /// The image under I_`to` of vertex `vertex` of K_`from` ∩ C_(`from`,`to`) (rule K2).
    #[cfg(feature = "family")]
    Transition {
        /// i: the contact of the last impact.
        from: usize,
        /// j: the next contact.
        to: usize,
        /// The vertex of K_i ∩ C_ij, in the order the clipping produces them.
        vertex: usize,
        /// The part of K_j's boundary the image violates (`None` when its v is >= 0).
        outside: Option<Boundary>,
        /// With gamma an interval: the end at which the image fails, canonical text.
        #[serde(skip_serializing_if = "Option::is_none")]
        gamma: Option<String>,
    },
    /// The image under I_`cone` of generator `generator` of D (rule K3).
    #[cfg(feature = "family")]
    ConvexAllDown {
        /// i of I_i and K_i.
        cone: usize,
        /// k of -m_{k,k+1}.
        generator: usize,
        /// The part of K_i's boundary the image violates (`None` when its v is >= 0).
        outside: Option<Boundary>,
        /// With gamma an interval: the end at which the image fails, canonical text.
        #[serde(skip_serializing_if = "Option::is_none")]
        gamma: Option<String>,
    },
    /// The PCC quadratic of the adjacent pair (`pair`, `pair` + 1 mod n) (rule K4).
    #[cfg(feature = "family")]
    PccPair {
        /// k of the pair (k, k+1).
        pair: usize,
        /// With gamma an interval: the end at which PCC is not excluded, canonical text.
        #[serde(skip_serializing_if = "Option::is_none")]
        gamma: Option<String>,
    },
    /// Step `index` (from 0) of a proof or refutation, with its id.
    #[cfg(any(feature = "proof", feature = "refutation"))]
    Step {
        /// Position in the list of steps.
        index: usize,
        /// The step's id.
        id: String,
    },
    /// A sub-box of an orbit certificate's set X, in the parameters y of X.
    #[cfg(feature = "orbit")]
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
    /// A leaf of a basin certificate (its index in `leaves`, its path).
    #[cfg(feature = "basin")]
    BasinLeaf {
        /// The index in `leaves`.
        leaf: usize,
        /// Its bisection path.
        path: String,
    },
    /// A node of a time-to-rest certificate, with the step j and the vertex of K_r ∩ C_j.
    #[cfg(feature = "rest")]
    RestNode {
        /// The node r.
        node: usize,
        /// The step j.
        #[serde(skip_serializing_if = "Option::is_none")]
        step: Option<u64>,
        /// The vertex of K_r ∩ C_j (G3).
        #[serde(skip_serializing_if = "Option::is_none")]
        vertex: Option<usize>,
        /// For an image outside the successor's cone: the boundary it crosses.
        #[serde(skip_serializing_if = "Option::is_none")]
        outside: Option<Boundary>,
        /// On a box of parameters: the corner (0 to 3, docs/certificate-format.md §9).
        #[serde(skip_serializing_if = "Option::is_none")]
        corner: Option<usize>,
        /// For a general body over an interval of γ: the end where the check fails (boxed, so that
        /// a rejection stays small).
        #[serde(skip_serializing_if = "Option::is_none")]
        gamma: Option<Box<str>>,
    },
}

/// The exact values that explain a rejection of another kind of file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum KindDetail {
    /// n beyond the regular polygons the kernel models (n, the largest n).
    #[cfg(feature = "field")]
    Contacts(u64, u64),
    /// A parameter interval where cos(2 pi/n) is irrational (n).
    #[cfg(any(feature = "field", feature = "boxes"))]
    IntervalIrrational(u64),
    /// An empty parameter interval [lo, hi], lo > hi (canonical text).
    #[cfg(any(feature = "boxes", feature = "family"))]
    EmptyInterval(String, String),
    /// A family with the wrong number of cones (found, the body's contacts or the most contacts
    /// of a body, whether the latter).
    #[cfg(feature = "family")]
    ConeCount(usize, usize, bool),
    /// Rule R4 on a box: a polynomial not shown negative on the sub-box of the locus (which,
    /// whether it is >= 0 at the sub-box's corner rather than not shown within, the limit).
    #[cfg(feature = "boxes")]
    PccBox(PccPolynomial, bool, usize),
    /// A family certificate's body.
    #[cfg(feature = "family")]
    Convex(ConvexBodyError),
    /// Rule K0: a family certificate's J is not J_eff of its inertia tensor.
    #[cfg(feature = "family")]
    Tensor(TensorFailure),
    /// An orbit certificate's failure.
    #[cfg(feature = "orbit")]
    Orbit(OrbitFailure),
    /// A basin certificate's failure.
    #[cfg(feature = "basin")]
    Basin(BasinFailure),
    /// A refutation's failure.
    #[cfg(feature = "refutation")]
    Refutation(RefutationFailure),
    /// A time-to-rest certificate's failure.
    #[cfg(feature = "rest")]
    Rest(RestFailure),
    /// A proof's failure.
    #[cfg(feature = "proof")]
    Proof(ProofFailure),
}

impl From<KindLocus> for Locus {
    fn from(l: KindLocus) -> Self {
        Locus::Kind(l)
    }
}

impl From<KindDetail> for Detail {
    fn from(d: KindDetail) -> Self {
        Detail::Kind(d)
    }
}

/// What a limit of a kind of file beyond point certificates counted (part of
/// [`Counted`](super::Counted)).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum KindCounted {
    /// The generators of cone `i` of a family.
    ConeGenerators(usize),
    /// The points of a refutation.
    Points,
    /// The subdivision depth of an orbit certificate.
    Depth,
    /// The sub-boxes an orbit certificate made the kernel examine.
    Boxes,
    /// The leaves of a basin certificate.
    Leaves,
    /// The impacts of a basin certificate's prefix.
    Prefix,
    /// The impacts of a basin certificate's `Tree` leaf.
    Tree,
}

impl From<KindCounted> for Counted {
    fn from(c: KindCounted) -> Self {
        Counted::Kind(c)
    }
}

/// A contradiction of the model of a kind of file beyond point certificates with itself (part of
/// [`Internal`](super::Internal); never expected: a bug in chatter).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum KindInternal {
    /// The cone C_j (the rod's C_1 when `j` is `None`) differs between corners of a box.
    CornersDiffer(Option<usize>),
    /// On a box, t = 1 is not a root of the PCC characteristic polynomial (as a polynomial).
    NotARootOnBox,
    /// The value at t = 1 of a general body's PCC polynomial (rule K4), canonical text, which is
    /// not 0, and the adjacent pair (k, k + 1).
    NotARootAtPair(String, (usize, usize)),
    /// No cone C_(i, j) for i != j.
    NoCone(usize, usize),
}

impl From<KindInternal> for Detail {
    fn from(i: KindInternal) -> Self {
        Detail::Internal(Internal::Kind(i))
    }
}
