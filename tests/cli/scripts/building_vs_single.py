#!/usr/bin/env python3
"""building_vs_single.py ASSESS SOURCE_DIR BUILDING.json WORK_DIR

Issue 22: a building case gives, mechanism by mechanism, the numbers of the
same mechanism run alone. Runs `assess run BUILDING --json --expand WORK_DIR`,
then `assess run WORK_DIR/M<n>.json --json` for every mechanism, and compares:
the whole assessment (every number of the façade JSON: alpha0, a0*, every check
D/C and PGA capacity, the records, every dynamic analysis and its D/C) must be
identical (numbers within 1e-12 relative; the only string allowed to differ is
the case file's name), and so must the safety indices (zetaE, TR_C/TR_D, per
code and approach). The governing mechanism of each (code, approach) is
recomputed from the single runs (lowest zetaE; dynamic: largest D/C) and must
be the building's. Issue 23: a mechanism with "ties" or "design" carries the
tie result of its single run (`"ties"`: the design found, every level's checks
and required forces, before/after, the tied dynamics; numbers within 1e-12
relative), its zetaE before/after are the single run's, and the building's
index before/after is recomputed from the single runs. Issue 37: a wall's
"ties" and "design" levels go to the mechanisms of the wall whose moving
blocks they cross (the expanded case holds the wall's crossing levels, then
the mechanism's own ties); the building designs a wall's ties for all those
mechanisms together, the single run for its mechanism alone (which may
accept an earlier combination, or keep an existing tie the wall removes): for
a mechanism of such a wall the stato di fatto is compared (the assessment,
`before`, `levels_before`, the analyses of the existing ties), and the
stato di progetto must pass every check in every mechanism of the wall when
the design is found. Exit 0 pass, 1 fail.
"""
import json
import math
import os
import subprocess
import sys

exe, src, building, work = sys.argv[1:5]
os.makedirs(work, exist_ok=True)
failures = []


def run(args):
    r = subprocess.run([exe] + args, capture_output=True, text=True, cwd=src)
    if r.returncode != 0:
        print(f"FAIL assess {' '.join(args)}: exit {r.returncode}: {r.stderr[:500]}")
        sys.exit(1)
    return json.loads(r.stdout)


def same(x, y, path, single_file):
    if isinstance(x, bool) or isinstance(y, bool):
        if x != y:
            failures.append(f"{path}: {x} != {y}")
        return
    if isinstance(x, (int, float)) and isinstance(y, (int, float)):
        if x != y and not (math.isfinite(x) and math.isfinite(y) and abs(x - y) <= 1e-12 * max(abs(x), abs(y))):
            failures.append(f"{path}: {x!r} != {y!r}")
        return
    if type(x) is not type(y):
        failures.append(f"{path}: {type(x).__name__} != {type(y).__name__}")
        return
    if isinstance(x, dict):
        for k in sorted(set(x) | set(y)):
            if k in ("assess_version", "schema_version"):
                continue
            if k not in x or k not in y:
                failures.append(f"{path}/{k}: only in {'the building' if k in x else 'the single run'}")
                continue
            if k == "case_file":
                continue
            same(x[k], y[k], f"{path}/{k}", single_file)
    elif isinstance(x, list):
        if len(x) != len(y):
            failures.append(f"{path}: {len(x)} != {len(y)} elements")
            return
        for i, (u, v) in enumerate(zip(x, y)):
            same(u, v, f"{path}/{i}", single_file)
    elif x != y and x != y.replace(single_file, building):
        failures.append(f"{path}: {x!r} != {y!r}")


OVERRIDES = ("knowledge_level", "FC", "codes", "method", "check_SLD", "building", "analysis", "dynamic")


def merge_patch(target, patch):  # RFC 7386
    if not isinstance(patch, dict):
        return patch
    target = dict(target) if isinstance(target, dict) else {}
    for k, v in patch.items():
        if v is None:
            target.pop(k, None)
        else:
            target[k] = merge_patch(target.get(k), v)
    return target


def compose(doc, wall, entry):
    """The single case an engineer would write for `entry`, by the documented rule (docs/user/building.md)."""
    case = {k: v for k, v in doc.items() if k not in ("walls", "record_selection", "project")}
    for over in (wall, entry):
        for k in OVERRIDES:
            if k in over:
                if k == "FC":
                    case.pop("knowledge_level", None)
                if k == "knowledge_level":
                    case.pop("FC", None)
                case = merge_patch(case, {k: over[k]})
    case["mechanism"] = entry["mechanism"]
    case["project"] = (doc["project"] + " — " if doc.get("project") else "") + wall["name"] + ": " + entry["name"]
    return case


def tie_composition(wall, entry, got):
    """Issue 37: the expanded case's ties are some of the wall's, in order, then the entry's own; its design
    levels some of the wall's (or the entry's own design when its wall has none). Returns an error or None."""
    ties = got.get("ties", [])
    own = entry.get("ties") or []
    wall_ties = wall.get("ties") or []
    head = ties[:len(ties) - len(own)] if own else ties
    if own and ties[len(ties) - len(own):] != own:
        return "the mechanism's own ties are not at the end of its expanded ties"
    it = iter(wall_ties)
    if not all(any(t == w for w in it) for t in head):
        return "the expanded ties are not the wall's levels in their order"
    if "design" in wall:
        if "design" in got:
            levels = got["design"]["ties"].get("levels", [])
            it = iter(wall["design"]["ties"].get("levels", []))
            if not all(any(t == w for w in it) for t in levels):
                return "the expanded design levels are not the wall's in their order"
            rest = {k: v for k, v in got["design"]["ties"].items() if k != "levels"}
            if rest != {k: v for k, v in wall["design"]["ties"].items() if k != "levels"}:
                return "the expanded design's settings are not the wall's"
    elif entry.get("design") is not None and got.get("design") != entry.get("design"):
        return "the mechanism's own design is not its expanded design"
    return None


doc = json.load(open(os.path.join(src, building), encoding="utf-8"))
b = run(["run", building, "--json", "--expand", work])
# The expanded cases are the documented composition (plus the shared range when shared).
k = 0
for wall in doc["walls"]:
    for entry in wall["mechanisms"]:
        m = b["mechanisms"][k]
        k += 1
        expected = compose(doc, wall, entry)
        got = json.loads(json.dumps(m["case"]))
        sel = got.get("dynamic", {}).get("select", {})
        if m["record_set"]["kind"] == "shared":
            if "period_range_s" not in sel:
                failures.append(f"{m['id']}: shared record set but no period_range_s in the expanded case")
            sel.pop("period_range_s", None)
        elif "period_range_s" in sel and "period_range_s" not in expected.get("dynamic", {}).get("select", {}):
            failures.append(f"{m['id']}: a period range written for a mechanism that does not share its records")
        err = tie_composition(wall, entry, got)
        if err:
            failures.append(f"{m['id']}: {err}")
        got = {k: v for k, v in got.items() if k not in ("ties", "design")}
        if got != expected:
            failures.append(f"{m['id']}: expanded case != the documented composition:\n{json.dumps(got, sort_keys=True)}\n"
                            f"{json.dumps(expected, sort_keys=True)}")
print(f"{'ok  ' if not failures else 'FAIL'} {k} expanded cases = the documented composition of the building file")
singles = []
for m in b["mechanisms"]:
    f = os.path.join(work, m["id"] + ".json")
    s = run(["run", f, "--json"])
    singles.append(s)
    n0 = len(failures)
    same(m["assessment"], {k: v for k, v in s.items() if k not in ("safety_indices", "ties")}, f"{m['id']}/assessment", f)
    same(m["safety_indices"], s["safety_indices"], f"{m['id']}/safety_indices", f)
    # Issue 23: the tie result and the zetaE before/after.
    ties_note = ""
    if ("ties" in m) != ("ties" in s):
        failures.append(f"{m['id']}: tie result only in {'the building' if 'ties' in m else 'the single run'}")
    elif "ties" in m and m["ties"].get("wall_members"):
        # A wall's ties: the stato di fatto as the single run; the wall's design passes in this mechanism.
        for key in ("before", "levels_before", "designed"):
            same(m["ties"][key], s["ties"][key], f"{m['id']}/ties/{key}", f)
        same(m["ties"]["dynamic"]["runs_before"], s["ties"]["dynamic"]["runs_before"], f"{m['id']}/ties/dynamic/runs_before", f)
        if m["ties"].get("found") and not m["ties"]["after"]["every_check_satisfied"]:
            failures.append(f"{m['id']}: the wall's design is found but this mechanism does not pass every check")
        same(m["intervention"]["zeta_E_before"], s["ties"]["before"]["zeta_E"], f"{m['id']}/intervention/zeta_E_before", f)
        same(m["intervention"]["zeta_E_after"], m["ties"]["after"]["zeta_E"], f"{m['id']}/intervention/zeta_E_after", f)
        ties_note = (f", the wall's ties ({'found' if m['ties'].get('found') else 'not found'}): stato di fatto identical, "
                     f"zetaE {m['intervention']['zeta_E_before']:.3f} -> {m['intervention']['zeta_E_after']:.3f}")
    elif "ties" in m:
        same(m["ties"], s["ties"], f"{m['id']}/ties", f)
        numbers = []
        walk = [m["ties"]]
        while walk:
            x = walk.pop()
            if isinstance(x, dict):
                walk.extend(x.values())
            elif isinstance(x, list):
                walk.extend(x)
            elif isinstance(x, (int, float)) and not isinstance(x, bool):
                numbers.append(x)
        if len(numbers) < 50 and not m["ties"].get("wall_members"):
            failures.append(f"{m['id']}/ties: only {len(numbers)} numbers compared")
        iv = m["intervention"]
        same(iv["zeta_E_before"], s["ties"]["before"]["zeta_E"], f"{m['id']}/intervention/zeta_E_before", f)
        same(iv["zeta_E_after"], s["ties"]["after"]["zeta_E"], f"{m['id']}/intervention/zeta_E_after", f)
        # Issue 29: the mechanism's own displacement (or strength) zetaE is its stato di fatto's (with its
        # existing ties, if any): zeta_E before.
        approach = "strength" if m["case"].get("method") == "linear" else "displacement"
        for x in s["safety_indices"]:
            if x["code"] == "NTC2018" and x["approach"] == approach and x["defined"]:
                same(x["zeta_E"], iv["zeta_E_before"], f"{m['id']}/ties: safety index = zeta_E before", f)
        ties_note = (f", ties ({iv['ties']}, {len(numbers)} numbers) identical, zetaE {iv['zeta_E_before']:.3f} -> "
                     f"{iv['zeta_E_after']:.3f}")
    k = m["assessment"]["kinematic"]
    print(f"{'ok  ' if len(failures) == n0 else 'FAIL'} {m['id']} {m['name']}: "
          f"{sum(1 for _ in m['assessment']['checks'])} checks, "
          f"{len(m['assessment'].get('dynamic', {}).get('analyses', []) or [])} dynamic analyses, "
          f"{len(m['safety_indices'])} safety indices identical to the single run{ties_note}")

# The governing mechanism per code and approach, from the single runs.
for g in b["governing"]:
    best, best_id = None, None
    for m, s in zip(b["mechanisms"], singles):
        for x in s["safety_indices"]:
            if x["code"] != g["code"] or x["approach"] != g["approach"] or x["checks"] == 0:
                continue
            if x["defined"]:
                key = x["zeta_E"] if x["zeta_E"] is not None else math.inf
                better = best is None or key < best
            else:
                key = x["dc"] if x["dc"] is not None else math.inf
                better = best is None or key > best
            if better:
                best, best_id = key, m["id"]
    if best_id != g.get("mechanism"):
        failures.append(f"governing {g['code']} {g['approach']}: building {g.get('mechanism')}, single runs {best_id}")
    else:
        print(f"ok   governing {g['code']} {g['approach']}: {best_id} ({'zetaE' if g['approach'] != 'dynamic' else 'D/C'} {best:.4f})")

# The building's index before/after the ties: the smallest mechanism zetaE, from the single runs.
ti = b["tie_index"]
for when in ("before", "after"):
    best, best_id = None, None
    for m, s in zip(b["mechanisms"], singles):
        if "ties" in s and when == "after" and m.get("ties", {}).get("wall_members"):
            z = m["ties"]["after"]["zeta_E"]  # the wall's design (checked against its own result above)
        elif "ties" in s:
            z = s["ties"][when]["zeta_E"]
        else:
            z = m["intervention"]["zeta_E_" + when]  # no ties: checked equal to the mechanism's own below
            approach = "strength" if m["case"].get("method") == "linear" else "displacement"
            own = [x["zeta_E"] for x in s["safety_indices"]
                   if x["code"] == "NTC2018" and x["approach"] == approach and x["defined"]]
            if own and own[0] is not None and z is not None:
                same(z, own[0], f"{m['id']}/intervention/zeta_E_{when} = its safety index", "")
        if z is not None and (best is None or z < best):
            best, best_id = z, m["id"]
    if best_id != ti.get("mechanism_" + when) or (best is not None and
                                                  abs(best - ti["zeta_E_" + when]) > 1e-12 * abs(best)):
        failures.append(f"building index {when}: {ti.get('mechanism_' + when)} {ti['zeta_E_' + when]}, "
                        f"single runs {best_id} {best}")
    elif best is not None:
        print(f"ok   building index {when} the ties: {best_id} (zetaE {best:.4f})")

# Issue 41: a mechanism alone (`--mechanism ID`) is its building line, a shared
# selection that fell back included: the same records, the same numbers.
for m in b["mechanisms"]:
    alone = run(["run", building, "--mechanism", m["id"], "--json"])
    n0 = len(failures)
    same(m["assessment"], {k: v for k, v in alone.items() if k not in ("safety_indices", "ties")},
         f"{m['id']}/--mechanism", building)
    if len(failures) == n0:
        print(f"ok   {m['id']}: --mechanism {m['id']} = its building line")

for f in failures[:40]:
    print("FAIL", f)
print(f"building_vs_single: {len(b['mechanisms'])} mechanisms, {len(failures)} difference(s)")
sys.exit(1 if failures else 0)
