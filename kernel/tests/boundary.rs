//! The trusted crate's boundary, checked: it depends on exact arithmetic, serde, ron and serde_json
//! only, and its source has no floating-point type and no reference to the untrusted tool.

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
