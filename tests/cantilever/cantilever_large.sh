#!/bin/bash
# The test cantilever_large: run the example program cantilever on
# coarse.prm (one and two MPI ranks) and check that it passes its own
# references (exit code 0, summary.txt says pass yes), that the tip rotated
# by more than 60 degrees and that no step lost more than 1e-6 of the load.
#
#   cantilever_large.sh <cantilever program> <coarse.prm>
set -uo pipefail
program=$1
prm=$2
status=0
for ranks in 1 2; do
  dir=ranks-$ranks
  rm -rf "$dir" && mkdir -p "$dir" && cd "$dir" || exit 1
  if mpirun -np $ranks "$program" "$prm" > log.txt 2>&1; then
    echo "PASS: $ranks rank(s): the cantilever meets its references"
  else
    echo "FAIL: $ranks rank(s): the cantilever stopped:"; tail -3 log.txt
    status=1
  fi
  if [ -f summary.txt ]; then
    awk -v r=$ranks '
      $1 == "max_tip_rotation_deg" { ok = ($2 > 60); print (ok ? "PASS" : "FAIL") ": " r " rank(s): tip rotation above 60 degrees"; if (!ok) bad = 1 }
      $1 == "largest_load_imbalance" { ok = ($2 <= 1e-6); print (ok ? "PASS" : "FAIL") ": " r " rank(s): largest lost load <= 1e-6"; if (!ok) bad = 1 }
      END { exit bad }' summary.txt || status=1
  else
    echo "FAIL: $ranks rank(s): no summary.txt"; status=1
  fi
  cd ..
done
exit $status
