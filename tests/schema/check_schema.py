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

# Issue 22: the building case schema (docs/schema/building.schema.json) refers
# to the case schema for the site, the building and each mechanism.
bschema = json.load(open(os.path.join(src, "docs/schema/building.schema.json"), encoding="utf-8"))
jsonschema.Draft202012Validator.check_schema(bschema)
try:
    from referencing import Registry, Resource
    registry = Registry().with_resource(schema["$id"], Resource.from_contents(schema))
    bvalidator = jsonschema.Draft202012Validator(bschema, registry=registry)
except ImportError:  # jsonschema < 4.18 (Debian 12: 4.10)
    resolver = jsonschema.RefResolver.from_schema(bschema, store={schema["$id"]: schema})
    bvalidator = jsonschema.Draft202012Validator(bschema, resolver=resolver)
bgood = sorted(glob.glob(os.path.join(src, "mechanisms/building-*.json"))) + sorted(
    glob.glob(os.path.join(src, "tests/cli/building/*.json")))
for f in bgood:
    doc = json.load(open(f, encoding="utf-8"))
    errors = list(bvalidator.iter_errors(doc))
    if errors:
        failures += 1
        print(f"FAIL {os.path.relpath(f, src)}: shipped building rejected by the schema: {errors[0].message}")
    else:
        print(f"ok   {os.path.relpath(f, src)}: building valid")
# Bad buildings the schema can judge (duplicate names and partial dynamic
# overrides are the tool's alone).
bbad = [os.path.join(src, "tests/cli/building_bad", n + ".json") for n in
        ("unknown_key", "no_walls", "no_site", "fc_and_level", "mechanisms_not_array", "unknown_entry_key",
         "site_override", "bad_thickness", "bad_Z_override",
         # Issue 23: tie rods in a building (a bad rod grade in a mechanism, a negative fm in a wall's design, ties
         # at the building level). An anchor off the wall and a design without levels are the tool's alone.
         "ties_bad_grade", "ties_wall_design_fm", "ties_building_level")]
for f in bbad:
    rel = os.path.relpath(f, src)
    doc = json.load(open(f, encoding="utf-8"))
    if bvalidator.is_valid(doc):
        failures += 1
        print(f"FAIL {rel}: bad building accepted by the schema")
    run = subprocess.run([exe, "run", f], capture_output=True, text=True, cwd=src)
    if run.returncode != 2 or "error:" not in run.stderr or os.path.basename(f) not in run.stderr:
        failures += 1
        print(f"FAIL {rel}: the tool gave exit {run.returncode}, stderr: {run.stderr.strip()[:300]}")
    else:
        print(f"ok   {rel}: rejected by the schema and by the tool ({run.stderr.strip()[:140]})")
if len(bgood) < 2:
    failures += 1
    print(f"FAIL expected at least 2 shipped buildings, found {len(bgood)}")

if n_good < 8 or len(bad) < 10:
    failures += 1
    print(f"FAIL expected at least 8 shipped cases and 10 bad cases, found {n_good} and {len(bad)}")
print(f"check_schema: {n_good} shipped cases valid, {len(bad)} bad cases rejected by schema and tool; "
      f"{len(bgood)} buildings valid, {len(bbad)} bad buildings rejected; {failures} failure(s)")
sys.exit(1 if failures else 0)
