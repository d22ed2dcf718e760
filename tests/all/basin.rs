//! Basin certificates (issue 27, docs/basin-certificates.md), from the tool's side: drops drawn
//! inside the leaves of the corpus certificate, simulated with the exact engine, have the
//! impacts the leaf states (and the ICC leaves end ICC, proved); `chatter basin` writes a file
//! that `chatter verify` accepts with the shares it printed.

use crate::common::{bin, files_of, root};
use chatter::exact::{Q, QExt};
use chatter::simulate::{Model, Options, Outcome, Shape, SplitMix64, Start, simulate_exact};
use chatter_kernel::rules::basin::leaf_box;
use chatter_kernel::syntax::basin::{BasinCertificate, Impact, LeafVerdict, Then};
use chatter_kernel::syntax::orbit::OrbitBody;
use chatter_kernel::syntax::{Encoding, read};

fn corpus() -> BasinCertificate {
    let path = root().join("certificates/valid/basin-n3-kappa1_8-gamma3_20.ron");
    read(&std::fs::read_to_string(path).unwrap(), Encoding::Ron).unwrap()
}

fn f(x: &malachite::rational::Rational) -> f64 {
    Q::from_rational(x.clone()).to_f64()
}

/// The absolute contacts of a prefix: `first`, then each step j places on from the last (mod n).
fn contacts(first: u64, steps: &[u64], n: u64) -> Vec<u8> {
    let mut out = vec![first as u8];
    for &j in steps {
        out.push(((out[out.len() - 1] as u64 + j) % n) as u8);
    }
    out
}

type Rat = malachite::rational::Rational;

/// The paths of a prefix or a tree as absolute contacts, each with its end (`None`: `Cc`/`Icc`
/// leaves, whose end the caller knows).
fn paths(v: &LeafVerdict, n: u64) -> Vec<(Vec<u8>, Option<Then>)> {
    fn walk(next: &[Impact], n: u64, above: &[u8], out: &mut Vec<(Vec<u8>, Option<Then>)>) {
        for imp in next {
            let c = match above.last() {
                None => imp.contact as u8,
                Some(&last) => ((last as u64 + imp.contact) % n) as u8,
            };
            let here = [above, &[c]].concat();
            match &imp.then {
                Then::Impacts { next } => walk(next, n, &here, out),
                end => out.push((here, Some(end.clone()))),
            }
        }
    }
    match v {
        LeafVerdict::Cc { first, steps, .. } | LeafVerdict::Icc { first, steps, .. } => {
            vec![(contacts(*first, steps, n), None)]
        }
        LeafVerdict::Rest { first, steps, node } => {
            vec![(contacts(*first, steps, n), Some(Then::Rest { node: *node }))]
        }
        LeafVerdict::Tree { next } => {
            let mut out = Vec::new();
            walk(next, n, &[], &mut out);
            out
        }
        LeafVerdict::Undecided => Vec::new(),
    }
}

/// The one path of `paths` that the impact sequence `run` begins with (a tree's paths are
/// prefix-free, so there is at most one).
fn taken<'a>(paths: &'a [(Vec<u8>, Option<Then>)], run: &[u8]) -> Option<&'a (Vec<u8>, Option<Then>)> {
    let mut found = paths.iter().filter(|(p, _)| run.starts_with(p));
    let first = found.next();
    assert!(found.next().is_none(), "two paths of a tree begin the same run");
    first
}

/// A drop drawn in the middle half of the leaf [l, h] (so that the `f64` change of coordinates,
/// exact to ~1e-16, stays inside the leaf): its paper coordinates, its `f64` start and that start
/// read exactly.
fn drop_in(
    model: &Model,
    (l, h): (&[Rat; 5], &[Rat; 5]),
    rng: &mut SplitMix64,
) -> ([f64; 5], Start<f64>, Start<Q>) {
    let y: [f64; 5] = std::array::from_fn(|k| {
        let (a, b) = (f(&l[k]), f(&h[k]));
        a + (b - a) * (0.25 + 0.5 * rng.open01())
    });
    let fs = &model.float;
    let start = Start { q: fs.from_paper(&[y[2], y[3], y[4]]), p: fs.from_paper(&[y[0], y[1], -1.0]) };
    let exact = Start {
        q: start.q.map(|x| Q::from_f64_exact(x).unwrap()),
        p: start.p.map(|x| Q::from_f64_exact(x).unwrap()),
    };
    (y, start, exact)
}

#[test]
fn exact_simulations_of_drops_inside_decided_leaves_follow_their_certified_impacts() {
    let cert = corpus();
    let OrbitBody::RegularPolygon { n, kappa, gamma } = &cert.body;
    let model = Model::new(Shape::Polygon(*n), kappa.parse().unwrap(), gamma.parse().unwrap()).unwrap();
    let num = |s: &String| chatter_kernel::exact::parse_canonical(s, Default::default()).unwrap();
    let lo: [malachite::rational::Rational; 5] = std::array::from_fn(|k| num(&cert.drops.lo[k]));
    let hi: [malachite::rational::Rational; 5] = std::array::from_fn(|k| num(&cert.drops.hi[k]));
    let mut rng = SplitMix64::new(27);
    let mut checked = [0usize; 2];
    for leaf in cert.leaves.iter().filter(|l| l.verdict != LeafVerdict::Undecided).take(6) {
        let (LeafVerdict::Cc { first, steps, .. } | LeafVerdict::Icc { first, steps, .. }) = &leaf.verdict
        else {
            continue;
        };
        let cc = matches!(leaf.verdict, LeafVerdict::Cc { .. });
        let (l, h) = leaf_box(&lo, &hi, &leaf.path);
        let expected = contacts(*first, steps, *n);
        for _ in 0..2 {
            let (_, _, exact) = drop_in(&model, (&l, &h), &mut rng);
            let run = simulate_exact(&model, &exact, &Options::new(expected.len() + 4));
            assert!(run.sequence.len() >= expected.len() || !cc, "{}: {:?}", leaf.path, run.outcome);
            let m = expected.len().min(run.sequence.len());
            assert_eq!(run.sequence[..m], expected[..m], "leaf {}", leaf.path);
            if !cc {
                assert_eq!((run.outcome, run.proved), (Outcome::Icc, true), "leaf {}", leaf.path);
            }
            checked[usize::from(!cc)] += 1;
        }
    }
    assert!(checked[0] + checked[1] >= 2, "{checked:?}");
}

#[test]
fn chatter_basin_writes_a_certificate_that_verify_accepts_with_the_same_shares() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("b.ron");
    let o = std::process::Command::new(bin())
        .args(["basin", "--n", "3", "--kappa", "1/8", "--gamma", "3/20", "--pattern", "2,2,1,1"])
        .args(["--box", "1/20,1/20,1/20,1/20,21/20:50001/1000000,50001/1000000,50001/1000000,50001/1000000,1050001/1000000"])
        .args(["--depth", "2", "-o", out.to_str().unwrap()])
        .output()
        .unwrap();
    let said = String::from_utf8_lossy(&o.stdout).to_string();
    assert_eq!(o.status.code(), Some(0), "{said}{}", String::from_utf8_lossy(&o.stderr));
    assert!(said.contains("cc_share 1,"), "{said}");
    let v =
        std::process::Command::new(bin()).args(["verify", "--json", out.to_str().unwrap()]).output().unwrap();
    let json: serde_json::Value = serde_json::from_slice(&v.stdout).unwrap();
    let file = &json["files"][0];
    assert_eq!(file["cc_share"], "1", "{json}");
    assert_eq!(
        (file["icc_share"].as_str(), file["undecided_share"].as_str()),
        (Some("0"), Some("0")),
        "{json}"
    );
}

/// The colour of the PNG at the point (x, y) of the slice `fig` (drawn at `PNG_SCALE`).
fn colour_at(png: &std::path::Path, fig: &chatter::plot::basin::BasinFigure, x: f64, y: f64) -> [u8; 3] {
    let map = resvg::tiny_skia::Pixmap::load_png(png).unwrap();
    let (u, v) = fig.pixel(x, y).unwrap();
    let s = chatter::plot::PNG_SCALE;
    let p = map.pixel((u as f32 * s) as u32, (v as f32 * s) as u32).unwrap();
    [p.red(), p.green(), p.blue()]
}

/// Draws a slice with `chatter plot basin` along `axes` and builds the same figure in the
/// library (for its pixel coordinates).
fn slice(file: &str, axes: &str, at: &[&str], out: &std::path::Path) -> chatter::plot::basin::BasinFigure {
    use chatter::exact::parse_user_number;
    use chatter::plot::basin::{BasinFigure, axis_index};
    let path = root().join(file);
    let mut args =
        vec!["plot".to_string(), "basin".into(), path.to_str().unwrap().into(), "--axes".into(), axes.into()];
    for a in at {
        args.extend(["--at".to_string(), a.to_string()]);
    }
    args.extend(["-o".to_string(), out.to_str().unwrap().into()]);
    let o = std::process::Command::new(bin()).args(&args).output().unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let cert: BasinCertificate = read(&std::fs::read_to_string(&path).unwrap(), Encoding::Ron).unwrap();
    let verdict =
        chatter_kernel::verify::verify_basin(&cert, Default::default(), &[chatter_kernel::verify::MALACHITE]);
    let chatter_kernel::verify::Verdict::Accepted(report) = verdict else { panic!("{verdict:?}") };
    let mut fixed: [Option<Q>; 5] = Default::default();
    for a in at {
        let (name, value) = a.split_once('=').unwrap();
        fixed[axis_index(name).unwrap()] = Some(parse_user_number(value).unwrap());
    }
    let axes: Vec<usize> = axes.split(',').map(|a| axis_index(a).unwrap()).collect();
    BasinFigure::new(&cert, &report, [axes[0], axes[1]], &fixed).unwrap()
}

#[test]
fn plot_basin_draws_each_leaf_of_the_slice_where_it_lies_in_its_verdicts_colour() {
    use chatter::plot::basin::ICC;
    use chatter::plot::cover::UNDECIDED;
    use chatter::plot::map::COMPLETE;
    let rgb = |c: plotters::style::RGBColor| [c.0, c.1, c.2];
    let d = tempfile::tempdir().unwrap();
    let icc = "certificates/valid/basin-icc-n3-kappa1_8-gamma1_2.ron";
    // Its leaves split (omega_x, omega_y) only: 0 (omega_x in [0.049, 0.05]), 13 (both upper
    // halves), 120 (omega_x in [0.05, 0.0505], omega_y lower), 1212 (undecided: omega_x in
    // [0.0505, 0.051], omega_y in [0.049, 0.0495]) and 1213 (omega_y in [0.0495, 0.05]).
    let a = d.path().join("a.png");
    let fig = slice(icc, "omega_x,omega_y", &[], &a);
    assert_eq!(colour_at(&a, &fig, 0.0495, 0.05), rgb(ICC), "leaf 0");
    assert_eq!(colour_at(&a, &fig, 0.0505, 0.0505), rgb(ICC), "leaf 13");
    assert_eq!(colour_at(&a, &fig, 0.05025, 0.0495), rgb(ICC), "leaf 120");
    assert_eq!(colour_at(&a, &fig, 0.05075, 0.04925), rgb(UNDECIDED), "leaf 1212");
    assert_eq!(colour_at(&a, &fig, 0.05075, 0.04975), rgb(ICC), "leaf 1213");
    // Outside the box (the chart's margin) nothing is drawn.
    assert_eq!(colour_at(&a, &fig, 0.0488, 0.05), [255, 255, 255]);
    // Across (omega_x, phi_x), omega_y fixed: in leaf 1212's range, then in 1213's, then on
    // their shared face, where the decided leaf is drawn over the undecided one.
    for (omega_y, expected) in [("0.04925", UNDECIDED), ("0.04975", ICC), ("0.0495", ICC)] {
        let b = d.path().join(format!("b{omega_y}.png"));
        let fig = slice(icc, "omega_x,phi_x", &[&format!("omega_y={omega_y}")], &b);
        assert_eq!(colour_at(&b, &fig, 0.05075, 0.0502), rgb(expected), "omega_y = {omega_y}");
        assert_eq!(colour_at(&b, &fig, 0.0495, 0.0495), rgb(ICC), "leaf 0 at omega_y = {omega_y}");
    }
    // The legend lists only what is drawn; the title gives the kernel's exact shares.
    let svg = d.path().join("b.svg");
    slice(icc, "omega_x,phi_x", &["omega_y=0.04975"], &svg);
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.contains("κ = 1/8") && text.contains("γ = 1/2") && text.contains("ICC 15/16"), "title");
    assert!(
        text.contains("proved ICC") && !text.contains("undecided: no verdict") && !text.contains("proved CC")
    );
    // A certificate with CC leaves: 0 (omega_x in [0.049, 0.05]), 10 ([0.05, 0.0505]), 11
    // undecided ([0.0505, 0.051]).
    let c = d.path().join("c.png");
    let fig = slice("certificates/valid/basin-n3-kappa1_8-gamma3_20.ron", "omega_x,omega_y", &[], &c);
    assert_eq!(colour_at(&c, &fig, 0.0495, 0.0495), rgb(COMPLETE), "leaf 0");
    assert_eq!(colour_at(&c, &fig, 0.05025, 0.0505), rgb(COMPLETE), "leaf 10");
    assert_eq!(colour_at(&c, &fig, 0.05075, 0.0495), rgb(UNDECIDED), "leaf 11");
}

#[test]
fn plot_basin_refuses_a_file_the_kernel_rejects() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("x.png");
    let bad = root().join("certificates/invalid/basin-first-out-of-range.ron");
    let o = std::process::Command::new(bin())
        .args(["plot", "basin", bad.to_str().unwrap(), "-o", out.to_str().unwrap()])
        .output()
        .unwrap();
    let said = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{said}");
    assert!(said.contains("REJECTED") && said.contains("basin-out-of-range"), "{said}");
    assert!(!out.exists());
}

#[test]
fn basin_map_on_a_2x2_grid_writes_the_kernels_shares_of_each_point_and_its_figure() {
    let d = tempfile::tempdir().unwrap();
    let dir = d.path().join("bmap");
    // Points (kappa, gamma) = (1/8, 3/20) (the triangle's band point), (1/8, 9/20) (far above the
    // CC threshold), (3/8, 3/20) and (3/8, 9/20); the default tiny box around the paper's centre.
    let map = ["basin-map", "--n", "3", "--kappa", "0:0.5:2", "--gamma", "0:0.6:2", "--depth", "2"];
    let run = |dir: &std::path::Path, more: &[&str], env: &[(&str, &str)]| {
        let o = std::process::Command::new(bin())
            .args(map)
            .args(more)
            .args(["--out", dir.to_str().unwrap()])
            .envs(env.iter().copied())
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    };
    run(&dir, &["--jobs", "2"], &[]);
    let csv = std::fs::read_to_string(dir.join("points.csv")).unwrap();
    let rows: Vec<Vec<&str>> = csv.lines().skip(1).map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 4, "{csv}");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    assert!(summary["share_of"].as_str().unwrap().contains("box of drops"));
    // The summary is a typed report: it validates against its committed schema (docs/schema/).
    assert_eq!(crate::schema::validate(&summary), "chatter.basin-map/1");
    for (i, row) in rows.iter().enumerate() {
        // The CSV's shares are the kernel's on the kept certificate, and sum to 1.
        let cert = dir.join(format!("certificates/point-{i}.ron"));
        let v = std::process::Command::new(bin())
            .args(["verify", "--json", cert.to_str().unwrap()])
            .output()
            .unwrap();
        let json: serde_json::Value = serde_json::from_slice(&v.stdout).unwrap();
        let file = &json["files"][0];
        for (col, key) in [(4, "cc_share"), (5, "icc_share"), (6, "undecided_share")] {
            assert_eq!(file[key], row[col], "point {i} {key}");
            assert_eq!(summary["points"][i][key], row[col], "point {i} {key}");
        }
        let sum = (4..7).map(|c| row[c].parse::<Q>().unwrap()).fold(Q::int(0), |s, x| &s + &x);
        assert_eq!(sum, Q::int(1), "{row:?}");
    }
    // The band point: the whole box is proved CC (as by `chatter basin` above).
    assert_eq!((rows[0][4], rows[0][10]), ("1", "2 1 1 2"), "{:?}", rows[0]);
    // At kappa = 3/8 both gammas are far above the CC threshold: drops are proved ICC there.
    for i in [2, 3] {
        assert!(rows[i][5].parse::<Q>().unwrap() >= Q::new(1, 2), "{:?}", rows[i]);
        assert_eq!(rows[i][4], "0");
    }
    // Deterministic across threads and shards: two shards on one thread each (the second as task
    // 1 of a SLURM array 0-1), merged, are the files of the single run.
    let shards = [d.path().join("shard0"), d.path().join("shard1")];
    run(&shards[0], &["--jobs", "1", "--shard", "0/2"], &[]);
    let slurm =
        [("SLURM_ARRAY_TASK_ID", "1"), ("SLURM_ARRAY_TASK_COUNT", "2"), ("SLURM_ARRAY_TASK_MIN", "0")];
    run(&shards[1], &["--jobs", "1", "--shard", "auto"], &slurm);
    assert!(shards[1].join("shard.json").exists() && !shards[1].join("summary.json").exists());
    assert_eq!(std::fs::read_to_string(shards[1].join("points.csv")).unwrap().lines().count(), 3);
    let again = d.path().join("again");
    let merge = |dirs: &[&std::path::Path], out: &std::path::Path| {
        std::process::Command::new(bin())
            .args(["basin-map", "merge"])
            .args(dirs)
            .arg("-o")
            .arg(out)
            .output()
            .unwrap()
    };
    let o = merge(&[&shards[1], &shards[0]], &again);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    // Merge runs no kernel: its line says whose shares these are and how to re-check them.
    assert!(String::from_utf8_lossy(&o.stdout).contains("not checked again: `chatter verify"));
    assert_eq!(files_of(&dir), files_of(&again), "the merged shards are not the single run's files");
    // What merge refuses (exit 2, nothing merged): a missing shard, a shard twice, a shard of
    // another map, a shard.json that is not one.
    let refused = |dirs: &[&std::path::Path], says: &str| {
        let o = merge(dirs, &d.path().join("refused"));
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert!(err.contains(says), "{err}");
    };
    refused(&[&shards[0]], "shard 1/2 is missing");
    refused(&[&shards[0], &shards[0]], "shard 0/2 given twice");
    let json = std::fs::read_to_string(shards[1].join("shard.json")).unwrap();
    let other = d.path().join("other");
    crate::common::copy_dir(&shards[1], &other);
    std::fs::write(other.join("shard.json"), json.replace("\"depth\": 2", "\"depth\": 3")).unwrap();
    refused(&[&shards[0], &other], "belongs to a different basin map");
    std::fs::write(other.join("shard.json"), json.replace("\"index\": 1", "\"index\": 7")).unwrap();
    refused(&[&shards[0], &other], "is not one of the 2 shards");
    // Rows or certificates that are not the shard's: a row edited, a certificate missing.
    std::fs::write(other.join("shard.json"), &json).unwrap();
    let csv = std::fs::read_to_string(other.join("points.csv")).unwrap();
    let edited = csv.replacen(",1,", ",2,", 1);
    assert_ne!(edited, csv);
    std::fs::write(other.join("points.csv"), edited).unwrap();
    refused(&[&shards[0], &other], "are not its certificate's");
    std::fs::write(other.join("points.csv"), &csv).unwrap();
    std::fs::remove_file(other.join("certificates/point-1.ron")).unwrap();
    refused(&[&shards[0], &other], "point-1.ron");
    // Refused before any work (exit 2): a shard out of range, options before `merge`, and an
    // output folder that holds other files (they are kept).
    let precious = d.path().join("precious");
    std::fs::create_dir(&precious).unwrap();
    std::fs::write(precious.join("notes.txt"), "keep").unwrap();
    for (args, says) in [
        (vec!["--shard", "2/2", "--out", other.to_str().unwrap()], "K must satisfy 0 <= K < N"),
        (vec!["--out", precious.to_str().unwrap()], "is not empty and holds no points.csv"),
    ] {
        let o = std::process::Command::new(bin()).args(map).args(&args).output().unwrap();
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(says), "{args:?}: {err}");
    }
    assert_eq!(std::fs::read_to_string(precious.join("notes.txt")).unwrap(), "keep");
    let o = std::process::Command::new(bin())
        .args(["basin-map", "--depth", "3", "merge", shards[0].to_str().unwrap(), "-o", "x"])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2), "options before merge: {}", String::from_utf8_lossy(&o.stderr));
    // The figure in both formats (the exact curve along 48 lines: this test is about the cells).
    for name in ["bmap.png", "bmap.svg"] {
        let out = d.path().join(name);
        let p = std::process::Command::new(bin())
            .args(["plot", "basin-map", dir.to_str().unwrap(), "--curve-lines", "48", "-o"])
            .arg(&out)
            .output()
            .unwrap();
        assert_eq!(p.status.code(), Some(0), "{name}: {}", String::from_utf8_lossy(&p.stderr));
    }
    let svg = d.path().join("bmap.svg");
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.contains("certified share") && text.contains("undecided share"), "legend");
    // Regression (2026-11-27): "proved CC" says what becomes of the time-to-rest cones' drops that
    // reach a simultaneous impact (the legend wraps its lines: the text elements' words, joined).
    let words: Vec<&str> =
        text.split('<').filter_map(|t| t.split_once('>')).flat_map(|(_, w)| w.split_whitespace()).collect();
    assert!(
        words
            .join(" ")
            .contains("meet a simultaneous impact, where the model stops, after a cone or inside a tree of prefixes, have volume zero")
    );
}

/// Regression (2026-11-27): `verify` called every drop of a `Rest` leaf "proved CC", though
/// docs/time-to-rest.md Theorem 5.1 excludes the drops that meet a simultaneous impact after the
/// cone is entered; its line and `basin-map --help` now say that those have volume zero
/// (docs/basin-certificates.md Lemma 4.1).
#[test]
fn a_basin_verdict_says_what_becomes_of_the_time_to_rest_cones_simultaneous_impacts() {
    let file = root().join("certificates/valid/basin-rest-n4-kappa1_6-gamma1_100.ron");
    let o = std::process::Command::new(bin()).arg("verify").arg(&file).output().unwrap();
    let said = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{said}");
    let assumption =
        "those of a cone that reach a simultaneous impact later, where the model stops, have volume zero";
    assert!(said.contains("proved CC") && said.contains(assumption), "{said}");
    let help = std::process::Command::new(bin()).args(["basin-map", "--help"]).output().unwrap();
    let help = String::from_utf8_lossy(&help.stdout).split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(help.contains("at which the model stops, have volume zero"), "{help}");
}

/// Below the CC threshold (the square plate, κ = 1/6, γ = 1/100) the producer embeds a
/// time-to-rest certificate and ends prefixes in its nodes' cones (`Rest` leaves, docs/
/// basin-certificates.md §4): the kernel accepts the file with no ICC share, and drops drawn in
/// each `Rest` leaf have the leaf's impacts and meet no simultaneous impact in 60 more (exact
/// runs; Lemma 4.1) and, in `f64` runs of 3000 impacts (evidence), chatter with an accumulation
/// time below the kernel's bound times h.
#[test]
fn rest_leaves_prove_drops_below_the_threshold_cc_within_their_time_bound() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("b.ron");
    let o = std::process::Command::new(bin())
        .args(["basin", "--n", "4", "--kappa", "1/6", "--gamma", "1/100"])
        .args(["--box", "1/25,1/25,1/50,1/50,26/25:3/50,3/50,1/25,1/25,53/50"])
        .args(["--depth", "6", "-o", out.to_str().unwrap()])
        .output()
        .unwrap();
    let said = String::from_utf8_lossy(&o.stdout).to_string();
    assert_eq!(o.status.code(), Some(0), "{said}{}", String::from_utf8_lossy(&o.stderr));
    assert!(said.contains("time-to-rest certificate of"), "{said}");
    let v =
        std::process::Command::new(bin()).args(["verify", "--json", out.to_str().unwrap()]).output().unwrap();
    let json: serde_json::Value = serde_json::from_slice(&v.stdout).unwrap();
    let file = &json["files"][0];
    assert_eq!(file["icc_share"], "0", "{json}");
    let bound: f64 = file["time_to_rest_bound"].as_str().map(crate::time_to_rest::num).unwrap();
    let cert: BasinCertificate = read(&std::fs::read_to_string(&out).unwrap(), Encoding::Ron).unwrap();
    assert!(cert.rest.is_some() && cert.orbit.is_some());
    // `Rest` leaves and trees ending in nodes' cones (the producer tries a tree where one prefix
    // does not hold on a whole sub-box).
    let rest: Vec<_> = cert
        .leaves
        .iter()
        .filter(|l| paths(&l.verdict, 4).iter().any(|(_, end)| matches!(end, Some(Then::Rest { .. }))))
        .collect();
    let share: f64 = rest.iter().map(|l| 0.5f64.powi(l.path.len() as i32)).sum();
    assert!(
        !rest.is_empty()
            && (crate::time_to_rest::num(file["cc_share"].as_str().unwrap()) - share).abs() < 1e-12
    );
    let model = Model::new(Shape::Polygon(4), Q::new(1, 6), Q::new(1, 100)).unwrap();
    let num = |s: &String| chatter_kernel::exact::parse_canonical(s, Default::default()).unwrap();
    let lo: [malachite::rational::Rational; 5] = std::array::from_fn(|k| num(&cert.drops.lo[k]));
    let hi: [malachite::rational::Rational; 5] = std::array::from_fn(|k| num(&cert.drops.hi[k]));
    let mut rng = SplitMix64::new(31);
    let mut checked = 0;
    for leaf in rest {
        let ways = paths(&leaf.verdict, 4);
        let longest = ways.iter().map(|(p, _)| p.len()).max().unwrap();
        let (l, h) = leaf_box(&lo, &hi, &leaf.path);
        for _ in 0..3 {
            let (y, start, exact) = drop_in(&model, (&l, &h), &mut rng);
            let fs = &model.float;
            // 60 impacts past the prefix, exactly: no simultaneous impact is met (Lemma 4.1 of
            // docs/basin-certificates.md: such drops have volume zero).
            let run = simulate_exact(&model, &exact, &Options::new(longest + 60));
            let (path, _) = taken(&ways, &run.sequence).unwrap_or_else(|| panic!("leaf {}", leaf.path));
            assert!(run.outcome != Outcome::Simultaneous && run.impacts > path.len(), "leaf {}", leaf.path);
            let float = chatter::simulate::simulate_float(fs, &start, &Options::new(3000));
            let t = float.accumulation.unwrap_or_else(|| panic!("leaf {}: {:?}", leaf.path, float.evidence));
            assert_eq!(float.evidence, Outcome::Cc, "leaf {}", leaf.path);
            assert!(
                t > 0.0 && t <= bound * y[4],
                "leaf {}: accumulation {t} > {bound} h = {}",
                leaf.path,
                bound * y[4]
            );
            checked += 1;
        }
    }
    assert!(checked >= 3, "{checked}");
}

/// Regression (2026-11-27): a slice through a `Rest` leaf was drawn and labelled as a leaf that
/// enters the orbit certificate's X; it is drawn as its own kind, in the proved-CC colour.
#[test]
fn plot_basin_draws_rest_leaves_as_their_own_kind_in_the_cc_colour() {
    use chatter::plot::basin::Kind;
    let d = tempfile::tempdir().unwrap();
    let png = d.path().join("rest.png");
    let fig = slice("certificates/valid/basin-rest-n4-kappa1_6-gamma1_100.ron", "phi_x,phi_y", &[], &png);
    assert!(!fig.rects.is_empty() && fig.rects.iter().all(|r| r.kind == Kind::Rest), "{:?}", fig.rects);
    let cc = slice(
        "certificates/valid/basin-n3-kappa1_8-gamma3_20.ron",
        "omega_x,omega_y",
        &[],
        &d.path().join("cc.png"),
    );
    let (x, y) = (fig.rects[0].x, fig.rects[0].y);
    let at = colour_at(&png, &fig, (x[0] + x[1]) / 2.0, (y[0] + y[1]) / 2.0);
    let r = cc.rects.iter().find(|r| r.kind == Kind::Cc).unwrap();
    let cc_colour =
        colour_at(&d.path().join("cc.png"), &cc, (r.x[0] + r.x[1]) / 2.0, (r.y[0] + r.y[1]) / 2.0);
    assert_eq!(at, cc_colour);
}

/// A tree leaf is drawn in the colour of its ends: the square plate's tree (ends in a node's cone)
/// as a `Rest` leaf, in the proved-CC colour; the triangle's at γ = 1/2 (ends v > 0) as ICC; the
/// legend then says that the drops meeting a simultaneous impact are not claimed.
#[test]
fn plot_basin_draws_a_tree_leaf_as_the_kind_of_its_ends() {
    use chatter::plot::basin::Kind;
    let d = tempfile::tempdir().unwrap();
    for (file, kind) in [
        ("certificates/valid/basin-tree-rest-n4-kappa1_6-gamma1_100.ron", Kind::Rest),
        ("certificates/valid/basin-tree-icc-n3-kappa1_8-gamma1_2.ron", Kind::Icc),
    ] {
        let fig = slice(file, "omega_x,omega_y", &[], &d.path().join("tree.png"));
        assert!(!fig.rects.is_empty() && fig.rects.iter().all(|r| r.kind == kind), "{file}: {:?}", fig.rects);
        assert_eq!(fig.trees, fig.rects.len(), "{file}: the legend's note on ties is drawn");
    }
}

/// Tree leaves (version 2, docs/basin-certificates.md §4.2): drops spread over the leaf of the
/// corpus's two tree certificates (contacts 0 and 3 of the square landing first in
/// either order; the triangle at γ = 1/2 branching at its fourth impact), run exactly, begin
/// with exactly one path of the tree, and end as its end says: v > 0 proved for `Icc`, no
/// simultaneous impact and CC in `f64` within the reported bound for `Rest`. Both branches of
/// each branching list are taken by some drop, so the trees are needed and the test exercises them.
#[test]
fn exact_drops_inside_tree_leaves_follow_one_path_of_the_tree_and_end_as_it_says() {
    for (file, seed) in
        [("basin-tree-rest-n4-kappa1_6-gamma1_100.ron", 41), ("basin-tree-icc-n3-kappa1_8-gamma1_2.ron", 43)]
    {
        let path = root().join("certificates/valid").join(file);
        let cert: BasinCertificate = read(&std::fs::read_to_string(&path).unwrap(), Encoding::Ron).unwrap();
        let OrbitBody::RegularPolygon { n, kappa, gamma } = &cert.body;
        let model = Model::new(Shape::Polygon(*n), kappa.parse().unwrap(), gamma.parse().unwrap()).unwrap();
        let num = |s: &String| chatter_kernel::exact::parse_canonical(s, Default::default()).unwrap();
        let lo: [Rat; 5] = std::array::from_fn(|k| num(&cert.drops.lo[k]));
        let hi: [Rat; 5] = std::array::from_fn(|k| num(&cert.drops.hi[k]));
        let kernel = chatter_kernel::verify::verify_basin_text_in(
            &std::fs::read_to_string(&path).unwrap(),
            Encoding::Ron,
            Default::default(),
            &chatter_kernel::verify::BOTH,
        );
        let chatter_kernel::verify::Verdict::Accepted(report) = kernel else { panic!("{file}: {kernel:?}") };
        let bound = report.time_to_rest_bound.as_deref().map(crate::time_to_rest::num);
        let mut rng = SplitMix64::new(seed);
        for leaf in cert.leaves.iter().filter(|l| matches!(l.verdict, LeafVerdict::Tree { .. })) {
            let ways = paths(&leaf.verdict, *n);
            let longest = ways.iter().map(|(p, _)| p.len()).max().unwrap();
            let (l, h) = leaf_box(&lo, &hi, &leaf.path);
            let (mut seen, mut ties) = (std::collections::BTreeSet::new(), 0);
            // The producer's 3^5 sample points (each coordinate at 1/6, 1/2, 5/6), whose
            // prefixes made the tree, then 16 drops drawn over nearly the whole leaf.
            const AT: [f64; 3] = [1.0 / 6.0, 0.5, 5.0 / 6.0];
            for i in 0..243 + 16 {
                let mut t = |k: usize| match i < 243 {
                    true => AT[i / 3usize.pow(k as u32) % 3],
                    false => 0.02 + 0.96 * rng.open01(),
                };
                let y: [f64; 5] = std::array::from_fn(|k| {
                    let (a, b) = (f(&l[k]), f(&h[k]));
                    a + (b - a) * t(k)
                });
                let fs = &model.float;
                let start =
                    Start { q: fs.from_paper(&[y[2], y[3], y[4]]), p: fs.from_paper(&[y[0], y[1], -1.0]) };
                let exact = Start {
                    q: start.q.map(|x| Q::from_f64_exact(x).unwrap()),
                    p: start.p.map(|x| Q::from_f64_exact(x).unwrap()),
                };
                let run = simulate_exact(&model, &exact, &Options::new(longest + 8));
                // The 27 sample points with ω_x = ω_y and φ_x = φ_y lie on the square's surface
                // of ties (contacts 0 and 3 land together: volume zero, not claimed).
                if run.outcome == Outcome::Simultaneous {
                    ties += 1;
                    continue;
                }
                let (taken_path, end) = taken(&ways, &run.sequence)
                    .unwrap_or_else(|| panic!("{file}: {:?} on no path", run.sequence));
                seen.insert(taken_path.clone());
                match end {
                    Some(Then::Icc) => assert_eq!((run.outcome, run.proved), (Outcome::Icc, true), "{file}"),
                    Some(Then::Rest { .. }) => {
                        // Near that surface the exact run, from the drop rounded to f64, may still
                        // order the contacts where the f64 run calls them simultaneous.
                        let float = chatter::simulate::simulate_float(fs, &start, &Options::new(3000));
                        if float.evidence == Outcome::Simultaneous {
                            ties += 1;
                            continue;
                        }
                        assert_eq!(float.evidence, Outcome::Cc, "{file}");
                        let t = float.accumulation.unwrap();
                        assert!(t <= bound.unwrap() * y[4], "{file}: {t} > {:?} h", bound);
                    }
                    other => panic!("{file}: end {other:?}"),
                }
            }
            assert!(seen.len() >= 2, "{file}: one path taken of {}: {seen:?}", ways.len());
            assert!(ties <= 27, "{file}: {ties} drops at a tie in f64");
        }
        // `verify` says which drops of a tree are not claimed.
        let o = std::process::Command::new(bin()).arg("verify").arg(&path).output().unwrap();
        let said = String::from_utf8_lossy(&o.stdout);
        assert!(
            said.contains("1 leaves are trees: their drops that meet a simultaneous impact inside the tree"),
            "{said}"
        );
    }
}

/// The producer's merge of sample drops' prefixes into a tree (src/basin/tree.rs): prefixes that
/// differ in order share their common impacts; a prefix that ends where another goes on, ends of
/// two kinds, two nodes at one end, or an end in X give no tree.
#[test]
fn plans_that_differ_in_order_merge_into_one_tree_and_conflicts_give_none() {
    use chatter::basin::float::Plan;
    use chatter::basin::tree::{branches, merge, write};
    let plan = |first: usize, steps: &[u64], rest: Option<usize>| Plan {
        first,
        steps: steps.to_vec(),
        cc: rest.is_some(),
        cuts: Vec::new(),
        rest,
    };
    let t = merge(&[plan(0, &[2, 1], None), plan(2, &[1], None), plan(0, &[2, 2], None)]).unwrap();
    assert_eq!(
        write(&t),
        "[(contact: 0, then: Impacts(next: [(contact: 2, then: Impacts(next: [(contact: 1, then: Icc), \
         (contact: 2, then: Icc)]))])), (contact: 2, then: Impacts(next: [(contact: 1, then: Icc)]))]"
    );
    assert!(branches(&t));
    assert!(merge(&[plan(0, &[2], None), plan(0, &[2, 1], None)]).is_none());
    assert!(merge(&[plan(0, &[], None), plan(1, &[], Some(0))]).is_none());
    assert!(merge(&[plan(0, &[], Some(0)), plan(0, &[], Some(1))]).is_none());
    let x = Plan { first: 0, steps: vec![], cc: true, cuts: vec![], rest: None };
    assert!(merge(&[x]).is_none());
    assert!(!branches(&merge(&[plan(1, &[1, 2], Some(3))]).unwrap()));
}
