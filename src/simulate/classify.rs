//! The driver loop and the CC / PCC / ICC classification, the same for both arithmetics.
//!
//! **Proof or evidence** (issue 22 §1). In an exact engine, rules 1 and 2, an exact tie (rule 3),
//! the exact pair proof (rule 4) and rule 4a are exact facts and theorems: their outcome is
//! *proved* ([`Run::proved`]); a cone entry (rule 4a) proves less than CC, and its outcome is
//! [`Outcome::NoIccNoPcc`] (issue 24). Every other rule — the paper's PCC criterion, the converging
//! intervals of rule 6, a pair that did not settle, a breakdown — is *evidence*: an exact run that
//! ends on one is `undecided`, with the evidence kept in [`Run::evidence`] and [`Run::decision`],
//! never counted as CC. Every verdict of an `f64` engine is evidence.
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
//!
//!    Rule 4a. Exact engines on regular polygons and the rod, after every impact: the
//!    post-impact state, relabelled so that the contact that landed is contact 0, lies in a set
//!    of [`super::certified::Certified`] (membership decided by `chatter_kernel::membership`):
//!    - the velocity in the cone K of a kernel-checked cone certificate whose claim excludes
//!      PCC: proved no ICC (v <= 0 for ever, the impacts never stop) and no PCC, outcome
//!      [`Outcome::NoIccNoPcc`]; not CC, as the finite accumulation time is not derived
//!      (docs/time-to-rest.md §3). Its evidence is CC (the paper's Lemma on v, which asserts
//!      that such a motion is CC or PCC);
//!    - the normalised state in the set X of a kernel-checked orbit certificate: proved CC, the
//!      impacts accumulating at a finite time.
//!
//!    Tested before rule 4 (in K or X, PCC is excluded); X before K. With
//!    [`Options::after_cone`] and an orbit set among the sets, a cone entry without a finite time
//!    is kept as the first fact ([`Run::cone_entry`]) and the run goes on (issue 24 §2), testing
//!    only X: an entry proves CC, and at the end of the budget the cone's proof stands.
//!
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

use super::certified::{Certified, SetKind};
use super::engine::{Engine, Step};
use super::pcc::{PairSummary, PaperPcc, paper_criterion};
use super::snapshot::{Scaled, Snapshot};
use super::system::FloatSystem;
use crate::exact::{Q, QExt, Rounding};
// Formerly defined here; its old path keeps working.
pub use super::text::singular;

/// Minimal alternation length before the PCC tests run (then after every impact).
pub const PCC_MIN_RUN: usize = 6;
/// Minimal drop of the mean log2 interval between consecutive quarters of the budget, for CC.
pub const CC_MIN_BITS: f64 = 4.0;
/// Smallest budget for which the CC test is made.
pub const MIN_BUDGET_FOR_CC: usize = 16;
/// Default ε of the paper's PCC criterion (the paper does not state its value).
pub const DEFAULT_PCC_EPSILON: f64 = 1e-8;

/// The outcomes: the paper's three (CC, PCC, ICC), two outside its trichotomy (undecided: no
/// rule could tell; simultaneous: an impact the model cannot resolve), and one that only a proof
/// gives, weaker than CC ([`Outcome::NoIccNoPcc`], issue 24).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Outcome {
    Cc,
    Pcc,
    Icc,
    Undecided,
    Simultaneous,
    /// Proved never to separate (no ICC: v <= 0 for ever, the impacts never stop) and never to end
    /// in PCC, by entering the cone K of a kernel-checked cone certificate; CC unless the impacts
    /// take infinite time: the finite accumulation time is not derived (docs/time-to-rest.md §3).
    /// Only exact runs give it, and only as a proof (never as evidence: the simulator's rules
    /// then say CC).
    NoIccNoPcc,
}

impl Outcome {
    /// The number of outcomes.
    pub const COUNT: usize = 6;

    /// Every outcome, in the order of all outcome counts (`[_; Outcome::COUNT]` arrays).
    pub const ALL: [Outcome; Outcome::COUNT] = [
        Outcome::Cc,
        Outcome::Pcc,
        Outcome::Icc,
        Outcome::Undecided,
        Outcome::Simultaneous,
        Outcome::NoIccNoPcc,
    ];

    /// The outcomes the simulator's rules give as evidence: all but [`Outcome::NoIccNoPcc`]. A
    /// prefix of [`Outcome::ALL`], so `EVIDENCE.iter().zip(counts)` pairs each with its count.
    pub const EVIDENCE: [Outcome; 5] =
        [Outcome::Cc, Outcome::Pcc, Outcome::Icc, Outcome::Undecided, Outcome::Simultaneous];

    /// The position in [`Outcome::ALL`] (and in every count array).
    pub fn index(self) -> usize {
        self as usize
    }

    /// The name used in output, JSON and CSV.
    pub fn name(self) -> &'static str {
        match self {
            Outcome::Cc => "CC",
            Outcome::Pcc => "PCC",
            Outcome::Icc => "ICC",
            Outcome::Undecided => "undecided",
            Outcome::Simultaneous => "simultaneous",
            Outcome::NoIccNoPcc => "no-ICC-no-PCC",
        }
    }

    /// The name in running text ("no ICC, no PCC" for [`Outcome::NoIccNoPcc`]).
    pub fn words(self) -> &'static str {
        match self {
            Outcome::NoIccNoPcc => "no ICC, no PCC",
            o => o.name(),
        }
    }

    /// Whether this outcome, proved, contradicts the decided `evidence` (CC, PCC or ICC): a
    /// different outcome, except that no ICC and no PCC is what CC evidence says too (CC is the
    /// only outcome left, if the impacts accumulate in finite time).
    pub fn contradicts(self, evidence: Outcome) -> bool {
        match self {
            Outcome::NoIccNoPcc => evidence != Outcome::Cc,
            o => o != evidence,
        }
    }
}

impl std::fmt::Display for Outcome {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
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
    /// Exact engines: the relabelled post-impact state after `after` impacts lies in a set that a
    /// kernel-checked certificate certifies (issue 22 §1): a cone K proves no ICC and no PCC
    /// ([`Outcome::NoIccNoPcc`]), an orbit certificate's set X proves CC, and `rest_by` bounds the
    /// time of the accumulation point from the start: the exact time of impact `after`, rounded
    /// up, plus B h/|v| there (B the certificate's `time_to_rest_bound`; docs/time-to-rest.md §1).
    Certified { after: usize, kind: SetKind, name: String, rest_by: Option<Q> },
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
            Decision::Certified { .. } => "entered-certified-set",
        }
    }

    /// Whether this test, in an exact engine (`exact`), proves its outcome: v > 0, no contact
    /// approaching, at rest, an exact tie, the exact pair proof and a certified set are exact
    /// facts and theorems; every other test, and every test in `f64`, is evidence.
    pub fn is_proof(&self, exact: bool) -> bool {
        exact
            && matches!(
                self,
                Decision::VPositive { .. }
                    | Decision::NoApproach { .. }
                    | Decision::AtRest { .. }
                    | Decision::Tie { exact: true, .. }
                    | Decision::ExactPair { .. }
                    | Decision::Certified { .. }
            )
    }

    /// What a proof by this test proves when the rules' verdict is `evidence`: that verdict,
    /// except for a cone entry, whose theorem gives no ICC and no PCC but not the finite
    /// accumulation time that CC needs (docs/time-to-rest.md §3): [`Outcome::NoIccNoPcc`]; a rod
    /// certificate with rule T1 does give it for an all-down drop (`rest_by`, §2): CC.
    pub fn proved_outcome(&self, evidence: Outcome) -> Outcome {
        match self {
            Decision::Certified { kind: SetKind::Cone, rest_by: None, .. } => Outcome::NoIccNoPcc,
            _ => evidence,
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
            Decision::Certified { after, kind, name, rest_by } => {
                let by = |when: &str, t: &Q| {
                    format!(
                        "; the impacts accumulate by t <= {} (the exact time of {when}, rounded up, plus \
                         the certificate's time_to_rest_bound times h/|v| there)",
                        t.decimal(6, Rounding::Up)
                    )
                };
                let (what, gives, by) = match (kind, rest_by) {
                    (SetKind::Cone, None) => (
                        "the velocity lies in the cone K",
                        "v <= 0 for ever from there (no separation, impacts never stop) and no PCC; \
                         finite accumulation time: not derived by this certificate (docs/time-to-rest.md)",
                        String::new(),
                    ),
                    (SetKind::Cone, Some(t)) => (
                        "the velocity lies in the cone K",
                        "no separation and no PCC; with its rule T1, complete chatter in finite time for \
                         this drop, all-down at its first impact (docs/time-to-rest.md §2)",
                        by("the first impact", t),
                    ),
                    (SetKind::Rest, t) => (
                        "the drop is all-down; by its rules G1-G5, F (a virtual time),",
                        "complete chatter for every all-down drop (docs/time-to-rest.md Theorem 5.1; \
                         Theorem 5.2 for a general body)",
                        t.as_ref().map_or(String::new(), |t| by("the first impact", t)),
                    ),
                    (SetKind::Orbit, t) => (
                        "the state lies, up to relabelling and scaling, in the set X",
                        "complete chatter from there, the impacts accumulating at a finite time",
                        t.as_ref().map_or(String::new(), |t| by(&format!("impact {after}"), t)),
                    ),
                };
                format!(
                    "after impact {after} {what} of a kernel-checked {} certificate ({name}), whose \
                     theorem gives {gives}{by}",
                    kind.name()
                )
            }
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
    /// Exact runs with certified sets: after entering a cone K (proved no ICC, no PCC), go on
    /// within the budget, so that the state can also enter an orbit certificate's set X (then
    /// proved CC with its time-to-rest bound); at the end of the budget the cone's proof stands.
    /// Without it the run stops at the cone (rule 4a).
    pub after_cone: bool,
}

impl Options {
    pub fn new(budget: usize) -> Options {
        Options { budget, pcc_epsilon: DEFAULT_PCC_EPSILON, record: false, after_cone: false }
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
    /// The verdict: for exact engines proved (CC, PCC, ICC, no ICC and no PCC, an exact tie) or
    /// `Undecided`; for `f64` engines the evidence of [`Run::evidence`] (never a proof).
    pub outcome: Outcome,
    /// Whether `outcome` is proved ([`Decision::is_proof`]).
    pub proved: bool,
    /// What the rules of the module doc say, proof or evidence (the paper's protocol): equal to
    /// `outcome` when proved, except CC for a cone entry proved [`Outcome::NoIccNoPcc`]; e.g. CC
    /// by converging intervals when an exact run is undecided. Never [`Outcome::NoIccNoPcc`].
    pub evidence: Outcome,
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
    /// With [`Options::after_cone`]: the cone entry (a [`Decision::Certified`] of kind cone) that
    /// proved no ICC and no PCC first, the run having gone on past it; `decision` is then the
    /// orbit entry that proved CC, or this same cone entry if the budget ran out first (or a tie).
    pub cone_entry: Option<Decision>,
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
    /// Empty sums for a budget of `n` impacts.
    fn new(n: usize) -> Quarters {
        Quarters { bounds: [n / 4, n / 2, 3 * n / 4, n], sums: [0.0; 3] }
    }

    /// Adds the log2 interval `l` of impact i (counted from 0) to its quarter, if any.
    #[inline]
    fn add(&mut self, i: usize, l: f64) {
        let b = &self.bounds;
        if i >= b[0] {
            let w = usize::from(i >= b[1]) + usize::from(i >= b[2]);
            self.sums[w] += l;
        }
    }

    /// The mean log2 interval of the 2nd, 3rd and 4th quarters.
    fn means(&self) -> [f64; 3] {
        let b = &self.bounds;
        [
            self.sums[0] / (b[1] - b[0]) as f64,
            self.sums[1] / (b[2] - b[1]) as f64,
            self.sums[2] / (b[3] - b[2]) as f64,
        ]
    }

    /// Rule 6, converging intervals: CC when the mean log2 interval drops by at least
    /// [`CC_MIN_BITS`] from the 2nd to the 3rd and from the 3rd to the 4th quarter, after `k` impacts.
    fn converging_intervals(&self, k: usize) -> Verdict {
        let m = self.means();
        let drops = [m[0] - m[1], m[1] - m[2]];
        let b = self.bounds;
        // Distance between the centres of the 2nd and 4th quarters.
        let span = (b[2] + b[3] - b[0] - b[1]) as f64 / 2.0;
        let bits_per_impact = (m[0] - m[2]) / span;
        if drops[0] >= CC_MIN_BITS && drops[1] >= CC_MIN_BITS {
            // Geometric tail from the mean of the last quarter, centred in it.
            let centre = (b[2] + b[3]) as f64 / 2.0;
            let l_next = m[2] - bits_per_impact * (k as f64 - centre);
            let tail = l_next - (1.0 - (-bits_per_impact).exp2()).log2();
            let decision = Decision::Converging { bits_per_impact, drops };
            return Verdict::cc(decision).with_tail(Some(tail)).with_contraction(bits_per_impact);
        }
        let decision = Decision::NotConverging { bits_per_impact, drops };
        Verdict::undecided(decision).with_contraction(bits_per_impact)
    }
}

/// A rule's verdict: the outcome, the test with its evidence, and the estimates kept in [`Run`].
struct Verdict {
    outcome: Outcome,
    decision: Decision,
    /// log2 of the estimated time from the last impact to the accumulation point.
    tail_log2: Option<f64>,
    /// Mean contraction of the intervals, bits per impact.
    contraction: Option<f64>,
}

impl Verdict {
    /// A verdict without estimates.
    fn new(outcome: Outcome, decision: Decision) -> Verdict {
        Verdict { outcome, decision, tail_log2: None, contraction: None }
    }

    /// Complete chatter.
    fn cc(decision: Decision) -> Verdict {
        Verdict::new(Outcome::Cc, decision)
    }

    /// The body leaves after finitely many impacts.
    fn icc(decision: Decision) -> Verdict {
        Verdict::new(Outcome::Icc, decision)
    }

    /// No rule could tell.
    fn undecided(decision: Decision) -> Verdict {
        Verdict::new(Outcome::Undecided, decision)
    }

    /// The same verdict with log2 of the time from the last impact to the accumulation point.
    fn with_tail(self, tail_log2: Option<f64>) -> Verdict {
        Verdict { tail_log2, ..self }
    }

    /// The same verdict with the mean contraction of the intervals, bits per impact.
    fn with_contraction(self, bits_per_impact: f64) -> Verdict {
        Verdict { contraction: Some(bits_per_impact), ..self }
    }

    /// Rule 1: v > 0, the body leaves (ICC).
    fn v_positive(after: usize) -> Verdict {
        Verdict::icc(Decision::VPositive { after })
    }

    /// Rule 3: contacts land at the same instant ("simultaneous", never resolved).
    fn tie(after: usize, contacts: Vec<usize>, exact: bool) -> Verdict {
        Verdict::new(Outcome::Simultaneous, Decision::Tie { after, contacts, exact })
    }

    /// Rule 5 (and a non-finite state): `f64` precision is exhausted, "undecided".
    fn breakdown(after: usize) -> Verdict {
        Verdict::undecided(Decision::Breakdown { after })
    }

    /// Rule 4, exact: the pair-chatter proof holds; CC when the limit velocity is 0, else PCC.
    fn exact_pair(after: usize, pr: &PairSummary) -> Verdict {
        let decision = Decision::ExactPair {
            after,
            pair: pr.pair,
            time_bound: pr.time_bound.to_f64(),
            v_limit: pr.v_limit,
        };
        let outcome = if pr.at_rest { Outcome::Cc } else { Outcome::Pcc };
        Verdict::new(outcome, decision).with_tail(Some(pr.time_bound.log2()))
    }
}

/// log2 of the geometric tail from the last two intervals of one contact (`tail_log`: log2 of the
/// last three intervals, newest first), when they shrink.
fn pair_tail(tail_log: &[f64; 3]) -> Option<f64> {
    let per = (tail_log[0] - tail_log[2]) / 2.0;
    (per < 0.0).then(|| tail_log[0] + per - (1.0 - per.exp2()).log2())
}

/// The driver's state: the engine, the trace so far and the running evidence of the rules.
struct Driver<'a, E: Engine> {
    eng: &'a mut E,
    /// Sets whose entry proves no ICC and no PCC (a cone) or CC (an orbit certificate's set);
    /// exact engines on regular polygons and the rod.
    certified: Option<&'a Certified>,
    fs: &'a FloatSystem,
    opts: Options,
    initial: Snapshot,
    seq: Vec<u8>,
    records: Vec<Record>,
    quarters: Quarters,
    /// log2 of the last three intervals, newest first.
    tail_log: [f64; 3],
    /// Length of the alternating adjacent-pair tail.
    alt: usize,
    /// Why the PCC tests have not held so far (for [`Decision::PairNotSettled`]).
    pair_note: String,
    /// Pair phases in which the paper's criterion was overruled, and whether the current one is.
    overruled: usize,
    overruled_here: bool,
    /// With [`Options::after_cone`]: the cone entry the run went on past (its proof stands).
    cone: Option<Decision>,
}

/// Runs `eng` until a rule of the module doc decides.
pub fn drive<E: Engine>(eng: &mut E, fs: &FloatSystem, opts: &Options) -> Run {
    drive_with(eng, fs, opts, None)
}

/// [`drive`], where an exact engine also proves its outcome once a post-impact state enters one of
/// the `certified` sets (rule 4a: no ICC and no PCC in a cone, CC in an orbit certificate's set).
pub fn drive_with<E: Engine>(
    eng: &mut E,
    fs: &FloatSystem,
    opts: &Options,
    certified: Option<&Certified>,
) -> Run {
    let mut driver = Driver::new(eng, fs, opts);
    driver.certified = certified;
    let verdict = driver.run();
    driver.finish(verdict)
}

impl<'a, E: Engine> Driver<'a, E> {
    /// Before the first impact: the initial state and empty evidence.
    fn new(eng: &'a mut E, fs: &'a FloatSystem, opts: &Options) -> Self {
        Driver {
            initial: eng.snapshot(),
            eng,
            certified: None,
            fs,
            opts: *opts,
            seq: Vec::with_capacity(opts.budget),
            records: Vec::new(),
            quarters: Quarters::new(opts.budget),
            tail_log: [0.0; 3],
            alt: 0,
            pair_note: String::from("not tested"),
            overruled: 0,
            overruled_here: false,
            cone: None,
        }
    }

    /// The loop: rule 1 before every event, then the event's rules, until one decides or the
    /// budget is used up (rule 6).
    fn run(&mut self) -> Verdict {
        loop {
            let k = self.seq.len();
            if self.eng.v_positive() {
                return Verdict::v_positive(k);
            }
            if k == self.opts.budget {
                return self.cone_verdict().unwrap_or_else(|| self.budget_exhausted());
            }
            if let Some(verdict) = self.event(k) {
                return verdict;
            }
        }
    }

    /// One event after `k` impacts: an impact (rules 4 and 5), or the end of the run (rules 2, 3).
    #[inline]
    fn event(&mut self, k: usize) -> Option<Verdict> {
        match self.eng.step() {
            Step::Impact { contact, dt } => self.impact(k, contact, dt),
            Step::Tie { contacts, exact, .. } => Some(Verdict::tie(k, contacts, exact)),
            Step::NoApproach => Some(self.no_approach(k)),
            Step::Breakdown => Some(Verdict::breakdown(k)),
        }
    }

    /// Rule 2: no contact approaches, ICC; at rest when p = 0 exactly.
    fn no_approach(&self, after: usize) -> Verdict {
        if self.eng.at_rest() {
            Verdict::icc(Decision::AtRest { after })
        } else {
            Verdict::icc(Decision::NoApproach { after })
        }
    }

    /// The (k+1)-th impact: rule 5 (an `f64` interval of exactly 0 with gamma > 0 after the first
    /// impact is a breakdown), then the bookkeeping, then the PCC tests of rule 4.
    #[inline]
    fn impact(&mut self, k: usize, contact: usize, dt: Scaled) -> Option<Verdict> {
        if dt.m == 0.0 && k > 0 && self.fs.gamma > 0.0 && !self.eng.is_exact() {
            return Some(Verdict::breakdown(k));
        }
        self.book(k, contact, dt);
        if let Some(v) = self.entered(k + 1) {
            return Some(v);
        }
        if self.cone.is_some() {
            // In K: PCC is excluded (rule 4a), only an orbit set can add to the proof.
            return None;
        }
        if self.alt >= PCC_MIN_RUN { self.pcc_tests(k + 1, contact) } else { None }
    }

    /// Rule 4a (exact engines): the relabelled post-impact state lies in a certified set, an
    /// orbit certificate's X tested first. The verdict (the evidence) is CC; a cone entry proves
    /// only [`Outcome::NoIccNoPcc`] ([`Decision::proved_outcome`]). With [`Options::after_cone`]
    /// a cone entry without a finite time is kept ([`Driver::cone`]) and the run goes on, testing
    /// only orbit sets from then on (every later velocity lies in K).
    fn entered(&mut self, after: usize) -> Option<Verdict> {
        let sets = self.certified?;
        // A time-to-rest certificate proves CC for a drop that was all-down at its first impact
        // (also of a general body, whose states are not relabelled).
        if after == 1
            && self.eng.first_drop().is_some()
            && let Some(set) = sets.rest()
        {
            return Some(Verdict::cc(self.certified_decision(after, set)));
        }
        let (q, p) = self.eng.relabelled()?;
        if let Some(set) = sets.entered_kind(SetKind::Orbit, &q, &p) {
            return Some(Verdict::cc(self.certified_decision(after, set)));
        }
        if self.cone.is_some() {
            return None;
        }
        let decision = self.certified_decision(after, sets.entered_kind(SetKind::Cone, &q, &p)?);
        let finite = matches!(decision, Decision::Certified { rest_by: Some(_), .. });
        if self.opts.after_cone && !finite && sets.has_orbits() {
            self.cone = Some(decision);
            return None;
        }
        Some(Verdict::cc(decision))
    }

    /// The decision of entering `set` after impact `after`, with its proved time of rest.
    fn certified_decision(&self, after: usize, set: &super::certified::Set) -> Decision {
        let rest_by = set.time_to_rest_bound.as_ref().and_then(|b| self.rest_by(set.kind, b));
        Decision::Certified { after, kind: set.kind, name: set.name.clone(), rest_by }
    }

    /// At the end of the budget, after a cone entry that the run went on past: that entry's proof
    /// (no ICC, no PCC), never CC.
    fn cone_verdict(&self) -> Option<Verdict> {
        self.cone.clone().map(Verdict::cc)
    }

    /// The proved time of the accumulation point, from the start, by a set with bound B: for an
    /// orbit set, the time of this impact plus B h/|v| now (docs/kernel-soundness.md §7 item 6);
    /// for a rod cone certificate with rule T1, whose theorem covers every all-down drop, the
    /// time of the first impact plus B h/|v| there, if the drop was all-down (docs/time-to-rest.md
    /// §2). Rational upper bounds throughout.
    fn rest_by(&self, kind: SetKind, b: &Q) -> Option<Q> {
        let (t, ratio) = match kind {
            SetKind::Orbit => (self.eng.time_above()?, self.eng.centre_ratio_above()?),
            SetKind::Cone | SetKind::Rest => self.eng.first_drop()?,
        };
        Some(&t + &(b * &ratio))
    }

    /// Records the (k+1)-th impact: its interval, the alternation length, the sequence, the record.
    #[inline]
    fn book(&mut self, k: usize, contact: usize, dt: Scaled) {
        let l = dt.log2_fast();
        if k > 0 {
            self.quarters.add(k, l);
        }
        self.tail_log = [l, self.tail_log[0], self.tail_log[1]];
        self.alt = self.alternation(k, contact);
        if self.alt < PCC_MIN_RUN {
            self.overruled_here = false;
        }
        self.seq.push(contact as u8);
        if self.opts.record {
            let (time, state) = (self.eng.time(), self.eng.snapshot());
            self.records.push(Record { impact: k + 1, contact, time, log2_dt: dt.log2(), state });
        }
    }

    /// The length of the alternating adjacent-pair tail once `contact` lands after `k` impacts.
    #[inline]
    fn alternation(&self, k: usize, contact: usize) -> usize {
        let seq = &self.seq;
        if k >= 1 && self.fs.adjacent(contact, seq[k - 1] as usize) {
            if k >= 2 && seq[k - 2] as usize == contact { self.alt + 1 } else { 2 }
        } else {
            1
        }
    }

    /// Rule 4 after `after` impacts, the last at `hit`: where the PCC Lemma excludes PCC the
    /// paper's criterion is only counted when overruled; otherwise the exact proof (exact
    /// engines) or the paper's criterion (`f64`) decides PCC.
    fn pcc_tests(&mut self, after: usize, hit: usize) -> Option<Verdict> {
        let other = self.seq[after - 2] as usize;
        if !self.fs.pcc_possible {
            self.count_overruled(hit, other);
            return None;
        }
        match self.eng.prove_pair(hit, other) {
            Some(Ok(pr)) => Some(Verdict::exact_pair(after, &pr)),
            Some(Err(e)) => {
                self.pair_note = format!("exact proof: {e}");
                None
            }
            None => self.paper_pcc(after, hit, other),
        }
    }

    /// Rule 4 where the Lemma excludes PCC: counts a pair phase in which the criterion holds anyway.
    fn count_overruled(&mut self, hit: usize, other: usize) {
        if !self.overruled_here && self.paper_test(hit, other).holds(self.opts.pcc_epsilon) {
            self.overruled += 1;
            self.overruled_here = true;
        }
    }

    /// Rule 4 in `f64`: PCC when the paper's criterion holds, else a note of its defects.
    fn paper_pcc(&mut self, after: usize, hit: usize, other: usize) -> Option<Verdict> {
        let (test, eps) = (self.paper_test(hit, other), self.opts.pcc_epsilon);
        if test.holds(eps) {
            return Some(self.paper_verdict(after, test));
        }
        self.pair_note = format!(
            "paper's criterion: 1 - cos = {:.1e}, 1 + cos = {:.1e}, eps = {eps:e}",
            test.q_defect, test.p_defect
        );
        None
    }

    /// The paper's criterion for the pair {hit, other} on the current state.
    fn paper_test(&self, hit: usize, other: usize) -> PaperPcc {
        paper_criterion(self.fs, &self.eng.snapshot(), hit, other)
    }

    /// PCC by the paper's criterion, with the tail estimated from the pair's last intervals.
    fn paper_verdict(&self, after: usize, test: PaperPcc) -> Verdict {
        let decision = Decision::PaperPcc { after, test, epsilon: self.opts.pcc_epsilon };
        Verdict::new(Outcome::Pcc, decision).with_tail(pair_tail(&self.tail_log))
    }

    /// Rule 6: the budget is used up. A pair still alternating where the Lemma allows PCC is
    /// judged by the PCC tests; otherwise the intervals must converge (and the budget suffice).
    fn budget_exhausted(&self) -> Verdict {
        let budget = self.opts.budget;
        if self.fs.pcc_possible && self.alt >= PCC_MIN_RUN {
            return self.pair_at_budget();
        }
        if budget < MIN_BUDGET_FOR_CC {
            return Verdict::undecided(Decision::BudgetTooSmall { budget });
        }
        self.quarters.converging_intervals(self.seq.len())
    }

    /// Rule 6 on an alternating adjacent pair: PCC if the exact proof or the paper's criterion
    /// holds now, otherwise "undecided" (CC is impossible on an adjacent pair).
    fn pair_at_budget(&self) -> Verdict {
        let k = self.seq.len();
        let (hit, other) = (self.seq[k - 1] as usize, self.seq[k - 2] as usize);
        if let Some(Ok(pr)) = self.eng.prove_pair(hit, other) {
            return Verdict::exact_pair(k, &pr);
        }
        let (test, eps) = (self.paper_test(hit, other), self.opts.pcc_epsilon);
        if test.holds(eps) {
            return self.paper_verdict(k, test);
        }
        let reason = format!(
            "{}; at the end 1 - cos = {:.1e}, 1 + cos = {:.1e}, eps = {eps:e}",
            self.pair_note, test.q_defect, test.p_defect
        );
        let pair = (hit.min(other), hit.max(other));
        Verdict::undecided(Decision::PairNotSettled { pair, run: self.alt, reason })
    }

    /// The run, with its trace, once a rule has decided.
    fn finish(self, verdict: Verdict) -> Run {
        let Verdict { outcome: evidence, decision, tail_log2, contraction } = verdict;
        let time = self.eng.time();
        let exact = self.eng.is_exact();
        let proved = decision.is_proof(exact);
        let outcome = match (exact, proved) {
            (true, false) => Outcome::Undecided,
            (_, true) => decision.proved_outcome(evidence),
            (false, false) => evidence,
        };
        Run {
            outcome,
            proved,
            evidence,
            decision,
            impacts: self.seq.len(),
            budget: self.opts.budget,
            sequence: self.seq,
            time,
            accumulation: tail_log2.map(|l| time + l.exp2()),
            tail_log2,
            contraction,
            initial: self.initial,
            last: self.eng.snapshot(),
            exact: self.eng.is_exact(),
            records: self.records,
            pcc_overruled: self.overruled,
            cone_entry: self.cone,
        }
    }
}
