# gnuplot -e "work='build/benchmarks/muIBeverloo'; out='docs/figures/muIBeverloo.png'" plot.gp
set terminal pngcairo size 1200,480 font ",10" noenhanced
set output out
set multiplot layout 1,2
set title "mass flow through the slot (muI, planar bin)"
set xlabel "t [s]"; set ylabel "W [kg/s/m]"
set key bottom right
plot for [r in "fit_b15 fit_b20 fit_b25 fit_b30 coarse_b20 height_b20 empty_b40"] \
     work."/".r.".rate" u 1:2 w l t r
set title "Beverloo: W against the slot width"
set xlabel "b [mm]"; set ylabel "W [kg/s/m]"
set logscale xy
set xrange [12:35]; set yrange [5:40]; set xtics (15, 20, 25, 30); set ytics (5, 10, 20, 30, 40)
set key top left
plot work."/fit.dat" u ($1*1e3):2 w p pt 7 ps 1.5 t "muI", \
     "" u ($1*1e3):3 w l t "fit C sqrt(g)(b - k d)^n", \
     "" u ($1*1e3):4 w l dt 2 t "slot law 1.03 sqrt(g)(b - 1.5 d)^1.5"
unset multiplot
