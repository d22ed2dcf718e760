//! Family certificates over an interval of gamma (docs/certificate-format.md §13, version 2): the
//! verdict is that of the two ends (docs/kernel-soundness.md §6), and a failure names its end.

use chatter_kernel::exact::ParseLimits;
use chatter_kernel::reject::{Code, KindLocus, Locus};
use chatter_kernel::verify::{BOTH, Verdict, verify_text};

const VALID: &str = include_str!("../../../../certificates/valid/convex-rectangle-2x1-gamma1_100-1_50.ron");
const UPPER: &str = include_str!("../../../../certificates/invalid/convex-interval-upper-end-outside.ron");

/// The text with `gamma` written as one number (version 1).
fn at(text: &str, interval: &str, gamma: &str) -> String {
    text.replacen(interval, &format!("gamma: \"{gamma}\","), 1).replacen("version: 2,", "version: 1,", 1)
}

fn verdict(text: &str) -> Verdict {
    verify_text(text, ParseLimits::default(), &BOTH)
}

#[test]
fn an_interval_is_accepted_with_each_end_and_rejected_at_the_first_end_that_fails() {
    let interval = "gamma: [\"1/100\", \"1/50\"],";
    assert!(VALID.contains(interval));
    assert!(matches!(verdict(VALID), Verdict::Accepted(_)));
    for g in ["1/100", "1/50"] {
        assert!(matches!(verdict(&at(VALID, interval, g)), Verdict::Accepted(_)), "gamma = {g}");
    }
    // The family of the single gamma 1/50 over [1/50, 1/30]: accepted at 1/50, rejected at 1/30
    // with the same code and place, which the interval's rejection names with its end.
    let interval = "gamma: [\"1/50\", \"1/30\"],";
    assert!(matches!(verdict(&at(UPPER, interval, "1/50")), Verdict::Accepted(_)));
    let (Verdict::Rejected(alone), Verdict::Rejected(both)) =
        (verdict(&at(UPPER, interval, "1/30")), verdict(UPPER))
    else {
        panic!("both must be rejected");
    };
    assert_eq!((alone.code, both.code), (Code::ImageOutside, Code::ImageOutside));
    let Locus::Kind(KindLocus::Transition { gamma: None, from, to, vertex, outside }) = alone.locus else {
        panic!("{:?}", alone.locus)
    };
    let named = KindLocus::Transition { gamma: Some("1/30".into()), from, to, vertex, outside };
    assert_eq!(both.locus, Locus::Kind(named));
}

#[test]
fn an_interval_with_equal_ends_is_its_single_gamma() {
    let interval = "gamma: [\"1/100\", \"1/50\"],";
    let same = VALID.replacen(interval, "gamma: [\"1/50\", \"1/50\"],", 1);
    assert_eq!(verdict(&same), verdict(&at(VALID, interval, "1/50")));
}

#[test]
fn both_ends_are_valid_bodies_before_any_cone_is_checked() {
    // [1/50, 3/2]: the cones hold at 1/50 and K2 would fail above it, but gamma = 3/2 is no body:
    // the range of γ at both ends is checked first, as for a box.
    let text = UPPER.replacen("gamma: [\"1/50\", \"1/30\"],", "gamma: [\"1/50\", \"3/2\"],", 1);
    let Verdict::Rejected(r) = verdict(&text) else { panic!("accepted") };
    assert_eq!((r.code, r.locus), (Code::ParameterOutOfRange, Locus::Field { path: "body.gamma[1]".into() }));
}
