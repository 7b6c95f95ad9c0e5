// Procedural textures of the ground (grass and fields) and the pavement (asphalt grain), made
// from seeded value noise (std::mt19937_64 with an explicit seed: the same seed gives the same
// texture bit for bit). Tileable: the noise lattice wraps, so the texture repeats seamlessly.
#pragma once

#include <cstdint>
#include <vector>

namespace fedsim::visual {

struct TextureImage {
  int size_px = 0;                 // square: size_px x size_px
  std::vector<std::uint8_t> rgba;  // row-major, 4 bytes a texel
};

/// Tileable fractal value noise in [0, 1]: `octaves` octaves, the coarsest with `cells`
/// lattice cells across the tile. size_px must be a multiple of cells << (octaves - 1).
std::vector<float> value_noise(std::uint64_t seed, int size_px, int cells, int octaves);

TextureImage ground_texture(std::uint64_t seed, int size_px);
TextureImage pavement_texture(std::uint64_t seed, int size_px);

}  // namespace fedsim::visual
