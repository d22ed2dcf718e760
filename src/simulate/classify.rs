//! The driver loop and the CC / PCC / ICC classification, the same for both arithmetics.
//!
//! Rules, in the order they are applied (every verdict records the rule in [`Decision`]):
//! 1. ICC when v > 0 at any time (the paper's Lemma: v never decreases, so the body leaves);
//!    checked at the start and after every impact.
//! 2. ICC when no contact approaches the floor (then v > 0 or p = 0, as v is the mean of the
//!    u_k). p = 0 exactly (possible only with gamma = 0 and a zero coupling, e.g. the rod with
//!    kappa = 1) is a body at rest after finitely many impacts: no chatter, reported as ICC
//!    with its own [`Decision::AtRest`].
//! 3. "simultaneous" when two or more contacts would land at the same instant: an exact tie of
//!    rational times, or (`f64`) times equal to within [`super::float::NEAR_TIE`]. Never resolved.
//! 4. PCC while two adjacent contacts alternate (n ≥ 3, at least [`PCC_MIN_RUN`] impacts), tested
//!    after every impact, and only when the PCC Lemma allows it
//!    ([`super::system::System::pcc_possible`]: the pair's step map has real eigenvalues):
//!    exact engines by the exact pair-chatter proof ([`super::pcc::prove_pair_chatter`]), `f64`
//!    engines by the paper's criterion with ε. Where the Lemma excludes PCC the criterion can still
//!    hold for a while (a pair phase that ends after tens of impacts, when the state is already
//!    within 1e-16 of m_(i,i+1)); it is then overruled and counted in [`Run::pcc_overruled`].
//! 5. `f64` only: an interval of exactly 0 with gamma > 0 cannot happen in exact dynamics after
//!    the first impact; it means that heights were lost in rounding: "undecided".
//! 6. When the budget is used up:
//!    - still alternating on an adjacent pair where the Lemma allows PCC: PCC if the exact proof
//!      or the paper's criterion holds now, otherwise "undecided" (complete chatter is impossible
//!      there: an adjacent pair alone cannot remove the velocity component along m_(i,i+1));
//!    - otherwise CC when the time intervals converge: with the budget N cut into quarters, the
//!      mean log2 interval must drop by at least [`CC_MIN_BITS`] from the 2nd to the 3rd quarter
//!      and again from the 3rd to the 4th; "undecided" when it does not (contraction per impact
//!      too close to 1 to tell within the budget) or when N < [`MIN_BUDGET_FOR_CC`].

use super::engine::{Engine, Snapshot, Step};
use super::pcc::{PaperPcc, paper_criterion};
use super::system::{FloatSystem, MAX_CONTACTS};
use crate::exact::{QExt, Ring};

/// Minimal alternation length before the PCC tests run (then after every impact).
pub const PCC_MIN_RUN: usize = 6;
/// Minimal drop of the mean log2 interval between consecutive quarters of the budget, for CC.
pub const CC_MIN_BITS: f64 = 4.0;
/// Smallest budget for which the CC test is made.
pub const MIN_BUDGET_FOR_CC: usize = 16;
/// Default ε of the paper's PCC criterion (the paper does not state its value).
pub const DEFAULT_PCC_EPSILON: f64 = 1e-8;

/// The five outcomes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Outcome {
    Cc,
    Pcc,
    Icc,
    Undecided,
    Simultaneous,
}

impl Outcome {
    pub const ALL: [Outcome; 5] =
        [Outcome::Cc, Outcome::Pcc, Outcome::Icc, Outcome::Undecided, Outcome::Simultaneous];

    /// The name used in output and JSON.
    pub fn name(self) -> &'static str {
        match self {
            Outcome::Cc => "CC",
            Outcome::Pcc => "PCC",
            Outcome::Icc => "ICC",
            Outcome::Undecided => "undecided",
            Outcome::Simultaneous => "simultaneous",
        }
    }
}

impl std::fmt::Display for Outcome {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// Singular for one impact in generated text.
pub fn singular(s: String) -> String {
    s.replace(" 1 impacts", " 1 impact").replace("(1 impacts", "(1 impact")
}

/// Which test decided, with its evidence. `after` counts the impacts done at that point.
#[derive(Clone, Debug, PartialEq)]
pub enum Decision {
    /// v > 0 (ICC).
    VPositive { after: usize },
    /// No contact approaches and p ≠ 0 (ICC).
    NoApproach { after: usize },
    /// p = 0 exactly after finitely many impacts (ICC: no chatter; the body is at rest).
    AtRest { after: usize },
    /// Contacts landing at the same instant.
    Tie { after: usize, contacts: Vec<usize>, exact: bool },
    /// The paper's criterion held (PCC).
    PaperPcc { after: usize, test: PaperPcc, epsilon: f64 },
    /// The exact pair-chatter proof held (PCC if v* < 0, CC if p* = 0).
    ExactPair { after: usize, pair: (usize, usize), time_bound: f64, v_limit: f64 },
    /// Budget exhausted with converging intervals (CC); drops in bits between quarters.
    Converging { bits_per_impact: f64, drops: [f64; 2] },
    /// Budget exhausted, intervals not clearly converging (undecided).
    NotConverging { bits_per_impact: f64, drops: [f64; 2] },
    /// Budget exhausted while an adjacent pair alternates without meeting a PCC test.
    PairNotSettled { pair: (usize, usize), run: usize, reason: String },
    /// Budget too small for the CC test.
    BudgetTooSmall { budget: usize },
    /// The `f64` state became non-finite or lost its heights in rounding (undecided).
    Breakdown { after: usize },
}

impl Decision {
    /// A short machine-readable name of the test.
    pub fn key(&self) -> &'static str {
        match self {
            Decision::VPositive { .. } => "v-positive",
            Decision::NoApproach { .. } => "no-contact-approaches",
            Decision::AtRest { .. } => "at-rest",
            Decision::Tie { exact: true, .. } => "exact-tie",
            Decision::Tie { exact: false, .. } => "float-near-tie",
            Decision::PaperPcc { .. } => "paper-pcc-criterion",
            Decision::ExactPair { .. } => "exact-pair-chatter-proof",
            Decision::Converging { .. } => "converging-intervals",
            Decision::NotConverging { .. } => "contraction-too-weak",
            Decision::PairNotSettled { .. } => "pair-not-settled",
            Decision::BudgetTooSmall { .. } => "budget-too-small",
            Decision::Breakdown { .. } => "float-precision-exhausted",
        }
    }

    /// One sentence naming the test and its evidence.
    pub fn describe(&self) -> String {
        singular(self.describe_raw())
    }

    fn describe_raw(&self) -> String {
        match self {
            Decision::VPositive { after } => format!(
                "v > 0 after {after} impacts (the paper's Lemma: v never decreases, so the body leaves)"
            ),
            Decision::NoApproach { after } => {
                format!("no contact approaches the floor after {after} impacts")
            }
            Decision::AtRest { after } => format!(
                "no contact approaches after {after} impacts: the velocity is exactly zero (plastic \
                 landing at rest, finitely many impacts, no chatter)"
            ),
            Decision::Tie { after, contacts, exact } => {
                let list = contacts.iter().map(ToString::to_string).collect::<Vec<_>>().join(", ");
                if *exact {
                    format!("exact tie after {after} impacts: contacts {list} land at the same rational time")
                } else {
                    format!(
                        "f64 near-tie after {after} impacts: contacts {list} land within rounding of each \
                         other (rerun with --exact to decide)"
                    )
                }
            }
            Decision::PaperPcc { after, test, epsilon } => format!(
                "the paper's PCC criterion after {after} impacts: state within eps = {epsilon:e} of a \
                 multiple of m_({},{}) (1 - cos = {:.1e} for q, 1 + cos = {:.1e} for p); all contacts \
                 then land together (undecidable)",
                test.pair.0, test.pair.1, test.q_defect, test.p_defect
            ),
            Decision::ExactPair { after, pair, time_bound, v_limit } => {
                if *v_limit < 0.0 {
                    format!(
                        "exact pair-chatter proof after {after} impacts: contacts {} and {} chatter to rest \
                         within time {time_bound:.3e}, no other contact lands first, limit velocity \
                         v* = {v_limit:.6} times m_({},{}); all contacts then land together (undecidable)",
                        pair.0, pair.1, pair.0, pair.1
                    )
                } else {
                    format!(
                        "exact pair-chatter proof after {after} impacts: contacts {} and {} bring the \
                         whole body to rest within time {time_bound:.3e}",
                        pair.0, pair.1
                    )
                }
            }
            Decision::Converging { bits_per_impact, drops } => format!(
                "budget exhausted with converging time intervals: mean log2 interval drops by {:.1} and \
                 {:.1} bits between the last quarters ({bits_per_impact:.3} bits per impact, ratio {:.4})",
                drops[0],
                drops[1],
                (-bits_per_impact).exp2()
            ),
            Decision::NotConverging { bits_per_impact, drops } => format!(
                "budget exhausted, contraction too close to 1 to tell: mean log2 interval drops by {:.1} \
                 and {:.1} bits between the last quarters (needs {CC_MIN_BITS} each; {bits_per_impact:.4} \
                 bits per impact)",
                drops[0], drops[1]
            ),
            Decision::PairNotSettled { pair, run, reason } => format!(
                "budget exhausted while contacts {} and {} alternate ({run} impacts) without meeting a PCC \
                 test ({reason}); CC is impossible on an adjacent pair",
                pair.0, pair.1
            ),
            Decision::BudgetTooSmall { budget } => {
                format!(
                    "budget of {budget} impacts too small to judge convergence (needs {MIN_BUDGET_FOR_CC})"
                )
            }
            Decision::Breakdown { after } => format!(
                "f64 precision exhausted after {after} impacts (state not finite, or an interval of \
                 exactly 0 with gamma > 0); rerun with --exact"
            ),
        }
    }
}

/// Simulation options.
#[derive(Clone, Copy, Debug)]
pub struct Options {
    /// Impact budget.
    pub budget: usize,
    /// ε of the paper's PCC criterion.
    pub pcc_epsilon: f64,
    /// Keep one [`Record`] per impact.
    pub record: bool,
}

impl Options {
    pub fn new(budget: usize) -> Options {
        Options { budget, pcc_epsilon: DEFAULT_PCC_EPSILON, record: false }
    }
}

/// One impact, for trajectories and plots.
#[derive(Clone, Debug, PartialEq)]
pub struct Record {
    /// Impact number, from 1.
    pub impact: usize,
    pub contact: usize,
    /// Time of the impact since the start.
    pub time: f64,
    /// log2 of the interval since the previous impact (or the start).
    pub log2_dt: f64,
    /// Post-impact state.
    pub state: Snapshot,
}

/// The result of one simulation.
#[derive(Clone, Debug)]
pub struct Run {
    pub outcome: Outcome,
    pub decision: Decision,
    pub impacts: usize,
    pub budget: usize,
    /// The contact of every impact.
    pub sequence: Vec<u8>,
    /// Time of the last impact (or of the tie) since the start.
    pub time: f64,
    /// Estimated accumulation time (CC, PCC): `time` plus 2^`tail_log2`.
    pub accumulation: Option<f64>,
    /// log2 of the estimated time from the last impact to the accumulation point (an upper
    /// bound when the exact pair proof decided).
    pub tail_log2: Option<f64>,
    /// Mean contraction of the intervals over the last half of the budget, bits per impact.
    pub contraction: Option<f64>,
    pub initial: Snapshot,
    /// The state at the end (post-impact).
    pub last: Snapshot,
    pub exact: bool,
    /// One record per impact when [`Options::record`].
    pub records: Vec<Record>,
    /// Pair phases in which the paper's PCC criterion held although the PCC Lemma excludes PCC
    /// for this body (the criterion was overruled; such phases end, see the module doc).
    pub pcc_overruled: usize,
}

/// Running sums of log2 intervals over the 2nd, 3rd and 4th quarters of the budget.
struct Quarters {
    bounds: [usize; 4],
    sums: [f64; 3],
}

impl Quarters {
    fn new(n: usize) -> Quarters {
        Quarters { bounds: [n / 4, n / 2, 3 * n / 4, n], sums: [0.0; 3] }
    }

    #[inline]
    fn add(&mut self, i: usize, l: f64) {
        let b = &self.bounds;
        if i >= b[0] {
            let w = usize::from(i >= b[1]) + usize::from(i >= b[2]);
            self.sums[w] += l;
        }
    }

    fn means(&self) -> [f64; 3] {
        let b = &self.bounds;
        [
            self.sums[0] / (b[1] - b[0]) as f64,
            self.sums[1] / (b[2] - b[1]) as f64,
            self.sums[2] / (b[3] - b[2]) as f64,
        ]
    }
}

/// Runs `eng` until a rule of the module doc decides.
pub fn drive<E: Engine>(eng: &mut E, fs: &FloatSystem, opts: &Options) -> Run {
    let n = fs.n;
    let budget = opts.budget;
    let mut adjacent = [[false; MAX_CONTACTS]; MAX_CONTACTS];
    if n >= 3 {
        for a in 0..n {
            adjacent[a][(a + 1) % n] = true;
            adjacent[(a + 1) % n][a] = true;
        }
    }
    let initial = eng.snapshot();
    let mut seq: Vec<u8> = Vec::with_capacity(budget);
    let mut records = Vec::new();
    let mut quarters = Quarters::new(budget);
    let mut tail_log = [0.0f64; 3]; // log2 of the last three intervals, newest first
    let mut alt = 0usize; // length of the alternating adjacent-pair tail
    let mut pair_note = String::from("not tested");
    let eps = opts.pcc_epsilon;

    let mut overruled = 0usize;
    let mut overruled_here = false;
    let finish =
        |outcome, decision, seq: Vec<u8>, records, eng: &E, tail: Option<f64>, contraction, pcc_overruled| {
            Run {
                outcome,
                decision,
                impacts: seq.len(),
                budget,
                sequence: seq,
                time: eng.time(),
                accumulation: tail.map(|l: f64| eng.time() + l.exp2()),
                tail_log2: tail,
                contraction,
                initial: initial.clone(),
                last: eng.snapshot(),
                exact: eng.is_exact(),
                records,
                pcc_overruled,
            }
        };
    // Every exit hands the trace (sequence, records, engine, overruled count) to `finish`.
    macro_rules! done {
        ($outcome:expr, $decision:expr, $tail:expr, $contraction:expr) => {
            finish($outcome, $decision, seq, records, eng, $tail, $contraction, overruled)
        };
    }
    let pair_tail = |tail_log: &[f64; 3]| -> Option<f64> {
        // log2 of the geometric tail from the last two intervals of one contact (per impact).
        let per = (tail_log[0] - tail_log[2]) / 2.0;
        (per < 0.0).then(|| tail_log[0] + per - (1.0 - per.exp2()).log2())
    };

    loop {
        let k = seq.len();
        if eng.v_positive() {
            return done!(Outcome::Icc, Decision::VPositive { after: k }, None, None);
        }
        if k == budget {
            break;
        }
        match eng.step() {
            Step::Impact { contact, dt } => {
                if dt.m == 0.0 && k > 0 && fs.gamma > 0.0 && !eng.is_exact() {
                    let d = Decision::Breakdown { after: k };
                    return done!(Outcome::Undecided, d, None, None);
                }
                let l = dt.log2_fast();
                if k > 0 {
                    quarters.add(k, l);
                }
                tail_log = [l, tail_log[0], tail_log[1]];
                alt = if k >= 1 && adjacent[contact][seq[k - 1] as usize] {
                    if k >= 2 && seq[k - 2] as usize == contact { alt + 1 } else { 2 }
                } else {
                    1
                };
                if alt < PCC_MIN_RUN {
                    overruled_here = false;
                }
                seq.push(contact as u8);
                if opts.record {
                    records.push(Record {
                        impact: k + 1,
                        contact,
                        time: eng.time(),
                        log2_dt: dt.log2(),
                        state: eng.snapshot(),
                    });
                }
                if alt >= PCC_MIN_RUN {
                    let other = seq[k - 1] as usize;
                    if !fs.pcc_possible {
                        if !overruled_here && paper_criterion(fs, &eng.snapshot(), contact, other).holds(eps)
                        {
                            overruled += 1;
                            overruled_here = true;
                        }
                    } else if let Some(proof) = eng.prove_pair(contact, other) {
                        match proof {
                            Ok(pr) => {
                                let d = Decision::ExactPair {
                                    after: k + 1,
                                    pair: pr.pair,
                                    time_bound: pr.time_bound.to_f64(),
                                    v_limit: pr.v_limit.to_f64(),
                                };
                                let acc = Some(super::exact::scaled(&pr.time_bound).log2());
                                let o = if pr.v_limit.is_zero() { Outcome::Cc } else { Outcome::Pcc };
                                return done!(o, d, acc, None);
                            }
                            Err(e) => pair_note = format!("exact proof: {e}"),
                        }
                    } else {
                        let test = paper_criterion(fs, &eng.snapshot(), contact, other);
                        if test.holds(eps) {
                            let d = Decision::PaperPcc { after: k + 1, test, epsilon: eps };
                            let acc = pair_tail(&tail_log);
                            return done!(Outcome::Pcc, d, acc, None);
                        }
                        pair_note = format!(
                            "paper's criterion: 1 - cos = {:.1e}, 1 + cos = {:.1e}, eps = {eps:e}",
                            test.q_defect, test.p_defect
                        );
                    }
                }
            }
            Step::Tie { contacts, exact, .. } => {
                let d = Decision::Tie { after: k, contacts, exact };
                return done!(Outcome::Simultaneous, d, None, None);
            }
            Step::NoApproach => {
                let d = if eng.at_rest() {
                    Decision::AtRest { after: k }
                } else {
                    Decision::NoApproach { after: k }
                };
                let o = Outcome::Icc;
                return done!(o, d, None, None);
            }
            Step::Breakdown => {
                return done!(Outcome::Undecided, Decision::Breakdown { after: k }, None, None);
            }
        }
    }

    // Budget exhausted.
    let k = seq.len();
    if fs.pcc_possible && alt >= PCC_MIN_RUN {
        let (hit, other) = (seq[k - 1] as usize, seq[k - 2] as usize);
        if let Some(Ok(pr)) = eng.prove_pair(hit, other) {
            let d = Decision::ExactPair {
                after: k,
                pair: pr.pair,
                time_bound: pr.time_bound.to_f64(),
                v_limit: pr.v_limit.to_f64(),
            };
            let acc = Some(super::exact::scaled(&pr.time_bound).log2());
            let o = if pr.v_limit.is_zero() { Outcome::Cc } else { Outcome::Pcc };
            return done!(o, d, acc, None);
        }
        let test = paper_criterion(fs, &eng.snapshot(), hit, other);
        if test.holds(eps) {
            let acc = pair_tail(&tail_log);
            let d = Decision::PaperPcc { after: k, test, epsilon: eps };
            return done!(Outcome::Pcc, d, acc, None);
        }
        let reason = format!(
            "{pair_note}; at the end 1 - cos = {:.1e}, 1 + cos = {:.1e}, eps = {eps:e}",
            test.q_defect, test.p_defect
        );
        let d = Decision::PairNotSettled { pair: (hit.min(other), hit.max(other)), run: alt, reason };
        return done!(Outcome::Undecided, d, None, None);
    }
    if budget < MIN_BUDGET_FOR_CC {
        return done!(Outcome::Undecided, Decision::BudgetTooSmall { budget }, None, None);
    }
    let m = quarters.means();
    let drops = [m[0] - m[1], m[1] - m[2]];
    let b = quarters.bounds;
    // Distance between the centres of the 2nd and 4th quarters.
    let span = (b[2] + b[3] - b[0] - b[1]) as f64 / 2.0;
    let bits_per_impact = (m[0] - m[2]) / span;
    if drops[0] >= CC_MIN_BITS && drops[1] >= CC_MIN_BITS {
        // Geometric tail from the mean of the last quarter, centred in it.
        let centre = (quarters.bounds[2] + quarters.bounds[3]) as f64 / 2.0;
        let l_next = m[2] - bits_per_impact * (k as f64 - centre);
        let tail = l_next - (1.0 - (-bits_per_impact).exp2()).log2();
        let d = Decision::Converging { bits_per_impact, drops };
        return done!(Outcome::Cc, d, Some(tail), Some(bits_per_impact));
    }
    let d = Decision::NotConverging { bits_per_impact, drops };
    done!(Outcome::Undecided, d, None, Some(bits_per_impact))
}
