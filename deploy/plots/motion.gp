# The motion platform of a recorded fedsim/motion_state CSV (fedsim record): the specific force
# the aircraft demanded against what the platform cued, the cab's attitude (tilt coordination)
# and position, and the six jack lengths, with the platform's status.
# gnuplot -e "infile='out/ils-autoland/fedsim_motion_state.csv'; outfile='out/ils-autoland/motion.png'; title='...'" deploy/plots/motion.gp
if (!exists("infile")) infile = 'fedsim_motion_state.csv'
if (!exists("outfile")) outfile = 'motion.png'
if (!exists("title")) title = 'fedsim motion platform'
set terminal pngcairo size 1400,1000 font 'sans,10' noenhanced
set output outfile
set datafile separator ','
set datafile columnheaders
set grid
set xlabel 'simulation time (s)'
set multiplot layout 2,2 title title
deg = 180.0 / pi
g = 9.80665
set key top right
set ylabel 'specific force (g)'
plot infile using 'sim_time_s':(column('specific_force_cmd_mps2[0]') / g) with lines lw 1 lc rgb '#aec7e8' title 'surge demanded', \
     infile using 'sim_time_s':(column('specific_force_cue_mps2[0]') / g) with lines lw 2 lc rgb '#1f77b4' title 'surge cued', \
     infile using 'sim_time_s':(-column('specific_force_cmd_mps2[2]') / g - 1) with lines lw 1 lc rgb '#ff9896' title 'heave demanded (n_z - 1)', \
     infile using 'sim_time_s':(-column('specific_force_cue_mps2[2]') / g - 1) with lines lw 2 lc rgb '#d62728' title 'heave cued (n_z - 1)'
set ylabel 'cab attitude (deg)'
plot infile using 'sim_time_s':(column('attitude_rad[0]') * deg) with lines lw 2 lc rgb '#9467bd' title 'roll', \
     infile using 'sim_time_s':(column('attitude_rad[1]') * deg) with lines lw 2 lc rgb '#2ca02c' title 'pitch', \
     infile using 'sim_time_s':(column('attitude_rad[2]') * deg) with lines lw 1 lc rgb '#8c564b' title 'yaw'
set ylabel 'cab position from neutral (m)'
plot infile using 'sim_time_s':'position_m[0]' with lines lw 2 lc rgb '#1f77b4' title 'surge', \
     infile using 'sim_time_s':'position_m[1]' with lines lw 2 lc rgb '#ff7f0e' title 'sway', \
     infile using 'sim_time_s':'position_m[2]' with lines lw 2 lc rgb '#d62728' title 'heave (+ down)'
set ylabel 'jack length (m)'
set y2label 'status: 0 parked, 1 engaging, 2 engaged, 3 fault, 4 parking'
set y2range [-0.5:8]
set y2tics 0,1,4
plot for [k=0:5] infile using 'sim_time_s':(column(sprintf('jack_length_m[%d]', k))) with lines lw 1 title sprintf('jack %d', k + 1), \
     infile using 'sim_time_s':'status' axes x1y2 with steps lw 2 lc rgb '#000000' title 'status'
unset multiplot
