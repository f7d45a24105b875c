# gnuplot -e "report='build/benchmarks/demSpeedAccuracy/results.txt'; out='docs/figures/demSpeedAccuracy.png'" benchmarks/demSpeedAccuracy/plot.gp
# (called by ./run with its own results)
# |error of D_fine vs the reference| against CPU time, one line per N (labels: strain)
set terminal pngcairo size 900,600 noenhanced
set output out
set logscale xy
set xlabel 'CPU time [s] (one core; packing, equilibration and sampling)'
set ylabel '|D_fine / D_reference - 1|'
set key top right
set grid
set title 'DEM speed vs accuracy: sheared 2:1 cell, phi 0.5, gammaDot 100 1/s (labels: strain sampled)'
Ns = "500 1000 2000 4000 8000"
plot for [i=1:words(Ns)] sprintf("< awk '$1 == %s' %s", word(Ns, i), report) \
        using 6:(abs($5)) with linespoints pt 7 title sprintf('N = %s', word(Ns, i)), \
     for [i=1:words(Ns)] sprintf("< awk '$1 == %s' %s", word(Ns, i), report) \
        using 6:(abs($5)):2 with labels offset 1.2,0.6 font ',8' notitle, \
     0.05 with lines dt 2 lc rgb 'gray' title '5 %'
