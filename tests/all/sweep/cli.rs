use crate::common::{bin, q};
use chatter::simulate::Outcome;
use chatter::sweep::table::{HEADER, parse_csv};
use chatter_kernel::model::Polygon;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const SLURM: [&str; 5] = [
    "SLURM_ARRAY_TASK_ID",
    "SLURM_ARRAY_TASK_COUNT",
    "SLURM_ARRAY_TASK_MIN",
    "SLURM_ARRAY_TASK_MAX",
    "SLURM_ARRAY_TASK_STEP",
];

fn chatter(args: &[&str], dir: &Path) -> Output {
    let mut c = Command::new(bin());
    c.args(args).current_dir(dir);
    for v in SLURM {
        c.env_remove(v);
    }
    c.output().unwrap()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// Every file under `dir`, relative path -> bytes.
fn files(dir: &Path) -> BTreeMap<PathBuf, Vec<u8>> {
    fn walk(root: &Path, d: &Path, out: &mut BTreeMap<PathBuf, Vec<u8>>) {
        for e in std::fs::read_dir(d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                walk(root, &p, out);
            } else {
                out.insert(p.strip_prefix(root).unwrap().to_path_buf(), std::fs::read(&p).unwrap());
            }
        }
    }
    let mut out = BTreeMap::new();
    walk(dir, dir, &mut out);
    out
}

const GRID: [&str; 10] =
    ["map", "--n", "3", "--rho", "0:1:7", "--gamma", "0:1:6", "--certify", "--simulate", "3"];

fn map(extra: &[&str], dir: &Path) -> Output {
    let args: Vec<&str> = GRID.iter().chain(extra).copied().collect();
    let o = chatter(&args, dir);
    assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
    o
}

#[test]
fn output_is_byte_identical_across_jobs_shards_and_merges() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    map(&["--jobs", "1", "--out", "one"], p);
    map(&["--jobs", "2", "--out", "two"], p);
    let one = files(&p.join("one"));
    assert!(one.keys().any(|k| k.starts_with("certificates")), "certificates are kept");
    assert!(one.contains_key(Path::new("points.csv")) && one.contains_key(Path::new("summary.json")));
    assert_eq!(one, files(&p.join("two")), "--jobs 1 and --jobs 2 differ");

    // Three shards as separate processes running at the same time, then merged.
    let children: Vec<_> = (0..3)
        .map(|k| {
            let shard = format!("{k}/3");
            let out = format!("part{k}");
            let args: Vec<String> = GRID
                .iter()
                .map(|s| s.to_string())
                .chain(["--shard".into(), shard, "--out".into(), out])
                .collect();
            let mut c = Command::new(bin());
            c.args(&args).current_dir(p);
            for v in SLURM {
                c.env_remove(v);
            }
            c.spawn().unwrap()
        })
        .collect();
    for mut c in children {
        assert!(c.wait().unwrap().success());
    }
    assert!(p.join("part1/shard.json").exists() && !p.join("part1/summary.json").exists());
    let o = chatter(&["map", "merge", "part2", "part0", "part1", "--out", "merged"], p);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(one, files(&p.join("merged")), "merged shards differ from one run");

    // The same through a SLURM job array (--array=1-2): --shard auto.
    for id in ["1", "2"] {
        let args: Vec<&str> = GRID.iter().copied().chain(["--shard", "auto", "--out", id]).collect();
        let o = Command::new(bin())
            .args(&args)
            .current_dir(p)
            .env("SLURM_ARRAY_TASK_ID", id)
            .env("SLURM_ARRAY_TASK_MIN", "1")
            .env("SLURM_ARRAY_TASK_MAX", "2")
            .env("SLURM_ARRAY_TASK_COUNT", "2")
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        assert!(
            stdout(&o).contains(&format!("(shard {}/2)", id.parse::<u32>().unwrap() - 1)),
            "{}",
            stdout(&o)
        );
    }
    let o = chatter(&["map", "merge", "1", "2", "--out", "slurm"], p);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(one, files(&p.join("slurm")));

    // Merging refuses incomplete or mixed sets.
    let o = chatter(&["map", "merge", "part0", "part1", "--out", "bad"], p);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("shard 2/3 is missing"), "{}", stderr(&o));
    let o = chatter(&["map", "merge", "part0", "1", "part2", "--out", "bad"], p);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("different sweep"), "{}", stderr(&o));
    let o = chatter(&["map", "merge", "part0", "part0", "part1", "--out", "bad"], p);
    assert!(stderr(&o).contains("given twice"), "{}", stderr(&o));
    // Regression (2026-11-28): a shard.json naming shard K >= N made merge panic (index out of
    // bounds); it is refused, naming the folder.
    let json = std::fs::read_to_string(p.join("part1/shard.json")).unwrap();
    std::fs::write(p.join("part1/shard.json"), json.replace("\"index\": 1", "\"index\": 7")).unwrap();
    let o = chatter(&["map", "merge", "part0", "part1", "part2", "--out", "bad"], p);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("part1 is not one of the 3 shards") && !stderr(&o).contains("panicked"));
}

#[test]
fn rows_hold_the_exact_criteria_and_verified_certificates() {
    let d = tempfile::tempdir().unwrap();
    map(&["--out", "m"], d.path());
    let text = std::fs::read_to_string(d.path().join("m/points.csv")).unwrap();
    assert!(text.starts_with(HEADER));
    for col in "n,rho,kappa,gamma,cc_criterion,pcc_criterion,finder,certified,claim,refuted,sim_runs,sim_cc_evidence,sim_pcc_evidence,sim_icc_evidence,mean_impacts,sim_cc_proved,sim_icc_proved,sim_undecided,orbit".split(',') {
        assert!(HEADER.split(',').any(|h| h == col), "column {col} missing");
    }
    let rows = parse_csv(&text).unwrap();
    assert_eq!(rows.len(), 42);
    let mut certified = 0;
    for (i, r) in rows.iter().enumerate() {
        assert_eq!(r.index, i);
        let rho = q(&r.rho);
        assert_eq!(r.kappa, &rho * &rho, "kappa = rho^2 exactly");
        let body = Polygon::new(3, r.kappa.clone(), r.gamma.clone()).unwrap();
        let (cc, _, _) = chatter::spectral::criteria::cc_criterion(&body);
        assert_eq!(r.cc_criterion, cc, "row {i}");
        assert!(r.certified.is_some(), "--certify fills the column");
        assert_eq!(r.certified == Some(true), r.claim.is_some());
        assert_eq!(r.certified == Some(true), r.certificate.is_some());
        assert_eq!(r.refuted, None, "no --refute");
        let s = r.sim.as_ref().unwrap();
        assert_eq!((s.runs, s.counts.iter().sum::<u64>()), (3, 3));
        // Issue 22: the same drops run exactly; a certificate excluding PCC proves every all-down
        // drop no-ICC-no-PCC (it enters K at its first impact; issue 24: not CC, the cone gives no
        // finite time) unless a time-to-rest certificate is made there (CC at the first impact) or
        // the run, going on, enters an orbit certificate's set (CC); without an orbit certificate
        // CC is proved only where the cone's claim excludes PCC (a time-to-rest certificate).
        let proved = s.proved.expect("proofs run by default");
        assert_eq!(proved.iter().sum::<u64>(), 3, "row {i}");
        if r.claim.as_deref() == Some("CompleteChatterFromAllDown") {
            let (cone, cc) = (proved[Outcome::NoIccNoPcc.index()], proved[Outcome::Cc.index()]);
            assert_eq!(cone + cc, 3, "row {i}: {proved:?}");
        }
        if r.orbit.is_none() && proved[Outcome::Cc.index()] > 0 {
            let claim = r.claim.as_deref();
            assert_eq!(
                claim,
                Some("CompleteChatterFromAllDown"),
                "row {i}: CC proved without a certified set"
            );
        }
        if r.certified != Some(true) && r.orbit.is_none() {
            assert_eq!(proved[0], 0, "row {i}: CC proved without a certified set");
        }
        certified += r.certified.unwrap_or(false) as usize;
    }
    assert!(certified > 0);
    // The kernel accepts every certificate the map kept.
    let o = chatter(&["verify", "m/certificates"], d.path());
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    assert_eq!(stdout(&o).matches(": OK (").count(), certified);
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.path().join("m/summary.json")).unwrap()).unwrap();
    assert_eq!(summary["points"], 42);
    assert_eq!(summary["counts"]["certified"]["true"], certified);
    assert_eq!(summary["grid"]["x"]["steps"], 7);
}

#[test]
fn the_n3_band_is_a_disagreement_in_the_summary() {
    // The single point kappa = 1/8, gamma = 3/20 (README: Conjecture 1 fails for the triangle).
    let d = tempfile::tempdir().unwrap();
    let args = [
        "map",
        "--n",
        "3",
        "--kappa",
        "0.12:0.13:1",
        "--gamma",
        "0.14:0.16:1",
        "--simulate",
        "10",
        "--out",
        "band",
    ];
    let o = chatter(&args, d.path());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let rows = parse_csv(&std::fs::read_to_string(d.path().join("band/points.csv")).unwrap()).unwrap();
    assert_eq!((rows[0].kappa.clone(), rows[0].gamma.clone()), (q("1/8"), q("3/20")));
    assert!(!rows[0].cc_criterion && rows[0].finder == "no-cone");
    assert_eq!(rows[0].rho, format!("{}", (0.125f64).sqrt()), "rho of a kappa grid is a decimal");
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.path().join("band/summary.json")).unwrap()).unwrap();
    assert_eq!(s["disagreement_kinds"]["simulated-chatter-criterion-fails"]["points"], 1);
    assert_eq!(s["disagreements"][0]["kind"], "simulated-chatter-criterion-fails");
    assert!(stdout(&o).contains("disagreement simulated-chatter-criterion-fails: 1 points"));
    // Issue 22: the drops are also proved CC, by an orbit certificate made for their pattern and
    // written under orbits/, which the kernel re-checks from the file.
    assert_eq!(s["disagreement_kinds"]["proved-chatter-criterion-fails"]["points"], 1);
    assert_eq!(rows[0].sim.as_ref().unwrap().proved, Some([10, 0, 0, 0, 0, 0]));
    let orbit = rows[0].orbit.clone().expect("an orbit certificate was made");
    let o = chatter(&["verify", &format!("band/{orbit}")], d.path());
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
}

#[test]
fn the_pentagon_map_has_criteria_finder_and_simulations_but_no_certificates() {
    let d = tempfile::tempdir().unwrap();
    let args = [
        "map",
        "--n",
        "5",
        "--rho",
        "0:0.4:3",
        "--gamma",
        "0:0.3:3",
        "--certify",
        "--simulate",
        "2",
        "--out",
        "p",
    ];
    let o = chatter(&args, d.path());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stderr(&o).contains("number-field kernel"), "{}", stderr(&o));
    let rows = parse_csv(&std::fs::read_to_string(d.path().join("p/points.csv")).unwrap()).unwrap();
    assert!(rows.iter().all(|r| r.certified.is_none() && r.sim.is_some()));
    assert!(rows.iter().any(|r| r.cc_criterion) && rows.iter().any(|r| !r.cc_criterion));
    assert!(rows.iter().all(|r| (r.finder == "found") == r.cc_criterion), "finder and criterion agree here");
}

#[test]
fn refute_decides_every_point_where_no_certificate_is_made() {
    let d = tempfile::tempdir().unwrap();
    let args =
        ["map", "--n", "4", "--rho", "0:1:8", "--gamma", "0:1/5:8", "--certify", "--refute", "--out", "r"];
    let o = chatter(&args, d.path());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let rows = parse_csv(&std::fs::read_to_string(d.path().join("r/points.csv")).unwrap()).unwrap();
    let (mut certified, mut refuted) = (0, 0);
    for r in &rows {
        match (r.certified, r.refuted) {
            (Some(true), None) => certified += 1,
            (Some(false), Some(true)) => refuted += 1,
            other => panic!("row {}: certified and refuted {other:?}", r.index),
        }
        // On this grid the exact criterion decides which (no counterexample to Conjecture 1).
        assert_eq!(r.cc_criterion, r.certified == Some(true), "row {}", r.index);
        assert_eq!(r.refuted == Some(true), r.refutation.is_some());
    }
    assert!(certified > 0 && refuted > 0, "{certified} certified, {refuted} refuted");
    let summary = std::fs::read_to_string(d.path().join("r/summary.json")).unwrap();
    assert!(summary.contains("\"refuted-criterion-holds\""));
    // The kernel accepts every certificate and refutation the map kept, in one run.
    let o = chatter(&["verify", "r"], d.path());
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stdout));
    assert!(String::from_utf8_lossy(&o.stdout).contains(&format!("{} files: {} OK", rows.len(), rows.len())));
}

#[test]
fn bad_input_exits_2_with_a_message() {
    let d = tempfile::tempdir().unwrap();
    std::fs::create_dir(d.path().join("precious")).unwrap();
    std::fs::write(d.path().join("precious/notes.txt"), "keep").unwrap();
    let base = ["--rho", "0:1:3", "--gamma", "0:1:3"];
    let cases: [(&[&str], &str); 12] = [
        (&base, "--n is required"),
        (&["--n", "3", "--gamma", "0:1:3"], "--rho"),
        (&["--n", "7", "--rho", "0:1:3", "--gamma", "0:1:3"], "--n"),
        (&["--n", "3", "--rho", "1:0:3", "--gamma", "0:1:3"], "--rho"),
        (&["--n", "3", "--rho", "0:1:3", "--gamma", "0:2:3"], "--gamma"),
        (&["--n", "3", "--kappa", "-1:1:3", "--gamma", "0:1:3"], "--kappa"),
        (&["--n", "3", "--rho", "0:1:3", "--gamma", "0:1:3", "--shard", "3/3"], "--shard"),
        (&["--n", "3", "--rho", "0:1:3", "--gamma", "0:1:3", "--shard", "auto"], "SLURM_ARRAY_TASK_ID"),
        (&["--n", "3", "--rho", "0:1:3", "--gamma", "0:1:3", "--simulate", "0"], "--simulate"),
        (&["--n", "3", "--rho", "0:1:3", "--gamma", "0:1:3", "--jobs", "0"], "--jobs"),
        (&["--n", "3", "--rho", "0:1:3", "--gamma", "0:1:3", "--out", "precious"], "not overwriting"),
        (&["--n", "3", "--rho", "0:1:3", "--kappa", "0:1:3", "--gamma", "0:1:3"], "--kappa"),
    ];
    for (args, needle) in cases {
        let all: Vec<&str> = ["map"].iter().chain(args).copied().collect();
        let o = chatter(&all, d.path());
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stdout(&o));
        assert!(stderr(&o).contains(needle), "{args:?}: {}", stderr(&o));
        assert!(!stderr(&o).contains("panicked"));
    }
    assert_eq!(std::fs::read_to_string(d.path().join("precious/notes.txt")).unwrap(), "keep");
    let o = chatter(&["map", "merge", "nowhere", "--out", "x"], d.path());
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("nowhere"));
}

#[test]
fn help_documents_the_flags_and_the_axes() {
    let d = tempfile::tempdir().unwrap();
    let out = stdout(&chatter(&["map", "--help"], d.path()));
    for s in [
        "--n",
        "--rho",
        "--kappa",
        "--gamma",
        "--certify",
        "--simulate",
        "--out",
        "--jobs",
        "--shard",
        "auto",
        "cell",
        "merge",
        "byte-identical",
    ] {
        assert!(out.contains(s), "map --help lacks {s}");
    }
}

#[test]
fn shard_auto_refuses_every_task_of_an_array_with_gaps() {
    // --array=1,5,9 as SLURM reports it in each task: no task runs, each says why and writes
    // nothing (the real SLURM run of .ci/slurm/test.sh checks the same in the tasks' logs).
    let d = tempfile::tempdir().unwrap();
    for id in ["1", "5", "9"] {
        let args: Vec<&str> = GRID.iter().copied().chain(["--shard", "auto", "--out", id]).collect();
        let o = Command::new(bin())
            .args(&args)
            .current_dir(d.path())
            .env("SLURM_ARRAY_TASK_ID", id)
            .env("SLURM_ARRAY_TASK_MIN", "1")
            .env("SLURM_ARRAY_TASK_MAX", "9")
            .env("SLURM_ARRAY_TASK_STEP", "1")
            .env("SLURM_ARRAY_TASK_COUNT", "3")
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(2), "task {id}: {}", stderr(&o));
        let e = stderr(&o);
        assert!(
            e.contains(
                "--shard auto: SLURM_ARRAY_TASK_COUNT=3 but SLURM_ARRAY_TASK_MIN=1 to SLURM_ARRAY_TASK_MAX=9"
            ),
            "task {id}: {e}"
        );
        assert!(!d.path().join(id).exists(), "task {id} wrote its folder");
    }
}
