# GPU ms against depth complexity (builtin:layers:N at 256x256), one line per technique.
load plots.'/common.gp'
eval "set terminal ".term." size 1000,700"
file = dir.'/layers.csv'
set output dir.'/time-vs-layers.png'
set title 'Time against depth complexity (builtin:layers:N, 256x256)'
set xlabel 'layers N (fragments per pixel)'
set ylabel 'GPU ms (median)'
set logscale xy
set xtics (2, 4, 8, 16, 32)
plot for [m in modes_in(file)] rows_of(file, m) using (column("layers")):(column("ms_median")) \
     with linespoints lw 1.5 title m
