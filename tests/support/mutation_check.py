#!/usr/bin/env python3
"""Checks that the regression tests of issue 10 fail without their fixes.

Usage: tests/support/mutation_check.py BUILD_DIR [DEFECT ...]
For each defect below, reverts its fix in the source tree (a textual
mutation), rebuilds the test executable in BUILD_DIR (a configured build of
this tree), runs it, reports whether it FAILS (as it must), and restores the
file, also on error. DEFECT: e.g. "defect 7" (default: all). Exit status 1
if a mutant is not caught (its test passes, it does not build, or its pattern
is no longer in the source). Not run by CTest: it rewrites sources;
docs/reliability.md lists the result.
"""
import os
import subprocess
import sys
SRC = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))) + '/'
BUILD = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else sys.exit(__doc__)
M = [
 ('defect 1', 'libassess/src/records/record_io.cpp',
  '    if (row.empty())\n      throw InputError(path + ":" + std::to_string(i + 1) + ": no value on this line (only separators)");\n', '',
  'test_unit_hostile_records'),
 ('defect 3/4', 'libassess/src/records/record_io.cpp',
  '  const std::string t = trim(text);\n  const std::string shown', '  return std::stol(trim(text));\n  const std::string t = trim(text);\n  const std::string shown',
  'test_unit_hostile_records'),
 ('defect 7', 'libassess/src/records/record_io.cpp',
  '    if (!std::isfinite(a))\n      throw InputError(where() + "value', '    if (false)\n      throw InputError(where() + "value',
  'test_unit_hostile_records'),
 ('defect 12 (subnormal)', 'libassess/src/records/record_io.cpp',
  '(errno == ERANGE && std::fabs(v) > 1.0)', '(errno == ERANGE)', 'test_unit_hostile_records'),
 ('defect 5', 'libassess/src/support/json_input.cpp',
  '    return nlohmann::json::parse(text);\n  } catch (const nlohmann::json::exception& e) {',
  '    return nlohmann::json::parse(text);\n  } catch (const nlohmann::json::parse_error& e) {', 'test_unit_hostile_inputs'),
 ('defect 6', 'libassess/src/dynamics/rocking_analysis.cpp',
  '  if (!(k <= limits::winkler_k_max_N_m3)) {', '  if (false) {', 'test_unit_hostile_inputs'),
 ('defect 9', 'libassess/src/campaign/output_lock.cpp',
  '    rc = ::flock(fd, op | LOCK_NB);', '    rc = 0;', 'test_unit_hostile_inputs'),
 ('defect 11', 'libassess/src/dynamics/rocking_analysis.cpp',
  '  within(tail_s, 0.0, limits::tail_max_s, "tail duration (s)");', '', 'test_unit_hostile_inputs'),
]
only = sys.argv[2:]
problems = 0
for name, f, old, new, target in M:
    if only and name not in only: continue
    p = SRC + f
    s = open(p).read()
    if s.count(old) != 1:
        print(f'{name}: pattern not found once in {f}')
        problems += 1
        continue
    open(p, 'w').write(s.replace(old, new))
    try:
        b = subprocess.run(['cmake', '--build', BUILD, '-j2', '--target', target], capture_output=True, text=True)
        if b.returncode != 0:
            print(f'{name}: mutant does not build, not checked\n{b.stderr[-800:]}')
            problems += 1
            continue
        r = subprocess.run([f'{BUILD}/tests/{target}'], capture_output=True, text=True, cwd=SRC, timeout=600)
        fails = [l for l in r.stdout.splitlines() if 'TEST CASE:' in l]
        problems += r.returncode == 0
        print(f'{name}: {target} exit {r.returncode} -> {"FAILS (good)" if r.returncode != 0 else "PASSES (test does not catch it)"}; failing cases: {sorted(set(fails))[:4]}')
    finally:
        open(p, 'w').write(s)
subprocess.run(['cmake', '--build', BUILD, '-j2', '--target', 'test_unit_hostile_records', 'test_unit_hostile_inputs'], capture_output=True)
print('restored and rebuilt')
sys.exit(1 if problems else 0)
