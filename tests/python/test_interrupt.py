"""Ctrl-C in a long call: study and a session's diagnose run without the GIL, stop on
SIGINT with KeyboardInterrupt soon after it, write nothing, and leave the module usable."""

import os
import signal
import threading
import time

import pytest

import aloft
from conftest import RACQUET, shared_data

# Far longer than the interrupt's wait below: 12 analyses of this many simulations.
LONG_STUDY_SAMPLES = 400_000
INTERRUPT_AFTER_S = 1.0
# Ctrl-C is answered within the signal poll (50 ms) plus the parallel loop's index in
# progress (a chunk of 64 simulations, or one flight); on a loaded machine, well within this.
ANSWER_WITHIN_S = 30.0


def interrupt_soon():
    timer = threading.Timer(INTERRUPT_AFTER_S, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    return timer


def test_ctrl_c_stops_study_and_writes_nothing(tmp_path):
    out = tmp_path / "study"
    timer = interrupt_soon()
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        aloft.study(mc_samples=LONG_STUDY_SAMPLES, threads=2, out=out)
    timer.join()
    assert time.monotonic() - start < INTERRUPT_AFTER_S + ANSWER_WITHIN_S
    assert not out.exists()
    # The module is still usable.
    assert aloft.study(mc_samples=10, threads=1)["monte_carlo"][0]["simulations"] == 10


def test_other_threads_run_python_during_a_long_call():
    ticks = []
    stop = threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.01)

    ticker = threading.Thread(target=tick)
    ticker.start()
    try:
        start = time.monotonic()
        aloft.study(mc_samples=1000, threads=1)
        end = time.monotonic()
    finally:
        stop.set()
        ticker.join()
    during = [t for t in ticks if start < t < end]
    # With the GIL held for the whole call the ticker would not run at all meanwhile.
    assert len(during) >= 5, f"{len(during)} ticks in {end - start:.2f} s"


def test_ctrl_c_stops_a_sessions_diagnosis(tmp_path):
    folder = shared_data("real", "racquet", "2025-01-23_18-29-01")
    report = tmp_path / "report.json"
    timer = threading.Timer(0.3, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        aloft.diagnose(RACQUET / "body.json", imu=folder / "gyro.csv", segments=folder / "segments.csv",
                       threads=1, json=report)
    timer.join()
    assert not report.exists()
