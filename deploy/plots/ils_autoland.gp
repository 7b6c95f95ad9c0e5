# The ILS approach and autoland of deploy/ils-autoland.yaml from its recordings (fedsim record):
# plan view and vertical profile against the runway (from fedsim_aircraft_state.csv), the ILS
# deviations NAV1 read (fedsim_navigation_state.csv), speed and thrust, pitch and sink rate, and
# the autopilot's modes (fedsim_autopilot_state.csv).
# gnuplot -e "outdir='out/ils-autoland'; outfile='out/ils-autoland/ils_autoland.png'; title='...'" deploy/plots/ils_autoland.gp
# The approach geometry defaults to KSFO 28R: the landing threshold (data/nav/runways.csv's end
# moved by its 91 m displacement), the runway's true azimuth, and from data/nav/ils.csv the
# localizer antenna 3716.6 m beyond the threshold and the glide-slope antenna abeam a point 239 m
# (784 ft) past it with a 3.00 deg path. The beam limits drawn are full scale (150 uA): the
# localizer 350 ft either side at the threshold (ICAO Annex 10's 700 ft course sector), the glide
# slope 0.24 of its angle above and below the path (as the receivers model them).
if (!exists("lat0")) lat0 = 37.613921
if (!exists("lon0")) lon0 = -122.358072
if (!exists("runway_heading_deg")) runway_heading_deg = 297.813
if (!exists("localizer_beyond_m")) localizer_beyond_m = 3716.6
if (!exists("glide_slope_beyond_m")) glide_slope_beyond_m = 239.0
if (!exists("glide_path_deg")) glide_path_deg = 3.0
aircraft = outdir.'/fedsim_aircraft_state.csv'
navigation = outdir.'/fedsim_navigation_state.csv'
autopilot = outdir.'/fedsim_autopilot_state.csv'
set terminal pngcairo size 1600,1400 font 'sans,10' noenhanced
set output outfile
set datafile separator ','
set datafile columnheaders
set grid
ft = 1 / 0.3048
kt = 3600.0 / 1852.0
nm = 1 / 1852.0
deg = 180.0 / pi
R = 6371008.8   # mean earth radius [m]: a plotting approximation (the models use WGS-84)
h = runway_heading_deg / deg
east(lon) = (lon * deg - lon0) / deg * cos(lat0 / deg) * R
north(lat) = (lat * deg - lat0) / deg * R
before_threshold(lat, lon) = -(east(lon) * sin(h) + north(lat) * cos(h))
left_of_centreline(lat, lon) = -east(lon) * cos(h) + north(lat) * sin(h)
set multiplot layout 3,2 title title

set title 'plan view: the track against the runway centreline'
set xlabel 'distance before the threshold (NM)'
set ylabel 'left of the centreline (m)'
set xrange [*:*] reverse
set key top right
localizer_limit(x_nm) = 106.68 * (x_nm / nm + localizer_beyond_m) / localizer_beyond_m
plot aircraft using (before_threshold(column('latitude_rad'), column('longitude_rad')) * nm):\
                    (left_of_centreline(column('latitude_rad'), column('longitude_rad'))) \
       with lines lw 2 lc rgb '#1f77b4' title 'aircraft (CG)', \
     0 with lines dt 2 lc rgb '#444444' title 'extended centreline', \
     (x > 0 ? localizer_limit(x) : 1/0) with lines lw 1 lc rgb '#999999' title 'localizer full scale', \
     (x > 0 ? -localizer_limit(x) : 1/0) with lines lw 1 lc rgb '#999999' notitle

set title 'vertical profile'
set ylabel 'height above the runway (ft)'
path_ft(x_nm, angle_deg) = (x_nm / nm + glide_slope_beyond_m) * tan(angle_deg / deg) * ft
plot aircraft using (before_threshold(column('latitude_rad'), column('longitude_rad')) * nm):(column('height_agl_m') * ft) \
       with lines lw 2 lc rgb '#1f77b4' title 'aircraft (CG)', \
     (x > -glide_slope_beyond_m * nm ? path_ft(x, glide_path_deg) : 1/0) with lines dt 2 lc rgb '#444444' \
       title sprintf('glide path %.2f deg from the GS antenna', glide_path_deg), \
     (x > -glide_slope_beyond_m * nm ? path_ft(x, 1.24 * glide_path_deg) : 1/0) with lines lw 1 lc rgb '#999999' \
       title 'glide slope full scale (0.24 of the angle)', \
     (x > -glide_slope_beyond_m * nm ? path_ft(x, 0.76 * glide_path_deg) : 1/0) with lines lw 1 lc rgb '#999999' notitle
set xrange [*:*] noreverse

set title 'ILS deviations NAV1 read (full scale = 1; a flagged reading is not drawn)'
set xlabel 'simulation time (s)'
set ylabel 'deviation (full scale)'
set yrange [-1.1:1.1]
shown(s, v) = (column(s) == 0 ? v : 1/0)
plot navigation using 'sim_time_s':(shown('nav[0].status', column('nav[0].course_deviation'))) \
       with lines lw 2 lc rgb '#1f77b4' title 'localizer (+ fly right)', \
     navigation using 'sim_time_s':(shown('nav[0].glideslope_status', column('nav[0].glideslope_deviation'))) \
       with lines lw 2 lc rgb '#d62728' title 'glide slope (+ fly up)'
set autoscale y

set title 'speed and thrust'
set ylabel 'airspeed (kt)'
set y2label 'throttle (0..1)'
set y2tics
set y2range [0:1]
plot aircraft using 'sim_time_s':(column('air.cas_mps') * kt) with lines lw 2 lc rgb '#d62728' title 'CAS', \
     aircraft using 'sim_time_s':(column('ground_speed_mps') * kt) with lines lw 1 lc rgb '#ff9896' title 'ground speed', \
     aircraft using 'sim_time_s':'controls.throttle[0]' axes x1y2 with lines lw 1 lc rgb '#2ca02c' title 'throttle 1'
unset y2tics
unset y2label

set title 'attitude and vertical speed'
set ylabel 'pitch, roll (deg)'
set y2label 'vertical speed (ft/s, + up)'
set y2tics
set y2range [-20:10]
plot aircraft using 'sim_time_s':(column('theta_rad') * deg) with lines lw 2 lc rgb '#2ca02c' title 'pitch', \
     aircraft using 'sim_time_s':(column('phi_rad') * deg) with lines lw 1 lc rgb '#9467bd' title 'roll', \
     aircraft using 'sim_time_s':(column('climb_rate_mps') * ft) axes x1y2 with lines lw 1 lc rgb '#1f77b4' title 'vertical speed'
unset y2tics
unset y2label

set title 'autopilot modes (FMA, fedsim/autopilot_state)'
set ylabel ''
set yrange [-0.5:20.5]
set ytics ('roll: -' 0, 'CWS R' 1, 'WLV' 2, 'HDG HOLD' 3, 'HDG SEL' 4, 'VOR/LOC' 5, 'ALIGN' 6, 'ROLLOUT' 7, 'TOGA' 8, \
           'pitch: -' 11, 'CWS P' 12, 'ALT HOLD' 13, 'ALT ACQ' 14, 'V/S' 15, 'MCP SPD' 16, 'G/S' 17, 'FLARE' 18, 'ROLLOUT' 19, 'TOGA' 20)
plot autopilot using 'sim_time_s':'fma.roll' with steps lw 2 lc rgb '#1f77b4' title 'roll mode', \
     autopilot using 'sim_time_s':(column('fma.pitch') + 11) with steps lw 2 lc rgb '#d62728' title 'pitch mode', \
     autopilot using 'sim_time_s':(column('fma.thrust') == 5 ? 10 : 1/0) with points pt 7 ps 0.4 lc rgb '#2ca02c' title 'A/T RETARD'
unset multiplot
