# gnuplot -e "work='build/benchmarks/muIBeverloo/axisymmetric'; out='docs/figures/muIBeverlooAxisymmetric.png'" plotAxisymmetric.gp
set terminal pngcairo size 1200,480 font ",10" noenhanced
set output out
set multiplot layout 1,2
set title "mass flow through the orifice (muI, axisymmetric bin, full 360 deg)"
set xlabel "t [s]"; set ylabel "Q [kg/s]"
set xrange [0:3.2]
set key top right
plot for [r in "fit_D15 fit_D20 fit_D25 fit_D30 coarse_D20 fine_D20 fine_D30 height_D20 empty_D25"] \
     work."/".r.".rate" u 1:2 w l t r
set title "Beverloo: Q against the orifice diameter"
set xlabel "D0 [mm]"; set ylabel "Q [kg/s]"
set logscale xy
set xrange [12:35]; set xtics (15, 20, 25, 30)
set key top left
plot work."/fit.dat" u ($1*1e3):2 w p pt 7 ps 1.5 t "muI", \
     "" u ($1*1e3):3 w l t "fit C sqrt(g)(D0 - k d)^n", \
     "" u ($1*1e3):4 w l dt 2 t "Beverloo 0.58 sqrt(g)(D0 - 1.5 d)^2.5"
unset multiplot
