"""Shared fixtures: the repository's scenes and the kinrepro CLI binary.

The CLI is the independent reference of these tests: it is the binary that
`cargo build --release` (or `cargo test --release`) leaves in target/release
(or $KINREPRO_CLI). Tests that compare against it are skipped without it.
"""

import json
import os
import pathlib
import subprocess
import sys

import pytest

import kinrepro

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCENES = ROOT / "scenes"


def cli_path():
    p = os.environ.get("KINREPRO_CLI")
    if p:
        return pathlib.Path(p)
    target = pathlib.Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    return target / "release" / "kinrepro"


@pytest.fixture(scope="session")
def cli():
    path = cli_path()
    if not path.is_file():
        pytest.skip(f"the kinrepro CLI is not built at {path} (cargo build --release)")

    def run(*args):
        out = subprocess.run(
            [str(path), *map(str, args)], cwd=ROOT, check=True, capture_output=True, text=True
        )
        return json.loads(out.stdout)

    return run


@pytest.fixture(autouse=True)
def in_root(monkeypatch):
    """Run every test from the repository root: scene paths as the CLI sees them."""
    monkeypatch.chdir(ROOT)


@pytest.fixture(scope="session")
def scene01():
    os.chdir(ROOT)
    return kinrepro.Scene.load("scenes/01_maxwell_vgroove_steel.toml")


@pytest.fixture(scope="session")
def study01(scene01):
    """The issue's reference study: 400 Monte Carlo samples, seed 9."""
    return kinrepro.study(scene01, samples=400, sampler="mc", seed=9)


def run_script(code, folder, timeout=300):
    """`code` saved as a script in `folder` (beside a link to the bundled
    scenes) and run by a fresh interpreter there, as a user runs an
    example; the completed process."""
    (folder / "scenes").symlink_to(SCENES)
    script = folder / "example.py"
    script.write_text(code)
    return subprocess.run(
        [sys.executable, str(script)], cwd=folder, capture_output=True, text=True, timeout=timeout
    )
