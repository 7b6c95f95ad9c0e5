// Identification of a fixed-pitch propeller's CT and CP factors (constant, or faded out over an
// advance-ratio band) from the static full-throttle rpm and the take-off ground roll.
#include "flight/model/scenario/propeller_calibration.hpp"

#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "flight/model/systems/propeller.hpp"

namespace fedsim::flight {

namespace {

// A sea-level runway (the position does not matter on the flat earth; ISA, no wind: the
// model's default weather).
const Runway kSeaLevelRunway{{0.0, 0.0, 0.0}, 0.0};

void require(bool ok, const std::string& field, const std::string& rule, double value) {
  if (!ok) {
    std::ostringstream m;
    m << field << " " << rule << " (got " << value << ")";
    throw std::invalid_argument(m.str());
  }
}

/// The x in [low, high] where the decreasing function f crosses `target` (bisection). Throws
/// naming `what` when f(low) and f(high) do not bracket the target.
double bisect_decreasing(const std::function<double(double)>& f, double target, double low,
                         double high, double tolerance, const std::string& what) {
  const double at_low = f(low);
  const double at_high = f(high);
  if (!(at_low >= target && at_high <= target)) {
    std::ostringstream m;
    m << what << ": the target " << target << " is not reached with factors in [" << low << ", "
      << high << "] (they give " << at_low << " .. " << at_high << ")";
    throw std::invalid_argument(m.str());
  }
  while (high - low > tolerance) {
    const double mid = 0.5 * (low + high);
    (f(mid) > target ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

}  // namespace

void TakeoffTechnique::validate() const {
  require(flaps_norm >= 0.0 && flaps_norm <= 1.0, "flaps_norm", "must lie in [0, 1]", flaps_norm);
  require(rotate_cas_mps > 0.0 && std::isfinite(rotate_cas_mps), "rotate_cas_mps",
          "must be positive and finite", rotate_cas_mps);
  require(rotation_elevator >= -1.0 && rotation_elevator <= 1.0, "rotation_elevator",
          "must lie in [-1, 1]", rotation_elevator);
  require(frame_rate_hz >= 10.0 && frame_rate_hz <= 10000.0, "frame_rate_hz",
          "must lie in [10, 10000]", frame_rate_hz);
  require(time_limit_s > 0.0 && time_limit_s <= 3600.0, "time_limit_s", "must lie in (0, 3600]",
          time_limit_s);
}

void PropellerCalibrationTargets::validate() const {
  require(static_rpm > 0.0 && std::isfinite(static_rpm), "static_rpm",
          "must be positive and finite", static_rpm);
  require(ground_roll_m > 0.0 && std::isfinite(ground_roll_m), "ground_roll_m",
          "must be positive and finite", ground_roll_m);
  technique.validate();
  require(factor_low >= Propeller::kMinCoefficientFactor, "factor_low",
          "must not be below Propeller::kMinCoefficientFactor", factor_low);
  require(factor_high <= Propeller::kMaxCoefficientFactor, "factor_high",
          "must not exceed Propeller::kMaxCoefficientFactor", factor_high);
  require(factor_low < factor_high, "factor_high", "must exceed factor_low", factor_high);
  require(factor_tolerance > 0.0 && factor_tolerance < factor_high - factor_low,
          "factor_tolerance", "must be positive and below the bracket's width", factor_tolerance);
  if (factor_fade) {
    const double start = factor_fade->start_advance_ratio;
    const double end = factor_fade->end_advance_ratio;
    require(start >= 0.0 && start <= Propeller::kMaxFadeAdvanceRatio,
            "factor_fade.start_advance_ratio", "must lie in [0, Propeller::kMaxFadeAdvanceRatio]",
            start);
    require(end >= 0.0 && end <= Propeller::kMaxFadeAdvanceRatio,
            "factor_fade.end_advance_ratio", "must lie in [0, Propeller::kMaxFadeAdvanceRatio]",
            end);
    require(end > start, "factor_fade.end_advance_ratio", "must exceed start_advance_ratio", end);
  }
}

AircraftModel::Options calibration_model_options() {
  AircraftModel::Options options;
  options.integrator = IntegrationMethod::kRk4;
  return options;
}

StaticRunUp static_full_throttle(const AircraftPack& pack) {
  AircraftModel model(pack, calibration_model_options());
  StaticRunUp out;
  out.converged = reposition_to_runway(model, kSeaLevelRunway, 1.0).converged;
  if (model.engine_count() == 0) return out;
  const EngineOutputs& e = model.outputs().engines[0];
  out.rpm = e.rpm;
  out.power_w = e.power_w;
  out.thrust_n = e.thrust_n;
  out.manifold_pressure_pa = e.manifold_pressure_pa;
  return out;
}

TakeoffRoll fly_takeoff_ground_roll(const AircraftPack& pack, const TakeoffTechnique& technique) {
  technique.validate();
  AircraftModel model(pack, calibration_model_options());
  AircraftControls controls = model.controls();
  controls.flaps = technique.flaps_norm;
  controls.brake_left = controls.brake_right = 1.0;
  controls.set_throttle(1.0);
  model.set_controls(controls);
  const TrimResult parked = reposition_to_runway(model, kSeaLevelRunway, 1.0);
  if (!parked.converged) {
    throw std::invalid_argument("take-off: the ground trim at full throttle failed: " +
                                parked.reason);
  }
  controls = parked.controls;
  controls.brake_left = controls.brake_right = 0.0;

  TakeoffRoll roll;
  const double dt_s = 1.0 / technique.frame_rate_hz;
  const double start_north_m = model.outputs().north_m;
  const double start_east_m = model.outputs().east_m;
  const auto frames = static_cast<long>(std::ceil(technique.time_limit_s / dt_s));
  for (long i = 0; i < frames; ++i) {
    if (model.outputs().cas_mps >= technique.rotate_cas_mps) {
      controls.elevator = technique.rotation_elevator;
    }
    model.set_controls(controls);
    model.step(dt_s);
    const AircraftOutputs& o = model.outputs();
    if (!o.weight_on_wheels) {
      roll.lifted_off = true;
      roll.ground_roll_m = std::hypot(o.north_m - start_north_m, o.east_m - start_east_m);
      roll.liftoff_cas_mps = o.cas_mps;
      if (!o.engines.empty() && o.engines[0].propeller_rpm > 0.0) {
        roll.liftoff_advance_ratio = o.tas_mps / (o.engines[0].propeller_rpm / 60.0 *
                                                  pack.engines[0].propeller.diameter_m);
      }
      roll.time_s = static_cast<double>(i + 1) * dt_s;
      break;
    }
  }
  return roll;
}

void set_propeller_factors(AircraftPack& pack, double thrust_coefficient_factor,
                           double power_coefficient_factor) {
  for (EngineSpec& engine : pack.engines) {
    if (engine.type != EngineType::piston_propeller) continue;
    engine.propeller.thrust_coefficient_factor = thrust_coefficient_factor;
    engine.propeller.power_coefficient_factor = power_coefficient_factor;
  }
}

void set_propeller_factor_fade(AircraftPack& pack,
                               const std::optional<PropellerSpec::FactorFade>& fade) {
  for (EngineSpec& engine : pack.engines) {
    if (engine.type == EngineType::piston_propeller) engine.propeller.factor_fade = fade;
  }
}

PropellerCalibration identify_propeller_factors(AircraftPack pack,
                                                const PropellerCalibrationTargets& targets) {
  targets.validate();
  if (pack.engines.empty() || pack.engines.front().type != EngineType::piston_propeller) {
    throw std::invalid_argument("propeller calibration: engine 0 of '" + pack.metadata.name +
                                "' is not a piston engine with a propeller");
  }
  set_propeller_factor_fade(pack, targets.factor_fade);
  const auto static_rpm = [&](double cp_factor) {
    set_propeller_factors(pack, 1.0, cp_factor);
    const StaticRunUp run = static_full_throttle(pack);
    if (!run.converged) {
      throw std::invalid_argument("static run-up: the ground trim at full throttle failed");
    }
    return run.rpm;
  };
  PropellerCalibration out;
  out.power_coefficient_factor =
      bisect_decreasing(static_rpm, targets.static_rpm, targets.factor_low, targets.factor_high,
                        targets.factor_tolerance, "static rpm (CP factor)");

  const auto ground_roll = [&](double ct_factor) {
    set_propeller_factors(pack, ct_factor, out.power_coefficient_factor);
    const TakeoffRoll roll = fly_takeoff_ground_roll(pack, targets.technique);
    // No lift-off within the time limit: a roll longer than any.
    return roll.lifted_off ? roll.ground_roll_m : std::numeric_limits<double>::infinity();
  };
  out.thrust_coefficient_factor =
      bisect_decreasing(ground_roll, targets.ground_roll_m, targets.factor_low,
                        targets.factor_high, targets.factor_tolerance, "ground roll (CT factor)");

  set_propeller_factors(pack, out.thrust_coefficient_factor, out.power_coefficient_factor);
  out.static_run = static_full_throttle(pack);
  out.roll = fly_takeoff_ground_roll(pack, targets.technique);
  return out;
}

}  // namespace fedsim::flight
