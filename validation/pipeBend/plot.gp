# Fines per bend (broken fraction of the fed d2mm) versus conveying velocity
set terminal pngcairo size 800,560
set output "results/finesPerBend.png"
set xlabel "conveying velocity [m/s]"
set ylabel "broken fraction per bend"
set logscale y
set format y "10^{%L}"
set key top left
set grid
plot for [RD in "1.5 3 5"] "< awk -v rd=".RD." '!/^#/ && $1 == rd && $4 > 0' results/finesPerBend.dat" \
     using 2:4 with linespoints lw 2 pt 7 title "R/D ".RD
