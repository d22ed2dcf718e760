"""certify and verify: round trips, exact numbers, the invalid corpus."""

import json
import pathlib
from fractions import Fraction as F

import pytest

import chatter

ROOT = pathlib.Path(__file__).resolve().parents[2]
INVALID = ROOT / "certificates" / "invalid"
EXPECTED = json.loads((INVALID / "expected.json").read_text())


def test_certify_then_verify_ron_and_json(tmp_path):
    cert = chatter.certify(3, F(3, 20), F(1, 20))
    assert cert.claim == "CompleteChatterFromAllDown"
    assert (cert.n, cert.kappa, cert.gamma) == (3, F(3, 20), F(1, 20))
    assert len(cert.generators) >= 3
    assert all(isinstance(x, F) for g in cert.generators for x in g)
    assert all(g[2] == -1 for g in cert.generators)  # on the plane v = -1
    for text in (cert.to_ron(), cert.to_json()):
        v = chatter.verify(text)
        assert v.ok and v.claim == cert.claim and v.n == 3
        assert v.generators == len(cert.generators)
        assert v.code is None and v.message is None
    path = tmp_path / "tetrahedron.json"
    cert.save(path)
    assert json.loads(path.read_text())["format"] == "chatter-certificate"
    assert chatter.verify(path).ok  # pathlib.Path
    cert.save(tmp_path / "t.ron")
    assert chatter.verify(str(tmp_path / "t.ron")).ok  # str path


def test_exact_inputs_int_str_fraction_agree():
    a = chatter.certify(4, F(1, 6), F(1, 100))
    b = chatter.certify(4, "1/6", "0.01")  # 0.01 is read exactly: 1/100
    assert a.to_ron() == b.to_ron()
    assert isinstance(a.kappa, F) and a.gamma == F(1, 100)
    rod = chatter.certify(2, F(1, 4), F(1, 9))
    assert rod.generators == [(F(-3), F(1)), (F(1), F(-3))]  # the paper's two-ray cone (u0, u1)


def test_claim_choice_and_box():
    c = chatter.certify(4, F(1, 6), F(1, 100), claim="effectively-invariant")
    assert c.claim == "EffectivelyInvariant"
    box = chatter.certify(4, (F(1, 10), F(3, 25)), (F(1, 100), F(1, 50)))
    assert box.kappa == (F(1, 10), F(3, 25)) and box.gamma == (F(1, 100), F(1, 50))
    v = chatter.verify(box.to_ron())
    assert v.ok and v.region == [[F(1, 10), F(3, 25)], [F(1, 100), F(1, 50)]]


def test_not_certified_is_an_exception_with_code():
    with pytest.raises(chatter.NotCertifiedError) as e:
        chatter.certify(4, F(1, 6), F(9, 10))
    assert e.value.code == "no-cone" and e.value.exit_code == 1
    assert "not certified" in e.value.message


@pytest.mark.parametrize("entry", EXPECTED, ids=[e["file"] for e in EXPECTED])
def test_invalid_corpus_gives_expected_code(entry):
    v = chatter.verify(INVALID / entry["file"])
    assert not v.ok
    assert v.code == entry["code"]
    assert entry["message"] in v.message  # the manifest holds a part of the reason
    assert v.raw["locus"] == entry["locus"]


def test_rejected_text_has_code_and_locus():
    text = (INVALID / "shrunk-rectangle.ron").read_text()
    v = chatter.verify(text)
    assert not v.ok and not v
    assert v.code == "image-outside"
    assert v.locus["kind"] == "piece" and v.locus["vertex"] == 0
    assert "outside edge 0 of K" in v.message


@pytest.mark.parametrize("valid", sorted((ROOT / "certificates" / "valid").glob("*.ron"))[:6], ids=str)
def test_valid_corpus_is_ok(valid):
    assert chatter.verify(valid).ok


def test_unreadable_input_raises():
    with pytest.raises(chatter.UsageError) as e:
        chatter.verify(ROOT / "no-such-file.ron")
    assert e.value.code == "unreadable" and e.value.exit_code == 2
    with pytest.raises(chatter.UsageError):
        chatter.verify(12)


def test_certify_kappa_in_the_cosine_field():
    """n = 5 with kappa an element of Q(cos 2 pi/5) as canonical text (certificate-format §12)."""
    cert = chatter.certify(5, "1/40 + 1/100*c", F(1, 100))
    assert cert.claim == "CcOrPccFromAllDown"
    assert cert.n == 5 and cert.kappa == "1/40 + 1/100*c" and cert.gamma == F(1, 100)
    assert 'kappa: "1/40 + 1/100*c"' in cert.to_ron()
    for text in (cert.to_ron(), cert.to_json()):
        v = chatter.verify(text)
        assert v.ok and v.claim == "CcOrPccFromAllDown" and v.n == 5
    # the same as the corpus certificate written by the command line
    corpus = ROOT / "certificates" / "valid" / "n5-kappa-field-gamma1_100-cc-or-pcc-from-all-down.ron"
    if corpus.exists():
        assert chatter.verify(corpus).claim == cert.claim


def test_certify_field_kappa_errors():
    with pytest.raises(chatter.UsageError) as e:
        chatter.certify(4, "1/40 + 1/100*c", F(1, 100))  # cos(2 pi/4) = 0 is rational
    assert e.value.code == "invalid-number"
    with pytest.raises(chatter.UsageError) as e:
        chatter.certify(5, "1/40 + 1/100*c*c*", F(1, 100))
    assert e.value.code == "invalid-number"
    with pytest.raises(chatter.UsageError) as e:
        chatter.certify(5, "-1/40 + 1/100*c", F(1, 100))
    assert e.value.code == "kappa-not-positive"
