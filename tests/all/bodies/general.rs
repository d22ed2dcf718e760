//! The named general bodies (phone, brick, table, lander; docs/bodies.md) are valid and simulate.

use chatter::bodies::general::general_catalogue;
use chatter::exact::Q;
use chatter::simulate::{Arithmetic, Model, Options, Outcome, counts, simulate_many};

#[test]
fn the_named_general_bodies_are_valid_and_simulate_at_low_gamma() {
    // The brick and the table carry much inertia against their contact distances (a large kappa),
    // so at gamma = 1/100 they leave (ICC) on every drop; the flat phone chatters to rest (CC) and
    // the lander's two rear feet chatter to rest first (PCC; at gamma = 1/20 it is CC).
    let all = general_catalogue(&Q::new(1, 100)).expect("valid bodies");
    let names: Vec<&str> = all.iter().map(|e| e.name).collect();
    assert_eq!(names, ["phone", "brick", "table", "lander"]);
    for e in &all {
        let m = Model::convex(&e.body);
        let runs = simulate_many(&m, 0, 20, Arithmetic::Float, &Options::new(200), &|| {});
        let c = counts(&runs);
        let expected = match e.name {
            "phone" => 0,
            "lander" => 1,
            _ => 2,
        };
        assert_eq!(c[expected], 20, "{}: {c:?} ({:?})", e.name, Outcome::ALL);
    }
}

#[test]
fn the_lander_file_and_the_catalogue_agree() {
    let text =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/certificates/bodies/lander.ron"))
            .unwrap();
    let data = chatter::bodies::file::BodyFile::parse(&text).unwrap().data().unwrap();
    let lander = general_catalogue(&Q::new(1, 20)).unwrap().into_iter().find(|e| e.name == "lander").unwrap();
    assert_eq!(data.contacts, lander.body.contacts());
    assert_eq!(&data.inertia, lander.body.inertia());
    assert_eq!(data.gamma, Some(Q::new(1, 20)));
}

fn read(text: &str) -> Result<chatter::bodies::file::BodyData, String> {
    chatter::bodies::file::BodyFile::parse(text).and_then(|f| f.data())
}

#[test]
fn body_files_in_json_and_with_mass_and_origin_give_the_same_planar_model() {
    let lander = general_catalogue(&Q::new(1, 20)).unwrap().remove(3);
    let json = r#"{"contacts": [["2.2", "0", "-1"], ["-1", "1.732", "-1"], ["-1", "-1.732", "-1"]],
        "inertia_tensor": ["853103/937500", "0", "4/375", "21731/22500", "0", "1765967/1406250"],
        "centre": ["1/75", "0", "-1/5"]}"#;
    let data = read(json).unwrap();
    assert_eq!(data.contacts, lander.body.contacts());
    assert_eq!(&data.inertia, lander.body.inertia());
    assert_eq!(data.tensor.as_ref(), Some(&lander.tensor));
    assert_eq!(data.gamma, None);
    // The same tensor given for a mass of 3 about the cylinder's centre (the origin): the
    // parallel-axis theorem, done here by hand, I_O = I_c + |c|^2 E - c c^T.
    let c = [Q::new(1, 75), Q::int(0), Q::new(-1, 5)];
    let about_origin = lander.tensor.plus(&chatter::bodies::inertia::Tensor::point(&c)).scaled(&Q::int(3));
    let six: Vec<String> = about_origin.urdf().iter().map(|x| format!("\"{x}\"")).collect();
    let ron = format!(
        "(contacts: [(\"2.2\", \"0\", \"-1\"), (\"-1\", \"1.732\", \"-1\"), (\"-1\", \"-1.732\", \"-1\")],
          inertia_tensor: ({}), mass: \"3\", inertia_origin: (\"0\", \"0\", \"0\"),
          centre: (\"1/75\", \"0\", \"-1/5\"), gamma: \"1/20\")",
        six.join(", ")
    );
    let data = read(&ron).unwrap();
    assert_eq!(&data.inertia, lander.body.inertia());
    assert_eq!(data.gamma, Some(Q::new(1, 20)));
}

#[test]
fn body_file_errors_name_the_problem() {
    let base = r#"(contacts: [("1", "0", "-1"), ("0", "1", "-1"), ("-1", "-1", "-1")], "#;
    for (rest, want) in [
        (r#"inertia_tensor: ("1", "0", "0", "1", "0", "3"))"#, "triangle inequality"),
        (r#"inertia_tensor: ("1", "0", "2", "1", "0", "1"))"#, "not positive definite"),
        (r#"inertia: ("1", "0", "1"), inertia_tensor: ("1", "0", "0", "1", "0", "1"))"#, "not both"),
        (r#"inertia: ("1", "0", "1"), mass: "2")"#, "go with inertia_tensor"),
        (r#"inertia_tensor: ("1", "0", "0", "1", "0", "1"), mass: "0")"#, "mass: must be > 0"),
        (
            r#"inertia_tensor: ("1", "0", "0", "1", "0", "1"), inertia_origin: ("0", "0", "0"))"#,
            "centre of mass in 3-D",
        ),
        (r#")"#, "missing inertia"),
    ] {
        let e = read(&format!("{base}{rest}")).unwrap_err();
        assert!(e.contains(want), "{rest}: {e}");
    }
    let uneven =
        r#"(contacts: [("1", "0", "-1"), ("0", "1", "-1"), ("-1", "-1", "0")], inertia: ("1", "0", "1"))"#;
    assert!(read(uneven).unwrap_err().contains("one horizontal plane"));
    let mixed = r#"(contacts: [("1", "0", "-1"), ("0", "1"), ("-1", "-1", "-1")], inertia: ("1", "0", "1"))"#;
    assert!(read(mixed).unwrap_err().contains("every contact or for none"));
}

#[test]
fn the_lander_in_urdf_gives_the_catalogue_s_planar_model() {
    use chatter::bodies::urdf::read;
    let text =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/certificates/bodies/lander.urdf"))
            .unwrap();
    let lander = general_catalogue(&Q::new(1, 20)).unwrap().remove(3);
    // foot_* sorts the feet counter-clockwise (the file lists them clockwise).
    for names in [vec!["foot_*"], vec!["foot_a", "foot_c_joint", "foot_b"]] {
        let names: Vec<String> = names.into_iter().map(String::from).collect();
        let data = read(&text, &names).and_then(|f| f.data()).unwrap();
        assert_eq!(data.contacts, lander.body.contacts(), "{names:?}");
        assert_eq!(&data.inertia, lander.body.inertia());
        assert_eq!(data.tensor.as_ref(), Some(&lander.tensor));
    }
    let err = |text: &str, names: &[&str]| {
        let names: Vec<String> = names.iter().map(|s| s.to_string()).collect();
        read(text, &names).and_then(|f| f.data()).unwrap_err()
    };
    assert!(err(&text, &[]).contains("needs --contacts"));
    assert!(err(&text, &["foot_x"]).contains("no fixed joint of the body link is named \"foot_x\""));
    assert!(err(&text, &["leg_*"]).contains("no fixed joint of the body link matches"));
    let rotated = text.replace("rpy=\"0 0 0\"", "rpy=\"0 0 0.1\"");
    assert!(err(&rotated, &["foot_*"]).contains("rpy != 0"));
    let two = text.replace(
        "<link name=\"foot_a\"/>",
        "<link name=\"foot_a\"><inertial><mass value=\"1\"/></inertial></link>",
    );
    assert!(err(&two, &["foot_*"]).contains("2 links have mass (body, foot_a)"));
    assert!(err("<robot><link", &["a"]).contains("not URDF"));
}
