//! The documents must not lie about the code: the trusted crate's line counts in
//! docs/kernel-soundness.md are the real ones.

use crate::common::root;
use std::collections::BTreeMap;

/// Non-blank, non-comment lines, as `grep -vcE '^\s*(//|$)'` counts them.
fn code_lines(text: &str) -> usize {
    text.lines().filter(|l| !(l.trim().is_empty() || l.trim_start().starts_with("//"))).count()
}

fn kernel_files(dir: &std::path::Path, out: &mut BTreeMap<String, usize>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            kernel_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            let rel = p.strip_prefix(root()).unwrap().to_string_lossy().replace('\\', "/");
            out.insert(rel, code_lines(&std::fs::read_to_string(&p).unwrap()));
        }
    }
}

#[test]
fn kernel_line_counts_in_the_soundness_document_are_current() {
    let mut actual = BTreeMap::new();
    kernel_files(&root().join("kernel/src"), &mut actual);
    let doc = std::fs::read_to_string(root().join("docs/kernel-soundness.md")).unwrap();
    let mut documented = BTreeMap::new();
    let mut subtotals: BTreeMap<String, usize> = BTreeMap::new();
    let mut total = None;
    for line in doc.lines().filter(|l| l.starts_with("| ")) {
        let cells: Vec<&str> = line.trim_matches('|').split('|').map(str::trim).collect();
        let [part, file, n] = cells[..] else { continue };
        let Ok(n) = n.trim_matches('*').replace(',', "").parse::<usize>() else { continue };
        if let Some(f) = file.strip_prefix('`').and_then(|f| f.strip_suffix('`')) {
            documented.insert(f.to_string(), n);
            *subtotals.entry(part.to_string()).or_default() += n;
        } else if part == "**all of chatter-kernel**" {
            total = Some(n);
        } else {
            let name = part.trim_matches('*').to_string();
            assert_eq!(subtotals.get(&name), Some(&n), "subtotal of {name}");
        }
    }
    assert_eq!(documented, actual, "the table of docs/kernel-soundness.md §4 (file -> lines)");
    assert_eq!(total, Some(actual.values().sum()), "the total of docs/kernel-soundness.md §4");
}
