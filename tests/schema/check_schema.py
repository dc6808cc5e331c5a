#!/usr/bin/env python3
"""check_schema.py ASSESS SOURCE_DIR

The case-file JSON schema (docs/schema/case.schema.json, draft 2020-12) is
itself valid; every shipped case (mechanisms/*.json with a "mechanism", and
the case files of tests/cli/comuni) validates against it; every schema-level
bad case of tests/schema/bad/ is rejected BOTH by the schema and by the tool
(`assess kinematic FILE` exits 2 with a message naming the file). Validator:
Debian's python3-jsonschema. Exit 0 pass, 1 fail, 77 skipped (no jsonschema).
"""
import glob
import json
import os
import subprocess
import sys

try:
    import jsonschema
except ImportError:
    print("check_schema: python3-jsonschema not installed (Debian: apt-get install python3-jsonschema); skipped")
    sys.exit(77)

exe, src = sys.argv[1], sys.argv[2]
schema = json.load(open(os.path.join(src, "docs/schema/case.schema.json"), encoding="utf-8"))
jsonschema.Draft202012Validator.check_schema(schema)
validator = jsonschema.Draft202012Validator(schema)
failures = 0

good = sorted(glob.glob(os.path.join(src, "mechanisms/*.json"))) + sorted(glob.glob(os.path.join(src, "tests/cli/comuni/site_comune.json")))
n_good = 0
for f in good:
    doc = json.load(open(f, encoding="utf-8"))
    if "mechanism" not in doc:  # campaign files have their own format
        continue
    n_good += 1
    errors = list(validator.iter_errors(doc))
    if errors:
        failures += 1
        print(f"FAIL {os.path.relpath(f, src)}: shipped case rejected by the schema: {errors[0].message}")

bad = sorted(glob.glob(os.path.join(src, "tests/schema/bad/*.json")))
for f in bad:
    rel = os.path.relpath(f, src)
    doc = json.load(open(f, encoding="utf-8"))
    if validator.is_valid(doc):
        failures += 1
        print(f"FAIL {rel}: bad case accepted by the schema")
    run = subprocess.run([exe, "kinematic", f], capture_output=True, text=True, cwd=src)
    if run.returncode != 2 or "error:" not in run.stderr or os.path.basename(f) not in run.stderr:
        failures += 1
        print(f"FAIL {rel}: the tool gave exit {run.returncode}, stderr: {run.stderr.strip()[:300]}")
    else:
        print(f"ok   {rel}: rejected by the schema and by the tool ({run.stderr.strip()[:140]})")

if n_good < 8 or len(bad) < 10:
    failures += 1
    print(f"FAIL expected at least 8 shipped cases and 10 bad cases, found {n_good} and {len(bad)}")
print(f"check_schema: {n_good} shipped cases valid, {len(bad)} bad cases rejected by schema and tool; {failures} failure(s)")
sys.exit(1 if failures else 0)
