# A stall entry from a recorded fedsim/aircraft_state CSV (fedsim-fly --pilot stall-entry, or a
# QTG stall test's run): airspeed, angle of attack, load factor with the load-factor-corrected
# lift coefficient (n_z / V^2, scaled to 1 at its maximum: 14 CFR 25.103's stall speed is
# V / sqrt(n_z) where it first peaks), and the controls the pilot flew.
# gnuplot -e "infile='out/qtg/runs/b737_stall/fedsim_aircraft_state.csv'; outfile='stall.png'; title='...'; vs=154.2" deploy/plots/stall.gp
if (!exists("infile")) infile = 'fedsim_aircraft_state.csv'
if (!exists("outfile")) outfile = 'stall.png'
if (!exists("title")) title = 'fedsim stall entry'
kt = 3600.0 / 1852.0
deg = 180.0 / pi
set terminal pngcairo size 1400,1000 font 'sans,10' noenhanced
set output outfile
set datafile separator ','
set datafile columnheaders
set grid
set xlabel 'simulation time (s)'
# the corrected lift coefficient's maximum, for the scaling (a first pass over the data)
stats infile using (column('load_factor_z') / (column('air.cas_mps') * kt)**2) name 'CL' nooutput
set multiplot layout 2,2 title title
set key top right
set ylabel 'calibrated airspeed (kt)'
if (exists("vs")) set arrow 1 from graph 0, first vs to graph 1, first vs nohead dt 2 lc rgb '#d62728'
plot infile using 'sim_time_s':(column('air.cas_mps') * kt) with lines lw 2 lc rgb '#1f77b4' title 'CAS', \
     (exists("vs") ? vs : 1/0) with lines dt 2 lc rgb '#d62728' title 'measured 1 g stall speed'
unset arrow 1
set ylabel 'angle of attack, pitch (deg)'
plot infile using 'sim_time_s':(column('air.alpha_rad') * deg) with lines lw 2 lc rgb '#ff7f0e' title 'alpha', \
     infile using 'sim_time_s':(column('theta_rad') * deg) with lines lw 1 lc rgb '#7f7f7f' title 'pitch'
set ylabel 'n_z (g); n_z / V^2 (1 at its maximum)'
set yrange [0:1.6]
plot infile using 'sim_time_s':'load_factor_z' with lines lw 2 lc rgb '#2ca02c' title 'n_z', \
     infile using 'sim_time_s':(column('load_factor_z') / (column('air.cas_mps') * kt)**2 / CL_max) with lines lw 2 lc rgb '#9467bd' title 'corrected lift coefficient'
set autoscale y
set ylabel 'controls flown (elevator -1 full aft; throttle 0 idle)'
set yrange [-1.1:1.1]
plot infile using 'sim_time_s':'controls.elevator' with lines lw 2 lc rgb '#2ca02c' title 'elevator', \
     infile using 'sim_time_s':'controls.throttle[0]' with lines lw 2 lc rgb '#000000' title 'throttle', \
     infile using 'sim_time_s':'controls.aileron' with lines lw 1 lc rgb '#9467bd' title 'aileron'
unset multiplot
