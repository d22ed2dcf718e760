//! The JSON twin of the certificate format (docs/certificate-format.md §11, issue 14 §1): every
//! corpus file converted to JSON gets the same verdict (report, code, locus and message), the
//! conversion is lossless both ways, the JSON reader is as strict as the RON one, and
//! `chatter convert` and `chatter verify` handle JSON files.

use crate::common::{bin, root};
use crate::corpus::ron_files;
use chatter::convert::{Target, convert};
use chatter::verify::files::{declares_format, list};
use chatter::verify::format::format_of_in;
use chatter::verify::read::{Input, read_input};
use chatter::write::write;
use chatter_kernel::certificate::{Code, Encoding, read, read_in};
use chatter_kernel::exact::ParseLimits;
use chatter_kernel::verify::{MALACHITE, verify_basin_text_in, verify_refutation_text_in, verify_text_in};
use std::path::Path;
use std::process::Command;

fn text_of(p: &Path) -> String {
    match read_input(p, 1 << 24) {
        Input::Text { text, .. } => text,
        other => panic!("{}: {other:?}", p.display()),
    }
}

/// The verdict on certificate or refutation text, as comparable text. On malachite alone: the
/// JSON reader feeds the same rules on both backends, and tests/all/corpus.rs checks that the two
/// backends agree on every corpus file (each corpus pass costs seconds; CI, issue 23 §4).
fn verdict(text: &str, encoding: Encoding) -> String {
    let limits = ParseLimits::default();
    let format = format_of_in(text, encoding);
    if format.as_deref() == Some(chatter_kernel::rest::FORMAT) {
        let v = chatter_kernel::verify::verify_rest_text_in(text, encoding, limits, &[MALACHITE]);
        return format!("{v:?}");
    }
    if format.as_deref() == Some(chatter_kernel::rest_family::FORMAT) {
        let v = chatter_kernel::verify::verify_rest_family_text_in(text, encoding, limits, &[MALACHITE]);
        return format!("{v:?}");
    }
    if format.as_deref() == Some(chatter_kernel::syntax::basin::FORMAT) {
        return format!("{:?}", verify_basin_text_in(text, encoding, limits, &[MALACHITE]));
    }
    if format.as_deref() == Some(chatter_kernel::refute::FORMAT) {
        format!("{:?}", verify_refutation_text_in(text, encoding, limits, &[MALACHITE]))
    } else {
        format!("{:?}", verify_text_in(text, encoding, limits, &[MALACHITE]))
    }
}

#[test]
fn every_valid_corpus_file_verifies_as_json_with_the_same_report() {
    let files = ron_files("certificates/valid");
    assert!(files.len() >= 60);
    for f in &files {
        let ron = text_of(f);
        let json = convert(&ron, Encoding::Ron, Target::Json).unwrap();
        let (a, b) = (verdict(&ron, Encoding::Ron), verdict(&json, Encoding::Json));
        assert!(a.starts_with("Accepted"), "{}: {a}", f.display());
        assert_eq!(a, b, "{}", f.display());
        // Lossless: RON -> JSON -> RON is the file itself (the corpus is in the writer's layout).
        assert_eq!(convert(&json, Encoding::Json, Target::Ron).unwrap(), ron, "{}", f.display());
        // And JSON -> RON -> JSON gives the same JSON.
        let again =
            convert(&convert(&json, Encoding::Json, Target::Ron).unwrap(), Encoding::Ron, Target::Json);
        assert_eq!(again.unwrap(), json, "{}", f.display());
        // The JSON is JSON for any reader, with the same field names.
        let v: serde_json::Value = serde_json::from_str(&json).unwrap();
        assert!(v.get("format").is_some() && v.get("body").is_some(), "{}", f.display());
    }
}

#[test]
fn every_invalid_corpus_file_whose_defect_survives_conversion_is_rejected_the_same_as_json() {
    let files = ron_files("certificates/invalid");
    let (mut converted, mut not_converted) = (0, 0);
    for f in &files {
        let ron = text_of(f);
        let a = verdict(&ron, Encoding::Ron);
        assert!(a.starts_with("Rejected"), "{}: {a}", f.display());
        match convert(&ron, Encoding::Ron, Target::Json) {
            Ok(json) => {
                // Code, locus and message identical: the content rules run on the same values.
                assert_eq!(verdict(&json, Encoding::Json), a, "{}", f.display());
                assert_eq!(
                    convert(&json, Encoding::Json, Target::Ron),
                    convert(&ron, Encoding::Ron, Target::Ron)
                );
                converted += 1;
            }
            Err(e) => {
                // Only a defect of the RON text itself (syntax, schema, header) stops the conversion.
                let reading =
                    ["syntax", "unknown-field", "missing-field", "duplicate-field", "unknown-variant"];
                let header = ["wrong-format", "unsupported-version"];
                assert!(
                    reading.iter().chain(&header).any(|c| e.ends_with(&format!("[{c}]"))),
                    "{}: {e}",
                    f.display()
                );
                not_converted += 1;
            }
        }
    }
    assert_eq!((converted, not_converted), (142, 20), "the defects that survive conversion");
}

/// The doc example's JSON twin (certificates/valid/doc-example-square.json).
fn square_json() -> String {
    std::fs::read_to_string(root().join("certificates/valid/doc-example-square.json")).unwrap()
}

/// The rejection code of JSON certificate text.
fn json_code(text: &str) -> Code {
    match read_in(text, Encoding::Json) {
        Err(r) => r.code,
        Ok(c) => match chatter_kernel::verify::verify(&c, ParseLimits::default()) {
            chatter_kernel::verify::Verdict::Rejected(r) => r.code,
            other => panic!("expected a rejection of {text}, got {other:?}"),
        },
    }
}

#[test]
fn the_json_twins_in_the_corpus_are_the_conversions_of_their_ron_files_and_the_doc_example() {
    for name in ["doc-example-square", "refutation-n4-kappa1_6-gamma1_20", "basin-icc-n3-kappa1_8-gamma1_2"] {
        let dir = root().join("certificates/valid");
        let ron = text_of(&dir.join(format!("{name}.ron")));
        let json = text_of(&dir.join(format!("{name}.json")));
        assert_eq!(convert(&ron, Encoding::Ron, Target::Json).unwrap(), json, "{name}");
    }
    // The worked example of §11 is the file, and the RON example of §1 is its conversion.
    let doc = std::fs::read_to_string(root().join("docs/certificate-format.md")).unwrap();
    let block = |fence: &str| {
        let start = doc.find(fence).unwrap_or_else(|| panic!("{fence} in the doc")) + fence.len();
        doc[start..][..doc[start..].find("```").unwrap()].to_string()
    };
    assert_eq!(block("```json\n"), square_json());
    let ron = block("```ron\n");
    assert_eq!(read(&ron).unwrap(), read_in(&square_json(), Encoding::Json).unwrap());
}

#[test]
fn the_json_reader_is_strict_with_the_same_codes_as_the_ron_reader() {
    let base = square_json();
    let with = |from: &str, to: &str| {
        assert!(base.contains(from), "{from}");
        base.replacen(from, to, 1)
    };
    let cases: Vec<(&str, String, Code)> = vec![
        ("a number as a JSON number", with("\"1/6\"", "0.5"), Code::Syntax),
        ("a number as a JSON integer", with("\"1/6\"", "1"), Code::Syntax),
        ("an exponent", with("\"version\": 1", "\"version\": 1e0"), Code::Syntax),
        ("a negative integer", with("\"n\": 4", "\"n\": -4"), Code::Syntax),
        ("a leading zero", with("\"n\": 4", "\"n\": 04"), Code::Syntax),
        ("a version as a string", with("\"version\": 1", "\"version\": \"1\""), Code::Syntax),
        (
            "a duplicate key",
            with("    \"claim\"", "    \"claim\": \"EffectivelyInvariant\",\n    \"claim\""),
            Code::DuplicateField,
        ),
        ("a duplicate key in the body", with("\"n\": 4,", "\"n\": 4, \"n\": 4,"), Code::DuplicateField),
        (
            "an unknown key",
            with("    \"claim\"", "    \"confidence\": \"high\",\n    \"claim\""),
            Code::UnknownField,
        ),
        ("an unknown key in the body", with("\"n\": 4,", "\"n\": 4, \"m\": 4,"), Code::UnknownField),
        ("a missing field", with("    \"claim\": \"CompleteChatterFromAllDown\",\n", ""), Code::MissingField),
        ("a missing version", with("    \"version\": 1,\n", ""), Code::MissingField),
        ("an unknown claim", with("CompleteChatterFromAllDown", "CompleteChatter"), Code::UnknownVariant),
        ("an unknown body", with("RegularPolygon", "Cube"), Code::UnknownVariant),
        ("a wrong format", with("chatter-certificate", "zeno-certificate"), Code::WrongFormat),
        ("version 4", with("\"version\": 1", "\"version\": 4"), Code::UnsupportedVersion),
        ("a byte order mark", format!("\u{feff}{base}"), Code::Syntax),
        ("trailing data", format!("{base}[]"), Code::Syntax),
        ("a second object", format!("{base}{base}"), Code::Syntax),
        ("a trailing comma", with("\"-1\"]\n    ],", "\"-1\"],\n    ],"), Code::Syntax),
        ("a comment", with("{\n", "{\n    // note\n"), Code::Syntax),
        ("an escape", with("\"1/100\"", "\"1\\/100\""), Code::Syntax),
        ("a unicode escape", with("\"1/100\"", "\"\\u0031/100\""), Code::Syntax),
        ("null", with("\"hand-written example\"", "null"), Code::Syntax),
        ("true", with("\"hand-written example\"", "true"), Code::Syntax),
        (
            "a struct as an array",
            with("{\"n\": 4, \"kappa\": \"1/6\", \"gamma\": \"1/100\"}", "[4, \"1/6\", \"1/100\"]"),
            Code::Syntax,
        ),
        (
            "a unit variant as an object",
            with("\"ContactVelocities\"", "{\"ContactVelocities\": {}}"),
            Code::Syntax,
        ),
        ("the top level as an array", "[\"chatter-certificate\", 1]".into(), Code::Syntax),
        ("an empty file", " \n".into(), Code::Syntax),
        ("a truncated file", base[..base.len() / 2].to_string(), Code::Syntax),
        ("RON parentheses", with("[\"0\", \"-11/4\", \"-1\"]", "(\"0\", \"-11/4\", \"-1\")"), Code::Syntax),
        ("a non-canonical number", with("\"1/6\"", "\"2/12\""), Code::BadNumber),
        ("a whitespace in a number", with("\"1/6\"", "\" 1/6\""), Code::BadNumber),
        ("two coordinates", with("[\"0\", \"-11/4\", \"-1\"]", "[\"0\", \"-11/4\"]"), Code::WrongArity),
        ("an interval in version 1", with("\"1/6\"", "[\"1/7\", \"1/6\"]"), Code::UnsupportedVersion),
        ("an interval of three numbers", with("\"1/6\"", "[\"1/7\", \"1/6\", \"1/5\"]"), Code::Syntax),
    ];
    for (what, text, code) in &cases {
        assert_eq!(json_code(text), *code, "{what}: {text}");
    }
    // The base file itself is accepted, and a box (version 2) interval reads as an interval.
    assert!(read_in(&base, Encoding::Json).is_ok());
    let boxed = with("\"version\": 1", "\"version\": 2").replacen("\"1/6\"", "[\"1/7\", \"1/6\"]", 1);
    let c = read_in(&boxed, Encoding::Json).unwrap();
    assert_eq!(convert(&write(&c), Encoding::Ron, Target::Json).unwrap(), boxed);
}

#[test]
fn the_limits_apply_to_json_as_to_ron() {
    let base = square_json();
    let long = format!("\"1{}/6\"", "0".repeat(20));
    let text = base.replacen("\"1/6\"", &long, 1);
    let ron = convert(&text, Encoding::Json, Target::Ron).unwrap();
    let limits = ParseLimits { max_digits: 10, ..ParseLimits::default() };
    let a = format!("{:?}", verify_text_in(&text, Encoding::Json, limits, &[MALACHITE]));
    let b = format!("{:?}", verify_text_in(&ron, Encoding::Ron, limits, &[MALACHITE]));
    assert!(a.contains("TooLarge"), "{a}");
    assert_eq!(a, b);
    let limits = ParseLimits { max_generators: 3, ..ParseLimits::default() };
    let a = format!("{:?}", verify_text_in(&base, Encoding::Json, limits, &[MALACHITE]));
    assert!(a.contains("max-generators"), "{a}");
}

/// `chatter ARGS`: (exit status, stdout, stderr).
fn run(args: &[&str]) -> (Option<i32>, String, String) {
    let o = Command::new(bin()).args(args).output().expect("run chatter");
    (
        o.status.code(),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

#[test]
fn convert_writes_both_ways_and_reports_bad_input_with_exit_status_2() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let square = root().join("certificates/valid/doc-example-square.ron");
    let json = d.join("square.json");
    let (code, _, err) =
        run(&["convert", square.to_str().unwrap(), "--to", "json", "-o", json.to_str().unwrap()]);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(std::fs::read_to_string(&json).unwrap(), square_json());
    let (code, out, _) = run(&["convert", json.to_str().unwrap(), "--to", "ron"]);
    assert_eq!(code, Some(0));
    assert_eq!(out, std::fs::read_to_string(&square).unwrap());
    // A gzip'd input is read too.
    let gz = root().join("certificates/invalid/too-many-generators.ron.gz");
    assert_eq!(
        run(&["convert", gz.to_str().unwrap(), "--to", "json", "-o", d.join("g.json").to_str().unwrap()]).0,
        Some(0)
    );
    // Errors: exit 2 with a message, never a panic.
    std::fs::write(d.join("bad.json"), "{\"format\": 1.5}").unwrap();
    std::fs::write(d.join("json-named.ron"), square_json()).unwrap();
    let proof = root().join("proofs/square.ron");
    let invalid = root().join("certificates/invalid/comment.ron");
    for (args, message) in [
        (vec!["convert", "/nonexistent/x.ron", "--to", "json"], "no such file"),
        (vec!["convert", d.join("bad.json").to_str().unwrap(), "--to", "ron"], "[syntax]"),
        (vec!["convert", d.join("json-named.ron").to_str().unwrap(), "--to", "json"], "maps are not part"),
        (vec!["convert", invalid.to_str().unwrap(), "--to", "json"], "comments are not part"),
        (vec!["convert", proof.to_str().unwrap(), "--to", "json"], "no JSON twin"),
        (vec!["convert", d.to_str().unwrap(), "--to", "json"], "not a regular file"),
        (
            vec!["convert", square.to_str().unwrap(), "--to", "json", "-o", "/nonexistent/dir/x.json"],
            "cannot write",
        ),
        (vec!["convert", square.to_str().unwrap(), "--to", "yaml"], "invalid value"),
        (vec!["convert", square.to_str().unwrap()], "--to"),
    ] {
        let (code, _, err) = run(&args);
        assert_eq!(code, Some(2), "{args:?}: {err}");
        assert!(err.contains(message), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
}

#[test]
fn verify_reads_json_files_and_skips_json_that_is_not_a_certificate() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("square.json"), square_json()).unwrap();
    std::fs::write(d.join("bad.JSON"), square_json().replace("\"1/6\"", "\"2/12\"")).unwrap();
    std::fs::write(d.join("broken.json"), "{\"format\": \"chatter-certificate\", \"version\": 1,,}").unwrap();
    std::fs::write(d.join("expected.json"), "[{\"file\": \"bad.JSON\", \"code\": \"bad-number\"}]").unwrap();
    std::fs::write(d.join("summary.json"), "{\"format\": \"something else\", \"points\": 3}").unwrap();
    let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
    std::io::Write::write_all(&mut gz, square_json().as_bytes()).unwrap();
    std::fs::write(d.join("square2.json.gz"), gz.finish().unwrap()).unwrap();
    let l = list(&[d.to_path_buf()]);
    let names: Vec<String> = l
        .entries
        .iter()
        .map(|e| match e {
            chatter::verify::files::Entry::File(p) => p.file_name().unwrap().to_string_lossy().into_owned(),
            other => panic!("{other:?}"),
        })
        .collect();
    assert_eq!(names, ["bad.JSON", "broken.json", "square.json", "square2.json.gz"]);
    assert_eq!(l.skipped.other_json, 2, "expected.json and summary.json");
    let (code, out, _) = run(&["verify", d.to_str().unwrap()]);
    assert_eq!(code, Some(1), "{out}");
    assert!(out.contains("square.json: OK (CompleteChatterFromAllDown, n = 4, 4 generators"), "{out}");
    assert!(out.contains("square2.json.gz: OK (") && out.contains("gzip'd"), "{out}");
    assert!(out.contains("bad.JSON: REJECTED: field `body.kappa`: \"2/12\""), "{out}");
    assert!(out.contains("broken.json: REJECTED: line 1"), "{out}");
    assert!(out.contains("4 files: 2 OK, 2 rejected, 0 errors; 2 skipped (0 not named *.ron, *.ron.gz, *.json or *.json.gz, 2 JSON not a certificate or refutation"), "{out}");
    // A JSON file named explicitly is always checked, whatever it declares.
    let (code, out, _) = run(&["verify", d.join("summary.json").to_str().unwrap()]);
    assert_eq!(code, Some(1));
    assert!(out.contains("REJECTED: field `format`"), "{out}");
    // The text test of the directory search.
    assert!(declares_format("{ \"format\" :\n \"chatter-refutation\" }"));
    // Every kind's format, basin certificates included (their JSON twins were once skipped).
    for kind in ["certificate", "family-certificate", "orbit-certificate", "basin-certificate"] {
        assert!(declares_format(&format!("{{\"format\": \"chatter-{kind}\"}}")), "{kind}");
    }
    assert!(!declares_format("[{\"file\": \"x.ron\", \"code\": \"wrong-format\", \"format\": \"x\"}]"));
}

#[test]
fn the_corpus_directories_verify_with_their_json_twins_and_the_manifest_is_skipped() {
    let valid = root().join("certificates/valid");
    let (code, out, _) = run(&["verify", valid.to_str().unwrap()]);
    assert_eq!(code, Some(0), "{out}");
    let ron = ron_files("certificates/valid").len();
    assert!(out.contains(&format!("{} files: {} OK, 0 rejected, 0 errors", ron + 5, ron + 5)), "{out}");
    assert!(out.contains("basin-icc-n3-kappa1_8-gamma1_2.json: OK (basin, n = 3"), "{out}");
    assert!(
        out.contains("refutation-n4-kappa1_6-gamma1_20.json: OK (refutes EffectivelyInvariant at n = 4"),
        "{out}"
    );
    let manifest = root().join("certificates/invalid/expected.json");
    let (code, out, _) = run(&["verify", "--expect", manifest.to_str().unwrap()]);
    assert_eq!(code, Some(0), "{out}");
    assert!(out.contains("0 mismatches with the manifest"), "{out}");
    assert!(out.contains("1 JSON not a certificate or refutation"), "{out}");
    assert!(!out.contains("expected.json:"), "{out}");
}
