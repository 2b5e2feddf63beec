# The pore pressure of large-strain.prm's column over time at four depths,
# from its probes, against the exact solution (doc/example_consolidation.md)
# and against Terzaghi's small-strain one. Run in the directory where the
# driver ran large-strain.prm:
#   gnuplot /path/to/examples/consolidation/plot_large_strain.gp
# writes large_strain_pressure.png.
set terminal pngcairo size 800,560 font ",11"
set output "large_strain_pressure.png"
set datafile separator ","
H  = 10.
q  = 5e5
Mc = 1.8e6            # lambda + 2 mu of the Hencky skeleton
D  = 1e-6 * Mc        # kappa_0 M, m^2/s
# J_inf: Mc ln J / J = -q (Newton's method from J = 0.8).
g(J) = Mc * log(J) / J + q
dg(J) = Mc * (1 - log(J)) / J**2
J1 = 0.8 - g(0.8) / dg(0.8); J2 = J1 - g(J1) / dg(J1); Jinf = J2 - g(J2) / dg(J2)
M(m) = pi * (2 * m + 1) / 2.
W(z, Tv) = sum [m = 0:80] 2. / M(m) * sin(M(m) * z / H) * exp(-M(m)**2 * Tv)
J(z, Tv) = Jinf + (1 - Jinf) * W(z, Tv)
exact(z, Tv) = 1 + Mc * log(J(z, Tv)) / J(z, Tv) / q
# Depths below the top of the probed points (their initial positions).
z0 = 2.578125; z1 = 5.078125; z2 = 7.578125; z3 = 9.921875
set xlabel "time factor T_v = kappa_0 M t / H^2"
set ylabel "pore pressure p / q"
set logscale x
set xrange [0.005:1]
set yrange [0:1.05]
set key bottom left
set samples 400
set title "Large-strain consolidation (J_{inf} = 0.80): qsmpm (points), exact (lines), Terzaghi (dashed)"
f = "large-strain-output/probes.csv"
plot exact(z0, x) lc 1 title sprintf("z/H = %.2f", z0 / H), \
     W(z0, x) lc 1 dt 2 notitle, \
     f every ::1 using (D * $2 / H**2):(column("probe0_pore_pressure") / q) with points pt 6 lc 1 notitle, \
     exact(z1, x) lc 2 title sprintf("z/H = %.2f", z1 / H), \
     W(z1, x) lc 2 dt 2 notitle, \
     f every ::1 using (D * $2 / H**2):(column("probe1_pore_pressure") / q) with points pt 6 lc 2 notitle, \
     exact(z2, x) lc 3 title sprintf("z/H = %.2f", z2 / H), \
     W(z2, x) lc 3 dt 2 notitle, \
     f every ::1 using (D * $2 / H**2):(column("probe2_pore_pressure") / q) with points pt 6 lc 3 notitle, \
     exact(z3, x) lc 4 title sprintf("z/H = %.2f", z3 / H), \
     W(z3, x) lc 4 dt 2 notitle, \
     f every ::1 using (D * $2 / H**2):(column("probe3_pore_pressure") / q) with points pt 6 lc 4 notitle
