"""Differential test: the plain checker against `chatter verify --json` (issue 23 §3).

Runs both on every file of certificates/valid and certificates/invalid, and on mutants of the
valid files of the supported kinds (one number changed, generated here), and asserts the same
verdict, the same code and, where the locus is not a text position, the same locus. Text
positions (line, column of a syntax or schema error) are the kernel's choice of where to point;
only their kind is compared. Files of kinds the plain checker does not implement are skipped.

The binary: $CHATTER_BIN, default target/release/chatter (relative to the repository root).
"""

import json
import os
import random
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
sys.path.insert(0, str(HERE))
import plain_checker  # noqa: E402

CORPUS = sorted(
    p for d in ("valid", "invalid") for p in (ROOT / "certificates" / d).iterdir()
    if p.name != "expected.json"
)


def chatter_bin():
    path = Path(os.environ.get("CHATTER_BIN", ROOT / "target/release/chatter"))
    if not path.is_file():
        pytest.skip(f"no chatter binary at {path} (set CHATTER_BIN)")
    return path


def chatter_verdicts(paths):
    """`chatter verify --json` on all paths at once: {path: file report}. One backend: the
    verdicts are compared with the plain checker's here, the backends with each other by the
    Rust tests (CI time, issue 23 §4)."""
    out = subprocess.run([str(chatter_bin()), "verify", "--backend", "malachite", "--json",
                          *map(str, paths)],
                         capture_output=True, text=True, timeout=600)
    report = json.loads(out.stdout)
    return {str(Path(f["path"])): f for f in report["files"]}


@pytest.fixture(scope="module")
def corpus_verdicts():
    return chatter_verdicts(CORPUS)


def assert_same(plain, kernel):
    """Same verdict, code and (non-text) locus; a readable message otherwise."""
    where = plain["path"]
    assert plain["verdict"] == kernel["verdict"], (
        f"{where}: plain {plain['verdict']} {plain.get('code', '')} {plain.get('reason', '')}; "
        f"chatter {kernel['verdict']} {kernel.get('code', '')} {kernel.get('reason', '')}")
    if plain["verdict"] != "rejected":
        return
    assert plain["code"] == kernel["code"], (
        f"{where}: plain {plain['code']} ({plain['reason']}); chatter {kernel['code']} "
        f"({kernel.get('reason', '')})")
    mine, theirs = plain["locus"], kernel.get("locus")
    if mine and mine.get("kind") == "text":
        assert theirs["kind"] == "text", f"{where}: locus {mine} vs {theirs}"
    else:
        assert mine == theirs, f"{where}: locus {mine} vs {theirs}"


@pytest.mark.parametrize("path", CORPUS, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_corpus_file_gets_the_same_verdict(path, corpus_verdicts):
    plain = plain_checker.check_file(str(path))
    if plain["verdict"] == "unsupported":
        pytest.skip(f"kind not implemented: {plain['reason']}")
    assert_same(plain, corpus_verdicts[str(path)])


def test_the_corpus_has_files_of_every_supported_kind():
    verdicts = [plain_checker.check_file(str(p)) for p in CORPUS]
    supported = [v for v in verdicts if v["verdict"] != "unsupported"]
    assert len(supported) >= 100
    kinds = {v.get("claim") for v in supported if v["verdict"] == "accepted"}
    assert {"refutation", "EffectivelyInvariant", "CompleteChatterFromAllDown"} <= kinds


# --- mutants ------------------------------------------------------------------------------------


def numbers_in(text):
    """(start, end) of every quoted canonical rational of a RON or JSON text."""
    spans, i = [], 0
    while True:
        i = text.find('"', i)
        if i < 0:
            return spans
        j = text.find('"', i + 1)
        s = text[i + 1:j]
        if s and all(c.isdigit() or c in "-/" for c in s) and any(c.isdigit() for c in s):
            spans.append((i + 1, j))
        i = j + 1


def canonical(x):
    return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"


def mutants(seed, per_file):
    """Valid supported files with one change: a number moved by a random amount (sometimes
    scaled or negated), the claim replaced, or one generator or point line dropped."""
    rng = random.Random(seed)
    out = []
    for path in sorted((ROOT / "certificates" / "valid").iterdir()):
        if plain_checker.check_file(str(path))["verdict"] == "unsupported":
            continue
        text = path.read_text()
        spans = numbers_in(text)
        lines = text.splitlines(keepends=True)
        droppable = [i for i, l in enumerate(lines) if l.lstrip().startswith(("(", "[\"", "{\"", "Seed", "Image", "Combination"))]
        for m in range(per_file):
            kind = rng.random()
            if kind < 0.7:
                a, b = rng.choice(spans)
                x = Fraction(text[a:b])
                delta = Fraction(rng.choice([1, -1]) * rng.randint(1, 9),
                                 rng.choice([10, 100, 10**6]))
                y = x * rng.choice([1, 2, -1]) + delta if rng.random() < 0.3 else x + delta
                new = text[:a] + canonical(y) + text[b:]
            elif kind < 0.85:
                claims = [c for c in plain_checker.CLAIMS if c in text]
                if not claims:
                    continue
                new = text.replace(claims[0], rng.choice(plain_checker.CLAIMS), 1)
            else:
                if not droppable:
                    continue
                i = rng.choice(droppable)
                new = "".join(lines[:i] + lines[i + 1:])
            out.append((f"{path.stem}-m{m}{path.suffix}", new))
    return out


def test_mutants_get_the_same_verdicts(tmp_path):
    files = []
    for name, text in mutants(seed=23, per_file=4):
        p = tmp_path / name
        p.write_text(text)
        files.append(p)
    kernel = chatter_verdicts(files)
    rejected = 0
    for p in files:
        plain = plain_checker.check_file(str(p))
        assert_same(plain, kernel[str(p)])
        rejected += plain["verdict"] == "rejected"
    # the mutants exercise both verdicts
    assert 0 < rejected < len(files)


# --- hand-written edge cases (each found a difference or probes a gap of the docs) ---------------

SQUARE = (ROOT / "certificates/valid/doc-example-square.ron").read_text()
ROD_REFUTATION = """Refutation(
    format: "chatter-refutation",
    version: 1,
    body: RegularPolygon(n: 2, kappa: "9/10", gamma: "1/2"),
    coordinates: ContactVelocities,
    refutes: CcOrPccFromAllDown,
    points: [
        Seed(index: 1),
    ],
)
"""
SEED = "        Seed(index: 1),\n"

EDGE_CASES = {
    # the rod's all-down seeds: §10 names "-m_{i,i+1}", §8 lists D's generators (0,-1), (-1,0)
    "rod-seed-1": ROD_REFUTATION,
    "rod-seed-0": ROD_REFUTATION.replace("index: 1", "index: 0"),
    "rod-seed-2": ROD_REFUTATION.replace("index: 1", "index: 2"),
    "refutation-no-name": ROD_REFUTATION.replace("Refutation(", "(", 1),
    "refutation-empty-points": ROD_REFUTATION.replace(SEED, ""),
    "refutation-kappa-interval": ROD_REFUTATION.replace('"9/10"', '["9/10", "1"]'),
    "combination-no-terms": ROD_REFUTATION.replace(SEED, SEED + "        Combination(terms: []),\n"),
    "combination-forward": ROD_REFUTATION.replace(
        SEED, SEED + '        Combination(terms: [(1, "1")]),\n'),
    "image-no-such-step": ROD_REFUTATION.replace(SEED, SEED + "        Image(step: 2, of: 0),\n"),
    "combination-bad-number": ROD_REFUTATION.replace(
        SEED, SEED + '        Combination(terms: [(0, "2/4")]),\n'),
    "generator-as-list": SQUARE.replace('("0", "-11/4", "-1")', '["0", "-11/4", "-1"]'),
    "certificate-no-name": SQUARE.replace("Certificate(", "(", 1),
    "time-bound-none": SQUARE.replace("    producer", "    time_to_rest_bound: None,\n    producer"),
    "box-in-version-3": SQUARE.replace("version: 1", "version: 3").replace(
        'kappa: "1/6"', 'kappa: ["1/6", "1/5"]'),
    "field-element-for-n-4": SQUARE.replace("version: 1", "version: 3").replace(
        '"1/6"', '"1/6 + c"'),
    "two-faults-kappa-first": SQUARE.replace('"1/6"', '"-1/6"').replace(
        '("1/20", "-11/4"', '("2/40", "-11/4"', 1),
}

# Known differences between the docs' reading and chatter (none since §10 was made explicit
# about a malformed coefficient: step-failed at its step).
KNOWN: dict = {}


@pytest.mark.parametrize("name", sorted(EDGE_CASES))
def test_edge_case_gets_the_same_verdict(name, tmp_path):
    if name in KNOWN:
        pytest.xfail(KNOWN[name])
    path = tmp_path / f"{name}.ron"
    path.write_text(EDGE_CASES[name])
    assert_same(plain_checker.check_file(str(path)), chatter_verdicts([path])[str(path)])


def test_numbers_of_ten_thousand_digits_are_read(tmp_path):
    """Regression: Python >= 3.11 refuses int(str) beyond 4,300 digits unless told otherwise."""
    import compare

    path = tmp_path / "square-long.ron"
    path.write_text(compare.heavier(SQUARE, 9_990, lambda i: True))
    assert max(len(s) for s in path.read_text().split('"')) > 9_000
    plain = plain_checker.check_file(str(path))
    assert plain["verdict"] != "error"
    assert_same(plain, chatter_verdicts([path])[str(path)])
