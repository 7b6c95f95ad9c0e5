// CSV output of the batch flight program.
#include "flight/fly/csv_recorder.hpp"
#include "common/units/units.hpp"

#include <charconv>
#include <numbers>
#include <stdexcept>

namespace fedsim::flight {

namespace {
// 12 significant figures: 1e-5 m in ECEF, 1e-9 deg of latitude (0.1 mm); enough for the NASA
// check cases (millimetres) and still compact.
constexpr int kPrecision = 12;
using O = AircraftOutputs;
using C = AircraftControls;
}  // namespace

CsvRecorder::CsvRecorder(std::size_t engines, std::size_t contacts) {
  add_standard_columns();
  for (std::size_t e = 0; e < engines; ++e) add_engine_columns(e);
  add("mass_kg", [](const O& o, const C&) { return o.mass_kg; });
  add("fuel_kg", [](const O& o, const C&) { return o.fuel_kg; });
  add("cg_x_m", [](const O& o, const C&) { return o.cg_m.x(); });
  add("cg_y_m", [](const O& o, const C&) { return o.cg_m.y(); });
  add("cg_z_m", [](const O& o, const C&) { return o.cg_m.z(); });
  add("wow", [](const O& o, const C&) { return o.weight_on_wheels ? 1.0 : 0.0; });
  add("gear_fz_n", [](const O& o, const C&) { return o.gear_normal_force_n; });
  for (std::size_t c = 0; c < contacts; ++c) add_contact_columns(c);
  add("numerical_fault", [](const O& o, const C&) { return o.numerical_fault ? 1.0 : 0.0; });
}

CsvRecorder::~CsvRecorder() {
  if (file_) std::fclose(file_);
}

void CsvRecorder::add(std::string name, Value value) {
  columns_.push_back({std::move(name), std::move(value)});
}

void CsvRecorder::add_standard_columns() {
  add("time_s", [](const O& o, const C&) { return o.time_s; });
  // Position.
  add("lat_deg", [](const O& o, const C&) { return o.geodetic.lat_rad * units::kRadToDeg; });
  add("lon_deg", [](const O& o, const C&) { return o.geodetic.lon_rad * units::kRadToDeg; });
  add("alt_m", [](const O& o, const C&) { return o.geodetic.alt_m; });
  add("h_agl_m", [](const O& o, const C&) { return o.height_agl_m; });
  add("north_m", [](const O& o, const C&) { return o.north_m; });
  add("east_m", [](const O& o, const C&) { return o.east_m; });
  add("ecef_x_m", [](const O& o, const C&) { return o.position_ecef_m.x(); });
  add("ecef_y_m", [](const O& o, const C&) { return o.position_ecef_m.y(); });
  add("ecef_z_m", [](const O& o, const C&) { return o.position_ecef_m.z(); });
  // Velocity.
  add("vn_mps", [](const O& o, const C&) { return o.velocity_ned_mps.x(); });
  add("ve_mps", [](const O& o, const C&) { return o.velocity_ned_mps.y(); });
  add("vd_mps", [](const O& o, const C&) { return o.velocity_ned_mps.z(); });
  add("u_mps", [](const O& o, const C&) { return o.velocity_b_mps.x(); });
  add("v_mps", [](const O& o, const C&) { return o.velocity_b_mps.y(); });
  add("w_mps", [](const O& o, const C&) { return o.velocity_b_mps.z(); });
  add("ground_speed_mps", [](const O& o, const C&) { return o.ground_speed_mps; });
  add("climb_rate_mps", [](const O& o, const C&) { return o.climb_rate_mps; });
  // Attitude.
  add("phi_deg", [](const O& o, const C&) { return o.euler.phi_rad * units::kRadToDeg; });
  add("theta_deg", [](const O& o, const C&) { return o.euler.theta_rad * units::kRadToDeg; });
  add("psi_deg", [](const O& o, const C&) { return o.euler.psi_rad * units::kRadToDeg; });
  add("q0", [](const O& o, const C&) { return o.q_ned_to_body[0]; });
  add("q1", [](const O& o, const C&) { return o.q_ned_to_body[1]; });
  add("q2", [](const O& o, const C&) { return o.q_ned_to_body[2]; });
  add("q3", [](const O& o, const C&) { return o.q_ned_to_body[3]; });
  // Rates and accelerations.
  add("p_dps", [](const O& o, const C&) { return o.omega_b_rps.x() * units::kRadToDeg; });
  add("q_dps", [](const O& o, const C&) { return o.omega_b_rps.y() * units::kRadToDeg; });
  add("r_dps", [](const O& o, const C&) { return o.omega_b_rps.z() * units::kRadToDeg; });
  add("pdot_dps2", [](const O& o, const C&) { return o.omega_dot_b_rps2.x() * units::kRadToDeg; });
  add("qdot_dps2", [](const O& o, const C&) { return o.omega_dot_b_rps2.y() * units::kRadToDeg; });
  add("rdot_dps2", [](const O& o, const C&) { return o.omega_dot_b_rps2.z() * units::kRadToDeg; });
  add("ax_mps2", [](const O& o, const C&) { return o.acceleration_b_mps2.x(); });
  add("ay_mps2", [](const O& o, const C&) { return o.acceleration_b_mps2.y(); });
  add("az_mps2", [](const O& o, const C&) { return o.acceleration_b_mps2.z(); });
  add("udot_mps2", [](const O& o, const C&) { return o.velocity_b_dot_mps2.x(); });
  add("vdot_mps2", [](const O& o, const C&) { return o.velocity_b_dot_mps2.y(); });
  add("wdot_mps2", [](const O& o, const C&) { return o.velocity_b_dot_mps2.z(); });
  add("fx_eye_mps2", [](const O& o, const C&) { return o.specific_force_eye_b_mps2.x(); });
  add("fy_eye_mps2", [](const O& o, const C&) { return o.specific_force_eye_b_mps2.y(); });
  add("fz_eye_mps2", [](const O& o, const C&) { return o.specific_force_eye_b_mps2.z(); });
  add("nz_g", [](const O& o, const C&) { return o.load_factor_z; });
  // Air data.
  add("alpha_deg", [](const O& o, const C&) { return o.alpha_rad * units::kRadToDeg; });
  add("beta_deg", [](const O& o, const C&) { return o.beta_rad * units::kRadToDeg; });
  add("tas_mps", [](const O& o, const C&) { return o.tas_mps; });
  add("cas_mps", [](const O& o, const C&) { return o.cas_mps; });
  add("eas_mps", [](const O& o, const C&) { return o.eas_mps; });
  add("tas_kt", [](const O& o, const C&) { return o.tas_mps * units::kMpsToKt; });
  add("cas_kt", [](const O& o, const C&) { return o.cas_mps * units::kMpsToKt; });
  add("mach", [](const O& o, const C&) { return o.mach; });
  add("qbar_pa", [](const O& o, const C&) { return o.qbar_pa; });
  add("static_pressure_pa", [](const O& o, const C&) { return o.static_pressure_pa; });
  add("pressure_alt_m", [](const O& o, const C&) { return o.pressure_altitude_m; });
  add("temperature_k", [](const O& o, const C&) { return o.temperature_k; });
  add("density_kgpm3", [](const O& o, const C&) { return o.density_kgpm3; });
  add("wind_n_mps", [](const O& o, const C&) { return o.wind_ned_mps.x(); });
  add("wind_e_mps", [](const O& o, const C&) { return o.wind_ned_mps.y(); });
  add("wind_d_mps", [](const O& o, const C&) { return o.wind_ned_mps.z(); });
  // Commands (in force from this row's time) and surface positions.
  add("elevator_cmd", [](const O&, const C& c) { return c.elevator_command(); });
  add("aileron_cmd", [](const O&, const C& c) { return c.aileron_command(); });
  add("rudder_cmd", [](const O&, const C& c) { return c.rudder_command(); });
  add("flaps_cmd", [](const O&, const C& c) { return c.flaps; });
  add("gear_cmd", [](const O&, const C& c) { return c.gear_down ? 1.0 : 0.0; });
  add("brake_left_cmd", [](const O&, const C& c) { return c.brake_left; });
  add("brake_right_cmd", [](const O&, const C& c) { return c.brake_right; });
  add("steering_cmd", [](const O&, const C& c) { return c.steering; });
  add("elevator_deg", [](const O& o, const C&) { return o.elevator_rad * units::kRadToDeg; });
  add("aileron_deg", [](const O& o, const C&) { return o.aileron_rad * units::kRadToDeg; });
  add("rudder_deg", [](const O& o, const C&) { return o.rudder_rad * units::kRadToDeg; });
  add("flap_norm", [](const O& o, const C&) { return o.flap_norm; });
  add("flap_deg", [](const O& o, const C&) { return o.flap_rad * units::kRadToDeg; });
  add("speedbrake_norm", [](const O& o, const C&) { return o.speedbrake_norm; });
  add("spoiler_norm", [](const O& o, const C&) { return o.spoiler_norm; });
  add("gear_norm", [](const O& o, const C&) { return o.gear_norm; });
  // Aerodynamic coefficients and the total force and moment (body axes, about the CG).
  add("cl", [](const O& o, const C&) { return o.aero.CL; });
  add("cd", [](const O& o, const C&) { return o.aero.CD; });
  add("cy", [](const O& o, const C&) { return o.aero.CY; });
  add("croll", [](const O& o, const C&) { return o.aero.Cl; });
  add("cm", [](const O& o, const C&) { return o.aero.Cm; });
  add("cn", [](const O& o, const C&) { return o.aero.Cn; });
  add("stalled", [](const O& o, const C&) { return o.stalled ? 1.0 : 0.0; });
  add("fx_n", [](const O& o, const C&) { return o.total_force_b_n.x(); });
  add("fy_n", [](const O& o, const C&) { return o.total_force_b_n.y(); });
  add("fz_n", [](const O& o, const C&) { return o.total_force_b_n.z(); });
  add("mx_nm", [](const O& o, const C&) { return o.total_moment_b_nm.x(); });
  add("my_nm", [](const O& o, const C&) { return o.total_moment_b_nm.y(); });
  add("mz_nm", [](const O& o, const C&) { return o.total_moment_b_nm.z(); });
  add("thrust_n", [](const O& o, const C&) { return o.total_thrust_n; });
}

void CsvRecorder::add_engine_columns(std::size_t e) {
  const std::string p = "eng" + std::to_string(e + 1) + "_";
  add(p + "throttle_cmd", [e](const O&, const C& c) { return c.throttle[e]; });
  add(p + "running", [e](const O& o, const C&) { return o.engines[e].running ? 1.0 : 0.0; });
  add(p + "thrust_n", [e](const O& o, const C&) { return o.engines[e].thrust_n; });
  add(p + "rpm", [e](const O& o, const C&) { return o.engines[e].rpm; });
  add(p + "n1_pct", [e](const O& o, const C&) { return o.engines[e].n1_pct; });
  add(p + "n2_pct", [e](const O& o, const C&) { return o.engines[e].n2_pct; });
  add(p + "map_pa", [e](const O& o, const C&) { return o.engines[e].manifold_pressure_pa; });
  add(p + "power_w", [e](const O& o, const C&) { return o.engines[e].power_w; });
  add(p + "fuel_flow_kgps", [e](const O& o, const C&) { return o.engines[e].fuel_flow_kgps; });
}

void CsvRecorder::add_contact_columns(std::size_t i) {
  const std::string p = "gear" + std::to_string(i + 1) + "_";
  add(p + "wow", [i](const O& o, const C&) { return o.contacts[i].weight_on_wheels ? 1.0 : 0.0; });
  add(p + "compression_m", [i](const O& o, const C&) { return o.contacts[i].compression_m; });
  add(p + "force_n", [i](const O& o, const C&) { return o.contacts[i].normal_force_n; });
}

std::vector<std::string> CsvRecorder::column_names() const {
  std::vector<std::string> names;
  for (const Column& c : columns_) names.push_back(c.name);
  return names;
}

void CsvRecorder::open(const std::string& path) {
  path_ = path;
  file_ = std::fopen(path.c_str(), "w");
  if (!file_) throw std::runtime_error(path + ": cannot open for writing");
  std::string header;
  for (const Column& c : columns_) header += (header.empty() ? "" : ",") + c.name;
  header += '\n';
  std::fputs(header.c_str(), file_);
}

void CsvRecorder::write(const AircraftOutputs& outputs, const AircraftControls& controls) {
  line_.clear();
  char buffer[32];
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    if (i > 0) line_ += ',';
    const auto result =
        std::to_chars(buffer, buffer + sizeof buffer, columns_[i].value(outputs, controls),
                      std::chars_format::general, kPrecision);
    line_.append(buffer, result.ptr);
  }
  line_ += '\n';
  std::fwrite(line_.data(), 1, line_.size(), file_);
}

void CsvRecorder::close() {
  if (!file_) return;
  const bool failed = std::ferror(file_) != 0;
  const bool close_failed = std::fclose(file_) != 0;
  file_ = nullptr;
  if (failed || close_failed) throw std::runtime_error(path_ + ": write error");
}

}  // namespace fedsim::flight
