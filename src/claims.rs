//! What each claim proves, in words that state every assumption (issue 24): the single place
//! where `certify`, `verify` and `reproduce` take the meaning of a claim from.
//!
//! Cone, box, number-field and family certificates establish the hypotheses of the paper's
//! Theorem on effectively invariant cones; from them the project derives (docs/model.md Lemma
//! 11.1, Theorem 11.4) that v ≤ 0 at all times, so the body never separates and its impacts never
//! stop, but not that the impacts accumulate at a finite time: docs/time-to-rest.md.
//! Orbit certificates do bound that time (docs/orbit-certificates.md §4).

/// The note appended wherever a cone-type certificate's claim is reported.
pub const FINITE_TIME_NOT_DERIVED: &str =
    "finite accumulation time: not derived by this certificate (docs/time-to-rest.md)";

/// What an accepted certificate with claim `name` proves (the claim names of
/// docs/certificate-format.md §5 and §14); `None` for an unknown name.
pub fn proves(name: &str) -> Option<&'static str> {
    Some(match name {
        "EffectivelyInvariant" => {
            "K is effectively invariant (v <= 0 on K, S_j(K ∩ C_j) ⊆ K); by itself nothing about a drop"
        }
        "CcOrPccFromAllDown" => {
            "every drop with all contacts moving down (impacts one contact at a time: a drop reaching a \
simultaneous impact leaves the model) keeps v <= 0 for ever: it never separates (no ICC) \
and its impacts never stop; PCC not excluded; finite accumulation time: not derived by this \
certificate (docs/time-to-rest.md)"
        }
        "CompleteChatterFromAllDown" => {
            "every drop with all contacts moving down (impacts one contact at a time: a drop reaching a \
simultaneous impact leaves the model) keeps v <= 0 for ever: it never separates (no ICC) \
and its impacts never stop; PCC excluded (the paper's Lemma on PCC); finite accumulation time: \
not derived by this certificate (docs/time-to-rest.md)"
        }
        "CompleteChatterFromSet" => {
            "every motion whose state after some impact lies in X (up to relabelling and scaling) \
follows the pattern for ever and its impacts accumulate at a finite time (the bounds rho, lambda, \
T-bar, docs/orbit-certificates.md §4); not: every drop"
        }
        _ => return None,
    })
}

/// What a rod point certificate with a claim about drops and a kernel-checked
/// `time_to_rest_bound` B proves (rule T1, docs/time-to-rest.md §2).
pub const WITH_TIME_TO_REST_BOUND: &str = "every drop with both ends moving down (one end landing at a \
time: a drop reaching a simultaneous impact leaves the model) keeps v <= 0 for ever and its impacts \
accumulate at a finite time T <= B h/|v| (B = time_to_rest_bound, rule T1; h, v: the centre's height and velocity \
just before the first impact; docs/time-to-rest.md §2)";

/// What a time-to-rest certificate (a virtual-time graph, rules G1-G5, F) with the claim `name` proves
/// (docs/time-to-rest.md Theorem 5.1).
pub fn proves_virtual_time(name: &str) -> &'static str {
    if name == "CompleteChatterFromAllDown" {
        "every drop with all contacts moving down (impacts one contact at a time: a drop reaching a \
simultaneous impact leaves the model) keeps v < 0 for ever and ends in complete chatter: its impacts \
never stop, PCC is excluded (the paper's Lemma on PCC), and they accumulate at a finite time \
T <= B h/|v| (B = time_to_rest_bound, rules G1-G5, F; h: the centre's height at the first impact, v: \
its velocity just before it; docs/time-to-rest.md Theorem 5.1, Theorem 5.2 for a general body)"
    } else {
        "every drop with all contacts moving down (impacts one contact at a time: a drop reaching a \
simultaneous impact leaves the model) keeps v < 0 for ever, its impacts never stop and they \
accumulate at a finite time T <= B h/|v| (B = time_to_rest_bound, rules G1-G5, F; h: the centre's \
height at the first impact, v: its velocity just before it; docs/time-to-rest.md Theorem 5.1, Theorem 5.2 for a \
general body); \
PCC not excluded"
    }
}

/// [`proves`], or [`WITH_TIME_TO_REST_BOUND`] when the kernel accepted a time-to-rest bound.
pub fn proves_with(name: &str, bound: bool) -> Option<&'static str> {
    if bound && (name == "CcOrPccFromAllDown" || name == "CompleteChatterFromAllDown") {
        return Some(WITH_TIME_TO_REST_BOUND);
    }
    proves(name)
}

/// Whether a claim's certificates derive a finite accumulation time (today: orbit certificates only).
pub fn derives_finite_time(name: &str) -> bool {
    name == "CompleteChatterFromSet"
}
