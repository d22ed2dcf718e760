//! Basin certificates (docs/basin-certificates.md) against the oracle's own check
//! (`chatter_oracle::kinds::basin`, `chatter_oracle::basin`): the corpus's valid files accepted
//! by both with the same shares and leaves and a kernel bound on the time to rest at least every
//! exact time the oracle follows; every invalid file rejected by the oracle itself with the
//! manifest's code (not only allowed by its one-sidedness); rule B3 decided like the kernel's
//! tree; the sample drops lying in their leaves.

use crate::common::{differential_file, root};
use chatter_oracle::arith::{Field, Num, Rat};
use chatter_oracle::basin::{DIMS, drop_state, partition};
use chatter_oracle::compare::compare;
use chatter_oracle::regular::model::Polygon;
use chatter_oracle::verdict::Kind;
use num_bigint::BigInt;

fn basin_files(dir: &str) -> Vec<std::path::PathBuf> {
    let mut v: Vec<_> = std::fs::read_dir(root().join(dir))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.file_name().unwrap().to_string_lossy().starts_with("basin-"))
        .collect();
    v.sort();
    v
}

#[test]
fn valid_basin_files_get_the_kernels_shares_and_a_bound_above_every_followed_drop() {
    let files = basin_files("certificates/valid");
    assert!(files.len() >= 3, "two RON files and a JSON twin");
    let mut bounds = 0;
    for path in &files {
        let (kernel, oracle, cmp) = differential_file(path);
        let name = path.display();
        assert!(cmp.is_ok() && kernel.accepted && oracle.accepted(), "{name}: {cmp:?} {oracle:?}");
        assert_eq!(oracle.kind, Kind::Basin, "{name}");
        let chatter_oracle::verdict::Outcome::Accept(report) = &oracle.outcome else { unreachable!() };
        assert!(report.basin.is_some() && report.basin == kernel.report.basin, "{name}: {report:?}");
        let cc_leaves = report.basin.as_ref().unwrap().1[0];
        assert_eq!(oracle.time_to_rest_bound.is_some(), cc_leaves > 0, "{name}");
        if let (Some(o), Some(Some(k))) = (&oracle.time_to_rest_bound, &kernel.time_to_rest_bound) {
            // The kernel's bound holds for every drop of every CC leaf; a lower one is a finding.
            let parse = |s: &str| chatter_oracle::arith::rational::parse_rational(s, usize::MAX).unwrap();
            assert!(parse(o) <= parse(k) && parse(o) > Rat::from_integer(0.into()), "{name}: {o} vs {k}");
            let mut low = kernel.clone();
            low.time_to_rest_bound = Some(Some(chatter_oracle::arith::rational::rational_text(
                &(parse(o) / Rat::from_integer(2.into())),
            )));
            assert!(compare(&low, &oracle).is_err_and(|f| f.kind == "wrong-report"), "{name}");
            bounds += 1;
        }
    }
    assert!(bounds >= 1, "a file with CC leaves");
}

#[test]
fn invalid_basin_files_are_rejected_by_the_oracle_itself_with_the_manifests_code() {
    let manifest: Vec<serde_json::Value> = serde_json::from_str(
        &std::fs::read_to_string(root().join("certificates/invalid/expected.json")).unwrap(),
    )
    .unwrap();
    let files = basin_files("certificates/invalid");
    assert!(files.len() >= 15);
    for path in &files {
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        let code = manifest.iter().find(|e| e["file"] == name.as_str()).expect("listed")["code"].clone();
        let (kernel, oracle, cmp) = differential_file(path);
        assert!(cmp.is_ok(), "{name}: {cmp:?}");
        assert_eq!(kernel.code.as_deref(), code.as_str(), "{name}");
        assert_eq!(oracle.codes(), [code.as_str().unwrap()], "{name}: {oracle:?}");
    }
}

#[test]
fn the_partition_is_one_bisection_tree_as_the_kernel_reads_it() {
    let ok = |paths: &[&str]| partition(&paths.iter().map(|p| p.as_bytes()).collect::<Vec<_>>()).is_ok();
    for good in [&[""][..], &["0", "1"], &["02", "03", "1"], &["9", "8"], &["0", "120", "1212", "1213", "13"]]
    {
        assert!(ok(good), "{good:?}");
    }
    // A gap, overlaps, a letter, two coordinates halved at one node; the last is a partition of
    // the box as a set (the same four quarters as "02", "03", "1"), but not of one tree.
    for bad in
        [&["0"][..], &["0", "1", "0"], &["0", "01"], &["01", "0"], &["a"], &["0", "2"], &["20", "30", "1"]]
    {
        assert!(!ok(bad), "{bad:?}");
    }
}

#[test]
fn a_sample_drops_coordinates_with_a_sine_lie_in_its_leaf() {
    // ω_x and φ_x enter as s ω_x and s φ_x, s = sin 2π/n: X/s must lie in [lo, hi] (X² between
    // s² lo² and s² hi² for a positive interval), for n = 3 (c = -1/2) and n = 5 (c irrational).
    let r = |p: i64, q: i64| Rat::new(BigInt::from(p), BigInt::from(q));
    for n in [3u32, 5] {
        let field = Field::cos(n);
        let body = Polygon::new(n as usize, Num::rational(&field, r(1, 8)), Num::rational(&field, r(3, 20)));
        let lo: [Rat; DIMS] = [r(49, 1000), r(49, 1000), r(49, 1000), r(49, 1000), r(1049, 1000)];
        let hi: [Rat; DIMS] = [r(51, 1000), r(51, 1000), r(51, 1000), r(51, 1000), r(1051, 1000)];
        let m: [Rat; DIMS] = std::array::from_fn(|k| (&lo[k] + &hi[k]) / r(2, 1));
        let (q, p) = drop_state(&body, &m, &lo, &hi).expect("the centre");
        let c = body.cos(1);
        let s2 = &Num::int(&field, 1) - &(&c * &c);
        let one = Num::int(&field, 1);
        let at = |x: &Rat| Num::rational(&field, x.clone());
        // p1 = -1 + X - c ω_y and q1 = h + Φ - c φ_y, with X = s ω_x and Φ = s φ_x.
        let x = &(&p[1] + &one) + &(&c * &at(&m[1]));
        let phi = &(&q[1] - &at(&m[4])) + &(&c * &at(&m[3]));
        for (v, k) in [(x, 0), (phi, 2)] {
            let sq = |b: &Rat| &s2 * &at(&(b * b));
            assert!(
                v.is_positive() && &v * &v >= sq(&lo[k]) && &v * &v <= sq(&hi[k]),
                "n = {n}, coordinate {k}"
            );
        }
        assert_eq!((p[2].clone(), q[2].clone()), (one.neg(), at(&m[4])), "v = -1, hc = h");
    }
}
