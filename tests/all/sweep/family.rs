//! `chatter map --family` (issue 25 §3): maps of a one-parameter family of general bodies
//! against gamma, checked against `certify` at the same body, against the regular square (the
//! rectangle plates and the square-based boxes are affine images of it), across shards, and drawn.

use crate::common::{bin, q};
use chatter::bodies::general::general_catalogue;
use chatter::sweep::family::{BodyFamily, FamilyKind};
use chatter::sweep::point::criteria;
use chatter::sweep::table::{Row, parse_csv};
use std::path::Path;
use std::process::{Command, Output};

fn chatter(args: &[&str], dir: &Path) -> Output {
    Command::new(bin()).args(args).current_dir(dir).env_remove("SLURM_ARRAY_TASK_ID").output().unwrap()
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// Runs `map` with `args` into DIR/`name` and reads its rows.
fn map(dir: &Path, name: &str, args: &[&str]) -> Vec<Row> {
    let o = chatter(&[&["map"], args, &["--out", name]].concat(), dir);
    assert_eq!(o.status.code(), Some(0), "{args:?}: {}", text(&o.stderr));
    parse_csv(&std::fs::read_to_string(dir.join(name).join("points.csv")).unwrap()).unwrap()
}

/// The largest certified gamma among `rows` (None: none certified).
fn top(rows: &[&Row]) -> Option<chatter::exact::Q> {
    rows.iter().filter(|r| r.certified == Some(true)).map(|r| r.gamma.clone()).max()
}

#[test]
fn a_family_map_point_agrees_with_certify_at_the_same_body_and_verify_accepts_its_certificates() {
    let d = tempfile::tempdir().unwrap();
    let rows =
        map(d.path(), "rect", &["--family", "rectangle:aspect=1:3:2", "--gamma", "0:0.06:4", "--certify"]);
    assert_eq!(rows.len(), 8);
    let head = std::fs::read_to_string(d.path().join("rect/points.csv")).unwrap();
    assert!(head.starts_with("index,n,family,parameter,gamma,cc_criterion,"), "{head}");
    assert!(
        rows.iter().any(|r| r.certified == Some(true)) && rows.iter().any(|r| r.certified == Some(false))
    );
    for r in &rows {
        assert_eq!((r.n, r.rho.as_str()), (4, "rectangle:aspect"));
        let body = format!("{},1", r.kappa);
        let o = chatter(&["certify", "--rectangle", &body, "--gamma", &r.gamma.to_string()], d.path());
        let out = text(&o.stdout);
        match &r.claim {
            Some(c) => assert!(out.contains(&format!("claim={c}")), "{r:?}: {out}"),
            None => assert!(out.starts_with("NOT CERTIFIED"), "{r:?}: {out}"),
        }
    }
    let v = chatter(&["verify", "rect"], d.path());
    assert_eq!(v.status.code(), Some(0), "{}", text(&v.stdout));
    let certified = rows.iter().filter(|r| r.certified == Some(true)).count();
    assert_eq!(text(&v.stdout).matches(": OK").count(), certified, "{}", text(&v.stdout));
}

#[test]
fn the_rectangle_family_has_the_square_plates_threshold_at_every_aspect() {
    // Every rectangular plate is an affine image of the square plate (kappa = 1/6, docs/model.md
    // §11.7): its certified region in gamma is the square's, whatever the aspect ratio.
    let d = tempfile::tempdir().unwrap();
    let gamma = ["--gamma", "0:0.05:20"];
    let fam =
        map(d.path(), "f", &[&["--family", "rectangle:aspect=0.5:4:3", "--certify"][..], &gamma].concat());
    let sq = map(d.path(), "s", &[&["--n", "4", "--kappa", "1/12:1/4:1", "--certify"][..], &gamma].concat());
    assert_eq!(sq[0].kappa, q("1/6"));
    let square: Vec<&Row> = sq.iter().collect();
    let step = q("1/400");
    let regular_top = top(&square).expect("the square plate certifies at small gamma");
    for column in fam.chunks(20) {
        let col: Vec<&Row> = column.iter().collect();
        let t = top(&col).expect("certified at small gamma");
        assert!(
            (&t - &regular_top).abs() <= step,
            "aspect {}: {t} vs the square's {regular_top}",
            column[0].kappa
        );
        for (f, s) in column.iter().zip(&sq) {
            assert_eq!(f.gamma, s.gamma);
            // A certificate needs the dominant eigenvalue of the product around the contacts
            // real and positive there (as the square's S_1 criterion): never beyond it.
            assert!(f.certified != Some(true) || f.cc_criterion, "{f:?}");
            assert_eq!(f.cc_criterion, s.cc_criterion, "aspect {} gamma {}", f.kappa, f.gamma);
        }
    }
}

#[test]
fn the_square_box_family_at_height_h_has_the_criterion_of_the_square_with_kappa_1_plus_h2_over_6() {
    // The uniform box 1 x 1 x h is the regular square with R^2 = 1/2 and J = (1 + h^2)/12 I,
    // i.e. kappa = (1 + h^2)/6 (docs/model.md §1-2): the product criterion must agree with the
    // regular square's exact CC criterion at every point.
    let d = tempfile::tempdir().unwrap();
    let rows = map(d.path(), "b", &["--family", "box=1x1:height=0:2:4", "--gamma", "0:0.1:10"]);
    assert!(rows.iter().any(|r| r.cc_criterion) && rows.iter().any(|r| !r.cc_criterion));
    for r in &rows {
        let kappa = (q("1") + &r.kappa * &r.kappa) / q("6");
        assert_eq!(r.cc_criterion, criteria(4, &kappa, &r.gamma).0, "height {} gamma {}", r.kappa, r.gamma);
    }
}

#[test]
fn the_lander_family_at_spread_1_is_the_catalogues_lander() {
    let (f, axis) = BodyFamily::parse("lander:spread=0:2:1").unwrap();
    assert_eq!((f.kind, axis.value(0)), (FamilyKind::Lander, q("1")));
    let (body, tensor) = f.body(&q("1"), &q("1/20")).unwrap();
    let lander = general_catalogue(&q("1/20")).unwrap().into_iter().find(|e| e.name == "lander").unwrap();
    assert_eq!((body.contacts(), body.inertia()), (lander.body.contacts(), lander.body.inertia()));
    assert_eq!(tensor.map(|t| t.urdf()), Some(lander.tensor.urdf()));
    // A wider stance spreads the legs' mass: J_eff grows.
    let (wide, _) = f.body(&q("3/2"), &q("1/20")).unwrap();
    assert!(wide.inertia()[0][0] > body.inertia()[0][0] && wide.inertia()[1][1] > body.inertia()[1][1]);
}

#[test]
fn family_maps_are_identical_across_shards_and_drawn_with_the_parameter_on_the_x_axis() {
    let d = tempfile::tempdir().unwrap();
    // The rectangle family: its figure's exact boundary is the square's, drawn in seconds (the
    // lander's takes about a minute; its points are tested in the lander test above).
    let args = [
        "--family",
        "rectangle:aspect=1:3:3",
        "--gamma",
        "0:0.2:4",
        "--certify",
        "--simulate",
        "2",
        "--proof-budget",
        "0",
    ];
    map(d.path(), "whole", &args);
    for k in ["0/2", "1/2"] {
        let o = chatter(
            &[&["map"][..], &args, &["--shard", k, "--out", &format!("part{}", &k[..1])]].concat(),
            d.path(),
        );
        assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    }
    let o = chatter(&["map", "merge", "part0", "part1", "--out", "merged"], d.path());
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    for f in ["points.csv", "summary.json"] {
        let read = |dir: &str| std::fs::read(d.path().join(dir).join(f)).unwrap();
        assert_eq!(read("whole"), read("merged"), "{f}");
    }
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.path().join("whole/summary.json")).unwrap()).unwrap();
    assert_eq!(
        (s["grid"]["variable"].as_str(), s["grid"]["family"]["kind"].as_str()),
        (Some("parameter"), Some("rectangle"))
    );
    assert_eq!(s["computed"]["proof_budget"], 0, "--proof-budget 0: the drops are evidence only");
    let o = chatter(&["plot", "map", "whole", "-o", "m.svg"], d.path());
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let svg = std::fs::read_to_string(d.path().join("m.svg")).unwrap();
    assert!(
        svg.contains("\naspect\n") && svg.contains("family finder"),
        "the axis and legend name the family"
    );
    assert!(
        svg.contains("boundary of the conjectural CC"),
        "the product criterion's boundary is drawn and named"
    );
}

/// With a proof budget a family map's drops are also run exactly against a time-to-rest
/// certificate of the body (docs/map.md "Body families"): at the 3/2 x 1 plate, gamma = 1/50 (below
/// the square plate's threshold, 0.0295), every drop is all-down at its first impact and proved
/// CC, and its evidence agrees; above the threshold (gamma = 1/10) none is proved CC.
#[test]
fn a_family_maps_drops_are_proved_cc_by_a_time_to_rest_certificate_below_the_threshold() {
    let d = tempfile::tempdir().unwrap();
    let rows = map(
        d.path(),
        "proved",
        &["--family", "rectangle:aspect=1:2:1", "--gamma", "0:0.12:3", "--simulate", "4", "--jobs", "2"],
    );
    let at = |g: &str| rows.iter().find(|r| r.gamma == q(g)).unwrap_or_else(|| panic!("gamma {g}: {rows:?}"));
    let sim = |g: &str| at(g).sim.clone().unwrap_or_else(|| panic!("gamma {g} has drops"));
    let below = sim("1/50");
    let proved = below.proved.expect("proofs were tried");
    assert_eq!((proved[0], below.counts[0], below.contradicted), (4, 4, 0), "{below:?}");
    let above = sim("1/10");
    assert_eq!(above.proved.expect("proofs were tried")[0], 0, "{above:?}");
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.path().join("proved/summary.json")).unwrap())
            .unwrap();
    assert_eq!(s["computed"]["proof_budget"], 300, "{s}");
}

/// Next to the boundary a family map runs the exactifier's retries (regression, 2026-11-28): the
/// cell (spread 193/200, gamma 27/500) of the 50 x 50 lander map (docs/map.md), whose first
/// exactifier run fails, is certified, as it is by `certify`.
#[test]
fn a_family_map_certifies_next_to_the_boundary_with_the_exactifiers_retries() {
    let d = tempfile::tempdir().unwrap();
    let args = ["--family", "lander:spread=0.95:0.98:1", "--gamma", "0.052:0.056:1", "--certify"];
    let rows = map(d.path(), "edge", &args);
    assert_eq!((rows.len(), rows[0].kappa.clone(), rows[0].gamma.clone()), (1, q("193/200"), q("27/500")));
    assert_eq!(rows[0].certified, Some(true), "{:?}", rows[0]);
}

#[test]
fn bad_family_options_exit_2_with_a_message() {
    let d = tempfile::tempdir().unwrap();
    for (args, says) in [
        (vec!["--family", "sphere:radius=0:1:3"], "not a body family"),
        (vec!["--family", "rectangle:height=0:1:3"], "aspect"),
        (vec!["--family", "lander=1x2:spread=0:1:3"], "no fixed base"),
        (vec!["--family", "box=1x0:height=0:1:3"], "two numbers > 0"),
        (vec!["--family", "rectangle:aspect=-1:1:3"], "0 or above"),
        (vec!["--family", "rectangle:aspect=0:1:3", "--refute"], "--refute"),
        (vec!["--family", "rectangle:aspect=0:1:3", "--n", "4"], "--n"),
    ] {
        let o = chatter(&[&["map"][..], &args, &["--gamma", "0:1:2", "--out", "x"]].concat(), d.path());
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(text(&o.stderr).contains(says), "{args:?}: {}", text(&o.stderr));
    }
}
