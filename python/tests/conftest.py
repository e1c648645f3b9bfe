"""Shared fixtures: the folder of the commands (CFPO_BUILD, set by
scripts/python-test.sh; the byte-identity tests are skipped without it)
and a helper that runs one command quietly in a temporary folder."""
import os
import subprocess
from pathlib import Path

import pytest


@pytest.fixture(scope="session")
def build():
    b = os.environ.get("CFPO_BUILD")
    if not b or not (Path(b) / "cfpo").exists():
        pytest.skip("CFPO_BUILD (the folder with the cfpo commands) is not set")
    return Path(b)


@pytest.fixture
def command(build, tmp_path):
    """command(name, *args) runs build/name with -q in tmp_path; returns its
    completed process (check=True)."""
    def run(name, *args, check=True):
        return subprocess.run([str(build / name), "-q", *map(str, args)], cwd=tmp_path, check=check,
                              capture_output=True, text=True)
    return run
