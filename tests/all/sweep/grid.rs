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
