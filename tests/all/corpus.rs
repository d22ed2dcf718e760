//! The certificate corpus: every file in certificates/valid verifies on both backends, and every
//! file in certificates/invalid is rejected with the code and message recorded in
//! certificates/invalid/expected.json.

use crate::common::root;
use chatter::exact::ParseLimits;
use chatter::verify::files::{declares_format, encoding_of, is_certificate_name, is_json_name};
use chatter::verify::read::{Input, read_input};
use chatter_kernel::certificate::{Claim, Encoding, read};
use chatter_kernel::syntax::Kind;
use chatter_kernel::verify::{MALACHITE, NUM, Verdict, verify_text, verify_text_in};
use serde::Deserialize;
use std::collections::BTreeSet;
use std::path::PathBuf;

/// The certificate files of a corpus directory (`*.ron`, `*.ron.gz`), sorted.
pub(crate) fn ron_files(dir: &str) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(root().join(dir))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| is_certificate_name(p))
        .collect();
    v.sort();
    v
}

/// The certificate files of a corpus directory as `chatter verify` finds them: also the JSON
/// twins (`*.json` declaring the format; not the manifest), sorted.
fn corpus_files(dir: &str) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(root().join(dir))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| is_certificate_name(p) || (is_json_name(p) && declares_format(&text_of(p))))
        .collect();
    v.sort();
    v
}

/// A corpus file's text (gzip'd files decompressed), as `chatter verify` reads it.
fn text_of(p: &std::path::Path) -> String {
    match read_input(p, 1 << 24) {
        Input::Text { text, .. } => text,
        other => panic!("{}: {other:?}", p.display()),
    }
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

/// Whether a corpus file is a refutation (by its name; the kernel checks the format field).
fn is_refutation(p: &std::path::Path) -> bool {
    p.file_name().is_some_and(|n| n.to_string_lossy().starts_with("refutation-"))
}

/// Time-to-rest certificates (docs/certificate-format.md §16; kernel/tests/all/rest.rs checks them).
fn is_rest(p: &std::path::Path) -> bool {
    p.file_name().is_some_and(|n| n.to_string_lossy().starts_with("rest-"))
}

/// Whether a corpus file is a basin certificate (by its name; the kernel checks the format
/// field): its own report, checked in kernel/tests/all/basin.rs and tests/all/basin.rs.
fn is_basin(p: &std::path::Path) -> bool {
    p.file_name().is_some_and(|n| n.to_string_lossy().starts_with("basin-"))
}

/// The kernel's rejection of certificate or refutation text (RON or JSON, by the file's name) on
/// the backends, if any.
fn rejection(
    path: &std::path::Path,
    text: &str,
    backends: &[chatter_kernel::verify::Backend],
) -> Option<chatter_kernel::certificate::Rejection> {
    let encoding = encoding_of(path);
    let format = chatter::verify::format::format_of_in(text, encoding);
    if format.as_deref() == Some(chatter_kernel::rest::FORMAT) {
        let limits = ParseLimits::default();
        return match chatter_kernel::verify::verify_rest_text_in(text, encoding, limits, backends) {
            Verdict::Rejected(r) => Some(r),
            other => panic!("expected a rejection, got {other:?}"),
        };
    }
    if format.as_deref() == Some(chatter_kernel::rest_family::FORMAT) {
        let limits = ParseLimits::default();
        return match chatter_kernel::verify::verify_rest_family_text_in(text, encoding, limits, backends) {
            Verdict::Rejected(r) => Some(r),
            other => panic!("expected a rejection, got {other:?}"),
        };
    }
    if format.as_deref() == Some(chatter_kernel::syntax::basin::FORMAT) {
        let limits = ParseLimits::default();
        return match chatter_kernel::verify::verify_basin_text_in(text, encoding, limits, backends) {
            Verdict::Rejected(r) => Some(r),
            other => panic!("expected a rejection, got {other:?}"),
        };
    }
    if format.as_deref() == Some(chatter_kernel::refute::FORMAT) {
        match chatter_kernel::verify::verify_refutation_text_in(
            text,
            encoding,
            ParseLimits::default(),
            backends,
        ) {
            Verdict::Rejected(r) => Some(r),
            other => panic!("expected a rejection, got {other:?}"),
        }
    } else {
        match verify_text_in(text, encoding, ParseLimits::default(), backends) {
            Verdict::Rejected(r) => Some(r),
            _ => None,
        }
    }
}

#[test]
fn every_valid_refutation_verifies_on_both_backends() {
    let files: Vec<PathBuf> =
        ron_files("certificates/valid").into_iter().filter(|f| is_refutation(f)).collect();
    assert!(files.len() >= 4, "refutations for n = 2, 3, 4, 6");
    let mut ns = BTreeSet::new();
    for f in &files {
        let text = text_of(f);
        let both =
            chatter_kernel::verify::verify_refutation_text(&text, ParseLimits::default(), &[MALACHITE, NUM]);
        let Verdict::Accepted(a) = &both else { panic!("{}: {both:?}", f.display()) };
        ns.insert(a.n);
        let r: chatter_kernel::refute::Refutation =
            chatter_kernel::syntax::read(&text, Encoding::Ron).unwrap();
        assert_eq!(
            chatter::write::write_refutation(&r),
            text,
            "{}: the writer's layout is canonical",
            f.display()
        );
    }
    assert_eq!(ns, BTreeSet::from([2, 3, 4, 6]));
}

#[test]
fn every_valid_certificate_verifies_on_both_backends() {
    let files: Vec<PathBuf> = ron_files("certificates/valid")
        .into_iter()
        .filter(|f| !is_refutation(f) && !is_basin(f) && !is_rest(f))
        .collect();
    assert!(files.len() >= 30, "the valid corpus has {} files", files.len());
    let (mut ns, mut claims) = (BTreeSet::new(), BTreeSet::new());
    for f in &files {
        let text = text_of(f);
        // Each backend alone accepts, with the same report (what `verify` on both backends
        // compares with `agree`, tested in kernel/tests/all/backends.rs).
        let both = verify_text(&text, ParseLimits::default(), &[MALACHITE]);
        let Verdict::Accepted(a) = &both else { panic!("{}: {both:?}", f.display()) };
        assert_eq!(verify_text(&text, ParseLimits::default(), &[NUM]), both, "{}", f.display());
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
        // Orbit certificates have no cone K (docs/certificate-format.md §14).
        let orbit = a.claim == Claim::CompleteChatterFromSet;
        assert_eq!(
            a.contains_translation, !orbit,
            "{name}: K contains the post-impact velocity of a translation"
        );
        ns.insert(a.n);
        claims.insert(a.claim);
    }
    assert_eq!(
        ns,
        BTreeSet::from([2, 3, 4, 5, 6, 7, 8, 12]),
        "the corpus covers the rod, n = 3, 4, 6 and the number fields of n = 5, 7, 8, 12"
    );
    assert_eq!(claims.len(), 4, "the corpus covers every claim (the three cone claims and the orbit claim)");
}

#[test]
fn every_invalid_certificate_is_rejected_for_its_stated_reason() {
    let manifest: Vec<Expected> = serde_json::from_str(
        &std::fs::read_to_string(root().join("certificates/invalid/expected.json")).unwrap(),
    )
    .unwrap();
    let files: BTreeSet<String> = corpus_files("certificates/invalid")
        .iter()
        .map(|p| p.file_name().unwrap().to_string_lossy().to_string())
        .collect();
    let listed: BTreeSet<String> = manifest.iter().map(|e| e.file.clone()).collect();
    assert_eq!(files, listed, "every invalid file has an expected verdict, and vice versa");
    assert!(manifest.len() >= 20);
    let reasons: BTreeSet<&str> = manifest.iter().map(|e| e.why.as_str()).collect();
    assert_eq!(reasons.len(), manifest.len(), "each file fails for a different stated reason");
    for e in &manifest {
        let path = root().join("certificates/invalid").join(&e.file);
        let text = text_of(&path);
        // Each backend alone (`verify` on both compares them with `agree`).
        for b in [&[MALACHITE][..], &[NUM]] {
            match rejection(&path, &text, b) {
                Some(r) => {
                    assert_eq!(r.code.as_str(), e.code, "{}: {}", e.file, r.message());
                    assert_eq!(serde_json::to_value(&r.locus).unwrap(), e.locus, "{}: locus", e.file);
                    assert!(
                        r.message().contains(&e.message),
                        "{}: {:?} lacks {:?}",
                        e.file,
                        r.message(),
                        e.message
                    );
                }
                None => panic!("{} ({}): expected a rejection", e.file, b[0].name),
            }
        }
    }
}

#[test]
fn corpus_certificates_round_trip_through_the_writer() {
    let mut basins = 0;
    for f in ron_files("certificates/valid").into_iter().filter(|f| !is_refutation(f)) {
        let text = std::fs::read_to_string(&f).unwrap();
        let kind = chatter_kernel::syntax::kind_of(&text, Encoding::Ron, Kind::Cone).unwrap().0;
        if kind == Kind::Family {
            let cert = chatter_kernel::certificate::read_convex(&text, Encoding::Ron).unwrap();
            assert_eq!(chatter::write::write_convex(&cert), text, "{}", f.display());
            continue;
        }
        if kind == Kind::Orbit {
            let cert = chatter_kernel::certificate::read_orbit(&text, Encoding::Ron).unwrap();
            assert_eq!(chatter::write::write_orbit(&cert), text, "{}", f.display());
            continue;
        }
        if kind == Kind::Rest {
            let cert: chatter_kernel::rest::TimeToRest =
                chatter_kernel::syntax::read(&text, Encoding::Ron).unwrap();
            assert_eq!(chatter::write::write_rest(&cert), text, "{}", f.display());
            continue;
        }
        if kind == Kind::RestFamily {
            let cert: chatter_kernel::rest_family::FamilyTimeToRest =
                chatter_kernel::syntax::read(&text, Encoding::Ron).unwrap();
            assert_eq!(chatter::write::write_rest_family(&cert), text, "{}", f.display());
            continue;
        }
        if kind == Kind::Basin {
            let cert = chatter_kernel::syntax::read(&text, Encoding::Ron).unwrap();
            assert_eq!(chatter::basin::write_basin(&cert), text, "{}", f.display());
            basins += 1;
            continue;
        }
        let cert = read(&text).unwrap();
        assert_eq!(chatter::write::write(&cert), text, "{}: the writer's layout is canonical", f.display());
    }
    assert!(basins >= 2, "the valid corpus has {basins} basin certificates");
}

/// The rows `| rule | code | file |` of docs/kernel-soundness.md §5 ("Which file breaks which rule").
fn rule_rows() -> Vec<(String, String, String)> {
    let doc = std::fs::read_to_string(root().join("docs/kernel-soundness.md")).unwrap();
    let start = doc.find("| rule | code | corpus file |").expect("the table of §5");
    doc[start..]
        .lines()
        .skip(2)
        .take_while(|l| l.starts_with('|'))
        .map(|l| {
            let c: Vec<&str> = l.trim_matches('|').split('|').map(|x| x.trim().trim_matches('`')).collect();
            (c[0].to_string(), c[1].to_string(), c[2].to_string())
        })
        .collect()
}

/// The kernel's half of §5: every row's file is rejected with the row's code. That each file
/// breaks only its rule is decided by the independent oracle in oracle/tests/all/rules.rs.
#[test]
fn every_acceptance_rule_has_a_corpus_file_rejected_with_its_code() {
    let rows = rule_rows();
    let rules: BTreeSet<&str> = rows.iter().map(|r| r.0.as_str()).collect();
    for rule in [
        "reading",
        "limits",
        "numbers",
        "body",
        "range of γ",
        "R1",
        "R2",
        "R3",
        "R4",
        "rod R2",
        "rod R3",
        "convex body",
        "K1",
        "K2",
        "K3",
        "K4",
        "B1",
        "B2",
        "B3",
        "B4",
    ] {
        assert!(rules.contains(rule), "rule {rule} has a row");
    }
    for (_, code, file) in &rows {
        let path = root().join("certificates/invalid").join(file);
        let text = text_of(&path);
        let r = rejection(&path, &text, &[MALACHITE, NUM]).unwrap_or_else(|| panic!("{file} is rejected"));
        assert_eq!(r.code.as_str(), code, "{file}");
    }
}
