// gnuplot comparison plots of fedsim against the NASA check-case tools.
#include "comparison_plot.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "common/math/rotation.hpp"
#include "nasa_channels.hpp"

namespace fedsim::flight::nasa {

namespace {
constexpr double kDegPerRad = 57.29577951308232;

bool in_degrees(const std::string& name) { return name.ends_with("_rad") || name.ends_with("_rps"); }

std::string axis_label(const std::string& name) {
  if (name.ends_with("_rps")) return name.substr(0, name.size() - 4) + " (deg/s)";
  if (name.ends_with("_rad")) return name.substr(0, name.size() - 4) + " (deg)";
  if (name.ends_with("_mps")) return name.substr(0, name.size() - 4) + " (m/s)";
  return name.substr(0, name.size() - 2) + " (m)";
}

// fedsim's own values: time then every channel (angles in degrees).
void write_values(const std::string& path, const TimeHistory& fedsim) {
  std::ofstream out(path);
  out.precision(12);
  for (std::size_t k = 0; k < fedsim.times().size(); ++k) {
    out << fedsim.times()[k];
    for (const Channel& c : kChannels) {
      const std::string name(c.name);
      const double v = fedsim.has(name) ? fedsim.channel(name)[k] : NAN;
      out << ' ' << (in_degrees(name) ? v * kDegPerRad : v);
    }
    out << '\n';
  }
}

// One NASA run minus fedsim at the run's sample times (NaN where the run lacks the channel).
void write_differences(const std::string& path, const TimeHistory& run, const TimeHistory& fedsim) {
  std::ofstream out(path);
  out.precision(12);
  for (double t : run.times()) {
    if (t > fedsim.times().back() + 1e-9) break;
    out << t;
    for (const Channel& c : kChannels) {
      const std::string name(c.name);
      double d = NAN;
      if (run.has(name) && fedsim.has(name)) {
        d = c.is_angle ? wrap_pi(run.angle_at(name, t) - fedsim.angle_at(name, t))
                       : run.at(name, t) - fedsim.at(name, t);
      }
      out << ' ' << (in_degrees(name) ? d * kDegPerRad : d);
    }
    out << '\n';
  }
}

// Top row: the trajectory itself (fedsim only; NASA runs overlay it to within a line width).
void write_value_panels(std::ofstream& gp, const std::string& values) {
  gp << "set ylabel 'altitude (m)'\nplot '" << values << "' using 1:2 with lines lw 2 lc rgb 'black' title 'fedsim'\n"
     << "set ylabel 'velocity NED (m/s)'\nplot '" << values << "' using 1:5 with lines lw 2 title 'v_north', '"
     << values << "' using 1:6 with lines lw 2 title 'v_east', '" << values
     << "' using 1:7 with lines lw 2 title 'v_down'\n"
     << "set ylabel 'Euler angles (deg)'\nplot '" << values << "' using 1:8 with lines lw 2 title 'phi', '"
     << values << "' using 1:9 with lines lw 2 title 'theta', '" << values
     << "' using 1:10 with lines lw 2 title 'psi'\n"
     << "set ylabel 'body rates wrt inertial (deg/s)'\nplot '" << values
     << "' using 1:11 with lines lw 2 title 'p', '" << values << "' using 1:12 with lines lw 2 title 'q', '"
     << values << "' using 1:13 with lines lw 2 title 'r'\n";
}
}  // namespace

bool gnuplot_available() { return std::system("command -v gnuplot > /dev/null 2>&1") == 0; }

bool plot_comparison(const std::string& case_id, const std::string& title,
                     const TimeHistory& fedsim, const NasaReference& reference,
                     const std::string& output_dir) {
  std::filesystem::create_directories(output_dir);
  const std::string stem = output_dir + "/" + case_id;
  write_values(stem + "_fedsim.dat", fedsim);
  for (const NasaRun& run : reference.runs()) {
    write_differences(stem + "_" + run.name + "_minus_fedsim.dat", run.history, fedsim);
  }
  std::ofstream gp(stem + ".gp");
  gp << "set terminal pngcairo size 2000,1600 font 'sans,10' noenhanced\n"
     << "set output '" << stem << ".png'\n"
     << "set multiplot layout 4,4 title '" << case_id << ": " << title
     << ". Top row: fedsim trajectory. Other rows: each NASA TM-2015-218675 tool minus fedsim.'\n"
     << "set grid\nset key top left font 'sans,8'\nset xlabel 'time (s)'\n";
  write_value_panels(gp, stem + "_fedsim.dat");
  int column = 2;
  for (const Channel& c : kChannels) {
    gp << "set ylabel 'NASA - fedsim: " << axis_label(std::string(c.name)) << "'\nplot ";
    bool first = true;
    for (const NasaRun& run : reference.runs()) {
      if (!run.history.has(std::string(c.name))) continue;
      gp << (first ? "" : ", ") << "'" << stem << "_" << run.name << "_minus_fedsim.dat' using 1:"
         << column << " with linespoints lw 2 ps 0.5 title '" << run.name << "'";
      first = false;
    }
    if (first) gp << "NaN notitle";
    gp << '\n';
    ++column;
  }
  gp << "unset multiplot\n";
  gp.close();
  if (!gnuplot_available()) return false;
  const std::string command = "gnuplot '" + stem + ".gp' > '" + stem + ".log' 2>&1";
  return std::system(command.c_str()) == 0 && std::filesystem::exists(stem + ".png");
}

}  // namespace fedsim::flight::nasa
