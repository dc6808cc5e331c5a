#!/bin/sh
# Runs one libFuzzer harness for a bounded time on a seed corpus made from the
# project's shipped files, and prints its figures (executions, time, crashes).
#   fuzz/run_fuzzer.sh EXE NAME SECONDS SOURCE_DIR WORK_DIR [libFuzzer options...]
# NAME: records | case_file | campaign | building | ties | catalogue | metadata | spectra. Exit status: libFuzzer's (non-zero on a
# crash, a leak, a sanitizer report or a timeout; the input is kept in WORK_DIR).
set -eu
exe=$1 name=$2 secs=$3 src=$4 work=$5
shift 5
rm -rf "$work"
mkdir -p "$work/seeds" "$work/corpus"
# Seeds: the shipped files, each at most max_len bytes (8 KB; building
# files 16 KB, so that the shipped buildings are whole, valid seeds).
max_len=8192
[ "$name" = building ] && max_len=16384
seed() { # seed PREFIX_BYTE FILE...
  prefix=$1; shift
  for f in "$@"; do
    [ -f "$f" ] || continue
    out="$work/seeds/$(basename "$f")"
    if [ -n "$prefix" ]; then printf "$prefix" > "$out"; else : > "$out"; fi
    head -c "$max_len" "$f" >> "$out"
  done
}
case "$name" in
  records)
    # First byte: even = format detected from the content, odd = plain text.
    seed '\000' "$src"/spectra/records/*.AT2 "$src"/spectra/records/*.at2 "$src"/spectra/records/*.DAT \
                "$src"/spectra/records/*.ASC "$src"/spectra/records/*.cor.acc "$src"/tests/data/*.AT2 \
                "$src"/tests/data/hostile/*.AT2 "$src"/tests/data/campaign/*.AT2
    seed '\001' "$src"/tests/data/*.txt "$src"/tests/data/hostile/*.txt ;;
  case_file)
    seed '' "$src"/mechanisms/*.json "$src"/tests/cli/run_bad/*.json "$src"/tests/cli/kinematic_bad/*.json \
            "$src"/tests/data/hostile/*.json ;;
  campaign)
    seed '' "$src"/tests/data/campaign/*.json "$src"/mechanisms/campaign-*.json ;;
  building)
    seed '' "$src"/mechanisms/building-*.json "$src"/tests/cli/building/*.json "$src"/tests/cli/building_bad/*.json \
            "$src"/tests/data/hostile/building_*.json ;;
  ties)
    seed '' "$src"/mechanisms/*-ties.json "$src"/tests/cli/ties/*.json "$src"/tests/cli/ties_bad/*.json \
            "$src"/tests/data/hostile/ties_*.json ;;
  catalogue)
    # A valid catalogue of the shipped catalogue's first records (the whole file is 680 kB), and the hostile ones.
    python3 - "$src/spectra/records/catalogue.json" "$work/seeds/catalogue_head.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
d["records"] = d["records"][:4]
open(sys.argv[2], "w").write(json.dumps(d, indent=1))
PY
    seed '' "$src"/tests/data/hostile/catalogue_*.json ;;
  metadata)
    seed '' "$src"/spectra/records/metadata.csv "$src"/tests/data/records_mini/metadata.csv \
            "$src"/tests/data/hostile/metadata_*.csv ;;
  spectra)
    # The body of a valid spectra file for the harness's catalogue (records a and b, PGA 0.25 g):
    # counts, periods 0, 0.1, 1 s, damping 0.05, the ids, the ordinates.
    python3 - "$work/seeds/spectra_valid.bin" <<'PY'
import struct, sys
pga = 0.25 * 9.80665
b = struct.pack("<III", 3, 1, 2) + struct.pack("<3d", 0.0, 0.1, 1.0) + struct.pack("<d", 0.05)
for i in (b"a", b"b"):
    b += struct.pack("<I", len(i)) + i
b += struct.pack("<3d", pga, 2.5 * pga, 0.4 * pga) + struct.pack("<3d", pga, 2.0 * pga, 0.6 * pga)
open(sys.argv[1], "wb").write(b)
PY
    ;;
  *) echo "unknown fuzzer '$name'" >&2; exit 2 ;;
esac
echo "fuzz $name: $(ls "$work/seeds" | wc -l) seed files, ${secs} s"
set +e
"$exe" "$work/corpus" "$work/seeds" -max_total_time="$secs" -max_len="$max_len" -timeout=20 -rss_limit_mb=2560 \
  -print_final_stats=1 -artifact_prefix="$work/" "$@" > "$work/log.txt" 2>&1
rc=$?
set -e
runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/log.txt" | tail -1)
time=$(sed -n 's/^stat::.*//p' "$work/log.txt" >/dev/null; grep -o 'Done [0-9]* runs in [0-9]* second' "$work/log.txt" | tail -1)
echo "fuzz $name: ${runs:-?} executions (${time:-no summary}), exit status $rc"
if [ $rc -ne 0 ]; then
  tail -n 60 "$work/log.txt"
  echo "fuzz $name: FAILED (input saved in $work/)"
fi
exit $rc
