//! The impact sequence in words.

use chatter::simulate::Shape;
use chatter::simulate::pattern::{Kind, find, steps, summary_for};

fn seq(s: &str) -> Vec<u8> {
    s.split(',').map(|x| x.parse().unwrap()).collect()
}

#[test]
fn rotations_pairs_and_transients_are_named() {
    let s = seq("2,0,1,2,0,1,2,0,1,2,0");
    let p = find(&s).unwrap();
    assert_eq!((p.transient, p.cycle.clone()), (0, vec![2, 0, 1]));
    assert_eq!(p.kind(Shape::Polygon(3)), Kind::Rotation(1));
    assert_eq!(
        summary_for(&s, Shape::Polygon(3)),
        "cycles 2→0→1 (S_1 repeated: each impact followed by its counter-clockwise neighbour) from the first impact (11 impacts)"
    );

    let s = seq("1,3,0,2,0,2,0,2,0,2");
    let p = find(&s).unwrap();
    assert_eq!(p.transient, 2);
    assert_eq!(p.kind(Shape::Polygon(4)), Kind::DistantPair);
    assert_eq!(
        summary_for(&s, Shape::Polygon(4)),
        "1,3 (2 impacts), then 0,2,0,2 (non-adjacent pair: rod-like) (8 impacts)"
    );

    let s = seq("1,2,0,1,0,1,0,1");
    assert_eq!(find(&s).unwrap().kind(Shape::Polygon(3)), Kind::AdjacentPair);
    assert!(
        summary_for(&s, Shape::Polygon(3)).ends_with("then 0,1,0,1 (adjacent pair: PCC-like) (6 impacts)"),
        "{}",
        summary_for(&s, Shape::Polygon(3))
    );

    let s = seq("0,3,2,1,0,3,2,1,0,3,2,1");
    assert_eq!(find(&s).unwrap().kind(Shape::Polygon(4)), Kind::Rotation(3));
    assert!(summary_for(&s, Shape::Polygon(4)).contains("clockwise neighbour"));

    let s = seq("0,1,0,1,0,1");
    assert_eq!(find(&s).unwrap().kind(Shape::Rod), Kind::RodEnds);
    assert!(summary_for(&s, Shape::Rod).contains("the two ends alternate"));
}

#[test]
fn mixed_cycles_list_their_steps() {
    let s = seq("0,2,0,2,1,2,1,2,0,2,0,2,1,2,1,2,0,2,0,2,1,2,1,2");
    let p = find(&s).unwrap();
    assert_eq!(p.cycle.len(), 8);
    assert_eq!(steps(&p.cycle, 3), vec![2, 1, 2, 2, 1, 2, 1, 1]);
    assert!(
        summary_for(&s, Shape::Polygon(3)).contains("steps S_2 S_1 S_2 S_2 S_1 S_2 S_1 S_1"),
        "{}",
        summary_for(&s, Shape::Polygon(3))
    );
}

#[test]
fn short_or_irregular_sequences_are_listed() {
    assert_eq!(summary_for(&[], Shape::Polygon(4)), "no impacts");
    assert_eq!(summary_for(&[2], Shape::Polygon(4)), "2 (1 impact, no settled pattern)");
    assert!(find(&seq("0,1,2,0,2,1,0,2")).is_none());
    // A random walk on the square's contacts, never the same contact twice in a row.
    let mut rng = chatter::simulate::SplitMix64::new(3);
    let mut long = vec![0u8];
    while long.len() < 100 {
        let next = (long[long.len() - 1] + 1 + (rng.next_u64() % 3) as u8) % 4;
        long.push(next);
    }
    assert!(find(&long).is_none());
    let s = summary_for(&long, Shape::Polygon(4));
    assert!(s.contains('…'), "{s}");
}
