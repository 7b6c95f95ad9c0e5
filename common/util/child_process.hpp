// Starts a program as a child process (tests and benchmarks): output to a log file, clean or hard
// kill, wait with a timeout. The child is killed when the object goes away or this process dies.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace fedsim::util {

class ChildProcess {
 public:
  ChildProcess(std::vector<std::string> argv, std::string log_path);
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  pid_t pid() const { return pid_; }
  /// Waits for exit; returns false on timeout. exit_code() is -signal if it died by a signal.
  bool wait(double timeout_s);
  void terminate();  // SIGTERM
  void kill_hard();  // SIGKILL
  bool running();
  int exit_code() const { return exit_code_; }
  std::string output() const;  // everything it printed so far

 private:
  pid_t pid_ = -1;
  std::string log_path_;
  bool exited_ = false;
  int exit_code_ = 0;
};

/// Reads a whole file ("" if missing).
std::string read_file(const std::string& path);
/// A fresh temporary folder (under $TMPDIR) named after `tag` and this process.
std::string temp_dir(const std::string& tag);

}  // namespace fedsim::util
