# Class numbers at t = 10: exact (hat integrals), ours, OpenFOAM v1912's (./Allrun)
set terminal pngcairo size 1000,700
set output "results/breakagePeer.png"
set multiplot layout 2,1
set logscale x
set xlabel "particle volume v [m^3]"
set key top left
set logscale y
set ylabel "particles per initial particle"
set format y "10^{%L}"
set title "Breakage S = v^2, uniform binary, 29 classes of ratio 1.5, t = 10"
plot "results/compare_t10.dat" using 2:3 with lines lw 2 lc rgb "black" title "exact (Ziff and McGrady)", \
     "" using 2:4 with points pt 6 title "segregationDegradationFoam", \
     "" using 2:5 with points pt 2 title "OpenFOAM v1912 populationBalance"
unset logscale y
set ylabel "relative error"
set title ""
set yrange [-0.15:0.15]
plot "results/compare_t10.dat" using 2:6 with linespoints pt 6 title "segregationDegradationFoam", \
     "" using 2:7 with linespoints pt 2 title "OpenFOAM v1912", 0 with lines lc rgb "gray" notitle
unset multiplot
