#!/usr/bin/env python3
"""Issue 39, class 7: every number option of every subcommand has its range.

Lists the subcommands of `assess` and their options from `--help`, and gives
every option of type FLOAT, INT or UINT (and the text options that hold
numbers: lists, --restitution) values beyond any range: 1e300, -1e300, a
hexadecimal 0x10 and nan. Each must be refused with exit status 2 and a
message that names the option and what is wrong ("out of range", "a
hexadecimal number", "must be a finite number"), before anything else is
read; never a crash, an internal error, inf or nan in a result.

  option_ranges.py ASSESS
"""
import re
import subprocess
import sys

exe = sys.argv[1]
VALUES = {"1e300": "out of range", "-1e300": "out of range", "0x10": "hexadecimal", "nan": "finite number"}
# Text options that hold numbers, checked in the command's callback: the
# arguments that reach that check (the rest never read).
TEXT_NUMBERS = {
    ("spectrum", "--periods"): ["--lat", "42.35", "--lon", "13.4"],
    ("fragility", "--stripes"): ["tests/data/fragility/free_wall.json"],
    ("fragility", "--ida-levels"): ["tests/data/fragility/free_wall.json", "--ida"],
    ("rocking", "--restitution"): ["--model", "rigid", "--thickness", "0.5", "--height", "4", "--unit-weight", "18",
                                   "--record", "spectra/records/RSN285_ITALY_A-BAG000.AT2"],
    ("dynamic", "--restitution"): ["mechanisms/two_storey_facade.json", "--record",
                                   "spectra/records/RSN285_ITALY_A-BAG000.AT2"],
}
# Text values of --restitution other than numbers are words; a number out of [-1, 1] is named by the model.
RESTITUTION = {"1e300": "restitution", "-1e300": "restitution", "0x10": "--restitution expects a number",
               "nan": "--restitution expects a number"}


def run(args):
    p = subprocess.run([exe] + args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=120)
    return p.returncode, p.stdout.decode(errors="replace")


def help_of(path):
    rc, out = run(path + ["--help"])
    if rc != 0:
        sys.exit("%s --help: exit %d" % (" ".join(path), rc))
    options, subs, in_subs = [], [], False
    for line in out.splitlines():
        if re.match(r"^\S", line):
            in_subs = line.strip().startswith("Subcommands")
            continue
        m = re.match(r"^\s+(?:-\w,)?(--[\w-]+)\s+([A-Z]+)", line)
        if m and not in_subs:
            options.append((m.group(1), m.group(2)))
            continue
        m = re.match(r"^\s+([a-z][\w-]*)\s{2,}\S", line)
        if m and in_subs:
            subs.append(m.group(1))
    return options, subs


failures, checked, commands = [], 0, 0
todo = [[s] for s in help_of([])[1]]
seen_text = set()
while todo:
    path = todo.pop(0)
    options, subs = help_of(path)
    todo += [path + [s] for s in subs]
    if subs:
        continue
    commands += 1
    for opt, kind in options:
        key = (path[-1], opt)
        if kind in ("FLOAT", "INT", "UINT"):
            base = []
        elif key in TEXT_NUMBERS:
            base = TEXT_NUMBERS[key]
            seen_text.add(key)
        else:
            continue
        checked += 1
        for value, why in VALUES.items():
            if opt == "--restitution":
                why = RESTITUTION[value]
            rc, out = run(path + base + [opt, value])
            lower = out.lower()
            bad = []
            if rc != 2:
                bad.append("exit %d" % rc)
            if opt not in out and opt != "--restitution":
                bad.append("the option is not named")
            if why not in out:
                bad.append("no '%s'" % why)
            if "internal error" in lower or "terminate called" in lower or re.search(r"(^|[^a-z_./'])-?(inf|nan)([^a-z_./']|$)", lower):
                bad.append("internal error, crash, inf or nan")
            if bad:
                failures.append("assess %s %s %s: %s\n    %s" % (" ".join(path + base), opt, value, ", ".join(bad),
                                                               out.strip().replace("\n", "\n    ")))
missing = set(TEXT_NUMBERS) - seen_text
if missing:
    failures.append("text options that hold numbers not found in --help: %s" % sorted(missing))
if failures:
    print("\n".join(failures))
    sys.exit(1)
print("ok: %d number options of %d subcommands refuse 1e300, -1e300, 0x10 and nan with their rule" % (checked, commands))
