# gnuplot -e "csv='out/bench-full/results.csv'; png='docs/benchmarks.png'" bench/plot.gp
# CPU time against size per tool (log scale), one panel per family; runs that did not finish
# (timeout, error) are left out of the curves and listed in the table of docs/benchmarks.md.
if (!exists("csv")) csv = 'out/bench-full/results.csv'
if (!exists("png")) png = 'docs/benchmarks.png'
set terminal pngcairo size 1400,1000 font ",11"
set output png
set logscale y
set grid
set key top left
set xlabel 'N'
set ylabel 'CPU time, user + system (s)'
# "N seconds" rows of one family, variant and tool that finished, sorted by N.
rows(f, v, t) = sprintf("< awk -F, '$1==\"%s\" && $3==\"%s\" && $4==\"%s\" && $5==\"ok\" && $12!=\"\" {print $2, $12}' %s | sort -n", f, v, t, csv)
tools = "sfcv-explicit sfcv-bdd spin abc-pdr"
titles = "'sfcv explicit' 'sfcv BDD' 'Spin (pan search)' 'ABC pdr'"
set multiplot layout 2,2 title 'sfcv against Spin and ABC (bench/run)'
set title 'parallel N --selector (2^N+1 states)'
plot for [t in tools] rows("parallel", "selector", t) using 1:2 with linespoints title t
set title 'parallel N, free inputs (2^N+1 states, 2^N successors each)'
plot for [t in tools] rows("parallel", "free", t) using 1:2 with linespoints title t
set title 'tanks N (fixed)'
plot for [t in tools] rows("tanks", "fixed", t) using 1:2 with linespoints title t
set title 'transfer N (Grafcet, sfcv rsg)'
plot rows("transfer", "", "sfcv-rsg") using 1:2 with linespoints title 'sfcv rsg'
unset multiplot
