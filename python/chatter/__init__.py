"""chatter: exact certificates that a rigid body dropped flat onto a floor comes to rest by
complete chatter (infinitely many impacts in finite time).

Python bindings of the Rust tool ``chatter`` (docs/python.md). Exact inputs are ``Fraction``,
``int`` or text read exactly (``"3/20"``, ``"0.05"`` is 1/20); exact outputs are ``Fraction``.
Long calls release the GIL. Errors are :class:`ChatterError` subclasses carrying the rejection
``code`` and the command line's ``exit_code``.

>>> import chatter
>>> from fractions import Fraction
>>> cert = chatter.certify(3, Fraction(3, 20), Fraction(1, 20))
>>> chatter.verify(cert.to_ron()).ok
True
"""

import json
import os

from . import _native
from ._errors import ChatterError, InternalError, NotCertifiedError, UsageError
from ._exact import axis, interval, numbers, python, text
from ._types import Certificate, Verdict

__all__ = [
    "certify",
    "verify",
    "classify",
    "simulate",
    "bodies",
    "map",
    "Certificate",
    "Verdict",
    "ChatterError",
    "UsageError",
    "NotCertifiedError",
    "InternalError",
]


def _n(n):
    if isinstance(n, bool) or not isinstance(n, int):
        raise UsageError(f"n: {n!r} is not an int", "invalid-input")
    if not 0 <= n < 2**64:
        raise UsageError(f"n: {n} is outside 0..2**64", "invalid-input")
    return n


def certify(n, kappa, gamma, claim=None):
    """Find, exactify and kernel-check an effectively invariant cone; return a Certificate.

    n: the number of contacts: 2 (the rod) or a regular n-gon, 3..64 (for n = 5, 7, 8, ...
    decided in Q(cos 2 pi/n)). kappa > 0 and gamma in [0, 1]: exact numbers (Fraction, int or
    text), or intervals (lo, hi) for a box certificate valid on the whole box. For n = 5, 7,
    8, ... kappa may also be the canonical text of an element of Q(c), c = cos(2 pi/n), e.g.
    "1/40 + 1/100*c" (docs/certificate-format.md §12); the certificate's kappa is that text.
    claim: None or "strongest" (default: the strongest that certifies),
    "effectively-invariant", "cc-or-pcc-from-all-down" or "complete-chatter-from-all-down".

    The certificate is returned only if the trusted kernel accepts it on both bignum
    backends. Raises NotCertifiedError (``.code`` e.g. "no-cone", "pcc-not-excluded") when
    no certificate can be made, UsageError for bad input.

    >>> chatter.certify(4, Fraction(1, 6), Fraction(1, 100)).claim
    'CompleteChatterFromAllDown'
    """
    if claim is not None and not isinstance(claim, str):
        raise UsageError(f"claim: {claim!r} is not a str", "invalid-claim")
    k, g = interval(kappa, "kappa"), interval(gamma, "gamma")
    return Certificate(json.loads(_native.certify(_n(n), k, g, claim)))


def _is_text(s):
    head = s.lstrip()[:1]
    return head in ("{", "(") or "\n" in s or s.lstrip().startswith("Certificate")


def verify(path_or_text):
    """Check a certificate (or refutation) with the trusted kernel on both backends.

    path_or_text: a path (str or os.PathLike) to a *.ron, *.json or gzip'd file, or the
    certificate's text itself (RON, or the JSON twin when it starts with "{").

    Returns a Verdict: ``.ok`` True if accepted; when rejected ``.ok`` is False and ``.code``
    (e.g. "image-outside"), ``.message`` and ``.locus`` say where the first check failed.
    A rejected certificate is an answer, not an exception; unreadable input raises
    UsageError (code "unreadable"), disagreeing backends InternalError.
    """
    if isinstance(path_or_text, os.PathLike):
        return Verdict(json.loads(_native.verify_path(os.fspath(path_or_text))))
    if isinstance(path_or_text, bytes):
        path_or_text = path_or_text.decode("utf-8", errors="replace")
    if not isinstance(path_or_text, str):
        raise UsageError(f"verify: {type(path_or_text).__name__} is not a path or text", "invalid-input")
    if _is_text(path_or_text):
        return Verdict(json.loads(_native.verify_text(path_or_text)))
    return Verdict(json.loads(_native.verify_path(path_or_text)))


def classify(n, kappa, gamma, velocity=None, digits=12):
    """Every exact spectral criterion at one body, with its evidence, as a dict.

    The report ``chatter.classify/1`` of ``chatter classify --json`` (docs/json.md,
    docs/schema/chatter.classify.v1.schema.json): "schema", "n", "kappa" and "gamma"
    ({"exact": Fraction, "f64": float}), "field" (None over Q), "cc" and "pcc" ({"holds",
    "matrix", "char_poly", "eigenvalues", "all_real", "dominant", ...}; the rod has "goyal"
    and "pcc" None), "cc_threshold" and "pcc_threshold" ("kind", "interval" as Fractions,
    "decimal", "midpoint", ...), "finder" ({"translation", "all_down"}, each with "outcome"),
    "drops" (counts of 20 random drops), "certificate" ({"verdict", "claim", ...}).
    n is 2..64 (5, 7, 8, ... decided in Q(cos 2 pi/n)).
    velocity: for the rod, (u0, u1) to decide CC from that start ("from_velocity").
    """
    vel = numbers(velocity, "velocity")
    out = _native.classify(_n(n), text(kappa, "kappa"), text(gamma, "gamma"), vel, digits)
    return python(json.loads(out))


def simulate(n, kappa, gamma, seed=0, impacts=200, exact=False, runs=None, position=None, velocity=None):
    """Simulate a drop event by event and classify it (CC, PCC, ICC, undecided, simultaneous;
    with exact=True also no-ICC-no-PCC).

    Without position/velocity the body is dropped as in the paper from ``seed``; ``runs=M``
    simulates M drops from seeds seed..seed+M-1 and returns their counts. impacts: the impact
    budget. exact: exact arithmetic instead of f64 (rationals for n = 2, 3, 4, 6, the field
    Q(cos 2π/n) for other n). position, velocity: a given start in chatter's coordinates ((h0, h1, hc), (u0, u1, v); the rod two numbers).

    Returns the report of ``chatter simulate --json`` (docs/json.md): ``chatter.simulate/1``
    with "outcome" ("CC", "PCC", "ICC", "no-ICC-no-PCC", ...), "proved", "evidence", "entered",
    "decided_by", "impacts", "start", "sequence", "total_time", "accumulation_time", ...; with
    runs ``chatter.simulate-batch/1`` with "counts", "proved", "evidence", "decided_by",
    "mean_impacts". An exact run proves "CC" only with a finite accumulation time (entering an
    orbit certificate's set); entering a certified cone proves "no-ICC-no-PCC": the drop never
    separates and never ends in PCC, but the finite time is not derived (docs/time-to-rest.md). "kappa", "gamma" (and a given start's numbers) are
    {"exact": Fraction, "f64": float}.
    """
    if runs is not None and (isinstance(runs, bool) or not isinstance(runs, int) or runs < 1):
        raise UsageError(f"runs: {runs!r} is not a positive int", "invalid-input")
    if isinstance(seed, bool) or not isinstance(seed, int) or not 0 <= seed < 2**64:
        raise UsageError(f"seed: {seed!r} is not an int in 0..2**64", "invalid-input")
    if isinstance(impacts, bool) or not isinstance(impacts, int) or impacts < 1:
        raise UsageError(f"impacts: {impacts!r} is not a positive int", "invalid-input")
    out = _native.simulate(
        _n(n), text(kappa, "kappa"), text(gamma, "gamma"), seed, impacts, bool(exact), runs,
        numbers(position, "position"), numbers(velocity, "velocity"),
    )
    return python(json.loads(out))


def bodies(digits=12):
    """The catalogue of bodies: the report ``chatter.bodies/1`` of ``chatter bodies --json``,
    {"schema": ..., "bodies": [row, ...]}, each row with "name", "n", "kappa" (Fraction where
    rational, else the text of the number), the CC and PCC thresholds in gamma ("cc", "pcc",
    "cc_gamma_interval" as Fractions), and the paper's values with "paper_status"."""
    if isinstance(digits, bool) or not isinstance(digits, int) or digits < 1:
        raise UsageError(f"digits: {digits!r} is not a positive int", "invalid-input")
    return python(json.loads(_native.bodies(digits)))


def map(n, gamma, rho=None, kappa=None, certify=False, refute=False, simulate=None, numpy=False):
    """The paper's map over (rho, gamma) or (kappa, gamma) as columns (a dict of lists).

    gamma and rho (or kappa): axes (lo, hi, steps) or text "lo:hi:steps": the centres of
    ``steps`` equal cells of [lo, hi] (exact). Every point gets the exact CC and PCC criteria
    and the float finder's verdict; certify=True adds an exact certificate where one can be
    made (n = 3, 4, 6), refute=True an exact refutation where not, simulate=RUNS the paper's
    random drops (200 impacts each).

    Returns the summary ``chatter.map/1`` (as ``summary.json``, docs/map.md: "schema",
    "grid", "computed", "points", "counts", "disagreement_kinds", "disagreements") with the
    points under "columns": a dict of lists named as the columns of points.csv: "index",
    "n", "rho", "kappa", "gamma", "cc_criterion", "pcc_criterion", "finder", "certified",
    "claim", "refuted", "sim_runs", "sim_cc_evidence", ... (f64 drops: evidence), "mean_impacts", "sim_cc_proved",
    "sim_no_icc_no_pcc_proved" (a certified cone entered: no ICC, no PCC, CC not proved), ...,
    "sim_undecided" (the exact runs' proofs), and
    "certificate"/"refutation" (RON text or None). Exact columns hold Fractions.
    numpy=True makes the columns numpy arrays instead, exact columns as float64.
    """
    if (rho is None) == (kappa is None):
        raise UsageError("map: give exactly one horizontal axis, rho=... or kappa=...", "invalid-input")
    variable, x = ("rho", rho) if rho is not None else ("kappa", kappa)
    sims = simulate
    if sims is not None and (isinstance(sims, bool) or not isinstance(sims, int)):
        raise UsageError(f"simulate: {sims!r} is not an int", "invalid-input")
    out = _native.map(
        _n(n), variable, axis(x, variable), axis(gamma, "gamma"), bool(certify), bool(refute), sims
    )
    result = python(json.loads(out))
    if numpy:
        result["columns"] = _numpy(result["columns"])
    return result


def _numpy(cols):
    import numpy as np
    from fractions import Fraction

    def array(col):
        if col and all(isinstance(v, Fraction) for v in col):
            return np.array([float(v) for v in col])
        return np.array(col, dtype=object if any(v is None for v in col) else None)

    return {k: array(v) for k, v in cols.items()}
