# Altitude, airspeed, pitch and roll of a recorded fedsim/aircraft_state CSV (fedsim record).
# gnuplot -e "infile='out/default/fedsim_aircraft_state.csv'; outfile='out/default/flight.png'; title='...'" deploy/plots/flight.gp
if (!exists("infile")) infile = 'fedsim_aircraft_state.csv'
if (!exists("outfile")) outfile = 'flight.png'
if (!exists("title")) title = 'fedsim flight'
set terminal pngcairo size 1400,1000 font 'sans,10' noenhanced
set output outfile
set datafile separator ','
set datafile columnheaders
set grid
set key off
set xlabel 'simulation time (s)'
set multiplot layout 2,2 title title
ft = 1 / 0.3048
kt = 3600.0 / 1852.0
deg = 180.0 / pi
set ylabel 'altitude (ft MSL)'
plot infile using 'sim_time_s':(column('altitude_msl_m') * ft) with lines lw 2 lc rgb '#1f77b4'
set ylabel 'airspeed (kt)'
set key top right
plot infile using 'sim_time_s':(column('air.tas_mps') * kt) with lines lw 2 lc rgb '#d62728' title 'TAS', \
     infile using 'sim_time_s':(column('air.cas_mps') * kt) with lines lw 2 lc rgb '#ff9896' title 'CAS'
set key off
set ylabel 'pitch (deg)'
plot infile using 'sim_time_s':(column('theta_rad') * deg) with lines lw 2 lc rgb '#2ca02c'
set ylabel 'roll (deg)'
plot infile using 'sim_time_s':(column('phi_rad') * deg) with lines lw 2 lc rgb '#9467bd'
unset multiplot
