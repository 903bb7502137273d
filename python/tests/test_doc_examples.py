"""Every Python example of the docs runs as a user runs it: saved as a
script file and run by a fresh interpreter, from a folder that holds the
bundled scenes. The cluster examples run in their own tests with their
cluster (test_dask.py: LocalCluster; test_slurm.py: SLURMCluster against a
real Slurm); python/examples runs in test_example.py."""

import pathlib
import re

import pytest

from conftest import run_script

ROOT = pathlib.Path(__file__).resolve().parents[2]
PAGES = sorted((ROOT / "docs").glob("*.md")) + [ROOT / "README.md"]


def blocks():
    out = []
    for page in PAGES:
        for k, code in enumerate(re.findall(r"```python\n(.*?)```", page.read_text(), re.S)):
            if "LocalCluster(" in code or "SLURMCluster(" in code:
                continue
            out.append(pytest.param(code, id=f"{page.name}-{k + 1}"))
    return out


@pytest.mark.parametrize("code", blocks())
def test_a_doc_example_runs_as_a_script(code, tmp_path):
    out = run_script(code, tmp_path)
    assert out.returncode == 0, out.stderr[-2000:]
    if "KinreproError as e" in code:
        # The error example prints the library's message.
        assert "preload.force" in out.stdout and "must be positive" in out.stdout, out.stdout


def test_the_docs_have_examples():
    assert len(blocks()) >= 2
