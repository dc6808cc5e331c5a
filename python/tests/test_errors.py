# Bad input raises assess.InputError, a ValueError with the command line's
# message and its JSON path; a failure of the machine raises OSError; nothing
# crashes the interpreter.
import os
import subprocess
import sys
import textwrap

import pytest

import assess
from conftest import CHURCH, WALL, cli


def cli_error(*args):
    _, err = cli(*args, expect_rc=2)
    assert err.startswith("assess: error: ")
    return err[len("assess: error: "):].strip()


def test_bad_case_raises_value_error_naming_the_path():
    case = os.path.join("tests", "cli", "run_bad", "unknown_key.json")
    with pytest.raises(ValueError) as e:
        assess.run(case)
    assert isinstance(e.value, assess.InputError)
    assert str(e.value) == cli_error("run", case)
    assert e.value.file == case
    assert e.value.path == "/dynamic"
    assert "polarity" in str(e.value)  # the suggestion of the command line


def test_bad_dict_names_its_json_path():
    import json

    with open(CHURCH, encoding="utf-8") as f:
        doc = json.load(f)
    doc["site"]["soil"] = "Z"
    with pytest.raises(assess.InputError) as e:
        assess.run(doc)
    assert e.value.file == "case" and e.value.path == "/site/soil"
    doc["site"]["soil"] = "C"
    doc["mechanism"]["storeys"][0]["thickness"] = float("nan")
    with pytest.raises(assess.InputError) as e:
        assess.kinematic(doc)
    assert e.value.path == "/mechanism/storeys/0/thickness"


def test_rocking_option_errors_are_the_cli_messages():
    with pytest.raises(assess.InputError) as e:
        assess.rocking("smooth", record="spectra/records/RSN292_ITALY_A-STU270.AT2", **WALL)
    assert str(e.value) == cli_error("rocking", "--model", "smooth", "--thickness", "0.25", "--height", "3",
                                     "--unit-weight", "12.06", "--record", "spectra/records/RSN292_ITALY_A-STU270.AT2")
    for scale in ("0", "-1", "200"):
        with pytest.raises(assess.InputError) as e:
            assess.rocking("rigid", record="spectra/records/RSN292_ITALY_A-STU270.AT2", scale=float(scale), **WALL)
        assert str(e.value) == cli_error("rocking", "--model", "rigid", "--thickness", "0.25", "--height", "3",
                                         "--unit-weight", "12.06", "--record", "spectra/records/RSN292_ITALY_A-STU270.AT2",
                                         "--scale", scale)
    with pytest.raises(assess.InputError, match=r"record: value 1 is not a number"):
        assess.rocking("rigid", record=[0.0, float("nan"), 0.1], dt=0.01, **WALL)
    with pytest.raises(assess.InputError, match="--dt: the time step"):
        assess.rocking("rigid", record=[0.0, 0.1, 0.0], **WALL)
    with pytest.raises(assess.InputError, match="one-dimensional"):
        assess.rocking("rigid", record=[[0.0, 0.1], [0.2, 0.3]], dt=0.01, **WALL)


def test_hostile_python_values_are_input_errors():
    loop = {"project": "x"}
    loop["site"] = loop  # a dict that holds itself
    with pytest.raises(assess.InputError, match="nested more than 64 levels"):
        assess.run(loop)
    with pytest.raises(assess.InputError, match="not a string"):
        assess.run({1: 2})
    with pytest.raises(assess.InputError, match="beyond 64 bits"):
        assess.kinematic({"schema_version": 10**30})
    with pytest.raises(assess.InputError, match="Python type object"):
        assess.kinematic({"project": object()})
    with pytest.raises(assess.InputError):
        assess.run("no/such/case.json")


def test_a_full_disk_is_an_os_error(tmp_path):
    # The results file stops growing at 4 kB (RLIMIT_FSIZE, SIGXFSZ ignored: write fails with EFBIG).
    script = textwrap.dedent("""
        import resource, signal, sys
        import assess
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (4096, 4096))
        spec = {"walls": [{"name": "w", "b": 0.125, "h": 1.5}], "unit_weight_kN_m3": 12.06,
                "records": [{"name": "s", "file": "spectra/records/RSN292_ITALY_A-STU270.AT2"}],
                "scale_factors": [0.1], "realisations": 60, "time_cov": 0.03, "amplitude_cov": 0.03,
                "seed": 1, "models": ["rigid"], "restitution": ["housner"]}
        try:
            assess.campaign(spec, out=sys.argv[1], threads=1)
        except OSError as e:
            print("OSError", e)
        except Exception as e:
            print("other", type(e).__name__, e)
    """)
    p = subprocess.run([sys.executable, "-c", script, str(tmp_path / "out")], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    assert p.stdout.startswith("OSError"), p.stdout + p.stderr
