"""Where the command line is: THINJKR_BIN (set by .ci/test), else the
workspace's debug or release build."""

import os
import pathlib
import shutil

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


def pytest_configure(config):
    # .ci/test runs `-m "not slow"`; the slow tier (.ci/slow) runs `-m slow`
    config.addinivalue_line(
        "markers", "slow: the slow tier's (.ci/slow), left out of CI for time")


@pytest.fixture(scope="session")
def cli():
    for cand in (os.environ.get("THINJKR_BIN"), ROOT / "target/debug/thinjkr",
                 ROOT / "target/release/thinjkr", shutil.which("thinjkr")):
        if cand and pathlib.Path(cand).is_file():
            return str(cand)
    pytest.fail("no thinjkr binary: build it (cargo build -p thinjkr) or set THINJKR_BIN")
