//! Verification of certificate files (docs/certificate-format.md §7): list the inputs
//! ([`files`]), read each with bounded work ([`read`]), run the kernel on the chosen backends
//! ([`chatter_kernel::verify`]) under a time limit, and report one verdict per input; with a
//! manifest ([`expect`]), compare the verdicts with the expected ones.

pub mod expect;
pub mod files;
pub mod format;
pub mod read;
pub mod text;

use chatter_kernel::certificate::{Code, Detail, Encoding, Locus, Rejection};
use chatter_kernel::exact::ParseLimits;
use chatter_kernel::verify::{Backend, Verdict, verify_text_in};
use format::format_of_in;
use serde::{Deserialize, Serialize};
use std::path::Path;
use std::time::{Duration, Instant};

/// The verdict on one file.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Status {
    /// Every backend accepts.
    #[serde(rename = "OK")]
    Ok,
    /// Every backend rejects, for the same reason.
    #[serde(rename = "REJECTED")]
    Rejected,
    /// The file cannot be read, or the backends disagree.
    #[serde(rename = "ERROR")]
    Error,
}

impl Status {
    /// The word printed in verdict lines.
    pub fn word(self) -> &'static str {
        match self {
            Status::Ok => "OK",
            Status::Rejected => "REJECTED",
            Status::Error => "ERROR",
        }
    }
}

/// One line of `chatter verify` output.
/// In JSON (`chatter.verify/1`, see [`crate::report::verify`]) the status is the report's
/// `verdict`; the kernel's code and locus are described loosely in the schema (their types live
/// in the trusted crate, which does not depend on schemars).
#[derive(Clone, Debug, Serialize, schemars::JsonSchema)]
pub struct FileVerdict {
    pub path: String,
    #[serde(skip)]
    pub status: Status,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub claim: Option<&'static str>,
    /// What the accepted certificate's claim proves, every assumption stated
    /// (`claims::proves`; e.g. that a finite accumulation time is not derived).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub proves: Option<&'static str>,
    /// Rule T1 (rod point certificates): the kernel-checked B of T <= B h/|v| (docs/time-to-rest.md §2).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub time_to_rest_bound: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub n: Option<u64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub generators: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub redundant: Option<Vec<usize>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_denominator_bits: Option<u64>,
    /// Whether K contains the post-impact velocity of a pure downward translation.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub contains_translation: Option<bool>,
    /// The rejection's code (kebab-case, docs/certificate-format.md).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<String>")]
    pub code: Option<Code>,
    /// Where the first failing check is (an object with a `kind`).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<serde_json::Map<String, serde_json::Value>>")]
    pub locus: Option<Locus>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
    /// Whether the file was gzip'd.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gzip: Option<bool>,
    /// For a box certificate: [lo, hi] of kappa and of gamma.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub region: Option<[[String; 2]; 2]>,
    /// For a family certificate, or a general body's time-to-rest certificate, over an interval
    /// of gamma: [lo, hi].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gamma_interval: Option<[String; 2]>,
    /// For an accepted family certificate that records a full inertia tensor (Ixx, Ixy, Ixz,
    /// Iyy, Iyz, Izz per unit mass about the centre of mass): the tensor, of which the kernel
    /// checked that the planar J is J_eff (rule K0, docs/model.md Proposition 11.0).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub inertia_tensor: Option<[String; 6]>,
    /// For a box certificate with rule R4: the sub-boxes of the Bernstein subdivision.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pcc_boxes: Option<usize>,
    /// For an orbit certificate: the sub-boxes of X on which every sign was shown.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub orbit_boxes: Option<usize>,
    /// For an accepted refutation: what it refutes and how.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub refutation: Option<RefutationReport>,
    /// For an accepted basin certificate: the share of its box of drops proved to end in complete
    /// chatter (entering the orbit certificate's X, or a node's cone of the time-to-rest
    /// certificate, where the drops that reach a simultaneous impact later, at which the model
    /// stops, have volume zero), exact "p/q" (docs/basin-certificates.md §4, Lemma 4.1).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cc_share: Option<String>,
    /// For a basin certificate: the share proved to reach v > 0 (ICC, the paper's Lemma on v).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub icc_share: Option<String>,
    /// For a basin certificate: the share with no verdict; the three shares sum to 1.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub undecided_share: Option<String>,
    /// For an accepted time-to-rest certificate: the nodes of its virtual-time graph (rules
    /// G1-G5, docs/time-to-rest.md §5); its bound B is `time_to_rest_bound`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rest_nodes: Option<usize>,
    /// For a basin certificate: its leaves (CC, ICC, undecided).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub basin_leaves: Option<[usize; 3]>,
    /// For a basin certificate: how many of its leaves are trees (in the text line only).
    #[serde(skip)]
    #[schemars(skip)]
    pub basin_trees: usize,
}

/// What an accepted refutation shows.
#[derive(Clone, Debug, Serialize, schemars::JsonSchema)]
pub struct RefutationReport {
    /// The claim refuted (every stronger claim is refuted too).
    pub refutes: &'static str,
    /// Derived points.
    pub points: usize,
    /// The last point (canonical text, long numbers abbreviated).
    pub last: Vec<String>,
    /// Whether its v is > 0 (else = 0).
    pub v_positive: bool,
}

impl FileVerdict {
    fn new(path: &Path, status: Status) -> Self {
        FileVerdict {
            path: path.display().to_string(),
            status,
            claim: None,
            proves: None,
            time_to_rest_bound: None,
            n: None,
            generators: None,
            redundant: None,
            max_denominator_bits: None,
            contains_translation: None,
            code: None,
            locus: None,
            reason: None,
            gzip: None,
            region: None,
            gamma_interval: None,
            inertia_tensor: None,
            pcc_boxes: None,
            orbit_boxes: None,
            refutation: None,
            cc_share: None,
            icc_share: None,
            undecided_share: None,
            rest_nodes: None,
            basin_leaves: None,
            basin_trees: 0,
        }
    }

    /// Whether the backends disagreed (an internal error).
    pub fn is_internal(&self) -> bool {
        self.code == Some(Code::Internal)
    }

    /// The human-readable line.
    pub fn line(&self) -> String {
        if self.status != Status::Ok {
            return format!(
                "{}: {}: {}",
                self.path,
                self.status.word(),
                self.reason.as_deref().unwrap_or("")
            );
        }
        if let Some(r) = &self.refutation {
            let v = if r.v_positive { "v > 0" } else { "v = 0" };
            return format!(
                "{}: OK (refutes {} at n = {}: {} derived points, the last ({}) with {v})",
                self.path,
                r.refutes,
                self.n.unwrap_or(0),
                r.points,
                r.last.join(", ")
            );
        }
        if let (Some(cc), Some(icc), Some(und), Some(l)) =
            (&self.cc_share, &self.icc_share, &self.undecided_share, &self.basin_leaves)
        {
            let ties = match self.basin_trees {
                0 => String::new(),
                t => format!(
                    " ({t} leaves are trees: their drops that meet a simultaneous impact inside the tree, where the model stops, have volume zero and are in no share)"
                ),
            };
            let time = self.time_to_rest_bound.as_ref().map_or(String::new(), |t| {
                format!("; every CC drop comes to rest within T <= {t} h/|v| (time_to_rest_bound)")
            });
            return format!(
                "{}: OK (basin, n = {}: of the box of drops, {cc} proved CC (they enter an orbit certificate's X or a time-to-rest graph's cone; those of a cone that reach a simultaneous impact later, where the model stops, have volume zero), {icc} proved v > 0 (ICC), {und} undecided{ties}; leaves {} CC, {} ICC, {} undecided{time})",
                self.path,
                self.n.unwrap_or(0),
                l[0],
                l[1],
                l[2]
            );
        }
        if let (Some(nodes), Some(b)) = (self.rest_nodes, &self.time_to_rest_bound) {
            let region = match (&self.region, &self.gamma_interval) {
                (Some([k, g]), _) => {
                    format!(", for every kappa in [{}, {}] and gamma in [{}, {}]", k[0], k[1], g[0], g[1])
                }
                (None, Some(g)) => format!(", for every gamma in [{}, {}]", g[0], g[1]),
                (None, None) => String::new(),
            };
            return format!(
                "{}: OK ({}, n = {}{region}: every all-down drop's impacts accumulate within T <= {b} h/|v|; a virtual time on {nodes} nodes, rules G1-G5, F)",
                self.path,
                self.claim.unwrap_or("?"),
                self.n.unwrap_or(0)
            );
        }
        if let Some(b) = self.orbit_boxes {
            let time = self.time_to_rest_bound.as_ref().map_or(String::new(), |t| {
                format!("; its impacts accumulate within T <= {t} h/|v| of that impact (time_to_rest_bound)")
            });
            return format!(
                "{}: OK ({}, n = {}: every state of the set X ends in complete chatter{time}; conditions shown on {b} sub-boxes)",
                self.path,
                self.claim.unwrap_or("?"),
                self.n.unwrap_or(0)
            );
        }
        let red = self.redundant.as_ref().map_or(0, Vec::len);
        let red = if red > 0 { format!(", {red} redundant") } else { String::new() };
        let gzip = if self.gzip == Some(true) { ", gzip'd" } else { "" };
        let region = match &self.region {
            Some([k, g]) => {
                format!(", for every kappa in [{}, {}] and gamma in [{}, {}]", k[0], k[1], g[0], g[1])
            }
            None => self
                .gamma_interval
                .as_ref()
                .map_or(String::new(), |g| format!(", for every gamma in [{}, {}]", g[0], g[1])),
        };
        let pcc =
            self.pcc_boxes.map_or(String::new(), |b| format!(", PCC exclusion shown on {b} Bernstein boxes"));
        let vacuous = if self.contains_translation == Some(false) {
            "; warning: K does not contain the post-impact velocity of a pure translation"
        } else {
            ""
        };
        // Issue 24: a claim about drops says what it does not prove.
        let finite = match (self.claim, &self.time_to_rest_bound) {
            (_, Some(b)) => format!("; time to rest T <= {b} h/|v| for every all-down drop (rule T1)"),
            (Some(c), None) if c != "EffectivelyInvariant" && !crate::claims::derives_finite_time(c) => {
                format!("; {}", crate::claims::FINITE_TIME_NOT_DERIVED)
            }
            _ => String::new(),
        };
        let tensor = match &self.inertia_tensor {
            Some(t) => format!("; J is J_eff of the recorded inertia tensor ({}) (rule K0)", t.join(", ")),
            None => String::new(),
        };
        format!(
            "{}: OK ({}, n = {}{region}, {} generators{red}, denominators <= {} bits{pcc}{tensor}{gzip}{vacuous}{finite})",
            self.path,
            self.claim.unwrap_or("?"),
            self.n.unwrap_or(0),
            self.generators.unwrap_or(0),
            self.max_denominator_bits.unwrap_or(0)
        )
    }
}

/// The verdict on certificate text, reported for `path`.
pub fn verdict_of(path: &Path, verdict: Verdict) -> FileVerdict {
    match verdict {
        Verdict::Accepted(a) => {
            let mut v = FileVerdict::new(path, Status::Ok);
            v.claim = Some(a.claim.name());
            v.proves = crate::claims::proves_with(a.claim.name(), a.time_to_rest_bound.is_some());
            v.time_to_rest_bound = a.time_to_rest_bound.clone();
            v.n = Some(a.n);
            v.generators = Some(a.generators);
            v.redundant = Some(a.redundant);
            v.max_denominator_bits = Some(a.max_denominator_bits);
            v.contains_translation = Some(a.contains_translation);
            v.region = a.region;
            v.pcc_boxes = a.pcc_boxes;
            v.orbit_boxes = a.orbit_boxes;
            if a.orbit_boxes.is_some() {
                (v.generators, v.redundant, v.contains_translation) = (None, None, None);
            }
            v
        }
        Verdict::Rejected(r) => {
            let mut v = FileVerdict::new(path, Status::Rejected);
            v.reason = Some(r.message());
            v.code = Some(r.code);
            v.locus = Some(r.locus);
            v
        }
        Verdict::Disagree(s) => {
            let mut v = FileVerdict::new(path, Status::Error);
            v.code = Some(Code::Internal);
            v.reason = Some(format!("internal error, backends disagree: {s}"));
            v
        }
    }
}

/// The verdict on refutation text, reported for `path`.
pub fn refutation_verdict_of(path: &Path, verdict: Verdict<chatter_kernel::refute::Refuted>) -> FileVerdict {
    match verdict {
        Verdict::Accepted(a) => {
            let mut v = FileVerdict::new(path, Status::Ok);
            v.claim = Some(a.claim.name());
            v.n = Some(a.n);
            v.refutation = Some(RefutationReport {
                refutes: a.claim.name(),
                points: a.points,
                last: a.last.iter().map(|x| chatter_kernel::explain::abbreviate(x)).collect(),
                v_positive: a.v_positive,
            });
            v
        }
        Verdict::Rejected(r) => verdict_of(path, Verdict::Rejected(r)),
        Verdict::Disagree(s) => verdict_of(path, Verdict::Disagree(s)),
    }
}

/// The verdict on basin certificate text, reported for `path`.
pub fn basin_verdict_of(path: &Path, verdict: Verdict<chatter_kernel::basin::BasinReport>) -> FileVerdict {
    match verdict {
        Verdict::Accepted(a) => {
            let mut v = FileVerdict::new(path, Status::Ok);
            v.n = Some(a.n);
            v.time_to_rest_bound = a.time_to_rest_bound;
            v.orbit_boxes = Some(a.orbit_boxes);
            (v.cc_share, v.icc_share, v.undecided_share) =
                (Some(a.cc_share), Some(a.icc_share), Some(a.undecided_share));
            v.basin_leaves = Some(a.leaves);
            v.basin_trees = a.trees;
            v
        }
        Verdict::Rejected(r) => verdict_of(path, Verdict::Rejected(r)),
        Verdict::Disagree(s) => verdict_of(path, Verdict::Disagree(s)),
    }
}

/// The verdict on time-to-rest certificate text, reported for `path`.
pub fn rest_verdict_of(path: &Path, verdict: Verdict<chatter_kernel::rest::Rested>) -> FileVerdict {
    match verdict {
        Verdict::Accepted(a) => {
            let mut v = FileVerdict::new(path, Status::Ok);
            (v.claim, v.n) = (Some(a.claim.name()), Some(a.n));
            v.proves = Some(crate::claims::proves_virtual_time(a.claim.name()));
            (v.time_to_rest_bound, v.rest_nodes) = (Some(a.bound), Some(a.nodes));
            (v.region, v.gamma_interval) = (a.region, a.gamma_interval);
            v
        }
        Verdict::Rejected(r) => verdict_of(path, Verdict::Rejected(r)),
        Verdict::Disagree(s) => verdict_of(path, Verdict::Disagree(s)),
    }
}

/// Which kind of file the text is, by its `format` field.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Certificate,
    Refutation,
    Proof,
}

/// What an accepted family certificate records beyond the kernel's report: the full inertia
/// tensor (rule K0 checked it) and the interval of gamma its claim holds on (the kernel checked
/// the rules at both ends, docs/kernel-soundness.md §6).
fn recorded_family(text: &str, encoding: Encoding, v: &mut FileVerdict) {
    use chatter_kernel::syntax::cone::Param;
    use chatter_kernel::syntax::family::{ConvexBodyText, ConvexCertificate};
    let Ok(cert) = chatter_kernel::syntax::read::<ConvexCertificate>(text, encoding) else { return };
    let ConvexBodyText::ConvexPolygon { inertia_tensor, gamma, .. } = cert.body;
    v.inertia_tensor = inertia_tensor.map(|(a, b, c, d, e, f)| [a, b, c, d, e, f]);
    if let Param::Interval(lo, hi) = gamma {
        v.gamma_interval = Some([lo, hi]);
    }
}

/// Verifies certificate or refutation text on the backends; the kind of a rejected certificate
/// is looked up only when its format is not a certificate's.
fn verify_any(
    text: &str,
    encoding: Encoding,
    limits: ParseLimits,
    backends: &[Backend],
) -> (FileVerdict, Kind) {
    let path = Path::new("");
    let verdict = verify_text_in(text, encoding, limits, backends);
    if !matches!(&verdict, Verdict::Rejected(r) if r.code == Code::WrongFormat || r.code == Code::Syntax) {
        let mut v = verdict_of(path, verdict);
        if v.status == Status::Ok {
            recorded_family(text, encoding, &mut v);
        }
        return (v, Kind::Certificate);
    }
    match format_of_in(text, encoding).as_deref() {
        Some(chatter_kernel::refute::FORMAT) => {
            let v = chatter_kernel::verify::verify_refutation_text_in(text, encoding, limits, backends);
            (refutation_verdict_of(path, v), Kind::Refutation)
        }
        Some(chatter_kernel::proof::FORMAT) => (verdict_of(path, verdict), Kind::Proof),
        Some(chatter_kernel::rest::FORMAT) => {
            let v = chatter_kernel::verify::verify_rest_text_in(text, encoding, limits, backends);
            (rest_verdict_of(path, v), Kind::Certificate)
        }
        Some(chatter_kernel::rest_family::FORMAT) => {
            let v = chatter_kernel::verify::verify_rest_family_text_in(text, encoding, limits, backends);
            (rest_verdict_of(path, v), Kind::Certificate)
        }
        Some(chatter_kernel::syntax::basin::FORMAT) => {
            let v = chatter_kernel::verify::verify_basin_text_in(text, encoding, limits, backends);
            (basin_verdict_of(path, v), Kind::Certificate)
        }
        _ => (verdict_of(path, verdict), Kind::Certificate),
    }
}

/// How files are verified: the kernel's limits, the file-size limit, the time limit per file and
/// the backends.
#[derive(Clone)]
pub struct Options {
    /// Limits on the numbers and generators (the deadline is set per file from `time_limit`).
    pub limits: ParseLimits,
    /// `max-file-size`: largest file read, in bytes (after decompression for gzip'd files).
    pub max_file_size: u64,
    /// `time-limit`: the longest a file may take, over all backends; `None` for no limit.
    pub time_limit: Option<Duration>,
    /// The backends the kernel runs on.
    pub backends: Vec<Backend>,
}

impl Options {
    /// The default limits (documented in docs/certificate-format.md §2) on the given backends.
    pub fn new(backends: Vec<Backend>) -> Self {
        Options {
            limits: ParseLimits::default(),
            max_file_size: DEFAULT_MAX_FILE_SIZE,
            time_limit: Some(DEFAULT_TIME_LIMIT),
            backends,
        }
    }
}

/// Default `max-file-size`: 16 MiB.
pub const DEFAULT_MAX_FILE_SIZE: u64 = 16 << 20;
/// Default `time-limit`: 60 s per file.
pub const DEFAULT_TIME_LIMIT: Duration = Duration::from_secs(60);

/// Runs `work` with a deadline `limit` from now. The kernel checks the deadline between its steps
/// and gives up with `time-limit`; should one step outlast it (only with limits raised far above
/// the defaults), the work is abandoned on its thread after a grace period and `None` returned.
pub fn with_time_limit<T: Send + 'static>(
    limit: Option<Duration>,
    work: impl FnOnce(Option<Instant>) -> T + Send + 'static,
) -> Option<T> {
    let Some(limit) = limit else { return Some(work(None)) };
    let deadline = Instant::now() + limit;
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let _ = tx.send(work(Some(deadline)));
    });
    rx.recv_timeout(limit + limit / 10 + Duration::from_secs(1)).ok()
}

/// The verdict for a file whose check ran past the time limit.
fn out_of_time(path: &Path, limit: Duration) -> FileVerdict {
    let during = format!("checking the file (time-limit = {} s)", limit.as_secs_f32());
    verdict_of(path, Verdict::Rejected(Rejection::time_limit(&during)))
}

/// The verdict for a file over `max-file-size`.
fn too_large(path: &Path, what: &str, max: u64) -> FileVerdict {
    let detail = Detail::FileSize(what.to_string(), max);
    let r = Rejection::new(Code::TooLarge, Locus::Limit { name: "max-file-size".into() }, detail);
    verdict_of(path, Verdict::Rejected(r))
}

/// The verdict for an input that cannot be read.
pub fn unreadable(path: &Path, why: &str) -> FileVerdict {
    let mut v = FileVerdict::new(path, Status::Error);
    v.reason = Some(why.to_string());
    v
}

/// Verifies one file: bounded reading, then the kernel on every backend under the time limit.
pub fn verify_file(path: &Path, opts: &Options) -> FileVerdict {
    let (text, gzip) = match read::read_input(path, opts.max_file_size) {
        read::Input::Text { text, gzip } => (text, gzip),
        read::Input::TooLarge { what } => return too_large(path, &what, opts.max_file_size),
        read::Input::Unreadable(why) => return unreadable(path, &why),
    };
    let (limits, backends) = (opts.limits, opts.backends.clone());
    let encoding = files::encoding_of(path);
    let run = move |deadline| verify_any(&text, encoding, ParseLimits { deadline, ..limits }, &backends);
    let Some((mut v, kind)) = with_time_limit(opts.time_limit, run) else {
        return out_of_time(path, opts.time_limit.unwrap_or_default());
    };
    v.path = path.display().to_string();
    if gzip {
        v.gzip = Some(true);
    }
    if kind == Kind::Proof && v.status == Status::Rejected {
        v.reason = v.reason.map(|r| format!("{r} (this file is a proof: use `chatter check-proof`)"));
    }
    v
}

/// Verifies every input of a listing, in order; `each` sees every verdict as it is made.
pub fn verify_all(
    listing: &files::Listing,
    opts: &Options,
    mut each: impl FnMut(&FileVerdict),
) -> Vec<FileVerdict> {
    let mut out = Vec::with_capacity(listing.entries.len());
    for e in &listing.entries {
        let v = match e {
            files::Entry::File(p) => verify_file(p, opts),
            files::Entry::Problem { path, message } => unreadable(path, message),
        };
        each(&v);
        out.push(v);
    }
    out
}

/// Counts of verdicts, and the exit rule over all of them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, schemars::JsonSchema)]
pub struct Summary {
    /// Inputs checked (files and problems).
    pub inputs: usize,
    /// Accepted.
    pub ok: usize,
    /// Rejected (including limits reached).
    pub rejected: usize,
    /// Not readable, or the backends disagree.
    pub errors: usize,
    /// Of the errors, disagreements of the backends (bugs).
    pub internal: usize,
    /// Files skipped.
    pub skipped: files::Skipped,
}

impl Summary {
    /// Counts the verdicts.
    pub fn of(verdicts: &[FileVerdict], skipped: files::Skipped) -> Self {
        let count = |s: Status| verdicts.iter().filter(|v| v.status == s).count();
        Summary {
            inputs: verdicts.len(),
            ok: count(Status::Ok),
            rejected: count(Status::Rejected),
            errors: count(Status::Error),
            internal: verdicts.iter().filter(|v| v.is_internal()).count(),
            skipped,
        }
    }

    /// The summary line, e.g. "3 files: 2 OK, 1 rejected, 0 errors; 4 skipped (...)".
    pub fn line(&self) -> String {
        let plural =
            |n: usize, word: &str| if n == 1 { format!("{n} {word}") } else { format!("{n} {word}s") };
        let mut s = format!(
            "{}: {} OK, {} rejected, {}",
            plural(self.inputs, "file"),
            self.ok,
            self.rejected,
            plural(self.errors, "error")
        );
        if self.internal > 0 {
            s += &format!(" ({} internal: the backends disagree)", self.internal);
        }
        let k = self.skipped;
        if k.total() > 0 {
            let json = if k.other_json > 0 {
                format!(", {} JSON not a certificate or refutation", k.other_json)
            } else {
                String::new()
            };
            s += &format!(
                "; {} skipped ({} not named *.ron, *.ron.gz, *.json or *.json.gz{json}, {} reached again through a link)",
                k.total(),
                k.other_names,
                k.seen_before
            );
        }
        s
    }
}
