//! The certificate corpus: every file in certificates/valid verifies on both backends, and every
//! file in certificates/invalid is rejected with the code and message recorded in
//! certificates/invalid/expected.json.

use crate::common::root;
use chatter::exact::ParseLimits;
use chatter_kernel::certificate::{Claim, read};
use chatter_kernel::verify::{MALACHITE, NUM, Verdict, verify_text};
use serde::Deserialize;
use std::collections::BTreeSet;
use std::path::PathBuf;

fn ron_files(dir: &str) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(root().join(dir))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "ron"))
        .collect();
    v.sort();
    v
}

#[derive(Deserialize)]
struct Expected {
    file: String,
    code: String,
    message: String,
    /// The structured locus, as `chatter verify --json` writes it.
    locus: serde_json::Value,
    why: String,
}

#[test]
fn every_valid_certificate_verifies_on_both_backends() {
    let files = ron_files("certificates/valid");
    assert!(files.len() >= 30, "the valid corpus has {} files", files.len());
    let (mut ns, mut claims) = (BTreeSet::new(), BTreeSet::new());
    for f in &files {
        let text = std::fs::read_to_string(f).unwrap();
        // Each backend alone, and both together, accept with the same report.
        let both = verify_text(&text, ParseLimits::default(), &[MALACHITE, NUM]);
        let Verdict::Accepted(a) = &both else { panic!("{}: {both:?}", f.display()) };
        for b in [MALACHITE, NUM] {
            assert_eq!(verify_text(&text, ParseLimits::default(), &[b]), both, "{}", f.display());
        }
        // Generated files name their claim; the certificate must carry it.
        let name = f.file_name().unwrap().to_string_lossy().to_string();
        let named = [
            ("-effectively-invariant.ron", Claim::EffectivelyInvariant),
            ("-cc-or-pcc-from-all-down.ron", Claim::CcOrPccFromAllDown),
            ("-complete-chatter-from-all-down.ron", Claim::CompleteChatterFromAllDown),
        ];
        if let Some((_, c)) = named.iter().find(|(suffix, _)| name.ends_with(suffix)) {
            assert_eq!(a.claim, *c, "{name}");
        }
        assert!(a.contains_translation, "{name}: K contains the post-impact velocity of a translation");
        ns.insert(a.n);
        claims.insert(a.claim);
    }
    assert_eq!(ns, BTreeSet::from([2, 3, 4, 6]), "the corpus covers every supported n");
    assert_eq!(claims.len(), 3, "the corpus covers every claim");
}

#[test]
fn every_invalid_certificate_is_rejected_for_its_stated_reason() {
    let manifest: Vec<Expected> = serde_json::from_str(
        &std::fs::read_to_string(root().join("certificates/invalid/expected.json")).unwrap(),
    )
    .unwrap();
    let files: BTreeSet<String> = ron_files("certificates/invalid")
        .iter()
        .map(|p| p.file_name().unwrap().to_string_lossy().to_string())
        .collect();
    let listed: BTreeSet<String> = manifest.iter().map(|e| e.file.clone()).collect();
    assert_eq!(files, listed, "every invalid file has an expected verdict, and vice versa");
    assert!(manifest.len() >= 20);
    let reasons: BTreeSet<&str> = manifest.iter().map(|e| e.why.as_str()).collect();
    assert_eq!(reasons.len(), manifest.len(), "each file fails for a different stated reason");
    for e in &manifest {
        let text = std::fs::read_to_string(root().join("certificates/invalid").join(&e.file)).unwrap();
        for b in [&[MALACHITE, NUM][..], &[MALACHITE], &[NUM]] {
            match verify_text(&text, ParseLimits::default(), b) {
                Verdict::Rejected(r) => {
                    assert_eq!(r.code.as_str(), e.code, "{}: {}", e.file, r.message);
                    assert_eq!(serde_json::to_value(&r.locus).unwrap(), e.locus, "{}: locus", e.file);
                    assert!(
                        r.message.contains(&e.message),
                        "{}: {:?} lacks {:?}",
                        e.file,
                        r.message,
                        e.message
                    );
                }
                other => panic!("{} ({}): expected a rejection, got {other:?}", e.file, b[0].name),
            }
        }
    }
}

#[test]
fn corpus_certificates_round_trip_through_the_writer() {
    for f in ron_files("certificates/valid") {
        let text = std::fs::read_to_string(&f).unwrap();
        let cert = read(&text).unwrap();
        assert_eq!(
            chatter_kernel::certificate::write(&cert),
            text,
            "{}: the writer's layout is canonical",
            f.display()
        );
    }
}
