# gnuplot: numerical and exact steady fine fraction of the column
set terminal pngcairo size 800,600 enhanced font ",11"
set output "results/profile.png"
set title "Uniform shear layer with the shear-rate closures (C_s = 0.26, C = 0.042), 30 % fines"
set xlabel "fines share of the solids c"
set ylabel "height z [m]"
set key bottom left
set xrange [0:1]
set grid
stats "results/profile.dat" using 1 nooutput
ev = STATS_records > 60 ? int(STATS_records/60) : 1
plot "results/profile.dat" using 3:1 with lines lw 2 lc rgb "black" title "exact", \
     "results/profile.dat" using 2:1 every ev with points pt 7 ps 0.6 lc rgb "red" title "segregationDegradationFoam"
