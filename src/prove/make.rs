//! Certified sets made on the fly (issue 22 §1): a cone certificate with claim
//! `CompleteChatterFromAllDown` by the certify pipeline, a time-to-rest certificate by the
//! virtual-time producer where one is found (issue 24), orbit certificates by the orbit producer;
//! each is used only once the kernel accepts it on both backends ([`Certified::add_cone`],
//! [`Certified::add_rest`], [`Certified::add_orbit`]).

use crate::exact::Q;
use crate::simulate::Model;
use crate::simulate::certified::{Certified, SetKind, parameters, pattern_text, primitive_cycle};
use chatter_kernel::certificate::Claim;
use std::collections::HashMap;
use std::sync::Mutex;

/// The deepest subdivision an orbit certificate made on the fly may ask of the kernel (as in
/// `chatter classify`).
pub const ORBIT_DEPTH: u64 = 1;

/// How hard the producers try: a single body (`chatter simulate`: the full budgets), or one
/// point of a sweep (`chatter map`: the survey budgets of `crate::certify::Request::survey` and
/// orbit sets down to δ = 2^-14).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Effort {
    /// The full budgets.
    Full,
    /// Bounded budgets for sweeps.
    Survey,
}

/// δ halvings of an orbit attempt at [`Effort::Survey`].
const SURVEY_HALVINGS: u64 = 10;

/// A cone certificate made on the fly (finder, exactifier, kernel on both backends), if one with
/// claim `CompleteChatterFromAllDown` exists for the model (not cached: see [`made`]).
pub fn cone(model: &Model, effort: Effort) -> Certified {
    let mut out = Certified::empty();
    let Some((n, _, _)) = parameters(model) else {
        out.notes.push("no certified sets: not a regular polygon".into());
        return out;
    };
    let mut req = crate::certify::Request::new(n, model.kappa.clone(), model.gamma.clone());
    if effort == Effort::Survey {
        req = req.survey();
    }
    req.claim = crate::certify::ClaimChoice::Exactly(Claim::CompleteChatterFromAllDown);
    match crate::certify::certify(&req).result {
        Ok(cert) => {
            let name = format!("cone certificate made on the fly ({} generators)", cert.cone.len());
            if let Err(e) = out.add_cone(model, &cert, &name) {
                out.notes.push(format!("the cone certificate made on the fly cannot serve: {e}"));
            }
            add_rest_for(&mut out, model, n, effort);
        }
        Err(f) => out.notes.push(format!("no cone certificate with claim CompleteChatterFromAllDown: {f}")),
    }
    out
}

/// Node cap of the virtual-time graph tried at [`Effort::Survey`] (the full search's is
/// `crate::certify::virtual_time::Config::default().max_nodes`).
const SURVEY_REST_NODES: usize = 40;

/// The only pad of the survey's graph (the full search tries smaller ones after it): on the
/// 20 × 20 maps of docs/map.md the smaller pads proved no more drops (n = 3, 4, 2026-11-27) and
/// made the n = 3 map 39% slower.
const SURVEY_REST_PAD: f64 = 1e-3;

/// The time-to-rest search of surveys (maps, basin maps): a cap of 40 nodes (`SURVEY_REST_NODES`),
/// the pad 10^-3 (`SURVEY_REST_PAD`) only, the alternating linear programs stopped by their pace
/// (`Config::pace`: the maps of `reproduce --quick` are byte-identical with it, and their n = 3
/// map 18% faster), and the closed graphs tried smallest first (`Config::smallest_first`: the same
/// map files, its n = 3 map 36.0 -> 21.4 CPU s; both 2026-11-27).
pub fn survey_rest_config() -> crate::certify::virtual_time::Config {
    crate::certify::virtual_time::Config {
        max_nodes: SURVEY_REST_NODES,
        pads: vec![SURVEY_REST_PAD],
        pace: true,
        smallest_first: true,
        ..Default::default()
    }
}

/// Tries a time-to-rest certificate (docs/time-to-rest.md §5; producer
/// `crate::certify::virtual_time`, kernel on both backends) and adds it to `sets`: with it an
/// all-down drop is proved CC at its first impact, with a bound on its time to rest. A failure
/// is a note, never a verdict.
pub fn add_rest_for(sets: &mut Certified, model: &Model, n: u64, effort: Effort) {
    use crate::certify::virtual_time::{Config, produce};
    let cfg = if effort == Effort::Survey { survey_rest_config() } else { Config::default() };
    let backends = [chatter_kernel::verify::MALACHITE, chatter_kernel::verify::NUM];
    match produce(n, &model.kappa, &model.gamma, &cfg, &backends) {
        Ok(made) => {
            let name = format!("time-to-rest certificate made on the fly ({} nodes)", made.nodes);
            if let Err(e) = sets.add_rest(model, &made.cert, &name) {
                sets.notes.push(format!("the time-to-rest certificate made on the fly cannot serve: {e}"));
            }
        }
        Err(e) => sets.notes.push(format!("no time-to-rest certificate: {e}")),
    }
}

type Cache = Mutex<HashMap<(u64, Q, Q), Certified>>;

/// The process-wide cache of sets made on the fly, per (n, κ, γ).
fn cache() -> &'static Cache {
    static CACHE: std::sync::OnceLock<Cache> = std::sync::OnceLock::new();
    CACHE.get_or_init(Default::default)
}

fn key(model: &Model) -> (u64, Q, Q) {
    (model.n() as u64, model.kappa.clone(), model.gamma.clone())
}

/// The sets made on the fly for a regular polygon model (a cone certificate, and the orbit
/// certificates [`remember`]ed), cached per (n, κ, γ) for the life of the process.
pub fn made(model: &Model) -> Certified {
    if let Some(c) = cache().lock().expect("cache").get(&key(model)) {
        return c.clone();
    }
    let made = cone(model, Effort::Full);
    cache().lock().expect("cache").entry(key(model)).or_insert(made).clone()
}

/// The sets made on the fly for a general body (docs/model.md §11): a time-to-rest certificate
/// of the body (docs/time-to-rest.md Theorem 5.2), made by the producer with its full budget (or
/// the survey's, [`survey_rest_config`] with the full cap of nodes: a labelled graph has nodes
/// per contact, and the 3/2 x 1 plate at γ = 1/50 needs 56) and accepted by the kernel on both
/// backends, whose claim excludes PCC; otherwise none, and a note says why (no drop is then
/// proved CC).
pub fn made_general(model: &Model, body: &chatter_kernel::model::ConvexBody<Q>, effort: Effort) -> Certified {
    let mut sets = Certified::empty();
    let cfg = match effort {
        Effort::Survey => crate::certify::virtual_time::Config {
            max_nodes: crate::certify::virtual_time::Config::default().max_nodes,
            fallback: false,
            ..survey_rest_config()
        },
        Effort::Full => crate::certify::virtual_time::Config::default(),
    };
    let both = chatter_kernel::verify::BOTH;
    let note =
        match crate::certify::virtual_time::produce_family(std::slice::from_ref(body), None, &cfg, &both) {
            Ok(p) => sets.add_rest_family(model, &p.cert, "time-to-rest certificate made on the fly").err(),
            Err(e) => Some(format!("no time-to-rest certificate of this body was made: {e}")),
        };
    sets.notes.extend(note);
    sets
}

/// Keeps these sets (e.g. with an orbit certificate added) as the model's cached sets.
pub fn remember(model: &Model, sets: &Certified) {
    cache().lock().expect("cache").insert(key(model), sets.clone());
}

/// Tries an orbit certificate for the steps `pattern`, reduced to its shortest repeated word
/// (orbit producer, kernel on both backends), and adds it to `sets`; `Ok(false)` when one made
/// on the fly for a phase of this pattern is there already.
pub fn add_orbit_for(
    sets: &mut Certified,
    model: &Model,
    pattern: &[usize],
    effort: Effort,
) -> Result<bool, String> {
    let Some((n, _, _)) = parameters(model) else { return Err("not a regular polygon".into()) };
    let canonical = primitive_cycle(pattern);
    let text = pattern_text(&canonical);
    let name = format!("orbit certificate made on the fly (pattern {text})");
    if sets.sets().iter().any(|s| s.kind == SetKind::Orbit && s.name == name) {
        return Ok(false);
    }
    let req = crate::orbit::Request {
        n,
        kappa: model.kappa.clone(),
        gamma: model.gamma.clone(),
        pattern: Some(canonical),
        drops: 0,
        max_depth: ORBIT_DEPTH,
    };
    let backends = [chatter_kernel::verify::MALACHITE, chatter_kernel::verify::NUM];
    let halvings = if effort == Effort::Survey { SURVEY_HALVINGS } else { crate::orbit::MAX_HALVINGS };
    let found =
        crate::orbit::certify_orbit_within(&req, &backends, &[], halvings).map_err(|f| f.to_string())?;
    sets.add_orbit(model, &found.certificate, &name)?;
    Ok(true)
}
