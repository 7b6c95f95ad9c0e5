// NASA atmospheric check cases through fedsim-fly.
#include "fly_check_case.hpp"
#include "common/util/build_paths.hpp"
#include "common/units/units.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "common/util/child_process.hpp"
#include "common/csv/csv_reader.hpp"

namespace fedsim::flight::nasa {

namespace {
constexpr double kEquatorialRadiusM = 6378137.0;  // WGS-84 a, as nasa_reference.cpp
constexpr double kDurationS = 30.0;
}  // namespace

std::vector<FlyCheckCase> fly_check_cases() {
  return {
      {"Atmos_01", "dropped sphere, no drag (fedsim-fly)", "nasa_sphere"},
      {"Atmos_02", "tumbling brick, no damping (fedsim-fly)", "nasa_brick"},
      {"Atmos_03", "tumbling brick with damping (fedsim-fly)", "nasa_brick_damped"},
      {"Atmos_06", "sphere with drag (fedsim-fly)", "nasa_sphere_drag"},
      {"Atmos_07", "sphere in a 20 ft/s wind from the west (fedsim-fly)", "nasa_sphere_drag"},
      {"Atmos_09", "cannonball fired eastward (fedsim-fly)", "nasa_sphere_drag"},
      {"Atmos_10", "cannonball fired northward (fedsim-fly)", "nasa_sphere_drag"},
  };
}

TimeHistory nasa_channels_from_fly_csv(const std::string& csv_path) {
  // fedsim-fly records fedsim/aircraft_state as fedsim record does: SI columns named after the
  // IDL fields (idl/aircraft_state.idl), time first.
  const csv::NumericTable csv = csv::NumericTable::load(csv_path);
  TimeHistory history({"altitude_m", "north_m", "east_m", "v_north_mps", "v_east_mps", "v_down_mps",
                       "phi_rad", "theta_rad", "psi_rad", "p_radps", "q_radps", "r_radps", "lat_rad",
                       "lon_rad"});
  const auto& t = csv.column("sim_time_s");
  const auto& lat = csv.column("latitude_rad");
  const auto& lon = csv.column("longitude_rad");
  const auto& alt = csv.column("altitude_msl_m");
  const auto& vn = csv.column("velocity_ned_mps[0]");
  const auto& ve = csv.column("velocity_ned_mps[1]");
  const auto& vd = csv.column("velocity_ned_mps[2]");
  const auto& phi = csv.column("phi_rad");
  const auto& theta = csv.column("theta_rad");
  const auto& psi = csv.column("psi_rad");
  const auto& p = csv.column("omega_body_radps[0]");
  const auto& q = csv.column("omega_body_radps[1]");
  const auto& r = csv.column("omega_body_radps[2]");
  if (csv.rows() == 0) throw std::runtime_error(csv_path + ": no rows");
  // Arc lengths as NasaReference makes them: from the equator, and from the meridian at the
  // starting latitude's parallel.
  const double cos_lat0 = std::cos(lat.front());
  for (std::size_t i = 0; i < csv.rows(); ++i) {
    history.append(t[i], {alt[i], lat[i] * kEquatorialRadiusM, lon[i] * kEquatorialRadiusM * cos_lat0,
                          vn[i], ve[i], vd[i], phi[i], theta[i], psi[i], p[i], q[i], r[i], lat[i],
                          lon[i]});
  }
  return history;
}

TimeHistory fly_case(const FlyCheckCase& c, const std::string& work_dir) {
  const std::string out_dir = work_dir + "/" + c.id;
  const std::string ic = fedsim::util::test_data_dir() + "/nasa/" + c.id + "/ic.yaml";
  // RK4 at 100 Hz as the direct rigid-body runs; the answers are converged in the step.
  // NASA defines the brick's damping with body rates relative to inertial space (SOURCE.md);
  // fedsim's default, rates relative to the air mass turning with the earth, differs by the
  // earth's rate (7.3e-5 rad/s), which case 3 would show 7000 times over its 1e-8 rad/s margin.
  util::ChildProcess fly({(fedsim::util::bin_dir() + "/fedsim-fly"), "--aircraft", c.pack, "--ic", ic, "--earth", "wgs84",
                          "--aero-rates", "inertial", "--integrator", "rk4", "--rate", "100",
                          "--duration", std::to_string(kDurationS), "--out", out_dir, "--quiet"},
                         work_dir + "/" + c.id + ".log");
  if (!fly.wait(120.0) || fly.exit_code() != 0) {
    throw std::runtime_error("fedsim-fly failed on " + c.id + " (exit " +
                             std::to_string(fly.exit_code()) + "): " + fly.output());
  }
  return nasa_channels_from_fly_csv(out_dir + "/fedsim_aircraft_state.csv");
}

}  // namespace fedsim::flight::nasa
