// The recording index (recording_index.hpp): the seek table's rule, the file the recorder writes
// beside each CSV, and a replay that starts late reading only the rows it needs.
#include "tools/topic/recording_index.hpp"
#include "tools/topic/topic_recorder.hpp"
#include "tools/topic/topic_replay.hpp"
#include "tools/topic/topic_tools.hpp"

#include "common/runtime/topic_types.hpp"

#include <fastrtps/types/DynamicDataFactory.h>
#include <fastrtps/types/DynamicPubSubType.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace fedsim::tools {
namespace {

namespace fs = std::filesystem;

TEST(RecordingIndex, AnEntryEachIntervalOfNewTimeAndNoneWhenAResetSendsTimeBack) {
  RecordingIndex index(1.0);
  std::uint64_t offset = 100;
  for (int i = 0; i <= 150; ++i) index.add_row(i * 0.02, offset += 10);  // 0 .. 3 s
  for (int i = 0; i <= 100; ++i) index.add_row(i * 0.02, offset += 10);  // a reset: 0 .. 2 s
  index.add_row(3.5, offset += 10);
  index.add_row(4.0, offset += 10);
  ASSERT_EQ(index.rows(), 151u + 101u + 2u);
  ASSERT_EQ(index.entries().size(), 5u);  // 0, 1, 2, 3, then 4.0 (3.5 is within 1 s of 3)
  EXPECT_DOUBLE_EQ(index.entries()[1].sim_time_s, 1.0);
  EXPECT_EQ(index.entries()[1].row, 50u);
  EXPECT_EQ(index.entries()[1].byte_offset, 100u + 51u * 10u);
  EXPECT_EQ(index.entries()[4].row, 253u);
  EXPECT_DOUBLE_EQ(*index.first_sim_time_s(), 0.0);
  EXPECT_DOUBLE_EQ(*index.last_sim_time_s(), 4.0);
  // Start one whole interval before the entry at/before the time.
  EXPECT_FALSE(index.start_for(0.5).has_value());
  EXPECT_EQ(index.start_for(1.5)->row, 0u);  // the first entry: the first row
  EXPECT_EQ(index.start_for(2.5)->row, 50u);
  EXPECT_EQ(index.start_for(100.0)->row, 150u);
  // Reception-time rows count but are never seek points.
  RecordingIndex received(1.0);
  received.add_row(std::nullopt, 10);
  EXPECT_EQ(received.rows(), 1u);
  EXPECT_TRUE(received.entries().empty());
  EXPECT_THROW(RecordingIndex(std::nan("")), std::invalid_argument);
  EXPECT_THROW(RecordingIndex(0.0), std::invalid_argument);
}

TEST(RecordingIndex, ReadsBackWhatItWritesAndNamesAMalformedFile) {
  RecordingIndex index(0.5);
  for (int i = 0; i < 10; ++i) index.add_row(i * 0.25, 20 + i * 7);
  const fs::path file = fs::temp_directory_path() / ("fedsim_index_" + std::to_string(::getpid()) + ".index.json");
  {
    std::ofstream out(file);
    out << index.to_json("fedsim/aircraft_state", "T", "x.csv", 20, {"sim_time_s", "a"});
  }
  const auto back = RecordingIndex::read(file);
  ASSERT_TRUE(back.has_value());
  ASSERT_EQ(back->entries().size(), index.entries().size());
  EXPECT_EQ(back->entries()[3].byte_offset, index.entries()[3].byte_offset);
  EXPECT_EQ(back->rows(), 10u);
  {
    std::ofstream out(file);
    out << R"({"format": "fedsim-recording-index-1", "seek_interval_s": 1, "rows": 2, "seek": [[1, 0, 5], [0.5, 1, 9]]})";
  }
  try {
    RecordingIndex::read(file);
    FAIL() << "seek times that go back must be refused";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(file.string() + ": not a recording index"), std::string::npos) << e.what();
  }
  fs::remove(file);
  EXPECT_FALSE(RecordingIndex::read(file).has_value());
  EXPECT_EQ(index_file_for("/a/b/fedsim_aircraft_state.csv"), fs::path("/a/b/fedsim_aircraft_state.index.json"));
}

// ---- the recorder's index and a late start ------------------------------------------------

ftypes::DynamicType_ptr state_type() {
  runtime::TopicType<msg::AircraftState>::PubSubType typed;
  return dynamic_type_by_name(typed.getName());
}

/// Records `n` aircraft states 20 ms apart through the recorder (typed -> CDR -> dynamic -> CSV).
fs::path record_states(const std::string& name, int n) {
  const fs::path dir = fs::temp_directory_path() / ("fedsim_index_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto type = state_type();
  TopicRecorder recorder("fedsim/aircraft_state", type, dir / csv_file_name("fedsim/aircraft_state"));
  runtime::TopicType<msg::AircraftState>::PubSubType typed;
  ftypes::DynamicPubSubType dynamic(type);
  ftypes::DynamicData* data = ftypes::DynamicDataFactory::get_instance()->create_data(type);
  for (int i = 0; i < n; ++i) {
    msg::AircraftState s;
    s.stamp().frame(static_cast<std::uint64_t>(i));
    s.stamp().sim_time_s(i * 0.02);
    s.altitude_msl_m(1000.0 + i);
    eprosima::fastrtps::rtps::SerializedPayload_t payload(typed.getSerializedSizeProvider(&s)());
    EXPECT_TRUE(typed.serialize(&s, &payload));
    EXPECT_TRUE(dynamic.deserialize(&payload, data));
    recorder.on_sample(*data, 0.0);
    if (i % 37 == 0) recorder.drain();
  }
  recorder.drain();
  recorder.flush();
  ftypes::DynamicDataFactory::get_instance()->delete_data(data);
  return dir;
}

TEST(RecordingIndex, TheRecorderIndexesEveryRowAtTheStartOfItsLine) {
  const fs::path dir = record_states("lines", 300);  // 0 .. 5.98 s
  const fs::path csv = dir / "fedsim_aircraft_state.csv";
  std::ifstream in(dir / "fedsim_aircraft_state.index.json");
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["topic"], "fedsim/aircraft_state");
  EXPECT_EQ(j["file"], "fedsim_aircraft_state.csv");
  EXPECT_EQ(j["rows"], 300);
  EXPECT_DOUBLE_EQ(j["last_sim_time_s"].get<double>(), 299 * 0.02);
  ASSERT_EQ(j["seek"].size(), 6u);
  std::ifstream text(csv, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(text)), std::istreambuf_iterator<char>());
  EXPECT_EQ(j["header_bytes"].get<std::size_t>(), bytes.find('\n') + 1);
  for (const auto& e : j["seek"]) {
    const auto offset = e[2].get<std::size_t>();
    ASSERT_LT(offset, bytes.size());
    EXPECT_EQ(bytes[offset - 1], '\n');
    // The line there is the row the entry names, stamped with the entry's time.
    const std::string line = bytes.substr(offset, bytes.find('\n', offset) - offset);
    EXPECT_DOUBLE_EQ(std::stod(line), e[0].get<double>());
    EXPECT_NEAR(std::stod(line) / 0.02, e[1].get<double>(), 1e-6);
  }
  fs::remove_all(dir);
}

TEST(RecordingIndex, AReplayFromLateReadsFromTheIndexAndLosesNoRowAfterTheStart) {
  const fs::path dir = record_states("late", 300);
  const Recording all = Recording::load(dir);
  const Recording late = Recording::load(dir, {}, 4.0);
  const auto& every = all.topics().at(0).rows;
  const auto& some = late.topics().at(0).rows;
  ASSERT_EQ(every.size(), 300u);
  // Entries at 0, 1, 2, 3, 4, 5 s: from 4.0 the loader starts one interval earlier, at 3 s.
  ASSERT_EQ(some.size(), 150u);
  EXPECT_DOUBLE_EQ(some.front().time_s, 3.0);
  EXPECT_EQ(some.front().line, 152);  // line numbers still name the file's lines
  for (std::size_t i = 0; i < some.size(); ++i) EXPECT_EQ(some[i].cells, every[150 + i].cells);
  // An index that does not match its file (here: every offset moved) is named, not misread.
  const fs::path index = dir / "fedsim_aircraft_state.index.json";
  std::ifstream in(index);
  auto j = nlohmann::json::parse(in);
  in.close();
  for (auto& e : j["seek"]) e[2] = e[2].get<std::uint64_t>() + 3;
  std::ofstream(index) << j.dump();
  try {
    Recording::load(dir, {}, 4.0);
    FAIL() << "a stale index must be refused";
  } catch (const ReplayError& e) {
    EXPECT_NE(std::string(e.what()).find("its index does not match it"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

TEST(RecordingIndex, ARecordingBeingWrittenReadsUpToItsLastWholeLine) {
  const fs::path dir = record_states("live", 100);
  const fs::path csv = dir / "fedsim_aircraft_state.csv";
  std::ifstream in(csv, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  // The recorder has written half of a 101st line when the station reads the folder.
  const std::size_t last_start = bytes.rfind('\n', bytes.size() - 2) + 1;
  const std::string half_line = bytes.substr(last_start, (bytes.size() - last_start) / 2);
  std::ofstream(csv, std::ios::app | std::ios::binary) << half_line;
  EXPECT_EQ(Recording::load(dir).topics().at(0).rows.size(), 100u);
  // Without the recorder's index it is a file someone wrote: a torn row is an error by line.
  fs::remove(dir / "fedsim_aircraft_state.index.json");
  try {
    Recording::load(dir);
    FAIL() << "a half row of a plain CSV file must be refused";
  } catch (const ReplayError& e) {
    EXPECT_NE(std::string(e.what()).find(csv.string() + ":102"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fedsim::tools
