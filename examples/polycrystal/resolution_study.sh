#!/bin/sh
# Resolution study of the polycrystal example (doc/example_polycrystal.md):
# the default sample (1000 grains, electrodeposited-Ni-like texture, mixed
# boundary conditions) on several grids. Run in the build directory of the
# example: sh resolution_study.sh [mpirun -np 2]. Each run writes
# resolution-<cells>x<cells>x<z>-p<points>/summary.txt; the table
# resolution.dat (and resolution_extra.dat for the runs with other z or
# points per cell) collect points per grain, E_x, E_y, E_in-plane and the
# wall time of the six tests.
launcher="$*"
header="# cells_in_plane cells_z points_per_dir n_points points_per_grain E_x E_y E_in_plane wall_time_s"
echo "$header" > resolution.dat
echo "$header" > resolution_extra.dat
for run in "32 4 2" "48 4 2" "64 4 2" "96 4 2" "64 8 2" "32 4 4"; do
  set -- $run
  name=resolution-$1x$1x$2-p$3
  sed -e "s/^\( *set Cells in plane *=\).*/\1 $1/" \
      -e "s/^\( *set Cells through thickness *=\).*/\1 $2/" \
      -e "s/^\( *set Points per cell per direction *=\).*/\1 $3/" \
      -e "s/^\( *set Output directory *=\).*/\1 $name/" \
      polycrystal.prm > $name.prm
  # A run whose summary exists (e.g. a copy of the default run) is reused.
  if [ ! -f $name/summary.txt ]; then
    $launcher ./polycrystal $name.prm > $name.log 2>&1 || { echo "$name failed"; exit 1; }
  fi
  s=$name/summary.txt
  get() { sed -n "s/^$1 = //p" $s; }
  # The grid series (2^3 points per cell, 4 cells in z) and the others.
  table=resolution.dat
  [ "$2" = 4 ] && [ "$3" = 2 ] || table=resolution_extra.dat
  echo "$1 $2 $3 $(get n_points) $(get points_per_grain) $(get E_x_GPa) $(get E_y_GPa) $(get E_in_plane_GPa) $(get wall_time_mixed_s)" >> $table
done
cat resolution.dat resolution_extra.dat
