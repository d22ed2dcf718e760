//! What the build promises: the workspace's `rust-version` is the true minimum (the highest
//! `rust-version` declared by a dependency in Cargo.lock; clippy's `incompatible_msrv` lint, run by
//! CI with `-D warnings`, checks our own use of the standard library against it), and the fuzz
//! crate's lock file pins the workspace's versions, so that CI builds it in the same target
//! directory without compiling any dependency twice (.ci/run).

use crate::common::root;
use std::collections::{BTreeMap, BTreeSet};
use std::path::PathBuf;

/// (name, version, source) of every package of a Cargo.lock.
fn locked(path: &str) -> Vec<(String, String, Option<String>)> {
    let text = std::fs::read_to_string(root().join(path)).unwrap();
    let mut out = Vec::new();
    for block in text.split("[[package]]").skip(1) {
        let field = |key: &str| {
            block.lines().find_map(|l| {
                l.strip_prefix(key)?.trim_start().strip_prefix("= \"")?.strip_suffix('"').map(str::to_string)
            })
        };
        out.push((field("name").unwrap(), field("version").unwrap(), field("source")));
    }
    assert!(out.len() > 10, "{path}: {} packages", out.len());
    out
}

/// A version "1.90" or "1.90.0" as (major, minor, patch).
fn version(text: &str) -> (u32, u32, u32) {
    let mut parts = text.split('.').map(|p| p.parse::<u32>().unwrap_or_else(|_| panic!("version {text:?}")));
    (parts.next().unwrap(), parts.next().unwrap_or(0), parts.next().unwrap_or(0))
}

/// The `rust-version` of the `[package]` (or `[workspace.package]`) section of a manifest.
fn rust_version(manifest: &str) -> Option<String> {
    let mut section = "";
    for line in manifest.lines() {
        let line = line.trim();
        if line.starts_with('[') {
            section = line;
        } else if (section == "[package]" || section == "[workspace.package]")
            && let Some(v) = line.strip_prefix("rust-version")
        {
            return Some(v.trim_start().strip_prefix('=')?.trim().trim_matches('"').to_string());
        }
    }
    None
}

fn cargo_home() -> PathBuf {
    std::env::var_os("CARGO_HOME")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(std::env::var_os("HOME").expect("HOME")).join(".cargo"))
}

#[test]
fn rust_version_is_the_highest_that_a_dependency_declares() {
    let manifest = std::fs::read_to_string(root().join("Cargo.toml")).unwrap();
    let ours = rust_version(&manifest).expect("Cargo.toml's [workspace.package] has a rust-version");
    for member in ["kernel/Cargo.toml", "python/Cargo.toml"] {
        let text = std::fs::read_to_string(root().join(member)).unwrap();
        assert!(text.contains("rust-version.workspace = true"), "{member} inherits rust-version");
    }
    // The sources cargo unpacked to build this workspace (every package built on this platform).
    let sources: Vec<PathBuf> = std::fs::read_dir(cargo_home().join("registry/src"))
        .expect("the cargo registry's sources (the workspace was built from them)")
        .map(|e| e.unwrap().path())
        .collect();
    let mut declared = BTreeMap::new();
    let mut unpacked = 0;
    for (name, v, source) in locked("Cargo.lock") {
        if !source.is_some_and(|s| s.starts_with("registry+")) {
            continue;
        }
        let Some(text) = sources
            .iter()
            .find_map(|s| std::fs::read_to_string(s.join(format!("{name}-{v}/Cargo.toml"))).ok())
        else {
            continue; // not built here (another platform's dependency)
        };
        unpacked += 1;
        if let Some(rv) = rust_version(&text) {
            declared.insert(format!("{name} {v}"), version(&rv));
        }
    }
    assert!(unpacked >= 100 && declared.len() >= 50, "{unpacked} sources found, {} declare", declared.len());
    let highest = *declared.values().max().unwrap();
    let needing: BTreeSet<&String> =
        declared.iter().filter(|(_, v)| **v == highest).map(|(p, _)| p).collect();
    assert_eq!(
        version(&ours),
        highest,
        "Cargo.toml says rust-version = {ours:?}; the dependencies need {}.{} ({needing:?})",
        highest.0,
        highest.1
    );
}

#[test]
fn the_fuzz_crate_locks_the_workspace_versions() {
    let workspace: BTreeSet<(String, String)> =
        locked("Cargo.lock").into_iter().map(|(n, v, _)| (n, v)).collect();
    let names: BTreeSet<&String> = workspace.iter().map(|(n, _)| n).collect();
    let fuzz = locked("fuzz/Cargo.lock");
    let mut shared = 0;
    for (name, v, _) in &fuzz {
        if names.contains(name) {
            assert!(
                workspace.contains(&(name.clone(), v.clone())),
                "fuzz/Cargo.lock has {name} {v}, Cargo.lock another version: run `cargo update --manifest-path fuzz/Cargo.toml -p {name} --precise VERSION`"
            );
            shared += 1;
        }
    }
    assert!(shared >= 20, "{shared} packages shared");
    // The same release profile, or every shared package would compile again.
    let profile = |path: &str| {
        let text = std::fs::read_to_string(root().join(path)).unwrap();
        let start = text.find("[profile.release]").unwrap_or_else(|| panic!("{path}: no [profile.release]"));
        text[start..]
            .lines()
            .skip(1)
            .take_while(|l| !l.starts_with('['))
            .filter(|l| !l.trim().is_empty() && !l.trim_start().starts_with('#'))
            .map(str::to_string)
            .collect::<Vec<_>>()
    };
    // (The per-package overrides of dev-dependencies, which the fuzz crate does not build, may differ.)
    assert_eq!(profile("fuzz/Cargo.toml"), profile("Cargo.toml"));
}

/// No library (the tool's, the kernel's, the oracle's) is a test harness (`[lib] test = false`, so that CI
/// does not compile it a second time): a unit test written inside src/ would never run, so there
/// must be none.
#[test]
fn the_library_has_no_unit_tests_that_would_not_run() {
    fn walk(dir: &std::path::Path, found: &mut Vec<String>) {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                walk(&path, found);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let text = std::fs::read_to_string(&path).unwrap();
                if text.lines().any(|l| matches!(l.trim(), "#[cfg(test)]" | "#[test]")) {
                    found.push(path.display().to_string());
                }
            }
        }
    }
    for (manifest, src) in
        [("Cargo.toml", "src"), ("kernel/Cargo.toml", "kernel/src"), ("oracle/Cargo.toml", "oracle/src")]
    {
        let manifest = std::fs::read_to_string(root().join(manifest)).unwrap();
        let lib = &manifest[manifest.find("[lib]").unwrap()..];
        assert!(
            lib.lines().skip(1).take_while(|l| !l.starts_with('[')).any(|l| l.trim() == "test = false"),
            "{src}"
        );
        let mut found = Vec::new();
        walk(&root().join(src), &mut found);
        assert!(
            found.is_empty(),
            "unit tests in {src}/ that `cargo test` would not run (move them to its tests/all/): {found:?}"
        );
    }
}

/// The units (package, target with mode and profile, features) of a cargo command's release build, from cargo's
/// unit graph (`--unit-graph`, unstable: enabled by RUSTC_BOOTSTRAP as for `cargo fuzz`).
fn units(args: &[&str]) -> Vec<(String, String, String)> {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let o = std::process::Command::new(cargo)
        .args(args)
        .args(["--release", "--frozen", "--unit-graph", "-Z", "unstable-options"])
        .current_dir(root())
        .env("RUSTC_BOOTSTRAP", "1")
        .output()
        .unwrap();
    assert!(o.status.success(), "cargo {args:?}: {}", String::from_utf8_lossy(&o.stderr));
    let graph: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    // "name@version" (two versions of a package may share name, features and profile).
    let name = |id: &str| id.rsplit(['#', '/']).next().unwrap().to_string();
    graph["units"]
        .as_array()
        .unwrap()
        .iter()
        .map(|u| {
            let f = |k: &str| u[k].to_string();
            let what = format!("{} {} {}", u["target"]["name"], f("mode"), f("profile"));
            (name(u["pkg_id"].as_str().unwrap()), what, f("features"))
        })
        .collect()
}

/// Issue 26: README's test command is said to build on the first command's release build. Cargo
/// resolves features per command: the packages whose features the test build (dev-dependencies,
/// the Python package) changes compile again, with everything above them. docs/measurements.md
/// names them; README must not claim the build is simply reused while the list is not empty.
#[test]
fn the_docs_name_the_packages_the_test_command_compiles_again() {
    let run = units(&["build"]);
    let test: BTreeSet<_> = units(&["test", "--workspace", "--no-run"]).into_iter().collect();
    let again: BTreeSet<String> = run
        .into_iter()
        .filter(|u| !test.contains(u))
        .map(|u| u.0.split('@').next().unwrap().to_string())
        .collect();
    let doc = std::fs::read_to_string(root().join("docs/measurements.md")).unwrap();
    let line =
        doc.split("Compiled again by the test command:").nth(1).expect("docs/measurements.md lists them");
    let line = &line[..line.find('.').unwrap_or(line.len())];
    let listed: BTreeSet<String> = line.split('`').skip(1).step_by(2).map(str::to_string).collect();
    assert_eq!(listed, again, "docs/measurements.md: the packages `cargo test` compiles again");
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap().replace('\n', " ");
    if !again.is_empty() {
        assert!(!readme.contains("on the same release build"), "README says the test build is the first's");
        assert!(readme.contains("compiles again"), "README must say that some packages compile again");
    }
}
