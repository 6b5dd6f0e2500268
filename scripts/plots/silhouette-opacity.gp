# Silhouette opacity (Sen, Chemudugunta, Gopi): opacity against the viewing angle of the first
# surface, face-on (0 deg) to the rim (90 deg), one line per technique, with the two exact models
# dashed: conventional alpha (what abuffer composites) and the thin absorbing shell
# (1 - a)^(1/|N_z|) per crossing that object-space sampling approximates. One panel per CSV of
# tools/silhouette_opacity.cpp (`strata-silhouette --csv`).
# Usage: gnuplot -e "csvs='a.csv b.csv'; out='docs/silhouette-opacity.png'" scripts/plots/silhouette-opacity.gp
if (!exists("csvs")) csvs = 'docs/silhouette/sphere.csv'
if (!exists("out")) out = 'docs/silhouette-opacity.png'
n = words(csvs)
if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
    set terminal pngcairo size 620*n,520 font "sans,10"
} else {
    set terminal png size 620*n,520
}
set output out
set datafile separator ","
set datafile columnheaders
set grid
set key top left
set xlabel "viewing angle acos|N_z| of the first surface (deg), bin centre"
set ylabel "opacity 1 - (over white - over black)"
set xrange [0:90]
set yrange [0:1.02]
mid(lo, hi) = 0.5 * (lo + hi)
methods = "abuffer crow screendoor screendoor-object screendoor-object-sw"
set multiplot layout 1,n
do for [i=1:n] {
    f = word(csvs, i)
    scene = system(sprintf("awk -F, 'NR == 2 { print $1 \" (alpha \" $2 \", \" $3 \"x\" $3 \" supersampling)\" }' '%s'", f))
    set title scene noenhanced
    plot f using (mid(column("angle_lo"), column("angle_hi"))):(column("exact_alpha")) with lines dt 2 lw 2 lc rgb "#444444" title "exact: alpha compositing", \
         f using (mid(column("angle_lo"), column("angle_hi"))):(column("exact_shell")) with lines dt 4 lw 2 lc rgb "#000000" title "exact: thin shell, (1-a)^{1/|N_z|}", \
         for [m in methods] f using (mid(column("angle_lo"), column("angle_hi"))):(column(m)) with linespoints pt 7 ps 0.7 lw 1.5 title m noenhanced
}
unset multiplot
