# The rigid footing of footing-rigid-consolidation.prm over time: its
# settlement against the undrained and drained references, and the pore
# pressure below its centre at three depths. Run in the directory where
# the driver ran footing-rigid-consolidation.prm:
#   gnuplot /path/to/examples/consolidation/plot_footing_rigid.gp
# writes footing_rigid_consolidation.png.
set terminal pngcairo size 800,760 font ",11"
set output "footing_rigid_consolidation.png"
set datafile separator ","
r  = "footing-rigid-consolidation-output/reactions.csv"
f  = "footing-rigid-consolidation-output/probes.csv"
q  = 400.             # the force over the half-width a = 1 m, Pa
cv = 1.346            # kappa E_oed = 1e-6 * 1.346e6 m^2/s
H  = 5.               # the drainage path: the layer's depth
# References (a / h = 8, see doc/example_consolidation.md): the same force
# on the dry soil, and on a nearly incompressible soil of the same shear
# modulus (nu = 0.499, F-bar), both in one step.
s_drained   = 1.26581e-3
s_undrained = 4.64099e-4
set logscale x
set format x "10^{%L}"
set xrange [1e-6:20]
set multiplot layout 2,1
set xlabel "time factor c_v t / H^2"
set ylabel "settlement of the footing (mm)"
set key right center
set title "footing-rigid-consolidation.prm: a rigid footing held at 0.78 (2 + pi) s_u a"
plot r every ::1 using (cv * column("load_factor") / H**2):(1e3 * column("footing_u")) with linespoints pt 6 lc 1 title "qsmpm (u-p)", \
     1e3 * s_drained w l dt 2 lc 2 title "drained (dry soil)", \
     1e3 * s_undrained w l dt 3 lc 3 title "undrained (nu = 0.499, F-bar)"
set ylabel "pore pressure p / (F / a)"
set key top right
set title ""
plot f every ::1 using (cv * column("load_factor") / H**2):(column("probe0_pore_pressure") / q) with linespoints pt 6 lc 1 title "depth 0.06 m", \
     f every ::1 using (cv * column("load_factor") / H**2):(column("probe1_pore_pressure") / q) with linespoints pt 6 lc 2 title "depth 1 m", \
     f every ::1 using (cv * column("load_factor") / H**2):(column("probe2_pore_pressure") / q) with linespoints pt 6 lc 3 title "depth 2 m"
unset multiplot
