// Records topics of an in-process composition to the same CSV files as `fedsim record`
// (DIR/<topic with '/' -> '_'>.csv, one line per sample written, the same header and cell
// text): each typed sample is serialized with its type support and read back as a DynamicData,
// then formatted by the recorder's CsvLayout. A scenario recorded this way and recorded from a
// DDS lockstep federation can therefore be compared byte for byte.
#pragma once

#include "common/runtime/composition.hpp"
#include "tools/topic/topic_recorder.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace fedsim::tools {

class InProcessRecorder {
 public:
  /// Records every sample written on `topics` (catalogue names) into `out_dir` (created);
  /// with `every_n_frames` > 1 only samples stamped with a multiple of it, and those of the
  /// last frame (written at close). Throws
  /// std::invalid_argument naming an unknown topic.
  InProcessRecorder(runtime::Composition& composition, const std::vector<std::string>& topics,
                    const std::filesystem::path& out_dir, std::uint64_t every_n_frames = 1);
  ~InProcessRecorder();

  /// Writes the queued lines to the files (call now and then; close() writes the rest).
  void drain();
  /// Writes everything and flushes the files.
  void close();
  /// (topic, file, samples written) of each recorded topic.
  struct Recorded {
    std::string topic;
    std::filesystem::path file;
    std::uint64_t samples = 0;
  };
  std::vector<Recorded> recorded() const;

 private:
  struct Stream;
  std::vector<std::unique_ptr<Stream>> streams_;
};

}  // namespace fedsim::tools
