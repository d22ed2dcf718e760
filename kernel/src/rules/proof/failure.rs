//! Why a proof is rejected, typed (docs/proof-format.md §7): each failure carries the names and
//! texts that explain it, and [`Failure::code`] gives its stable code. A failure of the header is
//! reported as `invalid-header`; a failure of a step with its own code, at the step.

use crate::exact::NumberError;
use crate::exact::univariate::SturmError;
use crate::model::polygon::BodyError;
use crate::reject::Code;

/// Why an expression's text is refused.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ExprError {
    /// Not the canonical text; the canonical text of the same polynomial.
    NotCanonical(String),
    /// A coefficient after a variable in a term.
    CoefficientFirst,
    /// A coefficient (the token) that is not a canonical rational.
    Coefficient(String, NumberError),
    /// A bad exponent in the token (more than [`super::MAX_DEGREE`], or not a number).
    Exponent(String),
    /// A variable that is not declared.
    UnknownVariable(String),
    /// An exponent that overflows.
    ExponentOverflow,
    /// An unexpected token.
    Unexpected(String),
    /// A sign at the end.
    DanglingSign,
    /// Not `N` nor `(N) / [atom] ...`.
    NotFraction,
    /// A token of the denominator that is not an atom in brackets.
    NotAtom(String),
}

/// Why a proof is rejected. Texts are canonical expressions or names from the file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Failure {
    /// An expression's text (the text, why).
    Expression(String, ExprError),
    /// A number's text (the text, why).
    Number(String, NumberError),
    /// A product of polynomials with this many terms each is beyond the size limit.
    Product(usize, usize),
    /// A polynomial with this many terms is beyond the limit.
    Terms(usize),
    /// Substituting the variable would give this total degree, beyond the limit.
    Substitution(String, u32),
    /// This degree in lambda is beyond the limit.
    LambdaDegree(u32),
    /// A variable that is not declared.
    UnknownVariable(String),
    /// A parameter's name that is not a declared variable.
    NotAVariable(String),
    /// An atom that is neither a hypothesis nor an earlier step.
    UnknownAtom(String),
    /// A point that is not named.
    UnknownPoint(String),
    /// A cone that is not declared.
    UnknownCone(String),
    /// A map name that is not S1..S(n-1) or I0 (the name, n).
    NotAMap(String, usize),
    /// A step id used twice.
    DuplicateId,
    /// An atom defined twice.
    DuplicateAtom(String),
    /// A point named twice.
    DuplicatePoint(String),
    /// A cone declared twice.
    DuplicateCone(String),
    /// A parameter given twice in a witness.
    GivenTwice(String),
    /// An atom with a denominator, used as a denominator.
    AtomDenominator(String),
    /// A variable that cannot be defined (again).
    CannotDefine(String),
    /// A definition that uses a variable neither a parameter nor defined before.
    UsesUndefined(String),
    /// A definition of a parameter.
    ParameterDefined(String),
    /// A variable that must be free (not a parameter, lambda or defined).
    NotFree(String),
    /// A name that is not a parameter (in a witness).
    NotParameter(String),
    /// p or q of a `Pcc` step involves other variables than gamma and kappa.
    PqVariables,
    /// A hypothesis that involves a variable other than gamma, kappa and lambda.
    HypothesisVariable(String),
    /// More variables than the limit.
    TooManyVariables,
    /// Variable names not distinct, or not alphanumeric starting with a letter.
    BadVariables,
    /// gamma, kappa and lambda not three different variables.
    SameParameters,
    /// The coordinates' third row is not (0, 0, 1).
    ThirdRow,
    /// The coordinates' matrix is singular.
    Singular,
    /// A body with irrational cos(2 pi/n), or not a polygon.
    UnsupportedN(u64),
    /// The model rejects the body.
    Body(BodyError),
    /// A map j that is not one of S_1..S_{n-1} (j, n).
    NoMap(u64, usize),
    /// chi is not (kappa + 1) det(lambda I - S_j) (j).
    NotCharacteristic(u64),
    /// A hypothesis that vanishes wherever chi does.
    HypothesisVanishes,
    /// kappa > 0 is not a hypothesis.
    KappaHypothesis,
    /// A `Positive` expression not equal to its certificate (expression, certificate).
    NotItsCertificate(String, String),
    /// An identity that does not hold (lhs, rhs).
    NotIdentity(String, String),
    /// det(t I - S_{n-1} S_1) is not (t - 1)(t^2 + p t + q).
    NotPccFactorisation,
    /// An image that is not the combination given (map, point).
    NotCombination(String, String),
    /// A facet that does not vanish at an end of its edge (facet, vertex, edge).
    FacetNotZero(String, String, usize),
    /// A crossing of an edge that is not the named point (from, to, key, point).
    NotTheCrossing(String, String, String, String),
    /// No step proves the sign (key, expression).
    NoStep(String, String),
    /// The step named does not prove the sign (key, expression).
    StepDoesNotProve(String, String),
    /// A value that must be non-negative is negative (expression, key).
    Negative(String, String),
    /// A definition's denominator not proved positive.
    DenominatorNotPositive(String),
    /// A coefficient of chi(b + s) not positive (variable, degree, bound).
    RootCoefficient(String, u32, String),
    /// A facet not positive at a vertex (facet, vertex).
    FacetNotPositive(String, String),
    /// A positivity certificate without terms.
    NoTerms,
    /// A certificate's coefficient that is not positive.
    CoefficientNotPositive(String),
    /// A `Positive` expression that vanishes on the region.
    VanishesOnRegion,
    /// A cone with fewer than three vertices or not one facet per edge.
    ConeShape,
    /// Vertices or facet names not distinct.
    NotDistinct,
    /// A facet name that cannot be part of a step key.
    FacetName,
    /// Fewer crossings listed than the clipping creates.
    FewerCrossings,
    /// A crossing listed that the clipping never creates.
    CrossingNeverCreated(String),
    /// An expression at a witness's point that still has other variables.
    OtherVariables,
    /// A hypothesis that does not hold at a witness's point.
    HypothesisFails(String),
    /// A Sturm sequence that does not check.
    Sturm(SturmError),
    /// The Sturm sequence counts another number of roots (counted, claimed).
    RootCount(usize, usize),
    /// A denominator that vanishes at a witness's point.
    DenominatorVanishes,
    /// An expression not positive at a witness's point.
    NotPositiveAt(String),
}

impl Failure {
    /// The stable code of a failing step (docs/proof-format.md §7).
    pub fn code(&self) -> Code {
        use Failure as F;
        match self {
            F::Expression(_, ExprError::UnknownVariable(_)) => Code::UnknownName,
            F::Expression(_, ExprError::Coefficient(..)) | F::Number(..) => Code::BadNumber,
            F::Expression(..) => Code::BadExpression,
            F::Product(..) | F::Terms(_) | F::Substitution(..) | F::LambdaDegree(_) => Code::TooLarge,
            F::UnknownVariable(_) | F::NotAVariable(_) | F::UnknownAtom(_) | F::UnknownPoint(_) => {
                Code::UnknownName
            }
            F::UnknownCone(_) | F::NotAMap(..) | F::NoMap(..) => Code::UnknownName,
            F::DuplicateId
            | F::DuplicateAtom(_)
            | F::DuplicatePoint(_)
            | F::DuplicateCone(_)
            | F::GivenTwice(_) => Code::DuplicateName,
            F::AtomDenominator(_) | F::CannotDefine(_) | F::UsesUndefined(_) | F::ParameterDefined(_) => {
                Code::MisusedName
            }
            F::NotFree(_) | F::NotParameter(_) | F::PqVariables | F::HypothesisVariable(_) => {
                Code::MisusedName
            }
            F::NotItsCertificate(..)
            | F::NotIdentity(..)
            | F::NotPccFactorisation
            | F::NotCombination(..) => Code::NotAnIdentity,
            F::FacetNotZero(..) | F::NotTheCrossing(..) | F::NotCharacteristic(_) => Code::NotAnIdentity,
            F::NoStep(..) | F::StepDoesNotProve(..) | F::Negative(..) | F::DenominatorNotPositive(_) => {
                Code::SignNotProved
            }
            F::RootCoefficient(..) | F::FacetNotPositive(..) => Code::SignNotProved,
            F::NoTerms | F::CoefficientNotPositive(_) | F::VanishesOnRegion | F::HypothesisVanishes => {
                Code::BadCertificate
            }
            F::ConeShape | F::NotDistinct | F::FacetName | F::FewerCrossings | F::CrossingNeverCreated(_) => {
                Code::BadCone
            }
            F::OtherVariables | F::HypothesisFails(_) | F::Sturm(_) | F::RootCount(..) => Code::BadWitness,
            F::DenominatorVanishes | F::NotPositiveAt(_) => Code::BadWitness,
            F::TooManyVariables | F::BadVariables | F::SameParameters | F::ThirdRow | F::Singular => {
                Code::InvalidHeader
            }
            F::UnsupportedN(_) | F::Body(_) | F::KappaHypothesis => Code::InvalidHeader,
        }
    }
}
