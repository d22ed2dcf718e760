//! Certified sets that turn a drop's outcome into a proof (issue 22 §1, issue 24): cone and orbit
//! certificates, each accepted by the kernel on both backends before it is used, whose sets a
//! post-impact state may enter (membership is decided by the kernel, `chatter_kernel::membership`).
//!
//! - a cone certificate proves, from any post-impact velocity in its cone K, that v ≤ 0 for ever
//!   (no separation, impacts never stop) and no PCC, when its claim excludes PCC
//!   (`CompleteChatterFromAllDown`) and it holds for the body's n, κ, γ (a point certificate with
//!   these exact values, or a box containing them). It does not prove that the impacts accumulate
//!   at a finite time (docs/time-to-rest.md §3: K may contain motions whose impacts never do): the
//!   run's proved outcome is `no-ICC-no-PCC` ([`super::Outcome::NoIccNoPcc`], not CC), and the
//!   report's `entered.finite_time` is false;
//! - an orbit certificate proves CC from any post-impact state in its set X (claim
//!   `CompleteChatterFromSet`, n, κ, γ equal);
//! - a time-to-rest certificate (claim `CompleteChatterFromAllDown`, rules G1-G5, F, n, κ, γ equal)
//!   proves CC for every drop that is all-down at its first impact, with T <= B h/|v| from there
//!   (docs/time-to-rest.md Theorem 5.1); it has no set to enter: the run tests the drop. So does a
//!   general body's (`chatter-family-time-to-rest`, Theorem 5.2) for the general body it names.
//!
//! Sets come from files (`chatter simulate --certificate FILE...`) or are made on the fly
//! (`crate::prove::made`, cached per body and parameters; `crate::prove::add_orbit_for` once a
//! drop's impacts show a periodic pattern).

use super::scalar::Nf;
use super::{Model, Shape};
use crate::exact::Q;
use chatter_kernel::certificate::{Body, Param};
use chatter_kernel::certificate::{Certificate, Claim, Encoding, OrbitCertificate, read_in, read_orbit};
use chatter_kernel::exact::ParseLimits;
use chatter_kernel::membership::{CertifiedCone, CertifiedOrbit, NotCertified};
use chatter_kernel::model::ConvexBody;
use chatter_kernel::model::linalg::Vec3;
use chatter_kernel::rest::TimeToRest;
use chatter_kernel::rest_family::FamilyTimeToRest;
use chatter_kernel::syntax::{Kind, kind_of, read};
use chatter_kernel::verify::{BOTH, Verdict, verify_rest, verify_rest_family};
use std::sync::Arc;

/// The kind of a certified set.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SetKind {
    /// The cone K of a cone certificate (velocities).
    Cone,
    /// The set X of an orbit certificate (normalised post-impact states).
    Orbit,
    /// A time-to-rest certificate: every all-down drop (tested at the first impact).
    Rest,
}

impl SetKind {
    /// The name used in output and JSON.
    pub fn name(self) -> &'static str {
        match self {
            SetKind::Cone => "cone",
            SetKind::Orbit => "orbit",
            SetKind::Rest => "time-to-rest",
        }
    }
}

enum Inner {
    Cone(Box<CertifiedCone<Q>>),
    Orbit(Box<CertifiedOrbit<Q>>),
    Rest,
}

/// The certificate a set comes from (as read or made; the kernel accepted it).
#[derive(Clone, Debug)]
pub enum Source {
    /// A cone certificate.
    Cone(Box<Certificate>),
    /// An orbit certificate.
    Orbit(Box<OrbitCertificate>),
    /// A time-to-rest certificate.
    Rest(Box<TimeToRest>),
    /// A time-to-rest certificate of a general body.
    RestFamily(Box<FamilyTimeToRest>),
}

/// One certified set, with where it came from.
pub struct Set {
    /// The certificate's file name, or a description of the certificate made on the fly.
    pub name: String,
    /// What the set is.
    pub kind: SetKind,
    /// The claim the kernel accepted.
    pub claim: Claim,
    /// The certificate.
    pub source: Source,
    /// B of an orbit certificate, derived by the kernel (`time_to_rest_bound`): from a post-impact
    /// state in X with centre height h and velocity v < 0, the impacts accumulate within B h/|v|
    /// (docs/kernel-soundness.md §7 item 6). For a rod cone certificate, the B that the kernel's
    /// rule T1 checked: every all-down drop accumulates its impacts within B h/|v| of its first
    /// impact (h, v there; docs/time-to-rest.md §2), whatever K. `None` for every other cone,
    /// which proves no finite time.
    pub time_to_rest_bound: Option<Q>,
    inner: Inner,
}

impl Set {
    /// Whether the relabelled post-impact state (q, p) lies in the set (decided by the kernel).
    fn contains(&self, q: &Vec3<Nf>, p: &Vec3<Nf>) -> bool {
        match &self.inner {
            Inner::Cone(c) => c.contains(p),
            Inner::Orbit(o) => o.contains(q, p),
            Inner::Rest => false,
        }
    }
}

/// The certified sets of one body with its parameters (cheap to clone: the sets are shared).
#[derive(Clone, Default)]
pub struct Certified {
    sets: Vec<Arc<Set>>,
    /// What was tried and why a set is missing (for the report).
    pub notes: Vec<String>,
}

/// Why a certificate cannot serve as a proof for this body.
fn not_certified(e: NotCertified) -> String {
    match e {
        NotCertified::Verdict(v) => match *v {
            Verdict::Rejected(r) => format!("rejected by the kernel: {r}"),
            Verdict::Disagree(s) => format!("the kernel's backends disagree: {s}"),
            Verdict::Accepted(_) => "accepted".into(),
        },
        NotCertified::Unreadable(s) => format!("a number could not be read again: {s}"),
    }
}

/// n, κ and γ of a regular polygon or rod model in the kernel's scalars.
pub fn parameters(model: &Model) -> Option<(u64, Nf, Nf)> {
    match model.shape() {
        Shape::Polygon(n) => Some((n, Nf::rational(model.kappa.clone()), Nf::rational(model.gamma.clone()))),
        Shape::Rod => Some((2, Nf::rational(model.kappa.clone()), Nf::rational(model.gamma.clone()))),
        Shape::Convex(_) => None,
    }
}

impl Certified {
    /// No sets: no drop can be proved CC (nor no ICC and no PCC).
    pub fn empty() -> Certified {
        Certified::default()
    }

    /// The sets, in the order they are tested.
    pub fn sets(&self) -> &[Arc<Set>] {
        &self.sets
    }

    /// The first set that contains the relabelled post-impact state (q, p).
    pub fn entered(&self, q: &Vec3<Nf>, p: &Vec3<Nf>) -> Option<&Set> {
        self.sets.iter().map(|s| &**s).find(|s| s.contains(q, p))
    }

    /// The first set of this kind that contains the relabelled post-impact state (q, p).
    pub fn entered_kind(&self, kind: SetKind, q: &Vec3<Nf>, p: &Vec3<Nf>) -> Option<&Set> {
        self.sets.iter().map(|s| &**s).find(|s| s.kind == kind && s.contains(q, p))
    }

    /// A time-to-rest certificate, if one was added (it proves every all-down drop CC).
    pub fn rest(&self) -> Option<&Set> {
        self.sets.iter().map(|s| &**s).find(|s| s.kind == SetKind::Rest)
    }

    /// Whether some set is an orbit certificate's X (then a run that entered a cone may go on,
    /// looking for it: [`super::Options::after_cone`]).
    pub fn has_orbits(&self) -> bool {
        self.sets.iter().any(|s| s.kind == SetKind::Orbit)
    }

    /// Adds a cone certificate that the kernel accepts, whose claim excludes PCC and which holds
    /// for the model; `Err` says why it cannot serve.
    pub fn add_cone(&mut self, model: &Model, cert: &Certificate, name: &str) -> Result<(), String> {
        let Some((n, kappa, gamma)) = parameters(model) else {
            return Err("proofs by certified sets need a regular polygon or the rod".into());
        };
        if cert.claim != Claim::CompleteChatterFromAllDown {
            return Err(format!(
                "its claim {} does not exclude PCC: only CompleteChatterFromAllDown proves no ICC and no PCC from K",
                cert.claim.name()
            ));
        }
        let (cone, _) = CertifiedCone::new(cert, ParseLimits::default()).map_err(not_certified)?;
        if !cone.applies_to(n, &kappa, &gamma) {
            return Err(format!("it is not about n = {n}, kappa = {}, gamma = {}", model.kappa, model.gamma));
        }
        let (kind, source, inner) =
            (SetKind::Cone, Source::Cone(Box::new(cert.clone())), Inner::Cone(Box::new(cone)));
        let bound = cert.time_to_rest_bound.as_deref().map(str::parse::<Q>).transpose();
        let time_to_rest_bound = bound.map_err(|e| format!("its time_to_rest_bound cannot be read: {e}"))?;
        let set = Set { name: name.into(), kind, claim: cert.claim, source, time_to_rest_bound, inner };
        self.sets.push(Arc::new(set));
        Ok(())
    }

    /// Adds an orbit certificate that the kernel accepts and which is about the model.
    pub fn add_orbit(&mut self, model: &Model, cert: &OrbitCertificate, name: &str) -> Result<(), String> {
        let Some((n, kappa, gamma)) = parameters(model) else {
            return Err("proofs by certified sets need a regular polygon (n >= 3)".into());
        };
        let (orbit, accepted) = CertifiedOrbit::new(cert, ParseLimits::default()).map_err(not_certified)?;
        if !orbit.applies_to(n, &kappa, &gamma) {
            return Err(format!("it is not about n = {n}, kappa = {}, gamma = {}", model.kappa, model.gamma));
        }
        let claim = Claim::CompleteChatterFromSet;
        let (kind, source, inner) =
            (SetKind::Orbit, Source::Orbit(Box::new(cert.clone())), Inner::Orbit(Box::new(orbit)));
        let bound = accepted.time_to_rest_bound.as_deref().map(str::parse::<Q>).transpose();
        let time_to_rest_bound = bound.map_err(|e| format!("its time_to_rest_bound cannot be read: {e}"))?;
        self.sets.push(Arc::new(Set { name: name.into(), kind, claim, source, time_to_rest_bound, inner }));
        Ok(())
    }

    /// Adds a time-to-rest certificate that the kernel accepts on both backends, whose claim
    /// excludes PCC and whose body is the model's (n, κ, γ equal); `Err` says why it cannot serve.
    pub fn add_rest(&mut self, model: &Model, cert: &TimeToRest, name: &str) -> Result<(), String> {
        let Body::RegularPolygon { n, kappa: Param::Point(k), gamma: Param::Point(g) } = &cert.body else {
            return Err("its body is not at a point".into());
        };
        let same = |text: &str, x: &Q| text.parse::<Q>().is_ok_and(|y| &y == x);
        if model.shape() != Shape::Polygon(*n) || !same(k, &model.kappa) || !same(g, &model.gamma) {
            return Err(format!("it is not about n = {n}, kappa = {}, gamma = {}", model.kappa, model.gamma));
        }
        if cert.claim != Claim::CompleteChatterFromAllDown {
            return Err(format!("its claim {} does not exclude PCC", cert.claim.name()));
        }
        let bound = accepted_bound(verify_rest(cert, ParseLimits::default(), &BOTH))?;
        self.push_rest(name, cert.claim, Source::Rest(Box::new(cert.clone())), bound);
        Ok(())
    }

    /// Adds a time-to-rest certificate's set (its B kernel-checked).
    fn push_rest(&mut self, name: &str, claim: Claim, source: Source, bound: Q) {
        let set = Set {
            name: name.into(),
            kind: SetKind::Rest,
            claim,
            source,
            time_to_rest_bound: Some(bound),
            inner: Inner::Rest,
        };
        self.sets.push(Arc::new(set));
    }

    /// Adds a general body's time-to-rest certificate (docs/certificate-format.md §17) that the
    /// kernel accepts on both backends, whose claim excludes PCC and whose body is the model's
    /// (the same contacts and inertia, and the model's γ the file's γ or in its interval: the
    /// same contact covectors and impact kicks); `Err` says why it cannot serve.
    pub fn add_rest_family(
        &mut self,
        model: &Model,
        cert: &FamilyTimeToRest,
        name: &str,
    ) -> Result<(), String> {
        if cert.claim != Claim::CompleteChatterFromAllDown {
            return Err(format!("its claim {} does not exclude PCC", cert.claim.name()));
        }
        let bound = accepted_bound(verify_rest_family(cert, ParseLimits::default(), &BOTH))?;
        let ends = crate::bodies::convex::of_text(&cert.body)?;
        // The body at the run's γ, if that lies in the file's γ (a point, or an interval).
        let (lo, hi) = (&ends[0], &ends[ends.len() - 1]);
        let same = model.exact.as_ref().is_some_and(|sys| {
            let inside = lo.gamma() <= &sys.gamma && &sys.gamma <= hi.gamma();
            let at = ConvexBody::new(lo.contacts().to_vec(), lo.inertia().clone(), sys.gamma.clone());
            let named = at.map(|b| super::System::convex(&b));
            sys.shape.is_convex()
                && inside
                && named.is_ok_and(|named| sys.contacts == named.contacts && sys.kicks == named.kicks)
        });
        if !same {
            return Err(
                "it is about another body (its contacts or inertia differ from the run's, or the run's gamma is not the file's)".into()
            );
        }
        self.push_rest(name, cert.claim, Source::RestFamily(Box::new(cert.clone())), bound);
        Ok(())
    }

    /// Adds the certificate in a file (RON, or its JSON twin by the extension `.json`).
    pub fn add_file(&mut self, model: &Model, path: &std::path::Path) -> Result<(), String> {
        let text = std::fs::read_to_string(path).map_err(|e| format!("cannot read it: {e}"))?;
        let json = path.extension().is_some_and(|e| e.eq_ignore_ascii_case("json"));
        let encoding = if json { Encoding::Json } else { Encoding::Ron };
        let name = path.display().to_string();
        if kind_of(&text, encoding, Kind::Cone).is_ok_and(|k| k.0 == Kind::RestFamily) {
            let cert: FamilyTimeToRest =
                read(&text, encoding).map_err(|r| format!("rejected by the kernel: {r}"))?;
            return self.add_rest_family(model, &cert, &name);
        }
        if kind_of(&text, encoding, Kind::Cone).is_ok_and(|k| k.0 == Kind::Rest) {
            let cert: TimeToRest =
                read(&text, encoding).map_err(|r| format!("rejected by the kernel: {r}"))?;
            return self.add_rest(model, &cert, &name);
        }
        if kind_of(&text, encoding, Kind::Cone).is_ok_and(|k| k.0 == Kind::Orbit) {
            let cert = read_orbit(&text, encoding).map_err(|r| format!("rejected by the kernel: {r}"))?;
            return self.add_orbit(model, &cert, &name);
        }
        let cert = read_in(&text, encoding).map_err(|r| format!("rejected by the kernel: {r}"))?;
        self.add_cone(model, &cert, &name)
    }
}

/// The steps of a cycle rotated to its lexicographically smallest phase (one name per cycle).
pub fn canonical_cycle(steps: &[usize]) -> Vec<usize> {
    (0..steps.len().max(1))
        .map(|r| steps[r..].iter().chain(&steps[..r]).copied().collect::<Vec<_>>())
        .min()
        .unwrap_or_default()
}

/// The shortest word whose repetition is the cycle `steps`, as [`canonical_cycle`]: a cycle of
/// contacts may repeat a shorter cycle of steps (the triangle's 0,1,0,2,0,2,1,2,1 is the steps
/// 1,2,2 three times), and the orbit producer wants the shorter one.
pub fn primitive_cycle(steps: &[usize]) -> Vec<usize> {
    let len = steps.len();
    let period = (1..=len).find(|&p| len.is_multiple_of(p) && (p..len).all(|i| steps[i] == steps[i - p]));
    canonical_cycle(&steps[..period.unwrap_or(len)])
}

/// "2,2,1,1".
pub fn pattern_text(steps: &[usize]) -> String {
    steps.iter().map(ToString::to_string).collect::<Vec<_>>().join(",")
}

/// B of a time-to-rest certificate the kernel accepted on both backends, or why it cannot serve.
fn accepted_bound(verdict: Verdict<chatter_kernel::rest::Rested>) -> Result<Q, String> {
    match verdict {
        Verdict::Accepted(a) => a.bound.parse::<Q>().map_err(|e| format!("its bound cannot be read: {e}")),
        Verdict::Rejected(r) => Err(format!("rejected by the kernel: {r}")),
        Verdict::Disagree(s) => Err(format!("the kernel's backends disagree: {s}")),
    }
}
