# The speed/accuracy trade: RMSE against the exact reference (abuffer) over GPU ms, one labelled
# point per technique, for builtin:layers:16 and scenes/fandisk-glass.json at 256x256. Exact
# techniques (RMSE 0) are drawn on the floor line RMSE = 1e-6 so a log axis can show them.
# Where scripts/bench_screendoor.sh has run, the screen-door family at 1x1, 4x4 and 16x16
# supersampling (screendoor-SCENE.csv) is drawn beside them in orange, labelled "id nN"
# (its own run: compare with its abuffer row, repeated there).
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
# Screen-door rows: each technique at each level; crow (no supersampling) once; abuffer not again.
shown(dummy) = strcol("mode") ne "abuffer" && (strcol("mode") ne "crow" || column("supersampling") == 1)
do for [scene in 'layers-16 fandisk-glass'] {
    set title scene.' (256x256); exact techniques drawn at 1e-6'
    f = dir.'/'.scene.'.csv'
    sd = dir.'/screendoor-'.scene.'.csv'
    if (system("test -f '".sd."' && echo 1 || echo 0") + 0) {
        plot f using (column("ms_median")):(exact(column("rmse"))) with points pt 7 ps 1.2 lc rgb '#1f77b4', \
             f using (column("ms_median")):(exact(column("rmse"))):(strcol("mode")) with labels offset 0.5,0.4 left rotate by 30 font ',8', \
             sd using (shown(0) ? column("ms_median") : NaN):(exact(column("rmse"))) with points pt 5 ps 1.1 lc rgb '#ff7f0e', \
             sd using (shown(0) ? column("ms_median") : NaN):(exact(column("rmse"))):(strcol("mode") eq "crow" ? "crow" : strcol("mode").' n'.strcol("supersampling")) with labels offset 0.5,-0.6 left rotate by -30 font ',8' tc rgb '#d95f02'
    } else {
        plot f using (column("ms_median")):(exact(column("rmse"))) with points pt 7 ps 1.2 lc rgb '#1f77b4', \
             f using (column("ms_median")):(exact(column("rmse"))):(strcol("mode")) with labels offset 0.5,0.4 left rotate by 30 font ',8'
    }
}
unset multiplot
