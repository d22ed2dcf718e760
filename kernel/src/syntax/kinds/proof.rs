//! The schema of proofs (docs/proof-format.md §2): format `"chatter-proof"`, version 1, RON
//! only. Expressions stay text here; the checker parses them with the proof's variables.

use crate::syntax::{Kind, Schema};
use serde::{Deserialize, Serialize};

/// Value of the `format` field.
pub const FORMAT: &str = "chatter-proof";
/// The one version this build reads.
pub const VERSION: u64 = 1;

/// A proof about a body of the model, for all parameters at once.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(rename = "Proof", deny_unknown_fields)]
pub struct ProofFile {
    /// Always [`FORMAT`].
    pub format: String,
    /// Always [`VERSION`].
    pub version: u64,
    /// A short name, e.g. "square".
    pub name: String,
    /// What the proof establishes, in words (informational; the checker reports what it checked).
    pub statement: String,
    /// The body whose model the maps and cones come from.
    pub body: ProofBody,
    /// Which variables stand for gamma and kappa.
    pub parameters: Parameters,
    /// All variable names, in the order that fixes the canonical term order.
    pub variables: Vec<String>,
    /// The rows of M with p_model = M p_proof; the third row must be (0, 0, 1) (same v).
    pub coordinates: [[String; 3]; 3],
    /// The eigenvalue variable, the step map it belongs to, and its characteristic polynomial.
    pub eigenvalue: Eigenvalue,
    /// Named expressions assumed positive.
    pub hypotheses: Vec<Hypothesis>,
    /// The steps, in order; each may use only what comes before it.
    pub steps: Vec<Step>,
}

/// The body of a proof.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub enum ProofBody {
    /// A regular polygon of contacts with rational cos(2 pi/n) (n = 3, 4, 6), for all kappa and gamma.
    RegularPolygon {
        /// Number of contacts.
        n: u64,
    },
}

/// The variables standing for the model's parameters.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Parameters {
    /// The coefficient of restitution.
    pub gamma: String,
    /// kappa = rho^2 / R^2.
    pub kappa: String,
}

/// lambda: a root of chi(lambda) = (kappa + 1) det(lambda I - S_map), i.e. an eigenvalue of S_map.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Eigenvalue {
    /// The variable.
    pub variable: String,
    /// j of the step map S_j.
    pub map: u64,
    /// chi, canonical polynomial text.
    pub chi: String,
}

/// An expression assumed positive, usable as an atom by its name.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Hypothesis {
    /// The atom's name.
    pub name: String,
    /// A polynomial.
    pub expr: String,
}

/// One step. Expressions are canonical polynomials, or `(N) / [a] [b]` for N over a product of
/// polynomial atoms.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub enum Step {
    /// `expr > 0`, because `expr = (sum of c * product of atoms) / (product of atoms in over)`
    /// with every `c > 0`; the step becomes an atom named `id`.
    Positive {
        /// The step's id and atom name.
        id: String,
        /// The expression proved positive.
        expr: String,
        /// The certificate's terms: a positive rational and a list of atoms.
        terms: Vec<(String, Vec<String>)>,
        /// Polynomial atoms dividing the certificate.
        over: Vec<String>,
    },
    /// `lhs = rhs` at every point of the region.
    Identity {
        /// The step's id.
        id: String,
        /// Left side.
        lhs: String,
        /// Right side.
        rhs: String,
    },
    /// Defines the variable `id` as `num / den`; `positive` names the step proving `den > 0`
    /// (`None` when `den` is a positive constant).
    Define {
        /// The variable defined.
        id: String,
        /// Numerator (a polynomial).
        num: String,
        /// Denominator (a polynomial).
        den: String,
        /// The step proving `den > 0`.
        positive: Option<String>,
    },
    /// The image of a named point under a map of the model (`"S1"`, ..., or `"I0"`) equals a
    /// combination of named points with the given coefficients.
    Image {
        /// The step's id.
        id: String,
        /// The map.
        map: String,
        /// The point mapped.
        point: String,
        /// (coefficient, point) pairs.
        equals: Vec<(String, String)>,
    },
    /// Names the point (x, y, -1) of the plane v = -1, in the proof's coordinates.
    Point {
        /// The point's name.
        id: String,
        /// First coordinate.
        x: String,
        /// Second coordinate.
        y: String,
    },
    /// Every real root of chi is below `below`: the coefficients of chi(below + s) in `variable`
    /// are positive (steps `{id}.{d}`, or positive constants). The atom `id` is `below - lambda`.
    RootBound {
        /// The step's id and atom name.
        id: String,
        /// The bound, a rational.
        below: String,
        /// The auxiliary variable s.
        variable: String,
    },
    /// The convex cone K over a polygon of named points: facet i (a covector) vanishes on
    /// vertices i and i + 1 and is positive on the others (steps `{id}.{facet}.{vertex}`).
    Cone {
        /// The cone's name.
        id: String,
        /// Named points, counter-clockwise or clockwise.
        vertices: Vec<String>,
        /// Facet names and covectors (a, b, c): a x + b y + c v >= 0 on K.
        facets: Vec<(String, [String; 3])>,
    },
    /// S_map(K ∩ C_map) ⊆ K: K is clipped by the covectors of C_map with signs from steps
    /// `{cone}.C{map}.h{m}.{point}`, crossings are the named points listed, and every facet is
    /// non-negative on the image of every vertex of the piece (steps `{cone}.S{map}.{vertex}.{facet}`).
    Invariant {
        /// The step's id.
        id: String,
        /// The cone.
        cone: String,
        /// j.
        map: u64,
        /// The named crossing points, in the order the clipping creates them.
        crossings: Vec<String>,
    },
    /// I_0(D) ⊆ K: every facet is non-negative on I_0 g for every generator g of D (steps
    /// `{cone}.I0.{index}.{facet}`).
    AllDown {
        /// The step's id.
        id: String,
        /// The cone.
        cone: String,
    },
    /// det(t I - S_{n-1} S_1) = (t - 1)(t^2 + p t + q), t the variable given.
    Pcc {
        /// The step's id.
        id: String,
        /// The polynomial variable t.
        variable: String,
        /// p.
        p: String,
        /// q.
        q: String,
    },
    /// At a rational parameter point: chi has exactly `roots` real roots in (lo, hi], by the
    /// Sturm sequence given, and each expression in `positive` is a positive number there.
    Witness {
        /// The step's id.
        id: String,
        /// Values of the parameter variables.
        at: Vec<(String, String)>,
        /// (lo, hi), rationals.
        interval: (String, String),
        /// The Sturm sequence of chi at the point, polynomials in lambda.
        sequence: Vec<String>,
        /// The number of distinct roots in (lo, hi].
        roots: usize,
        /// Expressions (free of lambda after substitution) that are positive at the point.
        positive: Vec<String>,
    },
}

impl Schema for ProofFile {
    const KIND: Kind = Kind::Proof;
}

impl Step {
    /// The step's id.
    pub fn id(&self) -> &str {
        match self {
            Step::Positive { id, .. }
            | Step::Identity { id, .. }
            | Step::Define { id, .. }
            | Step::Point { id, .. }
            | Step::Image { id, .. }
            | Step::RootBound { id, .. }
            | Step::Cone { id, .. }
            | Step::Invariant { id, .. }
            | Step::AllDown { id, .. }
            | Step::Pcc { id, .. }
            | Step::Witness { id, .. } => id,
        }
    }
}
