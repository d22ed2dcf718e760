//! The oracle against the kernel on the whole corpus: every file of `certificates/valid` and
//! `certificates/invalid` (RON, JSON, gzip'd), with the expected codes of
//! `certificates/invalid/expected.json` (time-to-rest certificates, `rest-*`, included since the
//! oracle checks rules G1-G5 itself). Any disagreement fails with the file.

use crate::common::{differential_file, root};
use chatter_oracle::compare::Agreement;
use std::collections::BTreeMap;

fn corpus(dir: &str) -> Vec<std::path::PathBuf> {
    let mut files: Vec<_> = std::fs::read_dir(root().join(dir))
        .expect("the corpus")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.file_name().is_some_and(|n| n != "expected.json"))
        .collect();
    files.sort();
    files
}

#[test]
fn every_corpus_file_gets_the_kernels_verdict_from_the_oracle() {
    let expected: Vec<serde_json::Value> = serde_json::from_str(
        &std::fs::read_to_string(root().join("certificates/invalid/expected.json")).expect("manifest"),
    )
    .expect("json");
    let mut failures = vec![];
    let mut tally: BTreeMap<String, usize> = BTreeMap::new();
    for dir in ["certificates/valid", "certificates/invalid"] {
        for path in corpus(dir) {
            let (kernel, oracle, cmp) = differential_file(&path);
            let name = path.file_name().unwrap().to_string_lossy().to_string();
            match cmp {
                Ok(a) => *tally.entry(format!("{a:?}")).or_default() += 1,
                Err(f) => failures.push(format!("{}: {f}", path.display())),
            }
            if dir.ends_with("/valid") && !kernel.accepted {
                failures.push(format!("{name}: the kernel rejects a valid corpus file: {kernel:?}"));
            }
            if let Some(e) = expected.iter().find(|e| e["file"] == name.as_str()) {
                let code = e["code"].as_str().expect("a code");
                let one_sided = oracle.sided == chatter_oracle::verdict::Sided::One;
                if kernel.accepted || !(oracle.codes().contains(&code) || one_sided) {
                    failures.push(format!("{name}: expected {code}, the oracle says {oracle:?}"));
                }
            }
        }
    }
    eprintln!("corpus: {tally:?}");
    assert!(failures.is_empty(), "{} disagreements:\n{}", failures.len(), failures.join("\n"));
    assert!(tally.get(&format!("{:?}", Agreement::BothAccept)).copied().unwrap_or(0) >= 80, "{tally:?}");
}

#[test]
#[ignore = "a timing tool, not a test"]
fn time_each_corpus_file() {
    for dir in ["certificates/valid", "certificates/invalid"] {
        for path in corpus(dir) {
            let t = std::time::Instant::now();
            let text = crate::common::read_text(&path).unwrap_or_default();
            let enc = chatter_oracle::read::Encoding::of_name(&path.to_string_lossy());
            let o = chatter_oracle::judge(&text, enc);
            let to = t.elapsed();
            let t = std::time::Instant::now();
            let _ = crate::common::kernel_file(&path);
            eprintln!(
                "{:>8.3} {:>8.3} {} {:?}",
                to.as_secs_f64(),
                t.elapsed().as_secs_f64(),
                path.display(),
                o.kind
            );
        }
    }
}

/// Inputs found by the fuzz target `oracle` (oracle/tests/data), kept as regression cases: each
/// must now get compatible verdicts.
#[test]
fn fuzz_findings_stay_resolved() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    let mut n = 0;
    for e in std::fs::read_dir(&dir).expect("tests/data") {
        let path = e.expect("entry").path();
        let (kernel, oracle, cmp) = differential_file(&path);
        assert!(cmp.is_ok(), "{}: {cmp:?}\n{kernel:?}\n{oracle:?}", path.display());
        n += 1;
    }
    assert!(n >= 1);
}

/// Where the kernel rejects an orbit certificate because a condition "fails at the centre of the
/// sub-box", the oracle evaluates the return map exactly at that centre and sees the same
/// condition fail (the kernel then claims a definite point, which the one-sided oracle can check).
#[test]
fn orbit_rejections_at_a_centre_are_confirmed_exactly() {
    use chatter_oracle::compare::orbit_centre_confirmed;
    use chatter_oracle::read::Encoding;
    let mut confirmed = 0;
    for path in corpus("certificates/invalid") {
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        if !name.starts_with("orbit-") || !name.ends_with(".ron") {
            continue;
        }
        let (kernel, _, _) = differential_file(&path);
        let text = std::fs::read_to_string(&path).unwrap();
        match orbit_centre_confirmed(&text, Encoding::Ron, &kernel) {
            Some(true) => confirmed += 1,
            Some(false) => panic!("{name}: the centre of the kernel's sub-box passes: {kernel:?}"),
            None => {}
        }
    }
    assert!(confirmed >= 4, "{confirmed} orbit rejections confirmed");
}
