# Log-log plot of the column's convergence study:
#   gnuplot -e "csv='convergence.csv'; png='column_convergence.png'" plot.gp
if (!exists("csv")) csv = 'convergence.csv'
if (!exists("png")) png = 'column_convergence.png'
set terminal pngcairo size 800,560 noenhanced
set output png
set datafile separator ','
set logscale xy
set xlabel 'cells over the height'
set ylabel 'stress error / (rho0 g l0)'
set key top right
set grid
plot csv using ($2):(strcol(1) eq 'linear' ? $3 : 1/0) with linespoints lw 2 pt 7 title 'linear, L2', \
     csv using ($2):(strcol(1) eq 'linear' ? $4 : 1/0) with linespoints lw 1 pt 6 dt 2 title 'linear, max', \
     csv using ($2):(strcol(1) eq 'cpGIMP' ? $3 : 1/0) with linespoints lw 2 pt 5 title 'cpGIMP, L2', \
     csv using ($2):(strcol(1) eq 'cpGIMP' ? $4 : 1/0) with linespoints lw 1 pt 4 dt 2 title 'cpGIMP, max', \
     0.03*(8.0/x)**1.5 with lines lc rgb 'gray' dt 3 title 'slope 1.5'
