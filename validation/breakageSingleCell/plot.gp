# Ziff-McGrady number density at t = 10 on the study's grids (./Allrun study)
set terminal pngcairo size 900,600
set output "results/ziff.png"
set logscale xy
set xlabel "particle volume v [m^3]"
set ylabel "number density n(v, 10) [1/m^3 per m^3]"
set key bottom left
set title "Breakage S = v^2, uniform binary: fixed pivot vs Ziff & McGrady (1985)"
set xrange [1e-6:1]
set yrange [1e-4:50]
f(v) = 20*exp(-10*v*v)
plot f(x) with lines lw 2 lc rgb "black" title "exact 2t exp(-t v^2)", \
     "results/ziff_2.dat" using 1:2 with points pt 4 title "ratio 2", \
     "results/ziff_1.4142135623730951.dat" using 1:2 with points pt 6 title "ratio 2^{1/2}", \
     "results/ziff_1.189207115002721.dat" using 1:2 with points pt 1 title "ratio 2^{1/4}"
