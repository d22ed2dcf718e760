//! Maps of a one-parameter family of general bodies against gamma (issue 25 §3): the uniform
//! rectangular plate by its aspect ratio, the uniform box by its height, the lander by the spread
//! of its legs (docs/map.md "Body families"). At each point: the conjectural product criterion
//! and the PCC Lemma's pairs (docs/model.md §11.11, §11.6), the family finder's verdict, with
//! `--certify` a family certificate checked by the kernel on both backends, with `--simulate`
//! the paper's random drops in f64 (evidence) and the same drops run exactly against a
//! time-to-rest certificate of the body made with the survey's budget (proofs).

use super::grid::{Axis, Point};
use super::point::{Evaluation, PAPER_BUDGET, SimStats, Tasks};
use crate::bodies::convex::{rectangle_plate, uniform_box};
use crate::bodies::general::lander_with_spread;
use crate::bodies::inertia::Tensor;
use crate::certify::convex::{ConvexReport, ConvexRequest, certify_convex, normalised, normaliser};
use crate::certify::{ClaimChoice, Failure};
use crate::exact::{Q, Ring, parse_user_number};
use crate::finder::family::{FloatFamily, find_family};
use crate::finder::{FinderConfig, Seed};
use crate::simulate::{Arithmetic, Model, Options, Outcome, counts, simulate_many};
use crate::spectral::convex::{Direction, pair_exclusions, product_criterion, product_profile};
use chatter_kernel::exact::{ParseLimits, to_canonical};
use chatter_kernel::model::{ConvexBody, PccExclusion};
use chatter_kernel::syntax::family::ConvexBodyText;
use chatter_kernel::verify::{Backend, Verdict, verify_convex_on};
use serde::{Deserialize, Serialize};

/// The kinds of body family.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum FamilyKind {
    /// The uniform rectangular plate `aspect` x 1 (every one an affine image of the square plate).
    Rectangle,
    /// The uniform box A x B x `height` standing on its A x B face (the base, default 2 x 1).
    Box,
    /// The lander (`chatter bodies`) with its feet's horizontal positions times `spread`.
    Lander,
}

impl FamilyKind {
    /// The body's name and the parameter's name.
    pub fn names(self) -> (&'static str, &'static str) {
        match self {
            FamilyKind::Rectangle => ("rectangle", "aspect"),
            FamilyKind::Box => ("box", "height"),
            FamilyKind::Lander => ("lander", "spread"),
        }
    }
}

/// A body family: the kind and, for the box, its fixed base.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize, schemars::JsonSchema)]
pub struct BodyFamily {
    pub kind: FamilyKind,
    /// The box's base A x B (canonical `p/q`); absent for the other kinds.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<[String; 2]>")]
    pub base: Option<[Q; 2]>,
}

/// The families `--family` accepts, for messages.
pub const FAMILIES: &str = "rectangle:aspect=A:B:STEPS, box:height=A:B:STEPS (base 2 x 1), box=PxQ:height=A:B:STEPS (base P x Q), lander:spread=A:B:STEPS";

impl BodyFamily {
    /// Reads `--family KIND[=PxQ]:PARAM=LO:HI:STEPS`: the family and the parameter's axis.
    pub fn parse(text: &str) -> Result<(BodyFamily, Axis), String> {
        let bad = || format!("{text:?} is not a body family; give one of {FAMILIES}");
        let (head, rest) = text.split_once(':').ok_or_else(bad)?;
        let (param, axis) = rest.split_once('=').ok_or_else(bad)?;
        let (name, base) = match head.split_once('=') {
            Some((n, b)) => (n.trim(), Some(b)),
            None => (head.trim(), None),
        };
        let kind = [FamilyKind::Rectangle, FamilyKind::Box, FamilyKind::Lander]
            .into_iter()
            .find(|k| k.names().0 == name)
            .ok_or_else(bad)?;
        if kind.names().1 != param.trim() {
            return Err(format!("{name} varies its {}: {FAMILIES}", kind.names().1));
        }
        let base = match (kind, base) {
            (FamilyKind::Box, None) => Some([Q::int(2), Q::int(1)]),
            (FamilyKind::Box, Some(b)) => Some(box_base(b)?),
            (_, None) => None,
            (_, Some(_)) => return Err(format!("{name} has no fixed base: {FAMILIES}")),
        };
        let axis = Axis::parse(axis)?;
        if axis.lo.is_negative() {
            return Err(format!(
                "the {} axis must start at 0 or above (cell centres are then > 0)",
                param.trim()
            ));
        }
        Ok((BodyFamily { kind, base }, axis))
    }

    /// E.g. `rectangle:aspect` or `box=2x1:height` (the CSV's `family` column: no commas).
    pub fn text(&self) -> String {
        let (name, param) = self.kind.names();
        match &self.base {
            Some([a, b]) => format!("{name}={a}x{b}:{param}"),
            None => format!("{name}:{param}"),
        }
    }

    /// The body at parameter `t` (> 0) and restitution `gamma`, with its full inertia tensor
    /// when it was built from one (the lander).
    pub fn body(&self, t: &Q, gamma: &Q) -> Result<(ConvexBody<Q>, Option<Tensor>), String> {
        let one = Q::int(1);
        let r = match (self.kind, &self.base) {
            (FamilyKind::Rectangle, _) => rectangle_plate(t, &one, gamma.clone()).map(|b| (b, None)),
            (FamilyKind::Box, Some([a, b])) => uniform_box(a, b, t, gamma.clone()).map(|b| (b, None)),
            (FamilyKind::Box, None) => return Err("a box family needs its base".into()),
            (FamilyKind::Lander, _) => lander_with_spread(t, gamma).map(|(b, t)| (b, Some(t))),
        };
        r.map_err(|e| format!("{} = {t}: {e}", self.kind.names().1))
    }

    /// A short title for figures, e.g. "plate aspect × 1".
    pub fn title(&self) -> String {
        match (self.kind, &self.base) {
            (FamilyKind::Rectangle, _) => "plate aspect × 1".into(),
            (FamilyKind::Box, Some([a, b])) => format!("box {a} × {b} × height"),
            (FamilyKind::Box, None) => "box".into(),
            (FamilyKind::Lander, _) => "lander, feet × spread".into(),
        }
    }
}

fn box_base(b: &str) -> Result<[Q; 2], String> {
    let v: Vec<Q> = b.split('x').map(parse_user_number).collect::<Result<_, _>>()?;
    match v.as_slice() {
        [p, q] if p.is_positive() && q.is_positive() => Ok([p.clone(), q.clone()]),
        _ => Err(format!("box={b}: the base is two numbers > 0, PxQ (e.g. box=2x1)")),
    }
}

/// The conjectural CC criterion (the product once around the polygon counter-clockwise has a
/// real, positive dominant eigenvalue, docs/model.md §11.11) and the PCC column: some adjacent
/// pair's quadratic does not exclude PCC (the PCC Lemma, docs/model.md §11.6).
pub fn criteria(body: &ConvexBody<Q>) -> (bool, bool) {
    let cc = product_criterion(body, Direction::CounterClockwise).holds;
    let pcc = pair_exclusions(body).iter().any(|p| p.exclusion() != Some(PccExclusion::Excluded));
    (cc, pcc)
}

/// The family finder's verdict from the downward translation's images I_i(0, 0, -1), on the
/// normalised body as in `certify` (docs/model.md §11.12).
pub fn finder(body: &ConvexBody<Q>) -> &'static str {
    let Some((b, _)) = normalised(body, &normaliser(body)) else { return "inconclusive" };
    find_family(&FloatFamily::of(&b), Seed::Translation, &FinderConfig::default()).summary().label()
}

/// The first seed of a point's drops: FNV-1a of "family/t/gamma" (as [`super::point::point_seed`]).
pub fn point_seed(family: &BodyFamily, t: &Q, gamma: &Q) -> u64 {
    format!("{}/{t}/{gamma}", family.text())
        .bytes()
        .fold(0xcbf2_9ce4_8422_2325, |h, b| (h ^ b as u64).wrapping_mul(0x0100_0000_01b3))
}

/// The paper's random drops in f64 (evidence), and with a proof budget the same drops run
/// exactly ([`prove_drops`]).
fn simulate(family: &BodyFamily, p: &Point, body: &ConvexBody<Q>, tasks: &Tasks, runs: u64) -> SimStats {
    let seed = point_seed(family, &p.kappa, &p.gamma);
    let model = Model::convex(body);
    let briefs = simulate_many(&model, seed, runs, Arithmetic::Float, &Options::new(PAPER_BUDGET), &|| {});
    let impacts = briefs
        .iter()
        .map(|b| if b.outcome == Outcome::Pcc { PAPER_BUDGET } else { b.impacts.min(PAPER_BUDGET) } as u64)
        .sum();
    let mut sim =
        SimStats { runs, counts: counts(&briefs).map(|c| c as u64), proved: None, contradicted: 0, impacts };
    if tasks.proof_budget > 0 {
        let (proved, contradicted) = prove_drops(&model, body, (seed, &briefs), tasks.proof_budget);
        (sim.proved, sim.contradicted) = (Some(proved), contradicted);
    }
    sim
}

/// The drops of `evidence` run exactly (`chatter simulate --exact`'s proofs for a general body)
/// against a time-to-rest certificate of the body made with the survey's budget
/// (docs/time-to-rest.md Theorem 5.2; kernel on both backends): a drop all-down at its first
/// impact is proved CC there, with a bound on its time to rest; without a certificate no drop is
/// proved CC. The proved counts, and the drops whose proof contradicts their evidence.
fn prove_drops(
    model: &Model,
    body: &ConvexBody<Q>,
    (seed, evidence): (u64, &[crate::simulate::Brief]),
    budget: usize,
) -> ([u64; Outcome::COUNT], u64) {
    let sets = crate::prove::made_general(model, body, crate::prove::Effort::Survey);
    let runs = evidence.len() as u64;
    let proved = crate::prove::prove_many(model, seed, runs, &Options::new(budget), sets, None, &|| {});
    let contradicted = super::point::contradicted(&proved.briefs, evidence);
    (crate::simulate::proved_counts(&proved.briefs).map(|c| c as u64), contradicted)
}

/// The certification pipeline of `certify` with the regular map's survey budgets but the
/// exactifier's retries (next to the boundary the first run's overshoot fails: the lander's
/// spread map certifies 992 of its 993 points with them, 984 without, in the same wall time);
/// the tensor is recorded and re-checked (rule K0) when the body was built from one.
fn certify(body: ConvexBody<Q>, tensor: Option<&Tensor>, e: &mut Evaluation) {
    let mut req = ConvexRequest::new(body);
    req.claim = ClaimChoice::Strongest;
    req.finder.max_iterations = 3000;
    req.exactify.max_rounds = 60;
    let mut report = certify_convex(&req);
    if let Some(t) = tensor {
        record_tensor(&mut report, t, &req.backends);
    }
    match report.result {
        Ok(cert) => {
            e.certified = Some(Some(cert.claim.name()));
            e.certificate = Some(crate::write::write_convex(&cert));
        }
        Err(Failure::Internal(s)) => e.internal = Some(s),
        Err(_) => e.certified = Some(None),
    }
}

/// Records the full inertia tensor in an accepted certificate and has the kernel check it again
/// (rule K0: J is its J_eff), as `certify --body` does, so that what is written was accepted.
fn record_tensor(report: &mut ConvexReport, t: &Tensor, backends: &[Backend]) {
    let Ok(cert) = &mut report.result else { return };
    let [a, b, c, d, e, f] = t.urdf().map(|x| to_canonical(&x));
    let ConvexBodyText::ConvexPolygon { inertia_tensor, .. } = &mut cert.body;
    *inertia_tensor = Some((a, b, c, d, e, f));
    match verify_convex_on(cert, ParseLimits::default(), backends) {
        Verdict::Accepted(_) => {}
        Verdict::Rejected(r) => report.result = Err(Failure::Kernel(r)),
        Verdict::Disagree(s) => report.result = Err(Failure::Internal(s)),
    }
}

/// Evaluates one point of a family map (`p.kappa` is the body parameter).
pub fn evaluate(family: &BodyFamily, p: &Point, tasks: Tasks) -> Evaluation {
    let (body, tensor) = family.body(&p.kappa, &p.gamma).expect("a validated family grid");
    let (cc_criterion, pcc_criterion) = criteria(&body);
    let mut e = Evaluation::new(cc_criterion, pcc_criterion, finder(&body));
    if let Some(runs) = tasks.simulate {
        e.sim = Some(simulate(family, p, &body, &tasks, runs));
    }
    if tasks.certify {
        certify(body, tensor.as_ref(), &mut e);
    }
    e
}

/// The boundary of the conjectural CC criterion over the map's window: in each of `lines` + 1
/// columns (fixed parameter) the gammas in (0, 1) where the criterion changes, exactly
/// (Sturm sequences, [`product_profile`]), linked column to column.
pub fn curves(family: &BodyFamily, x: &Axis, g: &Axis, lines: u32) -> super::curves::Curves {
    use crate::exact::QExt;
    use rayon::prelude::*;
    let xs: Vec<Q> = (0..=lines)
        .map(|i| &x.lo + &((&x.hi - &x.lo) * Q::new(i as i64, lines as i64)))
        .filter(|t| t.is_positive())
        .collect();
    let (g0, g1) = (g.lo.to_f64(), g.hi.to_f64());
    let cols: Vec<(f64, Vec<super::curves::Crossing>)> = xs
        .par_iter()
        .map(|t| {
            let cs = match family.body(t, &Q::new(1, 2)) {
                Ok((body, _)) => {
                    let p = product_profile(&body, Direction::CounterClockwise);
                    super::curves::crossings(&p, "cc")
                        .into_iter()
                        .filter(|c| c.at >= g0 && c.at <= g1)
                        .collect()
                }
                Err(_) => Vec::new(),
            };
            (t.to_f64(), cs)
        })
        .collect();
    // Columns only (no rows in the parameter direction): a link may span a twentieth of the
    // gamma window, so that steep stretches stay joined.
    let cell = ((&x.hi - &x.lo).to_f64() / lines as f64, (g1 - g0) / 80.0);
    let cc = super::curves::draw_crossings(&cols, &[], cell);
    super::curves::Curves { kind: Vec::new(), cc, pcc: Vec::new() }
}
