#include "flight/model/aircraft/stall_warning.hpp"

#include "flight/model/aircraft/aerodynamics.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace fedsim::flight {

StallAngles stall_angles(const AircraftPack& pack, double flap_norm, double speed_margin) {
  if (!(flap_norm >= 0.0 && flap_norm <= 1.0)) throw std::invalid_argument("stall_angles: flap_norm must lie in [0, 1]");
  if (!(speed_margin >= 1.0 && speed_margin <= 2.0)) {
    throw std::invalid_argument("stall_angles: speed_margin must lie in [1, 2]");
  }
  const Aerodynamics aero(pack);
  Aerodynamics::Inputs in;
  in.tas_mps = 60.0;
  in.mach = 0.2;
  in.qbar_pa = 2000.0;
  in.flap_norm = flap_norm;
  in.gear_norm = 1.0;
  const double alpha_end = std::min(0.6, aero.envelope().alpha_max_rad());
  constexpr double kStep = 0.001;
  std::vector<double> cl;
  double best = -1e9, best_alpha = 0.0;
  for (double alpha = 0.0; alpha <= alpha_end + 1e-12; alpha += kStep) {
    in.alpha_rad = alpha;
    const double c = aero.compute(in, false).CL;
    cl.push_back(c);
    if (c > best) {
      best = c;
      best_alpha = alpha;
    } else if (c < best - 1e-9) {
      break;  // past the first maximum
    }
  }
  if (cl.size() < 2 || !(best > cl.front())) {
    throw std::invalid_argument("stall_angles: the lift of pack '" + pack.metadata.name +
                                "' does not rise with the angle of attack: no stall to warn of");
  }
  StallAngles s;
  s.flap_norm = flap_norm;
  s.alpha_cl_max_rad = best_alpha;
  s.cl_max = best;
  const double warning_cl = best / (speed_margin * speed_margin);
  for (std::size_t i = 0; i < cl.size(); ++i) {
    if (cl[i] >= warning_cl) {
      s.alpha_warning_rad = static_cast<double>(i) * kStep;
      break;
    }
  }
  return s;
}

}  // namespace fedsim::flight
