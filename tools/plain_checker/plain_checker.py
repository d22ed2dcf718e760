#!/usr/bin/env python3
"""A plain Python checker of chatter certificates, written from the docs alone.

Sources: docs/certificate-format.md (syntax, fields, limits, rules R1-R4, T1, §9 boxes, §10
refutations, §11 JSON), docs/model.md §2-§5, §7 (maps, cones), docs/kernel-soundness.md §2.
Standard library only; exact arithmetic (int, fractions.Fraction).

Supported: cone certificates of regular polygons with rational cos 2pi/n (n = 2, 3, 4, 6), at a
point or on a box, and refutations. Every other kind (family, orbit, basin, proof, time-to-rest, number
fields) is reported "unsupported".

Usage: plain_checker.py [--json] FILE...
"""

import gzip
import json
import sys
from fractions import Fraction
from math import gcd

# Numbers of up to max-digits (10,000) digits and the derived ones are far longer than
# Python's default limit of 4,300 digits for int <-> str conversion.
if hasattr(sys, "set_int_max_str_digits"):
    sys.set_int_max_str_digits(0)

MAX_FILE_SIZE = 16 * 1024 * 1024
MAX_GENERATORS = 100_000
MAX_TOTAL_DIGITS = 2_000_000
MAX_DIGITS = 10_000
MAX_BERNSTEIN_BOXES = 20_000

RATIONAL_N = (2, 3, 4, 6)
CLAIMS = ("EffectivelyInvariant", "CcOrPccFromAllDown", "CompleteChatterFromAllDown")
COS = {3: Fraction(-1, 2), 4: Fraction(0), 6: Fraction(1, 2)}


class Reject(Exception):
    """A rejection: the code of certificate-format.md §7 and a locus (as chatter's --json)."""

    def __init__(self, code, locus=None, why=""):
        super().__init__(f"{code}: {why}")
        self.code, self.locus, self.why = code, locus, why


class Unsupported(Exception):
    """A file of a kind this checker does not implement."""


def field_locus(path):
    return {"kind": "field", "path": path}


# ---------------------------------------------------------------------------------------------
# Reading: strict RON subset (§2 "Strict syntax") and strict JSON (§11), into one value tree:
#   ("struct", name or None, [(key, value, pos)], pos)   RON Name(k: v) / ( k: v ) / JSON object
#   ("unit", name, pos)                                  RON bare identifier
#   ("call", name, [values], pos)                        RON Name(v, ...) e.g. Some("1/2")
#   ("seq", [values], shape, pos)                        shape: RON "tuple" or "list", JSON "array"
#   ("str", text, pos), ("int", value, pos)
# ---------------------------------------------------------------------------------------------


class Pos:
    """A position in the text; line and column are computed only when an error needs them."""

    __slots__ = ("s", "i")

    def __init__(self, s, i):
        self.s, self.i = s, i

    def __getitem__(self, k):
        line = self.s.count("\n", 0, self.i) + 1
        col = self.i - (self.s.rfind("\n", 0, self.i) + 1) + 1
        return (line, col)[k]


class Text:
    def __init__(self, s):
        self.s, self.i = s, 0

    def pos(self, i=None):
        return Pos(self.s, self.i if i is None else i)

    def fail(self, why, code="syntax", i=None):
        line, col = self.pos(i)
        raise Reject(code, {"kind": "text", "line": line, "column": col}, why)

    def ws(self):
        s, i = self.s, self.i
        while i < len(s) and s[i] in " \t\n\r":
            i += 1
        self.i = i

    def peek(self):
        return self.s[self.i] if self.i < len(self.s) else ""

    def expect(self, c):
        self.ws()
        if self.peek() != c:
            self.fail(f"expected {c!r}")
        self.i += 1

    def string(self):
        s, start = self.s, self.i
        i = start + 1
        while True:
            if i >= len(s):
                self.fail("unterminated string", i=start)
            c = s[i]
            if c == '"':
                break
            if c == "\\":
                self.fail("escapes in strings are not part of the format", i=i)
            if ord(c) < 0x20 or ord(c) == 0x7F:
                self.fail("control characters in strings", i=i)
            i += 1
        self.i = i + 1
        return s[start + 1:i]

    def integer(self):
        s, start = self.s, self.i
        i = start
        while i < len(s) and s[i].isdigit() and s[i].isascii():
            i += 1
        text = s[start:i]
        if i < len(s) and (s[i].isalnum() or s[i] in "._"):
            self.fail("only plain decimal integers are part of the format", i=start)
        if len(text) > 1 and text[0] == "0":
            self.fail("leading zeros in integers", i=start)
        self.i = i
        return int(text)


def lex_common(t, c):
    """Errors shared by both encodings, for a character that starts no value."""
    if c == "":
        t.fail("unexpected end of file")
    if c == "/":
        t.fail("comments are not part of the format")
    if c == "#":
        t.fail("extensions (#![enable(...)]) are not part of the format")
    if c in "+-":
        t.fail("signs outside strings are not part of the format")
    if c == "'":
        t.fail("character literals are not part of the format")
    if c == "{":
        t.fail("maps are not part of the format")
    t.fail(f"unexpected character {c!r}")


def is_ident_start(c):
    return c.isascii() and (c.isalpha() or c == "_")


def ron_ident(t):
    s, start = t.s, t.i
    i = start
    while i < len(s) and s[i].isascii() and (s[i].isalnum() or s[i] == "_"):
        i += 1
    t.i = i
    if i < len(s) and s[i] in "\"#" and s[start:i] in ("r", "b", "br"):
        t.fail("raw strings and byte strings are not part of the format", i=start)
    return s[start:i]


def ron_items(t, close, item):
    """`[ item { , item } [,] ] close`: a comma-separated sequence."""
    out = []
    t.ws()
    if t.peek() == close:
        t.i += 1
        return out
    while True:
        out.append(item())
        t.ws()
        c = t.peek()
        if c == ",":
            t.i += 1
            t.ws()
            if t.peek() == close:
                t.i += 1
                return out
            continue
        if c == close:
            t.i += 1
            return out
        if c == "":
            t.fail("unexpected end of file")
        t.fail(f"expected ',' or {close!r}")


def ron_field(t):
    t.ws()
    pos = t.pos()
    if not is_ident_start(t.peek()):
        lex_common(t, t.peek()) if not t.peek().isdigit() else t.fail("expected a field name")
    key = ron_ident(t)
    t.expect(":")
    return (key, ron_value(t), pos)


def ron_looks_like_fields(t):
    """After '(', a field list starts with `ident :`."""
    s, i = t.s, t.i
    while i < len(s) and s[i] in " \t\n\r":
        i += 1
    j = i
    while j < len(s) and s[j].isascii() and (s[j].isalnum() or s[j] == "_"):
        j += 1
    if j == i or not is_ident_start(s[i]):
        return False
    while j < len(s) and s[j] in " \t\n\r":
        j += 1
    return j < len(s) and s[j] == ":"


def ron_value(t):
    t.ws()
    c, pos = t.peek(), t.pos()
    if c == '"':
        return ("str", t.string(), pos)
    if c.isdigit() and c.isascii():
        return ("int", t.integer(), pos)
    if c == "[":
        t.i += 1
        return ("seq", ron_items(t, "]", lambda: ron_value(t)), "list", pos)
    if c == "(":
        t.i += 1
        if ron_looks_like_fields(t):
            return ("struct", None, ron_items(t, ")", lambda: ron_field(t)), pos)
        return ("seq", ron_items(t, ")", lambda: ron_value(t)), "tuple", pos)
    if is_ident_start(c):
        name = ron_ident(t)
        save = t.i
        t.ws()
        if t.peek() != "(":
            t.i = save
            return ("unit", name, pos)
        t.i += 1
        if ron_looks_like_fields(t):
            return ("struct", name, ron_items(t, ")", lambda: ron_field(t)), pos)
        return ("call", name, ron_items(t, ")", lambda: ron_value(t)), pos)
    lex_common(t, c)


def read_whole(text, value):
    """One value filling the whole text (no byte order mark, not empty, nothing after it)."""
    t = Text(text)
    if text.startswith("\ufeff"):
        t.fail("a byte order mark (U+FEFF) is not part of the format")
    t.ws()
    if t.peek() == "":
        t.fail("the file is empty")
    v = value(t)
    t.ws()
    if t.peek() != "":
        t.fail("trailing characters")
    return v


def read_ron(text):
    return read_whole(text, ron_value)


def json_value(t, must_object=False):
    t.ws()
    c, pos = t.peek(), t.pos()
    if must_object and c != "{":
        if c == "":
            t.fail("unexpected end of file")
        t.fail("a struct or a variant's fields must be a JSON object")
    if c == "{":
        t.i += 1
        members, seen = [], set()
        t.ws()
        if t.peek() == "}":
            t.i += 1
            return ("struct", None, members, pos)
        while True:
            t.ws()
            kpos = t.pos()
            if t.peek() != '"':
                t.fail("expected a string key")
            key = t.string()
            if key in seen:
                t.fail(f"duplicate field `{key}`", code="duplicate-field", i=t.i - len(key) - 2)
            seen.add(key)
            t.expect(":")
            upper = key[:1].isascii() and key[:1].isupper()
            members.append((key, json_value(t, must_object=upper), kpos))
            t.ws()
            c = t.peek()
            if c == ",":
                t.i += 1
                continue
            if c == "}":
                t.i += 1
                return ("struct", None, members, pos)
            t.fail("expected ',' or '}'")
    if c == "[":
        t.i += 1
        items = []
        t.ws()
        if t.peek() == "]":
            t.i += 1
            return ("seq", items, "array", pos)
        while True:
            items.append(json_value(t))
            t.ws()
            c = t.peek()
            if c == ",":
                t.i += 1
                continue
            if c == "]":
                t.i += 1
                return ("seq", items, "array", pos)
            t.fail("expected ',' or ']'")
    if c == '"':
        return ("str", t.string(), pos)
    if c.isdigit() and c.isascii():
        return ("int", t.integer(), pos)
    if is_ident_start(c):
        t.fail("literals and names outside strings are not part of the format")
    lex_common(t, c)


def read_json(text):
    return read_whole(text, lambda t: json_value(t, must_object=True))


# ---------------------------------------------------------------------------------------------
# Schema helpers (serde-like: fields in file order; unknown and repeated fields refused)
# ---------------------------------------------------------------------------------------------


def text_fail(pos, code, why):
    raise Reject(code, {"kind": "text", "line": pos[0], "column": pos[1]}, why)


def fields_of(v, names, required, struct_names):
    """The fields of a struct value as a dict, in serde's order of errors."""
    if v[0] != "struct":
        text_fail(v[-1], "syntax", "expected a struct")
    if v[1] is not None and v[1] not in struct_names:
        text_fail(v[-1], "syntax", f"expected struct {struct_names[0]}, found {v[1]}")
    out = {}
    for key, val, pos in v[2]:
        if key not in names:
            text_fail(pos, "unknown-field", f"unknown field `{key}`")
        if key in out:
            text_fail(pos, "duplicate-field", f"duplicate field `{key}`")
        out[key] = val
    for key in required:
        if key not in out:
            text_fail(v[-1], "missing-field", f"missing field `{key}`")
    return out


def enum_of(v, variants):
    """(variant name, payload or None) of a RON enum value or its JSON twin."""
    kind = v[0]
    if kind == "unit" or (kind == "str" and v[1][:1].isupper()):
        name, payload = v[1], None
    elif kind == "struct" and v[1] is not None:
        name, payload = v[1], ("struct", None, v[2], v[3])
    elif kind == "struct" and v[1] is None and len(v[2]) == 1:
        name, payload = v[2][0][0], v[2][0][1]
    else:
        text_fail(v[-1], "syntax", "expected an enum value")
    if name not in variants:
        text_fail(v[-1], "unknown-variant", f"unknown variant `{name}`")
    return name, payload


def seq_of(v, shape, what):
    """The items of a RON tuple or list (as `shape` says) or of a JSON array."""
    if v[0] != "seq" or v[2] not in (shape, "array"):
        text_fail(v[-1], "syntax", f"expected {what}")
    return v[1]


def want(v, kind, what):
    if v[0] != kind:
        text_fail(v[-1], "syntax", f"expected {what}")
    return v[1]


# ---------------------------------------------------------------------------------------------
# Numbers (§2 "Numbers", "Limits")
# ---------------------------------------------------------------------------------------------


def number(text, path, max_digits):
    """The canonical rational `text` as a Fraction, or bad-number / too-large at `path`."""
    loc = field_locus(path)

    def bad(why):
        raise Reject("bad-number", loc, f'"{text}": {why}')

    if text == "":
        bad("empty")
    for ch in text:
        if not (ch.isascii() and (ch.isdigit() or ch in "-/")):
            if ch.isspace():
                bad("whitespace")
            if ch == "+":
                bad("a leading '+' is not canonical")
            bad(f"invalid character {ch!r}")
    body = text[1:] if text[0] == "-" else text
    parts = body.split("/")
    if len(parts) > 2 or "-" in body or any(p == "" for p in parts):
        bad("not of the form p or p/q")
    if any(len(p) > 1 and p[0] == "0" for p in parts):
        bad("leading zeros")
    if sum(len(p) for p in parts) > max_digits:
        raise Reject("too-large", loc, f"more than the limit max-digits = {max_digits}")
    p = int(parts[0])
    q = int(parts[1]) if len(parts) == 2 else 1
    if text[0] == "-" and p == 0:
        bad("-0 is not canonical")
    if len(parts) == 2:
        if q == 0:
            bad("zero denominator")
        if q == 1:
            bad("denominator 1 is not canonical")
        if p == 0:
            bad("0/q is not canonical")
        if gcd(p, q) != 1:
            bad("not in lowest terms")
    return Fraction(-p if text[0] == "-" else p, q)


def collect_number_strings(v, out):
    """Every string of the value tree that names a number (all strings but the header's)."""
    kind = v[0]
    if kind == "str":
        out.append(v[1])
    elif kind in ("seq", "call"):
        for x in v[2] if kind == "call" else v[1]:
            collect_number_strings(x, out)
    elif kind == "struct":
        for key, x, _ in v[2]:
            if key not in ("format", "producer", "coordinates", "claim", "refutes"):
                collect_number_strings(x, out)


# ---------------------------------------------------------------------------------------------
# The model (docs/model.md §2-§4, §7): exact rationals for n = 3, 4, 6
# ---------------------------------------------------------------------------------------------


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def det3(a, b, c):
    return dot(cross(a, b), c)


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def apply(m, p):
    return tuple(m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] for i in range(3))


def integer_scaled(m):
    """A positive integer multiple of a rational matrix (cones ignore positive scaling)."""
    d = 1
    for row in m:
        for x in row:
            d = d * x.denominator // gcd(d, x.denominator)
    return [[int(x * d) for x in row] for row in m]


class Polygon:
    """The regular n-gon's exact model (model.md §2-§4), n = 3, 4, 6."""

    def __init__(self, n):
        self.n = n
        c1 = COS[n]
        self.c1 = c1
        u = {-2: Fraction(-1), -1: Fraction(0)}  # Chebyshev U_m(c1), model.md §2
        for m in range(0, n + 2):
            u[m] = 2 * c1 * u[m - 1] - u[m - 2]
        self.f = []
        for k in range(n + 1):
            a, b = -u[k - 2], u[k - 1]
            self.f.append((a, b, 1 - a - b))
        self.m = {}
        for k in range(n):
            self.m[k] = self.rest_point(k % n, (k + 1) % n)
        self.cones = {j: self.next_contact_cone(j) for j in range(1, n)}
        self.all_down = [tuple(-x for x in self.m[k]) for k in range(n)]

    def rest_point(self, k, l):
        """m_{k,l}: h_k = h_l = 0 and hc = 1 (model.md §4), by Cramer's rule."""
        fk, fl = self.f[k], self.f[l]
        det = fk[0] * fl[1] - fk[1] * fl[0]
        rk, rl = -fk[2], -fl[2]
        return ((rk * fl[1] - fk[1] * rl) / det, (fk[0] * rl - rk * fl[0]) / det, Fraction(1))

    def next_contact_cone(self, j):
        """The four covectors of C_j, in the order of model.md §4."""
        n = self.n
        return [
            (1, 0, 0),
            (0, 0, -1),
            integer_vector(cross(self.m[j % n], self.m[0])),
            integer_vector(cross(self.m[n - 1], self.m[j - 1])),
        ]

    def relabel(self, j):
        """R_j: rows f_j, f_{j+1}, (0, 0, 1) (model.md §3)."""
        return [list(self.f[j % self.n]), list(self.f[(j + 1) % self.n]), [0, 0, 1]]

    def impact(self, kappa, gamma):
        """I_0 p = p - beta u0 (kappa + 1, kappa + c1, kappa), beta = (1+gamma)/(1+kappa)."""
        beta = (1 + gamma) / (1 + kappa)
        d = (kappa + 1, kappa + self.c1, kappa)
        m = [[Fraction(int(i == k)) for k in range(3)] for i in range(3)]
        for i in range(3):
            m[i][0] -= beta * d[i]
        return m

    def step(self, j, kappa, gamma):
        return matmul(self.impact(kappa, gamma), self.relabel(j))


def integer_vector(v):
    d = 1
    for x in v:
        d = d * x.denominator // gcd(d, x.denominator)
    return tuple(int(x * d) for x in v)


# ---------------------------------------------------------------------------------------------
# Cone certificates (§2-§9)
# ---------------------------------------------------------------------------------------------

CERT_FIELDS = ("format", "version", "body", "coordinates", "claim", "cone", "time_to_rest_bound",
               "producer")
CERT_REQUIRED = ("format", "version", "body", "coordinates", "claim", "cone")


def parameter(v, path, version, max_digits):
    """A number or (version >= 2) an interval [lo, hi], as (lo, hi)."""
    if v[0] == "str":
        x = number(v[1], path, max_digits)
        return (x, x), False
    if (v[0] == "seq" and v[2] != "tuple" and len(v[1]) == 2
            and all(x[0] == "str" for x in v[1])):
        lo = number(v[1][0][1], f"{path}[0]", max_digits)
        hi = number(v[1][1][1], f"{path}[1]", max_digits)
        return (lo, hi), True
    text_fail(v[-1], "syntax", "expected a number or an interval of two numbers")


def body_of(v):
    name, payload = enum_of(v, ("RegularPolygon", "ConvexPolygon"))
    if name != "RegularPolygon":
        text_fail(v[-1], "unknown-variant", f"unknown variant `{name}`")
    return fields_of(payload, ("n", "kappa", "gamma"), ("n", "kappa", "gamma"),
                     ("RegularPolygon",))


def read_body(raw, version, claim, max_digits, point_only=False):
    """(n, kappa interval, gamma interval, is_box) after the rules of §3 and §9 R1."""
    n = want(raw["n"], "int", "an integer")
    if not 2 <= n <= 64:
        raise Reject("unsupported-body", field_locus("body.n"), f"n = {n}")
    if n not in RATIONAL_N:
        raise Unsupported(f"number field n = {n}")
    if point_only and (raw["kappa"][0] != "str" or raw["gamma"][0] != "str"):
        # Not in the docs (§10: "the body is at a point", no code): chatter's code and locus.
        raise Reject("parameter-out-of-range", field_locus("body"), "a refutation is at a point")
    kappa, kbox = parameter(raw["kappa"], "body.kappa", version, max_digits)
    gamma, gbox = parameter(raw["gamma"], "body.gamma", version, max_digits)
    if (kbox or gbox) and version < 2:
        raise Reject("unsupported-version", field_locus("version"), "intervals need version 2")
    for name, (lo, hi), box in (("kappa", kappa, kbox), ("gamma", gamma, gbox)):
        if box and lo > hi:
            raise Reject("parameter-out-of-range", field_locus(f"body.{name}"), "empty interval")
    lo_path = lambda name, box, end: f"body.{name}[{end}]" if box else f"body.{name}"
    if kappa[0] <= 0:
        raise Reject("parameter-out-of-range", field_locus(lo_path("kappa", kbox, 0)), "kappa > 0")
    if gamma[0] < 0:
        raise Reject("parameter-out-of-range", field_locus(lo_path("gamma", gbox, 0)), "gamma >= 0")
    if gamma[1] > 1:
        raise Reject("parameter-out-of-range", field_locus(lo_path("gamma", gbox, 1)), "gamma <= 1")
    if claim != "EffectivelyInvariant":
        if gamma[0] == 0:
            raise Reject("parameter-out-of-range", field_locus(lo_path("gamma", gbox, 0)),
                         "claims about drops need 0 < gamma < 1")
        if gamma[1] == 1:
            raise Reject("parameter-out-of-range", field_locus(lo_path("gamma", gbox, 1)),
                         "claims about drops need 0 < gamma < 1")
    return n, kappa, gamma, kbox or gbox


def check_limits(tree, count, max_generators, max_total):
    if count > max_generators:
        raise Reject("too-large", {"kind": "limit", "name": "max-generators"},
                     f"{count} generators")
    strings = []
    collect_number_strings(tree, strings)
    total = sum(len(s) for s in strings)
    if total > max_total:
        raise Reject("too-large", {"kind": "limit", "name": "max-total-digits"},
                     f"{total} characters of numbers")


def read_certificate(tree, version, limits):
    """The schema and R1 of a cone certificate; returns the parsed pieces."""
    raw = fields_of(tree, CERT_FIELDS, CERT_REQUIRED, ("Certificate",))
    body = body_of(raw["body"])
    enum_of(raw["coordinates"], ("ContactVelocities",))
    claim, _ = enum_of(raw["claim"], CLAIMS)
    cone = seq_of(raw["cone"], "list", "a list of generators")
    gens_raw = []
    for g in cone:
        if g[0] != "seq" or g[2] == "list" or any(x[0] != "str" for x in g[1]):
            text_fail(g[-1], "syntax", "expected a tuple of numbers")
        gens_raw.append([x[1] for x in g[1]])
    bound_raw = None
    if "time_to_rest_bound" in raw:
        b = raw["time_to_rest_bound"]
        if b[0] == "call" and b[1] == "Some" and len(b[2]) == 1 and b[2][0][0] == "str":
            bound_raw = b[2][0][1]
        elif b[0] == "str":
            bound_raw = b[1]
        elif not (b[0] == "unit" and b[1] == "None"):
            text_fail(b[-1], "syntax", "expected Some(\"p/q\")")
    check_limits(tree, len(gens_raw), limits["max_generators"], limits["max_total_digits"])
    n, kappa, gamma, box = read_body(body, version, claim, limits["max_digits"])
    arity = 2 if n == 2 else 3
    names = ("u0", "u1") if n == 2 else ("u0", "u1", "v")
    gens = []
    for i, g in enumerate(gens_raw):
        if len(g) != arity:
            raise Reject("wrong-arity", field_locus(f"cone[{i}]"),
                         f"expected {arity} coordinates, found {len(g)}")
        gens.append([number(x, f"cone[{i}].{names[k]}", limits["max_digits"])
                     for k, x in enumerate(g)])
    bound = None
    if bound_raw is not None:
        bound = number(bound_raw, "time_to_rest_bound", limits["max_digits"])
        if n != 2 or box:
            raise Reject("time-to-rest-not-shown", field_locus("time_to_rest_bound"),
                         "only a point certificate of the rod")
    return n, kappa, gamma, box, claim, gens, bound


def scaled_generator(g):
    """(p0/q0, p1/q1, p2/q2) -> (p0 q1 q2, q0 p1 q2, q0 q1 p2) (certificate-format.md §6)."""
    if len(g) == 2:
        return (g[0].numerator * g[1].denominator, g[0].denominator * g[1].numerator)
    p = [x.numerator for x in g]
    q = [x.denominator for x in g]
    return (p[0] * q[1] * q[2], q[0] * p[1] * q[2], q[0] * q[1] * p[2])


def hull(points):
    """Andrew's monotone chain on the projected generators: indices of K's vertices, CCW."""

    def less(i, j):  # (x_i, y_i) < (x_j, y_j), x = u0/(-v), y = u1/(-v)
        a, b = points[i], points[j]
        wa, wb = -a[2], -b[2]
        lx, rx = a[0] * wb, b[0] * wa
        if lx != rx:
            return lx < rx
        return a[1] * wb < b[1] * wa

    order = sorted(range(len(points)), key=_cmp_key(less))

    def orient(i, j, k):
        return -det3(points[i], points[j], points[k])

    def chain(seq):
        out = []
        for i in seq:
            while len(out) >= 2 and orient(out[-2], out[-1], i) <= 0:
                out.pop()
            out.append(i)
        return out

    lower, upper = chain(order), chain(order[::-1])
    return lower[:-1] + upper[:-1]


def _cmp_key(less):
    import functools

    return functools.cmp_to_key(lambda i, j: -1 if less(i, j) else (1 if less(j, i) else 0))


def clip(poly, cov):
    """Sutherland-Hodgman by cov . p >= 0; crossings (l.P) N - (l.N) P times sign(l.P)."""
    out = []
    m = len(poly)
    for i in range(m):
        p, q = poly[i], poly[(i + 1) % m]
        lp, lq = dot(cov, p), dot(cov, q)
        if lp >= 0:
            out.append(p)
        if (lp > 0 and lq < 0) or (lp < 0 and lq > 0):
            x = tuple(lp * b - lq * a for a, b in zip(p, q))
            out.append(x if lp > 0 else tuple(-c for c in x))
    return out


def locate(vertices, ids, edges, q):
    """None if q (with v < 0) is in K, else the locus of the first violated edge."""
    for e, f in enumerate(edges):
        if dot(f, q) < 0:
            return {"kind": "edge", "index": e, "from": ids[e], "to": ids[(e + 1) % len(ids)]}
    return None


def check_polygon(n, kappa, gamma, box, claim, gens):
    pts = [scaled_generator(g) for g in gens]
    for i, p in enumerate(pts):
        if p[2] >= 0:
            raise Reject("generator-not-below", {"kind": "generator", "index": i}, "v >= 0")
    if not pts:
        raise Reject("degenerate-cone", {"kind": "cone"}, "empty cone")
    ids = hull(pts)
    if len(ids) < 3:
        raise Reject("degenerate-cone", {"kind": "cone"}, "K must be a 3-D cone")
    verts = [pts[i] for i in ids]
    edges = [cross(verts[(e + 1) % len(verts)], verts[e]) for e in range(len(verts))]
    model = Polygon(n)
    pieces = {}
    for j in range(1, n):
        piece = verts
        for cov in model.cones[j]:
            piece = clip(piece, cov)
        pieces[j] = piece
    for ci, (k, g) in enumerate(corners(kappa, gamma)):
        extra = {"corner": ci} if box else {}
        for j in range(1, n):
            s = integer_scaled(model.step(j, k, g))
            for vi, p in enumerate(pieces[j]):
                q = apply(s, p)
                check_image(q, verts, ids, edges, "image",
                            {"kind": "piece", "piece": j, "vertex": vi, **extra})
    for ci, (k, g) in enumerate(corners(kappa, gamma)):
        extra = {"corner": ci} if box else {}
        if claim != "EffectivelyInvariant":
            i0 = integer_scaled(model.impact(k, g))
            for gi, d in enumerate(model.all_down):
                q = apply(i0, integer_vector(d))
                check_image(q, verts, ids, edges, "initial",
                            {"kind": "all-down", "generator": gi, **extra})
    if claim == "CompleteChatterFromAllDown":
        if box:
            check_pcc_box(model, kappa, gamma)
        else:
            check_pcc_point(model, kappa[0], gamma[0])


def corners(kappa, gamma):
    """The distinct corners, in the order (lo, lo), (hi, lo), (lo, hi), (hi, hi) (§9)."""
    out, seen = [], set()
    for k, g in ((kappa[0], gamma[0]), (kappa[1], gamma[0]), (kappa[0], gamma[1]),
                 (kappa[1], gamma[1])):
        if (k, g) not in seen:
            seen.add((k, g))
            out.append((k, g))
    return out


def check_image(q, verts, ids, edges, rule, locus):
    if q == (0, 0, 0):
        return
    if q[2] >= 0:
        code = "image-not-below" if rule == "image" else "initial-outside"
        raise Reject(code, {**locus, "outside": None}, "image with v >= 0")
    out = locate(verts, ids, edges, q)
    if out is not None:
        code = "image-outside" if rule == "image" else "initial-outside"
        raise Reject(code, {**locus, "outside": out}, "image outside K")


def pcc_quadratic(model, kappa, gamma):
    """(p, q) of det(tI - S_{n-1} S_1) = (t - 1)(t^2 + p t + q) (model.md §5)."""
    n = model.n
    a = matmul(model.step(n - 1, kappa, gamma), model.step(1, kappa, gamma))
    tr = a[0][0] + a[1][1] + a[2][2]
    m2 = sum(a[i][i] * a[k][k] - a[i][k] * a[k][i] for i in range(3) for k in range(i + 1, 3))
    det = det3(*[tuple(r) for r in a])
    if 1 - tr + m2 - det != 0:
        raise Reject("internal", {"kind": "nowhere"}, "t = 1 is not a root")
    return 1 - tr, det


def check_pcc_point(model, kappa, gamma):
    p, q = pcc_quadratic(model, kappa, gamma)
    if not (p * p - 4 * q < 0 and q < 1):
        raise Reject("pcc-not-excluded", {"kind": "pcc"}, f"t^2 + ({p}) t + ({q})")


# --- R4 on a box (§9): Bernstein coefficients of N and M, polynomials in (kappa, gamma) ------
# A bivariate polynomial is a dict {(i, j): Fraction} for kappa^i gamma^j.


def padd(a, b, sign=1):
    out = dict(a)
    for k, v in b.items():
        out[k] = out.get(k, 0) + sign * v
    return {k: v for k, v in out.items() if v != 0}


def pmul(a, b):
    out = {}
    for (i, j), x in a.items():
        for (k, l), y in b.items():
            out[(i + k, j + l)] = out.get((i + k, j + l), 0) + x * y
    return {k: v for k, v in out.items() if v != 0}


def pconst(c):
    return {(0, 0): Fraction(c)} if c != 0 else {}


KAPPA = {(1, 0): Fraction(1)}
GAMMA = {(0, 1): Fraction(1)}


def step_poly(model, j):
    """(1 + kappa) S_j with polynomial entries (kernel-soundness.md §2 "Boxes", item 2)."""
    one_k = padd(pconst(1), KAPPA)
    one_g = padd(pconst(1), GAMMA)
    d = (padd(KAPPA, pconst(1)), padd(KAPPA, pconst(model.c1)), KAPPA)
    i0 = [[pmul(one_k, pconst(int(i == k))) for k in range(3)] for i in range(3)]
    for i in range(3):
        i0[i][0] = padd(i0[i][0], pmul(one_g, d[i]), -1)
    r = model.relabel(j)
    return [[_sum(pmul(i0[i][k], pconst(r[k][c])) for k in range(3)) for c in range(3)]
            for i in range(3)]


def _sum(polys):
    out = {}
    for p in polys:
        out = padd(out, p)
    return out


def pmatmul(a, b):
    return [[_sum(pmul(a[i][k], b[k][j]) for k in range(3)) for j in range(3)] for i in range(3)]


def pcc_polys(model):
    """N = s(s - trA)^2 - 4 det A and M = det A - s^3, s = (1 + kappa)^2."""
    n = model.n
    a = pmatmul(step_poly(model, n - 1), step_poly(model, 1))
    one_k = padd(pconst(1), KAPPA)
    s = pmul(one_k, one_k)
    tr = _sum([a[0][0], a[1][1], a[2][2]])
    m2 = _sum(padd(pmul(a[i][i], a[k][k]), pmul(a[i][k], a[k][i]), -1)
              for i in range(3) for k in range(i + 1, 3))
    det = _sum([pmul(a[0][0], padd(pmul(a[1][1], a[2][2]), pmul(a[1][2], a[2][1]), -1)),
                pmul(a[0][1], padd(pmul(a[1][2], a[2][0]), pmul(a[1][0], a[2][2]), -1)),
                pmul(a[0][2], padd(pmul(a[1][0], a[2][1]), pmul(a[1][1], a[2][0]), -1))])
    s2, s3 = pmul(s, s), pmul(pmul(s, s), s)
    root = padd(padd(padd(s3, pmul(s2, tr), -1), pmul(s, m2)), det, -1)
    if root:
        raise Reject("internal", {"kind": "nowhere"}, "t = 1 is not a root")
    st = padd(s, tr, -1)
    big_n = padd(pmul(s, pmul(st, st)), pmul(pconst(4), det), -1)
    big_m = padd(det, s3, -1)
    return big_n, big_m


def bernstein(poly, kbox, gbox):
    """The Bernstein coefficients of poly on kbox x gbox, as a matrix b[i][j]."""
    dk = max((i for i, _ in poly), default=0)
    dg = max((j for _, j in poly), default=0)
    (k0, k1), (g0, g1) = kbox, gbox
    # substitute kappa = k0 + (k1 - k0) u, gamma = g0 + (g1 - g0) w: monomial coefficients in u, w
    c = [[Fraction(0)] * (dg + 1) for _ in range(dk + 1)]
    for (i, j), a in poly.items():
        pu = binomial_expand(k0, k1 - k0, i)
        pw = binomial_expand(g0, g1 - g0, j)
        for x, cu in enumerate(pu):
            if cu:
                for y, cw in enumerate(pw):
                    c[x][y] += a * cu * cw
    # power basis -> Bernstein basis: b_ij = sum_{x<=i, y<=j} C(i,x)/C(dk,x) C(j,y)/C(dg,y) c_xy
    from math import comb

    b = [[Fraction(0)] * (dg + 1) for _ in range(dk + 1)]
    for i in range(dk + 1):
        for j in range(dg + 1):
            acc = Fraction(0)
            for x in range(i + 1):
                fx = Fraction(comb(i, x), comb(dk, x))
                for y in range(j + 1):
                    if c[x][y]:
                        acc += fx * Fraction(comb(j, y), comb(dg, y)) * c[x][y]
            b[i][j] = acc
    return b


def binomial_expand(a, h, i):
    """Coefficients of (a + h u)^i in powers of u."""
    from math import comb

    return [comb(i, x) * a ** (i - x) * h ** x for x in range(i + 1)]


def check_pcc_box(model, kappa, gamma):
    for poly in pcc_polys(model):
        queue, examined = [(kappa, gamma)], 0
        while queue:
            kb, gb = queue.pop(0)
            examined += 1
            if examined > MAX_BERNSTEIN_BOXES:
                raise Reject("pcc-not-excluded", pcc_region(kb, gb), "out of boxes")
            b = bernstein(poly, kb, gb)
            if b[0][0] >= 0 or b[0][-1] >= 0 or b[-1][0] >= 0 or b[-1][-1] >= 0:
                for (ck, cg) in corners(kb, gb):
                    if peval(poly, ck, cg) >= 0:
                        raise Reject("pcc-not-excluded", pcc_region((ck, ck), (cg, cg)),
                                     "PCC not excluded at a corner")
            if all(x < 0 for row in b for x in row):
                continue
            km, gm = (kb[0] + kb[1]) / 2, (gb[0] + gb[1]) / 2
            queue += [((kb[0], km), (gb[0], gm)), ((km, kb[1]), (gb[0], gm)),
                      ((kb[0], km), (gm, gb[1])), ((km, kb[1]), (gm, gb[1]))]


def peval(poly, k, g):
    return sum(a * k ** i * g ** j for (i, j), a in poly.items())


def pcc_region(kb, gb):
    text = lambda x: str(x)
    return {"kind": "pcc-region", "kappa": [text(kb[0]), text(kb[1])],
            "gamma": [text(gb[0]), text(gb[1])]}


# --- The rod (§8, model.md §7) ----------------------------------------------------------------


def rod_s_less(a, b):
    """s(a) < s(b), s = u0 / w, w = -(u0 + u1) > 0."""
    return a[0] * -(b[0] + b[1]) < b[0] * -(a[0] + a[1])


def rod_maps(kappa, gamma):
    """I_0 and S_1 = I_0 R as integer matrices (model.md §7), c = (kappa-1)/(kappa+1)."""
    c = (kappa - 1) / (kappa + 1)
    i0 = [[-gamma, Fraction(0)], [-(1 + gamma) * c, Fraction(1)]]
    s1 = [[i0[0][1], i0[0][0]], [i0[1][1], i0[1][0]]]
    return integer_scaled2(i0), integer_scaled2(s1)


def integer_scaled2(m):
    d = 1
    for row in m:
        for x in row:
            d = d * x.denominator // gcd(d, x.denominator)
    return [[int(x * d) for x in row] for row in m]


def apply2(m, p):
    return (m[0][0] * p[0] + m[0][1] * p[1], m[1][0] * p[0] + m[1][1] * p[1])


def check_rod(kappa, gamma, box, claim, gens, bound):
    pts = [scaled_generator(g) for g in gens]
    for i, p in enumerate(pts):
        if p[0] + p[1] >= 0:
            raise Reject("generator-not-below", {"kind": "generator", "index": i}, "v >= 0")
    if not pts:
        raise Reject("degenerate-cone", {"kind": "cone"}, "empty cone")
    lo = hi = 0
    for i, p in enumerate(pts):
        if rod_s_less(p, pts[lo]):
            lo = i
        if rod_s_less(pts[hi], p):
            hi = i
    if not rod_s_less(pts[lo], pts[hi]):
        raise Reject("degenerate-cone", {"kind": "cone"}, "K must be a proper interval")
    piece = [pts[lo], pts[hi]]
    for cov in ((1, 0), (-1, -1)):
        piece = clip_segment(piece, cov)
    for ci, (k, g) in enumerate(corners(kappa, gamma)):
        extra = {"corner": ci} if box else {}
        i0, s1 = rod_maps(k, g)
        for vi, p in enumerate(piece):
            rod_image(apply2(s1, p), pts, lo, hi, "image",
                      {"kind": "piece", "piece": 1, "vertex": vi, **extra})
    for ci, (k, g) in enumerate(corners(kappa, gamma)):
        extra = {"corner": ci} if box else {}
        i0, s1 = rod_maps(k, g)
        if claim != "EffectivelyInvariant":
            for gi, d in enumerate(((0, -1), (-1, 0))):
                rod_image(apply2(i0, d), pts, lo, hi, "initial",
                          {"kind": "all-down", "generator": gi, **extra})
    if bound is not None:
        check_time_to_rest(kappa[0], gamma[0], claim, bound)


def clip_segment(seg, cov):
    """The segment's ends on cov >= 0, a crossing replacing an end below (kept in order)."""
    if not seg:
        return seg
    vals = [cov[0] * p[0] + cov[1] * p[1] for p in seg]
    if len(seg) == 1:
        return seg if vals[0] >= 0 else []
    (a, b), (la, lb) = seg, vals
    if la >= 0 and lb >= 0:
        return seg
    if la < 0 and lb < 0:
        return []
    if la < 0 and lb == 0:
        return [b]
    if lb < 0 and la == 0:
        return [a]
    x = tuple(la * q - lb * p for p, q in zip(a, b))
    if la < 0:
        return [tuple(-c for c in x), b]
    return [a, x]


def rod_image(q, pts, lo, hi, rule, locus):
    if q == (0, 0):
        return
    if q[0] + q[1] >= 0:
        code = "image-not-below" if rule == "image" else "initial-outside"
        raise Reject(code, {**locus, "outside": None}, "v >= 0")
    code = "image-outside" if rule == "image" else "initial-outside"
    if rod_s_less(q, pts[lo]):
        raise Reject(code, {**locus, "outside": {"kind": "end", "generator": lo}}, "below K")
    if rod_s_less(pts[hi], q):
        raise Reject(code, {**locus, "outside": {"kind": "end", "generator": hi}}, "above K")


def check_time_to_rest(kappa, gamma, claim, b):
    """T1 (§8): 2(1+k) <= s B or (1+k) - s B + g (1+k) B^2 <= 0, s = (1+g)(1-k)."""
    loc = field_locus("time_to_rest_bound")
    s = (1 + gamma) * (1 - kappa)
    d = 1 + kappa
    ok = (claim != "EffectivelyInvariant" and b > 0 and s > 0 and s * s - 4 * gamma * d * d >= 0
          and (2 * d <= s * b or d - s * b + gamma * d * b * b <= 0))
    if not ok:
        raise Reject("time-to-rest-not-shown", loc, f"B = {b} is not shown")


# ---------------------------------------------------------------------------------------------
# Refutations (§10)
# ---------------------------------------------------------------------------------------------

REF_FIELDS = ("format", "version", "body", "coordinates", "refutes", "points", "producer")
REF_REQUIRED = ("format", "version", "body", "coordinates", "refutes", "points")


def read_point(v):
    name, payload = enum_of(v, ("Seed", "Combination", "Image"))
    if name == "Seed":
        f = fields_of(payload, ("index",), ("index",), ("Seed",))
        return ("Seed", want(f["index"], "int", "an integer"))
    if name == "Image":
        f = fields_of(payload, ("step", "of"), ("step", "of"), ("Image",))
        return ("Image", want(f["step"], "int", "an integer"), want(f["of"], "int", "an integer"))
    f = fields_of(payload, ("terms",), ("terms",), ("Combination",))
    terms = []
    for t in seq_of(f["terms"], "list", "a list of terms"):
        if t[0] != "seq" or t[2] == "list" or len(t[1]) != 2 or t[1][0][0] != "int" or t[1][1][0] != "str":
            text_fail(t[-1], "syntax", "expected a term (index, \"c\")")
        terms.append((t[1][0][1], t[1][1][1]))
    return ("Combination", terms)


def check_refutation(tree, version, limits):
    raw = fields_of(tree, REF_FIELDS, REF_REQUIRED, ("Refutation",))
    body = body_of(raw["body"])
    enum_of(raw["coordinates"], ("ContactVelocities",))
    claim, _ = enum_of(raw["refutes"], CLAIMS)
    points = [read_point(p) for p in seq_of(raw["points"], "list", "a list of points")]
    if not points:
        # Not in the docs (§10 does not say what an empty list is): chatter's code and locus.
        raise Reject("step-failed", field_locus("points"), "no points")
    check_limits(tree, len(points), limits["max_generators"], limits["max_total_digits"])
    try:
        n, kappa, gamma, _ = read_body(body, version, "EffectivelyInvariant",
                                       limits["max_digits"], point_only=True)
    except Reject as r:
        # Not in the docs: chatter names the whole body in a refutation's body errors
        # (`body.kappa` etc. in a certificate's); observed, see README "Findings".
        if r.code == "parameter-out-of-range":
            r.locus = field_locus("body")
        raise
    coeffs = {}
    for i, p in enumerate(points):
        if p[0] == "Combination":
            coeffs[i] = [coefficient(c, f"points[{i}].terms[{t}].1", limits["max_digits"])
                         for t, (_, c) in enumerate(p[1])]
    k, g = kappa[0], gamma[0]
    if n == 2:
        derive_rod(points, coeffs, claim, k, g)
    else:
        derive_polygon(points, coeffs, claim, Polygon(n), k, g)


def coefficient(text, path, max_digits):
    """A combination's coefficient, or the rejection of its text: §10 makes a malformed
    coefficient a failure of its step (`step-failed`), found when the steps are checked in
    order."""
    try:
        return number(text, path, max_digits)
    except Reject as r:
        return r


def step_failed(i, kind, why):
    raise Reject("step-failed", {"kind": "step", "index": i, "id": kind}, why)


def derive(points, coeffs, seeds, images, in_cone, v_of):
    """The derived points P_i; the last must be non-zero with v >= 0."""
    derived = []
    for i, p in enumerate(points):
        if p[0] == "Seed":
            if not 0 <= p[1] < len(seeds):
                step_failed(i, "Seed", f"no seed {p[1]}")
            derived.append(seeds[p[1]])
        elif p[0] == "Combination":
            if not p[1]:
                step_failed(i, "Combination", "no terms")
            acc = None
            for (j, _), c in zip(p[1], coeffs[i]):
                if isinstance(c, Reject):
                    step_failed(i, "Combination", f"a coefficient that is not canonical: {c}")
                if not 0 <= j < i:
                    step_failed(i, "Combination", f"point {j} is not an earlier point")
                if c < 0:
                    step_failed(i, "Combination", f"the coefficient of point {j} is negative")
                term = tuple(c * x for x in derived[j])
                acc = term if acc is None else tuple(a + b for a, b in zip(acc, term))
            derived.append(acc)
        else:
            _, j, of = p
            if not 1 <= j < len(images) + 1 or not 0 <= of < i:
                step_failed(i, "Image", "bad step or point")
            if not in_cone(j, derived[of]):
                step_failed(i, "Image", f"point {of} is not in C_{j}")
            derived.append(images[j - 1](derived[of]))
    if not derived:
        raise Reject("step-failed", {"kind": "step", "index": 0, "id": "Seed"}, "no points")
    last = derived[-1]
    if all(x == 0 for x in last) or v_of(last) < 0:
        step_failed(len(points) - 1, points[-1][0], "the last point has v < 0 or is zero")


def fmat(m, p):
    return tuple(sum(m[i][k] * p[k] for k in range(len(p))) for i in range(len(m)))


def derive_polygon(points, coeffs, claim, model, k, g):
    i0 = model.impact(k, g)
    if claim == "EffectivelyInvariant":
        seeds = [fmat(i0, (Fraction(-1), Fraction(-1), Fraction(-1)))]
    else:
        seeds = [fmat(i0, d) for d in model.all_down]
    steps = [model.step(j, k, g) for j in range(1, model.n)]
    images = [lambda p, s=s: fmat(s, p) for s in steps]
    in_cone = lambda j, p: all(dot(c, p) >= 0 for c in model.cones[j])
    derive(points, coeffs, seeds, images, in_cone, lambda p: p[2])


def derive_rod(points, coeffs, claim, k, g):
    c = (k - 1) / (k + 1)
    i0 = [[-g, Fraction(0)], [-(1 + g) * c, Fraction(1)]]
    s1 = [[i0[0][1], i0[0][0]], [i0[1][1], i0[1][0]]]
    if claim == "EffectivelyInvariant":
        seeds = [fmat(i0, (Fraction(-1), Fraction(-1)))]
    else:
        seeds = [fmat(i0, (Fraction(0), Fraction(-1))), fmat(i0, (Fraction(-1), Fraction(0)))]
    in_cone = lambda j, p: p[0] >= 0 and -(p[0] + p[1]) >= 0
    derive(points, coeffs, seeds, [lambda p: fmat(s1, p)], in_cone, lambda p: p[0] + p[1])


# ---------------------------------------------------------------------------------------------
# Files
# ---------------------------------------------------------------------------------------------

OTHER_FORMATS = ("chatter-family-certificate", "chatter-orbit-certificate",
                 "chatter-basin-certificate", "chatter-proof", "chatter-time-to-rest",
                 "chatter-family-time-to-rest")


def header(tree):
    """(format, version) read first, unknown fields tolerated (§2)."""
    if tree[0] != "struct":
        text_fail(tree[-1], "syntax", "expected a struct")
    found = {}
    for key, v, pos in tree[2]:
        if key in ("format", "version"):
            if key in found:
                text_fail(pos, "duplicate-field", f"duplicate field `{key}`")
            found[key] = v
    for key in ("format", "version"):
        if key not in found:
            raise Reject("missing-field", field_locus(key), f"missing field `{key}`")
    fmt = want(found["format"], "str", "a string")
    version = want(found["version"], "int", "an integer")
    return fmt, version


def read_text(path):
    with open(path, "rb") as fh:
        data = fh.read(MAX_FILE_SIZE + 1)
    if data[:2] == b"\x1f\x8b":
        with gzip.open(path, "rb") as fh:
            data = fh.read(MAX_FILE_SIZE + 1)
    if len(data) > MAX_FILE_SIZE:
        raise Reject("too-large", {"kind": "limit", "name": "max-file-size"}, "file too large")
    return data.decode("utf-8")


DEFAULT_LIMITS = {"max_generators": MAX_GENERATORS, "max_total_digits": MAX_TOTAL_DIGITS,
                  "max_digits": MAX_DIGITS}


def check_text(text, is_json, limits=DEFAULT_LIMITS):
    """Raises Reject or Unsupported; returns a short report when accepted."""
    tree = read_json(text) if is_json else read_ron(text)
    fmt, version = header(tree)
    if fmt in OTHER_FORMATS or (fmt == "chatter-certificate" and version in (4, 5)):
        raise Unsupported(f"format {fmt} version {version}")
    if fmt == "chatter-refutation":
        if version != 1:
            raise Reject("unsupported-version", field_locus("version"), f"version {version}")
        check_refutation(tree, version, limits)
        return "refutation"
    if fmt != "chatter-certificate":
        raise Reject("wrong-format", field_locus("format"), f"found {fmt!r}")
    if version not in (1, 2, 3):
        raise Reject("unsupported-version", field_locus("version"), f"version {version}")
    n, kappa, gamma, box, claim, gens, bound = read_certificate(tree, version, limits)
    if n == 2:
        check_rod(kappa, gamma, box, claim, gens, bound)
    else:
        check_polygon(n, kappa, gamma, box, claim, gens)
    return claim


def check_file(path, limits=DEFAULT_LIMITS):
    """A dict: verdict accepted / rejected / unsupported / error, code and locus."""
    try:
        text = read_text(path)
        is_json = path.lower().endswith((".json", ".json.gz"))
        what = check_text(text, is_json, limits)
        return {"path": path, "verdict": "accepted", "claim": what}
    except Reject as r:
        return {"path": path, "verdict": "rejected", "code": r.code, "locus": r.locus,
                "reason": r.why}
    except Unsupported as u:
        return {"path": path, "verdict": "unsupported", "reason": str(u)}
    except (OSError, UnicodeDecodeError) as e:
        return {"path": path, "verdict": "error", "reason": str(e)}


def main(argv):
    as_json = "--json" in argv
    paths = [a for a in argv if a != "--json"]
    if not paths:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    results = [check_file(p) for p in paths]
    if as_json:
        print(json.dumps(results, indent=1))
    else:
        for r in results:
            extra = f" {r['code']}" if r["verdict"] == "rejected" else ""
            print(f"{r['path']}: {r['verdict']}{extra}: {r.get('reason', r.get('claim', ''))}")
    worst = {"accepted": 0, "unsupported": 0, "rejected": 1, "error": 2}
    return max(worst[r["verdict"]] for r in results)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
