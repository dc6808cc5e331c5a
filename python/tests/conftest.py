# Shared fixtures of the Python tests (run by CTest from the source tree with
# the build tree's package first on PYTHONPATH: python/CMakeLists.txt).
import json
import os
import subprocess

import pytest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CHURCH = os.path.join("mechanisms", "church-facade.json")
# The seed's Fig. 2 wall (2b = 0.25 m, 2h = 3 m, 12.06 kN/m^3; docs/seed-fig2.md)
# and the Sturno record of the seed study (39 s, 16 392 samples at 0.0024 s).
WALL = dict(thickness=0.25, height=3.0, unit_weight=12.06)
STURNO = os.path.join("spectra", "records", "RSN292_ITALY_A-STU270.AT2")


@pytest.fixture(autouse=True)
def _in_source_tree(monkeypatch):
    monkeypatch.chdir(ROOT)


def cli_exe():
    exe = os.environ.get("ASSESS_EXE")
    if not exe or not os.path.exists(exe):
        pytest.skip("the assess executable (ASSESS_EXE) is not available")
    return exe


def cli(*args, expect_rc=0):
    """Runs `assess ARGS` in the source tree; returns (stdout, stderr)."""
    p = subprocess.run([cli_exe(), *args], cwd=ROOT, capture_output=True, text=True)
    assert p.returncode == expect_rc, "assess %s: exit %d\n%s" % (" ".join(args), p.returncode, p.stderr)
    return p.stdout, p.stderr


def cli_json(*args):
    out, _ = cli(*args)
    return json.loads(out)


def pytest_sessionfinish(session, exitstatus):
    """Exit status 77 when every test was skipped (CTest SKIP_RETURN_CODE: reported as not run, not passed)."""
    reporter = session.config.pluginmanager.get_plugin("terminalreporter")
    if exitstatus == 0 and reporter is not None and reporter.stats.get("skipped") and not reporter.stats.get("passed"):
        session.exitstatus = 77
