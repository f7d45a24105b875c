# Wall hits along the outer wall of the bend: OpenFOAM's patchPostProcessing
# against particlePass, the same pass (compareImpactMaps)
set terminal pngcairo size 800,560
set output "results/outerWallProfile.png"
set xlabel "bend angle [deg]"
set ylabel "wall hits per second per 2-degree bin (outer half)"
set key top right
set grid
plot "results/outerWallProfile.d2mm.dat" using 1:2 with steps lw 2 title "d2mm, patchPostProcessing (hit points)", \
     "" using 1:3 with steps lw 2 dt 2 title "d2mm, particlePass (face centres)", \
     "results/outerWallProfile.d1mm.dat" using 1:2 with steps lw 2 title "d1mm (fragments), patchPostProcessing", \
     "" using 1:3 with steps lw 2 dt 2 title "d1mm (fragments), particlePass"
