# gnuplot plot.gp: results/profiles.png from results/profiles.dat (./check)
set terminal pngcairo size 1000,450 font ",10"
set output "results/profiles.png"
set multiplot layout 1,2 title "Nedderman-Tuzun field above a slot: cells (points) and exact (lines)"
set xlabel "x [m]"
set grid
set key top right
set xrange [-0.08:0.08]
set ylabel "downward speed v / U0"
plot for [i=0:2] "results/profiles.dat" index i using 2:4 with lines lc i+1 title sprintf("exact, z = %s m", word("0.1 0.2 0.3", i+1)), \
     for [i=0:2] "results/profiles.dat" index i using 2:3 with points pt 6 lc i+1 notitle
set ylabel "horizontal speed u / U0"
plot for [i=0:2] "results/profiles.dat" index i using 2:6 with lines lc i+1 title sprintf("exact, z = %s m", word("0.1 0.2 0.3", i+1)), \
     for [i=0:2] "results/profiles.dat" index i using 2:5 with points pt 6 lc i+1 notitle
unset multiplot
