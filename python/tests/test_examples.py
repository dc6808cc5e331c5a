# The example scripts of python/examples run and write their figures (the
# §3.2 study with 2 realisations instead of 50, the fragility with 2 records
# per stripe).
import os
import subprocess
import sys

import pytest

from conftest import ROOT

EXAMPLES = os.path.join(ROOT, "python", "examples")


@pytest.mark.parametrize("script, args, figure", [
    ("seed_fig2.py", [], "fig2.png"),
    ("church_facade.py", [], "church-dc.png"),
    ("seed_study_3_2.py", ["--realisations", "2"], "seed-3.2.png"),
    ("fragility_curve.py", ["--records", "2", "--stripes", "72,475,2475"], "fragility.png"),
])
def test_example_writes_its_figure(tmp_path, script, args, figure):
    env = dict(os.environ, MPLBACKEND="Agg", MPLCONFIGDIR=str(tmp_path / "mpl"))
    p = subprocess.run([sys.executable, os.path.join(EXAMPLES, script), *args, "--out", str(tmp_path)], cwd=ROOT,
                       env=env, capture_output=True, text=True)
    assert p.returncode == 0, p.stdout + p.stderr
    assert (tmp_path / figure).stat().st_size > 10000
    print(p.stdout)
