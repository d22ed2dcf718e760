"""classify, simulate, bodies and map: plain dicts with Fractions for exact values."""

from fractions import Fraction as F

import pytest

import chatter


def test_classify_triangle():
    d = chatter.classify(3, F(3, 20), F(1, 20))
    assert (d["n"], d["kappa"], d["gamma"]) == (3, F(3, 20), F(1, 20))
    assert d["method"] == "exact over Q"
    assert d["cc"]["holds"] is True and d["pcc"]["holds"] is False
    assert d["cc"]["evidence"]["char_poly"].startswith("t^3")
    lo, hi = d["cc_threshold"]["interval"]
    assert isinstance(lo, F) and lo < hi and lo > F(1, 20)  # gamma = 1/20 is below the threshold
    assert d["finder_all_down"] == "found"
    assert sum(d["simulation"].values()) == 20
    assert d["certificate"] == "CompleteChatterFromAllDown"


def test_classify_rod_velocity_and_pentagon():
    rod = chatter.classify(2, F(1, 3), "0.05", velocity=(F(1, 10), F(-1, 2)))
    assert "goyal" in rod and "pcc" not in rod
    assert rod["from_velocity"]["velocity"] == [F(1, 10), F(-1, 2)]
    pent = chatter.classify(5, F(1, 5), F(1, 100))
    assert pent["method"].startswith("exact in Q(") and pent["certificate"] is None


def test_simulate_single_drop_is_classified():
    s = chatter.simulate(3, F(3, 20), F(1, 20), seed=7)
    assert s["outcome"] == "CC" and s["impacts"] == 200 and s["budget"] == 200
    assert s["start"] == {"kind": "random-drop", "seed": 7}
    assert sum(s["contact_counts"]) == s["impacts"] == len(s["sequence"])
    assert isinstance(s["total_time"], float) and s["kappa"] == F(3, 20)


def test_simulate_batch_and_exact_and_given_start():
    b = chatter.simulate(4, F(1, 6), F(1, 100), runs=30)
    assert b["runs"] == 30 and sum(b["counts"].values()) == 30 and b["seeds"] == [0, 29]
    e = chatter.simulate(4, F(1, 6), F(1, 100), exact=True, impacts=50)
    assert e["arithmetic"] == "exact"
    g = chatter.simulate(4, F(1, 6), F(1, 100), position=("1/2", "1/2", 1), velocity=(-1, -1, -1), exact=True)
    assert g["start"]["kind"] == "given" and g["start"]["velocity"] == [F(-1)] * 3


def test_bodies_catalogue():
    rows = chatter.bodies()
    names = [r["name"] for r in rows]
    assert "uniform rod" in names and len(rows) >= 10
    rod = rows[names.index("uniform rod")]
    assert rod["kappa"] == F(1, 3) and rod["n"] == 2
    lo, hi = rod["cc_gamma_interval"]
    goyal = 7 - 4 * 3**0.5  # 7 - 4 sqrt(3) = 0.0717967...
    assert lo < hi and hi - lo < F(1, 10**9) and abs(float(lo) - goyal) < 1e-9


def test_map_columns():
    m = chatter.map(3, gamma=(0, 1, 4), rho=(0, 1, 5), certify=True, simulate=3)
    assert all(len(col) == 20 for col in m.values())
    assert m["index"] == list(range(20))
    assert m["rho"][:5] == [F(1, 10)] * 4 + [F(3, 10)]  # gamma varies fastest
    assert m["gamma"][:4] == [F(1, 8), F(3, 8), F(5, 8), F(7, 8)]
    assert all(k == r * r for k, r in zip(m["kappa"], m["rho"]))
    assert set(m["finder"]) <= {"found", "no-cone", "inconclusive"}
    for cert, ok in zip(m["certificate"], m["certified"]):
        assert (cert is not None) == ok
        if cert:
            assert chatter.verify(cert).ok
    assert all(r == 3 for r in m["sim_runs"])


def test_map_kappa_axis_rho_is_float():
    m = chatter.map(4, kappa="0:1/2:3", gamma=(0, F(1, 5), 2))
    assert len(m["kappa"]) == 6 and isinstance(m["rho"][0], float)
    assert m["certified"] == [None] * 6  # not asked


def test_map_as_numpy_arrays():
    np = pytest.importorskip("numpy")
    m = chatter.map(3, rho=(0, 1, 3), gamma=(0, 1, 3), numpy=True)
    assert isinstance(m["gamma"], np.ndarray) and m["gamma"].dtype == np.float64
    assert np.allclose(m["kappa"], m["rho"] ** 2)
    assert m["cc_criterion"].dtype == np.bool_ and m["index"].tolist() == list(range(9))
