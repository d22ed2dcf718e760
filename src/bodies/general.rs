//! Named general convex bodies (docs/model.md §11, docs/bodies.md): a phone, a brick, a table and
//! a three-legged lander, as exact data with their derivations. Lengths in the units named;
//! inertia per unit mass about the centre of mass.

use super::convex::uniform_box;
use crate::exact::Q;
use chatter_kernel::model::{ConvexBody, ConvexBodyError};

/// A named general body.
#[derive(Clone, Debug)]
pub struct GeneralEntry {
    pub name: &'static str,
    pub body: ConvexBody<Q>,
    /// How the contacts and J were obtained.
    pub derivation: &'static str,
}

fn q(n: i64, d: i64) -> Q {
    Q::new(n, d)
}

/// The phone, the brick, the table and the lander with restitution `gamma`.
pub fn general_catalogue(gamma: &Q) -> Result<Vec<GeneralEntry>, ConvexBodyError> {
    let g = || gamma.clone();
    let phone = uniform_box(&q(150, 1), &q(75, 1), &q(8, 1), g())?;
    let brick = uniform_box(&q(215, 1), &q(205, 2), &q(65, 1), g())?;
    let corners = |x: Q, y: Q| vec![[x.clone(), -&y], [x.clone(), y.clone()], [-&x, y.clone()], [-&x, -&y]];
    let table = ConvexBody::new(
        corners(q(55, 100), q(35, 100)),
        [[q(74263, 750000), q(0, 1)], [q(0, 1), q(141263, 750000)]],
        g(),
    )?;
    let lander = ConvexBody::new(
        vec![
            [&q(22, 10) - &q(1, 75), q(0, 1)],
            [&q(-1, 1) - &q(1, 75), q(1732, 1000)],
            [&q(-1, 1) - &q(1, 75), q(-1732, 1000)],
        ],
        [[q(75, 100), q(0, 1)], [q(0, 1), q(806, 1000)]],
        g(),
    )?;
    Ok(vec![
        GeneralEntry {
            name: "phone",
            body: phone,
            derivation: "uniform box 150 x 75 x 8 mm on its 150 x 75 face: J = diag(75^2 + 8^2, 150^2 + 8^2)/12",
        },
        GeneralEntry {
            name: "brick",
            body: brick,
            derivation: "uniform box 215 x 102.5 x 65 mm on its largest face: J = diag(102.5^2 + 65^2, 215^2 + 65^2)/12",
        },
        GeneralEntry {
            name: "table",
            body: table,
            derivation: "legs at (+-0.55, +-0.35) m; top 1.2 x 0.8 x 0.04 m (4/5 of the mass, centre 0.74 m up), \
                 four legs 0.72 m long (1/20 each, centres 0.36 m up); centre of mass 83/125 m up; \
                 J_xx = 4/5 ((0.8^2 + 0.04^2)/12 + (0.74 - 0.664)^2) + 1/5 (0.35^2 + 0.72^2/12 + (0.36 - 0.664)^2) \
                 = 74263/750000, J_yy likewise with 1.2 and 0.55 = 141263/750000 (m^2)",
        },
        GeneralEntry {
            name: "lander",
            body: lander,
            derivation: "certificates/bodies/lander.ron: feet at (2.2, 0), (-1, +-1.732) m, centre of mass \
                 (1/75, 0); a cylinder of 4/5 of the mass (radius 1, height 1.5) and three legs of 1/15 \
                 lumped at the feet: J = diag(0.75, 0.806) m^2",
        },
    ])
}
