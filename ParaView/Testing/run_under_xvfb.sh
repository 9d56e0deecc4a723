#!/usr/bin/env bash
# Runs a command under a fresh Xvfb (xvfb-run -a): run_under_xvfb.sh [xvfb-run
# options] -- command [args]. The display number is drawn at random, and a run whose X
# server refused the connection ("bad X server connection": a display another server
# still held, seen once in CI on a fixed number) is run again on another, up to three
# times; any other failure is the test's own and ends it.
set -uo pipefail
options=()
while [ "$#" -gt 0 ] && [ "$1" != "--" ]; do options+=("$1"); shift; done
shift
log="$(mktemp)"
trap 'rm -f "${log}"' EXIT
for attempt in 1 2 3; do
  display=$(( 100 + RANDOM % 800 ))
  xvfb-run -a -n "${display}" "${options[@]}" "$@" 2>&1 | tee "${log}"
  status="${PIPESTATUS[0]}"
  if [ "${status}" -eq 0 ] || ! grep -q "bad X server connection" "${log}"; then
    exit "${status}"
  fi
  echo "run_under_xvfb.sh: the X server on :${display} refused the connection; again (${attempt} of 3)" >&2
done
exit "${status}"
