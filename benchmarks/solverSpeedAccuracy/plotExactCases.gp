# gnuplot -e "datafile='results-exactCases.txt'; output='solverSpeedAccuracy-exactCases.png'" plotExactCases.gp
# results-exactCases.txt: block 0 column (N cells Co scheme cpu wall steps max L2),
#                         block 1 chute  (N cells Co scheme cpu wall steps meet L1 bound)
if (!exists("datafile")) datafile = 'results-exactCases.txt'
if (!exists("output")) output = 'solverSpeedAccuracy-exactCases.png'
set terminal pngcairo size 1400,540 font ",10"
set output output
set multiplot layout 1,3
set logscale xy
set grid
set xlabel "solver CPU time [s]"
set key bottom left
sel(s, c, col) = (strcol(4) eq s && strcol(3) eq c) ? column(col) : 1/0

set title "column (Gray-Chugunov): max error vs CPU\nlines: Co 0.45; circles: 0.2; dots: 0.9; triangles: maxCo 2, maxSegregationCo 0.45"
set ylabel "max |n - n_{exact}|"
plot for [s in "upwind linear vanLeer01"] datafile index 0 using 5:(sel(s, "0.45", 8)) with linespoints pt 7 title s, \
     for [s in "upwind linear vanLeer01"] datafile index 0 using 5:(sel(s, "0.2", 8)) with points pt 6 ps 1.5 notitle, \
     for [s in "upwind linear vanLeer01"] datafile index 0 using 5:(sel(s, "0.9", 8)) with points pt 7 ps 0.6 notitle, \
     for [s in "upwind linear vanLeer01"] datafile index 0 using 5:(sel(s, "2/0.45", 8)) with points pt 8 ps 1.2 notitle

set title "chute (Gray-Thornton): meeting-point error vs CPU\nlines: Co 0.45; circles: 0.2; dots: 0.9; triangles: maxCo 2, maxSegregationCo 0.45"
set ylabel "|x_m S_r - 1|"
plot for [s in "upwind limitedLinear01 vanLeer01"] datafile index 1 using 5:(sel(s, "0.45", 8)) with linespoints pt 7 title s, \
     for [s in "upwind limitedLinear01 vanLeer01"] datafile index 1 using 5:(sel(s, "0.2", 8)) with points pt 6 ps 1.5 notitle, \
     for [s in "upwind limitedLinear01 vanLeer01"] datafile index 1 using 5:(sel(s, "0.9", 8)) with points pt 7 ps 0.6 notitle, \
     for [s in "upwind limitedLinear01 vanLeer01"] datafile index 1 using 5:(sel(s, "2/0.45", 8)) with points pt 8 ps 1.2 notitle

set title "chute: L1 error of n.fine vs CPU"
set ylabel "mean |n - n_{exact}|"
plot for [s in "upwind limitedLinear01 vanLeer01"] datafile index 1 using 5:(sel(s, "0.45", 9)) with linespoints pt 7 title s, \
     for [s in "upwind limitedLinear01 vanLeer01"] datafile index 1 using 5:(sel(s, "0.2", 9)) with points pt 6 ps 1.5 notitle, \
     for [s in "upwind limitedLinear01 vanLeer01"] datafile index 1 using 5:(sel(s, "0.9", 9)) with points pt 7 ps 0.6 notitle, \
     for [s in "upwind limitedLinear01 vanLeer01"] datafile index 1 using 5:(sel(s, "2/0.45", 9)) with points pt 8 ps 1.2 notitle
unset multiplot
