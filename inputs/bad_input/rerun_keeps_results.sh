#!/usr/bin/env bash
# rerun_keeps_results.sh <launcher and grout...>: run keep_good.yaml, then keep_bad.yaml into
# the same output files; the bad run must fail (exit 2) and leave the good run's files
# byte for byte, with no temporary file left behind.
set -u
dir=$(mktemp -d rerun.XXXXXX)
cp keep_good.yaml keep_bad.yaml square.exo "$dir"/
cd "$dir" || exit 1
"$@" keep_good.yaml > /dev/null || { echo "rerun_keeps_results: keep_good.yaml failed"; exit 1; }
before=$(md5sum keep.e keep.csv keep_newton.csv)
"$@" keep_bad.yaml > /dev/null 2> err.txt
status=$?
cat err.txt
fail=0
[ "$status" -eq 2 ] || { echo "rerun_keeps_results: keep_bad.yaml exit $status, expected 2"; fail=1; }
after=$(md5sum keep.e keep.csv keep_newton.csv)
[ "$before" = "$after" ] || { echo "rerun_keeps_results: the failed rerun changed the results"; fail=1; }
if ls -a | grep -q '\.partial$'; then echo "rerun_keeps_results: temporary files left"; fail=1; fi
cd .. && rm -rf "$dir"
[ $fail -eq 0 ] && echo "rerun_keeps_results: previous results kept"
exit $fail
