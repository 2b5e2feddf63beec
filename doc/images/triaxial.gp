# The picture of doc/example_triaxial.md: the two element tests of
# examples/triaxial against the closed forms of Modified Cam Clay.
#   cd examples/triaxial
#   ../../build/qsmpm drained.prm && ../../build/qsmpm undrained.prm
#   ../../build/qsmpm undrained-pore-fluid.prm
#   gnuplot ../../doc/images/triaxial.gp      # writes triaxial.png
set terminal pngcairo size 1100,480 font ",11"
set output 'triaxial.png'
set datafile separator ','
set multiplot layout 1,2
M = 1.2; kappa = 0.01; lambda = 0.05; theta = lambda - kappa; p0 = 100.
# Undrained (p_c0 = 150): q(p) on the surface; drained (p_c0 = p0): p_c(p).
pcu(p) = 150. * (p0 / p)**(kappa / theta)
qu(p) = M * p * sqrt(pcu(p) / p - 1.)
# Undrained by the pore water, normally consolidated (p_c0 = p0).
pcw(p) = p0 * (p0 / p)**(kappa / theta)
qw(p) = M * p * sqrt(pcw(p) / p - 1.)
pcd(p) = p + (3. * (p - p0))**2 / (M * M * p)
vd(p) = kappa * log(p / p0) + theta * log(pcd(p) / p0)
set xlabel 'mean effective pressure p (kPa)'
set ylabel 'deviatoric stress q (kPa)'
set xrange [0:260]
set yrange [0:340]
set key top left font ',10'
set grid
set title 'Stress paths'
set samples 400
plot M * x w l lc rgb 'gray' dt 2 t 'critical state line q = M p', \
  (x < 150 ? M * sqrt(x * (150 - x)) : 1/0) w l lc rgb '#ff7f0e' dt 3 t 'initial yield surface, p_{c0} = 150', \
  (x < 100 ? M * sqrt(x * (100 - x)) : 1/0) w l lc rgb '#1f77b4' dt 3 t 'initial yield surface, p_{c0} = 100', \
  (x > 79.44 && x < 100 ? qu(x) : 1/0) w l lw 2 lc rgb '#ff7f0e' t 'undrained, closed form', \
  'undrained-output/reactions.csv' every ::1 u (-($20 + 2 * $6) / 3):($6 - $20) w p pt 6 lc rgb '#d62728' t 'undrained.prm', \
  (x > 57.44 && x < 100 ? qw(x) : 1/0) w l lw 2 lc rgb '#9467bd' t 'undrained (NC), closed form', \
  'undrained-pore-fluid-output/probes.csv' every ::1 u (-($18 + 2 * $16) / 3):($16 - $18) w p pt 4 ps 0.8 lc rgb '#8c564b' t 'undrained-pore-fluid.prm (effective)', \
  (x > 100 && x < 166.6 ? 3 * (x - 100) : 1/0) w l lw 2 lc rgb '#1f77b4' t 'drained, closed form', \
  'drained-output/reactions.csv' every ::1 u ((200 - $14) / 3):(-$14 - 100) w p pt 7 ps 0.7 lc rgb '#2ca02c' t 'drained.prm'
set title 'Drained: volumetric strain'
set xlabel 'mean effective pressure p (kPa)'
set ylabel 'volumetric strain v (compression positive)'
set xrange [100:160]
set yrange [0:0.05]
set key top left
plot vd(x) w l lw 2 lc rgb '#1f77b4' t 'closed form', \
  'drained-output/reactions.csv' every ::1 u ((200 - $14) / 3):(0.1 * $2 - 2 * $21) w p pt 7 ps 0.7 lc rgb '#2ca02c' t 'drained.prm'
unset multiplot
