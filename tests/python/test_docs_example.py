"""docs/python.md's example, run as a reader would run it: its python code blocks in
order, from a folder beside ../shared, with matplotlib drawing into a file (Agg)."""

import os
import re
import subprocess
import sys

import pytest

from conftest import SHARED, SOURCE


def page_code():
    page = (SOURCE / "docs" / "python.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", page, re.S)
    assert blocks, "docs/python.md has no python code block"
    return "\n".join(blocks)


def test_docs_example_runs_and_draws(tmp_path):
    pytest.importorskip("matplotlib", reason="matplotlib absent (Debian: python3-matplotlib)")
    if not (SHARED / "data" / "real" / "racquet").exists():
        pytest.skip(f"{SHARED}: no racquet sessions; the example reads them")
    # The page's paths are from the repository root: ../shared beside it.
    work = tmp_path / "aloft"
    work.mkdir()
    (tmp_path / "shared").symlink_to(SHARED)
    env = dict(os.environ, MPLBACKEND="Agg")
    done = subprocess.run([sys.executable, "-c", page_code()], cwd=work, env=env, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    figure = work / "omega.png"
    assert figure.exists() and figure.stat().st_size > 10_000
