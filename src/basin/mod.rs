//! Basin certificates' producer (untrusted; docs/basin-certificates.md §5): an orbit
//! certificate for the body, then the box of drops bisected adaptively; on each sub-box the
//! impact prefix that its centre follows in `f64` ([`float::Walker`]) is tried on the quarter
//! points, then by the kernel's rule B4 on the whole sub-box (exact intervals, malachite); a
//! sub-box where it fails is halved along the coordinate that moves the end state most, down to
//! the depth asked, below which it is left undecided. Deterministic: the leaves come out in
//! depth-first order whatever the threads do.

pub mod float;
pub mod map;
pub mod tree;

use crate::exact::{Q, QExt};
use crate::orbit::{Found, Request, certify_orbit};
use chatter_kernel::basin::drop::DIMS;
use chatter_kernel::exact::ParseLimits;
use chatter_kernel::orbit::Orbit;
use chatter_kernel::rules::basin::{Context, End, Prefix, leaf_box, read};
use chatter_kernel::rules::branches;
use chatter_kernel::rules::rest::forms;
use chatter_kernel::syntax::basin::{
    BasinCertificate, DropBox, FORMAT, Impact, Leaf, LeafVerdict, TREE_VERSION, VERSION,
};
use chatter_kernel::syntax::orbit::OrbitBody;
use chatter_kernel::verify::Backend;
use float::{Plan, Walker};
use malachite::rational::Rational;

/// A request for a basin certificate.
#[derive(Clone, Debug)]
pub struct BasinRequest {
    /// The orbit certificate's request (n, κ, γ, pattern, drops, its subdivision).
    pub orbit: Request,
    /// Lower corner of the box of drops (ω_x, ω_y, φ_x, φ_y, h).
    pub lo: [Q; DIMS],
    /// Upper corner.
    pub hi: [Q; DIMS],
    /// The deepest bisection of the box.
    pub depth: usize,
    /// The longest impact prefix tried.
    pub max_prefix: usize,
    /// A CC prefix ends where the centre's state is within this share of δ (X's parameters).
    pub entry: f64,
    /// The time-to-rest certificate's search (`None`: not tried); with one, a prefix may end in
    /// the cone of one of its nodes (`Rest` leaves: CC with a bound on the time to rest).
    pub rest: Option<crate::certify::virtual_time::Config>,
}

impl BasinRequest {
    /// The paper's drop box: ω, φ in (0, 0.1)², h in (1, 1.1) (R_1..R_5 uniform on (0, 0.1)).
    pub fn paper_box() -> ([Q; DIMS], [Q; DIMS]) {
        let (zero, tenth, one) = (Q::int(0), Q::new(1, 10), Q::int(1));
        (
            [zero.clone(), zero.clone(), zero.clone(), zero, one],
            [tenth.clone(), tenth.clone(), tenth.clone(), tenth, Q::new(11, 10)],
        )
    }
}

/// What the producer made.
pub struct Produced {
    /// The certificate (its leaves checked by the kernel on malachite while produced).
    pub certificate: BasinCertificate,
    /// The orbit certificate's search (or why none was found).
    pub orbit: Result<Found, String>,
    /// The time-to-rest certificate's search: its nodes and B, or why none (`None`: not tried).
    pub rest: Option<Result<(usize, Q), String>>,
    /// Leaves: CC, ICC, undecided.
    pub leaves: [usize; 3],
    /// Shares of the box (`f64`, for progress and the summary; the kernel's are exact).
    pub shares: [f64; 3],
}

/// The producer's state: the kernel's context, the walker, the box.
struct Producer<'a> {
    ctx: Context<Rational>,
    walker: Walker,
    lo: [Rational; DIMS],
    hi: [Rational; DIMS],
    depth: usize,
    progress: &'a (dyn Fn(f64) + Sync),
}

/// Produces a basin certificate; `progress` is told the share of the box decided so far.
pub fn produce(
    req: &BasinRequest,
    backends: &[Backend],
    progress: &(dyn Fn(f64) + Sync),
) -> Result<Produced, String> {
    // Without an orbit certificate only ICC leaves can be proved (far above the CC threshold).
    let found = certify_orbit(&req.orbit, backends).map_err(|e| e.to_string());
    let r = &req.orbit;
    let rest = req.rest.as_ref().map(|cfg| time_to_rest(r, cfg, backends));
    let mut cert = BasinCertificate {
        format: FORMAT.into(),
        version: VERSION,
        body: OrbitBody::RegularPolygon { n: r.n, kappa: r.kappa.to_string(), gamma: r.gamma.to_string() },
        drops: DropBox {
            lo: req.lo.iter().map(|x| x.to_string()).collect(),
            hi: req.hi.iter().map(|x| x.to_string()).collect(),
        },
        orbit: found.as_ref().ok().map(|f| f.certificate.clone()),
        rest: rest.as_ref().and_then(|r| r.as_ref().ok()).map(|m| m.cert.clone()),
        leaves: Vec::new(),
        producer: format!("chatter {} basin", env!("CARGO_PKG_VERSION")),
    };
    let (maps, orbit, lo, hi): (_, Option<Orbit<Rational>>, _, _) =
        read(&cert, ParseLimits::default()).map_err(|r| format!("the kernel refuses the request: {r}"))?;
    let forms = match &cert.rest {
        Some(r) => Some(
            forms::<Rational>(r, ParseLimits::default())
                .map_err(|e| format!("the kernel refuses the time-to-rest certificate: {e}"))?
                .1,
        ),
        None => None,
    };
    let facets: Vec<Vec<[Rational; 3]>> = forms.iter().flatten().map(|n| n.facets.clone()).collect();
    let mut walker = Walker::new(&maps, orbit.as_ref(), req.max_prefix).with_cones(&facets);
    walker.cut_every = found.as_ref().map_or(0, |f| base_period(&f.pattern));
    walker.entry = req.entry;
    let ctx = Context::new(maps, orbit).with_rest(forms);
    let p = Producer { ctx, walker, lo, hi, depth: req.depth, progress };
    let done = std::sync::atomic::AtomicU64::new(0);
    let unit = [0.0; DIMS].map(|_: f64| [0.0, 1.0]);
    cert.leaves = p.decide(String::new(), unit, &done);
    if cert.leaves.iter().any(|l| matches!(l.verdict, LeafVerdict::Tree { .. })) {
        cert.version = TREE_VERSION;
    }
    let mut leaves = [0usize; 3];
    let mut shares = [0.0; 3];
    for l in &cert.leaves {
        let k = chatter_kernel::rules::basin::kind(&l.verdict);
        leaves[k] += 1;
        shares[k] += 0.5f64.powi(l.path.len() as i32);
    }
    let rest = rest.map(|r| r.map(|m| (m.nodes, m.bound)));
    Ok(Produced { certificate: cert, orbit: found, rest, leaves, shares })
}

/// A time-to-rest certificate for the body whose claim excludes PCC (what `Rest` leaves need).
fn time_to_rest(
    r: &Request,
    cfg: &crate::certify::virtual_time::Config,
    backends: &[Backend],
) -> Result<crate::certify::virtual_time::Produced, String> {
    use chatter_kernel::syntax::cone::Claim;
    let made = crate::certify::virtual_time::produce(r.n, &r.kappa, &r.gamma, cfg, backends)
        .map_err(|e| e.to_string())?;
    if made.cert.claim != Claim::CompleteChatterFromAllDown {
        return Err("PCC is not excluded at this point (rule R4), so the graph does not prove CC".into());
    }
    Ok(made)
}

/// A sub-box in the unit coordinates of the box: [lo, hi] per coordinate.
type Unit = [[f64; 2]; DIMS];

impl Producer<'_> {
    /// The drop at unit coordinates u.
    fn drop_at(&self, u: &[f64; DIMS]) -> [f64; DIMS] {
        std::array::from_fn(|k| {
            let (a, b) = (
                Q::from_rational(self.lo[k].clone()).to_f64(),
                Q::from_rational(self.hi[k].clone()).to_f64(),
            );
            a + (b - a) * u[k]
        })
    }

    /// The leaves of the sub-box `path` (unit coordinates `b`), depth first.
    fn decide(&self, path: String, b: Unit, done: &std::sync::atomic::AtomicU64) -> Vec<Leaf> {
        let centre: [f64; DIMS] = std::array::from_fn(|k| (b[k][0] + b[k][1]) / 2.0);
        let plan = self.walker.plan(&self.drop_at(&centre));
        let probes = self.probes(&b, plan.as_ref());
        if let Some(plan) = &plan
            && probes.iter().all(|p| p.iter().all(Option::is_some))
            && self.kernel_accepts(&path, plan)
        {
            return self.leaf(path, verdict(plan), done);
        }
        if plan.as_ref().is_some_and(|p| !p.cc || p.rest.is_some())
            && let Some(next) = self.tree(&path, &b)
        {
            return self.leaf(path, LeafVerdict::Tree { next }, done);
        }
        if path.len() >= self.depth || (plan.is_none() && path.len() >= self.depth / 2) {
            return self.leaf(path, LeafVerdict::Undecided, done);
        }
        let followed = probes.iter().all(|p| p.iter().all(Option::is_some));
        let axis = match plan.as_ref().filter(|_| followed).and_then(|plan| self.corner_axis(&b, plan)) {
            Some(k) => k,
            None => self.axis(&b, &probes),
        };
        let halves = [0, 1].map(|side| {
            let mut c = b;
            let m = (b[axis][0] + b[axis][1]) / 2.0;
            c[axis][1 - side] = m;
            (format!("{path}{}", 2 * axis + side), c)
        });
        let [(p0, b0), (p1, b1)] = halves;
        let (mut l0, l1) = rayon::join(|| self.decide(p0, b0, done), || self.decide(p1, b1, done));
        l0.extend(l1);
        l0
    }

    fn leaf(&self, path: String, verdict: LeafVerdict, done: &std::sync::atomic::AtomicU64) -> Vec<Leaf> {
        // Volume in units of 2^-40 of the box.
        let add = 1u64 << 40usize.saturating_sub(path.len());
        let now = done.fetch_add(add, std::sync::atomic::Ordering::Relaxed) + add;
        (self.progress)(now as f64 / (1u64 << 40) as f64);
        vec![Leaf { path, verdict }]
    }

    /// For each coordinate, the ends of the plan at the two quarter points (`None`: not followed).
    fn probes(&self, b: &Unit, plan: Option<&Plan>) -> Vec<[Option<[f64; 3]>; 2]> {
        (0..DIMS)
            .map(|k| {
                [0.25, 0.75].map(|t| {
                    let u: [f64; DIMS] = std::array::from_fn(|i| {
                        let (a, c) = (b[i][0], b[i][1]);
                        if i == k { a + (c - a) * t } else { (a + c) / 2.0 }
                    });
                    plan.and_then(|p| self.walker.follow(&self.drop_at(&u), p))
                })
            })
            .collect()
    }

    /// The coordinate to halve: one along which the plan breaks, else the one whose quarter
    /// points' end states differ most (relative to the sub-box's width, widest first on ties).
    fn axis(&self, b: &Unit, probes: &[[Option<[f64; 3]>; 2]]) -> usize {
        let score = |k: usize| -> f64 {
            let width = b[k][1] - b[k][0];
            match probes[k] {
                [Some(x), Some(y)] => (0..3).map(|i| (x[i] - y[i]).abs()).fold(0.0, f64::max) + 1e-9 * width,
                _ => 1e9 + width,
            }
        };
        (0..DIMS).max_by(|&i, &j| score(i).total_cmp(&score(j)).then(j.cmp(&i))).unwrap_or(0)
    }

    /// Where the quarter points follow the plan but the kernel did not show it: the coordinate
    /// that separates the box's corners that follow the plan from those that do not (most
    /// such edges of the box, the widest on ties), if some corner does not.
    fn corner_axis(&self, b: &Unit, plan: &Plan) -> Option<usize> {
        let follows: Vec<bool> = (0..1usize << DIMS)
            .map(|c| {
                let u: [f64; DIMS] = std::array::from_fn(|k| b[k][(c >> k) & 1]);
                self.walker.follow(&self.drop_at(&u), plan).is_some()
            })
            .collect();
        if follows.iter().all(|&f| f) {
            return None;
        }
        let edges = |k: usize| {
            (0..follows.len()).filter(|&c| c >> k & 1 == 0 && follows[c] != follows[c | 1 << k]).count()
        };
        let score = |k: usize| (edges(k), b[k][1] - b[k][0]);
        (0..DIMS).filter(|&k| edges(k) > 0).max_by(|&i, &j| {
            score(i).partial_cmp(&score(j)).unwrap_or(std::cmp::Ordering::Equal).then(j.cmp(&i))
        })
    }

    /// A tree of the plans of 3^5 drops spread over the sub-box (each coordinate at 1/6, 1/2
    /// and 5/6 of its width), if they merge ([`tree::merge`]) into a tree that branches and the
    /// kernel's rule B4 for trees (malachite) shows it on the whole sub-box. Where the kernel
    /// finds a contact that the tree leaves out, the centre's walk with that impact forced there
    /// is added, [`tree::ROUNDS`] times at most.
    fn tree(&self, path: &str, b: &Unit) -> Option<Vec<Impact>> {
        const AT: [f64; 3] = [1.0 / 6.0, 0.5, 5.0 / 6.0];
        let at = |u: [f64; DIMS]| self.drop_at(&u);
        let mut plans: Vec<Plan> = (0..AT.len().pow(DIMS as u32))
            .map(|i| {
                self.walker.plan(&at(std::array::from_fn(|k| {
                    let t = AT[i / AT.len().pow(k as u32) % AT.len()];
                    b[k][0] + (b[k][1] - b[k][0]) * t
                })))
            })
            .collect::<Option<_>>()?;
        let centre = at(std::array::from_fn(|k| (b[k][0] + b[k][1]) / 2.0));
        let (lo, hi) = leaf_box(&self.lo, &self.hi, path);
        for _ in 0..=tree::ROUNDS {
            let next = tree::merge(&plans)?;
            let forced = match branches::examine(&self.ctx, &lo, &hi, &next) {
                Ok(_) => return tree::branches(&next).then_some(next),
                Err(failure) => tree::left_out(&failure)?,
            };
            plans.push(self.walker.plan_after(&centre, &forced)?);
        }
        None
    }

    /// Rule B4 of the kernel (malachite) on the sub-box `path` with `plan`.
    fn kernel_accepts(&self, path: &str, plan: &Plan) -> bool {
        let (lo, hi) = leaf_box(&self.lo, &self.hi, path);
        let end = match (plan.rest, plan.cc) {
            (Some(r), _) => End::Rest(r),
            (None, true) => End::Cc,
            (None, false) => End::Icc,
        };
        let prefix = Prefix { first: plan.first, steps: &plan.steps, cuts: &plan.cuts, end };
        self.ctx.leaf(&lo, &hi, &prefix).is_ok()
    }
}

/// The shortest period of a pattern (2,2,1,1 repeated twice: 4).
fn base_period(pattern: &[usize]) -> usize {
    (1..=pattern.len())
        .find(|&d| {
            pattern.len().is_multiple_of(d) && (d..pattern.len()).all(|i| pattern[i] == pattern[i - d])
        })
        .unwrap_or(pattern.len())
}

fn verdict(plan: &Plan) -> LeafVerdict {
    let (first, steps, cuts) = (plan.first as u64, plan.steps.clone(), plan.cuts.clone());
    if let Some(node) = plan.rest {
        return LeafVerdict::Rest { first, steps, node: node as u64 };
    }
    if plan.cc { LeafVerdict::Cc { first, steps, cuts } } else { LeafVerdict::Icc { first, steps, cuts } }
}

/// The certificate as RON text (docs/certificate-format.md §15), the orbit certificate embedded.
pub fn write_basin(c: &BasinCertificate) -> String {
    use crate::write::quoted;
    let OrbitBody::RegularPolygon { n, kappa, gamma } = &c.body;
    let list = |v: &[String]| v.iter().map(|s| quoted(s)).collect::<Vec<_>>().join(", ");
    let mut out = String::from("Certificate(\n");
    out.push_str(&format!("    format: {},\n    version: {},\n", quoted(&c.format), c.version));
    out.push_str(&format!(
        "    body: RegularPolygon(n: {n}, kappa: {}, gamma: {}),\n",
        quoted(kappa),
        quoted(gamma)
    ));
    out.push_str(&format!("    drops: (lo: [{}], hi: [{}]),\n", list(&c.drops.lo), list(&c.drops.hi)));
    if let Some(o) = &c.orbit {
        let orbit = crate::write::write_orbit(o);
        let orbit: Vec<String> = orbit.trim_end().lines().map(|l| format!("    {l}")).collect();
        out.push_str(&format!("    orbit: Some({}),\n", orbit.join("\n").trim_start()));
    }
    if let Some(r) = &c.rest {
        let rest: Vec<String> =
            crate::write::write_rest(r).trim_end().lines().map(|l| format!("    {l}")).collect();
        out.push_str(&format!("    rest: Some({}),\n", rest.join("\n").trim_start()));
    }
    out.push_str("    leaves: [\n");
    for l in &c.leaves {
        let v = match &l.verdict {
            LeafVerdict::Cc { first, steps, cuts } => {
                format!("Cc(first: {first}, steps: [{}], cuts: [{}])", join(steps), join(cuts))
            }
            LeafVerdict::Icc { first, steps, cuts } => {
                format!("Icc(first: {first}, steps: [{}], cuts: [{}])", join(steps), join(cuts))
            }
            LeafVerdict::Rest { first, steps, node } => {
                format!("Rest(first: {first}, steps: [{}], node: {node})", join(steps))
            }
            LeafVerdict::Undecided => "Undecided".into(),
            LeafVerdict::Tree { next } => format!("Tree(next: {})", tree::write(next)),
        };
        out.push_str(&format!("        (path: {}, verdict: {v}),\n", quoted(&l.path)));
    }
    out.push_str("    ],\n");
    out.push_str(&format!("    producer: {},\n)\n", quoted(&c.producer)));
    out
}

fn join(steps: &[u64]) -> String {
    steps.iter().map(u64::to_string).collect::<Vec<_>>().join(",")
}
