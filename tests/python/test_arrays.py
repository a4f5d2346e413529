"""simulate, deviation_angle and read_imu: the command's numbers and the files' own,
float64 C-contiguous arrays, no copy where none is needed."""

import csv
import json
import math

import numpy as np
import pytest

import aloft
from conftest import EXAMPLES, run_program, shared_data


def program_trajectory(tmp_path, body, w0, duration, rate, q0=None, integrator=None):
    out = tmp_path / "trajectory.csv"
    args = ["simulate", "--body", body, "--w0", ",".join(map(repr, w0)), "--duration", repr(duration),
            "--rate", repr(rate), "--out", out]
    if q0 is not None:
        args += ["--q0", ",".join(map(repr, q0))]
    if integrator is not None:
        args += ["--integrator", integrator]
    run_program(*args)
    return np.loadtxt(out, delimiter=",", skiprows=1)


def assert_float64_rows(array, shape):
    assert array.dtype == np.float64 and array.flags.c_contiguous and array.shape == shape


@pytest.mark.parametrize("integrator", [None, "splitting"])
def test_simulate_is_the_commands_flight(tmp_path, integrator):
    body = EXAMPLES / "throw_body.json"
    w0, q0 = (1.5, -12.25, 3.0), (0.5, 0.5, 0.5, 0.5)
    flight = aloft.simulate(str(body), w0, 0.75, 400.0, q0=q0, integrator=integrator)
    table = program_trajectory(tmp_path, body, w0, 0.75, 400.0, q0, integrator)
    assert_float64_rows(flight["t"], (301,))
    assert_float64_rows(flight["q"], (301, 4))
    assert_float64_rows(flight["w"], (301, 3))
    # The CSV's numbers are the shortest text of each double: they read back exactly.
    assert np.array_equal(flight["t"], table[:, 0])
    assert np.array_equal(flight["q"], table[:, 1:5])
    assert np.array_equal(flight["w"], table[:, 5:8])


def test_simulate_takes_a_dict_body_and_arrays(tmp_path):
    body = json.loads((EXAMPLES / "throw_body.json").read_text())
    body["inertia"]["tensor"] = np.array(body["inertia"]["tensor"])  # arrays in the dict are taken too
    w0 = np.array([[0.0, 2.0, 9.0]])[0]  # a view: converted once, not refused
    from_dict = aloft.simulate(body, w0, 0.5, 200, integrator="rk4")
    from_file = aloft.simulate(EXAMPLES / "throw_body.json", [0, 2, 9], 0.5, 200)
    for key in ("t", "q", "w"):
        assert np.array_equal(from_dict[key], from_file[key])
    assert np.array_equal(from_dict["w"][0], w0)  # the initial state round-trips exactly
    assert np.array_equal(from_dict["q"][0], [1, 0, 0, 0])


def test_deviation_angle_exact_angles():
    measured = np.array([[1.0, 0, 0], [1, 0, 0], [1, 0, 0], [0, 2, 0], [1, 1, 0], [0, 0, 0]])
    simulated = np.array([[1.0, 0, 0], [0, 1, 0], [-1, 0, 0], [0, 0, 3], [1, 0, 0], [1, 0, 0]])
    angles = aloft.deviation_angle(measured, simulated)
    assert_float64_rows(angles, (6,))
    assert angles[0] == 0.0
    assert angles[1] == pytest.approx(math.pi / 2, abs=1e-15)
    assert angles[2] == pytest.approx(math.pi, abs=1e-15)
    assert angles[3] == pytest.approx(math.pi / 2, abs=1e-15)
    assert angles[4] == pytest.approx(math.pi / 4, abs=1e-15)
    assert angles[5] == 0.0  # atan2(0, 0), as the reports take it


def test_deviation_angle_agrees_with_atan2_and_takes_any_layout():
    rng = np.random.default_rng(7)
    a, b = rng.normal(size=(1000, 3)), rng.normal(size=(1000, 3))
    expected = np.arctan2(np.linalg.norm(np.cross(a, b), axis=1), np.sum(a * b, axis=1))
    angles = aloft.deviation_angle(a, b)
    assert np.max(np.abs(angles - expected)) < 1e-15 * 8
    # Fortran order, a strided view and float32 are converted, with the same answers.
    assert np.array_equal(aloft.deviation_angle(np.asfortranarray(a), b), angles)
    assert np.array_equal(aloft.deviation_angle(np.hstack([a, a])[:, :3], b), angles)
    assert np.array_equal(aloft.deviation_angle(a.astype(np.float32), b.astype(np.float32)),
                          aloft.deviation_angle(a.astype(np.float32).astype(np.float64),
                                                b.astype(np.float32).astype(np.float64)))
    assert aloft.deviation_angle(a[0], b[0]).shape == ()


def test_read_imu_is_the_plain_log():
    path = EXAMPLES / "throw_imu.csv"
    log = aloft.read_imu(path)
    table = np.loadtxt(path, delimiter=",", skiprows=1)
    assert_float64_rows(log["gyro"], (len(table), 3))
    assert np.array_equal(log["t"], table[:, 0])
    assert np.array_equal(log["gyro"], table[:, 1:4])
    assert np.array_equal(log["accel"], table[:, 4:7])
    # The arrays view the reader's own memory (no copy): NumPy holds it through their base.
    assert log["gyro"].base is not None and log["t"].base is not None


def test_read_imu_is_the_phyphox_log_and_converts_units():
    path = shared_data("real", "racquet", "2025-01-16_17-10-11", "gyro.csv")
    with open(path, newline="") as f:
        rows = [[float(cell) for cell in row] for row in list(csv.reader(f))[1:]]
    table = np.array(rows)
    log = aloft.read_imu(str(path))
    assert set(log) == {"t", "gyro"}  # phyphox's gyroscope export has no accelerometer
    assert np.array_equal(log["t"], table[:, 0])
    assert np.array_equal(log["gyro"], table[:, 1:4])
    in_deg = aloft.read_imu(path, gyro_units="deg/s")
    assert np.allclose(in_deg["gyro"], table[:, 1:4] * math.pi / 180, rtol=1e-15, atol=0)
