#!/bin/sh
# check_html.sh FILE N_FIGURES [PATTERN ...]
# check_html.sh --self-test
#
# Loads FILE in Debian's headless Chromium and checks that
#   1. the page loads (chromium exits 0 and dumps a DOM),
#   2. the DOM holds exactly N_FIGURES <figure> elements, each with an <svg>,
#   3. every PATTERN (grep -E) is found in the DOM Chromium built (e.g. the
#      verdict box 'class="verdict (ok|fail)"', a figure id, '<table'),
#   4. the browser logged no console message (the report has no scripts, so
#      any CONSOLE line is an error: a failed resource, a parse problem, ...).
# Exit status: 0 pass, 1 fail, 77 skipped (chromium not installed; CTest
# SKIP_RETURN_CODE). --self-test writes a passing page and a failing page
# (console error) to a temporary directory and checks both verdicts.
set -u

CHROMIUM=${CHROMIUM:-chromium}
if ! command -v "$CHROMIUM" >/dev/null 2>&1; then
  echo "check_html: $CHROMIUM not found (Debian: apt-get install chromium); skipped"
  exit 77
fi

check() {  # check FILE N [PATTERN...] -> 0/1
  file=$1; expected=$2; shift 2
  work=$(mktemp -d)
  abs=$(cd "$(dirname "$file")" && pwd)/$(basename "$file")
  timeout 120 "$CHROMIUM" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
    --disable-background-networking --disable-component-update --disable-sync \
    --user-data-dir="$work/profile" --enable-logging=stderr --v=0 \
    --dump-dom "file://$abs" >"$work/dom.html" 2>"$work/stderr.txt"
  rc=$?
  status=0
  if [ $rc -ne 0 ] || ! grep -q "</html>" "$work/dom.html"; then
    echo "check_html: $file: chromium failed (exit $rc)"; status=1
  fi
  # One figure per line, then count figures that contain an <svg.
  figures=$(tr '\n' ' ' <"$work/dom.html" | sed 's/<figure/\n<figure/g' | grep -c '^<figure')
  with_svg=$(tr '\n' ' ' <"$work/dom.html" | sed 's/<figure/\n<figure/g' | grep '^<figure' |
             sed 's:</figure>.*::' | grep -c '<svg')
  if [ "$figures" -ne "$expected" ] || [ "$with_svg" -ne "$expected" ]; then
    echo "check_html: $file: $figures figures, $with_svg with an svg; expected $expected"; status=1
  fi
  for pattern in "$@"; do
    if ! tr '\n' ' ' <"$work/dom.html" | grep -Eq -- "$pattern"; then
      echo "check_html: $file: '$pattern' not found in the DOM"; status=1
    fi
  done
  if grep -q ':CONSOLE' "$work/stderr.txt"; then
    echo "check_html: $file: console messages:"; grep ':CONSOLE' "$work/stderr.txt"; status=1
  fi
  rm -rf "$work"
  [ $status -eq 0 ] && echo "check_html: $file: OK ($figures figures with svg, no console message)"
  return $status
}

if [ "${1:-}" = "--self-test" ]; then
  dir=$(mktemp -d)
  svg='<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10"><rect width="5" height="5"/></svg>'
  printf '<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>ok</title></head><body><figure id="a">%s</figure><figure id="b">%s</figure></body></html>\n' "$svg" "$svg" >"$dir/good.html"
  printf '<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>bad</title></head><body><figure id="a">%s</figure><script>console.error("broken")</script></body></html>\n' "$svg" >"$dir/bad.html"
  check "$dir/good.html" 2 || { rm -rf "$dir"; exit 1; }
  if check "$dir/bad.html" 1 >/dev/null; then
    echo "check_html: self-test: a console error went unnoticed"; rm -rf "$dir"; exit 1
  fi
  echo "check_html: self-test: console error detected as expected"
  rm -rf "$dir"
  exit 0
fi

[ $# -ge 2 ] || { echo "usage: check_html.sh FILE N_FIGURES [PATTERN ...] | --self-test"; exit 1; }
check "$@"
