// Which expected federates have acknowledged the current frame (pure logic, no DDS).
// The timing federate issues the next lockstep tick when complete() turns true.
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace fedsim::timing {

class AckTracker {
 public:
  explicit AckTracker(std::vector<std::string> expected = {});

  /// Starts waiting for acknowledgements of `frame` from every federate still expected.
  void start_frame(std::uint64_t frame);
  /// Records an acknowledgement; true if it completed the frame just now. Acknowledgements of
  /// other frames and from unknown federates are ignored (returns false).
  bool acknowledge(const std::string& federate, std::uint64_t frame);
  /// Stops expecting a federate (lost or stopped); true if that completed the frame.
  bool remove(const std::string& federate);
  /// Expects a removed federate again from the next start_frame (a frame boundary: the frame in
  /// progress does not wait for it); false if it is unknown or still expected.
  bool readmit(const std::string& federate);

  bool complete() const { return outstanding_ == 0; }
  std::uint64_t frame() const { return frame_; }
  bool expects(const std::string& federate) const;
  std::vector<std::string> missing() const;
  std::vector<std::string> expected() const;
  std::size_t expected_count() const;

 private:
  struct Member {
    std::string name;
    bool active = true;
    bool acked = false;
    bool readmitted = false;  // active again from the next frame
  };
  std::vector<Member> members_;
  std::unordered_map<std::string, std::size_t> index_;
  std::uint64_t frame_ = 0;
  std::size_t outstanding_ = 0;
};

}  // namespace fedsim::timing
