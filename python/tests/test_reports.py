"""classify, simulate, bodies and map: the library's typed reports (docs/json.md) as plain
dicts, canonical exact texts as Fractions."""

import json
import pathlib
from fractions import Fraction as F

import pytest

import chatter

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCHEMAS = ROOT / "docs" / "schema"


def exact(number):
    """The exact value of a Number {"exact": Fraction, "f64": float}, checking both halves."""
    assert set(number) == {"exact", "f64"}
    assert isinstance(number["exact"], F) and number["f64"] == float(number["exact"])
    return number["exact"]


def test_classify_triangle():
    d = chatter.classify(3, F(3, 20), F(1, 20))
    assert d["schema"] == "chatter.classify/1"
    assert (d["n"], exact(d["kappa"]), exact(d["gamma"])) == (3, F(3, 20), F(1, 20))
    assert d["field"] is None  # decided over Q
    assert d["cc"]["holds"] is True and d["pcc"]["holds"] is False
    assert d["cc"]["dominant"] == "positive" and d["cc"]["all_real"] in (True, False)
    assert d["cc"]["char_poly"].startswith("t^3")
    assert len(d["cc"]["eigenvalues"]) >= 1
    assert all(e["kind"] in ("real", "complex-pair") for e in d["cc"]["eigenvalues"])
    assert d["cc_threshold"]["kind"] == "below"
    lo, hi = d["cc_threshold"]["interval"]
    assert isinstance(lo, F) and lo < hi and lo > F(1, 20)  # gamma = 1/20 is below the threshold
    assert d["finder"]["all_down"]["outcome"] == "found"
    assert d["drops"]["runs"] == 20 and sum(d["drops"]["counts"].values()) == 20
    assert d["certificate"]["verdict"] == "certified"
    assert d["certificate"]["claim"] == "CompleteChatterFromAllDown"


def test_classify_rod_velocity_and_pentagon():
    rod = chatter.classify(2, F(1, 3), "0.05", velocity=(F(1, 10), F(-1, 2)))
    assert rod["goyal"] in (True, False) and rod["pcc"] is None and rod["finder"] is None
    assert [exact(u) for u in rod["from_velocity"]["velocity"]] == [F(1, 10), F(-1, 2)]
    assert rod["from_velocity"]["cc"] in (True, False)
    assert exact(rod["gamma"]) == F(1, 20)  # "0.05" is read exactly
    pent = chatter.classify(5, F(1, 5), F(1, 100))
    assert "cos(2*pi/5)" in pent["field"]  # decided in Q(cos 2 pi/5)
    assert pent["pcc"] is not None and pent["certificate"]["verdict"] in ("certified", "not-certified")


def test_simulate_single_drop_is_classified():
    s = chatter.simulate(3, F(3, 20), F(1, 20), seed=7)
    assert s["schema"] == "chatter.simulate/1"
    assert s["outcome"] == "CC" and s["impacts"] == 200 and s["budget"] == 200
    assert s["start"] == {"kind": "random-drop", "seed": 7}
    assert sum(s["contact_counts"]) == s["impacts"] == len(s["sequence"])
    assert isinstance(s["total_time"], float) and exact(s["kappa"]) == F(3, 20)
    assert s["arithmetic"] == "f64" and s["trajectory"] is None and s["plot"] is None


def test_simulate_batch_and_exact_and_given_start():
    b = chatter.simulate(4, F(1, 6), F(1, 100), runs=30)
    assert b["schema"] == "chatter.simulate-batch/1"
    assert b["runs"] == 30 and sum(b["counts"].values()) == 30 and b["seeds"] == [0, 29]
    assert sum(b["decided_by"].values()) == 30 and b["mean_impacts"] > 0
    e = chatter.simulate(4, F(1, 6), F(1, 100), exact=True, impacts=50)
    assert e["arithmetic"] == "exact"
    # The square plate at gamma = 1/100 has a cone certificate and a time-to-rest certificate
    # made on the fly (docs/time-to-rest.md §1, §5): every all-down drop is proved CC at its first
    # impact, with a bound on its time to rest.
    assert e["outcome"] == "CC" and e["proved"] and e["evidence"]["outcome"] == "CC"
    assert e["entered"]["kind"] == "time-to-rest"
    assert e["entered"]["impact"] == 1 and e["entered"]["finite_time"] is True
    assert float(e["entered"]["time_to_rest_bound"]) > e["total_time"]
    b = chatter.simulate(4, F(1, 6), F(1, 100), exact=True, impacts=50, runs=3)
    assert b["proved"]["no-ICC-no-PCC"] + b["proved"]["CC"] == 3 and b["evidence"]["CC"] == 3
    g = chatter.simulate(4, F(1, 6), F(1, 100), position=("1/2", "1/2", 1), velocity=(-1, -1, -1), exact=True)
    assert g["start"]["kind"] == "given"
    assert [exact(v) for v in g["start"]["velocity"]] == [F(-1)] * 3
    assert [exact(q) for q in g["start"]["position"]] == [F(1, 2), F(1, 2), F(1)]


def test_exact_simulation_in_a_number_field_agrees_with_f64():
    # n = 5: cos(2 pi/5) is irrational, the exact run is in Q(cos 2 pi/5) (issue 10).
    e = chatter.simulate(5, F(1, 20), F(1, 10), seed=3, exact=True, impacts=60)
    f = chatter.simulate(5, F(1, 20), F(1, 10), seed=3, impacts=60)
    assert e["arithmetic"] == "exact" and f["arithmetic"] == "f64"
    # The exact run's verdict is proved (or undecided); f64's is evidence (issue 22).
    assert e["evidence"]["outcome"] == f["outcome"] and f["proved"] is False and f["basis"] == "evidence"
    # Here a time-to-rest certificate in Q(cos 2 pi/5), made on the fly, proves the drop CC at its
    # first impact, with a bound on the time to rest (issue 24; an orbit set did before).
    assert e["outcome"] == "CC" and f["outcome"] == "CC" and e["proved"]
    assert e["entered"]["kind"] == "time-to-rest" and e["entered"]["impact"] == 1
    # The exact run stops once a proof is found, so its impacts are a prefix of the f64 run's.
    n = len(e["sequence"])
    assert n >= 1 and e["sequence"] == f["sequence"][:n]
    assert e["entered"]["impact"] == n and e["entered"]["finite_time"] is True


def test_bodies_catalogue():
    report = chatter.bodies()
    assert report["schema"] == "chatter.bodies/1"
    rows = report["bodies"]
    names = [r["name"] for r in rows]
    assert "uniform rod" in names and len(rows) >= 10
    rod = rows[names.index("uniform rod")]
    assert rod["kappa"] == F(1, 3) and rod["n"] == 2
    lo, hi = rod["cc_gamma_interval"]
    goyal = 7 - 4 * 3**0.5  # 7 - 4 sqrt(3) = 0.0717967...
    assert lo < hi and hi - lo < F(1, 10**9) and abs(float(lo) - goyal) < 1e-9
    assert rod["paper_status"]["cc"] in ("agrees", "close", "disagrees", None)


def test_map_columns():
    m = chatter.map(3, gamma=(0, 1, 4), rho=(0, 1, 5), certify=True, simulate=3)
    assert m["schema"] == "chatter.map/1" and m["points"] == 20
    assert m["grid"]["n"] == 3 and m["computed"]["certify"] is True and m["computed"]["simulate"] == 3
    cols = m["columns"]
    assert all(len(col) == 20 for col in cols.values())
    assert cols["index"] == list(range(20))
    assert cols["rho"][:5] == [F(1, 10)] * 4 + [F(3, 10)]  # gamma varies fastest
    assert cols["gamma"][:4] == [F(1, 8), F(3, 8), F(5, 8), F(7, 8)]
    assert all(k == r * r for k, r in zip(cols["kappa"], cols["rho"]))
    assert set(cols["finder"]) <= {"found", "no-cone", "inconclusive"}
    for cert, ok in zip(cols["certificate"], cols["certified"]):
        assert (cert is not None) == ok
        if cert:
            assert chatter.verify(cert).ok
    assert all(r == 3 for r in cols["sim_runs"])
    # Issue 24: drops that enter a certified cone are proved no-ICC-no-PCC, a column apart from
    # sim_cc_proved, which counts only CC with a finite accumulation time (time-to-rest or orbit
    # certificates; on this grid every cone point has one since the merged graphs of 2026-11-27).
    for claim, cc, cone in zip(cols["claim"], cols["sim_cc_proved"], cols["sim_no_icc_no_pcc_proved"]):
        if claim == "CompleteChatterFromAllDown":
            assert cc + cone == 3  # past the cone, orbit sets may prove CC (issue 24 §2)
    proved = m["counts"]["drops_proved"]
    assert proved["no-ICC-no-PCC"] == sum(cols["sim_no_icc_no_pcc_proved"])
    assert proved["CC"] == sum(cols["sim_cc_proved"]) > 0
    # the summary counts the columns' values
    assert sum(m["counts"]["finder"].values()) == 20
    assert m["counts"]["finder"].get("found", 0) == cols["finder"].count("found")


def test_map_kappa_axis_rho_is_float():
    m = chatter.map(4, kappa="0:1/2:3", gamma=(0, F(1, 5), 2))
    cols = m["columns"]
    assert len(cols["kappa"]) == 6 and isinstance(cols["rho"][0], float)
    assert cols["certified"] == [None] * 6  # not asked
    assert m["grid"]["variable"] == "kappa"


def test_map_as_numpy_arrays():
    np = pytest.importorskip("numpy")
    m = chatter.map(3, rho=(0, 1, 3), gamma=(0, 1, 3), numpy=True)
    cols = m["columns"]
    assert isinstance(cols["gamma"], np.ndarray) and cols["gamma"].dtype == np.float64
    assert np.allclose(cols["kappa"], cols["rho"] ** 2)
    assert cols["cc_criterion"].dtype == np.bool_ and cols["index"].tolist() == list(range(9))
    assert m["schema"] == "chatter.map/1"


def plain(value):
    """The JSON data of a result: Fractions back to canonical text (the inverse of the
    package's conversion), so that it can be checked against the JSON Schema."""
    if isinstance(value, F):
        return str(value.numerator) if value.denominator == 1 else f"{value.numerator}/{value.denominator}"
    if isinstance(value, list):
        return [plain(v) for v in value]
    if isinstance(value, dict):
        return {k: plain(v) for k, v in value.items()}
    return value


REPORTS = [
    ("chatter.classify/1", lambda: chatter.classify(3, F(3, 20), F(1, 20))),
    ("chatter.classify/1", lambda: chatter.classify(2, F(1, 3), F(1, 20), velocity=(F(1, 10), F(-1, 2)))),
    ("chatter.classify/1", lambda: chatter.classify(5, F(1, 5), F(1, 100))),
    ("chatter.simulate/1", lambda: chatter.simulate(3, F(3, 20), F(1, 20), seed=7)),
    ("chatter.simulate/1", lambda: chatter.simulate(4, F(1, 6), F(1, 100), position=(1, 1, 1), velocity=(-1, -1, -1))),
    ("chatter.simulate-batch/1", lambda: chatter.simulate(4, F(1, 6), F(1, 100), runs=5)),
    ("chatter.bodies/1", lambda: chatter.bodies()),
    ("chatter.map/1", lambda: chatter.map(3, rho=(0, 1, 2), gamma=(0, 1, 2), certify=True, refute=True, simulate=2)),
]


@pytest.mark.parametrize("schema,make", REPORTS, ids=[f"{s}-{i}" for i, (s, _) in enumerate(REPORTS)])
def test_report_has_its_schema_and_validates(schema, make):
    d = make()
    assert d["schema"] == schema
    name, version = schema.split("/")
    path = SCHEMAS / f"{name}.v{version}.schema.json"
    doc = json.loads(path.read_text())
    assert doc["properties"]["schema"]["const"] == schema
    data = plain(d)
    assert json.loads(json.dumps(data)) == data  # plain JSON again
    assert set(doc.get("required", [])) <= set(data)
    jsonschema = pytest.importorskip("jsonschema")
    jsonschema.Draft202012Validator(doc).validate(data)
