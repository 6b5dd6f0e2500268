# Shared by the scaling plots: reads the bench CSVs by column name (gnuplot >= 5.4).
# Called with -e "dir='OUT'; plots='scripts/plots'; term='TERMINAL'" (terminal without size).
set datafile separator comma
set datafile columnheaders
set grid
set key outside right top
# The techniques in a CSV, in the bench's order (one row per technique and run).
modes_in(file) = system("awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == \"mode\") c = i; next } !seen[$c]++ { printf \"%s \", $c }' ".file)
# The header and one technique's rows: each technique's points as one connected series.
rows_of(file, m) = "< awk -F, -v m=".m." 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == \"mode\") c = i; print; next } $c == m' ".file
