#!/usr/bin/env bash
# Runs check_series.py in pvbatch under a virtual X server (CTest test paraview_series).
#   run_check.sh XVFB_RUN PVBATCH CHECK_SCRIPT RUN_DIR OUT_PNG
# xvfb-run can hand pvbatch a display whose server is not yet accepting connections when the
# machine is loaded (seen once in a parallel ctest: "bad X server connection"); that attempt is
# repeated, up to three times. Any other failure is final.
set -uo pipefail
xvfb_run=$1 pvbatch=$2
shift 2
for attempt in 1 2 3; do
  output=$("$xvfb_run" -a -s "-screen 0 1024x768x24 -nolisten tcp" "$pvbatch" "$@" 2>&1)
  status=$?
  if [ $status -eq 0 ] || ! grep -q "bad X server connection" <<< "$output"; then
    echo "$output"
    exit $status
  fi
  echo "run_check.sh: attempt $attempt: the virtual X server was not ready; again" >&2
  sleep 2
done
echo "$output"
exit $status
