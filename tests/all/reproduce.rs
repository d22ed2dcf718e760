//! `chatter reproduce --quick`: the report is written, cites commands that really show its
//! evidence, and renders in a real headless browser (Debian's chromium; CI installs it).

use crate::common::{bin, copy_dir, files_of, reproduce_quick};
use std::path::Path;
use std::process::{Command, Output};

fn chatter(args: &[&str], dir: &Path) -> Output {
    Command::new(bin()).args(args).current_dir(dir).output().unwrap()
}

/// The commands a report cites ("Shown by:" lines of report.md).
fn cited(md: &str) -> Vec<String> {
    md.lines()
        .filter_map(|l| l.strip_prefix("- Shown by: `"))
        .map(|l| l.trim_end_matches('`').to_string())
        .collect()
}

fn chromium() -> Option<&'static str> {
    ["/usr/bin/chromium", "/usr/bin/chromium-browser"].into_iter().find(|p| Path::new(p).exists())
}

fn browser(profile: &Path, args: &[&str]) -> Output {
    Command::new(chromium().unwrap())
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            &format!("--user-data-dir={}", profile.display()),
        ])
        .args(args)
        .output()
        .unwrap()
}

#[test]
fn reproduce_quick_writes_a_report_that_a_browser_renders() {
    let run = reproduce_quick();
    let o = &run.output;
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let out = run.dir.join("out");
    let md = std::fs::read_to_string(out.join("report.md")).unwrap();
    for s in [
        "flat triangle plate",
        "The PCC Lemma's condition for n ≥ 4 — **differs**",
        "The n = 3 band above the threshold where drops still chatter — **differs**",
        "The n = 3 band across κ: orbit certificates and the S₁²S₂² criterion — **differs**",
        "refute Conjecture 1 (i) ⇒ (iii) for the triangle at κ ∈ {1/20, 1/8, 3/10}",
        "the PCC criterion (Conjecture 2) holds (exact)",
        "other than that of the eigenvalue 1 have u₀u₁ > 0 (decided exactly in Q(√D))",
        "The falling rod (Goyal's condition) — **agrees**",
        "The pentagon's cone (figure “sajatertekek” (f)) — **agrees**",
        "fit κ = 1/4",
        "Time to rest: complete chatter in finite time, with a proved bound — **agrees**",
    ] {
        assert!(md.contains(s), "report.md lacks {s:?}");
    }
    for dir in [
        "maps/n3/points.csv",
        "maps/n4/summary.json",
        "maps/n5/points.csv",
        "proofs/square.ron",
        "figures/map-n5.png",
    ] {
        assert!(out.join(dir).exists(), "{dir} missing");
    }
    // The band item refutes Conjecture 1 (i) => (iii) with the orbit certificate it wrote.
    crate::orbit_classify::check_reproduce_output(&out);
    let figures = md.matches("![").count();
    assert!(figures >= 9, "{figures} figures");
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    assert_eq!(html.matches("<figure").count(), figures, "every figure is embedded in the HTML");

    let Some(_) = chromium() else {
        assert!(std::env::var_os("CI").is_none(), "CI must install chromium (.ci/run does)");
        eprintln!(
            "\n*** SKIPPED the browser check of report.html: chromium is not installed (apt-get install -y chromium) ***\n"
        );
        return;
    };
    let profile = tempfile::tempdir().unwrap();
    let d = tempfile::tempdir().unwrap();
    let url = format!("file://{}", out.join("report.html").display());
    let dom = browser(profile.path(), &["--dump-dom", &url]);
    let dom = String::from_utf8_lossy(&dom.stdout);
    assert!(
        dom.contains("the paper's results reproduced"),
        "the page did not load: {}",
        &dom[..dom.len().min(300)]
    );
    assert_eq!(dom.matches("<figure").count(), figures);
    assert!(dom.matches("<svg").count() >= figures, "inline SVG figures in the DOM");
    assert!(dom.contains("class=\"verdict differs\"") && dom.contains("class=\"verdict agrees\""));
    let shot = d.path().join("shot.png");
    let o = browser(
        profile.path(),
        &["--window-size=1200,3000", &format!("--screenshot={}", shot.display()), &url],
    );
    assert!(shot.exists(), "no screenshot: {}", String::from_utf8_lossy(&o.stderr));
    assert!(std::fs::metadata(&shot).unwrap().len() > 50_000, "a blank page?");
}

/// The folder of a cited `chatter map` command (`words`) run as shard `k` of `of`: its rows are
/// the report's map's rows of that shard, and its certificates are the report's, byte for byte.
/// The folder is then replaced by a copy of the report's map, which the cited plot commands draw.
fn shard_is_the_reports_map(out: &Path, words: &[&str], k: usize, of: usize) {
    let after = |flag: &str| words.iter().position(|w| *w == flag).map(|i| words[i + 1]).unwrap();
    let (dir, report) = (out.join(after("--out")), out.join(format!("maps/n{}", after("--n"))));
    let lines = |d: &Path| std::fs::read_to_string(d.join("points.csv")).unwrap();
    let (shard, whole) = (lines(&dir), lines(&report));
    let whole: Vec<&str> = whole.lines().collect();
    let expected: Vec<&str> = whole[1..].iter().skip(k).step_by(of).copied().collect();
    let rows: Vec<&str> = shard.lines().skip(1).collect();
    assert_eq!(shard.lines().next(), Some(whole[0]), "{}: the header", dir.display());
    assert!(!rows.is_empty());
    assert_eq!(rows, expected, "`{}` as shard {k}/{of} vs {}", words.join(" "), report.display());
    for (rel, bytes) in files_of(&dir) {
        if !matches!(rel.to_str(), Some("points.csv" | "shard.json")) {
            let theirs = std::fs::read(report.join(&rel)).unwrap_or_default();
            assert!(bytes == theirs, "{}: not the report's file", dir.join(&rel).display());
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
    copy_dir(&report, &dir);
}

#[test]
fn every_cited_command_runs_from_the_folder_the_report_names() {
    let run = reproduce_quick();
    assert_eq!(run.output.status.code(), Some(0));
    // The commands write files into the folder: they run in a copy of it.
    let d = tempfile::tempdir().unwrap();
    copy_dir(&run.dir.join("out"), &d.path().join("out"));
    let md = std::fs::read_to_string(d.path().join("out/report.md")).unwrap();
    // The report names the folder its commands run from: its own.
    let named = "Every “Shown by” command runs as written from this report's folder, `out` (`cd out` first)";
    assert!(md.contains(named), "report.md does not say where its commands run");
    let html = std::fs::read_to_string(d.path().join("out/report.html")).unwrap();
    assert!(html.contains("runs as written from this report's folder, <code>out</code>"));
    let out = d.path().join("out");
    let commands = cited(&md);
    assert!(commands.len() >= 15);
    for needed in [
        "chatter verify certificates/",
        "chatter check-proof proofs/square.ron",
        "chatter bodies --plate 3 --only",
    ] {
        assert!(commands.iter().any(|c| c.contains(needed)), "the report no longer cites {needed}");
    }
    let mut seen = std::collections::BTreeSet::new();
    for c in &commands {
        for step in c.split("&&") {
            if !seen.insert(step.trim().to_string()) {
                continue;
            }
            let words: Vec<&str> = step.split_whitespace().collect();
            assert_eq!(words[0], "chatter", "{c}");
            // A map command runs on one shard of its grid (every eighth point): reproduce makes
            // the whole map from the command as written (`map_cmd::request_of`), and the shard's
            // rows and files must be the report map's.
            let map = words[1] == "map";
            let args = if map { [&words[1..], &["--shard", "3/8"]].concat() } else { words[1..].to_vec() };
            let o = chatter(&args, &out);
            assert_eq!(
                o.status.code(),
                Some(0),
                "`{step}` from out/: {}",
                String::from_utf8_lossy(&o.stderr)
            );
            if map {
                shard_is_the_reports_map(&out, &words, 3, 8);
            }
            if step.starts_with("chatter bodies --plate 3") {
                let text = String::from_utf8_lossy(&o.stdout);
                assert!(!text.contains("cube"), "`{step}` prints the whole catalogue: {text}");
            }
        }
    }
    for n in [3, 4, 5] {
        assert!(out.join(format!("map{n}/summary.json")).exists(), "the map n = {n} is not cited");
    }
    // README and the report cite this command for the n = 3 band: it shows the cycle and the
    // contraction per impact (classify shows neither).
    let band = "chatter simulate --n 3 --kappa 1/8 --gamma 0.15 --plot band.png";
    assert!(commands.iter().any(|c| c == band));
    let o = chatter(&band.split_whitespace().skip(1).collect::<Vec<_>>(), &out);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("cycles 2,1,0,1") && text.contains("ratio 0.86"), "{text}");
}
