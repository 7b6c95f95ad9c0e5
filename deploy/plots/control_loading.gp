# The control loader of a recorded fedsim/control_loading_state CSV (fedsim record): each
# control's position and the force the pilot feels, with the autopilot's back-drive and the
# loader's status.
# gnuplot -e "infile='out/ils-autoland/fedsim_control_loading_state.csv'; outfile='out/ils-autoland/control_loading.png'; title='...'" deploy/plots/control_loading.gp
if (!exists("infile")) infile = 'fedsim_control_loading_state.csv'
if (!exists("outfile")) outfile = 'control_loading.png'
if (!exists("title")) title = 'fedsim control loading'
set terminal pngcairo size 1400,1000 font 'sans,10' noenhanced
set output outfile
set datafile separator ','
set datafile columnheaders
set grid
set xlabel 'simulation time (s)'
set multiplot layout 2,2 title title
set key top right
set ylabel 'position (-1..1 of the travel; + forward / right)'
plot infile using 'sim_time_s':'pitch.position' with lines lw 2 lc rgb '#2ca02c' title 'column', \
     infile using 'sim_time_s':'roll.position' with lines lw 2 lc rgb '#9467bd' title 'wheel', \
     infile using 'sim_time_s':'yaw.position' with lines lw 2 lc rgb '#ff7f0e' title 'pedals', \
     infile using 'sim_time_s':'pitch.trim_position' with lines lw 1 dt 2 lc rgb '#2ca02c' title 'column trim datum'
set ylabel 'force felt (N)'
plot infile using 'sim_time_s':'pitch.force_n' with lines lw 2 lc rgb '#2ca02c' title 'column', \
     infile using 'sim_time_s':'roll.force_n' with lines lw 2 lc rgb '#9467bd' title 'wheel', \
     infile using 'sim_time_s':'yaw.force_n' with lines lw 2 lc rgb '#ff7f0e' title 'pedals'
set ylabel 'back-driven by the autopilot (each lane: low off, high on)'
set yrange [-0.2:3.5]
set ytics ('column' 0.5, 'wheel' 1.6, 'pedals' 2.7)
plot infile using 'sim_time_s':(column('pitch_backdriven') * 1.0) with steps lw 2 lc rgb '#2ca02c' title 'column', \
     infile using 'sim_time_s':(column('roll_backdriven') * 1.0 + 1.1) with steps lw 2 lc rgb '#9467bd' title 'wheel', \
     infile using 'sim_time_s':(column('yaw_backdriven') * 1.0 + 2.2) with steps lw 2 lc rgb '#ff7f0e' title 'pedals'
set ytics ('safe' 0, 'fading in' 1, 'active' 2, 'stick shaker' 3)
set yrange [-0.5:3.5]
set ylabel ''
plot infile using 'sim_time_s':'status' with steps lw 2 lc rgb '#000000' title 'status', \
     infile using 'sim_time_s':(column('stick_shaker') != 0 ? 3 : 1/0) with points pt 7 ps 0.4 lc rgb '#d62728' title 'shaker'
unset multiplot
