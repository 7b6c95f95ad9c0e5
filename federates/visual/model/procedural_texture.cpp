#include "visual/model/procedural_texture.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace fedsim::visual {

namespace {

float smooth(float t) { return t * t * (3.0f - 2.0f * t); }

// One octave: a periodic lattice of `cells` x `cells` random values, smoothly interpolated.
void add_octave(std::vector<float>& out, std::mt19937_64& random, int size_px, int cells,
                float amplitude) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<float> lattice(static_cast<std::size_t>(cells) * cells);
  for (auto& v : lattice) v = unit(random);
  const auto at = [&](int i, int j) {
    return lattice[static_cast<std::size_t>(j % cells) * cells + (i % cells)];
  };
  const float texels_per_cell = static_cast<float>(size_px) / cells;
  for (int y = 0; y < size_px; ++y) {
    const float fy = y / texels_per_cell;
    const int j = static_cast<int>(fy);
    const float ty = smooth(fy - j);
    for (int x = 0; x < size_px; ++x) {
      const float fx = x / texels_per_cell;
      const int i = static_cast<int>(fx);
      const float tx = smooth(fx - i);
      const float top = at(i, j) + tx * (at(i + 1, j) - at(i, j));
      const float bottom = at(i, j + 1) + tx * (at(i + 1, j + 1) - at(i, j + 1));
      out[static_cast<std::size_t>(y) * size_px + x] += amplitude * (top + ty * (bottom - top));
    }
  }
}

std::uint8_t byte(float v) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

void put(TextureImage& t, std::size_t i, float r, float g, float b) {
  t.rgba[4 * i] = byte(r);
  t.rgba[4 * i + 1] = byte(g);
  t.rgba[4 * i + 2] = byte(b);
  t.rgba[4 * i + 3] = 255;
}

}  // namespace

std::vector<float> value_noise(std::uint64_t seed, int size_px, int cells, int octaves) {
  if (size_px <= 0 || cells <= 0 || octaves <= 0 || size_px % (cells << (octaves - 1)) != 0) {
    throw std::invalid_argument("value_noise: size must be a multiple of cells << (octaves-1)");
  }
  std::mt19937_64 random(seed);
  std::vector<float> out(static_cast<std::size_t>(size_px) * size_px, 0.0f);
  float amplitude = 0.5f, total = 0.0f;
  for (int o = 0; o < octaves; ++o) {
    add_octave(out, random, size_px, cells << o, amplitude);
    total += amplitude;
    amplitude *= 0.5f;
  }
  for (auto& v : out) v /= total;
  return out;
}

TextureImage ground_texture(std::uint64_t seed, int size_px) {
  const std::vector<float> grass = value_noise(seed, size_px, 8, 5);
  const std::vector<float> fields = value_noise(seed + 1, size_px, 4, 3);
  TextureImage t{size_px,
                 std::vector<std::uint8_t>(static_cast<std::size_t>(size_px) * size_px * 4)};
  for (std::size_t i = 0; i < grass.size(); ++i) {
    const float g = grass[i];
    // Green grass, with drier, browner patches where the coarse noise is high.
    const float dry = std::clamp((fields[i] - 0.55f) * 4.0f, 0.0f, 1.0f);
    const float r = (0.20f + 0.16f * g) * (1.0f - dry) + (0.40f + 0.10f * g) * dry;
    const float gr = (0.30f + 0.14f * g) * (1.0f - dry) + (0.37f + 0.08f * g) * dry;
    const float b = (0.13f + 0.08f * g) * (1.0f - dry) + (0.22f + 0.06f * g) * dry;
    put(t, i, r, gr, b);
  }
  return t;
}

TextureImage pavement_texture(std::uint64_t seed, int size_px) {
  const std::vector<float> grain = value_noise(seed, size_px, 32, 3);
  const std::vector<float> patches = value_noise(seed + 1, size_px, 4, 2);
  TextureImage t{size_px,
                 std::vector<std::uint8_t>(static_cast<std::size_t>(size_px) * size_px * 4)};
  for (std::size_t i = 0; i < grain.size(); ++i) {
    const float v = 0.26f + 0.08f * grain[i] + 0.06f * (patches[i] - 0.5f);
    put(t, i, v, v, v * 1.02f);
  }
  return t;
}

}  // namespace fedsim::visual
