// Instructor scenario files (seed 9.8): timed and conditional events that the simulator runs
// frame by frame. Pure: no DDS, no threads, no clock; the host passes sim time and a FieldLookup.
//
// Format (YAML; every error is "file:line: field: problem"):
//
//   name: engine-failure-approach          # required
//   description: "..."                     # optional
//   events:                                # required, at least one
//     - at_s: 5                            # fires once, in the first frame whose sim time reaches 5 s
//       do: {command: freeze}
//     - every_s: 30                        # repeats at 30, 60, 90 ... s (with at_s: from at_s on)
//       do: {command: snapshot, tag: periodic}
//     - when: "fedsim/aircraft_state.height_agl_m < 1000 ft"
//       do: {command: fail, system: engine1}
//     - when: {all: ["fedsim/aircraft_state.on_ground == 1", "fedsim/aircraft_state.ground_speed_mps < 5 kt"]}
//       for_s: 10                          # the condition must hold this long (sim time)
//       do: stop
//     - at_s: 12
//       do: {log: "the approach begins"}
//
// Triggers: exactly one of at_s / when; every_s alone or with at_s. Times are sim seconds, finite,
// >= 0 (every_s > 0). for_s only with when. A timed event fires in the first frame whose time is
// within half a frame of its time or later (a scenario started late catches up at once).
// A condition event fires once, in the first frame its condition holds (for for_s of sim time
// without a break): level, not edge, so a condition already true at the start fires at once.
//
// Conditions: "<topic>.<field> <op> <number> [unit]", the field flattened as the recorder names
// its columns (fedsim/aircraft_state.air.tas_mps, fedsim/navigation_state.nav[0].course_deviation,
// fedsim/aircraft_state.velocity_ned_mps[2]); op one of < <= > >= == != (booleans read 1/0);
// the unit converts the number to the field's SI unit: ft, kt, deg, nm, fpm, m, mps, s. Lists:
// {all: [...]} and {any: [...]}, nesting allowed. A field with no value yet makes its comparison
// false (and is listed by missing_fields()).
//
// Actions (do:): stop (the scenario says the run is over), {log: "text"}, or an instructor command
// in exactly the instructor station's JSON vocabulary (common/instructor/request_json.hpp), checked
// by the same code: {command: reposition, airport: KSFO, runway: 28R, gate_nm: 10}.
//
// Order and rewinds: the actions of one frame come in file order, and none after a stop. Sim time
// going back by more than half a frame (the instructor's RESET, a snapshot restore) restarts the
// scenario: every event is re-armed and a stopped scenario runs again. (So a scenario that sends
// `reset` itself loops.) FREEZE stops sim time, so it stops the scenario's clock too: timed
// events and for_s wait while frozen, and a scenario cannot time a `run` after its own freeze.
#pragma once

#include "common/instructor/instructor_request.hpp"
#include "common/scenario/condition.hpp"

#include <optional>
#include <string>
#include <vector>

namespace fedsim::scenario {

struct Action {
  enum class Kind { kCommand, kStop, kLog };
  Kind kind = Kind::kLog;
  instructor::InstructorRequest command;  // kCommand only
  std::string text;                       // kLog: the message; else "stop" or describe(command)
  int line = 0;                           // the event's line in the scenario file, for logs
};

class Scenario {
 public:
  /// Throws util::ConfigError ("file:line: field: problem") for any invalid content.
  static Scenario load_file(const std::string& path);
  static Scenario parse(const std::string& text, const std::string& origin);

  /// The frame period that sets the half-frame tolerance of times (default 50 Hz).
  void set_frame_period(double period_s);

  /// One frame: the actions due at this sim time, in file order.
  std::vector<Action> step(double sim_time_s, const FieldLookup& lookup);

  /// Every "topic.field" the conditions read, sorted, each once (what a host subscribes to).
  std::vector<std::string> fields() const;
  /// The fields read in the last step() that had no value, sorted, each once.
  std::vector<std::string> missing_fields() const;
  /// A stop action has fired (until sim time goes back).
  bool finished() const { return finished_; }
  const std::string& name() const { return name_; }
  std::size_t event_count() const { return events_.size(); }

 private:
  struct Event {
    int line = 0;
    std::optional<double> at_s;  // timed: the (first) time
    double every_s = 0.0;        // > 0: repeats
    std::optional<Condition> when;
    double for_s = 0.0;
    Action action;
    // Run state.
    bool done = false;
    double next_s = 0.0;
    std::optional<double> held_since_s;
  };

  static Event parse_event(const util::ConfigNode& node);
  void rearm();
  bool due(Event& event, double sim_time_s, const FieldLookup& lookup);
  double half_frame() const { return 0.5 * frame_period_s_; }

  std::string name_;
  std::vector<Event> events_;
  double frame_period_s_ = 1.0 / 50.0;
  std::optional<double> last_time_s_;
  bool finished_ = false;
  std::vector<std::string> missing_;
};

}  // namespace fedsim::scenario
