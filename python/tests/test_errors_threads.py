"""Bad inputs raise ChatterError with a code (never a panic); long calls release the GIL."""

import threading
import time
from fractions import Fraction as F

import pytest

import chatter

BAD = [
    (chatter.certify, (1, F(1, 6), F(1, 100)), "unsupported-n"),
    (chatter.certify, (4, 0, F(1, 100)), "kappa-not-positive"),
    (chatter.certify, (4, F(-1, 6), F(1, 100)), "kappa-not-positive"),
    (chatter.certify, (4, F(1, 6), F(3, 2)), "gamma-out-of-range"),
    (chatter.certify, (4, "1/0", F(1, 100)), "invalid-number"),
    (chatter.certify, (4, "abc", F(1, 100)), "invalid-number"),
    (chatter.certify, (4, 0.1, F(1, 100)), "invalid-number"),
    (chatter.certify, (4, (F(1, 5), F(1, 10)), F(1, 100)), "invalid-number"),
    (chatter.classify, (1, F(1, 6), F(1, 100)), "invalid-input"),
    (chatter.classify, (65, F(1, 6), F(1, 100)), "invalid-input"),
    (chatter.classify, (4, F(1, 6), F(1, 100), (1, 2)), "invalid-input"),
    (chatter.simulate, (0, F(1, 6), F(1, 100)), "invalid-input"),
    (chatter.simulate, (65, F(1, 6), F(1, 100), 0, 200, True), "invalid-input"),
    (chatter.map, (3, (0, 1, 0), (0, 1, 3)), "invalid-input"),
    (chatter.map, (3, (1, 0, 3), (0, 1, 3)), "invalid-input"),
    (chatter.map, (3, (0, 1, 10**6), (0, 1, 3)), "invalid-input"),
    (chatter.certify, (2**70, 1, 0), "invalid-input"),
    (chatter.certify, (-3, 1, 0), "invalid-input"),
    (chatter.certify, (4, "1" * 5000, F(1, 100)), "invalid-number"),
    (chatter.certify, (4, F(1, 6), F(1, 100), "everything"), "invalid-claim"),
    (chatter.verify, ("",), "unreadable"),
]


@pytest.mark.parametrize("fn,args,code", BAD, ids=[f"{f.__name__}-{c}-{i}" for i, (f, _, c) in enumerate(BAD)])
def test_bad_input_raises_usage_error(fn, args, code):
    with pytest.raises(chatter.UsageError) as e:
        fn(*args)
    assert e.value.code == code and e.value.exit_code == 2
    assert isinstance(e.value, ValueError) and isinstance(e.value, chatter.ChatterError)


def test_malformed_certificate_text_is_rejected_not_raised():
    v = chatter.verify("(format: 1")
    assert not v.ok and v.code == "syntax" and "line 1" in v.message


def test_simulate_impacts_and_runs_limits():
    with pytest.raises(chatter.UsageError):
        chatter.simulate(4, F(1, 6), F(1, 100), impacts=0)
    with pytest.raises(chatter.UsageError):
        chatter.simulate(4, F(1, 6), F(1, 100), runs=10**7)
    with pytest.raises(chatter.UsageError):
        chatter.simulate(4, F(1, 6), F(1, 100), position=(0, 0, 1))


def test_two_threads_certify_concurrently():
    results = [None, None]

    def work(i):
        results[i] = chatter.certify(3, F(3, 20), F(1, 20)).to_ron()

    threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(timeout=120)
    assert results[0] is not None and results[0] == results[1]


def test_long_call_releases_the_gil():
    """While one thread simulates 20,000 drops, the main thread keeps running Python code."""
    done = threading.Event()
    started = threading.Event()

    def work():
        started.set()
        chatter.simulate(4, F(1, 6), F(1, 100), runs=20000, impacts=1000)
        done.set()

    t = threading.Thread(target=work)
    t.start()
    started.wait()
    t0, ticks = time.perf_counter(), 0
    while not done.is_set():
        ticks += 1
    elapsed = time.perf_counter() - t0
    t.join()
    assert elapsed > 0.05
    # With the GIL held for the whole call, this loop would run only between switches.
    assert ticks > 10000, (ticks, elapsed)
