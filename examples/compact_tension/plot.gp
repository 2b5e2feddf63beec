# Plots of the compact_tension runs, made with gnuplot (Debian: gnuplot-nox).
# Run in the directory that holds output-b15, output-b30 and output-b60:
#
#   gnuplot /path/to/examples/compact_tension/plot.gp
#
# It writes load_deflection.png (the three P-delta curves, like the paper's
# Fig. 3) and fields_b15.png (the normalized crack opening [[u_n]]/u0 and
# stresses sigma_xx/tau_nf, sigma_yy/tau_nf at initiation, partial and
# complete failure of b = 15 cm, like the paper's Fig. 4).
# With output-b15-2x2 present, it also writes b15_points_per_cell.png, and
# with output-b15-complete(-k1) (from an earlier file, see below)
# b15_complete_failure.png.
set datafile separator ','

set terminal pngcairo size 800,560 font ',11'
set output 'load_deflection.png'
set xlabel 'load-point displacement {/Symbol d} (mm)'
set ylabel 'load P (kN)'
set grid
set key top right
plot 'output-b15/load_displacement.csv' skip 1 using ($2*1e3):($3*1e-3) with lines lw 2 title 'b = 15 cm, h = 1 cm', \
     'output-b30/load_displacement.csv' skip 1 using ($2*1e3):($3*1e-3) with lines lw 2 title 'b = 30 cm, h = 2 cm', \
     'output-b60/load_displacement.csv' skip 1 using ($2*1e3):($3*1e-3) with lines lw 2 title 'b = 60 cm, h = 4 cm'

# Point fields: one square per material point, coloured by its value.
set terminal pngcairo size 1050,900 font ',9'
set output 'fields_b15.png'
unset grid
unset key
set size ratio -1
unset xlabel
unset ylabel
set format x ''
set format y ''
set tics scale 0
set palette rgbformulae 33,13,10
set multiplot layout 3,3 rowsfirst
stages = 'initiation partial complete'
names  = 'initiation partial\ failure complete\ failure'
do for [i=1:3] {
  file = sprintf('output-b15/points_%s.csv', word(stages, i))
  set title sprintf('%s: [[u_n]]/u_0', word(stages, i))
  set cbrange [0:1]
  plot file skip 1 using 1:2:3 with points pt 5 ps 0.75 palette
  set title sprintf('%s: {/Symbol s}_{xx}/{/Symbol t}_{nf}', word(stages, i))
  set cbrange [-1:1]
  plot file skip 1 using 1:2:4 with points pt 5 ps 0.75 palette
  set title sprintf('%s: {/Symbol s}_{yy}/{/Symbol t}_{nf}', word(stages, i))
  set cbrange [-1:1]
  plot file skip 1 using 1:2:5 with points pt 5 ps 0.75 palette
}
unset multiplot

# One against 2x2 points per cell for b = 15 cm (if b15-2x2.prm was run;
# steps.csv is written even if a run ends early).
if (strlen(system('ls output-b15-2x2/steps.csv 2>/dev/null')) > 0) {
  set terminal pngcairo size 800,560 font ',11'
  set output 'b15_points_per_cell.png'
  set size noratio
  set size 1,1
  set format x '%g'
  set format y '%g'
  set tics scale 1
  set grid
  set key top right
  set title 'b = 15 cm, h = 1 cm'
  set xlabel 'load-point displacement {/Symbol d} (mm)'
  set ylabel 'load P (kN)'
  plot 'output-b15/steps.csv' skip 1 using ($2*1e3):($3*1e-3) with lines lw 2 title '1 point per cell', \
       'output-b15-2x2/steps.csv' skip 1 using ($2*1e3):($3*1e-3) with lines lw 2 title '2x2 points per cell'
}

# The run to complete failure under displacement control (an earlier file,
# no longer shipped: b15.prm with Run to complete failure, Grid margin = 3,
# steps growing by 5 % from 1 mm on and 1 x 8 points in the back-face band
# cell, output in output-b15-complete; its tail depends on the number of
# MPI ranks, see doc/example_compact_tension.md, "Complete failure") and,
# if present, the same run with one point in that cell (Back-face point
# refinement = 1, output in output-b15-complete-k1): the load on a
# logarithmic displacement axis, and the running work of the load over
# G_f b d.
if (strlen(system('ls output-b15-complete/load_displacement.csv 2>/dev/null')) > 0) {
  set terminal pngcairo size 1100,460 font ',11'
  set output 'b15_complete_failure.png'
  set size noratio
  set size 1,1
  set format x '%g'
  set format y '%g'
  set tics scale 1
  set grid
  set key top right
  unset title
  Gbd = 122.7 * 0.15 * 0.12
  # Running trapezoidal integral of P d(delta); reset on the first row.
  work(x, P) = (W = W + 0.5 * (x - x_prev) * (P + P_prev), x_prev = x, P_prev = P, W)
  reset_work(row) = (row == 0 ? (W = 0, x_prev = 0, P_prev = 0, 0) : 0)
  have_k1 = strlen(system('ls output-b15-complete-k1/load_displacement.csv 2>/dev/null')) > 0
  set multiplot layout 1,2
  set logscale x
  set xrange [0.01:20]
  set xlabel 'load-point displacement {/Symbol d} (mm)'
  set ylabel 'load P (kN)'
  set title 'b = 15 cm, h = 1 cm, to complete failure'
  if (have_k1) {
    plot 'output-b15-complete/load_displacement.csv' skip 1 using ($2*1e3):($3*1e-3) with lines lw 2 title '1 x 8 points in the back-face cell', \
         'output-b15-complete-k1/load_displacement.csv' skip 1 using ($2*1e3):($3*1e-3) with lines lw 2 dt 2 title 'one point per cell'
  } else {
    plot 'output-b15-complete/load_displacement.csv' skip 1 using ($2*1e3):($3*1e-3) with lines lw 2 title '1 x 8 points in the back-face cell'
  }
  set ylabel 'work of the load / (G_f b d)'
  set key bottom right
  set yrange [0:1.05]
  set title 'energy balance'
  if (have_k1) {
    plot 'output-b15-complete/load_displacement.csv' skip 1 using (reset_work($0), $2*1e3):(work($2, $3) / Gbd) with lines lw 2 title '1 x 8 points in the back-face cell', \
         'output-b15-complete-k1/load_displacement.csv' skip 1 using (reset_work($0), $2*1e3):(work($2, $3) / Gbd) with lines lw 2 dt 2 title 'one point per cell', \
         1 with lines lc 'black' dt 3 title 'G_f b d', \
         14. / 15. with lines lc 'black' dt 2 title '1 - h/b'
  } else {
    plot 'output-b15-complete/load_displacement.csv' skip 1 using (reset_work($0), $2*1e3):(work($2, $3) / Gbd) with lines lw 2 title '1 x 8 points in the back-face cell', \
         1 with lines lc 'black' dt 3 title 'G_f b d'
  }
  unset multiplot
  unset logscale x
  set xrange [*:*]
  set yrange [*:*]
}
