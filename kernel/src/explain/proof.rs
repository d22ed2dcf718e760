//! The words of the rejections of proofs.

use crate::exact::univariate::SturmError;
use crate::rules::proof::{ExprError, Failure, MAX_DEGREE};
use std::fmt;

/// An expression's text, abbreviated when long.
fn short(s: &str) -> String {
    if s.chars().count() <= 120 {
        return s.to_string();
    }
    let head: String = s.chars().take(100).collect();
    format!("{head}... ({} characters)", s.chars().count())
}

impl fmt::Display for ExprError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ExprError::NotCanonical(c) => write!(f, "is not canonical (canonical form {c:?})"),
            ExprError::CoefficientFirst => write!(f, "a coefficient must come first in a term"),
            ExprError::Coefficient(t, e) => write!(f, "coefficient {t:?}: {e}"),
            ExprError::Exponent(t) => write!(f, "bad exponent in {t:?} (at most {MAX_DEGREE})"),
            ExprError::UnknownVariable(n) => write!(f, "unknown variable {n:?}"),
            ExprError::ExponentOverflow => write!(f, "exponent too large"),
            ExprError::Unexpected(t) => write!(f, "unexpected {t:?}"),
            ExprError::DanglingSign => write!(f, "a sign must be followed by a term"),
            ExprError::NotFraction => write!(f, "expected \"(N) / [atom] ...\""),
            ExprError::NotAtom(t) => write!(f, "{t:?} is not an atom in brackets"),
        }
    }
}

impl fmt::Display for SturmError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SturmError::Start => write!(f, "the sequence must start with the polynomial and its derivative"),
            SturmError::Derivative => write!(f, "element 1 of the sequence is not the derivative"),
            SturmError::Remainder(i) => {
                write!(f, "element {i} of the sequence is not minus the remainder of the two before it")
            }
            SturmError::LastDivides => write!(f, "the last element does not divide the one before it"),
            SturmError::EmptyInterval => write!(f, "the interval is empty"),
            SturmError::RootAtEnd => write!(f, "the polynomial vanishes at an end of the interval"),
        }
    }
}

impl fmt::Display for Failure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use Failure as F;
        match self {
            F::Expression(t, ExprError::NotCanonical(c)) => {
                write!(f, "{t:?} is not canonical (canonical form {c:?})")
            }
            F::Expression(t, e) => write!(f, "{t:?}: {e}"),
            F::Number(t, e) => write!(f, "{t:?}: {e}"),
            F::Product(a, b) => {
                write!(f, "a product of polynomials with {a} and {b} terms is beyond the size limit")
            }
            F::Terms(n) => write!(
                f,
                "a polynomial with {n} terms is beyond the limit of {}",
                crate::rules::proof::MAX_TERMS
            ),
            F::Substitution(v, d) => write!(
                f,
                "substituting {v} would give degree {d}, beyond the limit of {}",
                crate::rules::proof::MAX_TOTAL_DEGREE
            ),
            F::LambdaDegree(d) => write!(
                f,
                "degree {d} in lambda is beyond the limit of {}",
                crate::rules::proof::MAX_LAMBDA_DEGREE
            ),
            F::UnknownVariable(n) => write!(f, "unknown variable {n:?}"),
            F::NotAVariable(n) => write!(f, "{n:?} is not a variable"),
            F::UnknownAtom(n) => write!(f, "unknown atom {n:?} (not a hypothesis or an earlier step)"),
            F::UnknownPoint(p) => write!(f, "unknown point {p:?}"),
            F::UnknownCone(c) => write!(f, "unknown cone {c:?}"),
            F::NotAMap(m, n) => {
                write!(f, "{m:?} is not a map of the model (S1..S{}, I0)", n.saturating_sub(1))
            }
            F::DuplicateId => write!(f, "the id is used twice"),
            F::DuplicateAtom(n) => write!(f, "the atom {n:?} is defined twice"),
            F::DuplicatePoint(p) => write!(f, "the point {p:?} is named twice"),
            F::DuplicateCone(c) => write!(f, "the cone {c:?} is declared twice"),
            F::GivenTwice(n) => write!(f, "{n:?} is given twice"),
            F::AtomDenominator(n) => write!(f, "the atom {n:?} has a denominator"),
            F::CannotDefine(n) => write!(f, "the variable {n:?} cannot be defined (again)"),
            F::UsesUndefined(n) => {
                write!(f, "the definition uses {n:?}, which is neither a parameter nor defined before")
            }
            F::ParameterDefined(n) => write!(f, "the parameter {n:?} cannot be defined"),
            F::NotFree(v) => write!(f, "{v:?} must be a free variable (not a parameter, lambda or defined)"),
            F::NotParameter(n) => write!(f, "{n:?} is not a parameter"),
            F::PqVariables => {
                write!(f, "p and q (and their denominators) must be expressions in gamma and kappa only")
            }
            F::HypothesisVariable(n) => {
                write!(f, "a hypothesis may involve gamma, kappa and lambda only, not {n:?}")
            }
            F::TooManyVariables => write!(f, "at most {} variables", crate::rules::proof::MAX_VARIABLES),
            F::BadVariables => {
                write!(f, "variable names must be distinct, alphanumeric, starting with a letter")
            }
            F::SameParameters => write!(f, "gamma, kappa and lambda must be different variables"),
            F::ThirdRow => write!(f, "the third row must be (0, 0, 1): v is the same in both coordinates"),
            F::Singular => write!(f, "the matrix is singular"),
            F::UnsupportedN(n) => {
                write!(
                    f,
                    "n = {n}: proofs are about regular polygons with rational cos(2 pi/n), n in {{3, 4, 6}}"
                )
            }
            F::Body(e) => write!(f, "{e}"),
            F::NoMap(j, n) => write!(f, "map {j} is not one of S_1..S_{}", n.saturating_sub(1)),
            F::NotCharacteristic(j) => write!(f, "chi is not (kappa + 1) det(lambda I - S_{j}) of the model"),
            F::HypothesisVanishes => {
                write!(f, "the hypothesis vanishes wherever chi does: the region would be empty")
            }
            F::KappaHypothesis => {
                write!(f, "kappa > 0 must be a hypothesis (the maps are scaled by 1 + kappa)")
            }
            F::NotItsCertificate(e, c) => {
                write!(f, "{} is not equal to its certificate {}", short(e), short(c))
            }
            F::NotIdentity(l, r) => write!(f, "{} - ({}) does not vanish modulo chi", short(l), short(r)),
            F::NotPccFactorisation => write!(f, "det(t I - S_(n-1) S_1) is not (t - 1)(t^2 + p t + q)"),
            F::NotCombination(m, p) => write!(f, "{m} {p} is not the combination given"),
            F::FacetNotZero(name, v, i) => {
                write!(f, "facet {name} does not vanish at {v}, an end of edge {i}")
            }
            F::NotTheCrossing(from, to, key, w) => {
                write!(f, "the edge {from} -> {to} crosses {key} at a point that is not {w}")
            }
            F::NoStep(key, e) => write!(f, "no step `{key}` proves the sign of {}", short(e)),
            F::StepDoesNotProve(key, e) => write!(f, "step `{key}` does not prove the sign of {}", short(e)),
            F::Negative(e, key) => write!(f, "{} is negative (step `{key}`)", short(e)),
            F::DenominatorNotPositive(d) => write!(f, "the denominator {d} is not proved positive"),
            F::RootCoefficient(v, d, b) => {
                write!(f, "the coefficient of {v}^{d} in chi({b} + {v}) is not positive")
            }
            F::FacetNotPositive(name, v) => write!(f, "facet {name} is not positive at {v}"),
            F::NoTerms => write!(f, "a positivity certificate needs at least one term"),
            F::CoefficientNotPositive(c) => write!(f, "the coefficient {c} is not positive"),
            F::VanishesOnRegion => write!(f, "the expression vanishes on the region: it cannot be positive"),
            F::ConeShape => write!(f, "a cone needs at least three vertices and one facet per edge"),
            F::NotDistinct => write!(f, "the vertices, and the facet names, must be distinct"),
            F::FacetName => write!(f, "facet names are part of step keys: non-empty, without '.' or spaces"),
            F::FewerCrossings => write!(f, "fewer crossings listed than the clipping creates"),
            F::CrossingNeverCreated(w) => write!(f, "the crossing {w} is never created"),
            F::OtherVariables => write!(f, "the expression has other variables at the point"),
            F::HypothesisFails(e) => write!(f, "the point does not satisfy the hypothesis {e} > 0"),
            F::Sturm(e) => write!(f, "{e}"),
            F::RootCount(c, r) => write!(f, "the Sturm sequence counts {c} roots in (lo, hi], not {r}"),
            F::DenominatorVanishes => write!(f, "a denominator vanishes at the point"),
            F::NotPositiveAt(e) => write!(f, "{} is not positive at the point", short(e)),
        }
    }
}

impl std::error::Error for Failure {}
