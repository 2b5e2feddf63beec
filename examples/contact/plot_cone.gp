# The cone resistance of cone-penetration.prm against the depth of the
# cone's tip. Run in the directory where the driver ran the file:
#   gnuplot /path/to/examples/contact/plot_cone.gp
# writes cone_penetration.png. The cone's force per radian is column 10
# (cone_Fy) of reactions.csv; q_c = 2 pi F / (pi R^2) = 2 F / R^2 with R = 1,
# over s_u = 100. The tip depth is 4 R t (the load factor in column 2).
set terminal pngcairo size 800,500 font ",11"
set output "cone_penetration.png"
set datafile separator ","
f = "output-cone-penetration/reactions.csv"
set xlabel "tip depth / R"
set ylabel "q_c / s_u"
set grid
set key top left
set arrow from sqrt(3), graph 0 to sqrt(3), graph 1 nohead dt 2 lc rgb "black"
set label "cone embedded" right at sqrt(3) - 0.03, graph 0.85
plot f every ::1 using (4 * $2):(2 * $10 / 100.) with linespoints pt 7 ps 0.5 lc 1 \
     title "60-degree cone, smooth, G / s_u = 100, h = R / 4, cpGIMP"
