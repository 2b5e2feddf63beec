# The pore pressure of Terzaghi's column over time at four depths, from the
# probes of terzaghi.prm, against the exact solution. Run in the directory
# where the driver ran terzaghi.prm:
#   gnuplot /path/to/examples/consolidation/plot.gp
# writes terzaghi_pressure.png.
set terminal pngcairo size 800,560 font ",11"
set output "terzaghi_pressure.png"
set datafile separator ","
H  = 10.
q  = 1e4
cv = 1.8              # kappa E_oed, m^2/s
M(m) = pi * (2 * m + 1) / 2.
exact(z, Tv) = sum [m = 0:80] 2. / M(m) * sin(M(m) * z / H) * exp(-M(m)**2 * Tv)
# Depths below the top of the probed points (their initial positions).
z0 = 2.578125; z1 = 5.078125; z2 = 7.578125; z3 = 9.921875
set xlabel "time factor T_v = c_v t / H^2"
set ylabel "pore pressure p / q"
set logscale x
set xrange [0.005:1]
set yrange [0:1.05]
set key bottom left
set samples 400
set title "Terzaghi consolidation: qsmpm (points) and exact (lines), terzaghi.prm"
plot exact(z0, x) lc 1 title sprintf("z/H = %.2f", z0 / H), \
     "terzaghi-output/probes.csv" every ::1 using (cv * $2 / H**2):(column("probe0_pore_pressure") / q) with points pt 6 lc 1 notitle, \
     exact(z1, x) lc 2 title sprintf("z/H = %.2f", z1 / H), \
     "terzaghi-output/probes.csv" every ::1 using (cv * $2 / H**2):(column("probe1_pore_pressure") / q) with points pt 6 lc 2 notitle, \
     exact(z2, x) lc 3 title sprintf("z/H = %.2f", z2 / H), \
     "terzaghi-output/probes.csv" every ::1 using (cv * $2 / H**2):(column("probe2_pore_pressure") / q) with points pt 6 lc 3 notitle, \
     exact(z3, x) lc 4 title sprintf("z/H = %.2f", z3 / H), \
     "terzaghi-output/probes.csv" every ::1 using (cv * $2 / H**2):(column("probe3_pore_pressure") / q) with points pt 6 lc 4 notitle
