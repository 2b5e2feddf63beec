# The picture of doc/contact.md (Hertz): the points' contact pressure of
# the test contact_hertz on its three grids against Hertz's ellipse.
#   cd build && ctest -R contact_hertz.mpirun=1
#   cd tests/contact_hertz.release/mpirun=1
#   gnuplot ../../../../doc/images/contact_hertz.gp   # writes contact_hertz.png
set terminal pngcairo size 800,500 font ",11"
set output 'contact_hertz.png'
set datafile separator ','
set xlabel 'x / a (a: Hertz half-width for the measured force)'
set ylabel 'contact pressure / p0'
set xrange [0:1.3]
set yrange [0:1.2]
set key top right
set grid
set title 'Rigid cylinder on an elastic block (Penalty factor = 1): the points'' contact pressure'
plot sqrt(1-x*x) w l lw 2 lc rgb 'black' t 'Hertz', \
  'pressure-24.csv' every ::1 u 1:2 w p pt 6 ps 1.4 lc rgb '#2ca02c' t 'a/h = 3.5', \
  'pressure-48.csv' every ::1 u 1:2 w p pt 5 ps 1.0 lc rgb '#d62728' t 'a/h = 7', \
  'pressure-96.csv' every ::1 u 1:2 w p pt 7 ps 1.0 lc rgb '#1f77b4' t 'a/h = 14'
