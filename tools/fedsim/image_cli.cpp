#include "fedsim/image_cli.hpp"

#include "common/picture/image.hpp"
#include "visual/model/montage.hpp"

#include <iostream>
#include <memory>
#include <stdexcept>

namespace fedsim::launcher {

int image_montage(const std::string& out_path, const std::vector<std::string>& inputs, int gap_px,
                  std::ostream& err) {
  try {
    std::vector<picture::Image> images;
    for (const std::string& path : inputs) images.push_back(picture::read_png(path));
    picture::write_png(visual::side_by_side(images, gap_px, {16, 16, 16, 255}), out_path);
    return 0;
  } catch (const std::exception& e) {
    err << "fedsim image montage: " << e.what() << "\n";
    return 2;
  }
}

void add_image_commands(CLI::App& app, int& exit_code) {
  auto* image = app.add_subcommand("image", "pictures: montage");
  image->require_subcommand(1);
  struct Options {
    std::string out;
    std::vector<std::string> inputs;
    int gap_px = 0;
  };
  auto options = std::make_shared<Options>();
  auto* montage = image->add_subcommand("montage", "put PNG pictures side by side (left to right)");
  montage->add_option("out", options->out, "the PNG written")->required();
  montage->add_option("inputs", options->inputs, "the PNG pictures, left to right, of one height")
      ->required()->check(CLI::ExistingFile);
  montage->add_option("--gap", options->gap_px, "dark columns between the pictures [px]")
      ->check(CLI::Range(0, 64))->capture_default_str();
  montage->callback([options, &exit_code] {
    exit_code = image_montage(options->out, options->inputs, options->gap_px, std::cerr);
  });
}

}  // namespace fedsim::launcher
