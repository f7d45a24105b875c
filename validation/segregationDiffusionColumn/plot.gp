# gnuplot: numerical and exact steady fine fraction of the column
set terminal pngcairo size 800,600 enhanced font ",11"
set output "results/profile.png"
set title "Segregation-diffusion column (Gray and Chugunov 2006), Pe = 10, {/Symbol f}_0 = 0.3"
set xlabel "fine fraction n.fine"
set ylabel "height z"
set key bottom left
set xrange [0:1]
set grid
stats "results/profile.dat" using 1 nooutput
ev = STATS_records > 60 ? int(STATS_records/60) : 1
plot "results/profile.dat" using 3:1 with lines lw 2 lc rgb "black" title "exact", \
     "results/profile.dat" using 2:1 every ev with points pt 7 ps 0.6 lc rgb "red" title "segregationDegradationFoam"
