//! Certificates for general convex bodies (format `chatter-family-certificate`, docs/certificate-format.md §13) by
//! transport from a regular n-gon certificate (untrusted: the kernel re-checks every output).
//!
//! A regular n-gon certificate gives one cone K in contact coordinates (u0, u1, v) relabelled at
//! the last contact (docs/model.md §2-§5). Its family in the paper's coordinates p = (omega_x,
//! omega_y, v) is K_i = R^i W^-1 K (docs/model.md §11.5), i.e. K_i = { p : (u_i(p), u_{i+1}(p),
//! v) ∈ K }, the velocities whose speeds, relabelled at contact i, lie in K. By the Theorem on
//! affine images (docs/model.md §11.7) the image body's family is T K_i, and since
//! u'_k(T p) = u_k(p) and T keeps v, T K_i = { p' : (u'_i(p'), u'_{i+1}(p'), v') ∈ K }: the same
//! formula with the image's contacts. So every generator g of K gives the generator W_i'^-1 g of
//! K'_i, where W_i' has rows f'_i, f'_{i+1}, (0, 0, 1): exact and rational whenever the image's
//! contacts are, even for the triangle, whose own coordinates lie in Q(sqrt 3).

use crate::exact::{Q, Ring};
use chatter_kernel::certificate::{
    Body, Certificate, ConvexBodyText, ConvexCertificate, ConvexCoordinates, Generator, Param,
};
use chatter_kernel::exact::OrderedField;
use chatter_kernel::exact::to_canonical;
use chatter_kernel::model::linalg::Vec3;
use chatter_kernel::model::{ConvexBody, ConvexBodyError, Mat2, Vec2};
use chatter_kernel::syntax::family;

/// Why a regular certificate cannot be transported to a body.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum TransportError {
    /// The certificate is not a point certificate of a regular polygon with n >= 3 in contact
    /// coordinates (a box, the rod, or a number-field certificate).
    NotTransportable(String),
    /// The certificate's n differs from the body's number of contacts.
    ContactCount { certificate: u64, body: usize },
    /// A generator is not three rational numbers.
    BadGenerator(usize),
}

impl std::fmt::Display for TransportError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            TransportError::NotTransportable(why) => write!(f, "cannot transport: {why}"),
            TransportError::ContactCount { certificate, body } => {
                write!(f, "the certificate is for n = {certificate}, the body has {body} contacts")
            }
            TransportError::BadGenerator(i) => write!(f, "generator {i} is not three rational numbers"),
        }
    }
}

impl std::error::Error for TransportError {}

/// The velocity p = (omega_x, omega_y, v) with u_i(p) = g0, u_{i+1}(p) = g1 and v = g2, for
/// contacts r_i, r_{i+1} with D = x_i y_{i+1} - x_{i+1} y_i > 0 (docs/model.md §11.3): W_i^-1 g.
pub fn from_contact_speeds(ri: &Vec2<Q>, rj: &Vec2<Q>, g: &Vec3<Q>) -> Vec3<Q> {
    let d = ri[0].times(&rj[1]).minus(&rj[0].times(&ri[1]));
    let (a, b) = (g[0].minus(&g[2]), g[1].minus(&g[2]));
    // y_i wx - x_i wy = a, y_j wx - x_j wy = b.
    let wx = ri[0].times(&b).minus(&rj[0].times(&a)).over(&d).expect("D > 0 for adjacent contacts");
    let wy = ri[1].times(&b).minus(&rj[1].times(&a)).over(&d).expect("D > 0 for adjacent contacts");
    [wx, wy, g[2].clone()]
}

/// The family K_i = W_i^-1 K, i = 0..n-1, of a body with these contacts from a cone K in contact
/// coordinates (see the module documentation).
pub fn family(contacts: &[Vec2<Q>], cone: &[Vec3<Q>]) -> Vec<Vec<Vec3<Q>>> {
    let n = contacts.len();
    (0..n)
        .map(|i| cone.iter().map(|g| from_contact_speeds(&contacts[i], &contacts[(i + 1) % n], g)).collect())
        .collect()
}

/// The generators of a regular polygon point certificate, with its n.
/// n, the generators, and the upper end of gamma when it is an interval.
type RegularCone = (u64, Vec<Vec3<Q>>, Option<Q>);

fn regular_cone(cert: &Certificate) -> Result<RegularCone, TransportError> {
    let Body::RegularPolygon { n, kappa, gamma } = &cert.body;
    let hi = match gamma {
        Param::Point(_) => Ok(None),
        Param::Interval(_, hi) => hi.parse::<Q>().map(Some),
    };
    let (true, true, Ok(hi)) = (*n >= 3, kappa.as_point().is_some(), hi) else {
        return Err(TransportError::NotTransportable(
            "only certificates of polygons with n >= 3 at one kappa (a point, or an interval of gamma)"
                .into(),
        ));
    };
    let mut gens = Vec::with_capacity(cert.cone.len());
    for (i, g) in cert.cone.iter().enumerate() {
        let xs: Option<Vec<Q>> = g.0.iter().map(|s| s.parse::<Q>().ok()).collect();
        match xs.as_deref() {
            Some([a, b, c]) => gens.push([a.clone(), b.clone(), c.clone()]),
            _ => return Err(TransportError::BadGenerator(i)),
        }
    }
    Ok((*n, gens, hi))
}

/// The family certificate of a body and a family of cones.
pub fn convex_certificate(
    body: &ConvexBody<Q>,
    gamma_hi: Option<&Q>,
    claim: chatter_kernel::certificate::Claim,
    cones: &[Vec<Vec3<Q>>],
    producer: &str,
) -> ConvexCertificate {
    let t = |x: &Q| to_canonical(x);
    let j = body.inertia();
    let (gamma, version) = match gamma_hi.filter(|hi| *hi != body.gamma()) {
        Some(hi) => (Param::Interval(t(body.gamma()), t(hi)), family::INTERVAL_VERSION),
        None => (Param::Point(t(body.gamma())), family::VERSION),
    };
    ConvexCertificate {
        format: family::FORMAT.into(),
        version,
        body: ConvexBodyText::ConvexPolygon {
            contacts: body.contacts().iter().map(|r| (t(&r[0]), t(&r[1]))).collect(),
            inertia: (t(&j[0][0]), t(&j[0][1]), t(&j[1][1])),
            gamma,
            inertia_tensor: None,
        },
        coordinates: ConvexCoordinates::PaperVelocities,
        claim,
        cones: cones
            .iter()
            .map(|c| c.iter().map(|g| Generator(g.iter().map(t).collect())).collect())
            .collect(),
        producer: producer.into(),
    }
}

/// Transports a regular n-gon certificate to a body with n contacts: the family W_i'^-1 K with
/// the body's contacts, the certificate's claim. Sound only when the body is an affine image of
/// the certificate's regular body (docs/model.md §11.7) with the same gamma (the body at the lower
/// end of the certificate's interval of gamma, if it has one); the kernel decides
/// whether the result holds for the body given.
pub fn transport(body: &ConvexBody<Q>, cert: &Certificate) -> Result<ConvexCertificate, TransportError> {
    let (n, cone, gamma_hi) = regular_cone(cert)?;
    if n as usize != body.n() {
        return Err(TransportError::ContactCount { certificate: n, body: body.n() });
    }
    let cones = family(body.contacts(), &cone);
    let producer =
        format!("chatter {} (transported from a regular n = {n} certificate)", env!("CARGO_PKG_VERSION"));
    Ok(convex_certificate(body, gamma_hi.as_ref(), cert.claim, &cones, &producer))
}

/// The image of the regular n-gon body (n = 3, 4, 6; circumradius 1, J = kappa I) under the
/// linear map L with L(1, 0) = r0 and L(cos 2 pi/n, sin 2 pi/n) = r1 (det L > 0 when r0, r1 turn
/// counter-clockwise): contacts r_k = a_k r0 + b_k r1 with §2's coefficients a_k = -U_{k-2}(c_1),
/// b_k = U_{k-1}(c_1), and J' = B (kappa I) B^T = kappa P L L^T P^T, where
/// L L^T = V' G^-1 V'^T with V' = [r0 r1] and G = [[1, c_1], [c_1, 1]] the Gram matrix of the
/// regular body's contacts 0 and 1 (docs/model.md §11.7). Rational for rational r0, r1.
pub fn regular_image(
    n: usize,
    r0: &Vec2<Q>,
    r1: &Vec2<Q>,
    kappa: &Q,
    gamma: &Q,
) -> Result<ConvexBody<Q>, ConvexBodyError> {
    let c1 = match n {
        3 => Q::from_ratio(-1, 2),
        4 => Q::zero(),
        6 => Q::from_ratio(1, 2),
        _ => return Err(ConvexBodyError::TooFewContacts(n)),
    };
    let two_c = c1.plus(&c1);
    // U_{-2} = -1, U_{-1} = 0, U_m = 2 c U_{m-1} - U_{m-2}.
    let mut u = vec![Q::int(-1), Q::zero()];
    for m in 0..n {
        let next = two_c.times(&u[m + 1]).minus(&u[m]);
        u.push(next);
    }
    let contacts: Vec<Vec2<Q>> = (0..n)
        .map(|k| {
            let (a, b) = (u[k].negated(), u[k + 1].clone());
            [a.times(&r0[0]).plus(&b.times(&r1[0])), a.times(&r0[1]).plus(&b.times(&r1[1]))]
        })
        .collect();
    // G^-1 = [[1, -c], [-c, 1]] / (1 - c^2).
    let det = Q::one().minus(&c1.times(&c1));
    let gi = [[Q::one(), c1.negated()], [c1.negated(), Q::one()]];
    let v = [[r0[0].clone(), r1[0].clone()], [r0[1].clone(), r1[1].clone()]];
    let llt: Mat2<Q> = std::array::from_fn(|a| {
        std::array::from_fn(|b| {
            let mut s = Q::zero();
            for (p, row) in gi.iter().enumerate() {
                for (q, g) in row.iter().enumerate() {
                    s = s.plus(&v[a][p].times(g).times(&v[b][q]));
                }
            }
            s.over(&det).expect("1 - c^2 > 0")
        })
    });
    // P M P^T with P = [[0, 1], [-1, 0]]: [[m11, -m10], [-m01, m00]].
    let j = [
        [kappa.times(&llt[1][1]), kappa.times(&llt[1][0]).negated()],
        [kappa.times(&llt[0][1]).negated(), kappa.times(&llt[0][0])],
    ];
    ConvexBody::new(contacts, j, gamma.clone())
}

/// A body recognised as the image of a regular n-gon body under some L with det L > 0.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RegularPreimage {
    /// The regular polygon's number of contacts (3, 4 or 6).
    pub n: usize,
    /// The regular body's J = kappa I (circumradius 1).
    pub kappa: Q,
}

/// Decides exactly whether `body` is the image (docs/model.md §11.7) of the regular n-gon body
/// (n = 3, 4, 6; circumradius 1, J = kappa I, the same gamma) under some L with det L > 0, labels
/// unchanged: then L maps the regular contacts 0 and 1 to r_0 and r_1, so the body must equal
/// [`regular_image`] of r_0, r_1 with kappa = J_xx / J1_xx (J1 the image's J at kappa = 1), contacts
/// and J compared exactly. Labels rotated by s need no search: the rotation R^s maps the regular
/// body to itself (J = kappa I), so L R^s is a map of the same kind with labels unchanged.
pub fn regular_preimage(body: &ConvexBody<Q>) -> Option<RegularPreimage> {
    let n = body.n();
    let c = body.contacts();
    let (r0, r1) = (&c[0], &c[1]);
    if !matches!(n, 3 | 4 | 6) || !r0[0].times(&r1[1]).minus(&r1[0].times(&r0[1])).is_positive() {
        return None;
    }
    let unit = regular_image(n, r0, r1, &Q::one(), body.gamma()).ok()?;
    let kappa = body.inertia()[0][0].over(&unit.inertia()[0][0])?;
    let image = regular_image(n, r0, r1, &kappa, body.gamma()).ok()?;
    let same = kappa.is_positive() && image.contacts() == c && image.inertia() == body.inertia();
    same.then_some(RegularPreimage { n, kappa })
}
