#!/bin/sh
# A stand-in for Chromium or pandoc in the signal tests (issue 39): records its
# pid and a grandchild's in $ASSESS_TEST_PIDFILE, then waits. A SIGTERM or
# SIGINT to `assess` must stop both and remove the temporaries.
sleep 120 &
echo "$!" >> "$ASSESS_TEST_PIDFILE"
echo "$$" >> "$ASSESS_TEST_PIDFILE"
wait
