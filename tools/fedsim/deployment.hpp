// A deployment file: which federates `fedsim run` starts, with what arguments, on which DDS
// domain and QoS profile. YAML, validated on load (errors name file, line and field).
//
//   name: default
//   mode: lockstep            # realtime | lockstep (fedsim run --mode overrides)
//   rate_hz: 50
//   domain: 0                 # FEDSIM_DOMAIN / --domain override
//   qos_file: ${SOURCE_DIR}/qos/fedsim_qos.xml
//   participant_profile: fedsim_loopback
//   sync_qos: best_effort     # tick/acknowledgement QoS for every federate: best_effort | reliable
//   timing: {args: [--frames, "3000"]}
//   federates:
//     - {name: io, binary: fedsim-io, args: [--profile, "${DATA_DIR}/profiles/x.csv"]}
//     - {name: flight, binary: fedsim-flight, restart: on-failure, max_restarts: 3}
//     - {name: viewer, binary: fedsim, args: [topic, hz, fedsim/aircraft_state], lockstep: false,
//        federate_options: false}
//   after:                    # run in order once the federation stopped cleanly
//     - [gnuplot, "${OUT_DIR}/plot.gp"]
//     - run: [fedsim, image, montage, "${OUT_DIR}/m.png", "${OUT_DIR}/a.png", "${OUT_DIR}/b.png"]
//       needs: ["${OUT_DIR}/a.png", "${OUT_DIR}/b.png"]
//     - {run: [fedsim, qtg, --recording, "${OUT_DIR}", --only, x], whole_run: true}
//
// An after-step is a command (a list), or a map: `run:` the command, `needs:` the files it reads
// that a good run may not make (a picture taken at a height the flight may not reach), each named
// in its arguments, and `whole_run: true` for a step that judges the whole flight. Such a step is
// skipped, named and with its reason, when this run did not write a file it needs (missing, or
// left from an earlier run in the same folder) or when --duration cut the run short; the run's
// verdict is then the federation's. Inputs every run that ran makes (the recorded CSVs) are not
// listed: a plot that finds none has failed, and fails the run.
//
// Substitutions in args: ${SOURCE_DIR}, ${DATA_DIR}, ${DEPLOY_DIR} (the file's folder),
// ${OUT_DIR} (fedsim run --out), ${BIN_DIR} (where the fedsim binaries are).
// Names (the deployment's and each federate's) are 1-32 characters of A-Z a-z 0-9 _ -: they
// become file and folder names and the timing federate's comma-separated --expect list.
// A key given twice, or a key that is a list or a map, is an error (file:line: field).
// restart: no (the default) | on-failure: a federate that exits with an error or is killed by a
// signal (other than the launcher's own stop) is started again with the same command line, at
// most max_restarts times (default 3, 1..100) over the run; each restart is logged and counted.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace fedsim::launcher {

struct FederateSpec {
  std::string name;
  std::string binary;              // bare name (looked up in BIN_DIR, then PATH) or a path
  std::vector<std::string> args;
  bool lockstep = true;            // acknowledges every frame: the timing federate waits for it
  bool federate_options = true;    // pass --name/--domain/--qos-file/--participant-profile
  bool required = true;            // the run fails if this one exits with an error
  bool restart_on_failure = false; // restart: on-failure (else: no)
  int max_restarts = 3;            // restarts allowed over the run with restart: on-failure
};

/// One entry of `after:` (see the top of this file).
struct AfterStep {
  std::vector<std::string> argv;   // the program and its arguments, ${...} not yet substituted
  std::vector<std::string> needs;  // files this run must have written for the step to run
  bool whole_run = false;          // judges the whole flight: skipped when --duration cut it short
};

struct Deployment {
  std::string file;
  std::string name;
  std::string mode = "lockstep";
  double rate_hz = 50.0;
  int domain = 0;
  bool domain_given = false;
  std::string qos_file;
  std::string participant_profile = "fedsim_loopback";
  std::string sync_qos = "best_effort";  // tick/frame_done QoS of every federate: best_effort | reliable
  std::vector<std::string> timing_args;
  bool has_timing = true;
  std::vector<FederateSpec> federates;
  std::vector<AfterStep> after;
};

/// Loads and validates a deployment; throws util::ConfigError ("file:line: field: problem").
Deployment load_deployment(const std::string& path);
Deployment parse_deployment(const std::string& text, const std::string& origin);

/// Replaces ${NAME} by vars.at(NAME); an unknown name is an error naming it.
std::string substitute(const std::string& text, const std::map<std::string, std::string>& vars);

}  // namespace fedsim::launcher
