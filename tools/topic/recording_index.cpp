#include "tools/topic/recording_index.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace fedsim::tools {

RecordingIndex::RecordingIndex(double interval_s) : interval_s_(interval_s) {
  if (!std::isfinite(interval_s) || interval_s <= 0.0) {
    throw std::invalid_argument("recording index: interval " + std::to_string(interval_s) +
                                " s is not a positive finite number");
  }
}

void RecordingIndex::add_row(std::optional<double> sim_time_s, std::uint64_t byte_offset) {
  const std::uint64_t row = rows_++;
  if (!sim_time_s || !std::isfinite(*sim_time_s)) return;
  const double t = *sim_time_s;
  if (!first_) first_ = t;
  last_ = t;
  if (!newest_entry_time_ || t >= *newest_entry_time_ + interval_s_) {
    entries_.push_back({t, row, byte_offset});
    newest_entry_time_ = t;
  }
}

std::optional<SeekEntry> RecordingIndex::start_for(double sim_time_s) const {
  // The last entry at or before the time, then one more back (a whole interval of rows before).
  const auto after = std::upper_bound(entries_.begin(), entries_.end(), sim_time_s,
                                      [](double t, const SeekEntry& e) { return t < e.sim_time_s; });
  const auto count = static_cast<std::size_t>(after - entries_.begin());
  if (count < 2) return std::nullopt;
  return entries_[count - 2];
}

std::string RecordingIndex::to_json(const std::string& topic, const std::string& type_name,
                                    const std::string& csv_file, std::uint64_t header_bytes,
                                    const std::vector<std::string>& columns) const {
  nlohmann::json seek = nlohmann::json::array();
  for (const auto& e : entries_) seek.push_back({e.sim_time_s, e.row, e.byte_offset});
  nlohmann::json j = {{"format", "fedsim-recording-index-1"},
                      {"topic", topic},
                      {"type", type_name},
                      {"file", csv_file},
                      {"header_bytes", header_bytes},
                      {"columns", columns},
                      {"rows", rows_},
                      {"first_sim_time_s", first_ ? nlohmann::json(*first_) : nlohmann::json()},
                      {"last_sim_time_s", last_ ? nlohmann::json(*last_) : nlohmann::json()},
                      {"seek_interval_s", interval_s_},
                      {"seek", seek}};
  return j.dump(1) + "\n";
}

std::optional<RecordingIndex> RecordingIndex::read(const std::filesystem::path& index_file) {
  std::ifstream in(index_file);
  if (!in) return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    if (j.at("format") != "fedsim-recording-index-1") throw std::runtime_error("unknown format");
    RecordingIndex index(j.at("seek_interval_s").get<double>());
    index.rows_ = j.at("rows").get<std::uint64_t>();
    double previous = -INFINITY;
    for (const auto& e : j.at("seek")) {
      SeekEntry entry{e.at(0).get<double>(), e.at(1).get<std::uint64_t>(), e.at(2).get<std::uint64_t>()};
      if (!std::isfinite(entry.sim_time_s) || entry.sim_time_s <= previous) {
        throw std::runtime_error("seek times must increase");
      }
      previous = entry.sim_time_s;
      index.entries_.push_back(entry);
    }
    return index;
  } catch (const std::exception& e) {
    throw std::runtime_error(index_file.string() + ": not a recording index (" + e.what() + ")");
  }
}

std::filesystem::path index_file_for(const std::filesystem::path& csv_file) {
  std::filesystem::path index = csv_file;
  index.replace_extension(".index.json");
  return index;
}

}  // namespace fedsim::tools
