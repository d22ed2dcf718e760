"""The certificate and verdict objects returned by certify() and verify()."""

import json
import os

from ._exact import python


def _param(p):
    """A parameter of the JSON twin: a Fraction, or (lo, hi) for a box certificate."""
    p = python(p)
    return tuple(p) if isinstance(p, list) else p


class Certificate:
    """A certificate accepted by the trusted kernel on both bignum backends.

    Attributes: ``claim`` (e.g. ``"CompleteChatterFromAllDown"``), ``n``, ``kappa``, ``gamma``
    (``Fraction``, or ``(lo, hi)`` for a box certificate), ``generators`` (the cone's generators
    as tuples of ``Fraction``), ``coordinates``, ``method`` (how the cone was found),
    ``max_denominator_bits``, ``notes`` and ``timings_ms``.
    """

    def __init__(self, result):
        self._ron = result["ron"]
        self._json = result["json"]
        twin = json.loads(self._json)
        body = twin["body"]["RegularPolygon"]
        self.claim = twin["claim"]
        self.n = body["n"]
        self.kappa = _param(body["kappa"])
        self.gamma = _param(body["gamma"])
        self.coordinates = twin["coordinates"]
        self.generators = [tuple(python(g)) for g in twin["cone"]]
        self.method = result["method"]
        self.max_denominator_bits = result["max_denominator_bits"]
        self.notes = list(result["notes"])
        self.timings_ms = dict(result["timings_ms"])

    def to_ron(self):
        """The certificate as RON text (docs/certificate-format.md), as ``chatter certify -o``."""
        return self._ron

    def to_json(self):
        """The certificate's JSON twin (docs/certificate-format.md §11): same fields, same rules."""
        return self._json

    def save(self, path):
        """Writes the certificate to ``path``: its JSON twin if the name ends in .json, else RON."""
        text = self._json if os.fspath(path).lower().endswith(".json") else self._ron
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)

    def __repr__(self):
        return (
            f"<Certificate n={self.n} kappa={self.kappa} gamma={self.gamma} claim={self.claim}: "
            f"{len(self.generators)} generators>"
        )


class Verdict:
    """The verdict of the trusted kernel on one certificate (or refutation).

    ``ok`` is True when both backends accept. Otherwise ``code`` is the rejection code (e.g.
    ``"image-outside"``), ``message`` the reason and ``locus`` a dict locating the first
    failing check (docs/certificate-format.md §7). When accepted: ``claim``, ``n``,
    ``generators`` (their number), ``max_denominator_bits``, ``region`` (box certificates).
    ``raw`` holds every field of ``chatter verify --json``.
    """

    def __init__(self, raw):
        self.raw = raw
        self.path = raw.get("path")
        self.ok = raw["verdict"] == "accepted"
        self.claim = raw.get("claim")
        self.n = raw.get("n")
        self.generators = raw.get("generators")
        self.max_denominator_bits = raw.get("max_denominator_bits")
        self.code = raw.get("code")
        self.message = raw.get("reason")
        self.locus = python(raw.get("locus"))
        self.region = python(raw.get("region"))

    def __bool__(self):
        return self.ok

    def __repr__(self):
        if self.ok:
            return f"<Verdict OK {self.claim} n={self.n}, {self.generators} generators>"
        return f"<Verdict REJECTED [{self.code}] {self.message}>"
