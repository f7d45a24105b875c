# gnuplot -e "datafile='results-exactCases.txt'; output='solverSpeedAccuracy-exactCases.png'" plotExactCases.gp
# results-exactCases.txt: block 0 column (N cells Co scheme cpu wall steps max L2),
#                         block 1 chute  (N cells Co scheme cpu wall steps meet L1 bound)
# Lines: the meshes at Co 0.45; open circles Co 0.2, dots Co 0.9, triangles
# maxCo 2 with maxSegregationCo 0.45 (colour = scheme)
if (!exists("datafile")) datafile = 'results-exactCases.txt'
if (!exists("output")) output = 'solverSpeedAccuracy-exactCases.png'
set terminal pngcairo size 1400,540 font ",10"
set output output
set multiplot layout 1,3 title "Exact cases: error against CPU time over meshes; lines Co 0.45, circles 0.2, dots 0.9, triangles maxCo 2 / maxSegregationCo 0.45"
set logscale xy
set grid
set xlabel "solver CPU time [s]"
set key bottom left
sel(s, c, col) = (strcol(4) eq s && strcol(3) eq c) ? column(col) : 1/0
col = "upwind linear vanLeer01"
chu = "upwind limitedLinear01 vanLeer01"

set title "column (Gray-Chugunov 2006): max error"
set ylabel "max |n - n_{exact}|"
plot for [i=1:3] datafile index 0 using 5:(sel(word(col,i), "0.45", 8)) with linespoints pt 7 lc i title word(col,i), \
     for [i=1:3] datafile index 0 using 5:(sel(word(col,i), "0.2", 8)) with points pt 6 ps 1.5 lc i notitle, \
     for [i=1:3] datafile index 0 using 5:(sel(word(col,i), "0.9", 8)) with points pt 7 ps 0.6 lc i notitle, \
     for [i=1:3] datafile index 0 using 5:(sel(word(col,i), "2/0.45", 8)) with points pt 8 ps 1.2 lc i notitle

set title "chute (Gray-Thornton 2005): meeting point"
set ylabel "|x_m S_r - 1|"
plot for [i=1:3] datafile index 1 using 5:(sel(word(chu,i), "0.45", 8)) with linespoints pt 7 lc i title word(chu,i), \
     for [i=1:3] datafile index 1 using 5:(sel(word(chu,i), "0.2", 8)) with points pt 6 ps 1.5 lc i notitle, \
     for [i=1:3] datafile index 1 using 5:(sel(word(chu,i), "0.9", 8)) with points pt 7 ps 0.6 lc i notitle, \
     for [i=1:3] datafile index 1 using 5:(sel(word(chu,i), "2/0.45", 8)) with points pt 8 ps 1.2 lc i notitle

set title "chute: L1 error of n.fine"
set ylabel "mean |n - n_{exact}|"
plot for [i=1:3] datafile index 1 using 5:(sel(word(chu,i), "0.45", 9)) with linespoints pt 7 lc i title word(chu,i), \
     for [i=1:3] datafile index 1 using 5:(sel(word(chu,i), "0.2", 9)) with points pt 6 ps 1.5 lc i notitle, \
     for [i=1:3] datafile index 1 using 5:(sel(word(chu,i), "0.9", 9)) with points pt 7 ps 0.6 lc i notitle, \
     for [i=1:3] datafile index 1 using 5:(sel(word(chu,i), "2/0.45", 9)) with points pt 8 ps 1.2 lc i notitle
unset multiplot
