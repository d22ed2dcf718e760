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
