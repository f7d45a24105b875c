# Solver cost plot: gnuplot -e "datafile='plot.dat'; output='solverCost.png'" plot.gp
# plot.dat (written by solverCost.py), ns per cell per time step, CPU time unless _wall:
#   cells sTF perSpecies sdf1 ratio ratio1 sTF_wall perSpecies_wall ratio_wall
if (!exists("datafile")) datafile = 'plot.dat'
if (!exists("output")) output = 'solverCost.png'
set terminal pngcairo size 1100,450 font ",10"
set output output
set multiplot layout 1,2 title "segregationDegradationFoam vs scalarTransportFoam (OpenFOAM v1912): 2D mesh, Euler, upwind, linear corrected, PBiCGStab+DILU"
set logscale x
set xrange [5000:320000]
set xlabel "cells"
set grid
set key bottom right
set ylabel "time per cell per time step [ns]"
set yrange [0:*]
plot datafile using 1:2 with linespoints lw 2 pt 7 lc 1 title "scalarTransportFoam, per equation (CPU)", \
     datafile using 1:3 with linespoints lw 2 pt 5 lc 2 title "ours, per species (CPU, slope over 1,2,4,8)", \
     datafile using 1:4 with linespoints lw 1 pt 4 lc 3 dt 2 title "ours, 1 species, whole step (CPU)", \
     datafile using 1:7 with linespoints lw 1 pt 6 lc 1 dt 3 title "scalarTransportFoam (wall clock)", \
     datafile using 1:8 with linespoints lw 1 pt 4 lc 2 dt 3 title "ours, per species (wall clock)"
set ylabel "cost ratio ours / scalarTransportFoam"
set yrange [0:1.6]
set key bottom right
plot datafile using 1:5 with linespoints lw 2 pt 7 lc 2 title "per species (CPU time)", \
     datafile using 1:9 with linespoints lw 1 pt 6 lc 2 dt 3 title "per species (wall clock, shared machine)", \
     datafile using 1:6 with linespoints lw 1 pt 4 lc 3 dt 2 title "1 species, whole step (CPU time)", \
     0.6 with lines lw 2 lc rgb "red" title "target 0.6"
unset multiplot
