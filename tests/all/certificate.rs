//! Tests of `certificate`: the two-stage reader, the writer, the schema's error codes.

use chatter::write::write;
use chatter_kernel::certificate::{Body, Certificate, Claim, Code, Coordinates, FORMAT, Generator, read};

fn sample() -> Certificate {
    Certificate {
        format: FORMAT.into(),
        version: 1,
        body: Body::RegularPolygon { n: 4, kappa: "1/6".into(), gamma: "1/100".into() },
        coordinates: Coordinates::ContactVelocities,
        claim: Claim::CcOrPccFromAllDown,
        cone: vec![
            Generator(vec!["0".into(), "-11/4".into(), "-1".into()]),
            Generator(vec!["1/20".into(), "3/4".into(), "-1".into()]),
        ],
        time_to_rest_bound: None,
        producer: "a \"quoted\" producer\nwith a newline".into(),
    }
}

#[test]
fn the_writer_round_trips_and_is_stable() {
    let c = sample();
    let text = write(&c);
    // The strict syntax has no escapes: characters it cannot write in a string become spaces,
    // which only the free-text producer can contain.
    let back = read(&text).unwrap();
    assert_eq!(back.producer, "a  quoted  producer with a newline");
    assert_eq!(Certificate { producer: c.producer.clone(), ..back.clone() }, c);
    assert_eq!(write(&back), text);
    assert!(text.starts_with("Certificate(\n    format: \"chatter-certificate\",\n    version: 1,\n"));
    assert!(text.contains("    cone: [\n        (\"0\", \"-11/4\", \"-1\"),\n"));
}

#[test]
fn struct_name_and_field_order_are_free_and_producer_is_optional() {
    let text = r#"(
        claim: EffectivelyInvariant,
        cone: [("1", "2", "-3")],
        coordinates: ContactVelocities,
        body: RegularPolygon(gamma: "0", kappa: "2", n: 6),
        version: 1,
        format: "chatter-certificate",
    )"#;
    let c = read(text).unwrap();
    assert_eq!(c.producer, "");
    assert_eq!(c.claim, Claim::EffectivelyInvariant);
    assert_eq!(c.body, Body::RegularPolygon { n: 6, kappa: "2".into(), gamma: "0".into() });
}

fn code_of(text: &str) -> (Code, String) {
    let r = read(text).unwrap_err();
    (r.code, r.message())
}

#[test]
fn header_errors_come_before_schema_errors() {
    let base = write(&sample());
    let (c, m) = code_of(&base.replace("version: 1", "version: 7").replace("producer", "extra: 1, producer"));
    assert_eq!(c, Code::UnsupportedVersion, "{m}");
    assert!(m.contains("version 7"));
    let (c, m) = code_of(&base.replace("\"chatter-certificate\"", "\"other\""));
    assert_eq!(c, Code::WrongFormat);
    assert!(m.contains("field `format`") && m.contains("\"other\""));
    let (c, _) = code_of(&base.replace("    format: \"chatter-certificate\",\n", ""));
    assert_eq!(c, Code::MissingField);
}

#[test]
fn schema_errors_name_the_field_and_position() {
    let base = write(&sample());
    let (c, m) = code_of(&base.replace("    producer", "    colour: \"red\",\n    producer"));
    assert_eq!(c, Code::UnknownField);
    assert!(m.contains("colour") && m.starts_with("line "), "{m}");
    let (c, m) = code_of(&base.replace("    coordinates: ContactVelocities,\n", ""));
    assert_eq!(c, Code::MissingField);
    assert!(m.contains("coordinates"), "{m}");
    let (c, m) = code_of(&base.replace("claim: CcOrPccFromAllDown", "claim: Zeno"));
    assert_eq!(c, Code::UnknownVariant);
    assert!(m.contains("Zeno") && m.contains("line 6"), "{m}");
    let (c, m) = code_of(&base.replace("n: 4, ", "n: 4, m: 3, "));
    assert_eq!(c, Code::UnknownField, "unknown fields inside the body are denied too: {m}");
    let (c, _) = code_of(&base.replace("n: 4", "n: -4"));
    assert_eq!(c, Code::Syntax);
    let (c, _) = code_of("not ron at all");
    assert_eq!(c, Code::Syntax);
    let (c, _) = code_of(&base[..base.len() / 2]);
    assert_eq!(c, Code::Syntax);
}

#[test]
fn generators_keep_their_arity_for_the_kernel_to_judge() {
    let base = write(&sample());
    let c = read(&base.replace("(\"0\", \"-11/4\", \"-1\")", "(\"0\", \"-1\")")).unwrap();
    assert_eq!(c.cone[0].0.len(), 2);
    let c = read(&base.replace("(\"0\", \"-11/4\", \"-1\")", "(\"0\", \"-1\", \"2\", \"3\")")).unwrap();
    assert_eq!(c.cone[0].0.len(), 4);
}

#[test]
fn codes_have_stable_kebab_case_names() {
    assert_eq!(Code::ImageOutside.as_str(), "image-outside");
    assert_eq!(serde_json::to_string(&Code::PccNotExcluded).unwrap(), "\"pcc-not-excluded\"");
    assert_eq!(
        Claim::ALL.map(Claim::name),
        ["EffectivelyInvariant", "CcOrPccFromAllDown", "CompleteChatterFromAllDown"]
    );
    assert!(Claim::EffectivelyInvariant < Claim::CcOrPccFromAllDown);
    assert!(Claim::CcOrPccFromAllDown < Claim::CompleteChatterFromAllDown);
}
