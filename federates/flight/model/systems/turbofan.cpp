// Turbofan engine: thrust from idle and maximum thrust tables of Mach and altitude, spool
// dynamics for N1 and N2, fuel flow from TSFC.
#include "flight/model/systems/turbofan.hpp"
#include "common/units/units.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "flight/model/systems/param_checks.hpp"

namespace fedsim::flight {

namespace {
// US Standard Atmosphere 1976, layers 0 and 1.
constexpr double kSeaLevelTemperatureK = 288.15;
constexpr double kSeaLevelDensityKgpm3 = 1.225;
constexpr double kLapseRateKpm = 0.0065;
constexpr double kTropopauseM = 11000.0;
constexpr double kGasConstant = 287.05287;  // J/(kg K), dry air
constexpr double kTropopauseTemperatureK = kSeaLevelTemperatureK - kLapseRateKpm * kTropopauseM;
// Density ratio exponent in the troposphere: g / (L R) - 1.
constexpr double kTroposphereDensityExponent = units::kStandardGravityMps2 / (kLapseRateKpm * kGasConstant) - 1.0;

double tropopause_density_kgpm3() {
  return kSeaLevelDensityKgpm3 *
         std::pow(kTropopauseTemperatureK / kSeaLevelTemperatureK, kTroposphereDensityExponent);
}

// Exact first-order lag step toward target with separate up / down time constants.
double spool(double value, double target, double up_s, double down_s, double dt_s) {
  const double tau = target > value ? up_s : down_s;
  return value + (target - value) * -std::expm1(-dt_s / tau);
}
}  // namespace

void Turbofan::Params::validate() const {
  namespace pc = param_checks;
  pc::positive(max_thrust_n, "max_thrust_n");
  pc::not_empty(idle_thrust_fraction, "idle_thrust_fraction");
  pc::not_empty(max_thrust_fraction, "max_thrust_fraction");
  pc::positive(idle_n1_pct, "idle_n1_pct");
  if (!(max_n1_pct > idle_n1_pct)) pc::fail("max_n1_pct", "must exceed idle_n1_pct", max_n1_pct);
  pc::finite(max_n1_pct, "max_n1_pct");
  pc::positive(idle_n2_pct, "idle_n2_pct");
  if (!(max_n2_pct > idle_n2_pct)) pc::fail("max_n2_pct", "must exceed idle_n2_pct", max_n2_pct);
  pc::finite(max_n2_pct, "max_n2_pct");
  pc::positive(n1_spool_up_time_constant_s, "n1_spool_up_time_constant_s");
  pc::positive(n1_spool_down_time_constant_s, "n1_spool_down_time_constant_s");
  pc::positive(n2_spool_up_time_constant_s, "n2_spool_up_time_constant_s");
  pc::positive(n2_spool_down_time_constant_s, "n2_spool_down_time_constant_s");
  pc::positive(tsfc_kgpns, "tsfc_kgpns");
  pc::non_negative(tsfc_per_mach, "tsfc_per_mach");
  pc::non_negative(min_fuel_flow_kgps, "min_fuel_flow_kgps");
  pc::positive(idle_egt_rise_k, "idle_egt_rise_k");
  pc::finite(max_egt_rise_k, "max_egt_rise_k");
  if (!(max_egt_rise_k >= idle_egt_rise_k)) {
    pc::fail("max_egt_rise_k", "must be at least idle_egt_rise_k", max_egt_rise_k);
  }
  thrust_line.validate("thrust_line.");
}

Turbofan::Turbofan(Params params)
    : params_((params.validate(), std::move(params))), axis_b_(params_.thrust_line.axis_body()) {
  reset();
}

double Turbofan::density_altitude_m(double density_kgpm3) {
  const double rho = std::max(density_kgpm3, 1e-6);
  const double rho_11 = tropopause_density_kgpm3();
  if (rho >= rho_11) {
    const double sigma = rho / kSeaLevelDensityKgpm3;
    return kSeaLevelTemperatureK / kLapseRateKpm *
           (1.0 - std::pow(sigma, 1.0 / kTroposphereDensityExponent));
  }
  // Isothermal layer: rho = rho_11 exp(-g (h - 11 km) / (R T_11)).
  return kTropopauseM + kGasConstant * kTropopauseTemperatureK / units::kStandardGravityMps2 * std::log(rho_11 / rho);
}

void Turbofan::reset(bool running) {
  n1_pct_ = running ? params_.idle_n1_pct : 0.0;
  n2_pct_ = running ? params_.idle_n2_pct : 0.0;
  Inputs still;
  still.running = running;
  fill_outputs(still);
}

double Turbofan::thrust_n(const Inputs& in, double altitude_m) const {
  const Params& p = params_;
  const double mach = std::isnan(in.mach) ? 0.0 : std::max(in.mach, 0.0);
  const double idle = p.idle_thrust_fraction(mach, altitude_m);
  if (n1_pct_ < p.idle_n1_pct) {
    const double r = n1_pct_ / p.idle_n1_pct;
    return p.max_thrust_n * idle * r * r;
  }
  const double maximum = p.max_thrust_fraction(mach, altitude_m);
  const double n = std::min((n1_pct_ - p.idle_n1_pct) / (p.max_n1_pct - p.idle_n1_pct), 1.0);
  return p.max_thrust_n * (idle + (maximum - idle) * n * n);
}

void Turbofan::step(double dt_s, const Inputs& in) {
  if (!(dt_s > 0.0)) return;
  const Params& p = params_;
  const bool burning = in.running && !in.failed;
  const double tl = std::isnan(in.throttle) ? 0.0 : std::clamp(in.throttle, 0.0, 1.0);
  const double n1_cmd = burning ? p.idle_n1_pct + tl * (p.max_n1_pct - p.idle_n1_pct) : 0.0;
  const double n2_cmd = burning ? p.idle_n2_pct + tl * (p.max_n2_pct - p.idle_n2_pct) : 0.0;
  n1_pct_ =
      spool(n1_pct_, n1_cmd, p.n1_spool_up_time_constant_s, p.n1_spool_down_time_constant_s, dt_s);
  n2_pct_ =
      spool(n2_pct_, n2_cmd, p.n2_spool_up_time_constant_s, p.n2_spool_down_time_constant_s, dt_s);
  fill_outputs(in);
}

void Turbofan::fill_outputs(const Inputs& in) {
  const Params& p = params_;
  Outputs& out = outputs_;
  out.density_altitude_m = density_altitude_m(in.density_kgpm3);
  out.thrust_n = thrust_n(in, out.density_altitude_m);
  out.force_body_n = out.thrust_n * axis_b_;
  out.moment_datum_body_nm = p.thrust_line.position_m.cross(out.force_body_n);
  out.n1_pct = n1_pct_;
  out.n2_pct = n2_pct_;
  const bool burning = in.running && !in.failed;
  const double mach = std::isnan(in.mach) ? 0.0 : std::max(in.mach, 0.0);
  const double theta = std::max(in.temperature_k, 1.0) / kSeaLevelTemperatureK;
  const double tsfc = p.tsfc_kgpns * (1.0 + p.tsfc_per_mach * mach) * std::sqrt(theta);
  out.fuel_flow_kgps =
      burning ? std::max(tsfc * std::max(out.thrust_n, 0.0), p.min_fuel_flow_kgps) : 0.0;
  const double ambient_k = std::max(in.temperature_k, 1.0);
  const double n2 = std::clamp((n2_pct_ - p.idle_n2_pct) / (p.max_n2_pct - p.idle_n2_pct), 0.0, 1.0);
  out.exhaust_gas_temperature_k =
      burning ? ambient_k + p.idle_egt_rise_k + (p.max_egt_rise_k - p.idle_egt_rise_k) * n2
              : ambient_k;
}

}  // namespace fedsim::flight
