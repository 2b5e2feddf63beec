#!/usr/bin/env bash
# The coupled (Biot) footings of examples/consolidation against grid size:
# the flexible strip load held while the clay consolidates
# (footing-consolidation.prm, elastic) and the rigid footing driven by a
# force into yield and then held (footing-rigid-consolidation.prm, von
# Mises, F-bar), each with Subdivisions = 20, 40, 80 (a / h = 4, 8, 16),
# with the fixed-stress split and with the monolithic coupling. Per run:
# steps, Newton iterations per step (with the split: summed over the
# step's fixed-stress iterations, whose range is given too), GMRES per
# Newton iteration, wall time of the whole process, and the settlement at
# the end against the drained one of the dry soil on the same grid (the
# load in one step, `Enabled = false`: a computation without the pore
# fluid code; its GMRES per Newton iteration, all of the load in one step,
# in the last column). Prints a Markdown table.
#
#   benchmarks/footing-consolidation.sh [build directory, default: build] [ranks, default: 1] [levels, default: "20 40 80"]
#
# Takes about 10 minutes on one core (most of it a / h = 16). Needs a
# Release build.
set -euo pipefail
cd "$(dirname "$0")/.."
build=$(cd "${1:-build}" && pwd)
ranks=${2:-1}
levels=${3:-20 40 80}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
examples=$(pwd)/examples/consolidation
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# run <file> <subdivisions> <coupling|dry>: runs the driver in $tmp/run
# with the file's grid and coupling replaced; prints the wall time.
run() {
  local edits=(-e "s/set Subdivisions = .*/set Subdivisions = $2, $2/")
  if [ "$3" = dry ]; then
    edits+=(-e "s/set Enabled = true/set Enabled = false/"
            -e "s/set Final load factor = .*/set Final load factor = 1e-5/"
            -e "s/set Number of steps = .*/set Number of steps = 1/")
  else
    edits+=(-e "s/^\( *\)set Mobility = \(.*\)/\1set Mobility = \2\n\1set Coupling = $3/")
  fi
  rm -rf "$tmp/run" && mkdir "$tmp/run"
  sed "${edits[@]}" "$examples/$1" > "$tmp/run/input.prm"
  local start end
  start=$(date +%s.%N)
  (cd "$tmp/run" && mpirun -np "$ranks" "$build/qsmpm" input.prm > log 2>&1) ||
    { echo "failed: $1 $2 $3" >&2; tail -5 "$tmp/run/log" >&2; exit 1; }
  end=$(date +%s.%N)
  awk -v a="$start" -v b="$end" 'BEGIN { printf "%.1f s", b - a }'
}

# The settlement at the end of the last run: below the load's centre
# (probe 0) for the flexible load, the footing's motion for the rigid one.
settlement() {
  local directory
  directory=$(ls -d "$tmp"/run/*-output)
  if [ "$1" = footing-consolidation.prm ]; then
    column=probe0_u_y file=$directory/probes.csv
  else
    column=footing_u file=$directory/reactions.csv
  fi
  awk -F, -v c="$column" 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == c) k = i }
                          END { printf "%.9g", ($k < 0 ? -$k : $k) }' "$file"
}

# Steps, Newton per step, fixed-stress per step (coupling $1) and GMRES
# per Newton from the per-step lines of the last run.
counts() {
  awk -v coupling="$1" '$1 == "step" {
         for (i = 1; i <= NF; ++i) {
           if ($i == "newton") n = $(i + 1)
           if ($i == "gmres") g = $(i + 1)
           if ($i == "coupling") c = $(i + 1)
         }
         ++steps; newton += n; gmres += g
         if (steps == 1 || n < nmin) nmin = n
         if (n > nmax) nmax = n
         if (steps == 1 || c < cmin) cmin = c
         if (c > cmax) cmax = c
       }
       END {
         printf "%d | %d-%d", steps, nmin, nmax
         if (coupling == "fixed-stress") printf " (fixed-stress %d-%d)", cmin, cmax
         printf " | %.1f", gmres / newton
       }' "$tmp/run/log"
}

echo "| file | a / h | coupling | steps | Newton per step | GMRES per Newton | time | settlement at the end vs drained (dry soil) | dry soil: GMRES per Newton |"
echo "|---|---:|---|---:|---|---:|---:|---:|---:|"
for file in footing-consolidation.prm footing-rigid-consolidation.prm; do
  for n in $levels; do
    run "$file" "$n" dry > /dev/null
    drained=$(settlement "$file")
    dry=$(counts dry | awk -F'|' '{ print $3 }')
    for coupling in fixed-stress monolithic; do
      time=$(run "$file" "$n" "$coupling")
      s=$(settlement "$file")
      difference=$(awk -v s="$s" -v d="$drained" 'BEGIN { printf "%+.2f %%", 100 * (s - d) / d }')
      echo "| ${file%.prm} | $((n / 5)) | $coupling | $(counts "$coupling") | $time | $difference |$dry |"
    done
  done
done
