// The channels a QTG test compares: named quantities with their unit in the name (tas_kt,
// pitch_deg, ...), derived from the aircraft-state CSV that fedsim-fly records, and read from a
// reference CSV whose headers use the same names (time_s first).
#pragma once

#include <string>
#include <vector>
#include <map>

namespace fedsim::qtg {

/// A sampled signal: times (s, non-decreasing) and values.
struct Series {
  std::vector<double> t, x;
  bool empty() const { return t.empty(); }
};

/// Channel name -> series.
using Channels = std::map<std::string, Series>;

struct ChannelInfo {
  std::string name;
  std::string meaning;
};

/// Every channel a test may name, in report order.
const std::vector<ChannelInfo>& known_channels();
bool is_known_channel(const std::string& name);
/// The unit in a channel's name: the suffix after the last '_' when it is a unit fedsim uses
/// (kt, ft, deg, dps, fpm, g, s, m, lbf, n), otherwise "1" (normalised or dimensionless).
std::string channel_unit(const std::string& name);

/// Reads fedsim-fly's fedsim_aircraft_state.csv into every known channel; throws csv::CsvError.
Channels channels_from_state_csv(const std::string& path);

/// One column of a reference CSV against its time_s column (units in the headers: a column must
/// be a known channel name). Throws csv::CsvError "file:line: column 'x': problem".
Series read_reference_column(const std::string& path, const std::string& column);

/// Linear interpolation, held constant beyond the ends. The series must not be empty.
double interpolate(const Series& s, double t);

/// Writes channels (time_s first) to a CSV, every `every`-th sample (regression references).
void write_reference_csv(const std::string& path, const Channels& channels,
                         const std::vector<std::string>& names, const std::string& comment,
                         int every);

}  // namespace fedsim::qtg
