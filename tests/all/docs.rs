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

/// Whether the text holds a duration: a number followed by a unit of time ("3.6 ms", "1–9 s").
fn has_duration(text: &str) -> bool {
    let words: Vec<&str> = text.split_whitespace().collect();
    words.windows(2).any(|w| {
        let number = w[0].trim_start_matches(['(', '~', '≈', '*']);
        let unit = w[1].trim_end_matches(['.', ',', ';', ':', ')', '*']);
        number.starts_with(|c: char| c.is_ascii_digit())
            && number.chars().all(|c| c.is_ascii_digit() || ".,–-".contains(c))
            && ["s", "ms", "µs", "min", "minutes", "seconds", "hour", "hours"].contains(&unit)
    })
}

/// Whether the text holds a date YYYY-MM-DD.
fn has_date(text: &str) -> bool {
    text.as_bytes().windows(10).any(|w| {
        w.iter().enumerate().all(|(i, c)| if i == 4 || i == 7 { *c == b'-' } else { c.is_ascii_digit() })
    })
}

/// Issue 26 §2: a time measured on a shared machine is only meaningful with its date (and what
/// else ran): every section of docs/ that gives a duration dates it, except the section of the
/// certificate format's configured limits (defaults, not measurements).
#[test]
fn every_time_in_the_docs_is_dated() {
    let mut undated = Vec::new();
    for e in std::fs::read_dir(root().join("docs")).unwrap() {
        let p = e.unwrap().path();
        if p.extension().is_none_or(|x| x != "md") {
            continue;
        }
        let text = std::fs::read_to_string(&p).unwrap();
        let mut fenced = false;
        let prose: String = text
            .lines()
            .filter(|l| {
                fenced ^= l.starts_with("```");
                !fenced && !l.starts_with("```")
            })
            .map(|l| format!("{l}\n"))
            .collect();
        // Sections: a measurement is dated once, in its section.
        for block in prose.split("\n#") {
            let limits = block.contains("| limit | default |");
            if has_duration(block) && !has_date(block) && !limits {
                let name = p.file_name().unwrap().to_string_lossy().to_string();
                undated.push(format!("{name}: {}", &block[..block.len().min(100)]));
            }
        }
    }
    assert!(undated.is_empty(), "undated times:\n{}", undated.join("\n"));
}
