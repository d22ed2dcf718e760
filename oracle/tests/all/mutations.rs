//! Structure-aware mutations of corpus files (`chatter_oracle::mutate`), each verified by the
//! kernel on both backends and judged by the oracle; any disagreement fails with the mutated text.
//! The same decoder drives the fuzz target `fuzz/fuzz_targets/oracle.rs`.

use crate::common::{differential_ron, root};
use chatter_oracle::mutate::{Edit, FIELDS, decode, mutated};
use chatter_oracle::read::{Encoding, parse::parse};
use std::collections::BTreeMap;

/// Base files: small certificates and refutations of every kind (the large ones cost seconds per
/// mutation and are left to the fuzz target).
const BASES: [&str; 19] = [
    "valid/doc-example-square.ron",
    "valid/image-on-edge-square.ron",
    "valid/n2-kappa1_4-gamma1_9-complete-chatter-from-all-down.ron",
    "valid/n2-kappa1_3-gamma1_20-cc-or-pcc-from-all-down.ron",
    "valid/n2-kappa1_4_1_3-gamma1_100_1_20-box.ron",
    "valid/n3-kappa1_8-gamma3_100-complete-chatter-from-all-down.ron",
    "valid/n4-kappa1_6-gamma1_100-complete-chatter-from-all-down.ron",
    "valid/n4-kappa1_10_3_25-gamma1_100_1_50-box.ron",
    "valid/n6-kappa1_40-gamma1_20-cc-or-pcc-from-all-down.ron",
    "valid/n5-kappa1_200-gamma1_5-effectively-invariant.ron",
    "valid/convex-rectangle-2x1-gamma1_50.ron",
    "valid/orbit-n3-kappa1_8-gamma3_20.ron",
    "valid/refutation-n4-kappa1_6-gamma1_20.ron",
    "valid/refutation-n2-kappa1_3-gamma1_10.ron",
    "valid/refutation-n3-kappa1_8-gamma1_5-all-down.ron",
    "invalid/pcc-not-excluded.ron",
    "invalid/rod-time-to-rest-bound-too-small.ron",
    "valid/rest-n4-kappa1_6-gamma1_100.ron",
    "invalid/rest-scale-below-one.ron",
];

/// The time-to-rest certificates whose weights, scales, bound, generators and successors
/// [`rest_parts_mutated_alike`] edits.
const REST: [&str; 3] = [
    "valid/rest-n4-kappa1_6-gamma1_100.ron",
    "valid/rest-n4-kappa1_6-gamma1_50.ron",
    "valid/rest-v2-n4-kappa1_6-gamma1_100.ron",
];

/// splitmix64, for deterministic inputs.
fn next(state: &mut u64) -> u64 {
    *state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

#[test]
fn mutated_corpus_files_get_the_same_verdict_from_kernel_and_oracle() {
    let bases: Vec<_> = BASES
        .iter()
        .map(|b| {
            let text = std::fs::read_to_string(root().join("certificates").join(b)).expect("base file");
            parse(&text, Encoding::Ron).expect("a base file parses")
        })
        .collect();
    let (mut tally, mut codes): (BTreeMap<String, usize>, BTreeMap<String, usize>) = Default::default();
    let mut failures = vec![];
    let mut state = 23;
    let cases = 240;
    for case in 0..cases {
        let len = 1 + (next(&mut state) % 13) as usize;
        let bytes: Vec<u8> = (0..len).map(|_| next(&mut state) as u8).collect();
        let plan = decode(&bytes);
        let text = mutated(&bases[usize::from(plan.base) % bases.len()], &plan.edits);
        let (kernel, _, cmp) = differential_ron(&text);
        *codes.entry(kernel.code.clone().unwrap_or_else(|| "accepted".into())).or_default() += 1;
        match cmp {
            Ok(a) => *tally.entry(format!("{a:?}")).or_default() += 1,
            Err(f) => failures.push(format!("case {case} {plan:?}: {f}\n{text}")),
        }
    }
    eprintln!("mutations: {tally:?}\nkernel verdicts: {codes:?}");
    assert!(failures.is_empty(), "{} disagreements:\n{}", failures.len(), failures.join("\n\n"));
    // Both sides of the verdict are exercised.
    assert!(tally.get("BothAccept").copied().unwrap_or(0) >= 20, "{tally:?}");
    assert!(tally.get("BothReject").copied().unwrap_or(0) >= 60, "{tally:?}");
}

#[test]
fn unedited_bases_round_trip_through_the_writer_with_their_verdicts() {
    for b in BASES {
        let text = std::fs::read_to_string(root().join("certificates").join(b)).expect("base file");
        let again = mutated(&parse(&text, Encoding::Ron).expect("parses"), &[]);
        let (k1, o1, _) = differential_ron(&text);
        let (k2, o2, cmp) = differential_ron(&again);
        assert_eq!(
            (k1.accepted, k1.code),
            (k2.accepted, k2.code),
            "{b}: the kernel's verdict changed\n{again}"
        );
        assert_eq!(o1, o2, "{b}: the oracle's verdict changed");
        assert!(cmp.is_ok(), "{b}: {cmp:?}");
    }
}

/// Targeted edits of the parts of a time-to-rest certificate (docs/certificate-format.md §16): a
/// weight, a scale (version 1) or a numerator (version 2), the bound, a generator or a successor,
/// each edited alone (scaled, shifted,
/// negated, an integer changed), judged alike by the kernel and the oracle; both verdicts occur,
/// and the rejections cover rules G1 to G5.
#[test]
fn rest_parts_mutated_alike() {
    let bases: Vec<_> = REST
        .iter()
        .map(|b| {
            let text = std::fs::read_to_string(root().join("certificates").join(b)).expect("base file");
            parse(&text, Encoding::Ron).expect("a base file parses")
        })
        .collect();
    let (mut tally, mut codes): (BTreeMap<String, usize>, BTreeMap<String, usize>) = Default::default();
    let mut failures = vec![];
    let mut state = 24;
    for case in 0..60 {
        let r = next(&mut state);
        let edit =
            Edit::Field { name: (case % FIELDS.len()) as u8, at: (r >> 8) as u8, how: (r >> 16) as u8 };
        let text = mutated(&bases[(r % bases.len() as u64) as usize], &[edit]);
        let (kernel, _, cmp) = differential_ron(&text);
        *codes.entry(kernel.code.clone().unwrap_or_else(|| "accepted".into())).or_default() += 1;
        match cmp {
            Ok(a) => *tally.entry(format!("{a:?}")).or_default() += 1,
            Err(f) => failures.push(format!("case {case} {edit:?}: {f}\n{text}")),
        }
    }
    eprintln!("rest mutations: {tally:?}\nkernel verdicts: {codes:?}");
    assert!(failures.is_empty(), "{} disagreements:\n{}", failures.len(), failures.join("\n\n"));
    assert!(tally.get("BothAccept").copied().unwrap_or(0) >= 3, "{tally:?}");
    assert!(tally.get("BothReject").copied().unwrap_or(0) >= 20, "{tally:?}");
    let g = ["virtual-time-not-positive", "image-outside", "virtual-time-increases", "bound-too-small"];
    assert!(g.iter().all(|c| codes.contains_key(*c)), "{codes:?}");
}
