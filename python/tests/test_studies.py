# assess.spectrum, assess.records, assess.campaign and assess.fragility return
# what the command line prints (or writes), from the same library functions.
import json
import os

import numpy as np

import assess
from conftest import cli, cli_json

SITE = {"lat": 43.44, "lon": 12.64, "soil": "C"}  # the church's site (mechanisms/church-facade.json)
FREE_WALL = os.path.join("tests", "data", "fragility", "free_wall.json")


def same_spectrum(py, expected):
    points = expected.pop("spectrum")
    arrays = py.pop("spectrum")
    assert py == expected
    for key in points[0]:
        np.testing.assert_array_equal(arrays[key], [p[key] for p in points])


def test_spectrum_equals_cli_json():
    py = assess.spectrum(SITE, "SLV", periods=[0.0, 0.3, 1.0, 2.5])
    expected = cli_json("spectrum", "--lat", "43.44", "--lon", "12.64", "--soil", "C", "--limit-state", "SLV",
                        "--periods", "0,0.3,1,2.5", "--json")
    assert isinstance(py["spectrum"]["Se_g"], np.ndarray)
    same_spectrum(py, expected)


def test_spectrum_of_every_limit_state_and_a_return_period_equal_cli_json():
    py = assess.spectrum(SITE, None, q=1.5)
    expected = cli_json("spectrum", "--lat", "43.44", "--lon", "12.64", "--soil", "C", "--q", "1.5", "--json")
    for a, b in zip(py.pop("limit_states"), expected.pop("limit_states")):
        same_spectrum(a, b)
    assert py == expected
    same_spectrum(assess.spectrum(SITE, tr=975),
                  cli_json("spectrum", "--lat", "43.44", "--lon", "12.64", "--soil", "C", "--tr", "975", "--json"))


def test_records_list_and_select_equal_cli_json():
    assert assess.records.list(site_class="A", mw_min=6.5) == cli_json("records", "list", "--site-class", "A",
                                                                       "--mw-min", "6.5", "--json")
    assert len(assess.records.list(all=True)) == 450
    py = assess.records.select(SITE, count=5)
    assert py == cli_json("records", "select", "--lat", "43.44", "--lon", "12.64", "--soil", "C", "--count", "5",
                          "--json")
    assert len(py["records"]) == 5


SPEC = {
    "name": "python-test",
    "walls": [{"name": "b0.125_h1.5", "b": 0.125, "h": 1.5}, {"name": "b0.25_h3.0", "b": 0.25, "h": 3.0}],
    "unit_weight_kN_m3": 12.06,
    "k_kN_m3": 1e6,
    "records": [{"name": "Sturno WE", "file": "spectra/records/RSN292_ITALY_A-STU270.AT2"}],
    "scale_factors": [0.4, 1.0],
    "realisations": 3,
    "time_cov": 0.03,
    "amplitude_cov": 0.03,
    "seed": 20170612,
    "restitution": ["housner"],
    "models": ["smooth", "rigid"],
}


def test_campaign_rows_equal_the_cli_results(tmp_path):
    spec = tmp_path / "spec.json"
    spec.write_text(json.dumps(SPEC))
    cli("campaign", str(spec), "--out", str(tmp_path / "cli"), "--threads", "2", "--no-plots", "--quiet")
    rows = assess.campaign(SPEC, threads=2, out=tmp_path / "py")
    assert (tmp_path / "py" / "results.csv").read_bytes() == (tmp_path / "cli" / "results.csv").read_bytes()
    assert len(rows) == 2 * 1 * 2 * 3 * 2
    assert (tmp_path / "py" / "summary.json").read_bytes() == (tmp_path / "cli" / "summary.json").read_bytes()
    # The rows as a table: pandas when it imports, else a numpy structured array.
    try:
        import pandas as pd

        assert isinstance(rows, pd.DataFrame)
        columns = list(rows.columns)
    except ImportError:
        columns = list(rows.dtype.names)
    with open(tmp_path / "cli" / "results.csv", encoding="utf-8") as f:
        assert columns == f.readline().strip().split(",")


def test_campaign_rows_without_pandas(tmp_path, monkeypatch):
    import builtins

    real_import = builtins.__import__

    def no_pandas(name, *a, **k):
        if name == "pandas":
            raise ImportError("no pandas")
        return real_import(name, *a, **k)

    monkeypatch.setattr(builtins, "__import__", no_pandas)
    rows = assess.campaign(SPEC, threads=1, limit=6)
    assert isinstance(rows, np.ndarray) and rows.dtype.names[0] == "id"
    assert list(rows["id"]) == list(range(6))
    assert rows["wall"][0] == "b0.125_h1.5" and rows["model"][0] in ("smooth", "rigid")


def test_fragility_equals_cli_json(tmp_path):
    args = ["--stripes", "72,475,2475", "--records", "3", "--bootstrap", "20", "--no-plots", "--quiet", "--json"]
    expected = cli_json("fragility", FREE_WALL, "--out", str(tmp_path / "cli"), *args)
    py = assess.fragility(FREE_WALL, stripes=[72, 475, 2475], records=3, bootstrap=20, out=tmp_path / "py")
    assert py == expected
