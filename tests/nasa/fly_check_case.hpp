// The NASA TM-2015-218675 atmospheric check cases flown through the batch program fedsim-fly
// (aircraft pack + initial-condition file, rotating WGS-84 earth) and read back as SI channels.
#pragma once

#include <string>
#include <vector>

#include "time_history.hpp"

namespace fedsim::flight::nasa {

struct FlyCheckCase {
  std::string id;  // "Atmos_01": the folder of its reference data and of its ic.yaml
  std::string title;
  std::string pack;  // data/aircraft/<pack>.yaml
};

/// Cases 1, 2, 3, 6, 7, 9 and 10 with the packs that model their bodies.
std::vector<FlyCheckCase> fly_check_cases();

/// Runs `fedsim-fly --aircraft <pack> --ic tests/data/nasa/<id>/ic.yaml --earth wgs84
/// --aero-rates inertial --integrator rk4 --rate 100 --duration 30` (writing into work_dir) and
/// converts its CSV into the channels of nasa_channels.hpp (plus lat_rad, lon_rad). Throws
/// std::runtime_error with the program's output if it fails.
TimeHistory fly_case(const FlyCheckCase& check_case, const std::string& work_dir);

/// The channels of nasa_channels.hpp from a fedsim-fly CSV.
TimeHistory nasa_channels_from_fly_csv(const std::string& csv_path);

}  // namespace fedsim::flight::nasa
