"""Progress, Ctrl-C and exceptions from the progress callback: the build stops
between insertions and the interpreter goes on."""

import os
import signal
import threading
import time

import pytest

import ellvor


@pytest.fixture(scope="module")
def big():
    # About a second's build (50000 ellipses since the double certificate runs under
    # the upward rounding mode; 10^4 took 0.2 s): long enough to be interrupted.
    return ellvor.generate("ellipses", count=50000, seed=3)


@pytest.fixture
def sigint():
    """Python's own SIGINT handler (KeyboardInterrupt), also when the suite was started
    with SIGINT ignored (a background job)."""
    old = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, old)


def test_callback_sees_every_insertion_with_interval_zero():
    sites = ellvor.generate("ellipses", count=120, seed=2)
    calls = []
    ellvor.build(sites, progress=lambda done, total: calls.append((done, total)), progress_interval=0)
    assert calls == [(k, 120) for k in range(1, 121)]


def test_callback_is_throttled(big):
    calls = []
    d = ellvor.build(big, progress=lambda done, total: calls.append(done), progress_interval=10)
    assert calls[0] == 1 and calls[-1] == len(big) and len(calls) <= 3
    assert d.stats["inserted"] == len(big)


def test_an_exception_in_the_callback_stops_the_build():
    sites = ellvor.generate("ellipses", count=300, seed=4)
    seen = []

    class Stop(Exception):
        pass

    def progress(done, total):
        seen.append(done)
        if done == 50:
            raise Stop("enough")

    with pytest.raises(Stop, match="enough"):
        ellvor.build(sites, progress=progress, progress_interval=0)
    assert seen == list(range(1, 51))
    assert len(ellvor.build(sites).faces) > 0  # and the module goes on


def test_ctrl_c_interrupts_between_insertions(big, sigint):
    # The callback's first call (after one insertion) has another thread send
    # SIGINT while the build runs without the GIL; the build's next check of
    # Python's signals raises KeyboardInterrupt.
    seen, started = [], threading.Event()

    def progress(done, total):
        seen.append(done)
        started.set()

    def interrupt():
        started.wait()
        os.kill(os.getpid(), signal.SIGINT)

    sender = threading.Thread(target=interrupt)
    sender.start()
    start = time.monotonic()
    try:
        with pytest.raises(KeyboardInterrupt):
            ellvor.build(big, progress=progress, progress_interval=10)
    finally:
        started.set()
        sender.join()
    assert seen == [1]  # stopped: the last insertion's call never came
    # A check every 50 ms and one insertion; the full build takes about a second (the
    # bound leaves room for a loaded machine, `seen` above is the proof).
    assert time.monotonic() - start < 2


def test_ctrl_c_without_a_callback(big, sigint):
    timer = threading.Timer(0.2, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            ellvor.build(big)
    finally:
        timer.cancel()


def test_progress_true_prints_the_clis_line(capsys):
    ellvor.build(ellvor.generate("circles", count=40, seed=1), progress=True)
    err = capsys.readouterr().err
    assert err.endswith("\rinserted 40 of 40\n") and err.startswith("\rinserted 1 of 40")


def test_bad_progress_arguments():
    with pytest.raises(TypeError):
        ellvor.build([], progress=5)
    with pytest.raises(ValueError):
        ellvor.build([], progress=print, progress_interval=-1)
