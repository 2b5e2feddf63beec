#!/bin/bash
# Bad input to the programs: the driver qsmpm and the two paper examples
# compact_tension and polycrystal get malformed parameter files, functions,
# ODF files and geometries. For every case the program must
#
#  - exit with a non-zero code, by itself (not by a signal: code < 128, and
#    not killed by the time limit),
#  - print exactly one line "<program> stopped: <message>" to stderr, and
#    that message must contain a keyword chosen here: the entry, the
#    subsection or the file that is wrong (not deal.II's wording, which
#    changes between releases),
#  - keep that line printable and short: printable ASCII only (a binary file
#    must not send its bytes to the terminal), at most 700 characters,
#  - print no stack trace, deal.II exception banner or signal report,
#  - write nothing as converged: no reactions.csv or steps.csv with data
#    rows, and none of the files a finished run writes (summary.txt,
#    load_displacement.csv, effective_stiffness.csv, realizations.csv).
#
# On two MPI ranks the line is printed once as well: the errors are
# collective (all ranks read the same file and check the same values, and a
# failed step fails on all ranks), and rank 0 alone prints them.
#
#   bad_input.sh <qsmpm> <compact_tension> <polycrystal> <source dir>
#
# <source dir> is tests/bad_input (its .output lists the expected PASS
# lines); the examples' .prm and ODF files are found relative to it. The
# script prints one "PASS|FAIL <case> [<keyword>]" line per case, compares
# them with bad_input.output and exits non-zero on any difference.
set -u
# Absolute paths: every case runs in a directory of its own.
qsmpm=$(realpath "$1")
compact_tension=$(realpath "$2")
polycrystal=$(realpath "$3")
source_dir=$(cd "$4" && pwd)
examples=$source_dir/../../examples
work=$(pwd)/bad_input.work
rm -rf "$work" && mkdir -p "$work" || exit 1
mpirun_flags="-np 2"
export OMPI_MCA_rmaps_base_oversubscribe=1
limit=300

results=$work/results.txt
: > "$results"

# run_case <name> <keyword> <ranks> <program> <arguments...>
# The case's files are in $work/<name> (made by the caller); the program
# runs there.
run_case()
{
  local name=$1 keyword=$2 ranks=$3
  shift 3
  local dir=$work/$name status
  mkdir -p "$dir"
  cd "$dir" || return
  if [ "$ranks" -eq 1 ]; then
    timeout $limit "$@" > stdout.txt 2> stderr.txt
  else
    timeout $limit mpirun $mpirun_flags "$@" > stdout.txt 2> stderr.txt
  fi
  status=$?
  local why=""
  [ $status -eq 0 ] && why="$why exit code 0;"
  [ $status -eq 124 ] && why="$why time limit;"
  [ $status -ge 128 ] && why="$why signal (exit code $status);"
  local stopped
  stopped=$(grep -a "stopped:" stderr.txt)
  local n_lines
  n_lines=$(printf '%s' "$stopped" | grep -ac "stopped:")
  [ "$n_lines" -ne 1 ] && why="$why $n_lines 'stopped:' lines;"
  printf '%s' "$stopped" | LC_ALL=C grep -aq '[^ -~]' &&
    why="$why bytes other than printable ASCII in the message;"
  [ "$(printf '%s' "$stopped" | wc -c)" -gt 700 ] &&
    why="$why message longer than 700 characters;"
  printf '%s' "$stopped" | grep -qF -- "$keyword" ||
    why="$why message does not name <$keyword>;"
  # deal.II's exception banner, a signal, and (in a -DQSMPM_SANITIZE=ON
  # build, doc/sanitizers.md) a sanitizer's report.
  grep -qE "Stacktrace|An error occurred in line|Signal:|terminate called|Segmentation|Sanitizer|runtime error:" \
    stderr.txt stdout.txt && why="$why stack trace, signal or sanitizer report;"
  # Anything written as converged.
  local file
  for file in $(find . -name reactions.csv -o -name steps.csv); do
    [ "$(wc -l < "$file")" -gt 1 ] && why="$why data rows in $file;"
  done
  for file in summary.txt load_displacement.csv effective_stiffness.csv \
    realizations.csv; do
    [ -n "$(find . -name $file)" ] && why="$why $file written;"
  done
  if [ -z "$why" ]; then
    echo "PASS $name [$keyword]" | tee -a "$results"
  else
    echo "FAIL $name [$keyword]:$why" | tee -a "$results"
    echo "  $stopped"
  fi
  cd "$work" || exit 1
}

# ---------------------------------------------------------------------
# The driver. A small problem that runs in a fraction of a second (a 4x4
# grid under its own weight, bottom fixed); each case appends a few lines,
# and the later "set" of an entry wins.
base_prm()
{
  cat << 'EOF'
set Dimension = 2
subsection Geometry
  set Lower corner = 0,0
  set Upper corner = 1,1
  set Subdivisions = 4,4
end
subsection Material
  set Model = linear elastic
  subsection linear elastic
    set Young's modulus = 100
    set Poisson's ratio = 0.3
  end
end
subsection Boundary conditions
  set Dirichlet boundaries = 2:xy
  subsection Body force
    set Function expression = 0; -1
  end
end
subsection Load stepping
  set Number of steps = 2
end
subsection Output
  set Directory = out
  set Interval  = 0
end
EOF
}

# driver_case <name> <keyword> <ranks> <lines appended to the base file>
driver_case()
{
  mkdir -p "$work/$1"
  { base_prm; printf '%s\n' "$4"; } > "$work/$1/problem.prm"
  run_case "$1" "$2" "$3" "$qsmpm" problem.prm
}

# The base problem itself must run: otherwise every case below would test
# nothing.
mkdir -p "$work/base" && base_prm > "$work/base/problem.prm"
(cd "$work/base" && "$qsmpm" problem.prm > stdout.txt 2>&1) &&
  echo "PASS base problem runs" | tee -a "$results" ||
  echo "FAIL base problem runs" | tee -a "$results"

# Integer entries.
driver_case integer_fraction "Number of steps" 1 \
  $'subsection Load stepping\n set Number of steps = 2.5\nend'
driver_case integer_negative "Maximum Newton iterations" 1 \
  $'subsection Nonlinear solver\n set Maximum Newton iterations = -3\nend'
driver_case integer_out_of_range "Dimension" 1 'set Dimension = 4'
# Double entries.
driver_case double_text "Young's modulus" 1 \
  $'subsection Material\n subsection linear elastic\n  set Young\'s modulus = abc\n end\nend'
driver_case double_nan "Young's modulus" 1 \
  $'subsection Material\n subsection linear elastic\n  set Young\'s modulus = nan\n end\nend'
driver_case double_infinite "Final load factor" 1 \
  $'subsection Load stepping\n set Final load factor = inf\nend'
driver_case double_out_of_range "Poisson's ratio" 1 \
  $'subsection Material\n subsection linear elastic\n  set Poisson\'s ratio = 0.7\n end\nend'
driver_case double_out_of_range_2_ranks "Poisson's ratio" 2 \
  $'subsection Material\n subsection linear elastic\n  set Poisson\'s ratio = 0.7\n end\nend'
driver_case double_zero_modulus "Young's modulus" 1 \
  $'subsection Material\n subsection linear elastic\n  set Young\'s modulus = 0\n end\nend'
driver_case cam_clay_lambda_below_kappa "Compression index" 1 \
  $'subsection Material\n set Model = Modified Cam Clay\n subsection Modified Cam Clay\n  set Compression index = 0.005\n end\nend'
driver_case fixed_stress_factor_below_one "Fixed-stress factor" 1 \
  $'subsection Pore fluid\n set Enabled = true\n set Fixed-stress factor = 0.5\nend'
# Selection, Bool, List and Anything entries.
driver_case selection_unknown "Model" 1 \
  $'subsection Material\n set Model = plasticity\nend'
driver_case bool_unknown "Plane stress" 1 \
  $'subsection Material\n subsection linear elastic\n  set Plane stress = maybe\n end\nend'
# An Abaqus UMAT that cannot be loaded (the probe calls' checks of a UMAT
# that loads are in the test umat_bad_input).
driver_case umat_no_library "UMAT library" 1 \
  $'subsection Material\n set Model = umat\nend'
driver_case umat_missing_library_2_ranks "UMAT library" 2 \
  $'subsection Material\n set Model = umat\n subsection umat\n  set UMAT library = /no/such/libmodel.so\n end\nend'
driver_case list_wrong_length "Upper corner" 1 \
  $'subsection Geometry\n set Upper corner = 1,1,1\nend'
driver_case list_not_a_number "Lower corner" 1 \
  $'subsection Geometry\n set Lower corner = 0,a\nend'
driver_case list_zero_subdivisions "Subdivisions" 1 \
  $'subsection Geometry\n set Subdivisions = 0,4\nend'
driver_case anything_directory_under_a_file "/dev/null/out" 1 \
  $'subsection Output\n set Directory = /dev/null/out\nend'
driver_case anything_dirichlet_not_an_id "Dirichlet boundaries" 1 \
  $'subsection Boundary conditions\n set Dirichlet boundaries = two:xy\nend'
# Structure of the file.
driver_case unknown_entry "Youngs modulus" 1 \
  $'subsection Material\n set Youngs modulus = 1\nend'
driver_case unknown_subsection "Materials" 1 \
  $'subsection Materials\n set Model = linear elastic\nend'
driver_case subsection_not_closed "problem.prm" 1 \
  $'subsection Material\n set Model = linear elastic'
driver_case end_without_subsection "problem.prm" 1 'end'
# The file itself.
mkdir -p "$work/missing_file"
run_case missing_file "no-such-file.prm" 1 "$qsmpm" no-such-file.prm
mkdir -p "$work/directory_as_file/problem.prm"
run_case directory_as_file "problem.prm" 1 "$qsmpm" problem.prm
mkdir -p "$work/binary_garbage"
# Reproducible garbage: bytes 0..255, each four times, and a run of NULs.
awk 'BEGIN { for (r = 0; r < 4; ++r) for (i = 1; i < 256; ++i) printf "%c", i;
             for (i = 0; i < 64; ++i) printf "%c", 0 }' \
  > "$work/binary_garbage/problem.prm"
run_case binary_garbage "problem.prm" 1 "$qsmpm" problem.prm
mkdir -p "$work/binary_garbage_2_ranks"
cp "$work/binary_garbage/problem.prm" "$work/binary_garbage_2_ranks/"
run_case binary_garbage_2_ranks "problem.prm" 2 "$qsmpm" problem.prm
# A valid line, then a line of some 4000 binary bytes (no comment sign '#',
# no continuation '\\'): the message quotes a printable excerpt of it.
mkdir -p "$work/binary_long_line"
{ echo 'set Dimension = 2'
  awk 'BEGIN { for (r = 0; r < 16; ++r) for (i = 1; i < 256; ++i)
               if (i != 10 && i != 35 && i != 92) printf "%c", i }'
} > "$work/binary_long_line/problem.prm"
run_case binary_long_line "problem.prm" 1 "$qsmpm" problem.prm
# Geometry that contradicts itself.
driver_case geometry_inverted_box "Upper corner" 1 \
  $'subsection Geometry\n set Upper corner = -1,1\nend'
driver_case region_inverted "Region lower corner" 1 \
  $'subsection Material points\n set Region lower corner = 0.5,0.5\n set Region upper corner = 0.2,0.2\nend'
driver_case periodic_one_cell "Subdivisions" 1 \
  $'subsection Geometry\n set Subdivisions = 1,4\n set Periodic directions = x\nend'
# Functions.
driver_case function_nan "Body force" 1 \
  $'subsection Boundary conditions\n subsection Body force\n  set Function expression = 0; sqrt(x-0.5)\n end\nend'
driver_case function_nan_2_ranks "Body force" 2 \
  $'subsection Boundary conditions\n subsection Body force\n  set Function expression = 0; sqrt(x-0.5)\n end\nend'
driver_case function_infinite_at_end "Displacement" 1 \
  $'subsection Boundary conditions\n subsection Displacement\n  set Function expression = 0; 1/(1-t)\n end\nend'
driver_case function_three_components "Body force" 1 \
  $'subsection Boundary conditions\n subsection Body force\n  set Function expression = 0; 0; 1\n end\nend'
driver_case function_one_component "Displacement" 1 \
  $'subsection Boundary conditions\n subsection Displacement\n  set Function expression = 0\n end\nend'
driver_case function_syntax_error "Displacement" 1 \
  $'subsection Boundary conditions\n subsection Displacement\n  set Function expression = 0; x*/2\n end\nend'
driver_case function_unknown_variable "Traction" 1 \
  $'subsection Boundary conditions\n subsection Traction\n  set Function expression = 0; z\n end\nend'
driver_case function_bad_constant "Function constants" 1 \
  $'subsection Boundary conditions\n subsection Body force\n  set Function constants = g\n end\nend'
# Boundary conditions that cannot be.
driver_case boundary_id_missing "Dirichlet boundaries" 1 \
  $'subsection Boundary conditions\n set Dirichlet boundaries = 7:xy\nend'
driver_case traction_id_missing "Traction boundaries" 1 \
  $'subsection Boundary conditions\n set Traction boundaries = 9\nend'
driver_case surface_region_syntax "Surface traction region" 1 \
  $'subsection Boundary conditions\n set Surface traction region = x >\nend'
driver_case decohesion_region_syntax "Cracking region" 1 \
  $'subsection Material\n set Model = decohesion\n subsection decohesion\n  set Crack band width = 0.25\n  set Cracking region = x >\n end\nend'
driver_case smeared_cracks_region_syntax "Cracking region" 1 \
  $'subsection Material\n set Model = smeared cracks\n subsection smeared cracks\n  set Crack band width = 0.25\n  set Cracking region = x >\n end\nend'
driver_case surface_region_empty "selects no face" 2 \
  $'subsection Boundary conditions\n set Surface traction region = x < -5\nend'
driver_case surface_pressure_components "Surface traction type" 1 \
  $'subsection Boundary conditions\n set Surface traction region = y > 0.99\n set Surface traction type = pressure\n subsection Surface traction\n  set Function expression = 1; 2\n end\nend'
driver_case component_unknown "Dirichlet boundaries" 1 \
  $'subsection Boundary conditions\n set Dirichlet boundaries = 2:xw\nend'
driver_case no_support "rigid-body motion" 1 \
  $'subsection Boundary conditions\n set Dirichlet boundaries =\nend'
driver_case sliding_only "rigid-body motion" 1 \
  $'subsection Boundary conditions\n set Dirichlet boundaries = 0:x, 1:x\nend'
# Rigid bodies: one that starts inside the block (its surface 0.3 below the
# block's top, more than a point's size), a negative friction coefficient,
# an unknown shape.
driver_case rigid_body_inside "starts inside" 2 \
  $'subsection Boundary conditions\n subsection Rigid body\n  set Shape = half-space\n  set Name = plate\n  set Point = 0, 0.7\n  set Normal = 0, -1\n end\nend'
driver_case rigid_body_friction_negative "Friction coefficient" 1 \
  $'subsection Boundary conditions\n subsection Rigid body\n  set Shape = half-space\n  set Point = 0, 1\n  set Normal = 0, -1\n  set Friction = coulomb\n  set Friction coefficient = -0.3\n end\nend'
driver_case rigid_body_shape_unknown "Shape" 1 \
  $'subsection Boundary conditions\n subsection Rigid body\n  set Shape = pyramid\n end\nend'
# A body driven by a force: a zero load direction, a load that is no
# expression in t.
driver_case rigid_body_load_direction_zero "Load direction" 1 \
  $'subsection Boundary conditions\n subsection Rigid body\n  set Shape = half-space\n  set Point = 0, 1\n  set Normal = 0, -1\n  set Load direction = 0, 0\n end\nend'
driver_case rigid_body_load_expression "Rigid body: Load" 1 \
  $'subsection Boundary conditions\n subsection Rigid body\n  set Shape = half-space\n  set Point = 0, 1\n  set Normal = 0, -1\n  set Load direction = 0, -1\n  subsection Load\n   set Function expression = 2*q\n  end\n end\nend'
# A step that cannot converge: one Newton iteration, a tolerance GMRES
# cannot reach in one, one cut-back.
noconv=$'subsection Nonlinear solver\n set Maximum Newton iterations = 1\n set Tolerance = 1e-14\n set Residual floor = 0\n set Linear tolerance = 1e-2\nend\nsubsection Load stepping\n set Maximum cut-backs = 1\nend'
driver_case not_converging "Maximum cut-backs" 1 "$noconv"
driver_case not_converging_2_ranks "Maximum cut-backs" 2 "$noconv"
# Opening control: a gauge of one position, a gauge of two equal ones, no
# opening increment.
driver_case opening_gauge_one_position "Opening gauge" 1 \
  $'subsection Load stepping\n set Control = opening\n set Opening increment = 1e-3\n set Opening gauge = 0.5,0.5\nend'
driver_case opening_gauge_same_positions "Opening gauge" 1 \
  $'subsection Load stepping\n set Control = opening\n set Opening increment = 1e-3\n set Opening gauge = 0.5,0.5; 0.5,0.5\nend'
driver_case opening_increment_zero "Opening increment" 1 \
  $'subsection Load stepping\n set Control = opening\n set Opening gauge = 0.1,0.5; 0.9,0.5\nend'
# A gauge outside the body (the top is pulled, no body force).
driver_case opening_gauge_outside "Opening gauge" 1 \
  $'subsection Boundary conditions\n set Dirichlet boundaries = 2:xy, 3:y\n subsection Body force\n  set Function expression = 0; 0\n end\n subsection Displacement\n  set Function expression = 0; 0.01*t*y\n end\nend\nsubsection Load stepping\n set Control = opening\n set Opening increment = 1e-3\n set Opening gauge = 0.5,5; 0.5,6\nend'

# ---------------------------------------------------------------------
# compact_tension: b15.prm with 3 cm cells (a 13 x 10 grid) and its output
# in "out".
ct_case()
{
  mkdir -p "$work/$1"
  sed -e 's/^ *set Cell size .*/  set Cell size = 0.03/' \
    -e 's/^ *set Directory .*/  set Directory = out/' \
    -e 's/^ *set Interval .*/  set Interval = 0/' \
    "$examples/compact_tension/b15.prm" > "$work/$1/b15.prm"
  printf '%s\n' "$4" >> "$work/$1/b15.prm"
  run_case "$1" "$2" "$3" "$compact_tension" b15.prm
}
ct_case ct_ligament_shorter_than_two_cells "Ligament length" 1 \
  $'subsection Compact tension\n set Ligament length = 0.04\nend'
ct_case ct_cell_size_zero "Cell size" 1 \
  $'subsection Compact tension\n set Cell size = 0\nend'
ct_case ct_narrower_than_notch "Width over ligament" 1 \
  $'subsection Compact tension\n set Width over ligament = 0.5\nend'
ct_case ct_no_notch "Notch depth over ligament" 1 \
  $'subsection Compact tension\n set Notch depth over ligament = 0\nend'
ct_case ct_plate_wider_than_specimen "Load plate width" 1 \
  $'subsection Compact tension\n set Load plate width = 500\nend'
ct_case ct_zero_depth "Depth" 1 \
  $'subsection Compact tension\n set Depth = 0\nend'
ct_case ct_not_decohesion "Model" 1 \
  $'subsection Material\n set Model = linear elastic\nend'
ct_case ct_fraction_out_of_range "Stop below fraction of peak" 1 \
  $'subsection Run\n set Stop below fraction of peak = 1.5\nend'
ct_case ct_not_converging "Maximum cut-backs" 1 "$noconv"
ct_case ct_not_converging_2_ranks "Maximum cut-backs" 2 "$noconv"
# Cut in the middle of a line of subsection Material/decohesion.
mkdir -p "$work/ct_truncated_file"
head -c 1200 "$examples/compact_tension/b15.prm" > "$work/ct_truncated_file/b15.prm"
run_case ct_truncated_file "b15.prm" 1 "$compact_tension" b15.prm
mkdir -p "$work/ct_missing_file"
run_case ct_missing_file "no-such-file.prm" 1 "$compact_tension" no-such-file.prm

# ---------------------------------------------------------------------
# polycrystal: 10 grains on a 6 x 6 x 1 grid, the ODF in odf.txt next to
# the parameter file (made per case from the shipped uniform ODF).
poly_case() # name keyword ranks lines [odf]
{
  mkdir -p "$work/$1"
  cat > "$work/$1/polycrystal.prm" << 'EOF'
subsection Polycrystal
  set Number of grains              = 10
  set Cells in plane                = 6
  set Cells through thickness       = 1
  set Points per cell per direction = 1
  set ODF file                      = odf.txt
  set Elementary volumes            = 500
  set Load steps                    = 1
  set Output directory              = out
end
subsection Material
  set Model = cubic elastic
end
subsection Nonlinear solver
  set Residual floor   = 0
  set Linear tolerance = 1e-8
end
EOF
  printf '%s\n' "$4" >> "$work/$1/polycrystal.prm"
  [ -e "$work/$1/odf.txt" ] ||
    cp "$examples/polycrystal/odf/uniform.txt" "$work/$1/odf.txt"
  run_case "$1" "$2" "$3" "$polycrystal" polycrystal.prm
}
odf=$examples/polycrystal/odf/uniform.txt
mkdir -p "$work/odf_empty" && : > "$work/odf_empty/odf.txt"
poly_case odf_empty "odf.txt" 1 ""
mkdir -p "$work/odf_negative" && sed '200s/ 1$/ -1/' "$odf" > "$work/odf_negative/odf.txt"
poly_case odf_negative "odf.txt" 1 ""
mkdir -p "$work/odf_nan" && sed '200s/ 1$/ nan/' "$odf" > "$work/odf_nan/odf.txt"
poly_case odf_nan "odf.txt" 1 ""
mkdir -p "$work/odf_nan_2_ranks" && cp "$work/odf_nan/odf.txt" "$work/odf_nan_2_ranks/"
poly_case odf_nan_2_ranks "odf.txt" 2 ""
mkdir -p "$work/odf_nan_first_line" && sed '4s/ 1$/ nan/' "$odf" > "$work/odf_nan_first_line/odf.txt"
poly_case odf_nan_first_line "odf.txt" 1 ""
mkdir -p "$work/odf_truncated" && head -c 50000 "$odf" > "$work/odf_truncated/odf.txt"
poly_case odf_truncated "odf.txt" 1 ""
mkdir -p "$work/odf_all_zero" && awk '/^%/ { print; next } { $4 = 0; print }' "$odf" > "$work/odf_all_zero/odf.txt"
poly_case odf_all_zero "odf.txt" 1 ""
mkdir -p "$work/odf_off_grid" && sed '300s/^[0-9]* /7 /' "$odf" > "$work/odf_off_grid/odf.txt"
poly_case odf_off_grid "odf.txt" 1 ""
mkdir -p "$work/odf_binary_garbage" && cp "$work/binary_garbage/problem.prm" "$work/odf_binary_garbage/odf.txt"
poly_case odf_binary_garbage "odf.txt" 1 ""
mkdir -p "$work/odf_directory/odf.txt"
poly_case odf_directory "odf.txt" 1 ""
poly_case odf_missing "no-such-odf.txt" 1 \
  $'subsection Polycrystal\n set ODF file = no-such-odf.txt\nend'
poly_case poly_strain_zero "Strain" 1 \
  $'subsection Polycrystal\n set Strain = 0\nend'
poly_case poly_side_length_zero "Side length" 1 \
  $'subsection Polycrystal\n set Side length = 0\nend'
poly_case poly_unknown_test "Boundary conditions" 1 \
  $'subsection Polycrystal\n set Boundary conditions = mixed, shear\nend'
poly_case poly_periodic_one_cell "Cells through thickness" 1 \
  $'subsection Polycrystal\n set Boundary conditions = periodic\nend'
poly_case poly_not_cubic "Model" 1 \
  $'subsection Material\n set Model = linear elastic\nend'
poly_case poly_stiffness_not_positive "C11" 1 \
  $'subsection Material\n subsection cubic elastic\n  set C12 = 300\n end\nend'

echo "$(grep -c '^PASS' "$results") of $(grep -c . "$results") cases pass"
# The list of cases and keywords must be the expected one (a case that
# fails, or one added here but not to the .output, shows as a difference).
sed 's/\]:.*/]/' "$results" | diff "$source_dir/bad_input.output" - > "$work/diff.txt"
status=$?
[ $status -ne 0 ] && { echo "differences to bad_input.output:"; cat "$work/diff.txt"; }
exit $status
