#include "control_loading/model/control_loading.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "common/units/units.hpp"

namespace fedsim::control_loading {
namespace {

constexpr double kMinInnerRateHz = 1000.0;
// (w h)^2 + 2 c h/m <= kStabilityBudget, half the bound 4 of semi-implicit Euler.
constexpr double kStabilityBudget = 2.0;

bool in_unit_range(double value) { return std::isfinite(value) && std::abs(value) <= 1.0; }

// The largest h with (k/m) h^2 + (2 c/m) h <= budget.
double stable_substep_s(double k_npm, double c_nspm, double m_kg) {
  const double a = k_npm / m_kg;
  const double b = 2.0 * c_nspm / m_kg;
  return (-b + std::sqrt(b * b + 4.0 * a * kStabilityBudget)) / (2.0 * a);
}

}  // namespace

const char* to_string(Axis axis) {
  switch (axis) {
    case Axis::kPitch:
      return "pitch";
    case Axis::kRoll:
      return "roll";
    case Axis::kYaw:
      return "yaw";
  }
  return "unknown";
}

const char* to_string(LoaderStatus status) {
  switch (status) {
    case LoaderStatus::kSafe:
      return "safe";
    case LoaderStatus::kFadingIn:
      return "fading_in";
    case LoaderStatus::kActive:
      return "active";
  }
  return "unknown";
}

void validate(const ControlLoadingParameters& p) {
  for (int i = 0; i < kAxisCount; ++i) validate(p.axes[i], to_string(static_cast<Axis>(i)));
  validate(p.pilot);
  auto fail = [](const char* field, double value, const char* problem) {
    std::ostringstream message;
    message << "ControlLoadingParameters: " << field << " = " << value << " " << problem;
    throw std::invalid_argument(message.str());
  };
  if (!std::isfinite(p.inner_rate_hz) || p.inner_rate_hz < kMinInnerRateHz) {
    fail("inner_rate_hz", p.inner_rate_hz, "must be at least 1000");
  }
  if (!std::isfinite(p.watchdog_timeout_s) || !(p.watchdog_timeout_s > 0.0)) {
    fail("watchdog_timeout_s", p.watchdog_timeout_s, "must be positive");
  }
  if (!std::isfinite(p.fade_in_s) || !(p.fade_in_s > 0.0)) {
    fail("fade_in_s", p.fade_in_s, "must be positive");
  }
  if (!std::isfinite(p.pilot_force_limit_n) || !(p.pilot_force_limit_n > 0.0)) {
    fail("pilot_force_limit_n", p.pilot_force_limit_n, "must be positive");
  }
  if (!std::isfinite(p.qbar_limit_pa) || !(p.qbar_limit_pa > 0.0)) {
    fail("qbar_limit_pa", p.qbar_limit_pa, "must be positive");
  }
  StickShaker(p.shaker_alpha_rad, p.shaker_hysteresis_rad);  // checks the shaker's two fields
}

ControlLoading::ControlLoading(const ControlLoadingParameters& parameters)
    : parameters_((validate(parameters), parameters)),
      axes_{ControlAxis(parameters.axes[0], "pitch"), ControlAxis(parameters.axes[1], "roll"),
            ControlAxis(parameters.axes[2], "yaw")},
      shaker_(parameters.shaker_alpha_rad, parameters.shaker_hysteresis_rad) {
  max_stable_substep_s_ = 1.0;
  for (const ControlAxis& axis : axes_) {
    const double k = axis.stiffest_spring_npm() + parameters_.pilot.hand_stiffness_npm;
    const double c = axis.largest_damping_nspm() + parameters_.pilot.hand_damping_nspm;
    max_stable_substep_s_ =
        std::min(max_stable_substep_s_, stable_substep_s(k, c, axis.parameters().mass_kg));
  }
  publish_axes(ControlLoadingInputs{});
}

int ControlLoading::substeps_for(double dt_s) const {
  const double by_rate = dt_s * parameters_.inner_rate_hz;
  const double by_stability = dt_s / max_stable_substep_s_;
  return std::max(1, static_cast<int>(std::ceil(std::max(by_rate, by_stability) - 1e-9)));
}

bool ControlLoading::engage() {
  if (outputs_.status != LoaderStatus::kSafe) return false;
  outputs_.status = LoaderStatus::kFadingIn;
  force_gain_ = 0.0;
  reason_.clear();
  return true;
}

void ControlLoading::cut_off(const std::string& reason) {
  if (outputs_.status != LoaderStatus::kSafe) {
    reason_ = reason.empty() ? "unspecified" : reason;
  }
  outputs_.status = LoaderStatus::kSafe;
  force_gain_ = 0.0;
  shaker_.reset();
  // The motors are off from now: what the outputs say until the next step.
  outputs_.stick_shaker = false;
  for (AxisOutputs& a : outputs_.axes) {
    a.max_loader_force_n = 0.0;
    a.max_backdrive_force_n = 0.0;
  }
}

namespace {

// The first unusable input, as (axis or nullptr, field, value); field nullptr when all are
// usable. Allocation-free: the message is only built when something is wrong.
struct InputProblem {
  const char* axis = nullptr;
  const char* field = nullptr;
  double value = 0.0;
};

}  // namespace

bool ControlLoading::inputs_valid(const ControlLoadingInputs& in, std::string& problem) const {
  InputProblem found;
  for (int i = 0; i < kAxisCount && found.field == nullptr; ++i) {
    const AxisInputs& a = in.axes[i];
    found.axis = to_string(static_cast<Axis>(i));
    if (!std::isfinite(a.pilot_force_n) ||
        std::abs(a.pilot_force_n) > parameters_.pilot_force_limit_n) {
      found = {found.axis, "pilot_force_n", a.pilot_force_n};
    } else if (!in_unit_range(a.pilot_target_norm)) {
      found = {found.axis, "pilot_target_norm", a.pilot_target_norm};
    } else if (!in_unit_range(a.trim_norm)) {
      found = {found.axis, "trim_norm", a.trim_norm};
    } else if (!in_unit_range(a.backdrive_target_norm)) {
      found = {found.axis, "backdrive_target_norm", a.backdrive_target_norm};
    }
  }
  if (found.field == nullptr) {
    found.axis = nullptr;
    if (!std::isfinite(in.qbar_pa) || in.qbar_pa < 0.0 || in.qbar_pa > parameters_.qbar_limit_pa) {
      found.field = "qbar_pa";
      found.value = in.qbar_pa;
    } else if (!std::isfinite(in.alpha_rad) || std::abs(in.alpha_rad) > units::kPi) {
      found.field = "alpha_rad";
      found.value = in.alpha_rad;
    } else if (!std::isfinite(in.flight_data_age_s) || in.flight_data_age_s < 0.0) {
      found.field = "flight_data_age_s";
      found.value = in.flight_data_age_s;
    } else if (in.flight_data_age_s > parameters_.watchdog_timeout_s) {
      std::ostringstream why;
      why << "watchdog: flight data " << in.flight_data_age_s << " s old (limit "
          << parameters_.watchdog_timeout_s << " s)";
      problem = why.str();
      return false;
    }
  }
  if (found.field == nullptr) return true;
  std::ostringstream why;
  why << "input rejected: " << (found.axis ? found.axis : "") << (found.axis ? " " : "")
      << found.field << " = " << found.value;
  problem = why.str();
  return false;
}

namespace {

// Inputs with anything unusable replaced by a harmless value (used once the loader is safe).
ControlLoadingInputs sanitized(const ControlLoadingInputs& in, double force_limit_n) {
  ControlLoadingInputs out = in;
  for (AxisInputs& a : out.axes) {
    a.pilot_force_n = std::isfinite(a.pilot_force_n)
                          ? std::clamp(a.pilot_force_n, -force_limit_n, force_limit_n)
                          : 0.0;
    a.pilot_target_norm =
        std::isfinite(a.pilot_target_norm) ? std::clamp(a.pilot_target_norm, -1.0, 1.0) : 0.0;
    a.trim_norm = std::isfinite(a.trim_norm) ? std::clamp(a.trim_norm, -1.0, 1.0) : 0.0;
    a.backdrive_active = false;
    a.backdrive_target_norm = 0.0;
  }
  out.qbar_pa = std::isfinite(in.qbar_pa) ? std::max(in.qbar_pa, 0.0) : 0.0;
  out.alpha_rad = 0.0;
  return out;
}

}  // namespace

const ControlLoadingOutputs& ControlLoading::step(const ControlLoadingInputs& raw, double dt_s) {
  if (!std::isfinite(dt_s) || !(dt_s > 0.0)) {
    throw std::invalid_argument("ControlLoading::step: dt_s must be positive and finite");
  }
  std::string problem;
  const bool valid = inputs_valid(raw, problem);
  if (!valid) cut_off(problem);
  const ControlLoadingInputs inputs = valid ? raw : sanitized(raw, parameters_.pilot_force_limit_n);
  for (int i = 0; i < kAxisCount; ++i) {
    gradient_npm_[i] = scheduled_gradient_npm(parameters_.axes[i], inputs.qbar_pa);
    outputs_.axes[i].max_loader_force_n = outputs_.axes[i].max_backdrive_force_n = 0.0;
  }
  if (outputs_.status == LoaderStatus::kSafe) {
    shaker_.reset();
  } else {
    if (!shaker_.set_alpha_on(raw.shaker_alpha_rad)) shaker_.set_alpha_on(parameters_.shaker_alpha_rad);
    shaker_.update(inputs.alpha_rad);
  }
  const int n = substeps_for(dt_s);
  const double h = dt_s / n;
  for (int k = 0; k < n; ++k) run_substep(inputs, h);
  outputs_.substeps = n;
  outputs_.substep_s = h;
  publish_axes(inputs);
  return outputs_;
}

void ControlLoading::run_substep(const ControlLoadingInputs& in, double h) {
  if (outputs_.status == LoaderStatus::kFadingIn) {
    force_gain_ = std::min(1.0, force_gain_ + h / parameters_.fade_in_s);
    if (force_gain_ >= 1.0) outputs_.status = LoaderStatus::kActive;
  }
  shaker_.advance(h);
  for (int i = 0; i < kAxisCount; ++i) {
    ControlAxis& axis = axes_[i];
    const AxisInputs& a = in.axes[i];
    const ControlAxisParameters& p = axis.parameters();
    AxisDrive drive;
    drive.gradient_npm = gradient_npm_[i];
    drive.trim_target_m = a.trim_norm * p.trim_travel_m;
    drive.backdrive_active = a.backdrive_active;
    drive.backdrive_target_m = axis.position_m_for_norm(a.backdrive_target_norm);
    drive.shaker_force_n = p.shaker_force_n * shaker_.waveform(p.shaker_frequency_hz);
    drive.force_gain = force_gain_;
    if (in.pilot_source == PilotSource::kSimulatedPilot) {
      const double target_m = axis.position_m_for_norm(a.pilot_target_norm);
      drive.pilot_force_n = simulated_pilot_force_n(
          parameters_.pilot, target_m, axis.position_m(), axis.velocity_mps(),
          force_gain_ * axis.static_feel_force_n(target_m, axis.trim_m(), drive.gradient_npm));
    } else {
      drive.pilot_force_n = a.pilot_force_n;
    }
    axis.substep(drive, h);
    AxisOutputs& out = outputs_.axes[i];
    out.max_loader_force_n = std::max(out.max_loader_force_n, std::abs(axis.loader_force_n()));
    out.max_backdrive_force_n =
        std::max(out.max_backdrive_force_n, std::abs(axis.backdrive_force_n()));
    if (std::abs(axis.velocity_mps()) > p.velocity_trip_mps &&
        outputs_.status != LoaderStatus::kSafe) {
      cut_off(std::string("overspeed on ") + to_string(static_cast<Axis>(i)));
    }
  }
}

void ControlLoading::publish_axes(const ControlLoadingInputs& in) {
  for (int i = 0; i < kAxisCount; ++i) {
    const ControlAxis& axis = axes_[i];
    AxisOutputs& out = outputs_.axes[i];
    out.position_m = axis.position_m();
    out.velocity_mps = axis.velocity_mps();
    out.position_norm = axis.position_norm();
    out.velocity_norm_ps = axis.velocity_norm_ps();
    out.feel_force_n = axis.loader_force_n() + axis.mechanical_stop_force_n();
    out.pilot_force_n = axis.pilot_force_n();
    out.trim_norm = axis.parameters().trim_travel_m > 0.0
                        ? axis.trim_m() / axis.parameters().trim_travel_m
                        : 0.0;
    out.gradient_npm = scheduled_gradient_npm(axis.parameters(), in.qbar_pa);
    out.in_soft_stop = axis.in_soft_stop();
    out.in_hard_stop = axis.in_hard_stop();
    out.on_mechanical_stop = axis.on_mechanical_stop();
  }
  outputs_.stick_shaker = shaker_.active();
}

}  // namespace fedsim::control_loading
