# assess.rocking returns what `assess rocking ... --json` prints, its history
# equals the CLI's --history file, an array record gives the same analysis as
# the same record read from its file, and assess.RockingModel gives the seed's
# Fig. 2 numbers (docs/seed-fig2.md) and Housner's free-rocking period.
import math

import numpy as np
import pytest

import assess
from conftest import STURNO, WALL, cli_json

SMOOTH = dict(model="smooth", k=1e6, **WALL)  # 1e6 kN/m^3 = 1e9 N/m^3, the seed study's k
CLI_SMOOTH = ["rocking", "--model", "smooth", "--k", "1e6", "--thickness", "0.25", "--height", "3",
              "--unit-weight", "12.06"]


def without_history(d):
    return {k: v for k, v in d.items() if k not in ("t", "theta", "theta_dot")}


def test_rocking_equals_cli_json_and_history_file(tmp_path):
    hist = tmp_path / "h.csv"
    expected = cli_json(*CLI_SMOOTH, "--record", STURNO, "--scale", "1.6", "--history", str(hist), "--json")
    py = assess.rocking(record=STURNO, scale=1.6, history=True, **SMOOTH)
    assert without_history(py) == expected
    cli_hist = np.loadtxt(hist, delimiter=",", skiprows=1)
    assert cli_hist.shape == (py["t"].size, 3)
    # The file prints 9 significant digits (%.9g): equal within half a unit of the ninth.
    for col, key in enumerate(("t", "theta", "theta_dot")):
        np.testing.assert_allclose(py[key], cli_hist[:, col], rtol=6e-9, atol=1e-300, err_msg=key)
    assert py["theta"].dtype == np.float64 and py["t"][0] == 0.0
    assert np.max(np.abs(py["theta"])) == pytest.approx(py["theta_max"], rel=1e-12)


def test_rigid_one_sided_equals_cli():
    args = ["rocking", "--model", "rigid", "--thickness", "0.65", "--height", "14.57", "--unit-weight", "18",
            "--one-sided", "--record", STURNO, "--scale", "2", "--reverse", "--json"]
    py = assess.rocking("rigid", 0.65, 14.57, 18.0, STURNO, one_sided=True, scale=2.0, reverse=True)
    assert py == cli_json(*args)


def test_array_record_equals_the_same_record_from_its_file(tmp_path):
    rec = assess.records.read(STURNO)
    assert rec["npts"] == rec["acc"].size and rec["dt"] > 0
    # A plain file of the record in g, one value per line, written exactly (repr).
    values_g = rec["acc"] / 9.80665
    plain = tmp_path / "sturno_g.txt"
    plain.write_text("\n".join(repr(float(v)) for v in values_g) + "\n")
    from_file = assess.rocking(record=str(plain), dt=rec["dt"], **SMOOTH)
    from_array = assess.rocking(record=np.loadtxt(plain), dt=rec["dt"], **SMOOTH)
    assert without_history(from_array) == without_history(
        {**from_file, "record": {**from_file["record"], "name": "record"}})
    # The AT2 file and its samples in m/s^2: the same analysis.
    from_at2 = assess.rocking(record=STURNO, **SMOOTH)
    from_acc = assess.rocking(record=rec["acc"], dt=rec["dt"], unit="m/s^2", name=rec["name"], **SMOOTH)
    for key in from_at2:
        if key != "record":
            assert from_acc[key] == from_at2[key], key
    # Any float dtype, any contiguity: converted to doubles once.
    strided = np.repeat(rec["acc"], 2)[::2].astype(np.float64)
    assert assess.rocking(record=strided, dt=rec["dt"], unit="m/s^2", **SMOOTH)["theta_max"] == from_at2["theta_max"]


def test_rocking_model_gives_the_seed_fig2_numbers():
    # docs/seed-fig2.md, table: k = 1e9 N/m^3 (1e6 kN/m^3).
    m = assess.RockingModel("smooth", k=1e6, **WALL)
    W = 12.06 * 0.25 * 3.0  # kN/m
    assert m.weight == pytest.approx(W, rel=1e-12)
    # theta_cr = W / (2 b^2 k) (seed Eq. 1), closed form
    assert m.theta_cr == pytest.approx(W * 1e3 / (2 * 0.125**2 * 1e9), rel=1e-12)
    assert m.theta_u == pytest.approx(0.07981, abs=5e-6)  # table, 4 digits
    assert m.peak_moment == pytest.approx(0.8837, abs=5e-5)  # 883.7 N m/m
    assert m.capacity == pytest.approx(0.03987, abs=5e-6)  # 39.87 J/m
    th = np.linspace(0.0, m.theta_u, 7)
    M = m.moment(th)
    assert M.shape == th.shape and M[0] == pytest.approx(0.0, abs=1e-12) and M[-1] == pytest.approx(0.0, abs=1e-9)
    # Full contact (theta <= theta_cr, seed Eq. 1): M = W R sin(alpha - theta) - W b + (2/3) k b^3 theta
    #   = W b (cos theta - 1) - W h sin theta + (2/3) k b^3 theta   (R sin alpha = b, R cos alpha = h)
    for th in (0.25 * m.theta_cr, 0.5 * m.theta_cr, m.theta_cr):
        exact = W * 0.125 * (math.cos(th) - 1) - W * 1.5 * math.sin(th) + 2.0 / 3.0 * 1e6 * 0.125**3 * th
        assert m.moment(th) == pytest.approx(exact, rel=1e-9)


def test_rigid_free_rocking_period_is_the_energy_integral():
    m = assess.RockingModel("rigid", **WALL)
    R = math.hypot(0.125, 1.5)
    alpha = math.atan(0.125 / 1.5)
    # rectangle: I0 = (4/3) m R^2, p^2 = W R / I0 = 3 g / (4 R), with the library's g = 9.81 m/s^2
    # of the mass m = W / g (support/units.hpp)
    p = math.sqrt(3 * 9.81 / (4 * R))
    assert m.frequency_parameter == pytest.approx(p, rel=1e-12)
    assert m.alpha == pytest.approx(alpha, rel=1e-12)
    # A quarter period from theta0 to 0, from the energy W R cos(alpha - theta) + I0 theta'^2 / 2:
    # T/4 = (1/p) int_0^theta0 dtheta / sqrt(2 (cos(alpha - theta0) - cos(alpha - theta))); with
    # theta = theta0 - t^2 the integrand is smooth: Gauss-Legendre, 80 points.
    x, w = np.polynomial.legendre.leggauss(80)
    for f in (0.2, 0.5, 0.9):
        th0 = f * alpha
        t = 0.5 * math.sqrt(th0) * (x + 1.0)
        integrand = 2 * t / np.sqrt(2 * (math.cos(alpha - th0) - np.cos(alpha - th0 + t * t)))
        exact = 4.0 / p * 0.5 * math.sqrt(th0) * np.dot(w, integrand)
        r = m.free(th0, 20.0)
        first_zero = r["t"][np.argmax(r["theta"] <= 0.0)]
        assert 4.0 * first_zero == pytest.approx(exact, rel=1e-6), f
        # Housner's (1963) linearised period, 4/p acosh(1/(1 - theta0/alpha)), within its error for a slender block
        assert 4.0 * first_zero == pytest.approx(4.0 / p * math.acosh(1.0 / (1.0 - f)), rel=2e-3), f
