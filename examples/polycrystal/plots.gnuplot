# Pictures of doc/example_polycrystal.md from the outputs of the example
# (run in the build directory of the example after the default run, the
# resolution study and the realizations run):
#   gnuplot plots.gnuplot
set terminal pngcairo size 640,600 font ",11"

# Fig. 5 of the paper: the grains (material points coloured by grain).
set output "polycrystal_grains.png"
set size ratio -1
set xrange [0:1]
set yrange [0:1]
set xlabel "x / L"
set ylabel "y / L"
set title "1000 columnar Voronoi grains (points coloured by grain)"
unset colorbox
set palette defined (0 "#1f77b4", 1 "#ff7f0e", 2 "#2ca02c", 3 "#d62728", 4 "#9467bd", 5 "#8c564b", 6 "#e377c2", 7 "#7f7f7f", 8 "#bcbd22", 9 "#17becf")
set cbrange [0:9]
plot "polycrystal-output/grain_map.dat" using 1:2:(int($3 * 7919) % 10) with image notitle

# The resolution study: E_in-plane against the in-plane cell size h
# (resolution.dat: 2^3 points per cell, 4 cells through the thickness;
# resolution_extra.dat: more cells in z, more points per cell).
reset
set terminal pngcairo size 640,420 font ",11"
set output "polycrystal_resolution.png"
set xlabel "in-plane cell size h / L"
set ylabel "E_{in-plane} (GPa)"
set title "Resolution study (1000 grains, mixed boundary conditions)"
set key top left
set xrange [0:0.035]
set yrange [193:205]
hill = 194.64
plot "resolution.dat" using (1./$1):8 with linespoints pt 7 title "2^3 points per cell, 4 cells in z", \
     "" using (1./$1):8:(sprintf("%dx%dx%d", $1, $1, $2)) with labels offset 0,1 font ",9" notitle, \
     "resolution_extra.dat" every ::0::0 using (1./$1):8 with points pt 4 ps 1.5 title "64x64x8 (8 cells in z)", \
     "resolution_extra.dat" every ::1::1 using (1./$1):8 with points pt 6 ps 1.5 title "32x32x4, 4^3 points per cell", \
     hill with lines dt 2 title "Hill of the orientations", \
     197.4 with lines dt 3 title "paper (measured texture)"

# The realizations.
reset
set terminal pngcairo size 640,420 font ",11"
set output "polycrystal_realizations.png"
set datafile separator ","
stats "realizations/realizations.csv" using 4 nooutput
binwidth = 0.1
bin(x) = binwidth * floor(x / binwidth) + binwidth / 2
set boxwidth binwidth * 0.9
set style fill solid 0.6
set xrange [STATS_min - 0.3 : STATS_max + 0.3]
set yrange [0:*]
set ytics 1
set xlabel "E_{in-plane} (GPa)"
set ylabel "realizations"
set title sprintf("%d realizations: mean %.2f GPa, standard deviation %.2f GPa", STATS_records, STATS_mean, STATS_ssd)
plot "realizations/realizations.csv" using (bin($4)):(1) smooth frequency with boxes notitle
