//! The words of the rejections of cone and family certificates, and of the syntax layer.

use super::{abbreviate, quote, tuple};
use crate::model::pcc::PccExclusion;
use crate::reject::{Boundary, Counted, Detail, ImageFailure, Internal, Locus, Needs, TimeToRestFailure};
#[cfg(feature = "kinds")]
#[allow(unused_imports)] // which of them a kind needs depends on the features
use crate::reject::{KindCounted, KindDetail, KindInternal, KindLocus};
use crate::syntax::strict::Offence;

/// The words of a detail of the syntax layer or of a cone or family certificate.
pub(super) fn words(detail: &Detail, locus: &Locus) -> String {
    match detail {
        Detail::Lexical(offence, json) => {
            let section = if *json { "§11: strict JSON syntax" } else { "§2: strict syntax" };
            format!("{} (docs/certificate-format.md {section})", lexical(*offence))
        }
        Detail::Parser(what) => what.clone(),
        Detail::Missing => String::new(),
        Detail::Format(expected, Some(f)) => format!("expected {expected:?}, found {f:?}"),
        Detail::Format(expected, None) => format!("expected {expected:?}"),
        Detail::Version(found, [lo, hi]) if lo == hi => {
            format!("version {found} is not supported (this build reads version {lo})")
        }
        Detail::Version(found, [lo, hi]) => {
            format!("version {found} is not supported (this build reads versions {lo} to {hi})")
        }
        Detail::Needs(needs, found) => needs_words(*needs, *found),
        Detail::OrbitClaim => {
            "CompleteChatterFromSet is the claim of orbit certificates (chatter-orbit-certificate), not of a cone".into()
        }
        Detail::Number(text, error) => format!("{}: {error}", quote(text)),
        Detail::Limit(count, limit, what) => limit_words(*count, *limit, *what, locus),
        Detail::FileSize(what, max) => {
            format!("{what}, more than the limit max-file-size = {max} bytes: no verdict on the content")
        }
        Detail::Time(during) => format!("the time limit ran out while {during}: no verdict on the content"),
        Detail::Body(e) => e.to_string(),
        #[cfg(feature = "field")]
        Detail::Kind(KindDetail::Contacts(n, max)) => format!("n = {n}: the kernel models regular polygons with 2 to {max} contacts"),
        #[cfg(any(feature = "field", feature = "boxes"))]
        Detail::Kind(KindDetail::IntervalIrrational(n)) => format!(
            "parameter intervals (box certificates) are supported only where cos(2 pi/n) is rational (n = 2, 3, 4, 6), not for n = {n}"
        ),
        #[cfg(any(feature = "boxes", feature = "family"))]
        Detail::Kind(KindDetail::EmptyInterval(lo, hi)) => {
            format!("the interval [{}, {}] is empty (lo > hi)", abbreviate(lo), abbreviate(hi))
        }
        Detail::GammaForClaim(gamma, claim, general) => {
            let theorem = if *general { "Theorem 11.4" } else { "the paper's Theorem on effectively invariant cones" };
            format!(
                "gamma = {} is outside 0 < gamma < 1, which the claim {} needs ({theorem} assumes it); only EffectivelyInvariant holds for gamma = 0 or 1",
                abbreviate(gamma),
                claim.name()
            )
        }
        Detail::Arity(expected, found) => {
            format!("expected {} coordinates ({}), found {found}", expected.len(), expected.join(", "))
        }
        #[cfg(feature = "family")]
        Detail::Kind(KindDetail::ConeCount(found, contacts, true)) => {
            format!("{found} cones, more than {contacts} (one per contact)")
        }
        #[cfg(feature = "family")]
        Detail::Kind(KindDetail::ConeCount(found, contacts, false)) => {
            format!("expected one cone per contact ({contacts}), found {found}")
        }
        Detail::NotBelow(coords) => match locus {
            #[cfg(feature = "family")]
            Locus::Kind(KindLocus::ConvexGenerator { cone, index }) => format!("generator cones[{cone}][{index}] = {} has v >= 0", tuple(coords)),
            Locus::Generator { index } => format!("generator cone[{index}] = {} has v >= 0", tuple(coords)),
            _ => format!("a generator {} has v >= 0", tuple(coords)),
        },
        Detail::Degenerate(generators, rays, dimension) => degenerate(*generators, *rays, *dimension, locus),
        Detail::Image(f) => image(f, locus),
        Detail::Pcc(n, pqd, why) => pcc(*n, pqd, *why, locus),
        Detail::TimeToRest(why, b) => time_to_rest(*why, b),
        #[cfg(feature = "boxes")]
        Detail::Kind(KindDetail::PccBox(polynomial, at_corner, max)) => pcc_box(*polynomial, *at_corner, *max, locus),
        Detail::Internal(i) => internal(i),
        #[cfg(feature = "family")]
        Detail::Kind(KindDetail::Convex(e)) => format!("{e} (docs/model.md §11.1)"),
        #[cfg(feature = "family")]
        Detail::Kind(KindDetail::Tensor(f)) => tensor(f),
        #[allow(unreachable_patterns)]
        _ => format!("{detail:?}"),
    }
}

/// Rule T1 (docs/time-to-rest.md §2), in words.
fn time_to_rest(why: TimeToRestFailure, b: &str) -> String {
    let b = abbreviate(b);
    let reason = match why {
        TimeToRestFailure::NotRod => {
            "only a point certificate of the rod (n = 2) may carry it: for other bodies no theorem bounds the time to rest (docs/time-to-rest.md §4)"
        }
        TimeToRestFailure::Claim => "the claim EffectivelyInvariant says nothing about drops",
        TimeToRestFailure::NotPositive => "B must be positive",
        TimeToRestFailure::SigmaNotPositive => {
            "kappa >= 1, so sigma = (1 + gamma)(1 - kappa)/(1 + kappa) <= 0"
        }
        TimeToRestFailure::ComplexRoots => {
            "sigma^2 - 4 gamma < 0: the roots of lambda^2 - sigma lambda + gamma are not real"
        }
        TimeToRestFailure::TooSmall => {
            "1/B exceeds lambda_1, the larger root of lambda^2 - sigma lambda + gamma, so B < 1/lambda_1"
        }
    };
    format!("time_to_rest_bound B = {b} is not shown: {reason}")
}

/// What breaks the strict syntax, in words.
fn lexical(o: Offence) -> String {
    let words = match o {
        Offence::Empty => "the file is empty",
        Offence::NotClosed => "a string is not closed",
        Offence::Escape => "escapes in strings are not part of the format",
        Offence::Control => "control characters in strings are not part of the format",
        Offence::AfterString => "a token must not follow a string directly",
        Offence::JsonLiteral => {
            "literals and names outside strings (true, false, null) are not part of the JSON twin"
        }
        Offence::RawString => "raw strings and byte strings are not part of the format",
        Offence::LeadingZero => "integers with leading zeros are not part of the format",
        Offence::NotDecimal => {
            "only plain decimal integers are part of the format (no 0x, 0b, 0o, _, exponent or fraction)"
        }
        Offence::NotObject => "a struct or a variant's fields must be a JSON object",
        Offence::Comment => "comments are not part of the format",
        Offence::Extension => "extensions (#![enable(...)]) are not part of the format",
        Offence::ByteOrderMark => "a byte order mark (U+FEFF) is not part of the format",
        Offence::Sign => "signs outside strings are not part of the format (numbers are strings)",
        Offence::CharLiteral => "character literals are not part of the format",
        Offence::Map => "maps are not part of the format",
        Offence::TupleInterval => "a parameter interval is a list [\"lo\", \"hi\"], not a tuple",
        Offence::Parenthesis => "parentheses are not part of the JSON twin (structs are objects)",
        Offence::Character(c) if c.is_ascii_graphic() => {
            return format!("the character {c:?} is not part of the format");
        }
        Offence::Character(c) => {
            return format!("the character U+{:04X} outside a string is not part of the format", c as u32);
        }
    };
    words.to_string()
}

fn needs_words(needs: Needs, found: u64) -> String {
    match needs {
        Needs::Intervals => {
            format!(
                "parameter intervals (box certificates, general bodies over an interval of gamma) need version 2; this file says version {found}"
            )
        }
        Needs::FieldElements => {
            format!("elements of Q(cos 2 pi/n) need version 3; this file says version {found}")
        }
        Needs::Feature(f) => {
            format!(
                "this build of chatter-kernel is compiled without the Cargo feature `{f}`, which checks this file"
            )
        }
        Needs::Kind(format) => format!(
            "version {found} of this format is the legacy header of {format:?} files: read the file as that kind (chatter verify reads every kind)"
        ),
    }
}

fn limit_words(count: usize, limit: usize, what: Counted, locus: &Locus) -> String {
    let name = match locus {
        Locus::Limit { name } => name.as_str(),
        _ => "a limit",
    };
    let text = match what {
        Counted::Generators => format!("{count} generators, more than the limit {name} = {limit}"),
        Counted::Characters => format!("{count} characters of numbers, more than the limit {name} = {limit}"),
        #[cfg(feature = "kinds")]
        Counted::Kind(KindCounted::ConeGenerators(i)) => {
            format!("cone {i} has {count} generators, more than the limit {name} = {limit}")
        }
        #[cfg(feature = "kinds")]
        Counted::Kind(KindCounted::Points) => format!("{count} points, more than the limit {name} = {limit}"),
        #[cfg(feature = "kinds")]
        Counted::Kind(KindCounted::Depth) => {
            format!("subdivision {count} is deeper than the limit {name} = {limit}")
        }
        #[cfg(feature = "kinds")]
        Counted::Kind(KindCounted::Boxes) => {
            format!("more than the limit {name} = {limit} sub-boxes examined")
        }
        #[cfg(feature = "kinds")]
        Counted::Kind(KindCounted::Leaves) => format!("{count} leaves, more than the limit {name} = {limit}"),
        #[cfg(feature = "kinds")]
        Counted::Kind(KindCounted::Prefix) => {
            format!("a prefix of {count} impacts, more than the limit {name} = {limit}")
        }
        #[cfg(feature = "kinds")]
        Counted::Kind(KindCounted::Tree) => {
            format!("a tree of at least {count} impacts, more than the limit {name} = {limit}")
        }
    };
    format!("{text}: no verdict on the content")
}

fn degenerate(generators: usize, rays: usize, dimension: usize, locus: &Locus) -> String {
    match (locus, dimension, generators) {
        #[cfg(feature = "family")]
        (Locus::Kind(KindLocus::ConvexCone { cone: i }), _, _) => format!(
            "the {generators} generators of K_{i} span only {rays} distinct extreme ray(s) in a plane or line: K_{i} must be a 3-D cone"
        ),
        (_, d, 0) => format!("field `cone` is empty: K must be a {d}-D cone"),
        (_, 2, _) => "the generators span a single ray: K must be a 2-D cone (two distinct rays)".into(),
        _ => format!(
            "the {generators} generators span only {rays} distinct extreme ray(s) in a plane or line: K must be a 3-D cone"
        ),
    }
}

/// "vertex 0 of K∩C_1, at (0, -1), maps under S_1 to (..) outside edge 0 of K (..) by .."
fn image(f: &ImageFailure, locus: &Locus) -> String {
    let p = tuple(&f.point);
    let m1 = |m: usize| (m + 1) % f.n.max(1);
    let (what, outside) = match locus {
        Locus::Piece { piece: j, vertex: i, outside, .. } => {
            (format!("vertex {i} of K∩C_{j}, at {p}, maps under S_{j}"), outside)
        }
        Locus::AllDown { generator: m, outside, .. } if f.n == 2 => {
            (format!("I_0 maps the all-down generator {m} = {p}"), outside)
        }
        Locus::AllDown { generator: m, outside, .. } => {
            (format!("I_0 maps the all-down generator -m_({m},{}) = {p}", m1(*m)), outside)
        }
        #[cfg(feature = "family")]
        Locus::Kind(KindLocus::Transition { from: i, to: j, vertex: v, outside, gamma }) => {
            let what = format!("vertex {v} of K_{i}∩C_({i},{j}), at {p}, maps under I_{j} into K_{j}");
            (format!("{}{what}", at_gamma(gamma)), outside)
        }
        #[cfg(feature = "family")]
        Locus::Kind(KindLocus::ConvexAllDown { cone: i, generator: m, outside, gamma }) => {
            let what = format!("I_{i} maps the all-down generator -m_({m},{}) = {p} into K_{i}", m1(*m));
            (format!("{}{what}", at_gamma(gamma)), outside)
        }
        #[cfg(feature = "rest")]
        Locus::Kind(KindLocus::RestNode { node, step: Some(j), vertex: Some(i), outside, gamma, .. }) => {
            let what = format!("node {node}: vertex {i} of K_{node}∩C_{j}, at {p}, maps under S_{j}");
            let end = gamma
                .as_ref()
                .map_or(String::new(), |g| format!("at the end gamma = {} of the interval: ", abbreviate(g)));
            (format!("{end}{what} (K: the cone of the node `next` names)"), outside)
        }
        _ => (format!("the point {p}"), &None),
    };
    let q = f.image.as_deref().map(tuple).unwrap_or_default();
    let by = f.by.as_deref().map(abbreviate).unwrap_or_default();
    let tail = match outside {
        None if f.n == 2 => " to a velocity with v >= 0".to_string(),
        None => {
            let v = if f.v_zero { "v = 0" } else { "v > 0" };
            format!(" to a velocity with v >= 0 (here {v}): the centre of mass stops falling")
        }
        Some(Boundary::Edge { index, from, to }) => {
            format!(" to {q} outside edge {index} of K (generators {from} -> {to}) by {by}")
        }
        Some(Boundary::End { generator }) => {
            format!(" to {q} outside K, beyond generator {generator}, by {by} in u0/(-2v)")
        }
    };
    match &f.corner {
        Some([k, g]) => {
            format!("at the corner kappa = {}, gamma = {}: {what}{tail}", abbreviate(k), abbreviate(g))
        }
        None => format!("{what}{tail}"),
    }
}

/// "at the end gamma = 1/20 of the interval: " for a family certificate over an interval of gamma.
#[cfg(feature = "family")]
fn at_gamma(gamma: &Option<String>) -> String {
    gamma
        .as_deref()
        .map_or(String::new(), |g| format!("at the end gamma = {} of the interval: ", abbreviate(g)))
}

fn pcc(n: usize, pqd: &[String; 3], why: PccExclusion, locus: &Locus) -> String {
    let [p, q, d] = pqd.clone().map(|x| abbreviate(&x));
    let why = match why {
        PccExclusion::RealRoots => "the discriminant is >= 0 (real roots)",
        PccExclusion::ModulusNotBelowOne => "the roots are complex but of modulus sqrt(q) >= 1",
        PccExclusion::Excluded => "the Lemma on PCC applies",
    };
    let quadratic = format!(
        "(t - 1)(t^2 + ({p}) t + ({q})) with discriminant {d} (needs < 0) and constant term {q} (needs < 1): {why}"
    );
    match locus {
        #[cfg(feature = "family")]
        Locus::Kind(KindLocus::PccPair { pair: k, gamma }) => {
            let k1 = (k + 1) % n.max(1);
            let at = at_gamma(gamma);
            format!("{at}PCC of contacts {k} and {k1} is not excluded: det(tI - I_{k} I_{k1}) = {quadratic}")
        }
        _ => format!("PCC is not excluded: det(tI - S_{} S_1) = {quadratic}", n.saturating_sub(1)),
    }
}

#[cfg(feature = "boxes")]
fn pcc_box(
    polynomial: crate::rules::boxes::PccPolynomial,
    at_corner: bool,
    max: usize,
    locus: &Locus,
) -> String {
    use crate::rules::boxes::PccPolynomial;
    let what = match polynomial {
        PccPolynomial::Discriminant => "the discriminant p^2 - 4q",
        PccPolynomial::Modulus => "q - 1",
    };
    let Locus::Kind(KindLocus::PccRegion { kappa, gamma }) = locus else {
        return format!("{what} of the PCC quadratic");
    };
    let [k0, k1] = kappa.as_ref().clone().map(|x| abbreviate(&x));
    let [g0, g1] = gamma.as_ref().clone().map(|x| abbreviate(&x));
    if at_corner {
        format!(
            "PCC is not excluded on the box: at kappa = {k0}, gamma = {g0}, {what} of the PCC quadratic is >= 0"
        )
    } else {
        format!(
            "PCC exclusion not shown on the box: {what} of the PCC quadratic is not proved negative on kappa in [{k0}, {k1}], gamma in [{g0}, {g1}] within {max} sub-boxes"
        )
    }
}

fn internal(i: &Internal) -> String {
    match i {
        Internal::NotARoot(v) => format!("model error: det(I - S_(n-1) S_1) = {} is not 0", abbreviate(v)),
        Internal::NoEdge => "model error: a point with v < 0 outside K violates no edge of K".into(),
        #[cfg(feature = "kinds")]
        Internal::Kind(KindInternal::CornersDiffer(Some(j))) => {
            format!("model error: C_{j} differs between the corners of the box")
        }
        #[cfg(feature = "kinds")]
        Internal::Kind(KindInternal::CornersDiffer(None)) => {
            "model error: C_1 differs between the corners of the box".into()
        }
        #[cfg(feature = "kinds")]
        Internal::Kind(KindInternal::NotARootAtPair(v, (k, k1))) => {
            format!("model error: det(I - I_{k} I_{k1}) = {} is not 0", abbreviate(v))
        }
        #[cfg(feature = "kinds")]
        Internal::Kind(KindInternal::NotARootOnBox) => {
            "model error: t = 1 is not a root of det(tI - S_(n-1) S_1)".into()
        }
        #[cfg(feature = "kinds")]
        Internal::Kind(KindInternal::NoCone(i, j)) => format!("model error: no cone C_({i},{j})"),
    }
}

#[cfg(feature = "family")]
impl std::fmt::Display for crate::model::convex::ConvexBodyError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        use crate::model::convex::{ConvexBodyError as E, MAX_CONTACTS};
        match self {
            E::TooFewContacts(n) => write!(f, "{n} contacts: a convex body needs at least 3"),
            E::TooManyContacts(n) => write!(f, "{n} contacts: at most {MAX_CONTACTS} are supported"),
            E::RepeatedContact { contact } => write!(f, "contacts {contact} and {} coincide", contact + 1),
            E::Clockwise => write!(f, "the contacts are listed clockwise; list them counter-clockwise"),
            E::CollinearContacts { contact } => {
                write!(f, "contact {contact} lies on the line through its neighbours (not strictly convex)")
            }
            E::NotConvex { contact } => write!(f, "the contact polygon is not convex at contact {contact}"),
            E::NotSimple { turns } => write!(f, "the contact polygon winds {turns} times (not simple)"),
            E::OriginOnEdge { edge } => {
                write!(f, "the centre of mass lies on edge {edge}: it must be strictly inside")
            }
            E::OriginOutside { edge } => {
                write!(f, "the centre of mass lies outside the contact polygon (beyond edge {edge})")
            }
            E::InertiaNotSymmetric => write!(f, "the inertia tensor J must be symmetric"),
            E::InertiaNotPositiveDefinite => write!(f, "the inertia tensor J must be positive definite"),
            E::GammaOutOfRange => write!(f, "gamma must lie in [0, 1]"),
        }
    }
}

#[cfg(feature = "family")]
impl std::error::Error for crate::model::convex::ConvexBodyError {}

/// Rule K0 (docs/model.md Proposition 11.0), in words.
#[cfg(feature = "family")]
fn tensor(f: &crate::rules::family::TensorFailure) -> String {
    use crate::rules::family::TensorFailure as T;
    match f {
        T::ZzNotPositive(zz) => {
            format!("Izz = {zz} <= 0: no rigid body has this inertia tensor (rule K0)")
        }
        T::Differs { entry, written, derived } => format!(
            "the planar inertia J is not J_eff of the inertia tensor: {entry} is {written}, but the \
             tensor's J_eff = [[Ixx, Ixy], [Ixy, Iyy]] - b b^T / Izz, b = (Ixz, Iyz), has {entry} = \
             {derived} (rule K0, docs/model.md Proposition 11.0)"
        ),
    }
}
