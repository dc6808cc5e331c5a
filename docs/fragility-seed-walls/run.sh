#!/bin/sh
# Reruns the fragility of the seed's four §3.2 walls (smooth and rigid) at
# L'Aquila, soil B, and writes summary.md (the table of docs/fragility.md).
# Usage (from the repository root, after building): sh docs/fragility-seed-walls/run.sh [build/apps/assess]
set -eu
ASSESS=${1:-build/apps/assess}
DIR=docs/fragility-seed-walls
export ASSESS_DATA_DIR=${ASSESS_DATA_DIR:-$(pwd)}
for f in $DIR/cases/*.json; do
  name=$(basename "$f" .json)
  rm -rf "$DIR/run/$name"
  "$ASSESS" fragility "$f" --out "$DIR/run/$name" --quiet > "$DIR/run/$name.txt"
done
