# The speed/accuracy trade: RMSE against the exact reference (abuffer) over GPU ms, one labelled
# point per technique, for builtin:layers:16 and scenes/fandisk-glass.json at 256x256. Exact
# techniques (RMSE 0) are drawn on the floor line RMSE = 1e-6 so a log axis can show them.
load plots.'/common.gp'
set output dir.'/error-vs-time.png'
eval "set terminal ".term." size 1400,650"
set multiplot layout 1,2
set logscale xy
set xlabel 'GPU ms (median)'
set ylabel 'RMSE vs abuffer (linear RGB)'
set yrange [5e-7:*]
unset key
set format y '%.0e'
exact(r) = r < 1e-6 ? 1e-6 : r
do for [scene in 'layers-16 fandisk-glass'] {
    set title scene.' (256x256); exact techniques drawn at 1e-6'
    f = dir.'/'.scene.'.csv'
    plot f using (column("ms_median")):(exact(column("rmse"))) with points pt 7 ps 1.2 lc rgb '#1f77b4', \
         f using (column("ms_median")):(exact(column("rmse"))):(strcol("mode")) with labels offset 0.5,0.4 left rotate by 30 font ',8'
}
unset multiplot
