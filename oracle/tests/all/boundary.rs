//! The oracle shares no code with the kernel or the tool: its library's dependencies are exact
//! arithmetic and serde_json only (the compiler then forbids any use of the kernel), the kernel
//! and the tool appear only as dev-dependencies of the differential tests, and the crate is not
//! published. Its deciding code has no floating point (a lint), no unsafe code (forbidden).

fn manifest() -> String {
    std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/Cargo.toml")).expect("Cargo.toml")
}

/// The names of the dependencies in a `[section]` of the manifest.
fn section(name: &str) -> Vec<String> {
    let text = manifest();
    let start = text.find(&format!("[{name}]\n")).unwrap_or_else(|| panic!("no [{name}]")) + name.len() + 3;
    text[start..]
        .lines()
        .take_while(|l| !l.starts_with('['))
        .filter(|l| !l.trim().is_empty() && !l.starts_with('#'))
        .map(|l| l.split('=').next().expect("a key").trim().to_string())
        .collect()
}

#[test]
fn the_library_depends_on_arithmetic_and_serde_json_only() {
    assert_eq!(
        section("dependencies"),
        ["num-bigint", "num-integer", "num-rational", "num-traits", "serde_json"]
    );
    let dev = section("dev-dependencies");
    assert!(dev.contains(&"chatter-kernel".to_string()) && dev.contains(&"chatter".to_string()), "{dev:?}");
    assert!(manifest().contains("publish = false"));
}

#[test]
fn the_library_source_names_neither_the_kernel_nor_the_tool_nor_floats() {
    let mut stack = vec![std::path::PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/src"))];
    let mut files = 0;
    while let Some(p) = stack.pop() {
        if p.is_dir() {
            stack.extend(std::fs::read_dir(&p).unwrap().map(|e| e.unwrap().path()));
            continue;
        }
        let text = std::fs::read_to_string(&p).unwrap();
        files += 1;
        for word in ["chatter_kernel", "chatter::", "f64", "f32", "unsafe "] {
            assert!(!text.contains(word), "{} mentions {word}", p.display());
        }
    }
    assert!(files >= 20, "{files} source files");
    let lib = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/src/lib.rs")).unwrap();
    for attr in ["#![forbid(unsafe_code)]", "#![deny(missing_docs)]", "#![deny(clippy::float_arithmetic)]"] {
        assert!(lib.contains(attr), "{attr}");
    }
}
