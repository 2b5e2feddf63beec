#!/usr/bin/env bash
# The coupled (Biot) problems of examples/consolidation against grid size:
# fixed-stress iterations per step (Newton iterations per step with the
# monolithic coupling), GMRES per Newton iteration and wall time of
# Terzaghi's column and of Mandel's specimen under a rigid plate, with the
# errors against the exact solutions. Prints a Markdown table.
#
#   benchmarks/consolidation.sh [build directory, default: build] [ranks, default: 1] [coupling, default: fixed-stress]
#
# coupling is Pore fluid/Coupling: fixed-stress or monolithic.
#
# Takes about 2 minutes on one core. Needs a Release build.
set -euo pipefail
cd "$(dirname "$0")/.."
build=$(cd "${1:-build}" && pwd)
ranks=${2:-1}
coupling=${3:-fixed-stress}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
prm=$(pwd)/examples/consolidation/consolidation.prm
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

if [ "$coupling" = monolithic ]; then per_step="Newton"; else per_step="fixed-stress"; fi
echo "| column cells / steps | Terzaghi: $per_step per step, GMRES per Newton, time | L2(p)/q at T_v = 0.1, 0.5, 1 | specimen cells / steps | Mandel: $per_step per step, GMRES per Newton, time | peak error, settlement error |"
echo "|---|---|---|---|---|---|"
for level in 1 2 4; do
  column=$((16 * level)) specimen=$((8 * level))
  sed -e "s/set Column cells = .*/set Column cells = $column/" \
      -e "s/set Column steps = .*/set Column steps = $((10 * column))/" \
      -e "s/set Specimen cells = .*/set Specimen cells = $specimen/" \
      -e "s/set Specimen steps = .*/set Specimen steps = $((25 * specimen / 2))/" \
      -e "s/  set Mobility = \(.*\)/  set Mobility = \1\n  set Coupling = $coupling/" \
      "$prm" > "$tmp/consolidation.prm"
  (cd "$tmp" && mpirun -np "$ranks" "$build/examples/consolidation/consolidation" consolidation.prm) > "$tmp/log"
  lines=$(grep -E "fixed-stress iterations|monolithic:" "$tmp/log" |
          sed 's/^ *fixed-stress iterations per step //; s/^ *monolithic: Newton iterations per step //; s/GMRES per Newton //')
  summary=$tmp/summary.txt
  v() { grep "^$1 " "$summary" | awk '{ printf "%.3f %%", 100 * $3 }'; }
  echo "| $column / $((10 * column)) | $(echo "$lines" | sed -n 1p) | $(v terzaghi_l2_error_tv_0.1), $(v terzaghi_l2_error_tv_0.5), $(v terzaghi_l2_error_tv_1.0) | $specimen x $specimen / $((25 * specimen / 2)) | $(echo "$lines" | sed -n 2p) | $(v mandel_peak_pressure_error), $(v mandel_settlement_error) |"
done
