#!/bin/sh
# A stand-in for Chromium in the signal tests (issue 39): records its
# pid and a grandchild's in $ASSESS_TEST_PIDFILE, then waits. A SIGTERM or
# SIGINT to `assess` must stop both and remove the temporaries, and what the
# tool leaves in its TMPDIR when it is stopped (as Chromium leaves its
# org.chromium.* folders).
mkdir -p "${TMPDIR:-/tmp}/org.standin.$$"
sleep 120 &
echo "$!" >> "$ASSESS_TEST_PIDFILE"
echo "$$" >> "$ASSESS_TEST_PIDFILE"
wait
