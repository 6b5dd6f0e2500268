# GPU ms against pixel count (builtin:layers:8 at 128^2, 256^2, 512^2), one line per technique.
load plots.'/common.gp'
eval "set terminal ".term." size 1000,700"
file = dir.'/resolution.csv'
set output dir.'/time-vs-resolution.png'
set title 'Time against resolution (builtin:layers:8)'
set xlabel 'square size (pixels per side)'
set ylabel 'GPU ms (median)'
set logscale xy
set xtics (128, 256, 512)
plot for [m in modes_in(file)] rows_of(file, m) using (column("resolution")):(column("ms_median")) \
     with linespoints lw 1.5 title m
