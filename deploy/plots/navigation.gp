# NAV1/NAV2 course deviation and TO/FROM, DME distance, INS and GPS position errors and the
# flight director's bank command of a recorded fedsim/navigation_state CSV (fedsim record).
# gnuplot -e "infile='out/default/fedsim_navigation_state.csv'; outfile='out/default/navigation.png'; title='...'" deploy/plots/navigation.gp
if (!exists("infile")) infile = 'fedsim_navigation_state.csv'
if (!exists("outfile")) outfile = 'navigation.png'
if (!exists("title")) title = 'fedsim navigation'
set terminal pngcairo size 1400,1000 font 'sans,10' noenhanced
set output outfile
set datafile separator ','
set datafile columnheaders
set grid
set xlabel 'simulation time (s)'
set multiplot layout 2,2 title title
nm = 1 / 1852.0
deg = 180.0 / pi
shown(s, v) = (column(s) == 0 ? v : 1/0)   # SIGNAL_VALID is 0: a flagged reading is not drawn
set key top left
set ylabel 'course deviation (full scale = 1; + fly right)'
set yrange [-1.1:1.1]
plot infile using 'sim_time_s':(shown('nav[0].status', column('nav[0].course_deviation'))) with lines lw 2 lc rgb '#1f77b4' title 'NAV1', \
     infile using 'sim_time_s':(shown('nav[1].status', column('nav[1].course_deviation'))) with lines lw 2 lc rgb '#ff7f0e' title 'NAV2', \
     infile using 'sim_time_s':(column('nav[0].to_from') == 1 ? 1.05 : column('nav[0].to_from') == 2 ? -1.05 : 1/0) with points pt 7 ps 0.3 lc rgb '#1f77b4' title 'NAV1 TO (top) / FROM (bottom)'
set autoscale y
set ylabel 'DME slant range (NM)'
plot infile using 'sim_time_s':(shown('nav[0].dme_status', column('nav[0].dme_slant_range_m') * nm)) with lines lw 2 lc rgb '#1f77b4' title 'NAV1 DME', \
     infile using 'sim_time_s':(shown('nav[1].dme_status', column('nav[1].dme_slant_range_m') * nm)) with lines lw 2 lc rgb '#ff7f0e' title 'NAV2 DME'
set ylabel 'horizontal position error (m)'
plot infile using 'sim_time_s':(column('ins.valid') != 0 ? column('ins.horizontal_error_m') : 1/0) with lines lw 2 lc rgb '#2ca02c' title 'INS', \
     infile using 'sim_time_s':(column('gps.valid') != 0 ? column('gps.horizontal_error_m') : 1/0) with lines lw 1 lc rgb '#9467bd' title 'GPS'
set ylabel 'flight director bank command (deg)'
plot infile using 'sim_time_s':(column('fd.roll_valid') != 0 ? column('fd.roll_command_rad') * deg : 1/0) with lines lw 2 lc rgb '#d62728' title 'FD roll command'
unset multiplot
