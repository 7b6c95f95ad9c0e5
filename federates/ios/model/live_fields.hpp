// The instructor station's field registry: the newest value of every numeric field of every topic
// it hears, named as the recorder names CSV columns ("altitude_msl_m", "air.wind_ned_mps[0]",
// "nav[0].course_deviation"), so that a plot, a confirmation or a scenario condition picks any
// field of any topic by the same name. Booleans and enums are numbers (1/0, the enum's value);
// text fields are kept apart. A keyed topic with several instances (one per engine, per visual
// channel) is held per instance: "fedsim/engine_state[1]", "fedsim/visual_status[0]".
// Pure and single-threaded: the host guards it.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace fedsim::ios {

struct TopicFields {
  std::vector<std::string> names;        // numeric fields, in IDL order
  std::vector<double> values;            // same order
  std::map<std::string, std::string> text;  // text fields (idents, names)
  std::uint64_t samples = 0;             // samples taken into the table
  double updated_s = 0.0;                // host clock of the newest [s]
};

class LiveFields {
 public:
  /// Replaces the values of `topic` (an instance name) with a sample's flattened cells: a cell
  /// that reads as a number is a numeric field, any other is text (sequences are left out).
  void update(const std::string& topic, const std::vector<std::string>& names,
              const std::vector<std::string>& cells, double now_s);
  /// Sets one numeric field (the station's own "timing" view).
  void set(const std::string& topic, const std::string& field, double value, double now_s);

  std::optional<double> value(const std::string& topic, const std::string& field) const;
  const std::map<std::string, TopicFields>& topics() const { return topics_; }

  /// {"<topic>": {"n": samples, "f": {"<field>": value, ...}, "t": {"<text field>": "..."}}, ...}
  /// Non-finite numbers are written as null (JSON has no NaN).
  std::string to_json() const;

 private:
  std::map<std::string, TopicFields> topics_;
};

/// The instance name of a keyed topic's sample: "topic[<engine_index>]" or "topic[<channel_id>]"
/// where the sample has such a top-level key field, else the topic itself.
std::string instance_name(const std::string& topic, const std::vector<std::string>& names,
                          const std::vector<std::string>& cells);

}  // namespace fedsim::ios
