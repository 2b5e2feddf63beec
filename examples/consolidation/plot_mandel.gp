# Mandel's problem: the centre pressure and the plate's settlement over
# time, computed (points) and exact (lines), from mandel.csv of
#   ./consolidation consolidation.prm
# Run in the same directory:
#   gnuplot /path/to/examples/consolidation/plot_mandel.gp
# writes mandel_pressure.png.
set terminal pngcairo size 800,560 font ",11"
set output "mandel_pressure.png"
set xlabel "time factor c t / a^2"
set ylabel "centre pressure p / p_0"
set y2label "vertical strain -u_y / y (per mille)"
set ytics nomirror
set y2tics
set y2range [4.2:5.8]
set xrange [0:0.5]
set yrange [0.5:1.3]
set key top center horizontal maxrows 2
set title "Mandel's problem under a rigid plate: qsmpm (points), exact (lines)"
plot "mandel.csv" using 1:3 with lines lc 1 title "centre pressure, exact", \
     "mandel.csv" every 4 using 1:2 with points pt 6 lc 1 title "centre pressure, qsmpm", \
     "mandel.csv" using 1:(-1000 * $5) axes x1y2 with lines lc 2 title "plate settlement / b, exact", \
     "mandel.csv" every 4 using 1:(-1000 * $4) axes x1y2 with points pt 4 lc 2 title "plate settlement / b, qsmpm"
