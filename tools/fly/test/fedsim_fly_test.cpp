// Runs the built fedsim-fly: trim JSON and the recorded topics (fedsim record's CSV files), exit
// codes for bad input and failed trims (and no output then), input profiles absolute and
// relative, IC files, and bit-identical repeats.
#include <gtest/gtest.h>
#include "common/util/build_paths.hpp"
#include "common/units/units.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "common/util/child_process.hpp"
#include "common/csv/csv_reader.hpp"

namespace fedsim::fly {
namespace {

namespace fs = std::filesystem;

constexpr double kKt = units::kKtToMps;

struct FlyRun {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

class FedsimFly : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = util::temp_dir(
        "fedsim-fly-test-" +
        std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return dir_ + "/" + name; }

  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path(name)) << text;
    return path(name);
  }

  FlyRun fly(std::vector<std::string> args) const {
    args.insert(args.begin(), (fedsim::util::bin_dir() + "/fedsim-fly"));
    util::ChildProcess child(args, path("fly.log"));
    FlyRun run;
    EXPECT_TRUE(child.wait(120.0)) << "fedsim-fly did not finish";
    run.exit_code = child.exit_code();
    run.output = child.output();
    return run;
  }

  /// The JSON object fedsim-fly printed on a line of its own.
  static nlohmann::json json_of(const std::string& output) {
    std::istringstream lines(output);
    for (std::string line; std::getline(lines, line);) {
      if (!line.empty() && line.front() == '{') return nlohmann::json::parse(line);
    }
    ADD_FAILURE() << "no JSON line in: " << output;
    return {};
  }

  /// The recorded aircraft state and engine state of a run into `dir`.
  static csv::NumericTable state(const std::string& dir) {
    return csv::NumericTable::load(dir + "/fedsim_aircraft_state.csv");
  }
  static csv::NumericTable engine(const std::string& dir) {
    return csv::NumericTable::load(dir + "/fedsim_engine_state.csv");
  }

  std::vector<std::string> level_trim() const {
    return {"--aircraft", "c172",      "--trim", "level", "--alt-ft", "4000",  "--ktas",
            "100",        "--heading", "90",     "--lat", "28",       "--lon", "-90"};
  }

  static std::vector<std::string> join(std::vector<std::string> a,
                                       const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  }

  std::string dir_;
};

TEST_F(FedsimFly, TrimsPrintsJsonAndWritesOneRowPerFrame) {
  const std::string out = path("level");
  const FlyRun run = fly(join(level_trim(), {"--duration", "10", "--rate", "50", "--out", out}));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json trim = json_of(run.output);
  EXPECT_TRUE(trim["converged"].get<bool>());
  EXPECT_EQ(trim["kind"], "level");
  EXPECT_NEAR(trim["tas_kt"].get<double>(), 100.0, 1e-9);
  EXPECT_NEAR(trim["altitude_ft"].get<double>(), 4000.0, 1e-6);
  for (const char* key : {"alpha_deg", "theta_deg", "elevator", "aileron", "rudder", "throttle",
                          "elevator_deg", "thrust_n"}) {
    EXPECT_TRUE(trim.contains(key)) << key;
  }
  for (const auto& [axis, value] : trim["residuals"].items()) {
    EXPECT_LT(std::abs(value.get<double>()), 1e-4) << axis;
  }
  EXPECT_EQ(trim["residuals"].size(), 6u);

  const csv::NumericTable csv = state(out);
  ASSERT_EQ(csv.rows(), 501u);  // t = 0 and 500 frames of 20 ms
  EXPECT_DOUBLE_EQ(csv.column("sim_time_s").front(), 0.0);
  EXPECT_NEAR(csv.column("sim_time_s")[1], 0.02, 1e-12);
  EXPECT_NEAR(csv.column("sim_time_s").back(), 10.0, 1e-9);
  EXPECT_EQ(csv.column("stamp.frame").back(), 500.0);
  EXPECT_NEAR(csv.column("altitude_msl_m").front(), 1219.2, 1e-6);
  EXPECT_NEAR(csv.column("latitude_rad").front(), 28.0 * units::kDegToRad, 1e-12);
  EXPECT_NEAR(csv.column("air.tas_mps").front(), 100.0 * kKt, 1e-6);
  EXPECT_NEAR(csv.column("psi_rad").front(), units::kHalfPi, 1e-12);
  EXPECT_NEAR(csv.column("controls.elevator").front(), trim["elevator"].get<double>(), 1e-9);
  EXPECT_NEAR(csv.column("controls.throttle[0]").front(), trim["throttle"].get<double>(), 1e-9);
  EXPECT_NEAR(csv.column("altitude_msl_m").back(), 1219.2, 1.0);  // trimmed: holds its height
  const csv::NumericTable eng = engine(out);
  ASSERT_EQ(eng.rows(), 501u);
  EXPECT_GT(eng.column("rpm").front(), 1500.0);  // settled at the trimmed throttle
  EXPECT_GT(eng.column("exhaust_temperature_k").front(), 800.0);
  for (const char* column :
       {"position_ecef_m[0]", "velocity_ned_mps[0]", "velocity_body_mps[0]", "omega_body_radps[0]",
        "q_ned_from_body[0]", "air.alpha_rad", "air.cas_mps", "air.mach", "air.qbar_pa",
        "total_thrust_n", "mass_kg", "gear_normal_force_n", "gear[0].normal_force_n",
        "specific_force_eye_body_mps2[2]", "aero.lift", "force_body_n[2]", "moment_body_nm[1]",
        "cg_pack_m[0]", "load_factor_z", "north_m", "dropped_steps"}) {
    EXPECT_TRUE(csv.has(column)) << column;
  }
  EXPECT_FALSE(fs::exists(out + "/fedsim_pilot_controls.csv"));  // no --inputs, no I/O component
}

TEST_F(FedsimFly, RecordsTheColumnsFedsimRecordWrites) {
  const std::string out = path("columns");
  ASSERT_EQ(fly(join(level_trim(), {"--duration", "0.1", "--rate", "10", "--out", out, "--quiet"}))
                .exit_code,
            0);
  // The recorder's layout (tools/topic/csv_layout.hpp): time first, then every IDL field
  // flattened in declaration order, named after it (units in the names, SI).
  const std::string header = util::read_file(out + "/fedsim_aircraft_state.csv").substr(0, 80);
  EXPECT_EQ(header.rfind("sim_time_s,aircraft_id,stamp.frame,stamp.sim_time_s,latitude_rad,", 0), 0u)
      << header;
  EXPECT_EQ(state(out).rows(), 2u);
}

TEST_F(FedsimFly, ATrimOutOfReachExitsThreeWithTheReasonAndNoCsv) {
  const std::string out = path("fast");
  const FlyRun run = fly({"--aircraft", "c172", "--trim", "level", "--alt-ft", "4000", "--ktas",
                          "160", "--duration", "10", "--rate", "50", "--out", out});
  EXPECT_EQ(run.exit_code, 3) << run.output;
  EXPECT_NE(
      run.output.find("throttle saturated at 1.0: the aircraft cannot hold 4000 ft at 160 KTAS"),
      std::string::npos)
      << run.output;
  EXPECT_FALSE(json_of(run.output)["converged"].get<bool>());
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(FedsimFly, BadInputExitsTwoWithAMessageAndNoCsv) {
  const std::string out = path("bad");
  const std::string bad_profile = write("bad_profile.csv", "time_s, elevator\n0, 0\n1, banana\n");
  const std::string unknown_channel = write("unknown.csv", "time_s, wheel\n0, 0\n");
  const std::string bad_ic = write("bad_ic.yaml",
                                   "fedsim_initial_conditions: 1\n"
                                   "position: {lat_deg: 0, lon_deg: 0, alt_m: 100}\n"
                                   "velocity_ned_mps: [50, 0]\n");
  struct Case {
    std::vector<std::string> args;
    std::string says;
  };
  const std::vector<Case> cases = {
      {{"--aircraft", "concorde", "--trim", "level", "--ktas", "100"},
       "unknown aircraft pack 'concorde'"},
      {join(level_trim(), {"--warp-drive"}), "--warp-drive"},
      {join(level_trim(), {"--inputs", bad_profile}), "bad_profile.csv:3"},
      {join(level_trim(), {"--inputs", unknown_channel}), "wheel"},
      {join(level_trim(), {"--inputs", path("missing.csv")}), "missing.csv"},
      {join(level_trim(), {"--inputs-relative"}), "--inputs-relative needs --inputs"},
      {{"--aircraft", "c172", "--ic", bad_ic}, "bad_ic.yaml:3: velocity_ned_mps"},
      {{"--aircraft", "c172", "--trim", "level"}, "--ktas or --kcas"},
      {{"--aircraft", "c172", "--trim", "spin", "--ktas", "100"}, "--trim"},
      {join(level_trim(), {"--integrator", "verlet"}), "--integrator"},
      {{"--aircraft", "c172", "--trim", "ground", "--throttle", "nan"}, "--throttle"},
      {{"--aircraft", "c172", "--trim", "ground", "--throttle", "inf"}, "--throttle"},
      {{"--aircraft", "c172", "--trim", "ground", "--throttle", "1.5"}, "--throttle"},
      {{"--aircraft", "c172", "--trim", "ground", "--throttle", "-0.1"}, "--throttle"},
      {join(level_trim(), {"--throttle", "0.5"}), "--throttle sets the engines of a ground start"},
      // Start numbers out of range or not finite (the heading once flew at 1e300).
      {{"--aircraft", "c172", "--trim", "level", "--ktas", "100", "--heading", "1e300"}, "--heading"},
      {{"--aircraft", "c172", "--trim", "level", "--ktas", "nan"}, "--ktas"},
      {{"--aircraft", "c172", "--trim", "level", "--ktas", "100", "--alt-ft", "inf"}, "--alt-ft"},
      {{"--aircraft", "c172", "--trim", "turn", "--ktas", "100", "--bank-deg", "95"}, "--bank-deg"},
      {{"--aircraft", "c172", "--trim", "climb", "--ktas", "100", "--gamma-deg", "nan"}, "--gamma-deg"},
      {{"--aircraft", "c172", "--trim", "ground", "--runway-elevation-m", "-1e9"}, "--runway-elevation-m"},
  };
  for (const Case& c : cases) {
    const FlyRun run = fly(join(c.args, {"--duration", "1", "--rate", "50", "--out", out}));
    EXPECT_EQ(run.exit_code, 2) << c.says << "\n" << run.output;
    EXPECT_NE(run.output.find(c.says), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(out)) << c.says;
  }
  // Not a number (CLI11's own range check lets NaN through; fedsim's FiniteRange does not).
  const FlyRun nan_duration = fly(join(level_trim(), {"--duration", "nan", "--rate", "50", "--out", out}));
  EXPECT_EQ(nan_duration.exit_code, 2);
  EXPECT_NE(nan_duration.output.find("--duration: 'nan' is not a finite number"), std::string::npos)
      << nan_duration.output;
  EXPECT_FALSE(fs::exists(out));
  // Required options.
  EXPECT_EQ(fly(join(level_trim(), {"--rate", "50", "--out", out})).exit_code, 2);
  EXPECT_FALSE(fs::exists(out));
  // --help is not an error.
  const FlyRun help = fly({"--help"});
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.output.find("--inputs-relative"), std::string::npos);
}

TEST_F(FedsimFly, ARelativeProfileFliesAboutTheTrim) {
  const std::string profile = write("doublet.csv",
                                    "# elevator doublet about the trim\n"
                                    "time_s, elevator\n"
                                    "0.0, 0.0\n1.0, 0.0\n1.0, -0.1\n2.0, -0.1\n2.0, 0.1\n3.0, 0.1\n"
                                    "3.0, 0.0\n");
  const std::string out = path("doublet");
  const FlyRun run = fly(join(level_trim(), {"--inputs", profile, "--inputs-relative", "--duration",
                                             "20", "--rate", "100", "--out", out, "--quiet"}));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const double trimmed = json_of(run.output)["elevator"].get<double>();
  const csv::NumericTable csv = state(out);
  const auto& t = csv.column("sim_time_s");
  const auto& elevator = csv.column("controls.elevator");
  const auto& q = csv.column("omega_body_radps[1]");
  double q_max = 0.0;
  constexpr double kDt = 0.01;
  for (std::size_t i = 1; i < csv.rows(); ++i) {
    // The row at t holds the controls flown from t - dt to t; as in the federation they were
    // sampled by the I/O component one frame earlier, at t - 2 dt (the first at 0).
    const double sampled = std::max(0.0, t[i] - 2.0 * kDt);
    const double expected = sampled < 1.0 - 1e-9   ? 0.0
                            : sampled < 2.0 - 1e-9 ? -0.1
                            : sampled < 3.0 - 1e-9 ? 0.1
                                                   : 0.0;
    ASSERT_NEAR(elevator[i], trimmed + expected, 1e-6) << "t = " << t[i];
    q_max = std::max(q_max, q[i]);
  }
  EXPECT_GT(q_max, 2.0 * units::kDegToRad);  // stick back: nose up
  // The throttle the profile does not drive stays at the trim.
  EXPECT_NEAR(csv.column("controls.throttle[0]").back(),
              json_of(run.output)["throttle"].get<double>(), 1e-6);
  // The I/O component's own recording: the profile as sampled, frame by frame.
  const csv::NumericTable pilot = csv::NumericTable::load(out + "/fedsim_pilot_controls.csv");
  EXPECT_EQ(pilot.rows(), csv.rows());
}

TEST_F(FedsimFly, AnAbsoluteProfileSetsEveryChannel) {
  // Absolute: the profile is the inceptors. Channels it does not name keep the start's
  // (trimmed) controls.
  const std::string profile =
      write("idle.csv", "time_s, throttle, flaps\n0, 0.0, 0.0\n5, 0.0, 1.0\n");
  const std::string out = path("idle");
  ASSERT_EQ(fly(join(level_trim(), {"--inputs", profile, "--duration", "6", "--rate", "50", "--out",
                                    out, "--quiet"}))
                .exit_code,
            0);
  const csv::NumericTable csv = state(out);
  EXPECT_EQ(csv.column("controls.throttle[0]")[2], 0.0);
  const double trimmed_elevator = csv.column("controls.elevator")[0];
  EXPECT_GT(std::fabs(trimmed_elevator), 0.01);  // the trim moved it (the check below can fail)
  EXPECT_NEAR(csv.column("controls.elevator")[2], trimmed_elevator, 1e-6);  // sent as a float
  // Ramp: half way at 2.5 s, sampled two frames before the row that flies it.
  EXPECT_NEAR(csv.column("controls.flaps")[127], 0.5, 1e-6);
  const csv::NumericTable eng = engine(out);
  EXPECT_LT(eng.column("rpm").back(), eng.column("rpm").front() - 300.0);
  EXPECT_NEAR(csv.column("flap_norm").back(), 1.0, 1e-9);  // 4 s of transit for full flap
}

TEST_F(FedsimFly, StartsFromAnInitialConditionFile) {
  const std::string ic = write("c172.yaml",
                               "fedsim_initial_conditions: 1\n"
                               "position: {lat_deg: 45, lon_deg: 7, alt_ft: 6000}\n"
                               "velocity_body_mps: [50, 0, 2]\n"
                               "attitude_deg: {phi: 10, theta: 0, psi: 180}\n"
                               "controls: {throttle: 0.75, elevator: 0.1, flaps: 0.5}\n"
                               "weather:\n"
                               "  wind: [{alt_m: 0, speed_mps: 10, from_deg: 180}]\n");
  const std::string out = path("ic");
  const FlyRun run = fly({"--aircraft", "c172", "--ic", ic, "--duration", "2", "--rate", "100",
                          "--integrator", "ab2", "--out", out, "--quiet"});
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(run.output.find('{'), std::string::npos);  // no trim, no JSON
  const csv::NumericTable csv = state(out);
  EXPECT_NEAR(csv.column("latitude_rad").front(), 45.0 * units::kDegToRad, 1e-12);
  EXPECT_NEAR(csv.column("altitude_msl_m").front(), 6000.0 * units::kFtToM, 1e-6);
  EXPECT_NEAR(csv.column("velocity_body_mps[0]").front(), 50.0, 1e-9);
  EXPECT_NEAR(csv.column("phi_rad").front(), 10.0 * units::kDegToRad, 1e-12);
  // 10 m/s of headwind on 50 m/s southward; rolled, (v, w) keep their 2 m/s.
  EXPECT_NEAR(csv.column("air.tas_mps").front(), std::hypot(60.0, 2.0), 1e-6);
  EXPECT_NEAR(csv.column("controls.throttle[0]").front(), 0.75, 1e-12);
  EXPECT_NEAR(csv.column("flap_norm").front(), 0.5, 1e-12);  // surfaces start where they point
  // The engine starts settled at the file's throttle and airspeed, not spooling up from idle
  // (thousands of rpm per second): in the first 0.1 s its rpm hardly moves.
  const csv::NumericTable eng = engine(out);
  EXPECT_GT(eng.column("rpm").front(), 2000.0);
  EXPECT_NEAR(eng.column("rpm")[10], eng.column("rpm").front(), 5.0);
}

TEST_F(FedsimFly, SameSeedSameBytesWithTurbulence) {
  auto turbulent = [&](const std::string& name, const std::string& seed) {
    const std::string out = path(name);
    const FlyRun run =
        fly(join(level_trim(), {"--turbulence", "moderate", "--seed", seed, "--integrator", "ab2",
                                "--duration", "30", "--rate", "100", "--out", out, "--quiet"}));
    EXPECT_EQ(run.exit_code, 0) << run.output;
    return util::read_file(out + "/fedsim_aircraft_state.csv");
  };
  const std::string a = turbulent("a", "5");
  const std::string b = turbulent("b", "5");
  const std::string c = turbulent("c", "6");
  ASSERT_GT(a.size(), 100000u);
  EXPECT_TRUE(a == b) << "two runs with seed 5 differ";
  EXPECT_FALSE(a == c) << "seeds 5 and 6 gave the same turbulence";
  // And the turbulence is really there: the wind column moves.
  const csv::NumericTable csv = state(path("a"));
  const auto& wind = csv.column("air.wind_ned_mps[2]");
  EXPECT_GT(
      *std::max_element(wind.begin(), wind.end()) - *std::min_element(wind.begin(), wind.end()),
      0.5);
}

TEST_F(FedsimFly, OutputEveryNthFrame) {
  const std::string out = path("sparse");
  ASSERT_EQ(fly(join(level_trim(), {"--duration", "10", "--rate", "100", "--output-every", "25",
                                    "--out", out, "--quiet"}))
                .exit_code,
            0);
  const csv::NumericTable csv = state(out);
  EXPECT_EQ(csv.rows(), 41u);
  EXPECT_NEAR(csv.column("sim_time_s")[1], 0.25, 1e-12);
  EXPECT_NEAR(csv.column("sim_time_s").back(), 10.0, 1e-9);
  // An odd duration: the last frame is kept although it is not a multiple of 25.
  ASSERT_EQ(fly(join(level_trim(), {"--duration", "10.03", "--rate", "100", "--output-every", "25",
                                    "--out", out + "_odd", "--quiet"}))
                .exit_code,
            0);
  const csv::NumericTable odd = state(out + "_odd");
  EXPECT_EQ(odd.rows(), 42u);
  EXPECT_NEAR(odd.column("sim_time_s").back(), 10.03, 1e-9);
}

TEST_F(FedsimFly, GroundTrimOnARaisedRunway) {
  const std::string out = path("ground");
  const FlyRun run =
      fly({"--aircraft", "b737", "--trim", "ground", "--runway-elevation-m", "430", "--heading",
           "120", "--duration", "5", "--rate", "50", "--out", out, "--quiet"});
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(json_of(run.output)["converged"].get<bool>());
  const csv::NumericTable csv = state(out);
  EXPECT_EQ(csv.column("weight_on_wheels").back(), 1.0);
  EXPECT_GT(csv.column("altitude_msl_m").back(), 430.0);
  EXPECT_LT(csv.column("height_agl_m").back(), 3.0);
  EXPECT_LT(csv.column("ground_speed_mps").back(), 0.05);
  EXPECT_EQ(csv.column("controls.brake_left").back(), 1.0);
}

TEST_F(FedsimFly, GroundTrimWithTheEngineAtFullThrottleOnTheBrakes) {
  // A take-off start: parked, brakes set, the engine settled at full throttle.
  const std::string out = path("runup");
  const FlyRun run = fly({"--aircraft", "c172", "--trim", "ground", "--throttle", "1",
                          "--duration", "2", "--rate", "50", "--out", out, "--quiet"});
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(json_of(run.output)["converged"].get<bool>());
  EXPECT_EQ(json_of(run.output)["throttle"].get<double>(), 1.0);
  const csv::NumericTable csv = state(out);
  EXPECT_EQ(csv.column("controls.throttle[0]").front(), 1.0);
  EXPECT_EQ(csv.column("controls.brake_left").front(), 1.0);
  // Settled at the start: full-throttle static rpm (far above the 550 rpm idle) from row 0.
  const csv::NumericTable eng = engine(out);
  EXPECT_GT(eng.column("rpm").front(), 2000.0);
  EXPECT_NEAR(eng.column("rpm").back(), eng.column("rpm").front(), 5.0);
  EXPECT_GT(eng.column("thrust_n").front(), 1000.0);
  // Held by the brakes: inside the gear's viscous friction band (0.25 m/s), where a braked
  // wheel under a steady push creeps instead of sliding (data/aircraft/README.md).
  EXPECT_LT(csv.column("ground_speed_mps").back(), 0.25);
}

TEST_F(FedsimFly, ClimbAndTurnTrims) {
  const std::string out = path("x");
  FlyRun run =
      fly({"--aircraft", "b737", "--trim", "climb", "--alt-ft", "10000", "--kcas", "250",
           "--gamma-deg", "3", "--duration", "1", "--rate", "50", "--out", out, "--quiet"});
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NEAR(json_of(run.output)["flight_path_deg"].get<double>(), 3.0, 1e-6);
  EXPECT_NEAR(json_of(run.output)["cas_kt"].get<double>(), 250.0, 1e-6);
  run = fly({"--aircraft", "c172", "--trim", "turn", "--bank-deg", "30", "--alt-ft", "4000",
             "--ktas", "100", "--duration", "1", "--rate", "50", "--out", out, "--quiet"});
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json trim = json_of(run.output);
  EXPECT_NEAR(trim["phi_deg"].get<double>(), 30.0, 1e-9);
  EXPECT_NEAR(trim["turn_rate_dps"].get<double>(),
              units::kStandardGravityMps2 * std::tan(30.0 * units::kPi / 180.0) / (100.0 * kKt) * 180.0 / units::kPi, 0.05);
}

TEST_F(FedsimFly, ARelativeProfileKeepsTheTrimsGearLever) {
  // A 737 trimmed gear up, flown with a profile that names only the elevator: the gear stays up.
  // Negative control: the same profile naming gear_down lowers it (the column can move).
  const std::string pulse = write("pulse.csv", "time_s, elevator\n0, 0\n1, 0\n1, -0.05\n2, -0.05\n2, 0\n");
  const std::string lowered = write("gear.csv", "time_s, elevator, gear_down\n0, 0, 1\n");
  const std::vector<std::string> start = {"--aircraft", "b737", "--trim", "level", "--alt-ft", "10000",
                                          "--kcas", "250", "--duration", "4", "--rate", "50", "--quiet"};
  for (const auto& [profile, gear] : {std::pair{pulse, 0.0}, std::pair{lowered, 1.0}}) {
    const std::string out = path(gear == 0.0 ? "up" : "down");
    const FlyRun run = fly(join(start, {"--inputs", profile, "--inputs-relative", "--out", out}));
    ASSERT_EQ(run.exit_code, 0) << run.output;
    const csv::NumericTable csv = state(out);
    EXPECT_EQ(csv.column("controls.gear_down").front(), 0.0);
    EXPECT_EQ(csv.column("controls.gear_down").back(), gear) << profile;
  }
}

TEST_F(FedsimFly, TheStallEntryPilotDeceleratesAtItsRateAndIdentifiesTheStall) {
  // The C172 from 65 KCAS at idle, wings level: about the entry rate asked for, then the stall
  // identified (this pack ends its entry with the elevator at the aft stop) and recovered.
  // Negative control: half the entry rate halves the deceleration.
  const std::vector<std::string> start = {"--aircraft", "c172", "--trim", "level", "--alt-ft", "3000",
                                          "--kcas", "65", "--pilot", "stall-entry", "--duration", "60",
                                          "--rate", "50"};
  double rates[2] = {0, 0};
  for (int i = 0; i < 2; ++i) {
    const std::string rate = i == 0 ? "1" : "0.5";
    const std::string out = path("stall" + rate);
    const FlyRun run = fly(join(start, {"--entry-rate-kt-s", rate, "--out", out}));
    ASSERT_EQ(run.exit_code, 0) << run.output;
    const csv::NumericTable csv = state(out);
    const auto& t = csv.column("sim_time_s");
    const auto& cas = csv.column("air.cas_mps");
    const auto at = [&](double time) {  // the first row at or after `time`
      return static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), time - 1e-9) - t.begin());
    };
    rates[i] = (cas[at(5)] - cas[at(20)]) / kKt / 15.0;  // kt/s over the steady part of the entry
    EXPECT_EQ(csv.column("controls.throttle[0]")[at(10)], 0.0);
    EXPECT_LT(std::fabs(csv.column("phi_rad")[at(20)]), 2.0 * units::kDegToRad);  // wings level
    if (i == 0) {
      EXPECT_NE(run.output.find("stall entry: stall identified at"), std::string::npos) << run.output;
      EXPECT_NE(run.output.find("(elevator at the aft stop)"), std::string::npos) << run.output;
      EXPECT_EQ(csv.column("controls.throttle[0]").back(), 1.0);  // recovered with power
      EXPECT_GT(cas.back(), cas[at(30)]);
    }
  }
  EXPECT_NEAR(rates[0], 1.0, 0.25);
  EXPECT_NEAR(rates[1], 0.5, 0.15);
}

TEST_F(FedsimFly, ThePilotRefusesRelativeControlsAndBadSettings) {
  const std::string profile = write("p.csv", "time_s, flaps\n0, 0\n");
  FlyRun run = fly(join(level_trim(), {"--pilot", "stall-entry", "--inputs", profile, "--inputs-relative",
                                       "--duration", "1", "--rate", "50", "--out", path("r")}));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.output.find("--pilot flies absolute controls"), std::string::npos) << run.output;
  run = fly(join(level_trim(), {"--pilot", "stall-entry", "--entry-rate-kt-s", "nan", "--duration", "1",
                                "--rate", "50", "--out", path("n")}));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.output.find("--entry-rate-kt-s"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace fedsim::fly
