"""Bad input raises ValueError, a file that cannot be read OSError, each with the message
the command prints (its stderr line without the leading "aloft: "), and the interpreter
lives on."""

import errno
import json
import subprocess
import sys

import numpy as np
import pytest

import aloft
from conftest import EXAMPLES, RACQUET, run_program, shared_data

BODY = EXAMPLES / "throw_body.json"
IMU = EXAMPLES / "throw_imu.csv"


def command_message(*args):
    done = run_program(*args, check=False)
    assert done.returncode == 2, done
    line = done.stderr.strip()
    return line[len("aloft: "):] if line.startswith("aloft: ") else line


def test_missing_body_file_is_file_not_found(tmp_path):
    missing = tmp_path / "no_body.json"
    with pytest.raises(FileNotFoundError) as raised:
        aloft.replay(str(missing), imu=str(IMU))
    assert isinstance(raised.value, OSError) and raised.value.errno == errno.ENOENT
    assert str(raised.value) == command_message("replay", "--body", missing, "--imu", IMU)


def test_missing_log_is_os_error_with_the_commands_message(tmp_path):
    missing = tmp_path / "no_log.csv"
    with pytest.raises(OSError) as raised:
        aloft.diagnose(str(BODY), imu=str(missing))
    assert str(raised.value) == command_message("diagnose", "--body", BODY, "--imu", missing)
    with pytest.raises(OSError):
        aloft.read_imu(missing)
    with pytest.raises(OSError):
        aloft.records(missing)


def test_bad_body_is_value_error_with_the_commands_message(tmp_path):
    body = json.loads(BODY.read_text())
    body["inertia"]["tensor"][0][1] = 0.01  # not symmetric
    path = tmp_path / "asymmetric.json"
    path.write_text(json.dumps(body))
    with pytest.raises(ValueError) as raised:
        aloft.replay(str(path), imu=str(IMU))
    assert str(raised.value) == command_message("replay", "--body", path, "--imu", IMU)
    with pytest.raises(ValueError, match="^body dict: "):
        aloft.replay(body, imu=IMU)


def test_refused_options_are_value_errors_with_the_commands_line(tmp_path):
    with pytest.raises(ValueError) as raised:
        aloft.diagnose(BODY, imu=IMU, threds=2)
    assert str(raised.value) == command_message("diagnose", "--body", BODY, "--imu", IMU, "--threds", 2)
    assert "did you mean --threads?" in str(raised.value)
    with pytest.raises(ValueError, match="--threads"):
        aloft.diagnose(BODY, imu=IMU, threads=0)
    with pytest.raises(ValueError, match="give exactly one of --imu, --markers, --poses"):
        aloft.diagnose(BODY)
    with pytest.raises(ValueError, match="calibrate"):
        aloft.study(calibrate_to_paper=True)
    with pytest.raises(ValueError, match="--time-units"):
        aloft.read_imu(IMU, time_units="fortnights")


def test_bad_numbers_and_arrays_are_value_errors(tmp_path):
    with pytest.raises(ValueError) as raised:
        aloft.simulate(BODY, (0, 1, 2), 1.0, 100.0, q0=(1, 1, 0, 0))
    assert str(raised.value) == command_message("simulate", "--body", BODY, "--w0", "0,1,2", "--q0", "1,1,0,0",
                                                "--duration", 1, "--rate", 100, "--out", tmp_path / "t.csv")
    with pytest.raises(ValueError, match="rate"):
        aloft.simulate(BODY, (0, 1, 2), 1.0, -5.0)
    with pytest.raises(ValueError, match="w0"):
        aloft.simulate(BODY, (0, 1), 1.0, 100.0)
    with pytest.raises(ValueError, match="same shape"):
        aloft.deviation_angle(np.zeros((4, 3)), np.zeros((5, 3)))
    with pytest.raises(ValueError, match="same shape"):
        aloft.deviation_angle(np.zeros((4, 2)), np.zeros((4, 2)))
    with pytest.raises(TypeError):
        aloft.replay(BODY, imu=IMU, time_units=object())


def test_files_of_the_wrong_kind_are_value_errors():
    with pytest.raises(ValueError) as raised:
        aloft.records(str(IMU))
    assert str(raised.value) == command_message("records", IMU, "--json")
    with pytest.raises(ValueError):
        aloft.read_imu(BODY)


def test_the_interpreter_lives_on_after_bad_input():
    # In a fresh interpreter: three bad calls, each caught, then a good one and a clean exit.
    script = f"""
import aloft
for call in (lambda: aloft.diagnose({str(BODY)!r}, imu="/nonexistent/log.csv"),
             lambda: aloft.replay({{"name": "x"}}, imu={str(IMU)!r}),
             lambda: aloft.records({str(BODY)!r})):
    try:
        call()
    except (ValueError, OSError) as e:
        print(type(e).__name__)
print(len(aloft.replay({str(BODY)!r}, imu={str(IMU)!r})["flights"]))
"""
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert done.stdout.split() == ["FileNotFoundError", "ValueError", "ValueError", "1"]


def test_the_commands_warnings_are_python_warnings():
    session = shared_data("real", "racquet", "2025-01-16_17-10-11")
    body = RACQUET / "body.json"  # moments just off the triangle inequality, an extra key
    with pytest.warns(UserWarning, match="triangle inequality") as caught:
        aloft.simulate(body, (0.0, 20.0, 0.0), 0.1, 100.0)
    assert any("unknown key" in str(w.message) for w in caught)
    with pytest.warns(UserWarning, match="triangle inequality"):
        aloft.diagnose(body, imu=session / "gyro.csv", window="12.0:13.0")
