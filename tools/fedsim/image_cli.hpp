// `fedsim image montage OUT IN...`: the pictures IN (PNG, left to right, one height) side by side
// in OUT (PNG), e.g. three visual channels' frames as one panorama; `--gap PX` puts dark columns
// between them. Exit status: 0 written, 2 a missing or malformed picture, or heights that differ.
#pragma once

#include <CLI/CLI.hpp>

#include <iosfwd>
#include <string>
#include <vector>

namespace fedsim::launcher {

/// Writes the montage; returns the exit status, the reason on `err`.
int image_montage(const std::string& out_path, const std::vector<std::string>& inputs, int gap_px,
                  std::ostream& err);
/// Adds `fedsim image montage`; the callback stores its exit status in `exit_code`.
void add_image_commands(CLI::App& app, int& exit_code);

}  // namespace fedsim::launcher
