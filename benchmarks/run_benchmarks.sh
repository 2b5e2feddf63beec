#!/usr/bin/env bash
# Run every qsmpm benchmark and write doc/benchmarks.md.
#
#   benchmarks/run_benchmarks.sh [build directory, default: build]
#
# Takes about 30 minutes on a 2-core machine. Needs a Release build.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
bin=$build/benchmarks
out=doc/benchmarks.md
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpirun="mpirun --oversubscribe"
tmp=$(mktemp -d)

echo "yardstick ..." >&2
yardstick=$(benchmarks/yardstick.sh)
echo "strip ..." >&2
$bin/strip --cells 256 --reuse 1 > "$tmp/strip_reuse1.csv"
$bin/strip --cells 256 --reuse 5 > "$tmp/strip_reuse5.csv"
echo "solver_scaling (serial) ..." >&2
$bin/solver_scaling > "$tmp/scaling.csv"
echo "kernel_ratios ..." >&2
$bin/kernel_ratios 256 0 > "$tmp/ratios_2d.csv"
$bin/kernel_ratios 0 32 > "$tmp/ratios_3d_32.csv"
$bin/kernel_ratios 0 64 > "$tmp/ratios_3d_64.csv"
echo "gimp ..." >&2
$bin/gimp > "$tmp/gimp.csv"
echo "MPI: largest 3D case on 1 and 2 ranks ..." >&2
$mpirun -np 1 $bin/solver_scaling --dim 3 --min-3d 64 --max-3d 64 --max-none-3d 0 > "$tmp/np1.csv"
$mpirun -np 2 $bin/solver_scaling --dim 3 --min-3d 64 --max-3d 64 --max-none-3d 0 > "$tmp/np2.csv"

echo "paper runs: compact tension b = 15, 30, 60 cm; polycrystal on 1 and 2 ranks ..." >&2
# timed <directory> <log> <command...>: run the command in the directory with
# its output in <log>, and write its wall time in seconds to <log>.seconds.
timed() {
  local dir=$1 log=$2 t0
  shift 2
  t0=$(date +%s.%N)
  (cd "$dir" && "$@") > "$log" 2>&1
  echo "$(date +%s.%N) - $t0" | bc -l > "$log.seconds"
}
for b in 15 30 60; do
  timed "$build/examples/compact_tension" "$tmp/cts_b$b.log" ./compact_tension b$b.prm
done
for np in 1 2; do
  timed "$build/examples/polycrystal" "$tmp/poly_np$np.log" $mpirun -np $np ./polycrystal polycrystal.prm
done

value() { grep "^$2," "$1" | cut -d, -f2; }
table() {
  awk -F, 'NR == 1 { printf "| %s", $1; for (i = 2; i <= NF; ++i) printf " | %s", $i; print " |";
                     printf "|"; for (i = 1; i <= NF; ++i) printf "---|"; print ""; next }
           { printf "| %s", $1; for (i = 2; i <= NF; ++i) printf " | %s", $i; print " |" }' "$1"
}
# GMRES iterations per Newton step with AMG, finest over coarsest grid.
growth() {
  awk -F, -v d="$2" '$1 == d && $5 == "amg" { r = $7 / $6; if (first == "") first = r; last = r }
                     END { printf "%.2f (%.1f -> %.1f)", last / first, first, last }' "$1"
}
speedup=$(awk -F, 'FNR == 2 { t[FILENAME] = $8 } END { for (f in t) if (f ~ /np1/) a = t[f]; else b = t[f]; printf "%.2f", a / b }' "$tmp/np1.csv" "$tmp/np2.csv")

{
  echo "# Benchmarks"
  echo
  echo "Written by \`benchmarks/run_benchmarks.sh\` on $(date -u +%Y-%m-%d)."
  echo
  echo "## Machine"
  echo
  echo "- CPU: $(lscpu | sed -n 's/^Model name: *//p') ($(nproc) cores)"
  echo "- Memory: $(free -g | awk '/Mem:/ {print $2}') GiB"
  echo "- deal.II $(dpkg-query -W -f '${Version}' libdeal.ii-dev 2>/dev/null), Trilinos ML AMG, Open MPI"
  echo "- Build: Release"
  echo
  echo "Yardstick (\`benchmarks/yardstick.sh\`: 64 MiB of AES-CTR keystream through gzip -6, median"
  echo "of 3) in this run: $yardstick s. Times below in yardsticks (y) are wall time / yardstick."
  echo
  echo "## Strip (issue 14)"
  echo
  echo "Command: \`$bin/strip --cells 256 --reuse K\`. Unit block, 256 x 256 cells, 2 x 2 points per"
  echo "cell, linear elastic, clamped bottom, rollers on the sides, pressure on the left half of the"
  echo "top in 5 load steps, AMG, Newton tolerance 1e-6. K = 1 builds the AMG hierarchy every step,"
  echo "K = 5 once (\`Nonlinear solver/Preconditioner reuse steps\`; rebuilt earlier if GMRES per"
  echo "Newton iteration doubles)."
  echo
  echo "| reuse steps | s per step | y per step | AMG setup share | builds | GMRES per step | peak memory (MB) | peak bytes per point |"
  echo "|---|---|---|---|---|---|---|---|"
  for k in 1 5; do
    f="$tmp/strip_reuse$k.csv"
    printf "| %s | %.2f | %.2f | %.2f | %s | %s | %.0f | %.0f |\n" "$k" \
      "$(value "$f" seconds_per_step)" "$(echo "$(value "$f" seconds_per_step) / $yardstick" | bc -l)" \
      "$(value "$f" preconditioner_setup_share)" "$(value "$f" preconditioner_builds)" \
      "$(grep -E '^step_[0-9]+_gmres,' "$f" | cut -d, -f2 | tr '\n' ' ' | sed 's/ $//')" \
      "$(value "$f" peak_memory_MB)" "$(value "$f" peak_bytes_per_point)"
  done
  f="$tmp/strip_reuse5.csv"
  echo
  echo "Where the memory goes (K = 5, resident memory): $(value "$f" memory_start_MB | awk '{ printf "%.0f", $1 }') MB before the grid"
  echo "(the shared libraries: deal.II, Trilinos, PETSc, Open MPI), grid and dofs $(value "$f" memory_grid_MB | awk '{ printf "%.0f", $1 }') MB, points"
  echo "$(value "$f" memory_points_MB | awk '{ printf "%.0f", $1 }') MB, stiffness matrix $(value "$f" memory_stiffness_MB | awk '{ printf "%.0f", $1 }') MB; the rest of the peak is the solver's (AMG"
  echo "hierarchy, shape-function cache, vectors). Targets of issue 14: <= 0.2 y per step, <= 450 MB."
  echo
  echo "## Solver scaling"
  echo
  echo "Command: \`$bin/solver_scaling\`. One linear-elastic load step on a unit block with"
  echo "2^dim points per cell (bottom clamped, top moved down and sideways), Newton tolerance 1e-6,"
  echo "GMRES tolerance 1e-3 (the paper's), restart 200. \`gmres_iterations\` is summed over the"
  echo "Newton iterations; \`seconds\` is the wall time of the whole load step. Unpreconditioned"
  echo "cases above 256^2 (2D) and 32^3 (3D) cells are skipped: their cost grows with the grid."
  echo
  table "$tmp/scaling.csv"
  echo
  echo "GMRES iterations per Newton step with AMG, finest / coarsest grid: 2D $(growth "$tmp/scaling.csv" 2),"
  echo "3D $(growth "$tmp/scaling.csv" 3) (target < 1.5)."
  echo
  echo "## JFNK against assembled matrices"
  echo
  echo "Command: \`$bin/kernel_ratios 256 0\`, \`$bin/kernel_ratios 0 32\`, \`$bin/kernel_ratios 0 64\`."
  echo
  echo "| case | residual / SpMV | JFNK step / assembled Newton step | bytes per point | peak memory (MB) |"
  echo "|---|---|---|---|---|"
  for f in "$tmp/ratios_2d.csv:2d_256" "$tmp/ratios_3d_32.csv:3d_32" "$tmp/ratios_3d_64.csv:3d_64"; do
    file=${f%%:*}; tag=${f##*:}
    printf "| %s | %.2f | %.2f | %.0f | %.0f |\n" "$tag" \
      "$(value "$file" ${tag}_residual_over_vmult)" "$(value "$file" ${tag}_jfnk_over_assembled)" \
      "$(value "$file" ${tag}_bytes_per_point)" "$(value "$file" ${tag}_peak_memory_bytes | awk '{ print $1 / 1e6 }')"
  done
  echo
  echo "Targets: residual / SpMV <= 3, JFNK step / assembled step <= 1.5, <= 1024 bytes per point in 3D."
  echo "Bytes per point: growth of the resident memory while the points are created and the"
  echo "shape data cached, divided by the number of points (3D runs in a fresh process, so that"
  echo "freed memory of another run is not reused)."
  echo
  echo "Why the 2D residual costs more than 3 SpMVs (the 3D one less than 2): the residual"
  echo "does per material point what the matrix does per row, and in 2D there are 2 points"
  echo "per degree of freedom (4 per cell, 2 dofs per node) against 18 non-zeros per row of the"
  echo "Q1 stiffness; in 3D 8 points per cell share 3 dofs per node against 81 non-zeros per"
  echo "row. Per point the residual evaluates grad du, calls the constitutive model through"
  echo "its virtual update_stress() and adds the point's force; a batched model interface"
  echo "(one call per cell) is the next step if the 2D figure matters."
  echo
  echo "Raw output:"
  echo
  echo '```'
  cat "$tmp/ratios_2d.csv" "$tmp/ratios_3d_32.csv" "$tmp/ratios_3d_64.csv"
  echo '```'
  echo
  echo "## MPI"
  echo
  echo "Largest 3D case (64^3 cells, 2x2x2 points per cell, AMG) on 1 and 2 ranks:"
  echo
  table <(cat "$tmp/np1.csv"; tail -n +2 "$tmp/np2.csv")
  echo
  echo "Speed-up of the load step with 2 ranks: $speedup (target >= 1.6)."
  echo
  echo "## Paper runs"
  echo
  echo "Wall times of the paper's runs from their shipped .prm files (Release, this machine):"
  echo
  echo "| run | command | wall time (s) | figures |"
  echo "|---|---|---|---|"
  for b in 15 30 60; do
    log="$tmp/cts_b$b.log"
    printf "| compact tension b = %s cm | \`compact_tension b%s.prm\` | %.1f | %s; %s; %s |\n" "$b" "$b" \
      "$(cat "$tmp/cts_b$b.log.seconds")" \
      "$(grep -m1 'peak load' "$log" | sed 's/^ *//; s/  */ /g')" \
      "$(grep -m1 'energy ratio' "$log" | sed 's/^ *//; s/  */ /g')" \
      "$(grep -m1 'Newton iterations per step' "$log" | sed 's/^ *//; s/  */ /g')"
  done
  for np in 1 2; do
    summary="$build/examples/polycrystal/polycrystal-output/summary.txt"
    printf "| polycrystal, %s rank(s) | \`mpirun -np %s polycrystal polycrystal.prm\` | %.1f | %s |\n" "$np" "$np" \
      "$(cat "$tmp/poly_np$np.log.seconds")" \
      "$(grep -E '^(n_grains|n_points|E_in_plane_GPa) ' "$summary" | tr '\n' ';' | sed 's/;$//; s/;/; /g')"
  done
  echo
  echo "## GIMP shape functions"
  echo
  cat benchmarks/gimp_section.md
  echo
  echo '```'
  cat "$tmp/gimp.csv"
  echo '```'
  echo
  echo "The example pages ([compact tension](example_compact_tension.md), [polycrystal](example_polycrystal.md))"
  echo "discuss the results themselves."
} > "$out"
rm -rf "$tmp"
echo "wrote $out" >&2
