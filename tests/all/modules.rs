//! The top-level modules of src/ depend on each other one way only (issue 23 §4): the graph of
//! `crate::m` paths between them (in `use` lines, `use crate::{a, b}` groups, inline paths and
//! `super::` paths that climb to the crate root) has no cycle.

use crate::common::root;
use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// The top-level modules declared in src/lib.rs (`pub mod m;`, `mod m;`).
fn top_level_modules() -> BTreeSet<String> {
    let lib = std::fs::read_to_string(root().join("src/lib.rs")).unwrap();
    lib.lines()
        .filter_map(|l| {
            let l = l.trim().strip_prefix("pub ").unwrap_or(l.trim());
            l.strip_prefix("mod ")?.strip_suffix(';').map(str::to_string)
        })
        .collect()
}

/// The text of a file without its `//` comments (doc comments name modules in links).
fn code(text: &str) -> String {
    text.lines().map(|l| l.find("//").map_or(l, |i| &l[..i])).collect::<Vec<_>>().join("\n")
}

fn identifier(s: &str) -> &str {
    let end = s.find(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).unwrap_or(s.len());
    &s[..end]
}

/// The top-level modules that `text` (a file of module `path`, e.g. ["sweep", "summary"]) names.
fn references(text: &str, path: &[String]) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for (i, _) in text.match_indices("crate::") {
        let rest = &text[i + "crate::".len()..];
        if let Some(group) = rest.strip_prefix('{') {
            let group = &group[..group.find('}').unwrap_or(group.len())];
            // `use crate::{a::b, c}`: the first segment of each item (nested groups only go deeper).
            let mut depth = 0;
            let mut item_start = true;
            for (j, c) in group.char_indices() {
                match c {
                    '{' => depth += 1,
                    '}' => depth -= 1,
                    ',' if depth == 0 => item_start = true,
                    c if item_start && !c.is_whitespace() => {
                        out.insert(identifier(&group[j..]).to_string());
                        item_start = false;
                    }
                    _ => {}
                }
            }
        } else {
            out.insert(identifier(rest).to_string());
        }
    }
    // `super::super::m` from a file deep enough to reach the crate root.
    for (i, _) in text.match_indices("super::") {
        if i > 0 && text[..i].ends_with("::") {
            continue; // counted from the first `super::` of the chain
        }
        let mut rest = &text[i..];
        let mut up = 0;
        while let Some(r) = rest.strip_prefix("super::") {
            rest = r;
            up += 1;
        }
        if up == path.len() {
            out.insert(identifier(rest).to_string());
        }
    }
    out
}

fn walk(dir: &Path, path: Vec<String>, graph: &mut BTreeMap<String, BTreeSet<String>>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        let name = p.file_stem().unwrap().to_string_lossy().to_string();
        if p.is_dir() {
            walk(&p, [path.clone(), vec![name]].concat(), graph);
        } else if p.extension().is_some_and(|x| x == "rs") {
            let module = if name == "mod" { path.clone() } else { [path.clone(), vec![name]].concat() };
            let Some(top) = module.first().cloned() else { continue }; // lib.rs, main.rs
            let text = code(&std::fs::read_to_string(&p).unwrap());
            graph.entry(top.clone()).or_default().extend(references(&text, &module));
        }
    }
}

/// Module -> the other top-level modules it names.
fn graph() -> BTreeMap<String, BTreeSet<String>> {
    let modules = top_level_modules();
    let mut graph = BTreeMap::new();
    walk(&root().join("src"), Vec::new(), &mut graph);
    for (m, deps) in graph.iter_mut() {
        deps.retain(|d| d != m && modules.contains(d));
    }
    graph
}

/// A cycle of the graph, if there is one (depth-first search).
fn cycle(graph: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn visit(
        m: &str,
        graph: &BTreeMap<String, BTreeSet<String>>,
        stack: &mut Vec<String>,
        done: &mut BTreeSet<String>,
    ) -> Option<Vec<String>> {
        if let Some(i) = stack.iter().position(|s| s == m) {
            return Some([&stack[i..], &[m.to_string()]].concat());
        }
        if done.contains(m) {
            return None;
        }
        stack.push(m.to_string());
        for d in graph.get(m).into_iter().flatten() {
            if let Some(c) = visit(d, graph, stack, done) {
                return Some(c);
            }
        }
        stack.pop();
        done.insert(m.to_string());
        None
    }
    let mut done = BTreeSet::new();
    graph.keys().find_map(|m| visit(m, graph, &mut Vec::new(), &mut done))
}

#[test]
fn the_modules_of_src_have_no_cycle() {
    let graph = graph();
    // The parser sees the dependencies that are known to exist.
    for (from, to) in [("finder", "model"), ("exactify", "finder"), ("report", "sweep"), ("sweep", "json")] {
        assert!(graph[from].contains(to), "{from} -> {to} not found: {:?}", graph[from]);
    }
    if let Some(c) = cycle(&graph) {
        panic!("a cycle of modules in src/: {}", c.join(" -> "));
    }
}

#[test]
fn the_cycle_finder_finds_cycles() {
    let mut graph = BTreeMap::new();
    let text = "use crate::{a::X, b};\nfn f() { crate::c::g(); }\nuse super::super::d::Y;";
    let refs = references(text, &["m".into(), "n".into()]);
    assert_eq!(refs, ["a", "b", "c", "d"].map(String::from).into());
    graph.insert("m".to_string(), refs);
    graph.insert("b".to_string(), BTreeSet::from(["c".to_string()]));
    assert_eq!(cycle(&graph), None);
    graph.insert("c".to_string(), BTreeSet::from(["m".to_string()]));
    assert_eq!(cycle(&graph).unwrap().join(" -> "), "b -> c -> m -> b");
}
