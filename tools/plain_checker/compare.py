#!/usr/bin/env python3
"""Time the plain checker against `chatter verify` on heavy files (issue 23 §3).

The heavy files are built as kernel/tests/all/worst/files.rs describes: every number of a valid
corpus file (or only the body's) moved by +-1/(10^k + 7) so that it has about as many digits as
the default limits allow. Extra heavy refutations can be added with --extra FILE (e.g. one
written by `chatter refute` at a point needing many points, or with a long kappa).

Each file is checked in a fresh process (start-up included) `--runs` times; the table shows the
best wall time of each. Run it under `nice`:

    nice python3 tools/plain_checker/compare.py [--chatter BIN] [--runs 3] [--extra FILE ...]
"""

import argparse
import os
import platform
import subprocess
import sys
import tempfile
import time
from fractions import Fraction
from pathlib import Path

# Numbers of up to max-digits (10,000) digits and the derived ones are far longer than
# Python's default limit of 4,300 digits for int <-> str conversion.
if hasattr(sys, "set_int_max_str_digits"):
    sys.set_int_max_str_digits(0)

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
MAX_DIGITS = 9_990
MAX_TOTAL = 1_990_000


def canonical(x):
    return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"


def moved(x, digits):
    """x moved away from zero by 1/(10^k + 7), k chosen for about `digits` digits."""
    r = Fraction(x)
    k = max((digits - len(x)) // 2, 1)
    eps = Fraction(1, 10**k + 7)
    return canonical(r - eps if r < 0 else r + eps)


def is_number(part):
    return part != "" and all(c.isdigit() or c in "-/" for c in part)


def heavier(text, digits, pick):
    out, index = [], 0
    for i, part in enumerate(text.split('"')):
        number = i % 2 == 1 and is_number(part)
        out.append(moved(part, digits) if number and pick(index) else part)
        index += number
    return '"'.join(out)


def count(text):
    return sum(1 for i, p in enumerate(text.split('"')) if i % 2 == 1 and is_number(p))


def all_numbers(name):
    text = (ROOT / "certificates/valid" / name).read_text()
    return heavier(text, min(MAX_DIGITS, MAX_TOTAL // max(count(text), 1)), lambda i: True)


def body(name, k):
    text = (ROOT / "certificates/valid" / name).read_text()
    return heavier(text, MAX_DIGITS, lambda i: i < k)


HEAVY = [
    ("cone-n3-64-generators", lambda: all_numbers("n3-kappa3_20-gamma1_20-64-generators.ron")),
    ("cone-n4", lambda: all_numbers("n4-kappa1_6-gamma1_100-complete-chatter-from-all-down.ron")),
    ("cone-n6", lambda: all_numbers("n6-kappa1_40-gamma1_100-cc-or-pcc-from-all-down.ron")),
    ("rod-body", lambda: body("n2-kappa1_3-gamma1_20-complete-chatter-from-all-down.ron", 2)),
    ("box-n4-body", lambda: body("n4-kappa1_10_3_25-gamma1_100_1_50-box.ron", 4)),
    ("refutation-n6-body", lambda: body("refutation-n6-kappa1_20-gamma1_10.ron", 2)),
    ("refutation-n4-all", lambda: all_numbers("refutation-n4-kappa1_6-gamma1_20.ron")),
]


def timed(cmd, runs):
    """(best wall time, last stdout, exit code) of `runs` fresh runs of cmd."""
    best, out, rc = None, "", None
    for _ in range(runs):
        t = time.perf_counter()
        p = subprocess.run(cmd, capture_output=True, text=True)
        dt = time.perf_counter() - t
        best = dt if best is None else min(best, dt)
        out, rc = p.stdout, p.returncode
    return best, out, rc


def verdict_of_chatter(out):
    import json

    f = json.loads(out)["files"][0]
    return f["verdict"] + (f" {f['code']}" if "code" in f else "")


def verdict_of_plain(out):
    import json

    r = json.loads(out)[0]
    return r["verdict"] + (f" {r['code']}" if "code" in r else "")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--chatter", default=os.environ.get("CHATTER_BIN",
                                                        str(ROOT / "target/release/chatter")))
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--extra", nargs="*", default=[])
    ap.add_argument("--only", nargs="*", default=None, help="names of heavy files to run")
    args = ap.parse_args()
    plain = [sys.executable, str(HERE / "plain_checker.py"), "--json"]
    with tempfile.TemporaryDirectory() as tmp:
        files = []
        for name, make in HEAVY:
            if args.only is None or name in args.only:
                p = Path(tmp) / f"{name}.ron"
                p.write_text(make())
                files.append((name, p))
        files += [(Path(e).name, Path(e)) for e in args.extra]
        print(f"# {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}, {platform.node()}, "
              f"{os.cpu_count()} cores, {platform.python_implementation()} "
              f"{platform.python_version()}, load average {os.getloadavg()[0]:.2f} at start; "
              f"best of {args.runs}")
        print("| file | KiB | plain Python (s) | chatter both (s) | malachite (s) | num (s) "
              "| both / plain | verdicts |")
        print("| --- | ---: | ---: | ---: | ---: | ---: | ---: | --- |")
        for name, p in files:
            tp, op, _ = timed(plain + [str(p)], args.runs)
            row = [tp]
            verdicts = {verdict_of_plain(op)}
            for backend in ("both", "malachite", "num"):
                t, o, _ = timed([args.chatter, "verify", "--json", "--time-limit", "0",
                                 "--backend", backend, str(p)], args.runs)
                row.append(t)
                verdicts.add(verdict_of_chatter(o))
            v = verdicts.pop() if len(verdicts) == 1 else "DIFFER: " + ", ".join(sorted(verdicts))
            print(f"| {name} | {p.stat().st_size / 1024:.0f} | {row[0]:.2f} | {row[1]:.2f} | "
                  f"{row[2]:.2f} | {row[3]:.2f} | {row[1] / row[0]:.2f} | {v} |", flush=True)
        print(f"# load average {os.getloadavg()[0]:.2f} at the end")


if __name__ == "__main__":
    main()
