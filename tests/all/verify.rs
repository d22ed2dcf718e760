//! Tests of `chatter::verify`: the inputs (directories, links, special files), bounded reading,
//! limits, per-file verdicts, the exit rule over many inputs, and manifests (issue 9).

use crate::common::{bin, root};
use chatter::exact::ParseLimits;
use chatter::verify::files::{Entry, is_certificate_name, list};
use chatter::verify::{Options, Status, verify_file, with_time_limit};
use chatter_kernel::certificate::{Code, Locus, read};
use chatter_kernel::verify::{MALACHITE, NUM, Verdict, verify};
use std::os::unix::fs::symlink;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

fn opts() -> Options {
    Options::new(vec![MALACHITE, NUM])
}

fn square() -> PathBuf {
    root().join("certificates/valid/doc-example-square.ron")
}

fn names(dir: &Path, entries: &[Entry]) -> Vec<String> {
    entries
        .iter()
        .map(|e| match e {
            Entry::File(p) => p.strip_prefix(dir).unwrap().display().to_string(),
            Entry::Problem { path, message } => {
                format!("{}: {message}", path.strip_prefix(dir).unwrap().display())
            }
        })
        .collect()
}

/// `chatter verify ARGS`: (exit status, stdout).
fn verify_cli(args: &[&str]) -> (Option<i32>, String) {
    let o = Command::new(bin()).arg("verify").args(args).output().expect("run chatter");
    (o.status.code(), String::from_utf8_lossy(&o.stdout).into_owned())
}

#[test]
fn directories_are_searched_recursively_for_certificate_names_in_order() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("sub")).unwrap();
    for f in ["b.ron", "a.ron", "sub/c.ron", "notes.txt", "D.RON", "e.ron.gz", "f.ron.bak"] {
        std::fs::write(dir.path().join(f), "x").unwrap();
    }
    let l = list(&[dir.path().to_path_buf()]);
    assert_eq!(names(dir.path(), &l.entries), ["D.RON", "a.ron", "b.ron", "e.ron.gz", "sub/c.ron"]);
    assert_eq!((l.skipped.other_names, l.skipped.seen_before), (2, 0));
    assert!(is_certificate_name(Path::new("x.Ron.GZ")) && !is_certificate_name(Path::new("x.gz")));
}

#[test]
fn links_are_followed_once_per_real_path() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::copy(square(), d.join("a.ron")).unwrap();
    symlink(d.join("a.ron"), d.join("b.ron")).unwrap();
    // Two links from a directory to itself: the walk must end, and see a.ron once.
    symlink(d, d.join("loop1")).unwrap();
    symlink(d, d.join("loop2")).unwrap();
    let l = list(&[d.to_path_buf(), d.join("b.ron")]);
    assert_eq!(names(d, &l.entries), ["a.ron"]);
    // b.ron, loop1, loop2 inside the walk, and b.ron named again on the command line.
    assert_eq!(l.skipped.seen_before, 4);
    let (code, out) = verify_cli(&[d.to_str().unwrap()]);
    assert_eq!(code, Some(0), "{out}");
    assert_eq!(out.matches(": OK (").count(), 1, "{out}");
    assert!(out.contains("reached again through a link"), "{out}");
}

#[test]
fn special_files_are_never_opened_and_get_a_verdict() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let fifo = d.join("x.ron");
    assert!(Command::new("mkfifo").arg(&fifo).status().unwrap().success());
    symlink("/dev/zero", d.join("zero.ron")).unwrap();
    symlink(d.join("missing-target"), d.join("broken.ron")).unwrap();
    std::fs::copy(square(), d.join("ok.ron")).unwrap();
    let start = Instant::now();
    let (code, out) = verify_cli(&[d.to_str().unwrap()]);
    assert!(start.elapsed() < Duration::from_secs(30), "no blocking on the FIFO");
    assert_eq!(code, Some(2), "an unreadable input exits 2: {out}");
    assert!(out.contains("x.ron: ERROR: not a regular file: a FIFO"), "{out}");
    assert!(out.contains("zero.ron: ERROR: not a regular file: a character device"), "{out}");
    assert!(out.contains("broken.ron: ERROR: a symbolic link whose target cannot be read"), "{out}");
    assert!(out.contains("ok.ron: OK ("), "the readable file is still verified: {out}");
    assert!(out.contains("4 files: 1 OK, 0 rejected, 3 errors"), "{out}");
}

#[test]
fn one_missing_path_among_several_does_not_stop_the_others() {
    let s = square();
    let bad = root().join("certificates/invalid/shrunk-rectangle.ron");
    let (code, out) = verify_cli(&["/nonexistent/a.ron", s.to_str().unwrap(), bad.to_str().unwrap()]);
    assert_eq!(code, Some(2), "{out}");
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines[0], "/nonexistent/a.ron: ERROR: no such file or directory");
    assert!(lines[1].ends_with(
        "doc-example-square.ron: OK (CompleteChatterFromAllDown, n = 4, 4 generators, denominators <= 5 bits; finite accumulation time: not derived by this certificate (docs/time-to-rest.md))"
    ));
    assert!(lines[2].contains(": REJECTED: vertex 0 of K∩C_1"));
    assert_eq!(lines[3], "3 files: 1 OK, 1 rejected, 1 error", "the summary goes to stdout");
    // Without the missing path: a rejection exits 1.
    let (code, _) = verify_cli(&[s.to_str().unwrap(), bad.to_str().unwrap()]);
    assert_eq!(code, Some(1));
}

#[test]
fn an_unreadable_directory_is_one_error_and_the_rest_is_verified() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::copy(square(), d.join("ok.ron")).unwrap();
    let locked = d.join("locked");
    std::fs::create_dir(&locked).unwrap();
    std::fs::copy(square(), locked.join("inner.ron")).unwrap();
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(&locked, std::fs::Permissions::from_mode(0o000)).unwrap();
    let readable = std::fs::read_dir(&locked).is_ok(); // true when the tests run as root
    let l = list(&[d.to_path_buf()]);
    std::fs::set_permissions(&locked, std::fs::Permissions::from_mode(0o755)).unwrap();
    if readable {
        assert_eq!(names(d, &l.entries), ["locked/inner.ron", "ok.ron"]);
    } else {
        assert_eq!(names(d, &l.entries), ["locked: cannot list the directory: permission denied", "ok.ron"]);
    }
}

#[test]
fn bounded_reading_names_the_file_size_limit() {
    let o = Options { max_file_size: 100, ..opts() };
    let v = verify_file(&square(), &o);
    assert_eq!((v.status, v.code), (Status::Rejected, Some(Code::TooLarge)), "{v:?}");
    assert_eq!(v.locus, Some(Locus::Limit { name: "max-file-size".into() }));
    assert!(v.reason.unwrap().contains("more than the limit max-file-size = 100 bytes"));
    let size = std::fs::metadata(square()).unwrap().len();
    assert_eq!(verify_file(&square(), &Options { max_file_size: size, ..opts() }).status, Status::Ok);
}

fn gzip(bytes: &[u8]) -> Vec<u8> {
    use std::io::Write;
    let mut e = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
    e.write_all(bytes).unwrap();
    e.finish().unwrap()
}

#[test]
fn gzipped_certificates_are_read_within_the_size_limit() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read(square()).unwrap();
    let p = dir.path().join("sq.ron.gz");
    std::fs::write(&p, gzip(&text)).unwrap();
    let v = verify_file(&p, &opts());
    assert_eq!(v.status, Status::Ok, "{v:?}");
    assert!(v.line().contains("gzip'd"), "{}", v.line());
    // A small file that decompresses beyond the limit (a "gzip bomb") is refused by the limit.
    let bomb = dir.path().join("bomb.ron.gz");
    std::fs::write(&bomb, gzip(&vec![b' '; 1 << 20])).unwrap();
    assert!(std::fs::metadata(&bomb).unwrap().len() < 10_000);
    let v = verify_file(&bomb, &Options { max_file_size: 1 << 16, ..opts() });
    assert_eq!(v.code, Some(Code::TooLarge), "{v:?}");
    assert!(v.reason.unwrap().contains("decompresses to more than 65536 bytes"));
    // Not gzip after all: a damaged stream is an error that says so.
    let broken = dir.path().join("broken.ron.gz");
    std::fs::write(&broken, &gzip(&text)[..20]).unwrap();
    let v = verify_file(&broken, &opts());
    assert_eq!(v.status, Status::Error);
    assert!(v.reason.unwrap().contains("gzip'd file that does not decompress"));
}

#[test]
fn non_utf8_input_is_an_input_error_with_the_offset() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("latin1.ron");
    std::fs::write(&p, b"Certificate(\xe9)").unwrap();
    let v = verify_file(&p, &opts());
    assert_eq!(v.status, Status::Error);
    assert_eq!(v.reason.as_deref(), Some("not UTF-8 text: byte 12 (0xe9) is not valid UTF-8"));
    let z = dir.path().join("zip.ron");
    std::fs::write(&z, b"PK\x03\x04\xff\xff").unwrap();
    assert!(verify_file(&z, &opts()).reason.unwrap().contains("it looks like a zip archive"));
    let (code, _) = verify_cli(&[p.to_str().unwrap()]);
    assert_eq!(code, Some(2), "README: input errors exit 2");
}

#[test]
fn empty_files_and_byte_order_marks_are_named() {
    let dir = tempfile::tempdir().unwrap();
    let (e, b) = (dir.path().join("empty.ron"), dir.path().join("bom.ron"));
    std::fs::write(&e, "").unwrap();
    let mut bom = "\u{feff}".as_bytes().to_vec();
    bom.extend(std::fs::read(square()).unwrap());
    std::fs::write(&b, bom).unwrap();
    let r = |p: &Path| verify_file(p, &opts()).reason.unwrap();
    assert!(r(&e).contains("empty"), "{}", r(&e));
    assert!(r(&b).contains("byte order mark"), "{}", r(&b));
}

#[test]
fn the_digit_limit_is_configurable_and_named() {
    let p = square();
    // Its longest number, gamma = "1/100", has four digits.
    let with = |n| Options { limits: ParseLimits::digits(n), ..opts() };
    assert_eq!(verify_file(&p, &with(4)).status, Status::Ok);
    let v = verify_file(&p, &with(3));
    assert_eq!((v.status, v.code), (Status::Rejected, Some(Code::TooLarge)));
    assert!(
        v.reason.unwrap().contains(
            "field `body.gamma`: \"1/100\": number has 4 digits, more than the limit max-digits = 3"
        )
    );
}

#[test]
fn generator_and_total_digit_limits_are_named() {
    let cert = read(&std::fs::read_to_string(square()).unwrap()).unwrap();
    let at = |limits| match verify(&cert, limits) {
        Verdict::Rejected(r) => (r.code, r.locus),
        other => panic!("{other:?}"),
    };
    let gens = ParseLimits { max_generators: 3, ..Default::default() };
    assert_eq!(at(gens), (Code::TooLarge, Locus::Limit { name: "max-generators".into() }));
    let total = ParseLimits { max_total_digits: 20, ..Default::default() };
    assert_eq!(at(total), (Code::TooLarge, Locus::Limit { name: "max-total-digits".into() }));
    assert!(matches!(
        verify(&cert, ParseLimits { max_generators: 4, ..Default::default() }),
        Verdict::Accepted(_)
    ));
}

#[test]
fn a_passed_deadline_is_a_time_limit_on_both_backends_not_a_disagreement() {
    let cert = read(&std::fs::read_to_string(square()).unwrap()).unwrap();
    let limits = ParseLimits { deadline: Some(Instant::now()), ..Default::default() };
    match verify(&cert, limits) {
        Verdict::Rejected(r) => {
            assert_eq!((r.code, r.locus), (Code::TimeLimit, Locus::Limit { name: "time-limit".into() }));
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn the_watchdog_abandons_work_that_outlasts_the_limit() {
    let start = Instant::now();
    let r =
        with_time_limit(Some(Duration::from_millis(100)), |_| std::thread::sleep(Duration::from_secs(30)));
    assert!(r.is_none());
    assert!(start.elapsed() < Duration::from_secs(10));
    assert_eq!(with_time_limit(Some(Duration::from_secs(5)), |d| d.is_some()), Some(true));
    assert_eq!(with_time_limit(None, |d| d.is_none()), Some(true));
}

#[test]
fn the_invalid_corpus_matches_its_manifest() {
    let m = root().join("certificates/invalid/expected.json");
    let (code, out) = verify_cli(&["--expect", m.to_str().unwrap()]);
    assert_eq!(code, Some(0), "{out}");
    assert!(out.contains("0 mismatches with the manifest"), "{out}");
}

#[test]
fn manifest_mismatches_are_each_reported() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::copy(square(), d.join("ok.ron")).unwrap();
    std::fs::copy(root().join("certificates/invalid/shrunk-rectangle.ron"), d.join("bad.ron")).unwrap();
    std::fs::copy(square(), d.join("unlisted.ron")).unwrap();
    let manifest = serde_json::json!([
        {"file": "ok.ron", "code": "image-outside"},
        {"file": "bad.ron", "code": "image-outside", "locus": {"kind": "piece", "piece": 2, "vertex": 0, "outside": null}},
        {"file": "gone.ron", "verdict": "OK"},
    ]);
    std::fs::write(d.join("expected.json"), manifest.to_string()).unwrap();
    let (code, out) = verify_cli(&["--expect", d.join("expected.json").to_str().unwrap()]);
    assert_eq!(code, Some(1), "{out}");
    assert!(out.contains("ok.ron: expected REJECTED [image-outside], got OK"), "{out}");
    assert!(out.contains("bad.ron: expected the locus"), "{out}");
    assert!(out.contains("unlisted.ron: not in the manifest (got OK)"), "{out}");
    assert!(out.contains("gone.ron: listed in the manifest but not checked"), "{out}");
    assert!(out.contains("4 mismatches with the manifest"), "{out}");
    std::fs::write(d.join("broken.json"), "{").unwrap();
    let (code, _) = verify_cli(&["--expect", d.join("broken.json").to_str().unwrap()]);
    assert_eq!(code, Some(2), "an unreadable manifest is an input error");
}

/// `chatter::verify::format` reads the `format` field leniently (any struct name, comments
/// allowed), to tell the kinds of file apart in messages and directory listings.
#[test]
fn the_kind_of_a_file_is_read_from_its_format_field() {
    use chatter::verify::format::format_of;
    let cert = format!(
        "// made by \"chatter-proof\" tools\n{}",
        include_str!("../../certificates/valid/doc-example-square.ron")
    );
    assert_eq!(format_of(&cert).as_deref(), Some("chatter-certificate"));
    let proof =
        include_str!("../../proofs/square.ron").replacen("\"chatter-proof\"", "\"chatter\\u{2d}proof\"", 1);
    assert_eq!(format_of(&proof).as_deref(), Some("chatter-proof"));
    let family = include_str!("../../certificates/valid/convex-rectangle-2x1-gamma1_50.ron");
    assert_eq!(format_of(family).as_deref(), Some("chatter-family-certificate"));
    assert_eq!(format_of("not ron"), None);
}
