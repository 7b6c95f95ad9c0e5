// Pure tests (no network): a fedsim sample serialized by its generated type support is read back
// through a DynamicType built from the registered TypeObject, then printed and flattened to CSV.
#include "tools/topic/csv_layout.hpp"
#include "tools/topic/sample_tree.hpp"
#include "tools/topic/topic_tools.hpp"

#include "common/runtime/topic_types.hpp"

#include <fastrtps/types/DynamicDataFactory.h>
#include <fastrtps/types/DynamicPubSubType.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace fedsim::tools {
namespace {

/// A DynamicData holding `sample` as it would arrive over the wire.
class DynamicSample {
 public:
  template <class T>
  DynamicSample(T& sample, const std::string& type_name) {
    typename runtime::TopicType<T>::PubSubType typed;
    eprosima::fastrtps::rtps::SerializedPayload_t payload(typed.getSerializedSizeProvider(&sample)());
    EXPECT_TRUE(typed.serialize(&sample, &payload));
    type_ = dynamic_type_by_name(type_name);
    EXPECT_TRUE(type_) << type_name;
    ftypes::DynamicPubSubType dynamic(type_);
    data_ = ftypes::DynamicDataFactory::get_instance()->create_data(type_);
    EXPECT_TRUE(dynamic.deserialize(&payload, data_));
  }
  ~DynamicSample() { ftypes::DynamicDataFactory::get_instance()->delete_data(data_); }
  ftypes::DynamicData& data() { return *data_; }
  const ftypes::DynamicType_ptr& type() const { return type_; }
  SampleNode tree() { return read_sample(*data_, type_); }

 private:
  ftypes::DynamicType_ptr type_;
  ftypes::DynamicData* data_ = nullptr;
};

msg::AircraftState make_state() {
  msg::AircraftState s;
  s.aircraft_id(3);
  s.stamp().frame(42);
  s.stamp().sim_time_s(0.84);
  s.latitude_rad(0.6544984694978736);
  s.longitude_rad(-2.135);
  s.altitude_msl_m(1.0 / 3.0);
  s.velocity_ned_mps({1.5, -2.25, 3.0});
  s.q_ned_from_body({1.0, 0.0, 0.0, 0.0});
  s.air().tas_mps(55.5);
  s.air().wind_ned_mps({0.1, 0.2, 0.30000000000000004});
  s.on_ground(true);
  s.gear_count(3);
  s.gear()[0].weight_on_wheels(true);
  s.gear()[0].compression_m(0.125f);
  s.gear()[2].normal_force_n(0.1f);
  s.fuel_kg(std::numeric_limits<double>::quiet_NaN());
  return s;
}

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cell += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cell += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      cells.push_back(cell);
      cell.clear();
    } else {
      cell += c;
    }
  }
  cells.push_back(cell);
  return cells;
}

std::string cell(const CsvLayout& layout, const std::vector<std::string>& row,
                 const std::string& column) {
  const auto& cols = layout.columns();
  const auto it = std::find(cols.begin(), cols.end(), column);
  if (it == cols.end()) return "<no column " + column + ">";
  return row.at(static_cast<std::size_t>(it - cols.begin()));
}

TEST(SampleTree, ReadsNestedStructsArraysAndScalars) {
  auto state = make_state();
  DynamicSample sample(state, "fedsim::msg::AircraftState");
  const SampleNode tree = sample.tree();
  ASSERT_EQ(tree.kind, SampleNode::Kind::Struct);
  EXPECT_EQ(tree.children.front().name, "aircraft_id");  // IDL order
  EXPECT_EQ(tree.member("aircraft_id")->value.u, 3u);
  EXPECT_EQ(tree.member("stamp")->member("frame")->value.u, 42u);
  EXPECT_EQ(tree.member("stamp")->member("sim_time_s")->value.d, 0.84);
  const SampleNode* v = tree.member("velocity_ned_mps");
  ASSERT_EQ(v->kind, SampleNode::Kind::Array);
  ASSERT_EQ(v->children.size(), 3u);
  EXPECT_EQ(v->children[1].value.d, -2.25);
  EXPECT_EQ(tree.member("air")->member("wind_ned_mps")->children[2].value.d, 0.30000000000000004);
  const SampleNode* gear = tree.member("gear");
  ASSERT_EQ(gear->children.size(), 8u);
  EXPECT_EQ(gear->children[0].member("weight_on_wheels")->value.u, 1u);
  EXPECT_EQ(gear->children[0].member("compression_m")->value.kind, ScalarValue::Kind::Float32);
  EXPECT_EQ(gear->children[0].member("compression_m")->value.d, 0.125);
}

TEST(SampleTree, SelectsFields) {
  auto state = make_state();
  DynamicSample sample(state, "fedsim::msg::AircraftState");
  const SampleNode tree = sample.tree();
  std::string error;
  auto frame = select_field(tree, "stamp.frame", error);
  ASSERT_TRUE(frame) << error;
  EXPECT_EQ(to_yaml(*frame), "42\n");
  auto v2 = select_field(tree, "velocity_ned_mps[2]", error);
  ASSERT_TRUE(v2) << error;
  EXPECT_EQ(v2->value.d, 3.0);
  auto gear0 = select_field(tree, "gear[0].compression_m", error);
  ASSERT_TRUE(gear0) << error;
  EXPECT_EQ(to_yaml(*gear0), "0.125\n");
  EXPECT_FALSE(select_field(tree, "stamp.nope", error));
  EXPECT_NE(error.find("no field 'nope' in 'stamp'"), std::string::npos) << error;
  EXPECT_NE(error.find("sim_time_s"), std::string::npos) << error;  // lists the fields
  EXPECT_FALSE(select_field(tree, "gear[8]", error));
  EXPECT_FALSE(select_field(tree, "gear[x]", error));
}

TEST(SampleTree, YamlIsIndentedWithInlineScalarArrays) {
  auto state = make_state();
  DynamicSample sample(state, "fedsim::msg::AircraftState");
  const std::string yaml = to_yaml(sample.tree());
  EXPECT_EQ(yaml.rfind("aircraft_id: 3\nstamp:\n  frame: 42\n  sim_time_s: 0.84\n", 0), 0u)
      << yaml;
  EXPECT_NE(yaml.find("\nvelocity_ned_mps: [1.5, -2.25, 3]\n"), std::string::npos) << yaml;
  EXPECT_NE(yaml.find("\nair:\n  tas_mps: 55.5\n"), std::string::npos) << yaml;
  EXPECT_NE(yaml.find("  wind_ned_mps: [0.1, 0.2, 0.30000000000000004]\n"), std::string::npos)
      << yaml;
  EXPECT_NE(yaml.find("\ngear:\n  - weight_on_wheels: true\n    compression_m: 0.125\n"
                      "    normal_force_n: 0\n  - weight_on_wheels: false\n"),
            std::string::npos)
      << yaml;
  EXPECT_NE(yaml.find("\nfuel_kg: .nan\n"), std::string::npos) << yaml;
}

TEST(SampleTree, EnumsByNameAndBoundedStrings) {
  msg::SimCommand cmd;
  cmd.kind(msg::COMMAND_WEATHER);
  cmd.target("engine1, \"left\"");
  cmd.sequence_number(7);
  cmd.issuer("ios");
  cmd.run_state(msg::RUN_STATE_RESET);
  cmd.reposition().kind(msg::REPOSITION_APPROACH_GATE);
  cmd.reposition().airport("KSFO");
  cmd.weather().turbulence_seed(4000000000u);
  DynamicSample sample(cmd, "fedsim::msg::SimCommand");
  const SampleNode tree = sample.tree();
  const std::string yaml = to_yaml(tree);
  EXPECT_EQ(yaml.rfind("kind: COMMAND_WEATHER\ntarget: \"engine1, \\\"left\\\"\"\n", 0), 0u)
      << yaml;
  EXPECT_NE(yaml.find("\nrun_state: RUN_STATE_RESET\n"), std::string::npos) << yaml;
  EXPECT_NE(yaml.find("\nreposition:\n  kind: REPOSITION_APPROACH_GATE\n  airport: \"KSFO\"\n"),
            std::string::npos)
      << yaml;
  EXPECT_NE(yaml.find("  turbulence_seed: 4000000000\n"), std::string::npos) << yaml;

  const auto json = nlohmann::json::parse(to_json(tree));
  EXPECT_EQ(json["kind"], "COMMAND_WEATHER");
  EXPECT_EQ(json["target"], "engine1, \"left\"");
  EXPECT_EQ(json["reposition"]["airport"], "KSFO");
  EXPECT_EQ(json["weather"]["turbulence_seed"], 4000000000u);
}

TEST(CsvLayout, FlattensEveryFieldWithSimTimeFirst) {
  auto state = make_state();
  DynamicSample sample(state, "fedsim::msg::AircraftState");
  CsvLayout layout(sample.type());
  const auto& cols = layout.columns();
  EXPECT_TRUE(layout.has_sim_time());
  EXPECT_TRUE(layout.has_frame());
  ASSERT_GE(cols.size(), 4u);
  EXPECT_EQ(cols[0], "sim_time_s");
  EXPECT_EQ(cols[1], "aircraft_id");
  EXPECT_EQ(cols[2], "stamp.frame");
  EXPECT_EQ(cols[3], "stamp.sim_time_s");
  for (const char* name : {"velocity_ned_mps[0]", "velocity_ned_mps[2]", "q_ned_from_body[3]",
                           "air.wind_ned_mps[2]", "air.density_kgpm3", "gear[0].weight_on_wheels",
                           "gear[7].normal_force_n", "gear_count"}) {
    EXPECT_NE(std::find(cols.begin(), cols.end(), name), cols.end()) << name;
  }
  // 1 time + id + 2 stamp + 4 + 3 ecef + 3 + 3 + 4 + 3 + 4*3 + 3 body-dot + load factor
  // + 4 ground kinematics + 11+3 air + 5 surfaces + 3 more surfaces + 14 flown controls (incl. the trim position)
  // + 6 aero + stalled + 3 force + 3 moment + 3 mass + 3 cg + 1 engines + on_ground
  // + weight on wheels + gear force + gear_count + 8*3 gear + dropped steps + rotating earth
  EXPECT_EQ(cols.size(), 1u + 1 + 2 + 4 + 3 + 3 + 3 + 4 + 3 + 12 + 3 + 1 + 4 + 14 + 5 + 3 + 14 +
                             6 + 1 + 3 + 3 + 3 + 3 + 1 + 1 + 1 + 1 + 1 + 24 + 1 + 1);
  EXPECT_EQ(layout.header().rfind("sim_time_s,aircraft_id,stamp.frame,stamp.sim_time_s,", 0), 0u);

  const SampleNode tree = sample.tree();
  EXPECT_EQ(layout.frame_of(tree), 42u);
  const auto row = split_csv(layout.row(tree, 1234.5));
  ASSERT_EQ(row.size(), cols.size());
  EXPECT_EQ(row[0], "0.84");
  EXPECT_EQ(cell(layout, row, "stamp.frame"), "42");
  EXPECT_EQ(cell(layout, row, "velocity_ned_mps[1]"), "-2.25");
  EXPECT_EQ(std::stod(cell(layout, row, "altitude_msl_m")), 1.0 / 3.0);  // exact round trip
  EXPECT_EQ(std::stod(cell(layout, row, "latitude_rad")), 0.6544984694978736);
  EXPECT_EQ(cell(layout, row, "air.wind_ned_mps[2]"), "0.30000000000000004");
  EXPECT_EQ(cell(layout, row, "gear[2].normal_force_n"), "0.1");  // float: shortest float text
  EXPECT_EQ(cell(layout, row, "gear[0].weight_on_wheels"), "1");
  EXPECT_EQ(cell(layout, row, "on_ground"), "1");
  EXPECT_EQ(cell(layout, row, "fuel_kg"), "nan");
}

TEST(CsvLayout, EnumsAsIntegersAndStringsQuoted) {
  msg::SimCommand cmd;
  cmd.kind(msg::COMMAND_FAILURE);
  cmd.target("engine1, \"left\"");
  cmd.issuer("ios");
  cmd.failure().active(true);
  DynamicSample sample(cmd, "fedsim::msg::SimCommand");
  CsvLayout layout(sample.type());
  EXPECT_FALSE(layout.has_sim_time());
  EXPECT_FALSE(layout.has_frame());
  EXPECT_EQ(layout.columns()[0], "receive_time_s");
  const std::string line = layout.row(sample.tree(), 1700000000.25);
  EXPECT_EQ(line.rfind("1700000000.25,3,\"engine1, \"\"left\"\"\",0,ios,", 0), 0u) << line;
  const auto row = split_csv(line);
  ASSERT_EQ(row.size(), layout.columns().size());
  EXPECT_EQ(cell(layout, row, "target"), "engine1, \"left\"");
  EXPECT_EQ(cell(layout, row, "reposition.kind"), "0");
  EXPECT_EQ(cell(layout, row, "failure.active"), "1");
}

TEST(CsvLayout, TopLevelSimTimeIsMovedFirstNotRepeated) {
  msg::FrameTick tick;
  tick.frame(10);
  tick.sim_frame(9);
  tick.sim_time_s(0.18);
  tick.dt_s(0.02);
  tick.mode(msg::TIMING_MODE_LOCKSTEP);
  DynamicSample sample(tick, "fedsim::msg::FrameTick");
  CsvLayout layout(sample.type());
  EXPECT_EQ(layout.header().rfind("sim_time_s,frame,sim_frame,dt_s,frame_period_s,run_state,", 0),
            0u)
      << layout.header();
  EXPECT_EQ(std::count(layout.columns().begin(), layout.columns().end(), "sim_time_s"), 1);
  const SampleNode tree = sample.tree();
  EXPECT_EQ(layout.frame_of(tree), 10u);
  EXPECT_EQ(layout.row(tree, 0).rfind("0.18,10,9,0.02,0,", 0), 0u) << layout.row(tree, 0);
}

TEST(Format, NumbersRoundTrip) {
  for (double x : {0.1, 1.0 / 3.0, -2.5e-300, 6.02214076e23, 123456789.123456789, 0.0}) {
    EXPECT_EQ(std::stod(format_double(x)), x) << format_double(x);
  }
  EXPECT_EQ(format_double(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(format_float(0.1f), "0.1");
  EXPECT_EQ(std::stof(format_float(1.0f / 3.0f)), 1.0f / 3.0f);
  EXPECT_EQ(csv_quote("plain"), "plain");
  EXPECT_EQ(csv_quote("a,b"), "\"a,b\"");
  EXPECT_EQ(csv_quote("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csv_quote(" pad"), "\" pad\"");
  EXPECT_EQ(csv_file_name("fedsim/aircraft_state"), "fedsim_aircraft_state.csv");
}

}  // namespace
}  // namespace fedsim::tools
