#!/bin/bash
# The example program consolidation on grids where the body moves across
# grid lines (a shell test). The grid reaches a cell beyond the sides that
# move (Mandel's free side, Terzaghi's top), the drained side is the body's
# own surface and follows it, and the Mandel check covers the plate's
# settlement as well as the peak pressure:
#
#  1. Mandel, 32 x 32 cells, F = 22 kN/m, linear shape functions: the free
#     side's points move out by F nu_u / (2 G) = 9.2 mm at t = 0+, more than
#     h / 4 = 7.8 mm, and cross the grid line x = a. (A grid that ended at
#     x = a lost them in the first step.) The cell-crossing error makes the
#     settlement wrong by several per cent: the program must say so (exit 1,
#     pass = no, settlement error above 2 %, and the line that names the
#     crossing and cpGIMP).
#  2. The same with Shape functions = cpGIMP: exit 0, peak and settlement
#     within 1 % of Mandel's exact solution.
#  3. Terzaghi, 128 cells, 1280 steps, linear: the top settles by 0.056 m,
#     0.7 h, away from the grid's top face (a drained grid face stopped the
#     run at T_v = 0.84). Exit 0, L2 errors of p below 1 % of q at
#     T_v = 0.1, 0.5 and 1.
#  4. Terzaghi, 256 cells, 640 steps, cpGIMP: each displacement solve of
#     the fixed-stress iteration must resolve the forces of a small pressure
#     change. (Solves that stopped at a fixed floor, 1e-7 of the body's
#     forces, returned at once when the pressure changed by less than about
#     h / H of the coupling tolerance; the iteration then only relaxed the
#     flow problem, by 0.999 per iteration, and the run stopped in step
#     134.) Exit 0, at most 20 fixed-stress iterations in a step (an
#     elastic skeleton contracts them by 1 - K / M_c = 1/3 each: 12 from
#     1 to 1e-5 of the pressure), the L2 errors below 1 % of q.
#
#   consolidation_example.sh <consolidation> <source dir>
#
# Prints one "PASS|FAIL <case> <check>" line per check and compares them
# with consolidation_example.output.
set -u
program=$(realpath "$1")
source_dir=$(cd "$2" && pwd)
prm=$source_dir/../../examples/consolidation/consolidation.prm
work=$(pwd)/consolidation_example.work
rm -rf "$work" && mkdir -p "$work" || exit 1
results=$work/results.txt
: > "$results"

# check <case> <description> <condition (an awk expression in value)> <value>
check()
{
  if [ -z "$4" ]; then
    echo "FAIL $1 $2 (no value)" >> "$results"
  elif awk -v value="$4" "BEGIN { exit !($3) }"; then
    echo "PASS $1 $2" >> "$results"
  else
    echo "FAIL $1 $2 (measured $4)" >> "$results"
  fi
}

# value <case> <name>: the entry of the case's summary.txt
value()
{
  awk -v name="$2" '$1 == name { print $3 }' "$work/$1/summary.txt" 2> /dev/null
}

# run <case> <sed expressions...>: the shipped file, edited, run in
# $work/<case>; sets status.
run()
{
  local name=$1
  shift
  mkdir -p "$work/$name"
  sed "$@" "$prm" > "$work/$name/run.prm"
  (cd "$work/$name" && timeout 600 "$program" run.prm > stdout.txt 2> stderr.txt)
  status=$?
}

small_column=(-e 's/set Column cells = .*/set Column cells = 8/'
              -e 's/set Column steps = .*/set Column steps = 80/'
              -e 's/  set Output directory = .*/  set Terzaghi tolerance = 0.05\n  set Output directory = ./')
mandel_crossing=(-e 's/set Specimen cells = .*/set Specimen cells = 32/'
                 -e 's/set Plate force = .*/set Plate force = 2.2e4/')

run mandel_linear "${small_column[@]}" "${mandel_crossing[@]}"
check mandel_linear "exit status 1" 'value == 1' "$status"
check mandel_linear "pass = no" 'value == "no"' "$(value mandel_linear pass)"
check mandel_linear "settlement error > 0.02" 'value > 0.02' \
  "$(value mandel_linear mandel_settlement_error)"
check mandel_linear "names the crossing and cpGIMP" 'value > 0' \
  "$(grep -c 'crossed the grid line x = a.*cpGIMP' "$work/mandel_linear/stdout.txt")"

run mandel_cpgimp "${small_column[@]}" "${mandel_crossing[@]}" \
  -e 's/set Points per cell per direction = 2/set Points per cell per direction = 2\n  set Shape functions = cpGIMP/'
check mandel_cpgimp "exit status 0" 'value == 0' "$status"
check mandel_cpgimp "peak error < 0.01" 'value < 0.01' \
  "$(value mandel_cpgimp mandel_peak_pressure_error)"
check mandel_cpgimp "settlement error < 0.01" 'value < 0.01' \
  "$(value mandel_cpgimp mandel_settlement_error)"

run terzaghi_128 -e 's/set Column cells = .*/set Column cells = 128/' \
  -e 's/set Column steps = .*/set Column steps = 1280/' \
  -e 's/set Specimen cells = .*/set Specimen cells = 4/' \
  -e 's/set Specimen steps = .*/set Specimen steps = 50/'
check terzaghi_128 "exit status 0" 'value == 0' "$status"
for tv in 0.1 0.5 1.0; do
  check terzaghi_128 "L2 error at T_v = $tv < 0.01" 'value < 0.01' \
    "$(value terzaghi_128 terzaghi_l2_error_tv_$tv)"
done

run terzaghi_256_cpgimp -e 's/set Column cells = .*/set Column cells = 256/' \
  -e 's/set Column steps = .*/set Column steps = 640/' \
  -e 's/set Specimen cells = .*/set Specimen cells = 4/' \
  -e 's/set Specimen steps = .*/set Specimen steps = 50/' \
  -e 's/set Points per cell per direction = 2/set Points per cell per direction = 2\n  set Shape functions = cpGIMP/'
check terzaghi_256_cpgimp "exit status 0" 'value == 0' "$status"
check terzaghi_256_cpgimp "at most 20 fixed-stress iterations per step" \
  'value <= 20' "$(sed -n 's/.*fixed-stress iterations per step [0-9]*-\([0-9]*\),.*/\1/p' \
                   "$work/terzaghi_256_cpgimp/stdout.txt" | head -1)"
for tv in 0.1 0.5 1.0; do
  check terzaghi_256_cpgimp "L2 error at T_v = $tv < 0.01" 'value < 0.01' \
    "$(value terzaghi_256_cpgimp terzaghi_l2_error_tv_$tv)"
done

cat "$results"
diff "$results" "$source_dir/consolidation_example.output" > /dev/null
