# The bench report's speed/accuracy chart (core/bench/report_folder.cpp): every technique as a
# point, GPU ms against RMSE on log-log axes, coloured by family, with the Pareto front drawn as
# a staircase through its named members (what no measured technique beats). The caller sends, on
# gnuplot's standard input:
#   $points  rows "ms rmse family_index id measured_against_other_reference(0|1)"
#   $front   rows "ms rmse id", by ms
# and sets: out (the SVG file), families (space-separated names, family_index 0 = the first),
# ytics (the y axis' labels as a gnuplot tic list; exact rows, RMSE 0, are drawn a decade below
# every other point, where the list says "exact"), subtitle.
set terminal svg size 960,600 dynamic noenhanced font "sans,13" background "#ffffff"
set output out
set logscale xy
set grid xtics ytics mxtics mytics lc rgb "#dddddd"
set xlabel "GPU ms per frame, median (log)"
set ylabel "RMSE against the reference, linear RGB (log)"
set title subtitle
set key outside right top
eval sprintf("set ytics (%s)", ytics)
set mytics 10
set offsets graph 0.04, graph 0.04, graph 0.06, graph 0.04
# Colours that stay apart on white: a family's colour is the same on every report.
array palette[10] = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22"]
n = words(families)
plot for [i=1:n] $points using (int($3) == i - 1 && $5 == 0 ? $1 : NaN):2 \
         with points pt 7 ps 1.1 lc rgb palette[(i - 1) % 10 + 1] title word(families, i), \
     for [i=1:n] $points using (int($3) == i - 1 && $5 == 1 ? $1 : NaN):2 \
         with points pt 6 ps 1.3 lc rgb palette[(i - 1) % 10 + 1] notitle, \
     $front using 1:2 with steps lw 1.5 dt 2 lc rgb "#333333" title "Pareto front", \
     $front using 1:2:3 with labels left offset 0.6, 0.6 font ",11" tc rgb "#222222" notitle
