//! Standard general convex bodies as exact data (docs/model.md §11): the uniform plate of a
//! convex polygon (inertia from its exact second moments about the centroid, coordinates shifted
//! to the centroid), the uniform rectangular plate, the uniform box standing on a face, and the
//! regular n-gon with isotropic inertia (R = 1) for n = 3, 4, 6.
//!
//! Conventions: contact points in the body's horizontal frame through the centre of mass; the
//! inertia J per unit mass with J = [[int y^2 + z^2, -int x y], [-int x y, int x^2 + z^2]] / m, so
//! a flat body has J = P S P^T with S = int r r^T dm / m and P = [[0, 1], [-1, 0]].

use crate::exact::{Algebraic, CosField, OrderedField, Q};
use chatter_kernel::exact::OrderedField as _;
use chatter_kernel::model::{ConvexBody, ConvexBodyError, MAX_CONTACTS, Mat2, Vec2, check_convex_polygon};

/// Twice the signed area of the triangle (0, a, b): a_x b_y - b_x a_y.
fn cross<F: OrderedField>(a: &Vec2<F>, b: &Vec2<F>) -> F {
    a[0].times(&b[1]).minus(&b[0].times(&a[1]))
}

/// The area of a counter-clockwise polygon and its centroid.
fn area_centroid<F: OrderedField>(pts: &[Vec2<F>]) -> Option<(F, Vec2<F>)> {
    let n = pts.len();
    let (mut a2, mut cx, mut cy) = (F::zero(), F::zero(), F::zero());
    for k in 0..n {
        let (p, q) = (&pts[k], &pts[(k + 1) % n]);
        let c = cross(p, q);
        a2 = a2.plus(&c);
        cx = cx.plus(&c.times(&p[0].plus(&q[0])));
        cy = cy.plus(&c.times(&p[1].plus(&q[1])));
    }
    // A = a2 / 2, centroid = sum / (6 A) = sum / (3 a2).
    let three_a2 = F::from_i64(3).times(&a2);
    Some((a2.times(&F::from_ratio(1, 2)), [cx.over(&three_a2)?, cy.over(&three_a2)?]))
}

/// S = int r r^T dA / A about the origin, for a counter-clockwise polygon (the polygon
/// formulas: int x^2 dA = 1/12 sum c_k (x_k^2 + x_k x_{k+1} + x_{k+1}^2), int x y dA =
/// 1/24 sum c_k (x_k y_{k+1} + 2 x_k y_k + 2 x_{k+1} y_{k+1} + x_{k+1} y_k), c_k = r_k x r_{k+1}).
fn second_moments<F: OrderedField>(pts: &[Vec2<F>], area: &F) -> Option<Mat2<F>> {
    let n = pts.len();
    let (mut sxx, mut syy, mut sxy) = (F::zero(), F::zero(), F::zero());
    for k in 0..n {
        let (p, q) = (&pts[k], &pts[(k + 1) % n]);
        let c = cross(p, q);
        let quad = |a: &F, b: &F| a.times(a).plus(&a.times(b)).plus(&b.times(b));
        sxx = sxx.plus(&c.times(&quad(&p[0], &q[0])));
        syy = syy.plus(&c.times(&quad(&p[1], &q[1])));
        let two = F::from_i64(2);
        let mixed = p[0].times(&q[1]).plus(&q[0].times(&p[1]));
        let diag = two.times(&p[0].times(&p[1]).plus(&q[0].times(&q[1])));
        sxy = sxy.plus(&c.times(&mixed.plus(&diag)));
    }
    let (d12, d24) = (F::from_i64(12).times(area), F::from_i64(24).times(area));
    let (sxx, syy, sxy) = (sxx.over(&d12)?, syy.over(&d12)?, sxy.over(&d24)?);
    Some([[sxx, sxy.clone()], [sxy, syy]])
}

/// J = P S P^T = [[S_yy, -S_xy], [-S_xy, S_xx]]: the horizontal inertia of a flat body with
/// second moments S (docs/model.md §11.7).
pub fn flat_inertia<F: OrderedField>(s: &Mat2<F>) -> Mat2<F> {
    [[s[1][1].clone(), s[0][1].negated()], [s[1][0].negated(), s[0][0].clone()]]
}

/// The centroid c and the second moments S = int (r - c)(r - c)^T dA / A of a uniform plate of
/// the strictly convex counter-clockwise polygon `vertices` (in any frame).
pub fn plate_moments<F: OrderedField>(vertices: &[Vec2<F>]) -> Result<(Vec2<F>, Mat2<F>), ConvexBodyError> {
    check_convex_polygon(vertices)?;
    // A strictly convex counter-clockwise polygon has positive area: the divisions below succeed
    // (the error is unreachable).
    let (_, c) = area_centroid(vertices).ok_or(ConvexBodyError::Clockwise)?;
    let shifted = shift(vertices, &c);
    let (area, _) = area_centroid(&shifted).ok_or(ConvexBodyError::Clockwise)?;
    let s = second_moments(&shifted, &area).ok_or(ConvexBodyError::Clockwise)?;
    Ok((c, s))
}

fn shift<F: OrderedField>(pts: &[Vec2<F>], c: &Vec2<F>) -> Vec<Vec2<F>> {
    pts.iter().map(|p| [p[0].minus(&c[0]), p[1].minus(&c[1])]).collect()
}

/// The uniform flat plate of the strictly convex counter-clockwise polygon `vertices` (any
/// frame): contacts at its vertices, shifted so that the centroid is the origin (same labels),
/// inertia J = P S P^T from its exact second moments about the centroid.
pub fn polygon_plate<F: OrderedField>(
    vertices: &[Vec2<F>],
    gamma: F,
) -> Result<ConvexBody<F>, ConvexBodyError> {
    let (c, s) = plate_moments(vertices)?;
    ConvexBody::new(shift(vertices, &c), flat_inertia(&s), gamma)
}

/// The corners of an a x b rectangle centred at the origin, sides along the axes, counter-
/// clockwise from (a/2, -b/2): the images of the square's contacts (1, 0), (0, 1), (-1, 0),
/// (0, -1) under L = [[a/2, a/2], [-b/2, b/2]] (docs/model.md §11.7).
pub fn rectangle_contacts<F: OrderedField>(a: &F, b: &F) -> Vec<Vec2<F>> {
    let half = F::from_ratio(1, 2);
    let (x, y) = (a.times(&half), b.times(&half));
    vec![
        [x.clone(), y.negated()],
        [x.clone(), y.clone()],
        [x.negated(), y.clone()],
        [x.negated(), y.negated()],
    ]
}

/// The uniform rectangular plate a x b (a > 0 along x, b > 0 along y): J = diag(b^2, a^2) / 12.
pub fn rectangle_plate<F: OrderedField>(a: &F, b: &F, gamma: F) -> Result<ConvexBody<F>, ConvexBodyError> {
    uniform_box(a, b, &F::zero(), gamma)
}

/// The uniform box a x b x c standing on its a x b face (a phone, a brick): contacts at the
/// corners of that face, J = diag(b^2 + c^2, a^2 + c^2) / 12 (the box's inertia tensor about its
/// centre per unit mass; the face's depth c/2 below the centre does not enter, docs/model.md §11.1).
pub fn uniform_box<F: OrderedField>(a: &F, b: &F, c: &F, gamma: F) -> Result<ConvexBody<F>, ConvexBodyError> {
    let twelfth = F::from_ratio(1, 12);
    let c2 = c.times(c);
    let jxx = b.times(b).plus(&c2).times(&twelfth);
    let jyy = a.times(a).plus(&c2).times(&twelfth);
    let (z, z2) = (F::zero(), F::zero());
    ConvexBody::new(rectangle_contacts(a, b), [[jxx, z], [z2, jyy]], gamma)
}

/// The regular n-gon with circumradius 1, contact k at angle 2 pi k / n, isotropic inertia
/// J = kappa I (docs/model.md §1-2 in the paper's coordinates). `cos1`, `sin1` must be
/// cos(2 pi/n), sin(2 pi/n) exactly, in a field that contains both (checked: cos1^2 + sin1^2 = 1,
/// sin1 > 0, T_n(cos1) = 1 and T_m(cos1) != 1 for 0 < m < n).
pub fn regular_polygon<F: OrderedField>(
    n: usize,
    cos1: &F,
    sin1: &F,
    kappa: F,
    gamma: F,
) -> Result<ConvexBody<F>, String> {
    let unit = cos1.times(cos1).plus(&sin1.times(sin1)) == F::one();
    if !(3..=MAX_CONTACTS).contains(&n) || !unit || !sin1.is_positive() {
        return Err(format!("(cos1, sin1) is not (cos, sin)(2 pi/{n}) with 3 <= n <= {MAX_CONTACTS}"));
    }
    // T_m(c) and U_{m-1}(c) for m = 0..n: cos and sin / sin1 of 2 pi m / n.
    let two_c = cos1.times(&F::from_i64(2));
    let (mut t, mut u) = (vec![F::one(), cos1.clone()], vec![F::zero(), F::one()]);
    for m in 2..=n {
        t.push(two_c.times(&t[m - 1]).minus(&t[m - 2]));
        u.push(two_c.times(&u[m - 1]).minus(&u[m - 2]));
    }
    if t[n] != F::one() || (1..n).any(|m| t[m] == F::one()) {
        return Err(format!("cos1 is not cos(2 pi/{n})"));
    }
    let contacts = (0..n).map(|k| [t[k].clone(), sin1.times(&u[k])]).collect();
    let (z, z2) = (F::zero(), F::zero());
    ConvexBody::new(contacts, [[kappa.clone(), z], [z2, kappa]], gamma).map_err(|e| e.to_string())
}

/// The regular n-gon for n = 3, 4, 6 (rational cos 2 pi/n) with J = kappa I, exactly: in
/// Q(sqrt 3) = Q(cos 2 pi/12) for n = 3, 6 (sin 2 pi/n = sqrt 3 / 2 = cos 2 pi/12), rational for
/// n = 4.
pub fn regular_polygon_exact(n: usize, kappa: &Q, gamma: &Q) -> Result<ConvexBody<Algebraic<Q>>, String> {
    let field = CosField::<Q>::new(12).ok_or("Q(cos 2 pi/12) is always available")?;
    let (c, s) = match n {
        3 => (Algebraic::from_ratio(-1, 2), field.generator()),
        4 => (Algebraic::from_ratio(0, 1), Algebraic::from_ratio(1, 1)),
        6 => (Algebraic::from_ratio(1, 2), field.generator()),
        _ => return Err(format!("n = {n}: exact regular polygons here are n = 3, 4, 6")),
    };
    regular_polygon(n, &c, &s, Algebraic::rational(kappa.clone()), Algebraic::rational(gamma.clone()))
}

/// The exact body a file's `ConvexPolygon` names, at each end of its γ (one for a number): the
/// model's checks as error text (the kernel decides a file's acceptance).
pub fn of_text(b: &chatter_kernel::syntax::family::ConvexBodyText) -> Result<Vec<ConvexBody<Q>>, String> {
    use chatter_kernel::syntax::cone::Param;
    let q = |text: &str| text.parse::<Q>().map_err(|e| format!("{text:?}: {e}"));
    let chatter_kernel::syntax::family::ConvexBodyText::ConvexPolygon { contacts, inertia, gamma, .. } = b;
    let pts = contacts.iter().map(|(x, y)| Ok([q(x)?, q(y)?])).collect::<Result<Vec<_>, String>>()?;
    let jxy = q(&inertia.1)?;
    let j = [[q(&inertia.0)?, jxy.clone()], [jxy, q(&inertia.2)?]];
    let body = |g: &str| {
        ConvexBody::new(pts.clone(), j.clone(), q(g)?).map_err(|e| format!("the body is not valid: {e}"))
    };
    match gamma {
        Param::Point(g) => Ok(vec![body(g)?]),
        Param::Interval(lo, hi) => Ok(vec![body(lo)?, body(hi)?]),
    }
}
