# Plots `strata track --sweep-csv FILE` output: mean viewing error against latency, one line per
# predictor and deflection (columns of the wide CSV).
# Usage: gnuplot -e "csv='track-sweep.csv'; out='docs/track-sweep.png'" scripts/plot_track_sweep.gp
if (!exists("csv")) csv = 'track-sweep.csv'
if (!exists("out")) out = 'docs/track-sweep.png'
# pngcairo draws anti-aliased lines; plain png (libgd) is the fallback where cairo is missing.
if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
    set terminal pngcairo size 1000,620 font "sans,11"
} else {
    set terminal png size 1000,620
}
set output out
set datafile separator ","
set key top left
set grid
set xlabel "latency, frame start to display (ms)"
set ylabel "mean viewing error (deg)"
set title "Head-pose prediction: viewing error against latency (synthetic head motion, 120 Hz tracker)"
set logscale y
ncols = system(sprintf("head -1 '%s' | tr ',' '\\n' | wc -l", csv)) + 0
plot for [i=2:ncols] csv using 1:i with linespoints pointsize 0.6 title columnheader(i)
