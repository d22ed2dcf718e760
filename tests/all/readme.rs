//! README.md must not lie: its first two commands are the main job and the test command, and
//! the main job really reproduces the paper's results with a report (run here through the built
//! binary).

use crate::common::{bin, root};
use std::process::Command;

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
    assert!(readme.find("```sh").unwrap() < 40, "the commands come first");
    // CI runs the README's test command verbatim.
    let ci = std::fs::read_to_string(root().join(".ci/run")).unwrap();
    assert!(ci.lines().any(|l| l.trim() == block[1]), ".ci/run must run `{}`", block[1]);
}

#[test]
fn the_main_job_of_the_readme_works() {
    let dir = tempfile::tempdir().unwrap();
    let block = first_block();
    let mut ran = 0;
    for step in block[0].split("&&") {
        let (_, args) = step.split_once("cargo run --release --").expect("each step runs chatter");
        let args: Vec<&str> = args.split_whitespace().collect();
        let out = Command::new(bin()).args(&args).current_dir(dir.path()).output().unwrap();
        let stdout = String::from_utf8_lossy(&out.stdout);
        assert!(out.status.success(), "`chatter {}` failed: {stdout}", args.join(" "));
        assert!(stdout.contains(" agree, ") && stdout.contains("report.html"), "{stdout}");
        ran += 1;
    }
    assert_eq!(ran, 1);
    let report = std::fs::read_to_string(dir.path().join("out/report.md")).unwrap();
    assert!(report.contains("**agrees**") && report.contains("**differs**"));
    assert!(dir.path().join("out/report.html").exists());
}
