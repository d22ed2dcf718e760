//! A producer of time-to-rest certificates (issue 24 §1; docs/time-to-rest.md §5, Theorem 5.1;
//! the file format docs/certificate-format.md §16) for a regular polygon at a point (exact in Q
//! for n = 3, 4, 6, in Q(cos 2π/n) for the other n, where cones stay rational and the covectors,
//! numerators and pieces are field elements): the virtual-time graph and covectors searched in
//! `f64` (`graph`, `covector`, `tie`), made exact (`exactify`), the scales and the bound computed exactly (`scale`,
//! `bound`), and the file's text accepted by the kernel on both backends before anything is
//! written or reported. Untrusted: only the kernel's acceptance is a proof.

mod alternate;
mod bound;
mod covector;
mod exactify;
mod frames;
mod graph;
mod numerator;
mod scale;
mod tie;
mod transported;

use crate::certify::transport::regular_preimage;
use crate::exact::{Algebraic, CosField, Q, QExt, QField, Ring};
use crate::model::float::FloatPolygon;
use chatter_kernel::certificate::{Body, Claim, Coordinates, Encoding, Generator, Param};
use chatter_kernel::check::is_irrational;
use chatter_kernel::exact::ParseLimits;
use chatter_kernel::model::{ConvexBody, PccExclusion, Polygon, pcc_quadratic};
use chatter_kernel::rest::{FIELD_VERSION, FORMAT, Node, Rested, TimeToRest, VERSION};
use chatter_kernel::rest_family::{FamilyNode, FamilyTimeToRest};
use chatter_kernel::syntax::family::{ConvexBodyText, ConvexCoordinates};
use chatter_kernel::verify::{Backend, Verdict, verify_rest_family_text_in, verify_rest_text_in};
use frames::{FloatFrames, Frames};

/// The producer's exact scalars: Q (n = 3, 4, 6) or Q(cos 2π/n) (the other n).
pub trait Num: crate::exact::OrderedField {
    /// The nearest float (for the untrusted linear programs).
    fn f64(&self) -> f64 {
        self.nearest_f64()
    }
    /// A rational >= the number (the number itself when it is rational).
    fn upper(&self) -> Q;
}

impl Num for Q {
    fn f64(&self) -> f64 {
        self.to_f64()
    }
    fn upper(&self) -> Q {
        self.clone()
    }
}

impl Num for Algebraic<Q> {
    fn upper(&self) -> Q {
        self.enclose(&Q::new(1, 1 << 60)).1
    }
}

/// The search's budgets (all finite: the producer always stops).
#[derive(Clone, Debug)]
pub struct Config {
    /// Node cap of the float graph.
    pub max_nodes: usize,
    /// A new node is its image's hull enlarged by this share about its centroid.
    pub enlarge: f64,
    /// Half-sides of the square added at every vertex of a node (room for rounding to multiples of
    /// 2^-24), tried in turn until the kernel accepts: a smaller pad keeps a node closer to the
    /// images it holds, which a self-loop may need, and changes the whole graph.
    pub pads: Vec<f64>,
    /// Where no pad gives a certificate: graphs that merge an image no node contains into the
    /// node whose hull with it grows least, when that hull's area is at most this factor times
    /// the larger of the two (`graph::build`), tried in turn with the first pad.
    pub merges: Vec<f64>,
    /// Rounds of the covector search over the tied components.
    pub rounds: usize,
    /// Grid of the covector search: grid × grid/2 directions.
    pub grid: usize,
    /// Choose the numerators a_r by the linear program that minimises B (`numerator.rs`) before
    /// the least scales (a_r = c_r b_r, `scale.rs`); without it, the scales only.
    pub linear_program: bool,
    /// Stop alternating the linear programs (`alternate::improve`) as soon as t, at the pace of
    /// the last round, could not pass 0 in the rounds left (the maps' survey; the full search
    /// runs every round while t falls: on the hard points of the bench grid the pace rule lost
    /// one certificate of 86, 2026-11-27).
    pub pace: bool,
    /// Build every graph first (one per pad and merge factor: milliseconds each) and try the
    /// closed ones with the fewest nodes first (the maps' survey: on the 16 × 16 map of n = 3 it
    /// finds the same 28 certificates in 10.4 s of searching instead of 23.6 s, 2026-11-27,
    /// because a large closed graph whose exact check fails costs up to seconds). Without it,
    /// the list order of `pads` then `merges`.
    pub smallest_first: bool,
    /// For a general body: where none of the enlargements 0.3, 0.5, 0.1 gives a certificate,
    /// also try the fallback 0.05 (`GENERAL_FALLBACK`), and search even where the certificate
    /// transported from a regular polygon is accepted (off in surveys, whose points above the
    /// threshold would all pay for the first, and which take the transported certificate as it
    /// is).
    pub fallback: bool,
}

impl Default for Config {
    fn default() -> Self {
        Config {
            max_nodes: 200,
            enlarge: 0.3,
            pads: vec![1e-3, 1e-4, 1e-5],
            merges: vec![1.3, 1.2, 1.5, 1.1, 1.05, 1.4, 1.7, 2.0, 2.5],
            rounds: 12,
            grid: 40,
            linear_program: true,
            pace: false,
            smallest_first: false,
            fallback: true,
        }
    }
}

/// A time-to-rest certificate the kernel accepted on both backends (of a regular polygon, or
/// `Produced<FamilyTimeToRest>` of a general body).
pub struct Produced<C = TimeToRest> {
    pub cert: C,
    /// The file's RON text (what the kernel read).
    pub text: String,
    /// B as the kernel accepted it.
    pub bound: Q,
    pub nodes: usize,
    pub edges: usize,
}

/// The claim of a time-to-rest file (of a regular polygon or of a general body).
pub trait RestFile {
    fn claim(&self) -> Claim;
    /// Whether the file is a regular polygon's certificate transported to an affine image of it.
    fn transported(&self) -> bool {
        false
    }
}

impl RestFile for TimeToRest {
    fn claim(&self) -> Claim {
        self.claim
    }
}

impl RestFile for FamilyTimeToRest {
    fn claim(&self) -> Claim {
        self.claim
    }
    fn transported(&self) -> bool {
        self.producer == transported::PRODUCER
    }
}

/// Why no certificate was produced: what was searched and which check failed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum NotProduced {
    /// The search or an exact check failed (the message says which).
    Failed(String),
    /// The kernel's backends disagree (a bug).
    Disagree(String),
}

impl std::fmt::Display for NotProduced {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            NotProduced::Failed(s) => f.write_str(s),
            NotProduced::Disagree(s) => write!(f, "the kernel's backends disagree: {s}"),
        }
    }
}

/// The `producer` field of the files written.
pub const PRODUCER: &str =
    "chatter certify --time-to-rest (untrusted f64 graph, covectors and linear program, exact checks)";

/// The claim the kernel can accept: `CompleteChatterFromAllDown` where R4 excludes PCC, else
/// `CcOrPccFromAllDown` (docs/certificate-format.md §16).
fn claim<E: Num>(body: &Polygon<E>) -> Claim {
    match pcc_quadratic(body).map(|q| q.exclusion()) {
        Ok(PccExclusion::Excluded) => Claim::CompleteChatterFromAllDown,
        _ => Claim::CcOrPccFromAllDown,
    }
}

/// Produces a time-to-rest certificate at (n, κ, γ), accepted by the kernel on `backends`.
pub fn produce(
    n: u64,
    kappa: &Q,
    gamma: &Q,
    cfg: &Config,
    backends: &[Backend],
) -> Result<Produced, NotProduced> {
    let region = Region { kappa: [kappa.clone(), kappa.clone()], gamma: [gamma.clone(), gamma.clone()] };
    produce_on(n, &region, cfg, backends)
}

/// A box of parameters [κ_lo, κ_hi] × [γ_lo, γ_hi] (a point when lo = hi).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Region {
    pub kappa: [Q; 2],
    pub gamma: [Q; 2],
}

impl Region {
    /// The distinct corners in the kernel's order (lo, lo), (hi, lo), (lo, hi), (hi, hi).
    fn corners(&self) -> Vec<(Q, Q)> {
        super::corners(&self.kappa, &self.gamma)
    }

    fn is_point(&self) -> bool {
        self.kappa[0] == self.kappa[1] && self.gamma[0] == self.gamma[1]
    }
}

/// Produces a time-to-rest certificate for every (κ, γ) of the region (one graph and one B:
/// docs/time-to-rest.md §5, "Boxes"), accepted by the kernel on `backends`. Boxes need
/// n = 3, 4 or 6.
pub fn produce_on(
    n: u64,
    region: &Region,
    cfg: &Config,
    backends: &[Backend],
) -> Result<Produced, NotProduced> {
    let failed = NotProduced::Failed;
    let [g0, g1] = &region.gamma;
    if !(g0.is_positive() && g1 < &Q::int(1)) {
        return Err(failed("time-to-rest certificates need 0 < gamma < 1".into()));
    }
    if region.kappa[0] > region.kappa[1] || g0 > g1 {
        return Err(failed("an interval's lower end is above its upper end".into()));
    }
    if !is_irrational(n) {
        let bodies = (region.corners().into_iter())
            .map(|(k, g)| Polygon::new(n, k, g))
            .collect::<Result<Vec<_>, _>>()
            .map_err(|e| {
                failed(format!(
                    "no exact model of n = {n} here ({e:?}): time-to-rest certificates take 3 <= n <= 64"
                ))
            })?;
        return search(&bodies, region, cfg, backends);
    }
    if !region.is_point() {
        return Err(failed("boxes of parameters need n = 3, 4 or 6 (a rational cos 2 pi/n)".into()));
    }
    let field: std::sync::Arc<CosField<Q>> = CosField::new(n)
        .ok_or_else(|| failed(format!("n = {n}: regular polygons have 3 to 64 contacts here")))?;
    let (k, g) = (Algebraic::rational(region.kappa[0].clone()), Algebraic::rational(g0.clone()));
    let body = Polygon::with_cosine(n, field.generator(), k, g).map_err(|e| failed(format!("{e:?}")))?;
    search(&[body], region, cfg, backends)
}

/// The file a front end writes from an exact graph (its claim, B, nodes, edges and numerators)
/// and has the kernel check.
type Finish<'a, E, C> = &'a dyn Fn(&Q, Graph<'_, E>) -> Result<Produced<C>, NotProduced>;

/// The regular polygons' front end: every graph of the configuration over the bodies of the
/// region's corners, searched at its centre, written as a time-to-rest certificate.
fn search<E: Num>(
    bodies: &[Polygon<E>],
    region: &Region,
    cfg: &Config,
    backends: &[Backend],
) -> Result<Produced, NotProduced> {
    let failed = NotProduced::Failed;
    let n = bodies[0].n() as u64;
    let float = |k: f64, g: f64| {
        FloatPolygon::new(n, k, g).map(|b| FloatFrames::regular(&b)).map_err(|e| failed(format!("{e:?}")))
    };
    let fbodies = (region.corners().iter())
        .map(|(k, g)| float(k.to_f64(), g.to_f64()))
        .collect::<Result<Vec<_>, _>>()?;
    let mid = |x: &[Q; 2]| (x[0].to_f64() + x[1].to_f64()) / 2.0;
    let centre = float(mid(&region.kappa), mid(&region.gamma))?;
    let claim = if bodies.iter().all(|b| claim(b) == Claim::CompleteChatterFromAllDown) {
        Claim::CompleteChatterFromAllDown
    } else {
        Claim::CcOrPccFromAllDown
    };
    let finish = |b: &Q, graph: Graph<'_, E>| {
        let edges = graph.1.len();
        accepted(certificate(n, region, claim, b, graph), backends, edges)
    };
    graphs((bodies, &fbodies), &centre, cfg, &finish)
}

/// Every graph of the configuration, in turn, until the kernel accepts one.
fn graphs<B: Frames, C>(
    (bodies, fbodies): (&[B], &[FloatFrames]),
    centre: &FloatFrames,
    cfg: &Config,
    finish: Finish<'_, B::E, C>,
) -> Result<Produced<C>, NotProduced> {
    let failed = NotProduced::Failed;
    let Some(&first) = cfg.pads.first() else {
        return Err(failed("no pad to try: the configuration's list of pads is empty".into()));
    };
    let plain = cfg.pads.iter().map(|&pad| (pad, None));
    let keys = plain.chain(cfg.merges.iter().map(|&t| (first, Some(t))));
    let build = |(pad, merge): (f64, Option<f64>)| ((pad, merge), graph::build(fbodies, cfg, pad, merge));
    let graphs: Box<dyn Iterator<Item = _>> = if cfg.smallest_first {
        let mut all: Vec<_> = keys.map(build).collect();
        all.sort_by_key(|(_, g)| (!g.closed, g.nodes.len()));
        Box::new(all.into_iter())
    } else {
        Box::new(keys.map(build))
    };
    let mut why = Vec::new();
    for ((pad, merge), g) in graphs {
        match attempt((bodies, centre), cfg, g, finish) {
            Err(NotProduced::Failed(m)) => why.push((
                (pad, merge),
                match merge {
                    None => format!("pad {pad:e}: {m}"),
                    Some(t) => format!("pad {pad:e}, merging within area factor {t}: {m}"),
                },
            )),
            done => return done,
        }
    }
    // The reasons in the list order of the configuration, whatever the order tried.
    let order = |k: &(f64, Option<f64>)| match k.1 {
        None => cfg.pads.iter().position(|&p| p == k.0).unwrap_or(0),
        Some(t) => cfg.pads.len() + cfg.merges.iter().position(|&m| m == t).unwrap_or(0),
    };
    why.sort_by_key(|(k, _)| order(k));
    Err(failed(why.into_iter().map(|(_, m)| m).collect::<Vec<_>>().join("; ")))
}

/// One graph (nodes padded by a pad, images perhaps merged into nodes: [`graph::build`]),
/// searched (at the region's centre), made exact and checked (at every corner), then written.
fn attempt<B: Frames, C>(
    (bodies, centre): (&[B], &FloatFrames),
    cfg: &Config,
    g: graph::Graph,
    finish: Finish<'_, B::E, C>,
) -> Result<Produced<C>, NotProduced> {
    let failed = NotProduced::Failed;
    let size = format!("{} nodes, {} edges", g.nodes.len(), g.edges.len());
    if !g.closed {
        return Err(failed(format!(
            "the float graph did not close ({size}; cap {} nodes): an image left v < 0 or the cap was reached",
            cfg.max_nodes
        )));
    }
    let exact =
        |e: String| failed(format!("the float graph closed ({size}) but the exact check failed: {e}"));
    let maps = covector::Maps::new(centre, &g);
    let ties = tie::ties(&|r, j| maps.back(r, j), g.nodes.len(), &g.edges);
    let reps = covector::search(&maps, &g, &ties, cfg.rounds, cfg.grid)
        .map_err(|e| failed(format!("the float graph closed ({size}) but {e}")))?;
    let nodes = exactify::nodes(bodies, &g, &ties, &reps).map_err(exact)?;
    let edges = exactify::edges(bodies, &g, &nodes).map_err(exact)?;
    exactify::initial_inside(bodies, &nodes).map_err(exact)?;
    let (nodes, edges, a, b) = match numerators(bodies, (&nodes, &edges), &ties, cfg.linear_program) {
        Ok((a, b)) => (nodes, edges, a, b),
        Err(e) if cfg.linear_program => jointly(bodies, (&g, &ties, &maps), (&nodes, &edges), cfg.pace)
            .map_err(|j| exact(format!("{e}; {j}")))?,
        Err(e) => return Err(exact(e)),
    };
    finish(&b, (&nodes, &edges, &a))
}

/// Exact nodes and edges, numerators and B.
type Finished<E> = (Vec<exactify::Node<E>>, Vec<exactify::Edge<E>>, Vec<[E; 3]>, Q);

/// Produces a time-to-rest certificate of a general convex body (docs/time-to-rest.md §5,
/// "General bodies"; docs/certificate-format.md §17), accepted by the kernel on `backends`: at
/// its γ, or, given the body at both ends of an interval of γ (`ends`, the same body but for
/// γ), for every γ of the interval (version 2: one graph and one B, the float graph built with
/// the images at both ends, which hold the images at every γ between since I_j is affine in γ;
/// searched at the middle, checked exactly at both ends). An affine image of a regular n-gon
/// (n = 3, 4, 6) also gets the regular polygon's certificate transported (`transported.rs`): in
/// a survey (`cfg.fallback` off) that is the answer when the kernel accepts it; otherwise the
/// search runs too and the least B is kept.
pub fn produce_family(
    ends: &[ConvexBody<Q>],
    tensor: Option<[Q; 6]>,
    cfg: &Config,
    backends: &[Backend],
) -> Result<Produced<FamilyTimeToRest>, NotProduced> {
    let failed = NotProduced::Failed;
    let (Some(lo), Some(hi)) = (ends.first(), ends.last()) else {
        return Err(failed("no body to certify".into()));
    };
    if !(lo.gamma().is_positive() && hi.gamma() < &Q::int(1)) {
        return Err(failed("time-to-rest certificates need 0 < gamma < 1".into()));
    }
    if lo.gamma() > hi.gamma() {
        return Err(failed("an interval's lower end is above its upper end".into()));
    }
    let excluded = ends.iter().all(|body| {
        (0..body.n() as i64)
            .all(|k| body.pair_pcc_quadratic(k).is_ok_and(|q| q.exclusion() == PccExclusion::Excluded))
    });
    let claim = if excluded { Claim::CompleteChatterFromAllDown } else { Claim::CcOrPccFromAllDown };
    let interval = (lo.gamma() != hi.gamma()).then(|| hi.gamma());
    let finish = |b: &Q, graph: Graph<'_, Q>| {
        let cert = family_certificate((lo, interval), tensor.as_ref(), claim, b, graph);
        let text = crate::write::write_rest_family(&cert);
        let v = verify_rest_family_text_in(&text, Encoding::Ron, ParseLimits::default(), backends);
        produced(v, cert, text, graph.1.len())
    };
    let floats: Vec<FloatFrames> = ends.iter().map(FloatFrames::of).collect();
    let centre = match interval {
        None => FloatFrames::of(lo),
        Some(g) => {
            let mid = (lo.gamma() + g) / Q::int(2);
            let body = ConvexBody::new(lo.contacts().to_vec(), lo.inertia().clone(), mid);
            FloatFrames::of(&body.map_err(|e| failed(format!("the body at the interval's middle: {e:?}")))?)
        }
    };
    let mut why = Vec::new();
    let moved = match regular_preimage(lo) {
        None => None,
        Some(pre) => match transported::transported(ends, &pre, tensor.as_ref(), cfg, backends) {
            Ok(p) if !cfg.fallback => return Ok(p),
            Ok(p) => Some(p),
            Err(NotProduced::Failed(m)) => {
                why.push(format!("transport from the regular n = {} polygon: {m}", pre.n));
                None
            }
            Err(e) => return Err(e),
        },
    };
    let mut best: Option<Produced<FamilyTimeToRest>> = None;
    for (k, enlarge) in GENERAL_ENLARGEMENTS.into_iter().chain(GENERAL_FALLBACK).enumerate() {
        if k >= GENERAL_ENLARGEMENTS.len() && (best.is_some() || !cfg.fallback) {
            break;
        }
        let cfg = Config { enlarge, ..cfg.clone() };
        match graphs((ends, &floats), &centre, &cfg, &finish) {
            Ok(p) if best.as_ref().is_none_or(|b| p.bound < b.bound) => best = Some(p),
            Ok(_) => {}
            Err(NotProduced::Failed(m)) => why.push(format!("nodes enlarged by {enlarge}: {m}")),
            Err(e) => return Err(e),
        }
    }
    let least = |a: Produced<_>, b: Produced<_>| if b.bound < a.bound { b } else { a };
    match (moved, best) {
        (Some(a), Some(b)) => Ok(least(a, b)),
        (a, b) => a.or(b).ok_or_else(|| NotProduced::Failed(why.join("; "))),
    }
}

/// The enlargements of a new node tried for a general body, keeping the least B of those the
/// kernel accepts (docs/time-to-rest.md §5, "General bodies": at the lander, γ = 1/50, they give
/// B ≈ 23,530, 66.9 and none; at γ = 1/20 none, none and 1,289).
const GENERAL_ENLARGEMENTS: [f64; 3] = [0.3, 0.5, 0.1];

/// Enlargements tried only when none of [`GENERAL_ENLARGEMENTS`] gives a graph the kernel
/// accepts: at the triangle plate (0,0 3,0 1,2), γ = 1/20, the enlargement 0.05 gives B ≈ 6.50
/// where the others give none; tried after them, it costs nothing where they succeed (alone it
/// gave larger B or none on the other bodies of docs/time-to-rest.md §5, "General bodies").
const GENERAL_FALLBACK: [f64; 1] = [0.05];

/// The fields of a general body's file (over [γ, `hi`] when `hi` is given): nodes 0..n-1 are
/// the entries of contacts 0..n-1.
fn family_certificate(
    (body, hi): (&ConvexBody<Q>, Option<&Q>),
    tensor: Option<&[Q; 6]>,
    claim: Claim,
    bound: &Q,
    (nodes, edges, a): Graph<'_, Q>,
) -> FamilyTimeToRest {
    let node = |(r, x): (usize, &exactify::Node<Q>)| FamilyNode {
        contact: x.label,
        cone: x.cone.vertices.iter().map(generator).collect(),
        weight: generator(&x.weight),
        numerator: generator(&a[r]),
        next: edges.iter().filter(|e| e.from == r).map(|e| (e.step as u64, e.to)).collect(),
    };
    let nodes = nodes.iter().enumerate().map(node).collect();
    family_file((body, hi), tensor, claim, bound, ((0..body.n()).collect(), nodes), PRODUCER)
}

/// Three exact numbers as a generator's canonical text.
fn generator(v: &[Q; 3]) -> Generator {
    Generator(v.iter().map(ToString::to_string).collect())
}

/// A general body's file (over [γ, `hi`] when `hi` is given, version 2) with these entries and
/// nodes.
fn family_file(
    (body, hi): (&ConvexBody<Q>, Option<&Q>),
    tensor: Option<&[Q; 6]>,
    claim: Claim,
    bound: &Q,
    (entries, nodes): (Vec<usize>, Vec<FamilyNode>),
    producer: &str,
) -> FamilyTimeToRest {
    let s = |q: &Q| q.to_string();
    let j = body.inertia();
    let (gamma, version) = match hi {
        None => (Param::Point(s(body.gamma())), chatter_kernel::rest_family::VERSION),
        Some(hi) => (Param::Interval(s(body.gamma()), s(hi)), chatter_kernel::rest_family::INTERVAL_VERSION),
    };
    FamilyTimeToRest {
        format: chatter_kernel::rest_family::FORMAT.into(),
        version,
        body: ConvexBodyText::ConvexPolygon {
            contacts: body.contacts().iter().map(|c| (s(&c[0]), s(&c[1]))).collect(),
            inertia: (s(&j[0][0]), s(&j[0][1]), s(&j[1][1])),
            gamma,
            inertia_tensor: tensor.map(|t| (s(&t[0]), s(&t[1]), s(&t[2]), s(&t[3]), s(&t[4]), s(&t[5]))),
        },
        coordinates: ConvexCoordinates::PaperVelocities,
        claim,
        bound: bound.to_string(),
        entries,
        nodes,
        producer: producer.into(),
    }
}

/// The kernel's verdict on a file's text: the certificate, or why not.
fn produced<C>(v: Verdict<Rested>, cert: C, text: String, edges: usize) -> Result<Produced<C>, NotProduced> {
    match v {
        Verdict::Accepted(a) => {
            let bound = a
                .bound
                .parse::<Q>()
                .map_err(|e| NotProduced::Failed(format!("the bound cannot be read: {e}")))?;
            Ok(Produced { nodes: a.nodes, cert, text, bound, edges })
        }
        Verdict::Rejected(r) => Err(NotProduced::Failed(format!("the kernel rejected the graph: {r}"))),
        Verdict::Disagree(s) => Err(NotProduced::Disagree(s)),
    }
}

/// Where the numerators' program fails for the search's covectors: covectors and numerators by
/// alternating linear programs ([`alternate`]), then made exact and checked as before.
fn jointly<B: Frames>(
    bodies: &[B],
    (g, ties, maps): (&graph::Graph, &tie::Ties, &covector::Maps),
    (nodes, edges): exactify::Exact<'_, B::E>,
    pace: bool,
) -> Result<Finished<B::E>, String> {
    let kicks = (0..nodes.len())
        .map(|k| match ties.rep[k] == k {
            true => maps.tied_kicks(g, ties, k).iter().map(|v| [v.x, v.y, v.z]).collect(),
            false => Vec::new(),
        })
        .collect();
    let data = alternate::Data::new(bodies, (nodes, edges), ties, kicks)?;
    let start = nodes.iter().map(|x| x.weight.clone().map(|w| w.f64())).collect();
    let better = alternate::improve(&data, start, pace)
        .ok_or("alternating the covectors' and the numerators' linear programs (at most 30 rounds) found no covectors whose numerators keep (G3)")?;
    let reps: Vec<nalgebra::Vector3<f64>> =
        better.iter().map(|v| nalgebra::Vector3::new(v[0], v[1], v[2])).collect();
    let nodes = exactify::nodes(bodies, g, ties, &reps)?;
    let edges = exactify::edges(bodies, g, &nodes)?;
    let x = numerator::numerators(bodies, &nodes, &edges, ties)
        .map_err(|e| format!("after alternating, the numerators' linear program: {e}"))?;
    Ok((nodes, edges, x.a, x.bound))
}

/// Numerators a_r and B.
type Numerated<E> = (Vec<[E; 3]>, Q);

/// The numerators a_r and B: the least B of the linear program ([`numerator`]), else
/// a_r = c_r b_r with the least scales ([`scale`]); an error says why both failed.
fn numerators<B: Frames>(
    bodies: &[B],
    (nodes, edges): exactify::Exact<'_, B::E>,
    ties: &tie::Ties,
    linear_program: bool,
) -> Result<Numerated<B::E>, String> {
    let lp = match linear_program.then(|| numerator::numerators(bodies, nodes, edges, ties)) {
        Some(Ok(x)) => return Ok((x.a, x.bound)),
        Some(Err(e)) => format!("; the numerators' linear program: {e}"),
        None => String::new(),
    };
    let also = |e: String| format!("{e}{lp}");
    let mut cons = Vec::new();
    for body in bodies {
        cons.extend(scale::constraints(body, nodes, edges).map_err(also)?);
    }
    let c = scale::scales(nodes.len(), &cons).map_err(also)?;
    let scaled = |(x, c): (&exactify::Node<B::E>, &Q)| x.weight.clone().map(|w| w.times(&B::E::from_q(c)));
    let a: Vec<[B::E; 3]> = nodes.iter().zip(&c).map(scaled).collect();
    let mut b = Q::int(0);
    for body in bodies {
        b = b.max(bound::bound(body, nodes, &a, 20).map_err(also)?);
    }
    Ok((a, b))
}

/// The exact graph: nodes, edges and numerators.
type Graph<'a, E> = (&'a [exactify::Node<E>], &'a [exactify::Edge<E>], &'a [[E; 3]]);

/// The certificate's fields.
fn certificate<E: Num>(
    n: u64,
    region: &Region,
    claim: Claim,
    bound: &Q,
    (nodes, edges, a): Graph<'_, E>,
) -> TimeToRest {
    let text = |v: &[E; 3]| Generator(v.iter().map(ToString::to_string).collect());
    let node = |(r, x): (usize, &exactify::Node<E>)| Node {
        cone: x.cone.vertices.iter().map(text).collect(),
        weight: text(&x.weight),
        scale: String::new(),
        numerator: text(&a[r]),
        next: edges.iter().filter(|e| e.from == r).map(|e| (e.step as u64, e.to)).collect(),
    };
    TimeToRest {
        format: FORMAT.into(),
        version: if is_irrational(n) || !region.is_point() { FIELD_VERSION } else { VERSION },
        body: Body::RegularPolygon { n, kappa: param(&region.kappa), gamma: param(&region.gamma) },
        coordinates: Coordinates::ContactVelocities,
        claim,
        bound: bound.to_string(),
        nodes: nodes.iter().enumerate().map(node).collect(),
        producer: PRODUCER.into(),
    }
}

/// A parameter as written: a number, or an interval [lo, hi].
fn param(x: &[Q; 2]) -> Param {
    match x[0] == x[1] {
        true => Param::Point(x[0].to_string()),
        false => Param::Interval(x[0].to_string(), x[1].to_string()),
    }
}

/// The file's text checked by the kernel on both backends, as `chatter verify` reads it.
fn accepted(cert: TimeToRest, backends: &[Backend], edges: usize) -> Result<Produced, NotProduced> {
    let text = crate::write::write_rest(&cert);
    match verify_rest_text_in(&text, Encoding::Ron, ParseLimits::default(), backends) {
        // On a box, PCC may be excluded at every corner but not shown on the whole box (rule R4's
        // Bernstein bounds): the weaker claim then.
        Verdict::Rejected(r)
            if r.code.as_str() == "pcc-not-excluded" && cert.claim == Claim::CompleteChatterFromAllDown =>
        {
            accepted(TimeToRest { claim: Claim::CcOrPccFromAllDown, ..cert }, backends, edges)
        }
        Verdict::Rejected(r) => Err(NotProduced::Failed(format!(
            "the kernel rejected the graph ({} nodes): {r}",
            cert.nodes.len()
        ))),
        v => produced(v, cert, text, edges),
    }
}
