"""What the Python module's tests share: where things are, the command to compare with,
and a key-by-key comparison of reports.

ctest sets the environment (tests/python/CMakeLists.txt): PYTHONPATH holds the module of
this build, ALOFT_PROGRAM is the `aloft` program of the same build."""

import json
import os
import subprocess
from pathlib import Path

import pytest

SOURCE = Path(os.environ.get("ALOFT_SOURCE_DIR", Path(__file__).resolve().parents[2]))
SHARED = Path(os.environ.get("ALOFT_SHARED_DIR", SOURCE.parent / "shared"))
EXAMPLES = SOURCE / "examples"
PROGRAM = os.environ.get("ALOFT_PROGRAM", "aloft")
RACQUET = SHARED / "data" / "real" / "racquet"


def shared_data(*parts):
    """A path in ../shared/data, or the test skipped with the reason when it is absent."""
    path = SHARED.joinpath("data", *parts)
    if not path.exists():
        pytest.skip(f"{path} absent: the shared data folder is not beside this checkout")
    return path


def run_program(*args, check=True):
    """`aloft ARGS...`; returns the finished process (stdout, stderr as text)."""
    done = subprocess.run([PROGRAM, *map(str, args)], capture_output=True, text=True)
    if check and done.returncode != 0:
        raise AssertionError(f"aloft {' '.join(map(str, args))}: exit {done.returncode}: {done.stderr}")
    return done


def program_json(tmp_path, *args):
    """What json.loads makes of the report `aloft ARGS... --json FILE` writes."""
    report = tmp_path / "report.json"
    run_program(*args, "--json", report)
    return json.loads(report.read_text())


def assert_same_report(ours, theirs, where="report", skip=()):
    """Equal key by key, in the same order, floats exact; `where` names the first difference."""
    assert type(ours) is type(theirs), f"{where}: {type(ours).__name__} != {type(theirs).__name__}"
    if isinstance(ours, dict):
        keys = [k for k in ours if k not in skip]
        assert keys == [k for k in theirs if k not in skip], f"{where}: keys {keys} != {list(theirs)}"
        for key in keys:
            assert_same_report(ours[key], theirs[key], f"{where}.{key}", skip)
    elif isinstance(ours, list):
        assert len(ours) == len(theirs), f"{where}: {len(ours)} items != {len(theirs)}"
        for i, (a, b) in enumerate(zip(ours, theirs)):
            assert_same_report(a, b, f"{where}[{i}]", skip)
    else:
        assert ours == theirs, f"{where}: {ours!r} != {theirs!r}"
