# gnuplot: numerical and exact tracer profile at the final time
set terminal pngcairo size 800,600 enhanced font ",11"
set output "results/profile.png"
set title "Diffusion of a Gaussian pulse, D = 0.01, t = 0.75"
set xlabel "x"
set ylabel "tracer fraction n.tracer"
set key top right
set grid
stats "results/profile.dat" using 1 nooutput
ev = STATS_records > 60 ? int(STATS_records/60) : 1
plot "results/profile.dat" using 1:5 with lines lw 1 dt 2 lc rgb "gray50" title "initial (t = 0)", \
     "results/profile.dat" using 1:3 with lines lw 2 lc rgb "black" title "exact", \
     "results/profile.dat" using 1:2 every ev with points pt 7 ps 0.6 lc rgb "red" title "segregationDegradationFoam"
