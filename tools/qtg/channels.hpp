// The channels a QTG test compares: named quantities with their unit in the name (tas_kt,
// pitch_deg, ...), derived from the aircraft-state CSV that fedsim-fly records (and, for a
// federation test, the navigation and autopilot state and the runway), and read from a
// reference CSV whose headers use the same names (time_s first).
#pragma once

#include <optional>
#include <set>
#include <string>
#include <vector>
#include <map>

#include "tools/qtg/qtg_test.hpp"

namespace fedsim::qtg {

/// A sampled signal: times (s, non-decreasing) and values.
struct Series {
  std::vector<double> t, x;
  bool empty() const { return t.empty(); }
};

/// Channel name -> series.
using Channels = std::map<std::string, Series>;

/// Where a channel comes from: a recorded topic's CSV, or the aircraft state measured from the
/// test's runway.
enum class ChannelSource { aircraft_state, navigation_state, autopilot_state, runway };

struct ChannelInfo {
  std::string name;
  std::string meaning;
  ChannelSource source = ChannelSource::aircraft_state;
};

/// Every channel a test may name, in report order.
const std::vector<ChannelInfo>& known_channels();
bool is_known_channel(const std::string& name);
/// The unit in a channel's name: the suffix after the last '_' when it is a unit fedsim uses
/// (kt, ft, deg, dps, fpm, g, s, m, lbf, n, dots, fps), otherwise "1" (normalised or
/// dimensionless).
std::string channel_unit(const std::string& name);

/// The source of a known channel (aircraft_state for an unknown name).
ChannelSource channel_source(const std::string& name);
/// The recording's file of a source: fedsim_aircraft_state.csv, fedsim_navigation_state.csv,
/// fedsim_autopilot_state.csv (the runway channels read the aircraft state).
std::string source_file(ChannelSource source);

/// Reads fedsim-fly's fedsim_aircraft_state.csv into every aircraft-state channel; throws
/// csv::CsvError.
Channels channels_from_state_csv(const std::string& path);

/// Reads a recording folder (fedsim-fly's, or a `fedsim record` member's of a `fedsim run`):
/// the aircraft state always, the navigation and autopilot state when `sources` has them, the
/// runway channels when it has `runway` (then `runway` must be given; they are measured from
/// its fedsim::RunwayCentreline, as fedsim-autoland-mc measures them). Throws
/// std::runtime_error naming the file that is missing or bad, or std::invalid_argument naming
/// the runway (or its opposite end) not in the table.
/// `files`, when given, receives each file read with its sample times (to check the recording
/// covers the run).
struct RecordedFile {
  std::string path;
  std::vector<double> t;
};
Channels channels_from_recording(const std::string& dir, const std::set<ChannelSource>& sources,
                                 const std::optional<RunwaySpec>& runway,
                                 std::vector<RecordedFile>* files = nullptr);

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
