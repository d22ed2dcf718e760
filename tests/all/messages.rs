//! Issue 26 §3: every usage error names the option, what was given and what is accepted, in the
//! user's words, and never an internal function's name. One test per message of the issue.

use crate::common::{bin, root};
use std::path::Path;
use std::process::{Command, Output};

fn chatter(args: &[&str], dir: &Path) -> Output {
    Command::new(bin()).args(args).current_dir(dir).output().unwrap()
}

/// The run's stderr, after checking that it failed as a usage error (exit 2).
fn usage_error(args: &[&str]) -> String {
    let o = chatter(args, &root());
    let e = String::from_utf8_lossy(&o.stderr).to_string();
    assert_eq!(o.status.code(), Some(2), "`chatter {}`: {e}", args.join(" "));
    e
}

/// Names of internal functions a message must never show.
const INTERNAL: [&str; 6] =
    ["read_convex", "read_orbit", "read_in", "from_certificate", "parse_ranges", "panicked"];

fn no_internal_names(text: &str) {
    for name in INTERNAL {
        assert!(!text.contains(name), "the message names {name:?}: {text}");
    }
}

#[test]
fn issue26_map_n7_names_the_ns_maps_take_not_the_simulator() {
    let e =
        usage_error(&["map", "--n", "7", "--rho", "0:1:2", "--gamma", "0:1:2", "--out", "/nonexistent/x"]);
    assert!(e.contains("--n: 7") && e.contains("3, 4, 5 and 6"), "{e}");
    assert!(e.contains("chatter simulate --n 7"), "says where n = 7 is handled: {e}");
    assert!(!e.contains("simulator handles up to 6"), "simulate --n 7 works: {e}");
    no_internal_names(&e);
}

#[test]
fn issue26_kappa_abc_is_not_a_number_not_a_cosine() {
    let e = usage_error(&["certify", "--n", "3", "--kappa", "abc", "--gamma", "1/20"]);
    assert!(e.contains("--kappa") && e.contains("\"abc\"") && e.contains("1/8"), "{e}");
    assert!(!e.contains("names c = cos"), "{e}");
    // Where c is irrational, a malformed element of Q(c) is told the canonical form.
    let e = usage_error(&["certify", "--n", "5", "--kappa", "abc", "--gamma", "1/20"]);
    assert!(e.contains("--kappa") && e.contains("\"abc\"") && e.contains("1/40 + 1/100*c"), "{e}");
}

#[test]
fn issue26_certify_n1_says_what_certify_takes() {
    let e = usage_error(&["certify", "--n", "1", "--kappa", "1/6", "--gamma", "1/20"]);
    assert!(e.contains("--n: 1") && e.contains("n = 2 (the rod)") && e.contains("3 to 64"), "{e}");
    assert!(!e.contains("this exact model needs a rational cos"), "{e}");
}

#[test]
fn issue26_plot_cone_of_every_certificate_kind_names_no_internal_function() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    let valid = root().join("certificates/valid");
    let orbit = valid.join("orbit-n3-kappa1_8-gamma3_20.ron");
    let rectangle = valid.join("convex-rectangle-2x1-gamma1_50.ron");
    let o = chatter(&["certify", "--body", "phone", "--gamma", "1/50", "-o", "phone.ron"], p);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    for (cert, needle) in [
        (orbit.as_path(), "the set X on the velocity plane"),
        (rectangle.as_path(), "the cones K_i on the plane v = −1"),
        (p.join("phone.ron").as_path(), "the cones K_i on the plane v = −1"),
    ] {
        let o = chatter(&["plot", "cone", cert.to_str().unwrap(), "-o", "f.svg"], p);
        let all = format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
        assert_eq!(o.status.code(), Some(0), "{}: {all}", cert.display());
        no_internal_names(&all);
        assert!(std::fs::read_to_string(p.join("f.svg")).unwrap().contains(needle), "{}", cert.display());
    }
    // The JSON twin of a general body's certificate, and a file that is none.
    let o = chatter(&["convert", rectangle.to_str().unwrap(), "--to", "json", "-o", "r.json"], p);
    assert_eq!(o.status.code(), Some(0));
    let o = chatter(&["plot", "cone", "r.json", "-o", "r.svg"], p);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    std::fs::write(p.join("junk.ron"), "(format: \"chatter-certificate\", version: 4)").unwrap();
    let e = chatter(&["plot", "cone", "junk.ron", "-o", "j.svg"], p);
    assert_eq!(e.status.code(), Some(2));
    no_internal_names(&String::from_utf8_lossy(&e.stderr));
}
