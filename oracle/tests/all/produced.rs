//! Certificates and refutations produced on the fly by the tool (`chatter certify`'s library
//! function on a grid of bodies, with every weaker claim and the claim upgraded; a box; a general
//! convex body; the refuter; the orbit producer), written as RON by serde (no kernel writer), then
//! verified by the kernel on both backends and judged by the oracle. Any disagreement fails.

use crate::common::differential_ron;
use chatter::exact::Q;
use std::collections::BTreeMap;

fn q(s: &str) -> Q {
    s.parse().expect("a rational")
}

/// A claim of the tool's API by name (the type is inferred from the producer's signature).
fn claim<C: serde::de::DeserializeOwned>(name: &str) -> C {
    serde_json::from_str(&format!("\"{name}\"")).expect("a claim")
}

const CLAIMS: [&str; 3] = ["EffectivelyInvariant", "CcOrPccFromAllDown", "CompleteChatterFromAllDown"];

/// The RON text of a produced value, with the claim (or `refutes`) replaced when asked.
fn text_with_claim(ron_text: &str, field: &str, new: Option<&str>) -> String {
    let Some(new) = new else { return ron_text.to_string() };
    let at = ron_text.find(&format!("{field}:")).expect("the claim field") + field.len() + 1;
    let end = at + ron_text[at..].find(',').expect("a comma after the claim");
    format!("{}{new}{}", &ron_text[..at], &ron_text[end..])
}

struct Tally {
    counts: BTreeMap<String, usize>,
    failures: Vec<String>,
}

impl Tally {
    fn run(&mut self, what: &str, text: &str) -> bool {
        let (kernel, _, cmp) = differential_ron(text);
        match cmp {
            Ok(a) => *self.counts.entry(format!("{a:?}")).or_default() += 1,
            Err(f) => self.failures.push(format!("{what}: {f}\n{text}")),
        }
        kernel.accepted
    }
}

#[test]
fn produced_certificates_and_refutations_get_the_same_verdicts() {
    use chatter::certify::{Request, certify};
    let mut t = Tally { counts: BTreeMap::new(), failures: vec![] };
    let bodies = [
        (2, "1/3", "1/20"),
        (2, "1/10", "1/5"),
        (3, "1/8", "1/100"),
        (3, "3/20", "1/20"),
        (4, "1/6", "1/100"),
        (4, "1/8", "1/40"),
        (6, "1/40", "1/20"),
        (6, "1/20", "1/1000"),
    ];
    let mut produced = 0;
    for (n, k, g) in bodies {
        let report = certify(&Request::new(n, q(k), q(g)));
        let cert = report.result.unwrap_or_else(|e| panic!("certify n={n} kappa={k} gamma={g}: {e}"));
        let text = chatter::write::write(&cert);
        produced += 1;
        assert!(
            t.run(&format!("n={n} kappa={k} gamma={g}"), &text),
            "the tool's certificate is rejected\n{text}"
        );
        for c in CLAIMS {
            t.run(&format!("n={n} kappa={k} gamma={g} as {c}"), &text_with_claim(&text, "claim", Some(c)));
        }
    }
    // A box (§9).
    let mut boxed = Request::new(4, q("1/10"), q("1/100"));
    boxed.upper = Some((q("3/25"), q("1/50")));
    let cert = certify(&boxed).result.expect("the documented box certifies");
    let text = chatter::write::write(&cert);
    produced += 1;
    assert!(t.run("box n=4", &text));
    for c in CLAIMS {
        t.run(&format!("box as {c}"), &text_with_claim(&text, "claim", Some(c)));
    }
    // A general convex body (§13): the 2 x 1 plate.
    let body = chatter::bodies::convex::rectangle_plate(&q("2"), &q("1"), q("1/50")).expect("a plate");
    let report =
        chatter::certify::convex::certify_convex(&chatter::certify::convex::ConvexRequest::new(body));
    let text = chatter::write::write_convex(&report.result.expect("the plate certifies"));
    produced += 1;
    assert!(t.run("rectangle 2x1", &text));
    for c in CLAIMS {
        t.run(&format!("rectangle as {c}"), &text_with_claim(&text, "claim", Some(c)));
    }
    // Refutations (§10), and each moved to a claim it does not refute.
    let cfg = chatter::refute::RefuteConfig::default();
    for (n, k, g, c) in [
        (4, "1/6", "1/20", "EffectivelyInvariant"),
        (2, "1/3", "1/10", "CcOrPccFromAllDown"),
        (3, "1/8", "1/5", "CcOrPccFromAllDown"),
    ] {
        let r = chatter::refute::refute(n, &q(k), &q(g), claim(c), &cfg)
            .unwrap_or_else(|e| panic!("refute n={n}: {e}"));
        let text = chatter::write::write_refutation(&r);
        produced += 1;
        assert!(t.run(&format!("refutation n={n}"), &text), "the tool's refutation is rejected\n{text}");
        for other in CLAIMS {
            t.run(&format!("refutation n={n} as {other}"), &text_with_claim(&text, "refutes", Some(other)));
        }
    }
    // Orbit certificates (§14): the triangle's, and the pentagon's (its constants in Q(cos 2π/5)).
    use chatter_kernel::verify::{MALACHITE, NUM};
    for (n, k, g, pattern) in
        [(3, "1/8", "3/20", vec![2, 2, 1, 1]), (5, "961/25600", "61/160", vec![1, 1, 2, 4, 4, 3])]
    {
        let req = chatter::orbit::Request {
            n,
            kappa: q(k),
            gamma: q(g),
            pattern: Some(pattern),
            drops: 0,
            max_depth: 1,
        };
        let found = chatter::orbit::certify_orbit(&req, &[MALACHITE, NUM])
            .unwrap_or_else(|e| panic!("the documented orbit n = {n} certifies: {e:?}"));
        let text = chatter::write::write_orbit(&found.certificate);
        produced += 1;
        assert!(t.run(&format!("orbit n={n}"), &text), "the tool's orbit certificate is rejected\n{text}");
    }
    eprintln!("produced {produced} files; verdicts {:?}", t.counts);
    assert!(t.failures.is_empty(), "{} disagreements:\n{}", t.failures.len(), t.failures.join("\n\n"));
}
