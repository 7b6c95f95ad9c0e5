// Trim by Levenberg-Marquardt on all equations together with a numerical Jacobian.
#include "flight/model/scenario/trim.hpp"
#include "common/units/units.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/atmosphere/airspeed.hpp"
#include "flight/model/aircraft/aircraft_model.hpp"
#include "flight/model/weather/wind_profile.hpp"

namespace fedsim::flight {

namespace {

// Tolerances: 1e-4 m/s^2 (1e-5 g) on the forces, 1e-5 rad/s^2 on the moments; tighter than
// JSBSim's trim (1e-3 ft/s^2 and 1e-4 rad/s^2), reachable because every axis is solved
// together and the Jacobian is exact to truncation.
constexpr double kForceTolerance = 1e-4;
constexpr double kMomentTolerance = 1e-5;

// Default angle-of-attack bounds when the pack states none.
constexpr double kDefaultAlphaMin = -10.0 * units::kDegToRad;
constexpr double kDefaultAlphaMax = 25.0 * units::kDegToRad;
constexpr double kBetaLimit = 20.0 * units::kDegToRad;

std::string format(const char* fmt, double a) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, fmt, a);
  return buffer;
}

/// Pitch that gives flight-path angle gamma for alpha, beta and bank (the rate-of-climb
/// constraint, Stevens & Lewis, Aircraft Control and Simulation, 2nd ed., section 3.6).
double pitch_for_flight_path(double alpha, double beta, double phi, double gamma) {
  const double a = std::cos(alpha) * std::cos(beta);
  const double b =
      std::sin(phi) * std::sin(beta) + std::cos(phi) * std::sin(alpha) * std::cos(beta);
  const double sg = std::sin(gamma);
  const double root = std::sqrt(std::max(a * a - sg * sg + b * b, 0.0));
  return std::atan2(a * b + sg * root, a * a - sg * sg);
}

/// Rate of the local NED frame relative to the earth (the transport rate), NED components.
Eigen::Vector3d transport_rate_ned(const Eigen::Vector3d& v_ned, const GeodeticPosition& at) {
  const double rn = Wgs84::prime_vertical_radius_m(at.lat_rad) + at.alt_m;
  const double rm = Wgs84::meridian_radius_m(at.lat_rad) + at.alt_m;
  return {v_ned.y() / rn, -v_ned.x() / rm, -v_ned.y() * std::tan(at.lat_rad) / rn};
}

/// One trim problem: the unknowns, their bounds and how they place the model.
class TrimProblem {
 public:
  // Unknowns in flight, and on the ground.
  enum Flight { kAlpha, kBeta, kThrottle, kElevator, kAileron, kRudder, kTurnRate };
  enum Ground { kHeight, kTheta, kPhi };

  TrimProblem(AircraftModel& model, const TrimRequest& request)
      : model_(model), request_(request), wind_(model.weather().wind) {
    validate_request();
    ground_ = request.kind == TrimKind::kGround;
    turn_ = request.kind == TrimKind::kTurn;
    tolerances_ = {kForceTolerance,  kForceTolerance,  kForceTolerance, kMomentTolerance,
                   kMomentTolerance, kMomentTolerance, kForceTolerance};
    if (ground_) {
      equations_ = {kWDot, kPDot, kQDot};
      set_bounds({-5.0, -30.0 * units::kDegToRad, -30.0 * units::kDegToRad}, {50.0, 30.0 * units::kDegToRad, 30.0 * units::kDegToRad});
    } else {
      tas_mps_ = true_airspeed();
      equations_ = {kUDot, kVDot, kWDot, kPDot, kQDot, kRDot};
      if (turn_) equations_.push_back(kLateralForce);
      const aircraft_pack::LimitsSpec& limits = model.pack().limits;
      const double alpha_min = limits.alpha_min_rad.value_or(kDefaultAlphaMin);
      const double alpha_max = limits.alpha_max_rad.value_or(kDefaultAlphaMax);
      std::vector<double> lo = {alpha_min, -kBetaLimit, 0.0, -1.0, -1.0, -1.0};
      std::vector<double> hi = {alpha_max, kBetaLimit, 1.0, 1.0, 1.0, 1.0};
      if (turn_) {
        lo.push_back(-1.0);
        hi.push_back(1.0);
      }
      set_bounds(lo, hi);
    }
  }

  int unknowns() const { return static_cast<int>(lower_.size()); }
  int equations() const { return static_cast<int>(equations_.size()); }
  const Eigen::VectorXd& lower() const { return lower_; }
  const Eigen::VectorXd& upper() const { return upper_; }
  bool ground() const { return ground_; }
  bool turn() const { return turn_; }
  double tas_mps() const { return tas_mps_; }
  const std::vector<int>& equation_axes() const { return equations_; }
  const std::array<double, kTrimAxisCount>& tolerances() const { return tolerances_; }

  Eigen::VectorXd clamp(const Eigen::VectorXd& z) const {
    return z.cwiseMax(lower_).cwiseMin(upper_);
  }

  /// Finite-difference step of each unknown.
  double difference_step(int j) const {
    if (ground_) return j == kHeight ? 1e-6 : 1e-7;
    switch (j) {
      case kAlpha:
      case kBeta:
        return 1e-6;
      case kTurnRate:
        return 1e-7;
      default:
        return 1e-5;
    }
  }

  /// Puts the model in the state the unknowns describe.
  void apply(const Eigen::VectorXd& z) {
    if (ground_) {
      apply_ground(z);
    } else {
      apply_flight(z);
    }
  }

  /// Every residual at the model's present state (TrimAxis order, SI).
  std::array<double, kTrimAxisCount> all_residuals() const {
    const AircraftOutputs& o = model_.outputs();
    return {o.velocity_body_dot_mps2.x(),     o.velocity_body_dot_mps2.y(), o.velocity_body_dot_mps2.z(),
            o.omega_dot_body_radps2.x(),        o.omega_dot_body_radps2.y(),    o.omega_dot_body_radps2.z(),
            o.specific_force_cg_body_mps2.y()};
  }

  /// The trim's equations at z, each divided by its tolerance (|r_i| <= 1: met).
  Eigen::VectorXd scaled_residuals(const Eigen::VectorXd& z) {
    apply(z);
    const auto all = all_residuals();
    Eigen::VectorXd r(equations());
    for (int i = 0; i < equations(); ++i) {
      const int axis = equations_[static_cast<std::size_t>(i)];
      r[i] = all[static_cast<std::size_t>(axis)] / tolerances_[static_cast<std::size_t>(axis)];
    }
    return r;
  }

  Eigen::VectorXd initial_guess() {
    return ground_ ? initial_guess_ground() : initial_guess_flight();
  }

  const AircraftInitialConditions& last_state() const { return last_state_; }
  double last_theta() const { return last_theta_; }
  double last_phi() const { return last_phi_; }

  /// "hold 4000 ft at 100 KTAS" and the like, for failure messages.
  std::string condition_text() const {
    const std::string alt = format("%.0f ft", request_.position.alt_m / units::kFtToM);
    const std::string speed = format("%.0f", request_.airspeed_mps / units::kKtToMps) +
                              (request_.airspeed_is_cas ? " KCAS" : " KTAS");
    switch (request_.kind) {
      case TrimKind::kLevel:
        return "hold " + alt + " at " + speed;
      case TrimKind::kClimb:
        return (request_.flight_path_rad >= 0.0 ? "climb at " : "descend at ") +
               format("%.1f deg", std::abs(request_.flight_path_rad) / units::kDegToRad) + " and " + speed +
               " at " + alt;
      case TrimKind::kTurn:
        return "hold a " + format("%.0f deg", std::abs(request_.bank_rad) / units::kDegToRad) +
               " banked level turn at " + alt + " and " + speed;
      case TrimKind::kGround:
        return "rest on the runway";
    }
    return "trim";
  }

 private:
  void validate_request() const {
    const TrimRequest& r = request_;
    auto bad = [](const std::string& what) {
      throw std::invalid_argument("trim request: " + what);
    };
    if (!std::isfinite(r.position.lat_rad) || std::abs(r.position.lat_rad) > units::kPi / 2 ||
        !std::isfinite(r.position.lon_rad) || !std::isfinite(r.position.alt_m)) {
      bad("position must be finite with |lat| <= 90 deg");
    }
    if (!std::isfinite(r.heading_rad)) bad("heading must be finite");
    if (r.max_iterations < 1) bad("max_iterations must be >= 1");
    if (r.kind == TrimKind::kGround) {
      if (!(r.ground_throttle >= 0.0 && r.ground_throttle <= 1.0)) {
        bad("ground_throttle must be a number within 0..1 (got " +
            format("%g", r.ground_throttle) + ")");
      }
      return;
    }
    if (!(r.airspeed_mps > 0.0) || !std::isfinite(r.airspeed_mps)) bad("airspeed must be > 0");
    if (!(std::abs(r.flight_path_rad) < 60.0 * units::kDegToRad)) bad("flight path must be within +-60 deg");
    if (!(std::abs(r.bank_rad) < 80.0 * units::kDegToRad)) bad("bank must be within +-80 deg");
  }

  void set_bounds(const std::vector<double>& lo, const std::vector<double>& hi) {
    lower_ = Eigen::Map<const Eigen::VectorXd>(lo.data(), static_cast<Eigen::Index>(lo.size()));
    upper_ = Eigen::Map<const Eigen::VectorXd>(hi.data(), static_cast<Eigen::Index>(hi.size()));
  }

  double true_airspeed() const {
    if (!request_.airspeed_is_cas) return request_.airspeed_mps;
    return tas_from_cas_mps(request_.airspeed_mps, model_.atmosphere().at(request_.position.alt_m));
  }

  double bank() const { return turn_ ? request_.bank_rad : 0.0; }
  double flight_path() const {
    return request_.kind == TrimKind::kClimb ? request_.flight_path_rad : 0.0;
  }

  void apply_flight(const Eigen::VectorXd& z) {
    AircraftControls controls = request_.controls;
    controls.elevator = z[kElevator];
    controls.aileron = z[kAileron];
    controls.rudder = z[kRudder];
    controls.set_throttle(z[kThrottle]);
    model_.set_controls(controls);

    const double alpha = z[kAlpha], beta = z[kBeta], phi = bank();
    const double theta = pitch_for_flight_path(alpha, beta, phi, flight_path());
    const EulerAngles attitude{phi, theta, request_.heading_rad};
    const Eigen::Matrix3d ned_from_body = dcm_from_euler(attitude);
    const Eigen::Vector3d air_body =
        tas_mps_ * Eigen::Vector3d(std::cos(alpha) * std::cos(beta), std::sin(beta),
                                   std::sin(alpha) * std::cos(beta));
    const Eigen::Vector3d velocity_ned =
        ned_from_body * air_body + wind_.at(request_.position.alt_m).wind_ned_mps;

    // Body rates: the turn about the local vertical, plus on the WGS-84 earth the rotation of
    // the local NED axes over the curved earth (the model adds the earth's own rate).
    Eigen::Vector3d frame_rate_ned(0.0, 0.0, turn_ ? z[kTurnRate] : 0.0);
    if (model_.options().earth == EarthModelKind::kWgs84) {
      frame_rate_ned += transport_rate_ned(velocity_ned, request_.position);
    }

    AircraftInitialConditions ic;
    ic.position = request_.position;
    ic.velocity_frame = AircraftInitialConditions::VelocityFrame::kNed;
    ic.velocity_mps = velocity_ned;
    ic.attitude = attitude;
    ic.omega_body_radps = ned_from_body.transpose() * frame_rate_ned;
    ic.omega_relative_to_earth = true;
    place(ic, theta, phi);
  }

  void apply_ground(const Eigen::VectorXd& z) {
    AircraftControls controls = request_.controls;
    controls.set_throttle(request_.ground_throttle);
    controls.brake_left = 1.0;
    controls.brake_right = 1.0;
    model_.set_controls(controls);
    AircraftInitialConditions ic;
    ic.position = request_.position;
    ic.position.alt_m = model_.runway_elevation_m() + z[kHeight];
    ic.attitude = EulerAngles{z[kPhi], z[kTheta], request_.heading_rad};
    ic.omega_relative_to_earth = true;
    place(ic, z[kTheta], z[kPhi]);
  }

  void place(AircraftInitialConditions ic, double theta, double phi) {
    ic.settle_engines = true;
    const AircraftOutputs& o = model_.outputs();
    ic.fuel_kg = o.tank_fuel_kg;
    model_.set_state(ic);
    model_.settle_systems();
    last_state_ = ic;
    last_theta_ = theta;
    last_phi_ = phi;
  }

  Eigen::VectorXd initial_guess_flight() {
    // Lift first: scan alpha for the first angle at which the body-z force balance changes
    // sign (lift equal to weight), starting from the lowest angle so that the solution is on
    // the front of the lift curve; then Levenberg-Marquardt does the rest.
    Eigen::VectorXd z = Eigen::VectorXd::Zero(unknowns());
    z[kThrottle] = 0.5;
    if (turn_) z[kTurnRate] = units::kStandardGravityMps2 * std::tan(request_.bank_rad) / tas_mps_;
    double best_alpha = 2.0 * units::kDegToRad, best_abs = INFINITY, previous_w_dot = NAN;
    double previous_alpha = 0.0;
    for (double alpha = lower_[kAlpha]; alpha <= upper_[kAlpha] + 1e-12; alpha += 1.0 * units::kDegToRad) {
      z[kAlpha] = alpha;
      apply(z);
      const double w_dot = all_residuals()[kWDot];
      if (std::abs(w_dot) < best_abs) {
        best_abs = std::abs(w_dot);
        best_alpha = alpha;
      }
      if (previous_w_dot > 0.0 && w_dot <= 0.0) {
        best_alpha =
            previous_alpha + (alpha - previous_alpha) * previous_w_dot / (previous_w_dot - w_dot);
        break;
      }
      previous_w_dot = w_dot;
      previous_alpha = alpha;
    }
    z[kAlpha] = best_alpha;
    return z;
  }

  Eigen::VectorXd initial_guess_ground() {
    // Pitch that puts the foremost and the aftmost wheel at the same height, and the CG height
    // that lets the lowest wheel just touch, less the static deflection of all the struts.
    const auto& contacts = model_.pack().landing_gear.contacts;
    const Eigen::Vector3d cg = model_.outputs().cg_m;
    const GearContactSpec* front = nullptr;
    const GearContactSpec* back = nullptr;
    double stiffness = 0.0;
    for (const GearContactSpec& c : contacts) {
      if (c.type != ContactType::wheel) continue;
      if (!front || c.position_m.x() > front->position_m.x()) front = &c;
      if (!back || c.position_m.x() < back->position_m.x()) back = &c;
      stiffness += c.spring_n_per_m;
    }
    Eigen::VectorXd z = Eigen::VectorXd::Zero(3);
    if (!front) return z;
    const double dx = front->position_m.x() - back->position_m.x();
    const double theta =
        dx > 1e-6 ? std::atan((front->position_m.z() - back->position_m.z()) / dx) : 0.0;
    double lowest = -INFINITY;
    for (const GearContactSpec& c : contacts) {
      const Eigen::Vector3d arm = c.position_m - cg;
      lowest = std::max(lowest, -std::sin(theta) * arm.x() + std::cos(theta) * arm.z());
    }
    const double sag = model_.outputs().mass_kg * units::kStandardGravityMps2 / std::max(stiffness, 1.0);
    z[kHeight] = lowest - sag;
    z[kTheta] = theta;
    return z;
  }

  AircraftModel& model_;
  TrimRequest request_;
  WindProfile wind_;
  bool ground_ = false;
  bool turn_ = false;
  double tas_mps_ = 0.0;
  std::vector<int> equations_;
  std::array<double, kTrimAxisCount> tolerances_{};
  Eigen::VectorXd lower_, upper_;
  AircraftInitialConditions last_state_;
  double last_theta_ = 0.0, last_phi_ = 0.0;
};

/// Levenberg-Marquardt with bounds by projection (Nocedal & Wright, Numerical Optimization,
/// 2nd ed., section 10.3; Marquardt's diagonal scaling).
class LevenbergMarquardt {
 public:
  explicit LevenbergMarquardt(TrimProblem& problem) : problem_(problem) {}

  struct Outcome {
    Eigen::VectorXd z;
    Eigen::VectorXd r;
    int iterations = 0;
  };

  Outcome solve(Eigen::VectorXd z, int max_iterations) {
    Outcome out;
    z = problem_.clamp(z);
    Eigen::VectorXd r = problem_.scaled_residuals(z);
    double cost = r.squaredNorm();
    double lambda = 1e-3;
    int iteration = 0;
    for (; iteration < max_iterations && !met(r); ++iteration) {
      const Eigen::MatrixXd jacobian = jacobian_at(z);
      const Eigen::MatrixXd a = jacobian.transpose() * jacobian;
      const Eigen::VectorXd g = jacobian.transpose() * r;
      bool improved = false;
      while (lambda < 1e12) {
        Eigen::MatrixXd m = a;
        for (int j = 0; j < m.rows(); ++j) m(j, j) += lambda * a(j, j) + 1e-12;
        const Eigen::VectorXd step = -m.ldlt().solve(g);
        const Eigen::VectorXd z_new = problem_.clamp(z + step);
        const Eigen::VectorXd r_new = problem_.scaled_residuals(z_new);
        const double cost_new = r_new.squaredNorm();
        if (std::isfinite(cost_new) && cost_new < cost) {
          z = z_new;
          r = r_new;
          cost = cost_new;
          lambda = std::max(lambda * 0.1, 1e-12);
          improved = true;
          break;
        }
        lambda *= 10.0;
      }
      if (!improved) break;  // no descent left: a bound or no equilibrium
    }
    problem_.apply(z);  // leave the model at the answer
    out.z = z;
    out.r = r;
    out.iterations = iteration;
    return out;
  }

  static bool met(const Eigen::VectorXd& r) { return r.cwiseAbs().maxCoeff() <= 1.0; }

 private:
  /// Central differences; one-sided against a bound.
  Eigen::MatrixXd jacobian_at(const Eigen::VectorXd& z) {
    const int n = problem_.unknowns();
    Eigen::MatrixXd j(problem_.equations(), n);
    for (int k = 0; k < n; ++k) {
      const double h = problem_.difference_step(k);
      Eigen::VectorXd plus = z, minus = z;
      plus[k] = std::min(z[k] + h, problem_.upper()[k]);
      minus[k] = std::max(z[k] - h, problem_.lower()[k]);
      const double span = plus[k] - minus[k];
      if (span <= 0.0) {
        j.col(k).setZero();
        continue;
      }
      const Eigen::VectorXd r_plus = problem_.scaled_residuals(plus);
      const Eigen::VectorXd r_minus = problem_.scaled_residuals(minus);
      j.col(k) = (r_plus - r_minus) / span;
    }
    return j;
  }

  TrimProblem& problem_;
};

std::string residual_text(const TrimResult& result) {
  std::string text;
  for (int axis = 0; axis < kTrimAxisCount; ++axis) {
    const auto i = static_cast<std::size_t>(axis);
    if (!result.constrained[i] || std::abs(result.residuals[i]) <= result.tolerances[i]) continue;
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "%s%s %.3g", text.empty() ? "" : ", ",
                  std::string(trim_axis_name(axis)).c_str(), result.residuals[i]);
    text += buffer;
  }
  return text.empty() ? "" : " (" + text + ")";
}

/// Why a trim that did not converge failed: the first bound that holds it, else no
/// equilibrium within the iterations.
std::string failure_reason(const TrimProblem& problem, const Eigen::VectorXd& z, int iterations,
                           int max_iterations) {
  auto at_upper = [&](int k) { return z[k] >= problem.upper()[k] - 1e-9; };
  auto at_lower = [&](int k) { return z[k] <= problem.lower()[k] + 1e-9; };
  const std::string cannot = "the aircraft cannot " + problem.condition_text();
  if (!problem.ground()) {
    // Lift first: at the angle-of-attack limit nothing else can help; then power, then the
    // controls.
    using P = TrimProblem;
    if (at_upper(P::kAlpha)) {
      return "angle of attack at its limit of " +
             format("%.1f deg", problem.upper()[P::kAlpha] / units::kDegToRad) + ": " + cannot +
             " (the wing cannot carry the aircraft: below the stall speed)";
    }
    if (at_lower(P::kAlpha)) {
      return "angle of attack at its lower limit of " +
             format("%.1f deg", problem.lower()[P::kAlpha] / units::kDegToRad) + ": " + cannot;
    }
    if (at_upper(P::kThrottle)) return "throttle saturated at 1.0: " + cannot;
    if (at_lower(P::kThrottle)) {
      return "throttle saturated at idle: " + cannot +
             " without gaining speed (too much thrust "
             "or too little drag at idle)";
    }
    if (at_lower(P::kElevator)) return "elevator saturated at full nose-up (-1.0): " + cannot;
    if (at_upper(P::kElevator)) return "elevator saturated at full nose-down (+1.0): " + cannot;
    if (at_lower(P::kAileron) || at_upper(P::kAileron)) return "aileron saturated: " + cannot;
    if (at_lower(P::kRudder) || at_upper(P::kRudder)) return "rudder saturated: " + cannot;
    if (at_lower(P::kBeta) || at_upper(P::kBeta)) return "sideslip at its 20 deg limit: " + cannot;
  }
  if (iterations >= max_iterations) {
    return "no equilibrium found in " + std::to_string(max_iterations) + " iterations: " + cannot;
  }
  return "no equilibrium found (the solver stalled after " + std::to_string(iterations) +
         " iterations): " + cannot;
}
}  // namespace

TrimKind trim_kind_from_name(std::string_view name) {
  if (name == "level") return TrimKind::kLevel;
  if (name == "climb") return TrimKind::kClimb;
  if (name == "turn") return TrimKind::kTurn;
  if (name == "ground") return TrimKind::kGround;
  throw std::invalid_argument("unknown trim kind '" + std::string(name) +
                              "' (level, climb, turn, ground)");
}

std::string_view to_string(TrimKind kind) {
  switch (kind) {
    case TrimKind::kLevel:
      return "level";
    case TrimKind::kClimb:
      return "climb";
    case TrimKind::kTurn:
      return "turn";
    case TrimKind::kGround:
      return "ground";
  }
  return "level";
}

std::string_view trim_axis_name(int axis) {
  static constexpr std::string_view kNames[kTrimAxisCount] = {"u_dot_mps2",
                                                              "v_dot_mps2",
                                                              "w_dot_mps2",
                                                              "p_dot_radps2",
                                                              "q_dot_radps2",
                                                              "r_dot_radps2",
                                                              "lateral_specific_force_mps2"};
  return axis >= 0 && axis < kTrimAxisCount ? kNames[axis] : "unknown";
}

TrimResult Trim::solve(const TrimRequest& request) {
  TrimProblem problem(model_, request);
  TrimResult result;
  result.kind = request.kind;
  result.tolerances = problem.tolerances();
  for (int axis : problem.equation_axes())
    result.constrained[static_cast<std::size_t>(axis)] = true;

  const bool has_wheels = std::any_of(
      model_.pack().landing_gear.contacts.begin(), model_.pack().landing_gear.contacts.end(),
      [](const GearContactSpec& c) { return c.type == ContactType::wheel; });
  if (problem.ground() && !has_wheels) {
    result.reason = "the aircraft has no wheels to rest on";
    return result;
  }

  LevenbergMarquardt solver(problem);
  const auto outcome = solver.solve(problem.initial_guess(), request.max_iterations);
  result.iterations = outcome.iterations;
  result.residuals = problem.all_residuals();
  bool converged = true;
  for (int axis : problem.equation_axes()) {
    const auto i = static_cast<std::size_t>(axis);
    converged = converged && std::abs(result.residuals[i]) <= result.tolerances[i];
  }
  result.converged = converged;

  const AircraftOutputs& o = model_.outputs();
  result.controls = model_.controls();
  result.alpha_rad = o.alpha_rad;
  result.beta_rad = o.beta_rad;
  result.phi_rad = problem.last_phi();
  result.theta_rad = problem.last_theta();
  result.psi_rad = request.heading_rad;
  result.flight_path_rad = std::atan2(o.climb_rate_mps, std::max(o.ground_speed_mps, 1e-9));
  if (problem.ground()) result.flight_path_rad = 0.0;
  result.turn_rate_radps = problem.turn() ? outcome.z[TrimProblem::kTurnRate] : 0.0;
  result.tas_mps = o.tas_mps;
  result.cas_mps = o.cas_mps;
  result.altitude_m = o.geodetic.alt_m;
  result.elevator_rad = o.elevator_rad;
  result.aileron_rad = o.aileron_rad;
  result.rudder_rad = o.rudder_rad;
  result.total_thrust_n = o.total_thrust_n;
  result.initial_conditions = problem.last_state();
  if (!converged) {
    result.reason = failure_reason(problem, outcome.z, outcome.iterations, request.max_iterations) +
                    residual_text(result);
  }
  return result;
}

}  // namespace fedsim::flight
