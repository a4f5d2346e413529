"""The module as a consumer gets it: `cmake --install` into a fresh prefix, then imported
by a fresh interpreter from the prefix's site folder alone."""

import os
import subprocess
import sys
from pathlib import Path

from conftest import EXAMPLES


def test_installed_module_imports_and_works(tmp_path):
    prefix = tmp_path / "prefix"
    cmake = os.environ.get("CMAKE_COMMAND", "cmake")
    build = os.environ["ALOFT_BUILD_DIR"]
    subprocess.run([cmake, "--install", build, "--prefix", prefix, "--component", "python"], check=True,
                   capture_output=True)
    site = prefix / os.environ["ALOFT_PYTHON_INSTALL_DIR"]
    installed = list(site.glob("aloft*.so"))
    assert len(installed) == 1, f"{site}: {installed}"
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = str(site)
    script = f"""
import aloft
print(aloft.__file__)
print(len(aloft.read_imu({str(EXAMPLES / 'throw_imu.csv')!r})["t"]))
"""
    done = subprocess.run([sys.executable, "-c", script], env=env, cwd=tmp_path, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    where, samples = done.stdout.split()
    assert Path(where) == installed[0]
    assert int(samples) == len((EXAMPLES / "throw_imu.csv").read_text().splitlines()) - 1
