//! The general model on both bignum backends (malachite's `Q`, num-rational's `BigRational`):
//! every map, rest point, cone, quadratic, affine image and error must print identically.

use chatter::exact::{OrderedField, Q};
use chatter_kernel::model::{ConvexBody, ConvexBodyError};
use num_rational::BigRational;
use std::fmt::Display;

type Data = (&'static [(i64, i64, i64)], [(i64, i64); 3], (i64, i64));

/// Bodies as (contacts (x, y, denominator), J entries (xx, xy, yy) as fractions, gamma).
const BODIES: [Data; 4] = [
    (&[(5, -1, 3), (1, 7, 3), (-6, -2, 3)], [(3, 4), (1, 4), (7, 4)], (3, 10)),
    (&[(4, -3, 2), (6, 2, 2), (-1, 5, 2), (-7, -1, 2)], [(1, 2), (-1, 7), (5, 3)], (1, 1)),
    (&[(9, 0, 1), (3, 6, 1), (-4, 5, 1), (-6, -3, 1), (2, -7, 1)], [(8, 1), (2, 1), (1, 1)], (0, 1)),
    (&[(1, 0, 1), (0, 1, 1), (-1, 0, 1), (0, -1, 1)], [(1, 6), (0, 1), (1, 6)], (1, 20)),
];

fn build<F: OrderedField>(d: &Data) -> Result<ConvexBody<F>, ConvexBodyError> {
    let f = |(a, b): (i64, i64)| F::from_ratio(a, b);
    let contacts = d.0.iter().map(|&(x, y, den)| [F::from_ratio(x, den), F::from_ratio(y, den)]).collect();
    let [xx, xy, yy] = d.1;
    ConvexBody::new(contacts, [[f(xx), f(xy)], [f(xy), f(yy)]], f(d.2))
}

fn text<T: Display>(xs: impl IntoIterator<Item = T>) -> Vec<String> {
    xs.into_iter().map(|x| x.to_string()).collect()
}

/// Everything the model computes for a body, printed.
fn summary<F: OrderedField>(b: &ConvexBody<F>) -> Vec<String> {
    let n = b.n() as i64;
    let mut out = Vec::new();
    for k in 0..n {
        out.extend(text(b.impact(k).iter().flatten()));
        out.extend(text(b.edge_rest_point(k)));
        out.extend(text(b.impact_direction(k)));
        let quad = b.pair_pcc_quadratic(k).expect("t = 1 is a root");
        out.extend(text([&quad.p, &quad.q, &quad.discriminant]));
        out.push(format!("{:?}", quad.exclusion()));
        out.push(b.coupling_squared(k, k + 1).to_string());
        for j in (0..n).filter(|&j| j != k) {
            out.extend(text(b.next_contact_cone(k, j).unwrap().iter().flatten()));
            out.extend(text(b.next_contact_generators(k, j).unwrap().iter().flatten()));
        }
    }
    out.extend(text(b.all_down_generators().iter().flatten()));
    let l = [[F::from_ratio(3, 2), F::from_ratio(1, 3)], [F::from_ratio(-1, 5), F::from_i64(2)]];
    let img = chatter::model::affine::affine_image(b, &l).expect("det > 0");
    out.extend(text(img.body.inertia().iter().flatten()));
    out.extend(text(img.velocity_map.iter().flatten()));
    out.extend(text(img.body.impact(1).iter().flatten()));
    out
}

#[test]
fn both_backends_compute_the_same_model() {
    for d in &BODIES {
        let a = summary(&build::<Q>(d).unwrap());
        let b = summary(&build::<BigRational>(d).unwrap());
        assert!(a.len() > 100);
        assert_eq!(a, b);
    }
}

#[test]
fn both_backends_reject_the_same_data() {
    let bad: [Data; 4] = [
        (&[(1, 0, 1), (0, -1, 1), (-1, 0, 1), (0, 1, 1)], [(1, 6), (0, 1), (1, 6)], (1, 2)),
        (&[(1, 0, 1), (0, 1, 1), (-1, 0, 1)], [(1, 6), (0, 1), (1, 6)], (1, 2)),
        (&[(1, 0, 1), (0, 1, 1), (-1, 0, 1), (0, -1, 1)], [(1, 6), (1, 5), (1, 6)], (1, 2)),
        (&[(1, 0, 1), (0, 1, 1), (-1, 0, 1), (0, -1, 1)], [(1, 6), (0, 1), (1, 6)], (3, 2)),
    ];
    for d in &bad {
        let a = build::<Q>(d).unwrap_err();
        assert_eq!(a, build::<BigRational>(d).unwrap_err());
    }
}
