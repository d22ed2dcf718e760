//! Time to rest (issue 24, docs/time-to-rest.md): for the paper's bodies, the proved bound on the
//! time at which a drop's impacts accumulate beside the accumulation time that an `f64` run of the
//! same drop estimates (evidence). The rod's bound is its theorem's (§2, rule T1: t_1 + B h/|v|),
//! the plates', the hexagon's and the pentagon's from time-to-rest certificates made on the fly
//! (§5: t_1 + B h/|v|) or orbit certificates entered after the cone (§1, §4: t_k + B h/|v|).

use super::items::Context;
use super::{Item, Report, Table, Verdict};
use crate::exact::{Q, QExt, Rounding};
use crate::prove::{Effort, cone, prove_many};
use crate::simulate::{Arithmetic, Initial, Model, Options, Outcome, SetKind, Shape, simulate};

/// Impacts of an exact run (the orbit entries come after 7 to 116 impacts at these bodies).
pub const EXACT_BUDGET: usize = 300;
/// Impacts of the `f64` run whose accumulation time is compared.
pub const FLOAT_BUDGET: usize = 1000;
/// Relative rounding allowed between a proved bound and an `f64` accumulation time (a sum of
/// [`FLOAT_BUDGET`] rounded intervals, docs/time-to-rest.md §4).
pub const ROUNDING: f64 = 1e-9;

/// A body of the table: its name, n, κ, γ.
pub struct Body {
    pub name: &'static str,
    pub n: u64,
    pub kappa: Q,
    pub gamma: Q,
}

/// The rod, the square plate, the triangle plate (the paper's), and a hexagon and a pentagon point
/// below the CC threshold (the pentagon's certificate in Q(cos 2π/5), docs/time-to-rest.md §5).
pub fn bodies() -> Vec<Body> {
    let b = |name, n, k: (i64, i64), g: (i64, i64)| Body {
        name,
        n,
        kappa: Q::new(k.0, k.1),
        gamma: Q::new(g.0, g.1),
    };
    vec![
        b("rod", 2, (1, 3), (1, 20)),
        b("square plate", 4, (1, 6), (1, 100)),
        b("triangle plate", 3, (1, 8), (1, 10)),
        b("hexagon", 6, (1, 50), (1, 10)),
        b("pentagon", 5, (1, 20), (1, 10)),
    ]
}

/// One body's drops: proved outcomes and the bounds against the `f64` times.
#[derive(Clone, Debug)]
pub struct Row {
    pub name: &'static str,
    pub n: u64,
    pub kappa: Q,
    pub gamma: Q,
    pub drops: u64,
    /// Drops proved CC with a bound on the time to rest.
    pub bounded: usize,
    /// Drops proved only no-ICC-no-PCC (a cone entry, no orbit entry within the budget).
    pub no_icc_no_pcc: usize,
    /// Every other drop (undecided or another outcome).
    pub other: usize,
    /// The constants B of the sets that gave bounds, in decimals rounded up, with the set's name.
    pub constants: Vec<String>,
    /// Bounded drops with an `f64` accumulation time to compare.
    pub compared: usize,
    /// The largest `f64` accumulation time among them (evidence) and that drop's proved bound.
    pub largest: Option<(f64, f64)>,
    /// The least and the largest ratio bound / `f64` time over the compared drops.
    pub ratios: Option<(f64, f64)>,
    /// Compared drops whose bound lies below the `f64` time beyond [`ROUNDING`].
    pub below: usize,
}

/// Proves `drops` random drops of `body` (seeds 0..) and compares each proved bound with the
/// `f64` accumulation time of the same drop.
pub fn measure(body: &Body, drops: u64) -> Result<Row, String> {
    let shape = if body.n == 2 { Shape::Rod } else { Shape::Polygon(body.n) };
    let model = Model::new(shape, body.kappa.clone(), body.gamma.clone()).map_err(|e| e.to_string())?;
    let sets = cone(&model, Effort::Full);
    let proved = prove_many(&model, 0, drops, &Options::new(EXACT_BUDGET), sets, Some(Effort::Full), &|| {});
    let mut row = Row {
        name: body.name,
        n: body.n,
        kappa: body.kappa.clone(),
        gamma: body.gamma.clone(),
        drops,
        bounded: 0,
        no_icc_no_pcc: 0,
        other: 0,
        constants: constants(&proved.sets),
        compared: 0,
        largest: None,
        ratios: None,
        below: 0,
    };
    for b in &proved.briefs {
        match (b.proved, b.outcome, &b.rest_by) {
            (true, Outcome::Cc, Some(bound)) => {
                row.bounded += 1;
                compare(&mut row, &model, b.seed, bound.to_f64());
            }
            (true, Outcome::NoIccNoPcc, _) => row.no_icc_no_pcc += 1,
            _ => row.other += 1,
        }
    }
    Ok(row)
}

/// "1.2345 (orbit certificate ...)" for each set with a bound (B rounded up).
fn constants(sets: &crate::simulate::Certified) -> Vec<String> {
    sets.sets()
        .iter()
        .filter_map(|s| {
            let b = s.time_to_rest_bound.as_ref()?.decimal(4, Rounding::Up);
            let why = if s.kind == SetKind::Cone { "the rod's theorem, rule T1, checked on " } else { "" };
            Some(format!("{b} ({why}{})", s.name))
        })
        .collect()
}

/// Adds one bounded drop's comparison with its `f64` accumulation time (when it has one).
fn compare(row: &mut Row, model: &Model, seed: u64, bound: f64) {
    let f = simulate(model, &Initial::RandomDrop { seed }, Arithmetic::Float, &Options::new(FLOAT_BUDGET));
    let Some(t) = f.accumulation.filter(|t| f.evidence == Outcome::Cc && t.is_finite() && *t > 0.0) else {
        return;
    };
    row.compared += 1;
    if bound < t * (1.0 - ROUNDING) {
        row.below += 1;
    }
    if row.largest.is_none_or(|(l, _)| t > l) {
        row.largest = Some((t, bound));
    }
    let r = bound / t;
    row.ratios = Some(row.ratios.map_or((r, r), |(lo, hi)| (lo.min(r), hi.max(r))));
}

/// The table row's cells.
fn cells(r: &Row) -> Vec<String> {
    let (time, bound, ratio) = match r.largest {
        Some((t, b)) => (format!("{t:.9}"), format!("{b:.9}"), format!("{:.6}", b / t)),
        None => ("–".into(), "–".into(), "–".into()),
    };
    vec![
        r.name.to_string(),
        format!("{}, {}, {}", r.n, r.kappa, r.gamma),
        r.drops.to_string(),
        format!("{} ({} no-ICC-no-PCC, {} other)", r.bounded, r.no_icc_no_pcc, r.other),
        if r.constants.is_empty() { "–".into() } else { r.constants.join("; ") },
        time,
        bound,
        ratio,
        r.ratios.map_or("–".into(), |(lo, hi)| format!("{lo:.6} – {hi:.6}")),
    ]
}

/// The item: per body, drops proved CC with a bound and the bounds against the `f64` times.
pub fn time_to_rest(ctx: &Context, r: &mut Report) -> Result<(), String> {
    let drops = if ctx.plan.quick { 8 } else { ctx.plan.point_drops };
    let rows = bodies().iter().map(|b| measure(b, drops)).collect::<Result<Vec<_>, _>>()?;
    let header = [
        "body",
        "n, κ, γ",
        "drops",
        "proved CC with a bound",
        "B (proved; the set giving it)",
        "largest accumulation time (f64, evidence)",
        "that drop's proved bound",
        "ratio",
        "ratio over the drops",
    ];
    r.tables.push(Table {
        title: format!(
            "Time to rest: proved bounds t* ≤ t_k + B h/|v| beside the accumulation time of an f64 run of the same drop (evidence; {EXACT_BUDGET} exact impacts, {FLOAT_BUDGET} f64 impacts)"
        ),
        header: header.map(String::from).to_vec(),
        rows: rows.iter().map(cells).collect(),
    });
    let all = rows.iter().all(|x| x.bounded as u64 == x.drops && x.below == 0);
    let evidence = rows
        .iter()
        .map(|x| {
            format!(
                "{} (n = {}, κ = {}, γ = {}): {} of {} drops proved CC with a bound, {} compared with f64, {} bound(s) below the f64 time",
                x.name, x.n, x.kappa, x.gamma, x.bounded, x.drops, x.compared, x.below
            )
        })
        .collect();
    r.items.push(Item {
        title: "Time to rest: complete chatter in finite time, with a proved bound".into(),
        paper: "Complete chatter is infinitely many impacts in finite time (the mechanical problem); the paper derives v ≤ 0 for ever from its cones, not the finite time (docs/time-to-rest.md §1).".into(),
        ours: "proved: every drop counted in the table's fourth column accumulates its impacts by its bound t_k + B h/|v| (the rod by its theorem, docs/time-to-rest.md §2; the others by a time-to-rest certificate from the first impact, §5, or an orbit certificate's set entered after the cone, §1); the f64 accumulation times are evidence, and no bound lies below its drop's time beyond rounding".into(),
        verdict: Verdict::of(all),
        evidence,
        commands: vec![
            "chatter simulate --n 2 --kappa 1/3 --gamma 1/20 --exact --runs 8".into(),
            "chatter simulate --n 2 --kappa 1/3 --gamma 1/20 --runs 8 --impacts 400".into(),
            "chatter simulate --n 4 --kappa 1/6 --gamma 1/100 --exact --runs 8".into(),
        ],
        figures: vec![],
    });
    Ok(())
}
