//! The lines a reviewer must read to trust one kind of verdict (docs/kernel-soundness.md §4),
//! measured: the non-blank, non-comment lines of every source file reached from the kind's rules
//! by `mod` declarations and by `crate::`, `super::` and `self::` paths (in `use` statements or
//! inline), with the Cargo features of that kind only (and those they enable, as Cargo.toml
//! says). `verify/mod.rs`, which dispatches to every
//! kind, is read too, but its paths into other kinds' rules are not followed. The table in
//! docs/kernel-soundness.md §4 must be the measurement, and point certificates must stay under
//! their targets.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// The kinds of verdict: name in the table, the rules file (under src/), the features.
const KINDS: [(&str, &str, &[&str]); 14] = [
    ("point certificates, n = 3, 4, 6", "rules/cone.rs", &[]),
    ("point certificates of the rod", "rules/rod.rs", &[]),
    ("box certificates", "rules/boxes.rs", &["boxes"]),
    ("number fields", "rules/field.rs", &["field"]),
    ("family certificates", "rules/family.rs", &["family"]),
    ("orbit certificates, n = 3, 4, 6", "rules/orbit.rs", &["orbit"]),
    ("orbit certificates in number fields", "rules/orbit.rs", &["orbit", "field"]),
    ("basin certificates, n = 3, 4, 6", "rules/basin.rs", &["basin", "orbit"]),
    ("refutations", "rules/refutation.rs", &["refutation"]),
    ("proofs", "rules/proof/mod.rs", &["proof"]),
    ("time-to-rest certificates", "rules/rest.rs", &["rest"]),
    ("time-to-rest certificates in number fields", "rules/rest.rs", &["rest", "field"]),
    ("time-to-rest certificates on boxes", "rules/rest.rs", &["rest", "boxes"]),
    ("time-to-rest certificates of general bodies", "rules/rest_family.rs", &["family-rest"]),
];

/// Point certificates for n = 3, 4, 6: at most this many lines to read, of which at most this many
/// rules. Issue 23 asks for under 1,500 and under 300: the rules meet theirs; the whole is held
/// at its measurement (1,821 before the JSON twin, the codes of the other kinds and the
/// conveniences left the point kernel's files; docs/kernel-soundness.md §4 says where the lines
/// still are) so that it cannot grow unseen.
const POINT_BUDGET: (usize, usize) = (1_645, 279);

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

/// Non-blank, non-comment lines, as `grep -vcE '^\s*(//|$)'` counts them.
fn code_lines(text: &str) -> usize {
    text.lines().filter(|l| !(l.trim().is_empty() || l.trim_start().starts_with("//"))).count()
}

/// The file of the module `parts` (from the crate root), if there is one.
fn module_file(parts: &[String]) -> Option<PathBuf> {
    if parts.is_empty() {
        return Some(src().join("lib.rs"));
    }
    let base = parts.iter().fold(src(), |p, s| p.join(s));
    [base.with_extension("rs"), base.join("mod.rs")].into_iter().find(|p| p.exists())
}

/// The module path of a source file.
fn module_of(file: &Path) -> Vec<String> {
    let rel = file.strip_prefix(src()).unwrap().with_extension("");
    let mut parts: Vec<String> = rel.iter().map(|s| s.to_string_lossy().to_string()).collect();
    if parts.last().is_some_and(|p| p == "mod" || p == "lib") {
        parts.pop();
    }
    parts
}

/// The deepest module file a path (`crate::a::b::C`, `super::x`, `self::y`) names, seen from
/// the module `here`; `None` for a path into another crate.
fn resolve(path: &str, here: &[String]) -> Option<PathBuf> {
    let segs: Vec<&str> = path.split("::").map(|s| s.split(" as ").next().unwrap().trim()).collect();
    let (mut base, rest) = match segs.first() {
        Some(&"crate") => (Vec::new(), &segs[1..]),
        Some(&"self") => (here.to_vec(), &segs[1..]),
        Some(&"super") => (here[..here.len().saturating_sub(1)].to_vec(), &segs[1..]),
        _ => return None,
    };
    let mut rest = rest;
    while rest.first() == Some(&"super") {
        base.pop();
        rest = &rest[1..];
    }
    let mut best = module_file(&base);
    for i in 1..=rest.len() {
        let mut p = base.clone();
        p.extend(rest[..i].iter().map(|s| s.to_string()));
        if let Some(f) = module_file(&p) {
            best = Some(f);
        }
    }
    best
}

/// `a::{b, c::{d, e}}` as `a::b`, `a::c::d`, `a::c::e`.
fn expand(tree: &str) -> Vec<String> {
    let tree = tree.trim();
    let Some(open) = tree.find('{') else { return vec![tree.to_string()] };
    let (prefix, inner) = (&tree[..open], &tree[open + 1..tree.rfind('}').unwrap()]);
    let (mut parts, mut depth, mut cur) = (Vec::new(), 0, String::new());
    for ch in inner.chars() {
        depth += i32::from(ch == '{') - i32::from(ch == '}');
        if ch == ',' && depth == 0 {
            parts.push(std::mem::take(&mut cur));
        } else {
            cur.push(ch);
        }
    }
    parts.push(cur);
    parts
        .iter()
        .filter(|p| !p.trim().is_empty())
        .flat_map(|p| expand(p))
        .map(|p| format!("{prefix}{p}"))
        .collect()
}

/// Whether the predicate of a `#[cfg(...)]` holds with `features` (tests never count).
fn holds(pred: &str, features: &[&str]) -> bool {
    let pred = pred.trim();
    let args = |p: &str| -> Vec<String> {
        let inner = &p[p.find('(').unwrap() + 1..p.rfind(')').unwrap()];
        let (mut out, mut depth, mut cur) = (Vec::new(), 0, String::new());
        for ch in inner.chars() {
            depth += i32::from(ch == '(') - i32::from(ch == ')');
            if ch == ',' && depth == 0 {
                out.push(std::mem::take(&mut cur));
            } else {
                cur.push(ch);
            }
        }
        out.push(cur);
        out
    };
    if let Some(f) = pred.strip_prefix("feature").map(|r| r.trim_start_matches([' ', '=']).trim_matches('"'))
    {
        return features.contains(&f);
    }
    if pred.starts_with("any(") {
        return args(pred).iter().any(|a| holds(a, features));
    }
    if pred.starts_with("all(") {
        return args(pred).iter().all(|a| holds(a, features));
    }
    if pred.starts_with("not(") {
        return !holds(&args(pred)[0], features);
    }
    false
}

/// The files a source file refers to, with `features`: its `mod` declarations and the paths of
/// its `use` statements and code; an item under a `#[cfg(...)]` that does not hold is skipped.
fn references(file: &Path, features: &[&str]) -> Vec<PathBuf> {
    let text = std::fs::read_to_string(file).unwrap();
    let here = module_of(file);
    let lines: Vec<&str> =
        text.lines().map(|l| if l.trim_start().starts_with("//") { "" } else { l }).collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        let mut line = lines[i].split("//").next().unwrap().trim().to_string();
        while line.starts_with("#[cfg(") && !line.ends_with(")]") && i + 1 < lines.len() {
            i += 1;
            line.push_str(lines[i].trim());
        }
        if let Some(pred) = line.strip_prefix("#[cfg(").and_then(|p| p.strip_suffix(")]")) {
            i += 1;
            if !holds(pred, features) {
                i = skip_item(&lines, i);
            }
            continue;
        }
        let stmt = line
            .as_str()
            .trim_start_matches("pub(crate) ")
            .trim_start_matches("pub(super) ")
            .trim_start_matches("pub ");
        if let Some(name) = stmt.strip_prefix("mod ").and_then(|m| m.strip_suffix(';')) {
            let mut m = here.clone();
            m.push(name.to_string());
            out.extend(module_file(&m));
        } else if let Some(tree) = stmt.strip_prefix("use ") {
            let mut tree = tree.to_string();
            while !tree.trim_end().ends_with(';') {
                i += 1;
                tree.push_str(lines[i].split("//").next().unwrap().trim());
            }
            out.extend(
                expand(tree.trim_end().trim_end_matches(';')).iter().filter_map(|p| resolve(p, &here)),
            );
        } else {
            out.extend(inline_paths(&line).iter().filter_map(|p| resolve(p, &here)));
        }
        i += 1;
    }
    out
}

/// The index after the item starting at line `i` (one line, or up to its closing brace).
fn skip_item(lines: &[&str], mut i: usize) -> usize {
    while i < lines.len() && lines[i].trim_start().starts_with("#[") {
        i += 1;
    }
    let mut depth = 0i32;
    while i < lines.len() {
        depth += lines[i].matches('{').count() as i32 - lines[i].matches('}').count() as i32;
        let end = lines[i].trim_end();
        i += 1;
        if depth <= 0 && (end.ends_with(';') || end.ends_with(',') || end.ends_with('}')) {
            break;
        }
    }
    i
}

/// `crate::...` and `super::...` paths in a line of code.
fn inline_paths(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    for start in ["crate::", "super::"] {
        let mut from = 0;
        while let Some(k) = line[from..].find(start) {
            let at = from + k;
            let before = line[..at].chars().last();
            let end = line[at..]
                .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'))
                .map_or(line.len(), |e| at + e);
            if !before.is_some_and(|c| c.is_alphanumeric() || c == '_') {
                out.push(line[at..end].trim_end_matches(':').to_string());
            }
            from = end.max(at + start.len());
        }
    }
    out
}

/// `features` and the features they enable, as kernel/Cargo.toml's `[features]` says.
fn enabled<'a>(features: &[&'a str], toml: &'a str) -> Vec<&'a str> {
    let mut on = features.to_vec();
    let mut grew = true;
    while grew {
        grew = false;
        for (name, list) in toml.lines().filter_map(|l| l.split_once(" = [")) {
            for f in list.trim_end_matches(']').split(',').map(|f| f.trim().trim_matches('"')) {
                if on.contains(&name) && !f.is_empty() && !on.contains(&f) {
                    (on, grew) = ([on, vec![f]].concat(), true);
                }
            }
        }
    }
    on
}

/// The files a reviewer of one kind reads: reached from its rules and from verify/mod.rs.
fn reached(rules: &str, features: &[&str]) -> BTreeSet<PathBuf> {
    let toml = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("Cargo.toml")).unwrap();
    let features = &enabled(features, &toml)[..];
    let (verify, entry) = (src().join("verify/mod.rs"), src().join(rules));
    let (rules_dir, outcome) = (src().join("rules"), src().join("rules/outcome.rs"));
    let mut seen = BTreeSet::new();
    let mut todo = vec![verify.clone(), entry.clone()];
    while let Some(f) = todo.pop() {
        if !seen.insert(f.clone()) {
            continue;
        }
        for r in references(&f, features) {
            let other_kind = r.starts_with(&rules_dir) && r != entry && r != outcome;
            if !(f == verify && other_kind) {
                todo.push(r);
            }
        }
    }
    seen
}

/// Per kind: (files, lines, of which in rules/).
fn measure() -> BTreeMap<&'static str, (usize, usize, usize)> {
    let lines = |f: &PathBuf| code_lines(&std::fs::read_to_string(f).unwrap());
    KINDS
        .iter()
        .map(|(name, rules, features)| {
            let files = reached(rules, features);
            let in_rules = files.iter().filter(|f| f.starts_with(src().join("rules"))).map(lines).sum();
            (*name, (files.len(), files.iter().map(lines).sum(), in_rules))
        })
        .collect()
}

#[test]
fn point_certificates_stay_within_their_budget_with_fewer_than_300_lines_of_rules() {
    let (_, lines, rules) = measure()["point certificates, n = 3, 4, 6"];
    let files: Vec<String> = reached("rules/cone.rs", &[])
        .iter()
        .map(|f| format!("{} {}", code_lines(&std::fs::read_to_string(f).unwrap()), f.display()))
        .collect();
    assert!(lines <= POINT_BUDGET.0, "{lines} lines to read for a point certificate: {files:#?}");
    assert!(rules <= POINT_BUDGET.1, "{rules} lines of rules for a point certificate");
}

#[test]
fn the_size_table_of_the_soundness_document_is_the_measurement() {
    let doc =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/kernel-soundness.md"));
    let doc = doc.unwrap();
    let mut documented = BTreeMap::new();
    for line in doc.lines().filter(|l| l.starts_with("| ")) {
        let cells: Vec<&str> = line.trim_matches('|').split('|').map(str::trim).collect();
        let [kind, files, lines, rules] = cells[..] else { continue };
        let n = |s: &str| s.replace(',', "").parse::<usize>();
        if let (Ok(f), Ok(l), Ok(r)) = (n(files), n(lines), n(rules)) {
            documented.insert(kind.to_string(), (f, l, r));
        }
    }
    let measured: BTreeMap<String, _> = measure().into_iter().map(|(k, v)| (k.to_string(), v)).collect();
    assert_eq!(documented, measured, "docs/kernel-soundness.md §4: kind | files | lines | rules");
}

#[test]
fn the_measurement_follows_imports_and_features() {
    let point = reached("rules/cone.rs", &[]);
    let file = |p: &str| src().join(p);
    for needed in
        ["rules/cone.rs", "verify/mod.rs", "syntax/strict.rs", "exact/num_backend.rs", "model/polygon.rs"]
    {
        assert!(point.contains(&file(needed)), "{needed} is read for a point certificate");
    }
    for other in [
        "rules/rod.rs",
        "rules/boxes.rs",
        "exact/cos_field.rs",
        "explain/mod.rs",
        "rules/proof/mod.rs",
        "syntax/json.rs",
        "conveniences.rs",
    ] {
        assert!(!point.contains(&file(other)), "{other} is not read for a point certificate");
    }
    let field = reached("rules/field.rs", &["field"]);
    assert!(field.contains(&file("exact/cos_field.rs")) && field.contains(&file("exact/univariate.rs")));
    assert!(!field.contains(&file("rules/proof/check.rs")), "numbers do not depend on the proof checker");
}

/// Every kind of file whose kernel runs through `verify/kinds/` (a module declared there under its
/// feature) enables the internal feature `files` that builds that module, so that each kind
/// builds alone (regression: with the feature `rest` alone, `verify_rest_text_in` was missing,
/// 2026-11-28).
#[test]
fn every_kind_dispatched_by_verify_kinds_enables_the_feature_that_builds_it() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let toml = std::fs::read_to_string(root.join("Cargo.toml")).unwrap();
    let kinds = std::fs::read_to_string(src().join("verify/kinds/mod.rs")).unwrap();
    let lines: Vec<&str> = kinds.lines().collect();
    let mut checked = 0;
    for pair in lines.windows(2) {
        let Some(feature) = pair[0].strip_prefix("#[cfg(feature = \"").and_then(|f| f.strip_suffix("\")]"))
        else {
            continue;
        };
        if pair[1].starts_with("mod ") {
            assert!(
                enabled(&[feature], &toml).contains(&"files"),
                "feature {feature} does not enable `files`"
            );
            checked += 1;
        }
    }
    assert!(checked >= 6, "the modules of verify/kinds/mod.rs were not found ({checked})");
    assert!(
        std::fs::read_to_string(src().join("verify/mod.rs"))
            .unwrap()
            .contains("#[cfg(feature = \"files\")]\nmod kinds;")
    );
}
