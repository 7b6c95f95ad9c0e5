// One PNG per check case: fedsim against every NASA tool for the key channels (gnuplot).
#pragma once

#include <string>

#include "nasa_reference.hpp"
#include "time_history.hpp"

namespace fedsim::flight::nasa {

/// True when a gnuplot executable is on the PATH.
bool gnuplot_available();

/// Writes <output_dir>/<case_id>.png (and the .dat/.gp files it is drawn from): a top row with
/// fedsim's altitude, NED velocity, Euler angles and body rates, then one panel per compared
/// channel showing each NASA tool minus fedsim (angles in degrees). Returns false, having
/// written only the data and script, if gnuplot is missing or fails.
bool plot_comparison(const std::string& case_id, const std::string& title,
                     const TimeHistory& fedsim, const NasaReference& reference,
                     const std::string& output_dir);

}  // namespace fedsim::flight::nasa
