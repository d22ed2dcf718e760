//! The trusted crate's boundary, checked: it depends on exact arithmetic, serde, ron and serde_json
//! only; its source has no floating-point type and no reference to the untrusted tool; the
//! words of rejections (`explain/`) are outside the trusted path; the numbers do not depend on
//! the proof checker; and every file of rules starts with the list of its rules.

use std::path::Path;

const ALLOWED: [&str; 8] =
    ["malachite", "num-bigint", "num-integer", "num-rational", "num-traits", "ron", "serde", "serde_json"];

#[test]
fn the_kernel_depends_on_exact_arithmetic_serde_ron_and_serde_json_only() {
    let manifest = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("Cargo.toml")).unwrap();
    let deps = manifest.split("[dependencies]").nth(1).expect("a [dependencies] table");
    let deps = deps.split("\n[").next().unwrap();
    let mut names: Vec<&str> = deps
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .map(|l| l.split(['=', ' ']).next().unwrap())
        .collect();
    names.sort();
    assert_eq!(names, ALLOWED);
}

fn sources(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            sources(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

#[test]
fn the_kernel_source_has_no_floats_and_no_untrusted_code() {
    let mut files = Vec::new();
    sources(&Path::new(env!("CARGO_MANIFEST_DIR")).join("src"), &mut files);
    assert!(files.len() >= 20);
    for f in files {
        let text = std::fs::read_to_string(&f).unwrap();
        for (i, line) in text.lines().enumerate() {
            let code = line.split("//").next().unwrap();
            let words: Vec<&str> = code.split(|c: char| !c.is_alphanumeric() && c != '_').collect();
            for bad in ["f32", "f64", "unsafe"] {
                assert!(!words.contains(&bad), "{}:{}: {bad} in {line:?}", f.display(), i + 1);
            }
            assert!(!code.contains("chatter::"), "{}:{}: the tool in {line:?}", f.display(), i + 1);
        }
    }
}

/// The source files under `src/<dir>` (all of them for `""`).
fn files_under(dir: &str) -> Vec<std::path::PathBuf> {
    let mut files = Vec::new();
    sources(&Path::new(env!("CARGO_MANIFEST_DIR")).join("src").join(dir), &mut files);
    files
}

#[test]
fn the_rules_never_read_the_words_of_a_rejection() {
    for f in files_under("") {
        let text = std::fs::read_to_string(&f).unwrap();
        let rel = f.to_string_lossy();
        if rel.contains("/src/explain/") || rel.ends_with("/src/lib.rs") {
            continue;
        }
        let code: Vec<&str> = text.lines().map(|l| l.split("//").next().unwrap()).collect();
        let code = code.join("\n");
        assert!(!code.contains("crate::explain") && !code.contains("message()"), "{rel} uses the words");
    }
}

#[test]
fn the_numbers_do_not_depend_on_the_rules_or_the_proof_checker() {
    for f in files_under("exact") {
        let text = std::fs::read_to_string(&f).unwrap();
        for other in ["crate::rules", "crate::proof", "crate::syntax", "crate::verify"] {
            assert!(!text.contains(other), "{}: {other}", f.display());
        }
    }
}

#[test]
fn every_file_of_rules_starts_with_its_rules_and_their_codes() {
    let codes: Vec<String> =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("src/reject/mod.rs"))
            .unwrap()
            .lines()
            .filter_map(|l| {
                l.trim().split(" = \"").nth(1).map(|c| format!("`{}`", c.trim_end_matches("\",")))
            })
            .collect();
    assert!(codes.len() > 20, "the codes of reject/mod.rs");
    let kinds = ["cone", "rod", "boxes", "field", "family", "orbit", "refutation", "proof/mod"];
    for kind in kinds {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("src/rules/{kind}.rs"));
        let text = std::fs::read_to_string(&path).unwrap();
        let head: String = text.lines().take_while(|l| l.starts_with("//!")).collect::<Vec<_>>().join("\n");
        assert!(head.lines().filter(|l| l.starts_with("//! -")).count() >= 2, "{kind}: a list of rules");
        assert!(codes.iter().any(|c| head.contains(c.as_str())), "{kind}: the rules name their codes");
    }
}

/// The loci of the kinds beyond point certificates (`reject/kinds.rs`) are written in JSON as
/// every other locus: `kind` and the fields, with no trace of the nesting.
#[test]
#[cfg(all(feature = "family", feature = "orbit"))]
fn the_loci_of_the_other_kinds_are_written_as_before() {
    use chatter_kernel::reject::{KindLocus, Locus};
    let json = |l: Locus| serde_json::to_value(l).unwrap();
    let step = Locus::from(KindLocus::Step { index: 3, id: "q1".into() });
    assert_eq!(json(step), serde_json::json!({"kind": "step", "index": 3, "id": "q1"}));
    let pair = Locus::from(KindLocus::PccPair { pair: 2, gamma: None });
    assert_eq!(json(pair), serde_json::json!({"kind": "pcc-pair", "pair": 2}));
    let sub_box = Box::new([["0", "1"], ["1/2", "1"], ["0", "1/4"]].map(|r| r.map(String::from)));
    let orbit = Locus::from(KindLocus::OrbitBox { sub_box, depth: 1, step: None, contact: None });
    assert_eq!(
        json(orbit),
        serde_json::json!({"kind": "orbit-box", "sub_box": [["0", "1"], ["1/2", "1"], ["0", "1/4"]], "depth": 1})
    );
    #[cfg(feature = "basin")]
    {
        let leaf = Locus::from(KindLocus::BasinLeaf { leaf: 4, path: "021".into() });
        assert_eq!(json(leaf), serde_json::json!({"kind": "basin-leaf", "leaf": 4, "path": "021"}));
    }
    assert_eq!(json(Locus::Cone), serde_json::json!({"kind": "cone"}));
}
