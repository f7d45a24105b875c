# gnuplot -e "work='build/benchmarks/muIBeverloo'; out='docs/figures/muIBeverloo.png'" plot.gp
set terminal pngcairo size 1500,480 font ",10" noenhanced
set output out
set multiplot layout 1,3
set title "mass flow through the slot (muI, planar bin)"
set xlabel "t [s]"; set ylabel "W [kg/s/m]"
set key bottom right
plot for [r in "fit_b15 fit_b20 fit_b25 fit_b30 coarse_b20 fine_b20 height_b20 empty_b40"] \
     work."/".r.".rate" u 1:2 w l t r
set title "Beverloo: W against the slot width"
set xlabel "b [mm]"; set ylabel "W [kg/s/m]"
set logscale xy
set xrange [12:35]; set yrange [5:40]; set xtics (15, 20, 25, 30); set ytics (5, 10, 20, 30, 40)
set key top left
plot work."/fit.dat" u ($1*1e3):2 w p pt 7 ps 1.5 t "muI", \
     "" u ($1*1e3):3 w l t "fit C sqrt(g)(b - k d)^n", \
     "" u ($1*1e3):4 w l dt 2 t "slot law 1.03 sqrt(g)(b - 1.5 d)^1.5"
unset logscale; unset xtics; unset ytics; set xtics auto; set ytics auto
set title "mesh convergence over t = 0.2-0.4 s (b = 15, 20, 25, 30 mm)"
set xlabel "cell size dx [mm]"; set ylabel "W / W(dx -> 0) (Richardson)"
set xrange [0:5.5]; set yrange [*:*]
set key bottom left
if (system("grep -q ^b= ".work."/convergence.dat 2>/dev/null && echo 1") eq "1") {
    plot for [i=0:3] work."/convergence.dat" index i u 1:2 w lp pt 7 t columnheader(1)
} else {
    set label 1 "no fine runs (run without -only, or -only fine)" at graph 0.1, graph 0.5
    plot 1 notitle lc rgb "white"
}
unset multiplot
