#!/usr/bin/env python3
"""`assess run --fragility DIR` (issue 16): the additional probabilistic result
in the terminal, the JSON and the HTML relazione (IT and EN).

Usage: check_fragility_in_report.py EXE CASE OUTDIR
Runs a small fragility of CASE into OUTDIR/frag, then `assess run` with
--fragility. Checks that the JSON's "fragility" carries the governing
overturning curve of summary.json (median, beta, lambda_c, return period,
probability in VN) and the code's SLV return period, labelled as not a code
check; that its numbers obey their closed forms (T = 1/lambda_c,
P = 1 - exp(-lambda_c VN), docs/theory/fragility.md §3); that both HTML
languages show them in the box; that the terminal stays within 120 columns.
"""
import json
import math
import os
import shutil
import subprocess
import sys

# Relative tolerances (-): values copied through JSON (17 digits) and the closed
# forms evaluated in double precision.
TOL_COPY = 1e-15
TOL_CLOSED_FORM = 1e-12


def run(*args):
    p = subprocess.run(args, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"{' '.join(args)}: exit {p.returncode}\n{p.stdout}\n{p.stderr}")
    return p.stdout


def close(a, b, tol):
    return abs(a - b) <= tol * max(abs(a), abs(b))


def main():
    exe, source_case, out = sys.argv[1:4]
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    # A copy of the case (edited at the end: a stale result must be refused).
    case = os.path.join(out, os.path.basename(source_case))
    shutil.copyfile(source_case, case)
    frag = os.path.join(out, "frag")
    run(exe, "fragility", case, "--stripes", "72,475,2475", "--records", "3", "--bootstrap", "0", "--no-plots",
        "--out", frag, "--quiet")
    with open(os.path.join(frag, "summary.json")) as f:
        s = json.load(f)
    g = s["governing"]
    errors = []

    j = json.loads(run(exe, "run", case, "--fragility", frag, "--json"))["fragility"]
    if j["kind"] != "additional probabilistic result, not a code check":
        errors.append(f"kind: {j['kind']!r}")
    if not j["has_risk"] or "return_period_years" not in g:
        errors.append("expected a risk figure for this case (has_risk false)")
    pairs = [("median_pga_m_s2", g["theta_m_s2"]), ("beta", g["beta"]), ("lambda_per_year", g["lambda_per_year"]),
             ("return_period_years", g["return_period_years"]), ("probability_in_VN", g["probability_in_VN"]),
             ("VN_years", s["VN_years"]), ("TR_SLV_years", s["code"]["SLV"]["TR_years"]),
             ("pga_SLV_m_s2", s["code"]["SLV"]["pga_m_s2"]),
             ("P_overturning_at_SLV_pga", s["code"]["SLV"]["P_overturning_at_pga"])]
    for key, want in pairs:
        if not close(j[key], want, TOL_COPY):
            errors.append(f"{key}: {j[key]} vs summary {want}")
    lam, vn = j["lambda_per_year"], j["VN_years"]
    if not close(j["return_period_years"] * lam, 1.0, TOL_CLOSED_FORM):
        errors.append(f"return period {j['return_period_years']} != 1/lambda {1 / lam}")
    if not close(j["probability_in_VN"], -math.expm1(-lam * vn), TOL_CLOSED_FORM):
        errors.append(f"P in VN {j['probability_in_VN']} != 1 - exp(-lambda VN) {-math.expm1(-lam * vn)}")
    if not close(j["median_pga_g"] * 9.81, j["median_pga_m_s2"], TOL_CLOSED_FORM):  # g of NTC 2018 §3.2.3.2.3 (support/units.hpp)
        errors.append("median_pga_g is not median_pga_m_s2 / g")
    if not 0.0 < j["TR_SLV_years"] < 1e4 or not 0.0 < j["probability_in_VN"] < 1.0:
        errors.append("TR_SLV or P in VN out of range")

    # The terminal's summary (issue 41: the relazione's own sections) carries the labelled box.
    text = run(exe, "run", case, "--fragility", frag, "--lang", "en")
    if "Additional probabilistic result" not in text or "Not a code check" not in text:
        errors.append("terminal: no labelled probabilistic result")
    long_lines = [l for l in text.splitlines() if len(l) > 120]
    if long_lines:
        errors.append(f"terminal: {len(long_lines)} lines over 120 columns: {long_lines[0]!r}")

    expect = {
        "en": ["Additional probabilistic result: annual risk of overturning", "Not a code check",
               f"{j['median_pga_g']:.3f} g", f"{j['beta']:.3f}", f"{j['lambda_per_year']:.3e}/year",
               f"{j['return_period_years']:.0f} years", f"{100 * j['probability_in_VN']:.1f} %",
               f"Return period of SLV (code, NTC 2018 §3.2.1)</td><td class=\"num\">{j['TR_SLV_years']:.0f} years",
               f"(VN = {vn:.0f} years)", "class=\"box probabilistic\""],
        # The Italian edition writes the decimal comma (issue 28).
        "it": ["Risultato probabilistico aggiuntivo: rischio annuo di ribaltamento", "Non è una verifica di norma",
               f"{j['median_pga_g']:.3f} g".replace(".", ","), f"{j['return_period_years']:.0f} anni",
               f"Periodo di ritorno dello SLV (norma, NTC 2018 §3.2.1)</td><td class=\"num\">{j['TR_SLV_years']:.0f} anni"],
    }
    for lang, needles in expect.items():
        html = os.path.join(out, f"report_{lang}.html")
        run(exe, "run", case, "--fragility", frag, "--html", html, "--lang", lang)
        with open(html, encoding="utf-8") as f:
            page = f.read()
        for n in needles:
            if n not in page:
                errors.append(f"HTML ({lang}): missing {n!r}")
        # The box comes after the verdicts by approach, not among the checks.
        if page.find("class=\"box probabilistic\"") < page.find("fig-dc"):
            errors.append(f"HTML ({lang}): the probabilistic box precedes the verdicts by approach")
    # Without --fragility (and no CASE.fragility in the working directory) there is no fragility result.
    if "fragility" in json.loads(run(exe, "run", case, "--json")):
        errors.append("JSON without --fragility has a fragility result")

    # The case edited after the fragility: its result is refused, naming the change (exit status 2).
    with open(case, "a") as f:
        f.write("\n")
    p = subprocess.run([exe, "run", case, "--fragility", frag, "--json"], capture_output=True, text=True)
    if p.returncode != 2 or "has changed since this fragility was computed" not in p.stderr:
        errors.append(f"edited case: exit {p.returncode}, stderr {p.stderr.strip()!r}")

    if errors:
        sys.exit("\n".join(errors))
    print(f"fragility in report: median {j['median_pga_g']:.3f} g, beta {j['beta']:.3f}, "
          f"lambda {lam:.3e}/year, T {j['return_period_years']:.0f} years, P(VN) {100 * j['probability_in_VN']:.1f} %, "
          f"TR SLV {j['TR_SLV_years']:.0f} years: ok")


if __name__ == "__main__":
    main()
