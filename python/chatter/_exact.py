"""Exact numbers in and out: inputs as Fraction, int or canonical text; outputs as Fraction."""

import re
from fractions import Fraction
from numbers import Integral

from ._errors import UsageError

# The canonical text of an exact rational as chatter writes it: "3", "-7/20".
_CANONICAL = re.compile(r"-?[0-9]+(/[0-9]+)?")


def text(x, name):
    """The exact text of an input number: Fraction, int, or text chatter reads exactly
    ("3/20", "0.05" = 1/20, "1e-2"). Floats are refused: 0.05 as a float is not 1/20."""
    if isinstance(x, bool):
        raise UsageError(f"{name}: {x!r} is a bool, not a number", "invalid-number")
    if isinstance(x, Integral):
        return str(int(x))
    if isinstance(x, Fraction):
        return f"{x.numerator}/{x.denominator}" if x.denominator != 1 else str(x.numerator)
    if isinstance(x, str):
        return x
    if isinstance(x, float):
        raise UsageError(
            f"{name}: {x!r} is a float; give an exact number: Fraction, int or text such as '1/20'",
            "invalid-number",
        )
    raise UsageError(f"{name}: {x!r} is not a number (Fraction, int or str)", "invalid-number")


def interval(x, name):
    """A number, or a closed interval (lo, hi) as "lo:hi" (box certificates)."""
    if isinstance(x, (tuple, list)):
        if len(x) != 2:
            raise UsageError(f"{name}: an interval is (lo, hi), got {len(x)} numbers", "invalid-number")
        return f"{text(x[0], name)}:{text(x[1], name)}"
    return text(x, name)


def axis(x, name):
    """A map axis (lo, hi, steps) as "lo:hi:steps" (text "a:b:STEPS" is passed on)."""
    if isinstance(x, str):
        return x
    if not isinstance(x, (tuple, list)) or len(x) != 3:
        raise UsageError(f"{name}: an axis is (lo, hi, steps), got {x!r}", "invalid-input")
    lo, hi, steps = x
    if isinstance(steps, bool) or not isinstance(steps, Integral):
        raise UsageError(f"{name}: steps must be an int, got {steps!r}", "invalid-input")
    return f"{text(lo, name)}:{text(hi, name)}:{int(steps)}"


def numbers(xs, name):
    """A list of exact numbers as texts (None stays None)."""
    if xs is None:
        return None
    return [text(x, name) for x in xs]


def python(value):
    """JSON data with every canonical rational text turned into a Fraction (recursively);
    other strings, numbers, booleans and None are kept."""
    if isinstance(value, str):
        return Fraction(value) if _CANONICAL.fullmatch(value) else value
    if isinstance(value, list):
        return [python(v) for v in value]
    if isinstance(value, dict):
        return {k: python(v) for k, v in value.items()}
    return value
