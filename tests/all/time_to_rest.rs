//! Issue 24: what the certificates say about the time to rest (docs/time-to-rest.md). The output of
//! `verify` and `certify` must not describe a cone certificate as proving a finite accumulation
//! time; the rod's theorem (docs/time-to-rest.md §2) and the finding of §3 are checked exactly.

use crate::common::{bin, q, root};
use chatter::certify::rest::rod_bound;
use chatter::claims::{FINITE_TIME_NOT_DERIVED, derives_finite_time, proves, proves_with};
use chatter::exact::Q;
use std::process::{Command, Output};

fn chatter(args: &[&str], dir: &std::path::Path) -> Output {
    Command::new(bin()).args(args).current_dir(dir).output().expect("run chatter")
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// Claims whose certificates do not derive the finite time (cone, box, field and family kinds).
const DROP_CLAIMS: [&str; 2] = ["CcOrPccFromAllDown", "CompleteChatterFromAllDown"];

#[test]
fn verify_says_that_no_cone_certificate_proves_a_finite_accumulation_time() {
    // What verify says, not how the backends compare (json.rs runs the corpus on both): one
    // backend, as the whole corpus is read twice here (CI time, issue 23 §4).
    let o = chatter(&["verify", "--backend", "malachite", "certificates/valid"], &root());
    assert_eq!(o.status.code(), Some(0));
    let out = stdout(&o);
    let (mut seen, mut bounded) = (0, 0);
    // Time-to-rest certificates prove the finite time (rules G1-G5, docs/time-to-rest.md §5).
    let rest: Vec<&str> = out.lines().filter(|l| l.contains("rules G1-G5")).collect();
    assert_eq!(rest.len(), 13, "{out}");
    assert!(
        rest.iter().all(|l| l.contains("accumulate within T <= ") && !l.contains(FINITE_TIME_NOT_DERIVED))
    );
    for line in out.lines().filter(|l| l.contains(": OK (") && !l.contains("rules G1-G5")) {
        let about_drops = DROP_CLAIMS.iter().any(|c| line.contains(&format!("OK ({c},")));
        // Only rod point certificates may carry a kernel-checked bound (rule T1).
        let bound = line.contains("time to rest T <= ");
        assert!(
            !bound || (about_drops && line.contains("n = 2,") && !line.contains("for every kappa")),
            "{line}"
        );
        assert_eq!(line.contains(FINITE_TIME_NOT_DERIVED), about_drops && !bound, "{line}");
        seen += usize::from(about_drops);
        bounded += usize::from(bound);
    }
    assert!(seen >= 20, "the corpus has many certificates about drops: {seen}\n{out}");
    assert_eq!(bounded, 8, "the rod's point certificates about drops carry B\n{out}");

    let o = chatter(&["verify", "--backend", "malachite", "certificates/valid", "--json"], &root());
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    for f in v["files"].as_array().unwrap() {
        let Some(claim) = f["claim"].as_str() else { continue };
        if !f["refutation"].is_null() {
            continue;
        }
        if !f["rest_nodes"].is_null() {
            assert_eq!(f["proves"].as_str(), Some(chatter::claims::proves_virtual_time(claim)));
            assert!(f["time_to_rest_bound"].is_string(), "{f}");
            continue;
        }
        let p = f["proves"].as_str().unwrap_or_else(|| panic!("no `proves` for {f}"));
        let bound = f["time_to_rest_bound"].as_str();
        assert_eq!(Some(p), proves_with(claim, bound.is_some()));
        if DROP_CLAIMS.contains(&claim) && bound.is_none() {
            assert!(p.contains(FINITE_TIME_NOT_DERIVED) && !p.contains("complete chatter"), "{p}");
        }
    }
}

#[test]
fn certify_reports_what_the_claim_proves_and_no_time_to_rest_bound() {
    let d = tempfile::tempdir().unwrap();
    let o = chatter(&["certify", "--json"], d.path());
    assert_eq!(o.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["claim"], "CompleteChatterFromAllDown");
    assert!(v["proves"].as_str().unwrap().contains(FINITE_TIME_NOT_DERIVED), "{v}");
    assert!(v["time_to_rest_bound"].is_null(), "no cone certificate derives a bound today");
    let out = stdout(&chatter(&["certify"], d.path()));
    let line = out.lines().find(|l| l.starts_with("proves: ")).unwrap_or_else(|| panic!("{out}"));
    assert!(line.contains("PCC excluded") && line.ends_with(FINITE_TIME_NOT_DERIVED), "{line}");
    // The help says which certificates prove the finite time.
    let help = stdout(&chatter(&["--help"], d.path()));
    assert!(help.contains("proved only by orbit certificates, by the rod's bound"), "{help}");
    assert!(help.contains("time-to-rest certificates (rules G1-G5"), "{help}");
}

/// One exact flight of the rod (docs/model.md §7, §3 with n = 2): right after an impact at end 0,
/// end 1 at height `h1` > 0, velocities `(u0, u1)` with u1 < 0. Returns the flight, end 0's height
/// when end 1 lands, and the velocities after that impact, relabelled (end 1 becomes end 0).
fn rod_flight(kappa: &Q, gamma: &Q, h1: &Q, [u0, u1]: [Q; 2]) -> (Q, Q, [Q; 2]) {
    let one = Q::int(1);
    let f = h1 / &(-&u1);
    let h0 = &u0 * &f;
    // u_j+ = u_j- - (1 + γ) u_k- (κ + c_{j-k}) / (1 + κ), c = cos π = -1.
    let coupling = &(kappa - &one) / &(kappa + &one);
    let other = &u0 - &(&(&(&one + gamma) * &u1) * &coupling);
    (f, h0, [-(gamma * &u1), other])
}

/// docs/time-to-rest.md §2: at κ = 1/3, γ = 1/20 (σ = 21/40, λ_1 = 2/5, λ_2 = 1/8) every all-down
/// drop's flights sum to T = H/(w_1 − λ_2 w_0) ≤ h/(λ_1|v|), checked on exact partial sums.
#[test]
fn the_rod_accumulates_its_impacts_at_the_time_of_the_theorem() {
    let (kappa, gamma) = (q("1/3"), q("1/20"));
    let (l1, l2) = (q("2/5"), q("1/8"));
    let sigma = q("21/40");
    assert_eq!(&l1 + &l2, sigma);
    assert_eq!(&l1 * &l2, gamma);
    let tiny = q("1/1000000000000000000000000");
    for (w0, u, big_h) in [("1", "0", "1"), ("1", "3", "2"), ("5", "1/7", "1/3"), ("1/9", "4", "7")] {
        let (w0, u, big_h) = (q(w0), q(u), q(big_h));
        // The first impact, at end 0 with pre-impact speed w0; end 1 moves down at u.
        let mut vel = [&gamma * &w0, -(&u + &(&sigma * &w0))];
        let w1 = &u + &(&sigma * &w0);
        let t = &big_h / &(&w1 - &(&l2 * &w0));
        let v = (&w0 + &u) / Q::int(2);
        let h = &big_h / &Q::int(2);
        assert!(t <= &h / &(&l1 * &v), "the bound T <= h/(lambda_1 |v|)");
        let (mut height, mut sum) = (big_h.clone(), Q::int(0));
        for _ in 0..80 {
            let (f, h0, next) = rod_flight(&kappa, &gamma, &height, vel);
            assert!(next[1] < Q::int(0), "the other end always approaches (impacts never stop)");
            sum = &sum + &f;
            (height, vel) = (h0, next);
        }
        assert!(sum < t, "partial sums stay below T");
        assert!(&t - &sum < &tiny * &t, "and reach it: T - sum = {}", &t - &sum);
    }
}

/// docs/time-to-rest.md §3: on the generator (4/3, −10/3) of the corpus's accepted rod cone at
/// κ = 1/3, γ = 1/20 (the λ_2 eigenvector) every flight is 16/5 times the previous one: infinitely
/// many impacts in infinite time; at κ = 1/4, γ = 1/9 (Δ = 0) the generator (1, −3) gives equal
/// flights.
#[test]
fn accepted_rod_cones_contain_motions_whose_impacts_never_accumulate() {
    for (file, kappa, gamma, generator, ratio) in [
        ("n2-kappa1_3-gamma1_20-complete-chatter-from-all-down.ron", "1/3", "1/20", ["4/3", "-10/3"], "16/5"),
        ("n2-kappa1_4-gamma1_9-complete-chatter-from-all-down.ron", "1/4", "1/9", ["1", "-3"], "1"),
    ] {
        let text = std::fs::read_to_string(root().join("certificates/valid").join(file)).unwrap();
        assert!(
            text.contains(&format!("(\"{}\", \"{}\")", generator[0], generator[1])),
            "{file} has the generator"
        );
        let (kappa, gamma) = (q(kappa), q(gamma));
        let (mut height, mut vel, mut last) = (Q::int(1), [q(generator[0]), q(generator[1])], None::<Q>);
        for _ in 0..30 {
            let (f, h0, next) = rod_flight(&kappa, &gamma, &height, vel);
            if let Some(prev) = last {
                assert_eq!(&f / &prev, q(ratio));
            }
            (height, vel, last) = (h0, next, Some(f));
        }
    }
}

/// Rule T1 on each backend alone: B = 1/λ_1 exactly is accepted (κ = 1/3, γ = 1/20: 5/2; κ = 1/4,
/// γ = 1/9, Δ = 0: 3), anything below is refused, and only the rod at a point may carry B.
#[test]
fn rule_t1_accepts_exactly_the_bounds_of_the_theorem_on_both_backends() {
    use chatter_kernel::verify::{MALACHITE, NUM, Verdict, verify_text};
    let rod = |kappa: &str, gamma: &str, claim: &str, gens: &str, b: &str| {
        format!(
            "Certificate(format: \"chatter-certificate\", version: 1, body: RegularPolygon(n: 2, kappa: \"{kappa}\", gamma: \"{gamma}\"), coordinates: ContactVelocities, claim: {claim}, cone: [{gens}], time_to_rest_bound: Some(\"{b}\"))"
        )
    };
    let third = "(\"-10/3\", \"4/3\"), (\"4/3\", \"-10/3\")";
    let quarter = "(\"-3\", \"1\"), (\"1\", \"-3\")";
    let cases = [
        (rod("1/3", "1/20", "CompleteChatterFromAllDown", third, "5/2"), Some("5/2")),
        (rod("1/3", "1/20", "CcOrPccFromAllDown", third, "100"), Some("100")),
        (rod("1/3", "1/20", "CompleteChatterFromAllDown", third, "2499999/1000000"), None),
        (rod("1/3", "1/20", "EffectivelyInvariant", third, "5/2"), None),
        (rod("1/3", "1/20", "CompleteChatterFromAllDown", third, "0"), None),
        (rod("1/4", "1/9", "CompleteChatterFromAllDown", quarter, "3"), Some("3")),
        (rod("1/4", "1/9", "CompleteChatterFromAllDown", quarter, "2999999/1000000"), None),
    ];
    for (text, expect) in &cases {
        for b in [MALACHITE, NUM] {
            match (verify_text(text, Default::default(), &[b]), expect) {
                (Verdict::Accepted(a), Some(bound)) => {
                    assert_eq!(a.time_to_rest_bound.as_deref(), Some(*bound))
                }
                (Verdict::Rejected(r), None) => {
                    assert_eq!(r.code.as_str(), "time-to-rest-not-shown", "{text}")
                }
                (v, _) => panic!("{}: {text}: {v:?}", b.name),
            }
        }
    }
    // The pipeline writes B for rod point certificates and the kernel accepts it.
    let d = tempfile::tempdir().unwrap();
    let o = chatter(
        &["certify", "--n", "2", "--kappa", "1/3", "--gamma", "1/20", "--json", "-o", "r.ron"],
        d.path(),
    );
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let b: Q = v["time_to_rest_bound"].as_str().unwrap_or_else(|| panic!("{v}")).parse().unwrap();
    assert!(b >= q("5/2") && b < q("5000001/2000000"), "B = {b} is within 1e-6 of 1/lambda_1");
    let out = stdout(&chatter(&["verify", "r.ron"], d.path()));
    assert!(out.contains("time to rest T <= ") && !out.contains(FINITE_TIME_NOT_DERIVED), "{out}");
}

/// `chatter simulate` compares rod drops with the bound: no violation on the corpus's rod bodies
/// (f64 evidence, 40 random drops each), and the measured ratio comes close to the sharp bound
/// only from below.
#[test]
fn simulated_rod_drops_stay_within_the_bound_on_the_corpus_bodies() {
    use chatter::simulate::rest::measure;
    use chatter::simulate::{Arithmetic, Initial, Model, Options, Shape, simulate};
    // Not κ = 1/4, γ = 1/9 (Δ = 0): its flights decay like 1/m², so the simulator cannot estimate
    // the accumulation point from 400 impacts.
    for (kappa, gamma) in [("1/3", "1/20"), ("1/3", "7/100"), ("1/10", "1/5")] {
        let model = Model::new(Shape::Rod, q(kappa), q(gamma)).unwrap();
        let opts = Options::new(400);
        let mut measured = 0;
        for seed in 0..40 {
            let initial = Initial::RandomDrop { seed };
            let run = simulate(&model, &initial, Arithmetic::Float, &opts);
            if let Some(m) = measure(&model, &initial, &run) {
                let b = chatter::exact::QExt::to_f64(&m.bound);
                assert!(
                    m.ratio > 0.5 && m.ratio <= b * (1.0 + 1e-9),
                    "{kappa} {gamma} seed {seed}: {} > {b}",
                    m.ratio
                );
                measured += 1;
            }
        }
        assert!(measured >= 30, "{kappa} {gamma}: {measured} drops measured");
    }
}

/// Issue 24: no cone-type claim may be described as proving complete chatter in finite time.
#[test]
fn cone_claims_state_that_finite_time_is_not_derived() {
    for name in DROP_CLAIMS {
        let t = proves(name).unwrap();
        assert!(t.contains(FINITE_TIME_NOT_DERIVED), "{name}: {t}");
        assert!(!t.contains("complete chatter") && !t.contains("CC or PCC"), "{name}: {t}");
        assert!(!derives_finite_time(name));
        assert!(t.contains("simultaneous impact leaves the model"), "{name}: {t}");
    }
    assert!(proves("CompleteChatterFromSet").unwrap().contains("finite time"));
    assert!(derives_finite_time("CompleteChatterFromSet"));
    assert!(proves("CompleteChatter").is_none());
}

/// The rod's bound B of rule T1 (docs/time-to-rest.md §2): exactly 1/λ_1 at rational roots, just
/// above it otherwise, absent outside the theorem's hypotheses.
#[test]
fn the_bound_is_sharp_at_rational_roots_and_absent_outside_the_theorem() {
    // κ = 1/3, γ = 1/20: λ_1 = 2/5; κ = 1/4, γ = 1/9: Δ = 0, λ = 1/3 (exact).
    assert_eq!(rod_bound(&q("1/3"), &q("1/20")), Some(q("5/2")));
    // κ = 1/3, γ = 7/100: λ_1 irrational, B just above 1/λ_1 = 3.2579...
    let b = rod_bound(&q("1/3"), &q("7/100")).unwrap();
    assert!(b > q("16289/5000") && b < q("1629/500"), "{b}");
    assert_eq!(rod_bound(&q("1/4"), &q("1/9")), Some(q("3")));
    assert_eq!(rod_bound(&q("1/4"), &q("1/8")), None, "Δ < 0: ICC");
    assert_eq!(rod_bound(&q("1"), &q("1/20")), None, "σ = 0");
}

/// Issue 24 §1 (`chatter reproduce`'s time-to-rest item): at the rod, the square plate, the
/// triangle plate, the hexagon point and the pentagon point of the table, every drop counts once (proved CC with a
/// bound, proved no-ICC-no-PCC, or other), the drops proved CC with a bound are those of the
/// documented measurements (all of them), and no proved bound lies below the `f64` accumulation
/// time of its drop beyond rounding.
#[test]
fn the_reproduce_table_bounds_are_never_below_the_simulated_times() {
    use chatter::reproduce::time_to_rest::{ROUNDING, bodies, measure};
    for body in bodies() {
        let row = measure(&body, 4).unwrap();
        assert_eq!(row.bounded + row.no_icc_no_pcc + row.other, 4, "{row:?}");
        assert_eq!(row.bounded, 4, "{row:?}");
        assert!(row.compared >= 1 && row.compared <= row.bounded, "{row:?}");
        assert_eq!(row.below, 0, "{row:?}");
        let (lo, hi) = row.ratios.unwrap();
        assert!(lo >= 1.0 - ROUNDING && lo <= hi, "{row:?}");
        let (time, bound) = row.largest.unwrap();
        assert!(bound >= time * (1.0 - ROUNDING), "{row:?}");
        assert!(!row.constants.is_empty(), "{row:?}");
    }
}

/// The square plate's time-to-rest certificate against brute force (docs/time-to-rest.md
/// Theorem 5.1): 200 random all-down drops, simulated in `f64` with the physics of docs/model.md
/// §2-§3 written again here, follow the certificate's nodes; along each, the virtual time after an
/// impact never exceeds the virtual time before it minus the flight (steps (c)-(d) of the proof),
/// and the time from the first impact to the 300th stays below B h/|v|.
#[test]
fn the_virtual_time_of_the_square_plates_certificate_falls_along_simulated_drops() {
    let largest = falls_along_drops(
        "rest-n4-kappa1_6-gamma1_100.ron",
        Plate { n: 4, kappa: 1.0 / 6.0, gamma: 1.0 / 100.0 },
    );
    // The drops take time: the check is not vacuous (the bound is loose, about 33 times).
    assert!(largest > 1.0, "largest T |v|/h = {largest}");
}

/// The same brute force for the version-2 files, whose numerators a_r come from a linear program
/// (docs/time-to-rest.md §5): the square plate (B ≈ 10.3, about 4 times the largest simulated
/// T|v|/h) and the triangle at (κ 1/10, γ 1/20), the first triangle with a time-to-rest bound.
#[test]
fn the_virtual_time_of_the_version_2_certificates_falls_along_simulated_drops() {
    let square = falls_along_drops(
        "rest-v2-n4-kappa1_6-gamma1_100.ron",
        Plate { n: 4, kappa: 1.0 / 6.0, gamma: 1.0 / 100.0 },
    );
    assert!(square > 1.0, "largest T |v|/h = {square}");
    let triangle =
        falls_along_drops("rest-v2-n3-kappa1_10-gamma1_20.ron", Plate { n: 3, kappa: 0.1, gamma: 0.05 });
    assert!(triangle > 0.5, "largest T |v|/h = {triangle}");
}

/// 200 random all-down drops followed through a valid corpus file's nodes (see [`follow`]); the
/// largest T|v|/h, which must not exceed B.
fn falls_along_drops(file: &str, plate: Plate) -> f64 {
    let text = std::fs::read_to_string(root().join("certificates/valid").join(file)).unwrap();
    let cert: chatter_kernel::rest::TimeToRest =
        chatter_kernel::syntax::read(&text, chatter_kernel::syntax::Encoding::Ron).unwrap();
    let bound = num(&cert.bound);
    let mut seed = 0x2545_f491_4f6c_dd1d_u64;
    let (mut drops, mut largest) = (0, 0.0_f64);
    while drops < 200 {
        let (q, p) = random_drop(&mut seed);
        let Some(ratio) = follow(&plate, &cert, q, p) else { continue };
        assert!(ratio <= bound * (1.0 + 1e-9), "{file}: T |v|/h = {ratio} > B = {bound}");
        largest = largest.max(ratio);
        drops += 1;
    }
    assert!(largest < bound, "{file}: largest T |v|/h = {largest}, B = {bound}");
    largest
}

/// A regular n-gon plate (docs/model.md §2-§3) in `f64`.
pub(crate) struct Plate {
    pub(crate) n: usize,
    pub(crate) kappa: f64,
    pub(crate) gamma: f64,
}

impl Plate {
    fn angle(&self, m: i64) -> f64 {
        2.0 * std::f64::consts::PI * m as f64 / self.n as f64
    }
    /// u_k = a_k u0 + b_k u1 + (1 - a_k - b_k) v, a_k = -sin θ_{k-1}/sin θ_1, b_k = sin θ_k/sin θ_1.
    fn row(&self, k: i64) -> [f64; 3] {
        let s1 = self.angle(1).sin();
        let (a, b) = (-self.angle(k - 1).sin() / s1, self.angle(k).sin() / s1);
        [a, b, 1.0 - a - b]
    }
    /// p - β u_k d_k, d_k = (κ + c_k, κ + c_{k-1}, κ), β = (1 + γ)/(1 + κ).
    fn impact(&self, k: i64, p: [f64; 3]) -> [f64; 3] {
        let (uk, beta) = (dot(self.row(k), p), (1.0 + self.gamma) / (1.0 + self.kappa));
        let d = [self.kappa + self.angle(k).cos(), self.kappa + self.angle(k - 1).cos(), self.kappa];
        std::array::from_fn(|i| p[i] - beta * uk * d[i])
    }
    /// Coordinates in the frame of contact k (the relabelling R_k of docs/model.md §3).
    fn frame(&self, k: i64, x: [f64; 3]) -> [f64; 3] {
        [dot(self.row(k), x), dot(self.row(k + 1), x), x[2]]
    }
    /// The next contact to land and the flight before it.
    fn next(&self, q: [f64; 3], p: [f64; 3]) -> Option<(i64, f64)> {
        (0..self.n as i64)
            .filter(|&k| dot(self.row(k), p) < 0.0)
            .map(|k| (k, dot(self.row(k), q) / -dot(self.row(k), p)))
            .min_by(|a, b| a.1.total_cmp(&b.1))
    }
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub(crate) fn num(s: &str) -> f64 {
    let (a, b) = s.split_once('/').unwrap_or((s, "1"));
    a.parse::<f64>().unwrap() / b.parse::<f64>().unwrap()
}

/// A canonical element of Q(c), c = cos(2π/n) ("a + b*c - d*c^2", docs/certificate-format.md §12),
/// in `f64`; a rational as [`num`].
pub(crate) fn element(s: &str, n: usize) -> f64 {
    let c = (2.0 * std::f64::consts::PI / n as f64).cos();
    let signed = s.replace(" - ", " + -");
    signed
        .split(" + ")
        .map(|term| {
            let (coef, power) = match term.split_once("*c") {
                None if term == "c" => ("1", "1"),
                None => (term, "0"),
                Some((coef, rest)) => (coef, rest.strip_prefix('^').unwrap_or("1")),
            };
            num(coef) * c.powi(power.parse().unwrap())
        })
        .sum()
}

/// A drop with every contact up and moving down (velocity (u0, u1, -1), centre at height 1).
pub(crate) fn random_drop(seed: &mut u64) -> ([f64; 3], [f64; 3]) {
    let mut uniform = || {
        *seed ^= *seed << 13;
        *seed ^= *seed >> 7;
        *seed ^= *seed << 17;
        (*seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let q = [0.05 + 1.9 * uniform(), 0.05 + 1.9 * uniform(), 1.0];
    let p = [-1.95 * uniform() - 0.02, -1.95 * uniform() - 0.02, -1.0];
    (q, p)
}

/// Follows a drop through the certificate's nodes for 300 impacts, checking that the virtual time
/// falls; the time from the first impact over h/|v| there, or `None` for a drop that is not
/// all-down with every contact up.
pub(crate) fn follow(
    plate: &Plate,
    cert: &chatter_kernel::rest::TimeToRest,
    mut q: [f64; 3],
    mut p: [f64; 3],
) -> Option<f64> {
    let n = plate.n as i64;
    if (0..n).any(|k| dot(plate.row(k), q) <= 0.0 || dot(plate.row(k), p) >= 0.0) {
        return None;
    }
    // Φ_r(q, p) = (a_r·q)/(−b_r·p), a_r = c_r b_r in version 1.
    let phi = |r: usize, k: i64, q: [f64; 3], p: [f64; 3]| {
        let node = &cert.nodes[r];
        let b = [0, 1, 2].map(|i| element(&node.weight.0[i], plate.n));
        let a = match node.scale.is_empty() {
            true => [0, 1, 2].map(|i| element(&node.numerator.0[i], plate.n)),
            false => b.map(|x| x * num(&node.scale)),
        };
        dot(a, plate.frame(k, q)) / -dot(b, plate.frame(k, p))
    };
    let (mut last, t) = plate.next(q, p)?;
    q = std::array::from_fn(|i| q[i] + t * p[i]);
    let (h, v) = (q[2], -p[2]);
    p = plate.impact(last, p);
    let (mut node, mut time) = (0, 0.0);
    let mut after = phi(node, last, q, p);
    for _ in 0..300 {
        let (k, f) = plate.next(q, p).expect("v < 0: another contact lands");
        let j = (k - last).rem_euclid(n) as u64;
        let to = cert.nodes[node].next.iter().find(|s| s.0 == j).expect("a successor").1;
        q = std::array::from_fn(|i| q[i] + f * p[i]);
        let before = phi(node, last, q, p);
        assert!(before <= after - f + 1e-9 * after.abs(), "the flight shortens Φ by less than {f}");
        p = plate.impact(k, p);
        let now = phi(to, k, q, p);
        assert!(now <= before * (1.0 + 1e-9), "the virtual time grows: {before} -> {now}");
        (node, last, after, time) = (to, k, now, time + f);
    }
    Some(time * v / h)
}

/// `simulate --exact` with a time-to-rest certificate proves every all-down drop CC at its first
/// impact, with a bound that the drop's own accumulation time (an `f64` run, evidence) respects;
/// a drop with a contact moving up is not decided by it.
#[test]
fn simulate_proves_all_down_drops_cc_by_a_time_to_rest_certificate() {
    let cert = root().join("certificates/valid/rest-n4-kappa1_6-gamma1_100.ron");
    let body = ["simulate", "--n", "4", "--kappa", "1/6", "--gamma", "1/100", "--json"];
    for seed in ["0", "1", "2"] {
        let mut args = body.to_vec();
        args.extend(["--exact", "--seed", seed, "--certificate", cert.to_str().unwrap()]);
        let v: serde_json::Value = serde_json::from_slice(&chatter(&args, &root()).stdout).unwrap();
        assert_eq!((v["outcome"].as_str(), v["proved"].as_bool()), (Some("CC"), Some(true)), "{v}");
        let entered = &v["entered"];
        assert_eq!((entered["kind"].as_str(), entered["impact"].as_u64()), (Some("time-to-rest"), Some(1)));
        let bound: f64 = entered["time_to_rest_bound"].as_str().unwrap().parse().unwrap();
        let mut args = body.to_vec();
        args.extend(["--seed", seed, "--impacts", "2000"]);
        let f: serde_json::Value = serde_json::from_slice(&chatter(&args, &root()).stdout).unwrap();
        let t = f["accumulation_time"].as_f64().unwrap_or_else(|| panic!("{f}"));
        assert!(t > 0.0 && t <= bound, "seed {seed}: accumulation time {t} > proved bound {bound}");
    }
    // A drop whose contact 1 moves up at the start is not all-down: the certificate does not decide it.
    let mut args = body.to_vec();
    args.extend(["--exact", "--position", "0.001,0.002,1", "--velocity", "0.3,0.1,-1"]);
    args.extend(["--certificate", cert.to_str().unwrap()]);
    let v: serde_json::Value = serde_json::from_slice(&chatter(&args, &root()).stdout).unwrap();
    assert_ne!(v["entered"]["kind"].as_str(), Some("time-to-rest"), "{v}");
}

/// Issue 24 with issue 22 §1: without `--certificate`, `simulate --exact` makes the time-to-rest
/// certificate itself (cached with the cone, kernel-checked), so a drop at the square plate is
/// proved CC at its first impact with a bound above its `f64` accumulation time; where no graph
/// is found (the triangle at κ = 1/10, γ = 3/20) the drop is not proved CC by one.
#[test]
fn simulate_makes_a_time_to_rest_certificate_on_the_fly_where_the_producer_finds_one() {
    let square = ["simulate", "--n", "4", "--kappa", "1/6", "--gamma", "1/100", "--json", "--seed", "4"];
    let mut args = square.to_vec();
    args.push("--exact");
    let v: serde_json::Value = serde_json::from_slice(&chatter(&args, &root()).stdout).unwrap();
    assert_eq!((v["outcome"].as_str(), v["proved"].as_bool()), (Some("CC"), Some(true)), "{v}");
    assert_eq!(v["entered"]["kind"].as_str(), Some("time-to-rest"), "{v}");
    assert!(v["entered"]["certificate"].as_str().is_some_and(|s| s.contains("made on the fly")), "{v}");
    let bound: f64 = v["entered"]["time_to_rest_bound"].as_str().unwrap().parse().unwrap();
    let mut args = square.to_vec();
    args.extend(["--impacts", "2000"]);
    let f: serde_json::Value = serde_json::from_slice(&chatter(&args, &root()).stdout).unwrap();
    let t = f["accumulation_time"].as_f64().unwrap_or_else(|| panic!("{f}"));
    assert!(t > 0.0 && t <= bound, "accumulation time {t} > proved bound {bound}");
    let triangle =
        ["simulate", "--n", "3", "--kappa", "1/10", "--gamma", "3/20", "--json", "--exact", "--seed", "4"];
    let v: serde_json::Value = serde_json::from_slice(&chatter(&triangle, &root()).stdout).unwrap();
    assert_ne!(v["entered"]["kind"].as_str(), Some("time-to-rest"), "{v}");
}
