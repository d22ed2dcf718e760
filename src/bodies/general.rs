//! Named general convex bodies (docs/model.md §11, docs/bodies.md): a phone, a brick, a table and
//! a three-legged lander, each built exactly from its 3-D geometry (parts with their masses,
//! positions and own tensors) and reduced to the planar model with J_eff (docs/model.md §11.1).
//! Lengths in the units named; inertia per unit mass about the centre of mass.

use super::convex::rectangle_contacts;
use super::inertia::{Part, Tensor, Vec3, assemble};
use crate::exact::Q;
use chatter_kernel::model::{ConvexBody, ConvexBodyError};

/// A named general body.
#[derive(Clone, Debug)]
pub struct GeneralEntry {
    pub name: &'static str,
    /// The planar model: contacts about the centre of mass, J_eff (docs/model.md §11.1).
    pub body: ConvexBody<Q>,
    /// The full inertia tensor per unit mass about the centre of mass, from the 3-D geometry.
    pub tensor: Tensor,
    /// How the contacts and the tensor were obtained.
    pub derivation: &'static str,
}

fn q(n: i64, d: i64) -> Q {
    Q::new(n, d)
}

fn v3(x: Q, y: Q, z: Q) -> Vec3 {
    [x, y, z]
}

/// The planar model of a body assembled from `parts` resting on `feet` (points in the parts'
/// frame, counter-clockwise, at one height): contacts about the centre of mass and J_eff.
fn from_parts(parts: &[Part], feet: &[Vec3], gamma: Q) -> Result<(ConvexBody<Q>, Tensor), ConvexBodyError> {
    let a = assemble(parts).map_err(|_| ConvexBodyError::InertiaNotPositiveDefinite)?;
    let j = a.tensor.effective().ok_or(ConvexBodyError::InertiaNotPositiveDefinite)?;
    let contacts = feet.iter().map(|f| [&f[0] - &a.centre[0], &f[1] - &a.centre[1]]).collect();
    Ok((ConvexBody::new(contacts, j, gamma)?, a.tensor))
}

/// The three-legged lander (certificates/bodies/lander.ron): a cylinder of 4/5 of the mass
/// (radius 1, height 1.5, centre at the origin) and three legs of 1/15 lumped at their feet,
/// H = 1 m below the cylinder's centre, at (2.2, 0), (-1, ±1.732).
pub fn lander_parts() -> (Vec<Part>, Vec<Vec3>) {
    lander_parts_spread(&q(1, 1))
}

/// The lander with its feet's horizontal positions multiplied by `spread` (> 0; 1 is the
/// catalogue's lander): the legs' masses move with the feet, so J_eff changes with the spread
/// (the body family `lander:spread`, docs/map.md "Body families").
pub fn lander_parts_spread(spread: &Q) -> (Vec<Part>, Vec<Vec3>) {
    let h = q(-1, 1);
    let foot = |x: Q, y: Q| v3(&x * spread, &y * spread, h.clone());
    let feet = vec![foot(q(22, 10), q(0, 1)), foot(q(-1, 1), q(1732, 1000)), foot(q(-1, 1), q(-1732, 1000))];
    let mut parts = vec![Part {
        mass: q(4, 5),
        at: v3(q(0, 1), q(0, 1), q(0, 1)),
        own: Tensor::cylinder(&q(1, 1), &q(3, 2)),
    }];
    parts.extend(feet.iter().map(|f| Part::point(q(1, 15), f.clone())));
    (parts, feet)
}

/// The table: a top 1.2 x 0.8 x 0.04 m (4/5 of the mass, centre 0.74 m up) on four legs 0.72 m
/// long (thin vertical rods of 1/20 each, centres 0.36 m up) at (±0.55, ±0.35), feet at z = 0.
pub fn table_parts() -> (Vec<Part>, Vec<Vec3>) {
    let corners = [(1, -1), (1, 1), (-1, 1), (-1, -1)];
    let leg = |(sx, sy): (i64, i64), z: Q| v3(q(55 * sx, 100), q(35 * sy, 100), z);
    let top = Tensor::uniform_box(&q(12, 10), &q(8, 10), &q(4, 100));
    let mut parts = vec![Part { mass: q(4, 5), at: v3(q(0, 1), q(0, 1), q(74, 100)), own: top }];
    let rod = Tensor::vertical_rod(&q(72, 100));
    parts.extend(corners.iter().map(|&c| Part { mass: q(1, 20), at: leg(c, q(36, 100)), own: rod.clone() }));
    (parts, corners.iter().map(|&c| leg(c, q(0, 1))).collect())
}

/// A uniform box a x b x c standing on its a x b face, centre at the origin.
fn box_parts(a: &Q, b: &Q, c: &Q) -> (Vec<Part>, Vec<Vec3>) {
    let z = -(c / Q::int(2));
    let feet = rectangle_contacts(a, b).into_iter().map(|[x, y]| v3(x, y, z.clone())).collect();
    let origin = v3(q(0, 1), q(0, 1), q(0, 1));
    (vec![Part { mass: q(1, 1), at: origin, own: Tensor::uniform_box(a, b, c) }], feet)
}

/// The lander of [`lander_parts_spread`] with restitution `gamma`: its planar model and full tensor.
pub fn lander_with_spread(spread: &Q, gamma: &Q) -> Result<(ConvexBody<Q>, Tensor), ConvexBodyError> {
    let (parts, feet) = lander_parts_spread(spread);
    from_parts(&parts, &feet, gamma.clone())
}

/// The phone, the brick, the table and the lander with restitution `gamma`, each from its 3-D
/// geometry (full tensor about the centre of mass, reduced to J_eff).
pub fn general_catalogue(gamma: &Q) -> Result<Vec<GeneralEntry>, ConvexBodyError> {
    let build = |(parts, feet): (Vec<Part>, Vec<Vec3>)| from_parts(&parts, &feet, gamma.clone());
    let (phone, phone_t) = build(box_parts(&q(150, 1), &q(75, 1), &q(8, 1)))?;
    let (brick, brick_t) = build(box_parts(&q(215, 1), &q(205, 2), &q(65, 1)))?;
    let (table, table_t) = build(table_parts())?;
    let (lander, lander_t) = build(lander_parts())?;
    Ok(vec![
        GeneralEntry {
            name: "phone",
            body: phone,
            tensor: phone_t,
            derivation: "uniform box 150 x 75 x 8 mm on its 150 x 75 face: I = diag(75^2 + 8^2, 150^2 + 8^2, 150^2 + 75^2)/12, \
                 no products of inertia, J = J_eff",
        },
        GeneralEntry {
            name: "brick",
            body: brick,
            tensor: brick_t,
            derivation: "uniform box 215 x 102.5 x 65 mm on its largest face: I = diag(102.5^2 + 65^2, 215^2 + 65^2, \
                 215^2 + 102.5^2)/12, no products of inertia, J = J_eff",
        },
        GeneralEntry {
            name: "table",
            body: table,
            tensor: table_t,
            derivation: "legs at (+-0.55, +-0.35) m; top 1.2 x 0.8 x 0.04 m (4/5 of the mass, centre 0.74 m up), \
                 four legs 0.72 m long (thin rods, 1/20 each, centres 0.36 m up); centre of mass 83/125 m up; \
                 J_xx = 4/5 ((0.8^2 + 0.04^2)/12 + (0.74 - 0.664)^2) + 1/5 (0.35^2 + 0.72^2/12 + (0.36 - 0.664)^2) \
                 = 74263/750000, J_yy likewise with 1.2 and 0.55 = 141263/750000 (m^2); symmetric: no products \
                 of inertia, J = J_eff",
        },
        GeneralEntry {
            name: "lander",
            body: lander,
            tensor: lander_t,
            derivation: "certificates/bodies/lander.ron: a cylinder of 4/5 of the mass (radius 1, height 1.5 m, centre \
                 at the origin) and three legs of 1/15 lumped at their feet (2.2, 0, -1), (-1, +-1.732, -1) m; \
                 centre of mass (1/75, 0, -1/5); full tensor from the parts (I_xz = 4/375 from the feet's depth and the cylinder's height), \
                 J_eff = J - b b^T / I_zz, b = (I_xz, I_yz)",
        },
    ])
}
