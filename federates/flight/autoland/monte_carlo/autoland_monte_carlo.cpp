#include "flight/autoland/monte_carlo/autoland_monte_carlo.hpp"

#include "flight/model/afcs/closed_loop_flight.hpp"
#include "flight/model/afcs/lateral_guidance.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace fedsim::flight::autoland {

namespace {

constexpr double kFt = units::kFtToM;
constexpr double kKt = units::kKtToMps;
constexpr double kDeg = units::kDegToRad;

void require(bool ok, const char* field, double value) {
  if (!ok) throw std::invalid_argument("ScenarioRanges: " + std::string(field) + " = " + std::to_string(value) + " is out of range");
}

/// Fuel shared over the tanks in proportion to their capacities.
std::vector<double> fuel_by_tank(const AircraftPack& pack, double fuel_kg) {
  double capacity = 0.0;
  for (const aircraft_pack::FuelTankSpec& t : pack.mass.fuel_tanks) capacity += t.capacity_kg;
  std::vector<double> out;
  for (const aircraft_pack::FuelTankSpec& t : pack.mass.fuel_tanks) {
    out.push_back(capacity > 0.0 ? std::min(fuel_kg * t.capacity_kg / capacity, t.capacity_kg) : 0.0);
  }
  return out;
}

AircraftControls landing_configuration() {
  AircraftControls c;
  c.flaps = 0.875;  // flaps 30 of the 737's 40
  c.gear_down = true;
  return c;
}

WeatherSettings weather_of(const Scenario& s) {
  WeatherSettings w;
  if (s.wind_speed_mps > 0.0) {
    w.wind.altitude_m = {0.0, 10000.0};
    w.wind.speed_mps = {s.wind_speed_mps, s.wind_speed_mps};
    w.wind.from_direction_rad = {s.wind_from_rad, s.wind_from_rad};
  }
  w.turbulence = s.turbulence;
  w.turbulence_seed = s.turbulence_seed;
  return w;
}

afcs::McpButtons press(bool afcs::McpButtons::*which) {
  afcs::McpButtons b;
  b.*which = true;
  return b;
}

}  // namespace

void ScenarioRanges::validate() const {
  require(max_wind_mps >= 0.0 && max_wind_mps <= 40.0, "max_wind_mps", max_wind_mps);
  require(max_tailwind_mps > 0.0 && max_tailwind_mps <= 40.0, "max_tailwind_mps", max_tailwind_mps);
  require(min_fuel_kg >= 0.0 && min_fuel_kg <= max_fuel_kg, "min_fuel_kg", min_fuel_kg);
  require(max_fuel_kg <= 1e5, "max_fuel_kg", max_fuel_kg);
  require(reference_mass_kg > 0.0, "reference_mass_kg", reference_mass_kg);
  require(reference_cas_mps > 30.0 && reference_cas_mps < 150.0, "reference_cas_mps", reference_cas_mps);
  require(min_start_nm >= 4.0 && min_start_nm <= max_start_nm && max_start_nm <= 18.0, "min_start_nm", min_start_nm);
  require(max_start_offset_m >= 0.0 && max_start_offset_m <= 5000.0, "max_start_offset_m", max_start_offset_m);
  require(min_below_glide_path_m >= 0.0 && min_below_glide_path_m <= max_below_glide_path_m &&
              max_below_glide_path_m < 1500.0,
          "min_below_glide_path_m", min_below_glide_path_m);
}

std::string_view to_string(Turbulence::Severity severity) {
  switch (severity) {
    case Turbulence::Severity::kNone: return "none";
    case Turbulence::Severity::kLight: return "light";
    case Turbulence::Severity::kModerate: return "moderate";
    case Turbulence::Severity::kSevere: return "severe";
  }
  return "?";
}

Scenario draw_scenario(std::mt19937_64& rng, const ScenarioRanges& r, const nav::IlsApproach& approach, int run) {
  const double course_true_rad = approach.course_true_rad;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto between = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };
  Scenario s;
  s.run = run;
  s.wind_speed_mps = between(0.0, r.max_wind_mps);
  do {
    s.wind_from_rad = between(0.0, units::kTwoPi);
    s.headwind_mps = s.wind_speed_mps * std::cos(s.wind_from_rad - course_true_rad);
  } while (-s.headwind_mps > r.max_tailwind_mps);
  s.crosswind_mps = s.wind_speed_mps * std::sin(s.wind_from_rad - course_true_rad);
  const double t = unit(rng);
  s.turbulence = t < 0.25 ? Turbulence::Severity::kNone
                          : (t < 0.75 ? Turbulence::Severity::kLight : Turbulence::Severity::kModerate);
  s.turbulence_seed = rng();
  s.fuel_kg = between(r.min_fuel_kg, r.max_fuel_kg);
  s.start_before_threshold_m = between(r.min_start_nm, r.max_start_nm) * units::kNmToM;
  s.start_left_m = between(-r.max_start_offset_m, r.max_start_offset_m);
  const double glide_path_m = approach.threshold.elevation_m + approach.threshold_crossing_height_m +
                              s.start_before_threshold_m * std::tan(approach.glide_path_angle_rad);
  s.start_altitude_m = glide_path_m - between(r.min_below_glide_path_m, r.max_below_glide_path_m);
  return s;
}

RunResult fly_scenario(const Scenario& s, const AircraftPack& pack, const nav::IlsApproach& approach,
                       const RunwayCentreline& runway, double max_time_s,
                       std::unique_ptr<afcs::ClosedLoopFlight>* kept) {
  RunResult result;
  result.scenario = s;
  auto flight = std::make_unique<afcs::ClosedLoopFlight>(pack, approach);
  afcs::ClosedLoopFlight& f = *flight;
  f.set_recording(kept != nullptr);
  f.model().set_weather(weather_of(s));
  AircraftInitialConditions fuel;
  fuel.position.alt_m = s.start_altitude_m;
  fuel.fuel_kg = fuel_by_tank(pack, s.fuel_kg);
  f.model().reset(fuel);
  result.mass_kg = f.model().outputs().mass_kg;
  const ScenarioRanges ranges;
  result.scenario.approach_cas_mps = ranges.reference_cas_mps * std::sqrt(result.mass_kg / ranges.reference_mass_kg);
  const double intercept = s.start_left_m >= 0.0 ? 30.0 * kDeg : -30.0 * kDeg;
  const double tas = result.scenario.approach_cas_mps * (1.0 + 0.015 * s.start_altitude_m / 1000.0 * 3.28);
  const TrimResult trim = f.start_level({s.start_before_threshold_m, s.start_left_m, s.start_altitude_m},
                                        approach.course_true_rad + intercept, tas, landing_configuration());
  if (!trim.converged) {
    result.violations.push_back("no trim at the start: " + trim.reason);
    return result;
  }
  f.mcp().autothrottle_armed = true;
  f.mcp().autobrake_setting = 2;
  f.press(press(&afcs::McpButtons::autopilot_engage));
  f.step();
  f.press(press(&afcs::McpButtons::altitude_hold));
  f.press(press(&afcs::McpButtons::speed));
  f.press(press(&afcs::McpButtons::approach));
  f.mcp().calibrated_airspeed_mps = result.scenario.approach_cas_mps;
  f.run_until([](const afcs::FlightSample& x) { return x.main_gear_on_ground && x.ground_speed_mps < 0.5; },
              max_time_s);
  result.flown_s = f.time_s();
  result.figures = afcs::landing_figures(f, runway);
  result.violations = afcs::limit_violations(result.figures);
  if (!result.figures.autopilot_engaged) result.violations.push_back("autopilot disengaged");
  if (kept != nullptr) *kept = std::move(flight);
  return result;
}

Percentiles percentiles(std::vector<double> v) {
  Percentiles p;
  if (v.empty()) return p;
  std::sort(v.begin(), v.end());
  auto at = [&](double q) {
    const double h = (static_cast<double>(v.size()) - 1.0) * q;
    const auto lo = static_cast<std::size_t>(std::floor(h));
    const std::size_t hi = std::min(lo + 1, v.size() - 1);
    return v[lo] + (h - static_cast<double>(lo)) * (v[hi] - v[lo]);
  };
  p.min = v.front();
  p.p1 = at(0.01);
  p.p5 = at(0.05);
  p.p50 = at(0.5);
  p.p95 = at(0.95);
  p.p99 = at(0.99);
  p.max = v.back();
  return p;
}

void write_touchdowns_csv(std::ostream& out, const std::vector<RunResult>& results) {
  out << "run,wind_kt,wind_from_deg,headwind_kt,crosswind_kt,turbulence,mass_kg,vapp_kcas,start_nm,start_left_m,"
         "start_alt_ft,touchdown_beyond_ft,touchdown_centreline_ft,touchdown_course_ft,sink_fps,bank_deg,"
         "pitch_deg,decrab_deg,touchdown_kcas,stop_beyond_m,stop_centreline_m,max_rollout_offset_m,"
         "within_limits,violations\n";
  out << std::fixed << std::setprecision(3);
  for (const RunResult& r : results) {
    const Scenario& s = r.scenario;
    const afcs::LandingFigures& f = r.figures;
    const afcs::Touchdown& t = f.touchdown;
    std::string why;
    for (const std::string& v : r.violations) why += (why.empty() ? "" : "; ") + v;
    out << s.run << ',' << s.wind_speed_mps / kKt << ',' << s.wind_from_rad / kDeg << ',' << s.headwind_mps / kKt
        << ',' << s.crosswind_mps / kKt << ',' << to_string(s.turbulence) << ',' << r.mass_kg << ','
        << s.approach_cas_mps / kKt << ',' << s.start_before_threshold_m / units::kNmToM << ',' << s.start_left_m
        << ',' << s.start_altitude_m / kFt << ',' << t.beyond_threshold_m / kFt << ','
        << f.touchdown_left_of_centreline_m / kFt << ',' << t.left_of_course_m / kFt << ','
        << t.sink_rate_mps / kFt << ',' << t.roll_rad / kDeg << ',' << t.pitch_rad / kDeg << ','
        << t.heading_minus_course_rad / kDeg << ',' << t.cas_mps / kKt << ',' << f.stop_beyond_threshold_m << ','
        << f.stop_left_of_centreline_m << ',' << f.max_rollout_offset_m << ',' << (r.violations.empty() ? 1 : 0)
        << ",\"" << why << "\"\n";
  }
}

namespace {

struct Figure {
  const char* name;
  const char* unit;
  double (*value)(const RunResult&);
  double limit_low, limit_high;  // NaN: none
};

std::vector<Figure> figures(const afcs::LandingLimits& l) {
  const double none = NAN;
  return {
      {"touchdown beyond threshold", "ft", [](const RunResult& r) { return r.figures.touchdown.beyond_threshold_m / kFt; },
       l.min_beyond_threshold_m / kFt, l.max_beyond_threshold_m / kFt},
      {"touchdown from centreline", "ft",
       [](const RunResult& r) { return r.figures.touchdown_left_of_centreline_m / kFt; },
       -l.max_centreline_offset_m / kFt, l.max_centreline_offset_m / kFt},
      {"sink rate", "ft/s", [](const RunResult& r) { return r.figures.touchdown.sink_rate_mps / kFt; }, none,
       l.max_sink_rate_mps / kFt},
      {"bank", "deg", [](const RunResult& r) { return r.figures.touchdown.roll_rad / kDeg; },
       -l.max_bank_rad / kDeg, l.max_bank_rad / kDeg},
      {"pitch", "deg", [](const RunResult& r) { return r.figures.touchdown.pitch_rad / kDeg; }, none, none},
      {"heading - course", "deg",
       [](const RunResult& r) { return r.figures.touchdown.heading_minus_course_rad / kDeg; }, none, none},
      {"touchdown speed", "KCAS", [](const RunResult& r) { return r.figures.touchdown.cas_mps / kKt; }, none, none},
      {"stop beyond threshold", "m", [](const RunResult& r) { return r.figures.stop_beyond_threshold_m; }, none,
       none},
      {"rollout offset (max)", "m", [](const RunResult& r) { return r.figures.max_rollout_offset_m; }, none,
       l.runway_half_width_m},
  };
}

std::vector<double> values_of(const Figure& f, const std::vector<RunResult>& results) {
  std::vector<double> v;
  for (const RunResult& r : results) if (r.figures.touched_down) v.push_back(f.value(r));
  return v;
}

std::string limit_text(const Figure& f) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(1);
  if (std::isnan(f.limit_low) && std::isnan(f.limit_high)) return "";
  if (std::isnan(f.limit_low)) s << "< " << f.limit_high;
  else s << f.limit_low << " .. " << f.limit_high;
  return s.str();
}

}  // namespace

void write_percentiles_csv(std::ostream& out, const std::vector<RunResult>& results, const afcs::LandingLimits& limits) {
  out << "figure,unit,n,min,p1,p5,p50,p95,p99,max,limit_low,limit_high\n" << std::fixed << std::setprecision(3);
  for (const Figure& f : figures(limits)) {
    const std::vector<double> v = values_of(f, results);
    const Percentiles p = percentiles(v);
    out << '"' << f.name << "\"," << f.unit << ',' << v.size() << ',' << p.min << ',' << p.p1 << ',' << p.p5 << ','
        << p.p50 << ',' << p.p95 << ',' << p.p99 << ',' << p.max << ',' << f.limit_low << ',' << f.limit_high << '\n';
  }
}

void write_percentiles_markdown(std::ostream& out, const std::vector<RunResult>& results,
                                const afcs::LandingLimits& limits) {
  out << "| figure | unit | min | 1 % | 5 % | 50 % | 95 % | 99 % | max | limit |\n"
      << "|---|---|---|---|---|---|---|---|---|---|\n"
      << std::fixed << std::setprecision(1);
  for (const Figure& f : figures(limits)) {
    const Percentiles p = percentiles(values_of(f, results));
    out << "| " << f.name << " | " << f.unit << " | " << p.min << " | " << p.p1 << " | " << p.p5 << " | " << p.p50
        << " | " << p.p95 << " | " << p.p99 << " | " << p.max << " | " << limit_text(f) << " |\n";
  }
}

void write_scatter_gnuplot(std::ostream& out, const std::string& csv, const std::string& png,
                           const afcs::LandingLimits& l, const std::string& title) {
  const double x0 = l.min_beyond_threshold_m / kFt, x1 = l.max_beyond_threshold_m / kFt;
  const double y = l.max_centreline_offset_m / kFt;
  const double sink = l.max_sink_rate_mps / kFt, bank = l.max_bank_rad / kDeg;
  out << "set terminal pngcairo size 1400,600 noenhanced\n"
      << "set output '" << png << "'\n"
      << "set datafile separator ','\n"
      << "set key top right\n"
      << "set grid\n"
      << "set multiplot layout 1,2 title '" << title << "'\n"
      << "set title 'Touchdown position (main gear first contact)'\n"
      << "set xlabel 'beyond the threshold (ft)'\nset ylabel 'left of the runway centreline (ft)'\n"
      << "set xrange [0:3000]\nset yrange [-40:40]\n"
      << "set object 1 rect from " << x0 << ',' << -y << " to " << x1 << ',' << y
      << " fillstyle empty border lc rgb 'red' lw 2\n"
      << "plot '" << csv << "' every ::1 using 12:(strcol(6) eq 'none' ? $13 : 1/0) with points pt 7 ps 1 lc rgb '#1f77b4' title 'no turbulence', \\\n"
      << "     '' every ::1 using 12:(strcol(6) eq 'light' ? $13 : 1/0) with points pt 5 ps 1 lc rgb '#2ca02c' title 'light', \\\n"
      << "     '' every ::1 using 12:(strcol(6) eq 'moderate' ? $13 : 1/0) with points pt 9 ps 1.2 lc rgb '#d62728' title 'moderate', \\\n"
      << "     NaN with lines lc rgb 'red' lw 2 title 'limits (200-2700 ft, +-27 ft)'\n"
      << "unset object 1\n"
      << "set title 'Sink rate and bank at touchdown'\n"
      << "set xlabel 'bank (deg, + right wing down)'\nset ylabel 'sink rate (ft/s)'\n"
      << "set xrange [-8:8]\nset yrange [0:8]\n"
      << "set object 2 rect from " << -bank << ",0 to " << bank << ',' << sink
      << " fillstyle empty border lc rgb 'red' lw 2\n"
      << "plot '" << csv << "' every ::1 using 16:(strcol(6) eq 'none' ? $15 : 1/0) with points pt 7 ps 1 lc rgb '#1f77b4' title 'no turbulence', \\\n"
      << "     '' every ::1 using 16:(strcol(6) eq 'light' ? $15 : 1/0) with points pt 5 ps 1 lc rgb '#2ca02c' title 'light', \\\n"
      << "     '' every ::1 using 16:(strcol(6) eq 'moderate' ? $15 : 1/0) with points pt 9 ps 1.2 lc rgb '#d62728' title 'moderate', \\\n"
      << "     NaN with lines lc rgb 'red' lw 2 title 'limits (6 ft/s, +-5 deg)'\n"
      << "unset multiplot\n";
}

}  // namespace fedsim::flight::autoland
