// The one place a deployment member becomes a component, for every host of a deployment
// (`fedsim run` over DDS names the timing member's arguments here; `fedsim run --in-process`
// and `fedsim graph` build the components): the registry of component programs, the timing
// member the launcher adds, a member's arguments parsed by its own program exactly as its
// command line would be, and a `fedsim record` member's topics.
#pragma once

#include "common/runtime/federate_main.hpp"
#include "fedsim/deployment.hpp"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fedsim::launcher {

/// The component programs by binary name (e.g. "fedsim-flight"): every federate of the tree,
/// the frame clock (fedsim-timing) and the instructor station (fedsim-ios) included.
const std::map<std::string, runtime::FederateProgram (*)()>& component_programs();

/// The timing federate as a member (`fedsim run` adds it unless timing.enabled is false): named
/// "timing", its arguments the deployment's mode and rate, --shutdown-on-exit, --expect with the
/// lockstep members, then the deployment's timing.args.
FederateSpec timing_spec(const Deployment& d);

/// A member as its host sees it: arguments substituted.
struct Member {
  const FederateSpec* spec = nullptr;  // into the deployment, or to timing_ (the timing member)
  std::string binary;                  // the program's file name ("fedsim-flight", "fedsim")
  std::vector<std::string> args;
  bool is_timing = false;
};

/// Every member of the deployment, the timing member last (if the deployment has one). Throws
/// util::ConfigError for an unknown ${VARIABLE}.
class Members {
 public:
  Members(const Deployment& d, const std::map<std::string, std::string>& vars);
  Members(const Members&) = delete;
  Members& operator=(const Members&) = delete;
  const std::vector<Member>& all() const { return members_; }

 private:
  FederateSpec timing_;
  std::vector<Member> members_;
};

/// Builds a member's component as its program's main() would from the same arguments (the
/// deployment's sync QoS applied, as `fedsim run` passes it), or nullptr if its program is not a
/// component program. Throws util::ConfigError ("file: federate 'x': ...") for bad arguments,
/// and what the program's make_component throws for bad input (runtime::ProgramError...).
std::unique_ptr<runtime::Component> build_component(const Deployment& d, const Member& member);

/// What a `fedsim record` member records (the options that matter without DDS; the others are
/// accepted and ignored).
struct RecorderSpec {
  std::vector<std::string> topics;
  std::string out_dir;  // "" if --out is not given
};
/// nullopt for a member whose program is not `fedsim record`.
std::optional<RecorderSpec> recorder_of(const Member& member);

}  // namespace fedsim::launcher
