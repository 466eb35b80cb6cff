# gnuplot -e "csv='out/bench-full/results.csv'; png='docs/benchmarks.png'" bench/plot.gp
# Wall time against size per tool (log scale), one panel per family; runs that did not finish
# (timeout, error) are left out of the curves and listed in the table of docs/benchmarks.md.
if (!exists("csv")) csv = 'out/bench-full/results.csv'
if (!exists("png")) png = 'docs/benchmarks.png'
set terminal pngcairo size 1400,1000 font ",11"
set output png
set datafile separator ','
set logscale y
set grid
set key top left
set xlabel 'N'
set ylabel 'wall time (s)'
sel(f, v, t, x) = (strcol(1) eq f && strcol(3) eq v && strcol(4) eq t && strcol(5) eq "ok" && strcol(7) ne "") ? x : 1/0
tools = "sfcv-explicit sfcv-bdd spin abc-pdr"
titles = "'sfcv explicit' 'sfcv BDD' 'Spin (pan search)' 'ABC pdr'"
set multiplot layout 2,2 title 'sfcv against Spin and ABC (bench/run)'
set title 'parallel N --selector (2^N+1 states)'
plot for [t in tools] csv using (sel("parallel", "selector", t, $2)):(column(7)) smooth unique with linespoints title t
set title 'parallel N, free inputs (2^N+1 states, 2^N successors each)'
plot for [t in tools] csv using (sel("parallel", "free", t, $2)):(column(7)) smooth unique with linespoints title t
set title 'tanks N (fixed)'
plot for [t in tools] csv using (sel("tanks", "fixed", t, $2)):(column(7)) smooth unique with linespoints title t
set title 'transfer N (Grafcet, sfcv rsg)'
plot csv using (sel("transfer", "", "sfcv-rsg", $2)):(column(7)) smooth unique with linespoints title 'sfcv rsg'
unset multiplot
