# The strip load of footing-consolidation.prm over time: the settlement
# below the load's centre against its undrained and drained references,
# and the pore pressure at three depths. Run in the directory where the
# driver ran footing-consolidation.prm:
#   gnuplot /path/to/examples/consolidation/plot_footing.gp
# writes footing_consolidation.png.
set terminal pngcairo size 800,760 font ",11"
set output "footing_consolidation.png"
set datafile separator ","
f  = "footing-consolidation-output/probes.csv"
q  = 257.1
cv = 1.346            # kappa E_oed = 1e-6 * 1.346e6 m^2/s
H  = 5.               # the drainage path: the layer's depth
# References (h = 0.125 m, see doc/example_consolidation.md): the same load
# on the dry soil, and on an incompressible soil of the same shear modulus
# (nu = 0.4999, F-bar), both in one step.
s_drained   = 5.98167e-4
s_undrained = 2.92193e-4
set logscale x
set format x "10^{%L}"
set xrange [1e-6:20]
set multiplot layout 2,1
set xlabel "time factor c_v t / H^2"
set ylabel "settlement below the centre (mm)"
set key bottom right
set title "footing-consolidation.prm: a strip load q = (2 + pi) s_u / 2, held"
plot f every ::1 using (cv * $2 / H**2):(-1e3 * $6) with linespoints pt 6 lc 1 title "qsmpm (u-p)", \
     1e3 * s_drained w l dt 2 lc 2 title "drained (dry soil)", \
     1e3 * s_undrained w l dt 3 lc 3 title "undrained (nu = 0.4999, F-bar)"
set ylabel "pore pressure p / q"
set key top right
set title ""
plot f every ::1 using (cv * $2 / H**2):($10 / q) with linespoints pt 6 lc 1 title "depth 0.06 m", \
     f every ::1 using (cv * $2 / H**2):($21 / q) with linespoints pt 6 lc 2 title "depth 1 m", \
     f every ::1 using (cv * $2 / H**2):($32 / q) with linespoints pt 6 lc 3 title "depth 2 m"
unset multiplot
