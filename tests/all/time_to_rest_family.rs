//! Issue 24 §1 for general bodies: time-to-rest certificates of a general convex body
//! (docs/time-to-rest.md §5, Theorem 5.2; docs/certificate-format.md §17), produced by
//! `chatter certify --time-to-rest` and checked against brute force with the physics of
//! docs/model.md §11 written again here in `f64`.

use crate::common::root;
use crate::time_to_rest::num;
use chatter_kernel::rest_family::FamilyTimeToRest;
use chatter_kernel::syntax::cone::Param;
use std::process::Command;

/// A general body in `f64` (docs/model.md §11.1-§11.3): contacts, J and γ.
struct Body {
    contacts: Vec<[f64; 2]>,
    j: [[f64; 2]; 2],
    gamma: f64,
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The γ a file's claim is about: its point, or its interval's ends and three points between.
fn gammas(cert: &FamilyTimeToRest) -> Vec<f64> {
    let chatter_kernel::syntax::family::ConvexBodyText::ConvexPolygon { gamma, .. } = &cert.body;
    match gamma {
        Param::Point(g) => vec![num(g)],
        Param::Interval(lo, hi) => {
            let (lo, hi) = (num(lo), num(hi));
            [0.0, 0.25, 0.5, 0.75, 1.0].iter().map(|t| lo + t * (hi - lo)).collect()
        }
    }
}

impl Body {
    fn of(cert: &FamilyTimeToRest, gamma: f64) -> Body {
        let chatter_kernel::syntax::family::ConvexBodyText::ConvexPolygon { contacts, inertia, .. } =
            &cert.body;
        let (a, b, c) = (num(&inertia.0), num(&inertia.1), num(&inertia.2));
        Body {
            contacts: contacts.iter().map(|(x, y)| [num(x), num(y)]).collect(),
            j: [[a, b], [b, c]],
            gamma,
        }
    }
    fn n(&self) -> usize {
        self.contacts.len()
    }
    /// f_k = (y_k, -x_k, 1).
    fn f(&self, k: usize) -> [f64; 3] {
        let [x, y] = self.contacts[k % self.n()];
        [y, -x, 1.0]
    }
    /// p - (1 + γ) u_k w_k, w_k = M^{-1} f_k / N_k.
    fn impact(&self, k: usize, p: [f64; 3]) -> [f64; 3] {
        let [[a, b], [_, c]] = self.j;
        let det = a * c - b * b;
        let f = self.f(k);
        let minv = [(c * f[0] - b * f[1]) / det, (a * f[1] - b * f[0]) / det, f[2]];
        let nk = dot(f, minv);
        let uk = dot(f, p);
        std::array::from_fn(|i| p[i] - (1.0 + self.gamma) * uk * minv[i] / nk)
    }
    /// m_{k,k+1} = f_k × f_{k+1} / D.
    fn rest(&self, k: usize) -> [f64; 3] {
        let (a, b) = (self.f(k), self.f(k + 1));
        let x = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
        x.map(|c| c / x[2])
    }
    /// The next contact to land and the flight before it.
    fn next(&self, q: [f64; 3], p: [f64; 3]) -> Option<(usize, f64)> {
        (0..self.n())
            .filter(|&k| dot(self.f(k), p) < 0.0)
            .map(|k| (k, dot(self.f(k), q) / -dot(self.f(k), p)))
            .min_by(|a, b| a.1.total_cmp(&b.1))
    }
}

fn vector(g: &chatter_kernel::certificate::Generator) -> [f64; 3] {
    [0, 1, 2].map(|i| num(&g.0[i]))
}

/// Follows a drop (configuration q with every contact up, velocity p with every contact moving
/// down) through the certificate's nodes for 300 impacts, checking that the virtual time Φ_r falls
/// in every flight and at every impact; the time from the first impact over h/|v| there.
fn follow(body: &Body, cert: &FamilyTimeToRest, mut q: [f64; 3], mut p: [f64; 3]) -> f64 {
    let phi = |r: usize, q: [f64; 3], p: [f64; 3]| {
        let node = &cert.nodes[r];
        dot(vector(&node.numerator), q) / -dot(vector(&node.weight), p)
    };
    let (first, t) = body.next(q, p).expect("a contact moves down");
    q = std::array::from_fn(|i| q[i] + t * p[i]);
    let (h, v) = (q[2], -p[2]);
    p = body.impact(first, p);
    let (mut node, mut time) = (cert.entries[first], 0.0);
    assert_eq!(cert.nodes[node].contact, first);
    let mut after = phi(node, q, p);
    for _ in 0..300 {
        let (k, f) = body.next(q, p).expect("v < 0: another contact lands");
        let to = cert.nodes[node].next.iter().find(|s| s.0 == k as u64).expect("a successor").1;
        q = std::array::from_fn(|i| q[i] + f * p[i]);
        let before = phi(node, q, p);
        assert!(before <= after - f + 1e-9 * after.abs(), "the flight shortens Φ by less than {f}");
        p = body.impact(k, p);
        let now = phi(to, q, p);
        assert!(now <= before * (1.0 + 1e-9), "the virtual time grows: {before} -> {now}");
        (node, after, time) = (to, now, time + f);
    }
    time * v / h
}

fn uniform(seed: &mut u64) -> f64 {
    *seed ^= *seed << 13;
    *seed ^= *seed >> 7;
    *seed ^= *seed << 17;
    (*seed >> 11) as f64 / (1u64 << 53) as f64
}

/// 200 random all-down drops of a corpus file's body (velocity a random positive combination of
/// the generators -m_{k,k+1} of D, configuration one of the m_{k,k+1} with every contact up),
/// followed through its nodes, at its γ (over an interval: at both ends and three γ between):
/// the largest T|v|/h, never above B.
fn falls_along_drops(file: &str) -> (f64, f64) {
    let text = std::fs::read_to_string(root().join("certificates/valid").join(file)).unwrap();
    let cert: FamilyTimeToRest =
        chatter_kernel::syntax::read(&text, chatter_kernel::syntax::Encoding::Ron).unwrap();
    let bound = num(&cert.bound);
    let mut seed = 0x2545_f491_4f6c_dd1d_u64;
    let mut largest = 0.0_f64;
    for body in gammas(&cert).into_iter().map(|g| Body::of(&cert, g)) {
        largest = largest.max(drops(&body, &cert, &mut seed, file));
    }
    (largest, bound)
}

/// The largest T|v|/h of 200 random all-down drops of one body, each below the file's B.
fn drops(body: &Body, cert: &FamilyTimeToRest, seed: &mut u64, file: &str) -> f64 {
    let (bound, mut largest) = (num(&cert.bound), 0.0_f64);
    for _ in 0..200 {
        let weights: Vec<f64> = (0..body.n()).map(|_| 0.01 + uniform(seed)).collect();
        let mut p = [0.0; 3];
        let mut q = [0.0; 3];
        for (k, w) in weights.iter().enumerate() {
            let (m, mu) = (body.rest(k), 0.01 + uniform(seed));
            (0..3).for_each(|i| (p[i], q[i]) = (p[i] - w * m[i], q[i] + mu * m[i]));
        }
        let ratio = follow(body, cert, q, p);
        let gamma = body.gamma;
        assert!(ratio <= bound * (1.0 + 1e-9), "{file}, gamma {gamma}: T |v|/h = {ratio} > B = {bound}");
        largest = largest.max(ratio);
    }
    largest
}

/// The corpus's general-body files against brute force: the lander (3 contacts, full inertia
/// tensor), the 2 x 1 rectangular plate, at one γ and over an interval of γ, and the triangle
/// plate (0,0 3,0 1,2) at γ = 1/20 (made with the fallback enlargement 0.05).
#[test]
fn the_virtual_time_of_general_body_certificates_falls_along_simulated_drops() {
    for file in [
        "rest-family-lander-gamma1_50.ron",
        "rest-family-rectangle2x1-gamma1_100.ron",
        "rest-family-lander-gamma1_50-1_40.ron",
        "rest-family-rectangle2x1-gamma1_100-1_50.ron",
        "rest-family-triangle-plate-gamma1_20.ron",
        "rest-family-rectangle2x1-gamma1_100-1_50-transported.ron",
    ] {
        let (largest, bound) = falls_along_drops(file);
        eprintln!("{file}: largest T|v|/h of 200 drops {largest}, B = {bound}, factor {}", bound / largest);
        // The drops take time: the check is not vacuous.
        assert!(largest > 0.5 && largest < bound, "{file}: largest T |v|/h = {largest}, B = {bound}");
    }
}

/// `certify --rectangle 2,1 --gamma 1/100 --time-to-rest FILE --json` writes a general body's file
/// that `verify` accepts, and reports its B; over an interval of γ (the lander, [1/50, 1/40]) it
/// writes version 2, which `verify` reports for every γ of the interval.
#[test]
fn certify_writes_a_general_bodys_time_to_rest_certificate() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("rest.ron");
    let bin = env!("CARGO_BIN_EXE_chatter");
    let args = ["certify", "--rectangle", "2,1", "--gamma", "1/100", "--json", "--time-to-rest"];
    let out = Command::new(bin).args(args).arg(&file).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let b = v["time_to_rest_bound"].as_str().unwrap_or_else(|| panic!("{v}"));
    assert_eq!(v["time_to_rest"]["claim"], "CompleteChatterFromAllDown", "{v}");
    let verified = Command::new(bin).arg("verify").arg("--json").arg(&file).output().unwrap();
    let w: serde_json::Value = serde_json::from_slice(&verified.stdout).unwrap();
    assert_eq!(w["files"][0]["time_to_rest_bound"].as_str(), Some(b), "{w}");
    let interval = ["certify", "--body", "lander", "--gamma", "1/50:1/40", "--time-to-rest"];
    let file = dir.path().join("x.ron");
    let out = Command::new(bin).args(interval).arg(&file).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stdout));
    let cert: FamilyTimeToRest = chatter_kernel::syntax::read(
        &std::fs::read_to_string(&file).unwrap(),
        chatter_kernel::syntax::Encoding::Ron,
    )
    .unwrap();
    assert_eq!(cert.version, chatter_kernel::rest_family::INTERVAL_VERSION);
    let verified = Command::new(bin).arg("verify").arg(&file).output().unwrap();
    let text = String::from_utf8_lossy(&verified.stdout);
    assert!(
        text.contains("OK (CompleteChatterFromAllDown, n = 3, for every gamma in [1/50, 1/40]:"),
        "{text}"
    );
}

/// Rules G3 to K4 over an interval of γ are checked at its two ends only (docs/kernel-soundness.md
/// §10, "General bodies"): the corpus's interval files, written as version 1 at seven γ strictly
/// inside their intervals, are accepted by the kernel on both backends (brute force against the
/// reduction); the rectangle's graph over a wider interval fails at the upper end, and names it.
#[test]
fn an_interval_of_gamma_holds_at_every_gamma_between_its_ends() {
    use chatter_kernel::verify::{BOTH, Verdict, verify_rest_family_text_in};
    let limits = chatter_kernel::exact::ParseLimits::default();
    for (file, lo, hi) in [
        ("rest-family-lander-gamma1_50-1_40.ron", (1, 50), (1, 40)),
        ("rest-family-rectangle2x1-gamma1_100-1_50.ron", (1, 100), (1, 50)),
    ] {
        let text = std::fs::read_to_string(root().join("certificates/valid").join(file)).unwrap();
        let interval = format!("gamma: [\"{}/{}\", \"{}/{}\"]", lo.0, lo.1, hi.0, hi.1);
        assert!(text.contains(&interval) && text.contains("version: 2,"), "{file}");
        for k in 1..=7 {
            // lo + k (hi - lo) / 8, as a fraction over 8 lo.1 hi.1.
            let d = 8 * lo.1 * hi.1;
            let g = (8 - k) * lo.0 * hi.1 + k * hi.0 * lo.1;
            let point = text
                .replace(&interval, &format!("gamma: \"{}\"", reduced(g, d)))
                .replace("version: 2,", "version: 1,");
            let v = verify_rest_family_text_in(&point, chatter_kernel::syntax::Encoding::Ron, limits, &BOTH);
            assert!(matches!(v, Verdict::Accepted(_)), "{file} at gamma {g}/{d}: {v:?}");
        }
    }
    let text = std::fs::read_to_string(
        root().join("certificates/valid/rest-family-rectangle2x1-gamma1_100-1_50.ron"),
    )
    .unwrap();
    let wide = text.replace("gamma: [\"1/100\", \"1/50\"]", "gamma: [\"1/100\", \"1/40\"]");
    let v = verify_rest_family_text_in(&wide, chatter_kernel::syntax::Encoding::Ron, limits, &BOTH);
    let Verdict::Rejected(r) = v else { panic!("{v:?}") };
    let locus = serde_json::to_value(&r.locus).unwrap();
    assert_eq!(locus["gamma"], "1/40", "{locus}");
}

/// p/q in lowest terms, as canonical text.
fn reduced(p: u64, q: u64) -> String {
    let g = (1..=p.min(q)).rev().find(|d| p.is_multiple_of(*d) && q.is_multiple_of(*d)).unwrap_or(1);
    format!("{}/{}", p / g, q / g)
}

/// `simulate --exact --certificate` with a file over an interval of γ proves drops at a γ inside
/// the interval (here 9/400, between 1/50 and 1/40) and is refused at a γ outside it.
#[test]
fn simulate_uses_an_interval_certificate_at_every_gamma_of_its_interval() {
    let file = root().join("certificates/valid/rest-family-lander-gamma1_50-1_40.ron");
    let run = |g: &str| {
        let args = ["simulate", "--body", "lander", "--gamma", g, "--json", "--exact", "--seed", "3"];
        Command::new(env!("CARGO_BIN_EXE_chatter"))
            .args(args)
            .arg("--certificate")
            .arg(&file)
            .output()
            .unwrap()
    };
    let v: serde_json::Value = serde_json::from_slice(&run("9/400").stdout).unwrap();
    assert_eq!((v["outcome"].as_str(), v["proved"].as_bool()), (Some("CC"), Some(true)), "{v}");
    assert_eq!(v["entered"]["kind"], "time-to-rest", "{v}");
    let outside = run("1/30");
    // With --json the usage error is a `chatter.error/1` report on stdout.
    let err: serde_json::Value = serde_json::from_slice(&outside.stdout).unwrap();
    assert_eq!(outside.status.code(), Some(2), "{err}");
    assert!(
        err["message"].as_str().is_some_and(|m| m.contains("the run's gamma is not the file's")),
        "{err}"
    );
}

fn simulate(args: &[&str]) -> serde_json::Value {
    let out = Command::new(env!("CARGO_BIN_EXE_chatter")).arg("simulate").args(args).output().unwrap();
    serde_json::from_slice(&out.stdout)
        .unwrap_or_else(|e| panic!("{e}: {}", String::from_utf8_lossy(&out.stderr)))
}

/// `simulate --exact` of a general body proves each all-down drop CC at its first impact by a
/// time-to-rest certificate (a corpus file, or one made on the fly), with the impacts accumulating
/// by t_1 + B h/|v|; the `f64` run of the same drop (evidence) accumulates them before that bound.
/// A drop with a contact moving up at the start is not decided by it.
#[test]
fn simulate_proves_general_body_drops_cc_by_a_time_to_rest_certificate() {
    let lander = root().join("certificates/valid/rest-family-lander-gamma1_50.ron");
    let cases: [(&[&str], Option<&std::path::Path>); 2] = [
        (&["--body", "lander", "--gamma", "1/50"], Some(&lander)),
        (&["--rectangle", "2,1", "--gamma", "1/100"], None),
    ];
    for (body, file) in cases {
        for seed in ["0", "1"] {
            let mut args = [body, &["--json", "--exact", "--seed", seed]].concat();
            if let Some(f) = file {
                args.extend(["--certificate", f.to_str().unwrap()]);
            }
            let v = simulate(&args);
            assert_eq!((v["outcome"].as_str(), v["proved"].as_bool()), (Some("CC"), Some(true)), "{v}");
            let entered = &v["entered"];
            assert_eq!(
                (entered["kind"].as_str(), entered["impact"].as_u64()),
                (Some("time-to-rest"), Some(1))
            );
            let made = entered["certificate"].as_str().is_some_and(|s| s.contains("made on the fly"));
            assert_eq!(made, file.is_none(), "{v}");
            let bound: f64 = entered["time_to_rest_bound"].as_str().unwrap().parse().unwrap();
            let f = simulate(&[body, &["--json", "--seed", seed, "--impacts", "2000"]].concat());
            let t = f["accumulation_time"].as_f64().unwrap_or_else(|| panic!("{f}"));
            assert!(
                t > 0.0 && t <= bound,
                "{body:?} seed {seed}: accumulation time {t} > proved bound {bound}"
            );
        }
    }
    let up = ["--position", "0.001,0.002,1", "--velocity", "1,0,-1", "--certificate"];
    let v = simulate(
        &[
            &["--body", "lander", "--gamma", "1/50", "--json", "--exact"],
            &up[..],
            &[lander.to_str().unwrap()],
        ]
        .concat(),
    );
    assert_ne!(v["entered"]["kind"].as_str(), Some("time-to-rest"), "{v}");
    // A file about another body serves no run.
    let other = Command::new(env!("CARGO_BIN_EXE_chatter"))
        .args(["simulate", "--rectangle", "2,1", "--gamma", "1/50", "--exact", "--certificate"])
        .arg(&lander)
        .output()
        .unwrap();
    assert_eq!(other.status.code(), Some(2), "{}", String::from_utf8_lossy(&other.stdout));
    assert!(
        String::from_utf8_lossy(&other.stderr).contains("another body"),
        "{}",
        String::from_utf8_lossy(&other.stderr)
    );
}

/// An affine image of a regular polygon gets the regular polygon's bound by transport (issue 24
/// §1, "general bounds as tight as the regular ones"): the square plate and the 2 x 1 plate as
/// general bodies at gamma = 1/100 get exactly the regular square's B (10.32, where the search
/// gave 653 and 57.2), with one copy of the regular graph per contact, accepted by the kernel on
/// both backends; in a survey (no fallback) that certificate is the answer, and a body that is
/// no affine image (the lander) still gets the search's.
#[test]
fn an_affine_image_gets_the_regular_polygons_bound_by_transport() {
    use chatter::bodies::convex::rectangle_plate;
    use chatter::certify::virtual_time::{Config, produce, produce_family};
    use chatter::exact::Q;
    use chatter_kernel::verify::BOTH;
    let g = Q::new(1, 100);
    let regular = produce(4, &Q::new(1, 6), &g, &Config::default(), &BOTH).unwrap();
    let survey = Config { fallback: false, ..Config::default() };
    for (a, b) in [(1, 1), (2, 1)] {
        let body = rectangle_plate(&Q::int(a), &Q::int(b), g.clone()).unwrap();
        let p = produce_family(std::slice::from_ref(&body), None, &survey, &BOTH).unwrap();
        assert_eq!(p.bound, regular.bound, "{a} x {b}");
        assert_eq!(p.cert.nodes.len(), 4 * regular.cert.nodes.len(), "{a} x {b}");
        assert!(p.cert.producer.contains("transported"), "{}", p.cert.producer);
        let full = produce_family(std::slice::from_ref(&body), None, &Config::default(), &BOTH).unwrap();
        assert!(full.bound <= regular.bound, "{a} x {b}: the least B is kept");
    }
    let lander = chatter::bodies::general::general_catalogue(&Q::new(1, 50)).unwrap().remove(3).body;
    let p = produce_family(std::slice::from_ref(&lander), None, &survey, &BOTH).unwrap();
    assert!(!p.cert.producer.contains("transported"), "{}", p.cert.producer);
    // `certify` says which graph it wrote.
    let dir = tempfile::tempdir().unwrap();
    let args = ["certify", "--rectangle", "4,1", "--gamma", "1/100", "--time-to-rest"];
    let out = Command::new(env!("CARGO_BIN_EXE_chatter"))
        .args(args)
        .arg(dir.path().join("r.ron"))
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("(about 10.319624)") && text.contains("graph transported to this affine image"),
        "{text}"
    );
}
