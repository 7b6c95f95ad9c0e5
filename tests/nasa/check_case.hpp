// The NASA TM-2015-218675 atmospheric check cases simulated with fedsim's rigid-body library:
// case definitions (from the report, checked against NASA's own time histories) and a runner.
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

#include "flight/model/dynamics/rigid_body.hpp"
#include "time_history.hpp"

namespace fedsim::flight::nasa {

enum class CheckBody {
  kSphere,  // 1 slug, 0.5 ft diameter, I = 3.6 slug ft^2 about every axis
  kBrick,   // 8 x 4 x 2.25 in face brick, 0.155404754 slug
};

struct CheckCase {
  std::string id;     // "Atmos_01": also the folder of its reference data
  std::string title;
  CheckBody body = CheckBody::kSphere;
  double drag_coefficient = 0.0;          // sphere: CD on the cross-section area
  bool brick_damping = false;             // brick: Clp = Cmq = Cnr = -1
  Eigen::Vector3d wind_ned_mps = Eigen::Vector3d::Zero();  // steady wind (air velocity)
  InitialConditions initial;
  double duration_s = 30.0;
};

/// Cases 1, 2, 3, 6, 7, 9 and 10 (case 8, the wind shear, needs the weather models).
std::vector<CheckCase> atmospheric_check_cases();

MassProperties mass_properties_of(CheckBody body);

/// Runs a case on the rotating WGS-84 earth with US 1976 air and records the channels of
/// nasa_channels.hpp (plus lat_rad, lon_rad) every output period.
TimeHistory simulate(const CheckCase& check_case, IntegrationMethod method, double step_s,
                     double output_period_s);

}  // namespace fedsim::flight::nasa
