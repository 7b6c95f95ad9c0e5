// Replay of a recording: the row -> DynamicData inverse of the recorder's flattening (pure, exact
// round trips), the loader's checks, and the replayer over loopback DDS (domains 171-175).
#include "tools/topic/test/test_support.hpp"
#include "tools/topic/topic_recorder.hpp"
#include "tools/topic/topic_replay.hpp"
#include "tools/topic/topic_tools.hpp"

#include "common/runtime/federate_options.hpp"
#include "common/runtime/subscription.hpp"
#include "common/runtime/topic_types.hpp"
#include "common/util/wait_until.hpp"

#include <fastrtps/types/DynamicDataFactory.h>
#include <fastrtps/types/DynamicPubSubType.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <thread>

namespace fedsim::tools {
namespace {

using namespace std::chrono_literals;
namespace fs = std::filesystem;

/// A DynamicData of `type`, freed with the holder.
class Data {
 public:
  explicit Data(const ftypes::DynamicType_ptr& type)
      : data_(ftypes::DynamicDataFactory::get_instance()->create_data(type)) {}
  ~Data() { ftypes::DynamicDataFactory::get_instance()->delete_data(data_); }
  Data(const Data&) = delete;
  Data& operator=(const Data&) = delete;
  ftypes::DynamicData& operator*() const { return *data_; }

 private:
  ftypes::DynamicData* data_;
};

template <class T>
ftypes::DynamicType_ptr type_of() {
  typename runtime::TopicType<T>::PubSubType typed;
  return dynamic_type_by_name(typed.getName());
}

/// The recorder's code path (as InProcessRecorder): typed sample -> CDR -> DynamicData -> CSV.
template <class T>
void to_dynamic(const T& sample, ftypes::DynamicData& out) {
  typename runtime::TopicType<T>::PubSubType typed;
  eprosima::fastrtps::rtps::SerializedPayload_t payload(
      typed.getSerializedSizeProvider(const_cast<T*>(&sample))());
  ASSERT_TRUE(typed.serialize(const_cast<T*>(&sample), &payload));
  ftypes::DynamicPubSubType dynamic(type_of<T>());
  ASSERT_TRUE(dynamic.deserialize(&payload, &out));
}

template <class T>
std::string recorded_row(const T& sample) {
  const auto type = type_of<T>();
  Data data(type);
  to_dynamic(sample, *data);
  return CsvLayout(type).row(read_sample(*data, type), 0.0);
}

/// Row -> DynamicData -> row again.
std::string reflattened(const RowDecoder& decoder, const std::string& row) {
  Data data(decoder.type());
  decoder.decode(split_recorded_row(row), *data);
  return decoder.layout().row(read_sample(*data, decoder.type()), 0.0);
}

msg::AircraftState varied_state(std::uint64_t frame) {
  msg::AircraftState s;
  s.aircraft_id(65535);
  s.stamp().frame(frame);
  s.stamp().sim_time_s(static_cast<double>(frame) * 0.02);
  s.latitude_rad(0.6544984694978736 + 1e-9 * static_cast<double>(frame));
  s.longitude_rad(-2.135);
  s.altitude_msl_m(1.0 / 3.0 + static_cast<double>(frame));
  s.height_agl_m(-0.0);
  s.position_ecef_m({-2.7e6, -4.3e6, 3.8e6 + 0.1 * static_cast<double>(frame)});
  s.velocity_ned_mps({0.1 + 0.2, -1e-300, 4.9406564584124654e-324});  // denormal
  s.q_ned_from_body({0.9999999999999999, 1e-17, -2.5e-8, 0.5});
  s.phi_rad(-3.141592653589793);
  s.air().tas_mps(55.5 + static_cast<double>(frame) / 7.0);
  s.air().wind_ned_mps({0.1, 0.2, 0.30000000000000004});
  s.air().static_pressure_pa(1.7976931348623157e308);
  s.controls().throttle({0.0, 0.25, 1.0, 1.0 / 3.0});
  s.controls().gear_down(frame % 2 == 0);
  s.stalled(true);
  s.mass_kg(79015.8);
  s.engine_count(2);
  s.on_ground(frame % 3 == 0);
  s.gear_count(8);
  for (std::size_t g = 0; g < 8; ++g) {
    s.gear()[g].weight_on_wheels(g % 2 == 1);
    s.gear()[g].compression_m(static_cast<float>(g) / 3.0f);
    s.gear()[g].normal_force_n(g == 7 ? 1e-45f : -3.4028235e38f);  // float denormal, float max
  }
  s.dropped_steps(std::numeric_limits<std::uint64_t>::max());
  s.rotating_earth(true);
  return s;
}

msg::NavigationState varied_nav(std::uint64_t frame) {
  msg::NavigationState n;
  n.aircraft_id(0);
  n.stamp().frame(frame);
  n.stamp().sim_time_s(static_cast<double>(frame) * 0.02);
  n.nav()[0].frequency_khz(110300);
  n.nav()[0].signal(msg::NAV_SIGNAL_LOCALIZER);
  n.nav()[0].status(msg::SIGNAL_BEHIND_ANTENNA);
  n.nav()[0].ident("I,SFO");        // a comma: quoted
  n.nav()[0].dme_ident("say \"x\"");  // quotes: doubled
  n.nav()[0].course_deviation(-0.75 + 0.001 * static_cast<double>(frame));
  n.nav()[0].to_from(msg::TO_FROM_FROM);
  n.nav()[1].ident(" SFO ");        // edge blanks: quoted, kept
  n.nav()[1].glideslope_status(msg::SIGNAL_CONE_OF_CONFUSION);
  n.adf().ident("#1");              // not a comment
  n.marker().beacon(msg::MARKER_INNER);
  n.ins().valid(true);
  n.ins().velocity_ned_mps({1.5, -2.25, 3e-310});
  n.gps().satellites_used(9);
  n.gps().denied(frame % 2 == 1);
  n.fd().lateral_mode(msg::FD_LATERAL_NAV);
  n.fd().vertical_mode(msg::FD_VERTICAL_GLIDESLOPE);
  return n;
}

msg::EngineState varied_engine(std::uint16_t index) {
  msg::EngineState e;
  e.aircraft_id(1);
  e.engine_index(index);
  e.stamp().frame(7);
  e.stamp().sim_time_s(0.14);
  e.running(true);
  e.thrust_n(-120.5 * index);
  e.n1_pct(101.25);
  e.fuel_flow_kgps(1e-5);
  e.exhaust_temperature_k(1e20);
  return e;
}

TEST(ReplayRows, RoundTripIsExactForAircraftNavigationAndEngineStates) {
  const RowDecoder aircraft(type_of<msg::AircraftState>());
  for (std::uint64_t frame : {1, 2, 3, 1000000}) {
    const std::string row = recorded_row(varied_state(frame));
    EXPECT_EQ(reflattened(aircraft, row), row);
  }
  const RowDecoder nav(type_of<msg::NavigationState>());
  const std::string nav_row = recorded_row(varied_nav(5));
  EXPECT_NE(nav_row.find("\"I,SFO\""), std::string::npos) << nav_row;
  EXPECT_EQ(reflattened(nav, nav_row), nav_row);
  const RowDecoder engine(type_of<msg::EngineState>());
  for (std::uint16_t i = 0; i < 4; ++i) {
    const std::string row = recorded_row(varied_engine(i));
    EXPECT_EQ(reflattened(engine, row), row);
  }
}

TEST(ReplayRows, NonFiniteValuesReadBackAsWritten) {
  msg::AircraftState s = varied_state(8);
  s.fuel_kg(std::numeric_limits<double>::quiet_NaN());
  s.total_thrust_n(-std::numeric_limits<double>::infinity());
  s.gear()[3].normal_force_n(std::numeric_limits<float>::infinity());
  const std::string row = recorded_row(s);
  EXPECT_NE(row.find(",nan,"), std::string::npos) << row;
  EXPECT_EQ(reflattened(RowDecoder(type_of<msg::AircraftState>()), row), row);
}

TEST(ReplayRows, RoundTripOfTopLevelTimeAndSequences) {
  msg::FrameTick tick;  // sim_time_s is a top-level field: the CSV moves it first
  tick.frame(9);
  tick.sim_time_s(0.18);
  tick.dt_s(0.02);
  tick.run_state(msg::RUN_STATE_FREEZE);
  const std::string tick_row = recorded_row(tick);
  EXPECT_EQ(reflattened(RowDecoder(type_of<msg::FrameTick>()), tick_row), tick_row);

  msg::VisualPicture picture;  // a sequence<octet>: one JSON-array cell
  picture.channel_id(2);
  picture.name("left");
  picture.encoding("image/jpeg");
  picture.data({0, 255, 7, 128});
  const RowDecoder pictures(type_of<msg::VisualPicture>());
  const std::string row = recorded_row(picture);
  EXPECT_NE(row.find("\"[0,255,7,128]\""), std::string::npos) << row;
  EXPECT_EQ(reflattened(pictures, row), row);
  picture.data({});
  const std::string empty = recorded_row(picture);
  EXPECT_EQ(reflattened(pictures, empty), empty);
}

TEST(ReplayRows, AChangedCellGivesADifferentSampleInTheRightMember) {
  const RowDecoder decoder(type_of<msg::AircraftState>());
  const std::string row = recorded_row(varied_state(4));
  auto cells = split_recorded_row(row);
  const auto& columns = decoder.layout().columns();
  const auto tas = static_cast<std::size_t>(
      std::find(columns.begin(), columns.end(), "air.tas_mps") - columns.begin());
  ASSERT_LT(tas, cells.size());
  cells[tas] = "12.5";
  Data data(decoder.type());
  decoder.decode(cells, *data);
  const SampleNode tree = read_sample(*data, decoder.type());
  const std::string changed = decoder.layout().row(tree, 0.0);
  EXPECT_NE(changed, row);
  std::string error;
  EXPECT_EQ(select_field(tree, "air.tas_mps", error)->value.d, 12.5) << error;
  EXPECT_EQ(split_recorded_row(changed), cells);  // only that cell differs
}

TEST(ReplayRows, KeyColumnsNameTheInstance) {
  const RowDecoder aircraft(type_of<msg::AircraftState>());
  ASSERT_EQ(aircraft.key_columns().size(), 1u);
  EXPECT_EQ(aircraft.layout().columns()[aircraft.key_columns()[0]], "aircraft_id");
  const RowDecoder engine(type_of<msg::EngineState>());
  ASSERT_EQ(engine.key_columns().size(), 2u);
  EXPECT_EQ(engine.layout().columns()[engine.key_columns()[1]], "engine_index");
}

// ---- recordings on disk ---------------------------------------------------------------------

fs::path fresh_dir(const std::string& name) {
  auto dir = fs::temp_directory_path() / ("fedsim_replay_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// Writes samples to DIR/<topic>.csv through the recorder itself (TopicRecorder).
template <class T>
void record(const fs::path& dir, const runtime::Topic<T>& topic, const std::vector<T>& samples) {
  const auto type = type_of<T>();
  TopicRecorder recorder(topic.name(), type, dir / csv_file_name(topic.name()));
  Data data(type);
  for (const T& s : samples) {
    to_dynamic(s, *data);
    recorder.on_sample(*data, 0.0);
  }
  recorder.drain();
  recorder.flush();
}

std::vector<std::string> data_lines(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  if (!lines.empty()) lines.erase(lines.begin());  // the header
  return lines;
}

void write_file(const fs::path& file, const std::string& text) {
  std::ofstream out(file);
  out << text;
}

std::string load_error(const fs::path& dir) {
  try {
    Recording::load(dir);
  } catch (const ReplayError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ReplayRecording, RefusesAHeaderOfAnotherVersionNamingTheColumn) {
  const auto dir = fresh_dir("header");
  record(dir, runtime::topics::aircraft_state, {varied_state(1)});
  const auto file = dir / "fedsim_aircraft_state.csv";
  std::ifstream in(file);
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  in.close();
  const auto pos = header.find(",latitude_rad,");
  ASSERT_NE(pos, std::string::npos);
  write_file(file, header.substr(0, pos) + ",lat_rad," + header.substr(pos + 14) + "\n" + row + "\n");
  const std::string error = load_error(dir);
  EXPECT_NE(error.find(file.string() + ": the header differs"), std::string::npos) << error;
  EXPECT_NE(error.find("column 5: 'lat_rad' in the file, 'latitude_rad' expected"),
            std::string::npos) << error;
  fs::remove_all(dir);
}

TEST(ReplayRecording, NamesFileLineAndColumnOfABadCell) {
  const auto dir = fresh_dir("bad_cell");
  record(dir, runtime::topics::aircraft_state, {varied_state(1), varied_state(2)});
  const auto file = dir / "fedsim_aircraft_state.csv";
  std::ifstream in(file);
  std::string header, row1, row2;
  std::getline(in, header);
  std::getline(in, row1);
  std::getline(in, row2);
  in.close();
  auto cells = split_recorded_row(row2);
  cells[6] = "12.x";  // column 7: altitude_msl_m
  std::string bad = cells[0];
  for (std::size_t i = 1; i < cells.size(); ++i) bad += "," + cells[i];
  write_file(file, header + "\n" + row1 + "\n" + bad + "\n");
  std::string error = load_error(dir);
  EXPECT_NE(error.find(file.string() + ":3:7: column 'altitude_msl_m': not a number: '12.x'"),
            std::string::npos) << error;
  write_file(file, header + "\n" + row1 + ",1\n");
  error = load_error(dir);
  EXPECT_NE(error.find(file.string() + ":2:"), std::string::npos) << error;
  EXPECT_NE(error.find("cells, the header has"), std::string::npos) << error;
  fs::remove_all(dir);
}

TEST(ReplayRecording, AnEmptyOrMissingFolderIsExitCodeTwo) {
  const auto dir = fresh_dir("empty");
  write_file(dir / "notes.csv", "a,b\n1,2\n");  // not a fedsim topic
  EXPECT_THROW(Recording::load(dir), RecordingNotFound);
  ReplayCliOptions options;
  options.dir = dir.string();
  std::ostringstream out, err;
  EXPECT_EQ(run_replay(options, out, err), 2);
  EXPECT_NE(err.str().find("'" + dir.string() + "' holds no recording"), std::string::npos) << err.str();
  EXPECT_NE(err.str().find("notes.csv: not a fedsim topic"), std::string::npos) << err.str();
  options.dir = (dir / "missing").string();
  std::ostringstream out2, err2;
  EXPECT_EQ(run_replay(options, out2, err2), 2);
  EXPECT_NE(err2.str().find("no recording folder '" + (dir / "missing").string() + "'"),
            std::string::npos) << err2.str();
  fs::remove_all(dir);
}

TEST(ReplayCli, ChecksEveryNumber) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"replay", "d", "--speed", "nan"},
        std::vector<std::string>{"replay", "d", "--speed", "101"},
        std::vector<std::string>{"replay", "d", "--speed", "-1"},
        std::vector<std::string>{"replay", "d", "--from-s", "-0.5"},
        std::vector<std::string>{"replay", "d", "--from-s", "inf"}}) {
    CLI::App app{"fedsim"};
    add_replay_command(app);
    std::vector<std::string> reversed(args.rbegin(), args.rend());
    EXPECT_THROW(app.parse(reversed), CLI::ValidationError) << args[2] << " " << args[3];
  }
}

// ---- over DDS ----------------------------------------------------------------------------------

using test::loopback;

/// Keeps every sample a typed reader (the topic's default "state" QoS, as a display) receives.
template <class T>
class Collector {
 public:
  Collector(std::shared_ptr<runtime::DdsParticipant> dds, const runtime::Topic<T>& topic)
      : sub_(std::move(dds), topic, {}, [this](const T& s, const auto&) {
          std::lock_guard lock(mutex_);
          samples_.push_back(s);
        }) {}
  std::size_t count() const {
    std::lock_guard lock(mutex_);
    return samples_.size();
  }
  std::vector<T> samples() const {
    std::lock_guard lock(mutex_);
    return samples_;
  }
  bool wait_for(std::size_t n, std::chrono::milliseconds timeout) const {
    return util::wait_until([&] { return count() >= n; }, std::chrono::duration<double>(timeout).count(), 2ms);
  }
  runtime::Subscription<T>& sub() { return sub_; }

 private:
  mutable std::mutex mutex_;
  std::vector<T> samples_;
  runtime::Subscription<T> sub_;
};

std::vector<msg::AircraftState> states(std::uint64_t n) {
  std::vector<msg::AircraftState> out;
  for (std::uint64_t f = 1; f <= n; ++f) out.push_back(varied_state(f));
  return out;
}

std::vector<msg::NavigationState> navs(std::uint64_t n) {
  std::vector<msg::NavigationState> out;
  for (std::uint64_t f = 1; f <= n; ++f) out.push_back(varied_nav(f));
  return out;
}

template <class T>
std::vector<std::string> rows_of(const std::vector<T>& samples) {
  std::vector<std::string> rows;
  for (const T& s : samples) rows.push_back(recorded_row(s));
  return rows;
}

TEST(ReplayDds, EverySampleArrivesExactlyAndInOrderAtFullSpeed) {
  const auto dir = fresh_dir("exact");
  record(dir, runtime::topics::aircraft_state, states(300));
  record(dir, runtime::topics::navigation_state, navs(300));
  auto reader_dds = runtime::DdsParticipant::create(loopback(171, "replay_test_reader"));
  Collector<msg::AircraftState> aircraft(reader_dds, runtime::topics::aircraft_state);
  Collector<msg::NavigationState> nav(reader_dds, runtime::topics::navigation_state);
  Replayer replayer(runtime::DdsParticipant::create(loopback(171, "replay_test")),
                    Recording::load(dir), {.speed = 0.0});
  ASSERT_TRUE(replayer.wait_for_readers(5s));
  ASSERT_TRUE(aircraft.sub().wait_for_writers(1, 5s));
  ASSERT_TRUE(nav.sub().wait_for_writers(1, 5s));

  const auto start = std::chrono::steady_clock::now();
  replayer.start();
  util::wait_until([&] { return replayer.finished(); }, 10, 1ms);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(replayer.finished());
  EXPECT_TRUE(replayer.error().empty()) << replayer.error();
  EXPECT_EQ(replayer.published(), 600u);
  std::printf("[ replay ] 600 samples at speed 0 in %.3f s: %.0f samples/s\n", wall, 600 / wall);

  ASSERT_TRUE(aircraft.wait_for(300, 2s)) << aircraft.count();
  ASSERT_TRUE(nav.wait_for(300, 2s)) << nav.count();
  EXPECT_EQ(rows_of(aircraft.samples()), data_lines(dir / "fedsim_aircraft_state.csv"));
  EXPECT_EQ(rows_of(nav.samples()), data_lines(dir / "fedsim_navigation_state.csv"));
  EXPECT_DOUBLE_EQ(replayer.position_s(), 300 * 0.02);
  const auto fields = replayer.latest_fields("fedsim/aircraft_state");
  ASSERT_TRUE(fields.has_value());
  EXPECT_EQ(fields->at("stamp.frame"), 300.0);
  EXPECT_EQ(fields->at("altitude_msl_m"), varied_state(300).altitude_msl_m());
  EXPECT_EQ(fields->count("stalled"), 1u);
  EXPECT_FALSE(replayer.latest_fields("fedsim/engine_state").has_value());
  fs::remove_all(dir);
}

TEST(ReplayDds, PauseStopsResumeGoesOnSeekJumps) {
  const auto dir = fresh_dir("pause");
  record(dir, runtime::topics::aircraft_state, states(300));  // 6 s of simulation at 50 Hz
  auto reader_dds = runtime::DdsParticipant::create(loopback(172, "replay_test_reader"));
  Collector<msg::AircraftState> aircraft(reader_dds, runtime::topics::aircraft_state);
  Replayer replayer(runtime::DdsParticipant::create(loopback(172, "replay_test")),
                    Recording::load(dir), {.speed = 4.0});
  ASSERT_TRUE(replayer.wait_for_readers(5s));
  ASSERT_TRUE(aircraft.sub().wait_for_writers(1, 5s));
  replayer.start();
  ASSERT_TRUE(aircraft.wait_for(20, 10s));

  replayer.pause();  // publication has stopped when it returns
  const std::uint64_t published_at_pause = replayer.published();
  // What was published before the pause arrives (best effort: one might be lost, so no assert).
  aircraft.wait_for(published_at_pause, 5s);
  const std::size_t paused_count = aircraft.count();
  // Paused, time passes and nothing goes out: this look lasts on purpose (what must not happen
  // has no event to wait for).
  std::this_thread::sleep_for(300ms);
  EXPECT_EQ(replayer.published(), published_at_pause);
  EXPECT_EQ(aircraft.count(), paused_count);
  EXPECT_LT(paused_count, 150u);

  // Seek while paused: the latest state at/before 4.0 s goes out at once, nothing more.
  replayer.seek(4.0);
  ASSERT_TRUE(aircraft.wait_for(paused_count + 1, 10s));
  EXPECT_EQ(replayer.published(), published_at_pause + 1);
  auto received = aircraft.samples();
  ASSERT_EQ(received.size(), paused_count + 1);
  EXPECT_LT(received.back().stamp().sim_time_s(), 4.0);
  EXPECT_EQ(received.back().stamp().frame(), 199u);  // 199 * 0.02 < 4.0 <= 200 * 0.02
  EXPECT_EQ(replayer.position_s(), 4.0);

  replayer.resume();
  ASSERT_TRUE(aircraft.wait_for(paused_count + 2, 10s));
  received = aircraft.samples();
  EXPECT_EQ(received[paused_count + 1].stamp().frame(), 200u);  // the first at/after 4.0 s
  ASSERT_TRUE(util::wait_until([&] { return replayer.finished(); }, 10, 5ms));
  ASSERT_TRUE(aircraft.wait_for(paused_count + 1 + 101, 10s));
  EXPECT_EQ(aircraft.samples().back().stamp().frame(), 300u);
  fs::remove_all(dir);
}

TEST(ReplayDds, LoopsAndRunsThroughTheCli) {
  const auto dir = fresh_dir("cli");
  record(dir, runtime::topics::aircraft_state, states(50));
  {
    auto reader_dds = runtime::DdsParticipant::create(loopback(173, "replay_test_reader"));
    Collector<msg::AircraftState> aircraft(reader_dds, runtime::topics::aircraft_state);
    Replayer replayer(runtime::DdsParticipant::create(loopback(173, "replay_test")),
                      Recording::load(dir), {.speed = 0.0, .from_s = 0.5, .loop = true});
    ASSERT_TRUE(replayer.wait_for_readers(5s));
    ASSERT_TRUE(aircraft.sub().wait_for_writers(1, 5s));
    replayer.start();
    ASSERT_TRUE(aircraft.wait_for(1 + 26 + 50 + 50 + 1, 5s));  // 24, 25..50, 1..50, 1..50, 1
    EXPECT_FALSE(replayer.finished());
    EXPECT_GE(replayer.loops(), 2u);
    replayer.stop();
    const auto samples = aircraft.samples();
    EXPECT_EQ(samples[0].stamp().frame(), 24u);  // the state before the start, then 25 on
    EXPECT_EQ(samples[1].stamp().frame(), 25u);
    EXPECT_EQ(samples[27].stamp().frame(), 1u);  // 24, 25..50, then over again
  }
  auto reader_dds = runtime::DdsParticipant::create(loopback(174, "replay_test_reader"));
  Collector<msg::AircraftState> aircraft(reader_dds, runtime::topics::aircraft_state);
  CLI::App app{"fedsim"};
  add_replay_command(app);
  testing::internal::CaptureStdout();
  app.parse(std::vector<std::string>{"--wait=3", "--domain=174", "--speed=0", dir.string(), "replay"});
  const std::string text = testing::internal::GetCapturedStdout();
  EXPECT_NE(text.find("replaying fedsim/aircraft_state: 50 samples, QoS 'state'"), std::string::npos) << text;
  EXPECT_NE(text.find("stopped (end of the recording): replayed 50 samples up to 1.0 / 1.0 s"),
            std::string::npos) << text;
  EXPECT_TRUE(aircraft.wait_for(50, 2s)) << aircraft.count();
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fedsim::tools
