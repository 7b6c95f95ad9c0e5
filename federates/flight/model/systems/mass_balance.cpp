// Mass, centre of gravity and inertia of the aircraft from its empty mass, point masses and
// fuel tanks, with fuel drawn from the tanks by the engines.
#include "flight/model/systems/mass_balance.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "flight/model/systems/param_checks.hpp"

namespace fedsim::flight {

namespace {
// Fuel below this is treated as none (avoids endless splitting of rounding residue).
constexpr double kEmptyTankKg = 1e-9;

// Inertia of a point mass about a point at offset r from it: m (|r|^2 E - r r^T).
Eigen::Matrix3d point_inertia(double mass_kg, const Eigen::Vector3d& r) {
  return mass_kg * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
}

std::string indexed(const std::string& list, std::size_t i, const std::string& field) {
  return list + "[" + std::to_string(i) + "]." + field;
}
}  // namespace

void MassBalance::Params::validate() const {
  namespace pc = param_checks;
  pc::positive(empty_mass_kg, "empty_mass_kg");
  pc::finite(empty_cg_m, "empty_cg_m");
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) pc::finite(empty_inertia_kgm2(i, j), "empty_inertia_kgm2");
  }
  if (!empty_inertia_kgm2.isApprox(empty_inertia_kgm2.transpose(), 1e-9)) {
    throw std::invalid_argument("empty_inertia_kgm2 must be symmetric");
  }
  if (empty_inertia_kgm2.selfadjointView<Eigen::Lower>().eigenvalues().minCoeff() <= 0.0) {
    throw std::invalid_argument("empty_inertia_kgm2 must be positive definite");
  }
  for (std::size_t i = 0; i < point_masses.size(); ++i) {
    pc::non_negative(point_masses[i].mass_kg, indexed("point_masses", i, "mass_kg"));
    pc::finite(point_masses[i].position_m, indexed("point_masses", i, "position_m"));
  }
  for (std::size_t i = 0; i < tanks.size(); ++i) {
    pc::non_negative(tanks[i].capacity_kg, indexed("tanks", i, "capacity_kg"));
    pc::in_range(tanks[i].initial_contents_kg, 0.0, tanks[i].capacity_kg,
                 indexed("tanks", i, "initial_contents_kg"));
    pc::finite(tanks[i].position_m, indexed("tanks", i, "position_m"));
  }
  for (std::size_t e = 0; e < engine_feeds.size(); ++e) {
    if (engine_feeds[e].empty()) {
      throw std::invalid_argument("engine_feeds[" + std::to_string(e) + "] lists no tank");
    }
    for (std::size_t t : engine_feeds[e]) {
      if (t >= tanks.size()) {
        throw std::invalid_argument("engine_feeds[" + std::to_string(e) + "] names tank " +
                                    std::to_string(t) + ", but there are only " +
                                    std::to_string(tanks.size()) + " tanks");
      }
    }
  }
}

MassBalance::MassBalance(Params params) : params_((params.validate(), std::move(params))) {
  point_mass_kg_.resize(params_.point_masses.size());
  outputs_.tank_contents_kg.resize(params_.tanks.size());
  outputs_.engine_starved.resize(params_.engine_feeds.size());
  reset();
}

void MassBalance::reset() {
  for (std::size_t i = 0; i < params_.point_masses.size(); ++i) {
    point_mass_kg_[i] = params_.point_masses[i].mass_kg;
  }
  for (std::size_t t = 0; t < params_.tanks.size(); ++t) {
    outputs_.tank_contents_kg[t] = params_.tanks[t].initial_contents_kg;
  }
  for (std::size_t e = 0; e < params_.engine_feeds.size(); ++e) {
    outputs_.engine_starved[e] = feeds_empty(e);
  }
  update_mass_properties();
}

void MassBalance::set_tank_contents_kg(std::size_t tank, double contents_kg) {
  if (tank >= params_.tanks.size()) throw std::out_of_range("no fuel tank " + std::to_string(tank));
  const double c = std::isnan(contents_kg) ? 0.0 : contents_kg;
  outputs_.tank_contents_kg[tank] = std::clamp(c, 0.0, params_.tanks[tank].capacity_kg);
  for (std::size_t e = 0; e < params_.engine_feeds.size(); ++e) {
    outputs_.engine_starved[e] = feeds_empty(e);
  }
  update_mass_properties();
}

void MassBalance::set_point_mass_kg(std::size_t index, double mass_kg) {
  if (index >= point_mass_kg_.size())
    throw std::out_of_range("no point mass " + std::to_string(index));
  param_checks::non_negative(mass_kg, indexed("point_masses", index, "mass_kg"));
  point_mass_kg_[index] = mass_kg;
  update_mass_properties();
}

bool MassBalance::feeds_empty(std::size_t engine) const {
  const std::vector<std::size_t>& feeds = params_.engine_feeds[engine];
  return std::none_of(feeds.begin(), feeds.end(),
                      [&](std::size_t t) { return outputs_.tank_contents_kg[t] > kEmptyTankKg; });
}

double MassBalance::draw_fuel(std::size_t engine, double demand_kg) {
  const std::vector<std::size_t>& feeds = params_.engine_feeds[engine];
  std::vector<double>& contents = outputs_.tank_contents_kg;
  // Each pass shares the remaining demand among the tanks that still have fuel; a tank that
  // cannot cover its share empties and the rest is shared again. At most one pass per tank.
  for (std::size_t pass = 0; pass < feeds.size() && demand_kg > kEmptyTankKg; ++pass) {
    const auto with_fuel = std::count_if(feeds.begin(), feeds.end(),
                                         [&](std::size_t t) { return contents[t] > kEmptyTankKg; });
    if (with_fuel == 0) break;
    const double share_kg = demand_kg / static_cast<double>(with_fuel);
    for (std::size_t t : feeds) {
      if (contents[t] <= kEmptyTankKg) continue;
      const double taken_kg = std::min(share_kg, contents[t]);
      contents[t] -= taken_kg;
      demand_kg -= taken_kg;
    }
  }
  return std::max(demand_kg, 0.0);
}

void MassBalance::step(double dt_s, const Inputs& in) {
  if (in.engine_fuel_flow_kgps.size() != params_.engine_feeds.size()) {
    throw std::invalid_argument(
        "MassBalance::step: " + std::to_string(in.engine_fuel_flow_kgps.size()) +
        " fuel flows for " + std::to_string(params_.engine_feeds.size()) + " engines");
  }
  if (!(dt_s > 0.0)) return;
  for (std::size_t e = 0; e < params_.engine_feeds.size(); ++e) {
    const double flow = in.engine_fuel_flow_kgps[e];
    const double demand_kg = (std::isfinite(flow) && flow > 0.0) ? flow * dt_s : 0.0;
    const double unmet_kg = draw_fuel(e, demand_kg);
    outputs_.engine_starved[e] = unmet_kg > kEmptyTankKg || feeds_empty(e);
  }
  update_mass_properties();
}

void MassBalance::update_mass_properties() {
  Outputs& out = outputs_;
  double mass = params_.empty_mass_kg;
  Eigen::Vector3d moment = params_.empty_mass_kg * params_.empty_cg_m;
  out.fuel_kg = 0.0;
  for (std::size_t i = 0; i < point_mass_kg_.size(); ++i) {
    mass += point_mass_kg_[i];
    moment += point_mass_kg_[i] * params_.point_masses[i].position_m;
  }
  for (std::size_t t = 0; t < params_.tanks.size(); ++t) {
    mass += out.tank_contents_kg[t];
    moment += out.tank_contents_kg[t] * params_.tanks[t].position_m;
    out.fuel_kg += out.tank_contents_kg[t];
  }
  out.mass_kg = mass;
  out.cg_m = moment / mass;

  // Parallel-axis theorem about the new CG.
  Eigen::Matrix3d inertia = params_.empty_inertia_kgm2 +
                            point_inertia(params_.empty_mass_kg, params_.empty_cg_m - out.cg_m);
  for (std::size_t i = 0; i < point_mass_kg_.size(); ++i) {
    inertia += point_inertia(point_mass_kg_[i], params_.point_masses[i].position_m - out.cg_m);
  }
  for (std::size_t t = 0; t < params_.tanks.size(); ++t) {
    inertia += point_inertia(out.tank_contents_kg[t], params_.tanks[t].position_m - out.cg_m);
  }
  out.inertia_kgm2 = inertia;
}

}  // namespace fedsim::flight
