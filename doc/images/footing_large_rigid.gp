# The picture of doc/example_footing.md (deep penetration): the pressure
# under the footing against its settlement, the footing as grid nodes
# (footing-large.prm) and as a rigid body (footing-large-rigid.prm).
#   cd build/examples/footing
#   ./footing footing-large.prm && ./footing footing-large-rigid.prm
#   gnuplot ../../../doc/images/footing_large_rigid.gp   # writes footing_large_rigid.png
set terminal pngcairo size 800,500 font ",11"
set output 'footing_large_rigid.png'
set datafile separator ','
set xlabel 'settlement s / a'
set ylabel 'q / c'
set xrange [0:0.5]
set yrange [0:7]
set key bottom right
set grid
set title 'Strip footing pushed in at finite strain (cpGIMP, F-bar, a/h = 8)'
# The footing's force is column 10 of reactions.csv (footing_Fy): the
# reaction of the prescribed nodes (negative) or the material's force on
# the rigid body; c = 100, a = 1, s = 0.5 t.
plot 2 + pi w l dt 2 lc rgb 'black' t '2 + pi', \
  'output-footing-large/points-8-F-bar/reactions.csv' u (0.5*$2):(-$10/100) w lp pt 7 ps 0.5 lc rgb '#d62728' t 'grid nodes', \
  'output-footing-large-rigid/points-8-F-bar/reactions.csv' u (0.5*$2):($10/100) w lp pt 5 ps 0.5 lc rgb '#1f77b4' t 'rigid body'
