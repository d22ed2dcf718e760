//! README.md must not lie: its first two commands are the main job and the test command, and
//! the main job really reproduces the paper's results with a report (run here through the built
//! binary).

use crate::common::{REPRODUCE_QUICK, reproduce_quick, root};

fn first_block() -> Vec<String> {
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let start = readme.find("```sh\n").expect("README starts with a sh block") + 6;
    let end = start + readme[start..].find("```").unwrap();
    readme[start..end].lines().map(str::to_string).collect()
}

#[test]
fn readme_begins_with_the_main_job_and_the_test_command() {
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let block = first_block();
    assert_eq!(block.len(), 2, "exactly two commands: {block:?}");
    // What the tool proves comes first, in a few lines, then the commands.
    let before = &readme[..readme.find("```sh").unwrap()];
    assert!(before.lines().count() <= 8, "the commands come within the first lines");
    assert!(before.contains("proves") && before.contains("complete chatter"), "{before}");
    // CI runs the README's test command verbatim.
    let ci = std::fs::read_to_string(root().join(".ci/run")).unwrap();
    assert!(ci.lines().any(|l| l.trim() == block[1]), ".ci/run must run `{}`", block[1]);
}

#[test]
fn the_main_job_of_the_readme_works() {
    let block = first_block();
    let mut ran = 0;
    for step in block[0].split("&&") {
        let (_, args) = step.split_once("cargo run --release --").expect("each step runs chatter");
        let args: Vec<&str> = args.split_whitespace().collect();
        // The shared run of the tests (one per test process) is exactly this command, in an
        // empty directory.
        assert_eq!(args, REPRODUCE_QUICK, "README's main job is the command the tests run");
        let run = reproduce_quick();
        let stdout = String::from_utf8_lossy(&run.output.stdout);
        assert!(run.output.status.success(), "`chatter {}` failed: {stdout}", args.join(" "));
        assert!(stdout.contains(" agree, ") && stdout.contains("report.html"), "{stdout}");
        ran += 1;
    }
    assert_eq!(ran, 1);
    let out = reproduce_quick().dir.join("out");
    let report = std::fs::read_to_string(out.join("report.md")).unwrap();
    assert!(report.contains("**agrees**") && report.contains("**differs**"));
    assert!(out.join("report.html").exists());
}

/// The relative links of a Markdown text: (target file, anchor).
fn links(text: &str) -> Vec<(String, Option<String>)> {
    let mut out = Vec::new();
    for (i, _) in text.match_indices("](") {
        let rest = &text[i + 2..];
        let Some(end) = rest.find(')') else { continue };
        let target = &rest[..end];
        if target.contains("://") || target.starts_with("mailto:") || target.contains(char::is_whitespace) {
            continue;
        }
        let (file, anchor) = match target.split_once('#') {
            Some((f, a)) => (f.to_string(), Some(a.to_string())),
            None => (target.to_string(), None),
        };
        out.push((file, anchor));
    }
    out
}

/// GitHub's anchor of a heading: lower case, spaces to `-`, other punctuation dropped.
fn slug(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter_map(|c| match c {
            ' ' => Some('-'),
            c if c.is_alphanumeric() || c == '-' || c == '_' => Some(c),
            _ => None,
        })
        .collect()
}

#[test]
fn every_link_of_the_readme_and_the_docs_resolves() {
    let mut pages = vec![root().join("README.md")];
    for e in std::fs::read_dir(root().join("docs")).unwrap() {
        let p = e.unwrap().path();
        if p.extension().is_some_and(|x| x == "md") {
            pages.push(p);
        }
    }
    let mut checked = 0;
    for page in &pages {
        let text = std::fs::read_to_string(page).unwrap();
        for (file, anchor) in links(&text) {
            let target = if file.is_empty() { page.clone() } else { page.parent().unwrap().join(&file) };
            assert!(
                target.exists(),
                "{}: link to {file} ({}) does not exist",
                page.display(),
                target.display()
            );
            if let Some(anchor) = anchor.filter(|_| target.extension().is_some_and(|x| x == "md")) {
                let md = std::fs::read_to_string(&target).unwrap();
                let found = md
                    .lines()
                    .filter_map(|l| l.strip_prefix('#'))
                    .any(|h| slug(h.trim_start_matches('#')) == anchor);
                assert!(found, "{}: no heading #{anchor} in {file}", page.display());
            }
            checked += 1;
        }
    }
    assert!(checked >= 40, "{checked} links");
    assert_eq!(
        slug("7.4 Conjecture 2 and the square plate: no PCC orbit, and why"),
        "74-conjecture-2-and-the-square-plate-no-pcc-orbit-and-why"
    );
}

#[test]
fn the_readme_shows_a_map_with_its_certificates_made_by_the_tool() {
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let first_screen: String = readme.lines().take(40).collect::<Vec<_>>().join("\n");
    let start = first_screen.find("![").expect("a figure on the first screen");
    let (file, _) = links(&first_screen[start..]).into_iter().next().unwrap();
    let png = std::fs::read(root().join(&file)).unwrap();
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n", "{file} is a PNG");
    let width = u32::from_be_bytes(png[16..20].try_into().unwrap());
    let height = u32::from_be_bytes(png[20..24].try_into().unwrap());
    assert!(width >= 1000 && height >= 600, "{file}: {width} x {height}");
    // The command that made it, with certificates.
    assert!(
        first_screen.contains("--certify") && first_screen.contains("chatter plot map"),
        "{first_screen}"
    );
    for link in ["docs/commands.md", "docs/findings.md", "docs/measurements.md"] {
        assert!(first_screen.contains(&format!("]({link})")), "the first screen links {link}");
    }
}

/// `#[test]` attributes (proptest's included) in the Rust sources of the three crates.
fn test_functions(dir: &std::path::Path) -> usize {
    let mut n = 0;
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            n += test_functions(&p);
        } else if p.extension().is_some_and(|x| x == "rs") {
            n += std::fs::read_to_string(&p).unwrap().lines().filter(|l| l.trim() == "#[test]").count();
        }
    }
    n
}

#[test]
fn the_readme_counts_the_tests() {
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let actual: usize = ["src", "tests", "kernel/src", "kernel/tests", "oracle/src", "oracle/tests"]
        .iter()
        .map(|d| test_functions(&root().join(d)))
        .sum();
    let said = readme.split("#[test]` functions").next().unwrap().rsplit(['(', ' ']).nth(1).unwrap();
    assert_eq!(said.parse::<usize>().ok(), Some(actual), "README says {said} `#[test]` functions");
}

/// The files and folders README.md's commands write in the clone: the word after `--out`, `-o`,
/// `--plot` or `-m venv` in its code (blocks and inline), placeholders in capitals left out.
fn readme_outputs(readme: &str) -> std::collections::BTreeSet<String> {
    let (mut fenced, mut prose, mut inside) = (Vec::new(), String::new(), false);
    for line in readme.lines() {
        if line.starts_with("```") {
            inside = !inside;
        } else if inside {
            fenced.push(line);
        } else {
            prose.push_str(line);
            prose.push('\n');
        }
    }
    let code = fenced.into_iter().chain(prose.split('`').skip(1).step_by(2));
    let mut out = std::collections::BTreeSet::new();
    for c in code {
        let words: Vec<&str> = c.split_whitespace().collect();
        for w in words.windows(2) {
            let path = w[1].trim_matches(|ch: char| ch == '"' || ch == '\'' || ch == ')');
            let placeholder = path.chars().any(|ch| ch.is_ascii_uppercase());
            if matches!(w[0], "--out" | "-o" | "--plot" | "venv") && !placeholder && !path.is_empty() {
                out.insert(path.to_string());
            }
        }
    }
    out
}

/// Issue 26 §2: `git status` stays clean after following README.md: .gitignore covers every file
/// and folder its commands create (README's map command wrote map3/ and map-n3.png unignored).
#[test]
fn gitignore_covers_what_the_readme_creates() {
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let outputs = readme_outputs(&readme);
    for needed in ["out", ".venv", "map3", "map-n3.png"] {
        assert!(outputs.contains(needed), "README's outputs, as read here, lack {needed}: {outputs:?}");
    }
    // As a file or as a folder (a pattern "/out/" matches only a folder; none exists here).
    let ignored = |path: &str| {
        let o = std::process::Command::new("git")
            .args(["check-ignore", "--no-index", "-q", path])
            .current_dir(root())
            .output()
            .expect("git");
        o.status.code() == Some(0)
    };
    for path in &outputs {
        assert!(
            ignored(path) || ignored(&format!("{path}/")),
            ".gitignore does not cover {path}, which README's commands create"
        );
    }
}

/// Issue 26 §2: the command README.md gives for its figure runs as written (with `chatter` for
/// the built binary, in an empty folder) and draws exactly the committed docs/img/map-n3.png.
#[test]
fn the_readme_figure_command_runs_as_written_and_draws_the_committed_figure() {
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap().replace('\n', " ");
    let command = readme
        .split('`')
        .find(|c| c.starts_with("chatter map --n 3") && c.contains("chatter plot map"))
        .expect("README gives the command of its figure");
    let d = tempfile::tempdir().unwrap();
    let mut made = None;
    for step in command.split("&&") {
        let words: Vec<&str> = step.split_whitespace().collect();
        assert_eq!(words[0], "chatter", "{command}");
        let o = std::process::Command::new(crate::common::bin())
            .args(&words[1..])
            .current_dir(d.path())
            .output()
            .unwrap();
        assert!(o.status.success(), "`{step}`: {}", String::from_utf8_lossy(&o.stderr));
        made = words.windows(2).find(|w| w[0] == "-o").map(|w| d.path().join(w[1])).or(made);
    }
    let made = std::fs::read(made.expect("the command writes a figure with -o")).unwrap();
    let committed = std::fs::read(root().join("docs/img/map-n3.png")).unwrap();
    assert!(made == committed, "docs/img/map-n3.png is not what README's command draws now");
}

/// README's `cargo fuzz run` lines (not run by CI: building libFuzzer compiles every dependency
/// again) name targets of fuzz/Cargo.toml and only corpus folders that exist or that the line
/// makes first (libFuzzer stops on a missing one), with the fuzzer's options after `--`.
#[test]
fn the_readme_fuzz_lines_name_real_targets_and_folders() {
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let manifest = std::fs::read_to_string(root().join("fuzz/Cargo.toml")).unwrap();
    let lines: Vec<&str> = readme.lines().filter(|l| l.contains("cargo fuzz run")).collect();
    assert!(lines.len() >= 2, "{lines:?}");
    for line in lines {
        let (head, options) = line.split_once(" -- ").unwrap_or((line, ""));
        assert!(head.starts_with("cd fuzz && "), "{line}");
        assert!(head.contains("&& RUSTC_BOOTSTRAP=1 cargo fuzz run "), "{line}");
        let made: Vec<&str> = head.split(" && ").filter_map(|c| c.strip_prefix("mkdir -p ")).collect();
        assert!(options.split_whitespace().all(|o| o.starts_with('-')), "{line}");
        let args: Vec<&str> = head.split("cargo fuzz run ").nth(1).unwrap().split_whitespace().collect();
        let target = args[0];
        assert!(manifest.contains(&format!("name = \"{target}\"")), "{line}: no target {target}");
        let (mut flags, mut folders) = (args[1..].iter(), Vec::new());
        while let Some(a) = flags.next() {
            match *a {
                "--sanitizer" => assert_eq!(flags.next(), Some(&"none"), "{line}"),
                f if f.starts_with('-') => panic!("{line}: unexpected option {f}"),
                folder => folders.push(folder),
            }
        }
        for f in folders {
            assert!(
                made.contains(&f) || root().join("fuzz").join(f).is_dir(),
                "{line}: {f} is no folder (from fuzz/)"
            );
        }
    }
    assert!(readme.contains("CI does not run these lines"), "README says who runs the fuzz lines");
}
