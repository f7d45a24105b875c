# gnuplot: steady fine fraction in the chute with the exact shock lines
Sr = 1.25
phi0 = 0.4
set terminal pngcairo size 900,600 enhanced font ",11"
set output "results/chute.png"
set title "Plug-flow chute (Gray and Thornton 2005): n.fine, exact shocks (lines), measured shocks (points)"
set xlabel "x"
set ylabel "z"
set xrange [0:1.2]
set yrange [0:1]
set cbrange [0:1]
set cblabel "n.fine"
set palette defined (0 "#2c7bb6", 0.4 "#ffffbf", 1 "#d7191c")
xm = 1.0/Sr
zl(x) = x < xm ? Sr*phi0*x : phi0
zu(x) = x < xm ? 1 - Sr*(1 - phi0)*x : phi0
set samples 500
plot "results/field.dat" using 1:2:3 with image notitle, \
     zl(x) with lines lw 2 lc rgb "black" title "exact shocks", \
     zu(x) with lines lw 2 lc rgb "black" notitle, \
     "results/shocks.dat" using 1:2 every 2 with points pt 6 ps 0.7 lc rgb "white" title "measured", \
     "results/shocks.dat" using 1:3 every 2 with points pt 6 ps 0.7 lc rgb "white" notitle
