# gnuplot -e "datafile='results.txt'; output='solverSpeedAccuracy.png'" plot.gp
# results.txt columns: refine cells maxCo scheme cpu wall steps maxErr meanErr M_end
if (!exists("datafile")) datafile = 'results.txt'
if (!exists("output")) output = 'solverSpeedAccuracy.png'
set terminal pngcairo size 900,550 font ",10"
set output output
set title "silo2D, outlet coarse fraction: error against the reference vs solver CPU time"
set logscale xy
set xlabel "solver CPU time [s]"
set ylabel "max_t |M - M_{ref}|"
set grid
set key top right
plot datafile using ($1==1 && strcol(4) eq "upwind" ? $5 : 1/0):8 with linespoints pt 7 lc 1 title "upwind, refine 1 (Co 0.25-4)", \
     datafile using ($1==1 && strcol(4) eq "limitedLinear01" ? $5 : 1/0):8 with linespoints pt 5 lc 2 title "limitedLinear01, refine 1", \
     datafile using ($1==1 && strcol(4) eq "vanLeer01" ? $5 : 1/0):8 with linespoints pt 9 lc 3 title "vanLeer01, refine 1", \
     datafile using ($1==2 && strcol(4) eq "upwind" ? $5 : 1/0):8 with points pt 6 ps 2 lc 1 title "upwind, refine 2", \
     datafile using ($1==2 && strcol(4) eq "limitedLinear01" ? $5 : 1/0):8 with points pt 4 ps 2 lc 2 title "limitedLinear01, refine 2", \
     datafile using ($1==2 && strcol(4) eq "vanLeer01" ? $5 : 1/0):8 with points pt 8 ps 2 lc 3 title "vanLeer01, refine 2"
