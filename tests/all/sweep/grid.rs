use crate::common::q;
use chatter::sweep::grid::{Axis, Grid, Shard, Variable};
use std::collections::HashMap;

#[test]
fn axes_are_cell_centres_read_exactly() {
    let a = Axis::parse("0:1:4").unwrap();
    let v: Vec<String> = (0..4).map(|i| a.value(i).to_string()).collect();
    assert_eq!(v, ["1/8", "3/8", "5/8", "7/8"]);
    let b = Axis::parse("0.1:0.2:1").unwrap();
    assert_eq!(b.value(0), q("3/20"), "decimals are exact");
    assert_eq!(b.text(), "1/10:1/5:1");
    for bad in ["1:0:3", "0:1:0", "0:1", "a:1:2", "0:1:x", "0:1:-2", "0:0:5"] {
        assert!(Axis::parse(bad).is_err(), "{bad} accepted");
    }
}

#[test]
fn rho_grids_have_exact_kappa_and_rows_in_order() {
    let g = Grid {
        n: 3,
        variable: Variable::Rho,
        x: Axis::parse("0:1:2").unwrap(),
        gamma: Axis::parse("0:1:3").unwrap(),
        family: None,
    };
    assert_eq!(g.len(), 6);
    let p = g.point(4); // ix = 1, ig = 1
    assert_eq!((p.ix, p.ig), (1, 1));
    assert_eq!(p.rho, Some(q("3/4")));
    assert_eq!(p.kappa, q("9/16"));
    assert_eq!(p.gamma, q("1/2"));
    let bad = Grid { n: 7, ..g.clone() };
    assert!(bad.validate().unwrap_err().contains("--n"));
    let bad = Grid { gamma: Axis::parse("0:2:3").unwrap(), ..g };
    assert!(bad.validate().unwrap_err().contains("--gamma"));
}

#[test]
fn shards_partition_the_grid() {
    for count in 1..6 {
        let mut seen = vec![0; 23];
        for k in 0..count {
            for i in (Shard { index: k, count }).indices(23) {
                seen[i] += 1;
            }
        }
        assert!(seen.iter().all(|&s| s == 1), "{count} shards: {seen:?}");
    }
    assert_eq!(Shard::parse("2/5").unwrap(), Shard { index: 2, count: 5 });
    for bad in ["5/5", "1/0", "x/2", "3", "-1/2"] {
        assert!(Shard::parse(bad).is_err(), "{bad} accepted");
    }
}

fn slurm(vars: &[(&str, &str)]) -> Result<Shard, String> {
    let m: HashMap<String, String> = vars.iter().map(|(k, v)| (k.to_string(), v.to_string())).collect();
    Shard::from_slurm(|k| m.get(k).cloned())
}

#[test]
fn shard_auto_counts_as_slurm_does() {
    // --array=0-3
    let zero = [("SLURM_ARRAY_TASK_MIN", "0"), ("SLURM_ARRAY_TASK_COUNT", "4")];
    for id in 0..4 {
        let id = id.to_string();
        let mut v = zero.to_vec();
        v.push(("SLURM_ARRAY_TASK_ID", &id));
        assert_eq!(slurm(&v).unwrap().index.to_string(), id);
    }
    // --array=1-10: task 5 is shard 4 of 10.
    let s = slurm(&[
        ("SLURM_ARRAY_TASK_ID", "5"),
        ("SLURM_ARRAY_TASK_MIN", "1"),
        ("SLURM_ARRAY_TASK_COUNT", "10"),
    ]);
    assert_eq!(s.unwrap(), Shard { index: 4, count: 10 });
    // --array=0-8:2: task 6 is shard 3 of 5.
    let s = slurm(&[
        ("SLURM_ARRAY_TASK_ID", "6"),
        ("SLURM_ARRAY_TASK_MIN", "0"),
        ("SLURM_ARRAY_TASK_STEP", "2"),
        ("SLURM_ARRAY_TASK_COUNT", "5"),
    ]);
    assert_eq!(s.unwrap(), Shard { index: 3, count: 5 });
    assert!(slurm(&[("SLURM_ARRAY_TASK_COUNT", "4")]).unwrap_err().contains("SLURM_ARRAY_TASK_ID"));
    assert!(
        slurm(&[("SLURM_ARRAY_TASK_ID", "4"), ("SLURM_ARRAY_TASK_COUNT", "4")]).is_err(),
        "0-based: 4 is out"
    );
    assert!(
        slurm(&[
            ("SLURM_ARRAY_TASK_ID", "3"),
            ("SLURM_ARRAY_TASK_STEP", "2"),
            ("SLURM_ARRAY_TASK_COUNT", "4")
        ])
        .is_err()
    );
    assert!(slurm(&[("SLURM_ARRAY_TASK_ID", "x"), ("SLURM_ARRAY_TASK_COUNT", "4")]).is_err());
}

/// The five variables as SLURM sets them in every task (observed on slurm-wlm 22.05).
fn array(id: u64, min: u64, max: u64, step: u64, count: u64) -> Result<Shard, String> {
    let (id, min, max, step, count) =
        (id.to_string(), min.to_string(), max.to_string(), step.to_string(), count.to_string());
    slurm(&[
        ("SLURM_ARRAY_TASK_ID", &id),
        ("SLURM_ARRAY_TASK_MIN", &min),
        ("SLURM_ARRAY_TASK_MAX", &max),
        ("SLURM_ARRAY_TASK_STEP", &step),
        ("SLURM_ARRAY_TASK_COUNT", &count),
    ])
}

/// Asserts that the error names every `needle` (variables with their values).
fn refused(r: Result<Shard, String>, needles: &[&str]) {
    let e = r.expect_err("accepted");
    for n in needles {
        assert!(e.contains(n), "{n:?} not in {e:?}");
    }
}

#[test]
fn shard_auto_accepts_every_range_as_slurm_reports_it() {
    let shards = |min, max, step, count, ids: &[u64]| -> Vec<Shard> {
        ids.iter().map(|&id| array(id, min, max, step, count).unwrap()).collect()
    };
    let expect = |count| (0..count).map(|index| Shard { index, count }).collect::<Vec<_>>();
    // --array=0-3 and --array=0-3%2 (a % limit sets nothing).
    assert_eq!(shards(0, 3, 1, 4, &[0, 1, 2, 3]), expect(4));
    // --array=0-6:3; --array=2-9:3, for which SLURM reports MAX=8.
    assert_eq!(shards(0, 6, 3, 3, &[0, 3, 6]), expect(3));
    assert_eq!(shards(2, 8, 3, 3, &[2, 5, 8]), expect(3));
    // --array=3: one task; --array=1,2,3: a list without gaps is a range.
    assert_eq!(shards(3, 3, 1, 1, &[3]), expect(1));
    assert_eq!(shards(1, 3, 1, 3, &[1, 2, 3]), expect(3));
}

#[test]
fn shard_auto_refuses_a_list_with_gaps() {
    // --array=1,5,9: SLURM reports MIN=1, MAX=9, STEP=1, COUNT=3; every task is refused, also
    // task 1, which alone would look like shard 0 of 3.
    for id in [1, 5, 9] {
        refused(
            array(id, 1, 9, 1, 3),
            &[
                "SLURM_ARRAY_TASK_COUNT=3",
                "SLURM_ARRAY_TASK_MIN=1",
                "SLURM_ARRAY_TASK_MAX=9",
                "are 9 IDs",
                "--array=1,5,9",
            ],
        );
    }
    // --array=1,2,5: tasks 1 and 2 would otherwise run shards 0 and 1 of 3, and shard 2 never.
    for id in [1, 2, 5] {
        refused(array(id, 1, 5, 1, 3), &["SLURM_ARRAY_TASK_COUNT=3", "SLURM_ARRAY_TASK_MAX=5", "are 5 IDs"]);
    }
}

#[test]
fn shard_auto_refuses_a_count_that_does_not_match_the_ids() {
    // COUNT says 4 but the IDs run 0..7.
    refused(array(2, 0, 7, 1, 4), &["SLURM_ARRAY_TASK_COUNT=4", "SLURM_ARRAY_TASK_MAX=7", "are 8 IDs"]);
    // COUNT says 8 but the IDs run 0..3.
    refused(array(2, 0, 3, 1, 8), &["SLURM_ARRAY_TASK_COUNT=8", "SLURM_ARRAY_TASK_MAX=3", "are 4 IDs"]);
    refused(array(0, 0, 0, 1, 0), &["SLURM_ARRAY_TASK_COUNT=0"]);
}

#[test]
fn shard_auto_refuses_a_step_that_does_not_divide() {
    refused(
        array(0, 0, 7, 2, 4),
        &["SLURM_ARRAY_TASK_STEP=2 does not divide", "SLURM_ARRAY_TASK_MAX - SLURM_ARRAY_TASK_MIN = 7 - 0"],
    );
    refused(array(0, 0, 6, 0, 4), &["SLURM_ARRAY_TASK_STEP=0"]);
}

#[test]
fn shard_auto_refuses_min_above_max() {
    refused(array(5, 5, 3, 1, 1), &["SLURM_ARRAY_TASK_MIN=5 is above SLURM_ARRAY_TASK_MAX=3"]);
}

#[test]
fn shard_auto_refuses_a_task_id_outside_the_array() {
    // --array=1-4 with a task ID below, above, or between the IDs of --array=0-6:2.
    refused(array(0, 1, 4, 1, 4), &["SLURM_ARRAY_TASK_ID=0 is outside", "MIN=1..SLURM_ARRAY_TASK_MAX=4"]);
    refused(array(5, 1, 4, 1, 4), &["SLURM_ARRAY_TASK_ID=5 is outside", "MIN=1..SLURM_ARRAY_TASK_MAX=4"]);
    refused(
        array(3, 0, 6, 2, 4),
        &["SLURM_ARRAY_TASK_ID=3 is not SLURM_ARRAY_TASK_MIN=0 plus a multiple of SLURM_ARRAY_TASK_STEP=2"],
    );
    // Without MAX (a hand-made environment) it is MIN + (COUNT - 1) STEP.
    refused(
        slurm(&[("SLURM_ARRAY_TASK_ID", "4"), ("SLURM_ARRAY_TASK_COUNT", "4")]),
        &["SLURM_ARRAY_TASK_ID=4 is outside SLURM_ARRAY_TASK_MIN=0..SLURM_ARRAY_TASK_MAX=3"],
    );
}

#[test]
fn shard_auto_names_a_missing_or_unreadable_variable() {
    refused(slurm(&[("SLURM_ARRAY_TASK_ID", "1")]), &["SLURM_ARRAY_TASK_COUNT is not set", "sbatch --array"]);
    refused(
        slurm(&[
            ("SLURM_ARRAY_TASK_ID", "1"),
            ("SLURM_ARRAY_TASK_COUNT", "4"),
            ("SLURM_ARRAY_TASK_MAX", "x"),
        ]),
        &["SLURM_ARRAY_TASK_MAX=\"x\" is not a non-negative integer"],
    );
}
