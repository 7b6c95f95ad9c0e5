#include "common/picture/image.hpp"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

namespace fedsim::picture {

Image::Image(int width, int height) : width_px(width), height_px(height) {
  if (width <= 0 || height <= 0) throw std::invalid_argument("Image: size must be positive");
  rgba.assign(static_cast<std::size_t>(width) * height * 4, 0);
}

Rgba8 Image::at(int column, int row) const {
  if (column < 0 || row < 0 || column >= width_px || row >= height_px) {
    throw std::out_of_range("Image::at(" + std::to_string(column) + ", " + std::to_string(row) +
                            ") outside " + std::to_string(width_px) + "x" +
                            std::to_string(height_px));
  }
  const std::size_t i = (static_cast<std::size_t>(row) * width_px + column) * 4;
  return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
}

void Image::set(int column, int row, Rgba8 value) {
  if (column < 0 || row < 0 || column >= width_px || row >= height_px) {
    throw std::out_of_range("Image::set outside the image");
  }
  const std::size_t i = (static_cast<std::size_t>(row) * width_px + column) * 4;
  rgba[i] = value.r;
  rgba[i + 1] = value.g;
  rgba[i + 2] = value.b;
  rgba[i + 3] = value.a;
}

namespace {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

// libpng reports errors through a callback that must not return: it records the message and
// jumps back to the setjmp point in the caller (libpng is C; no exception crosses it).
struct PngError {
  std::string message;
};

void on_png_error(png_structp png, png_const_charp message) {
  static_cast<PngError*>(png_get_error_ptr(png))->message = message;
  png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}

// The C part of writing: returns false (message in `error`) when libpng fails.
bool write_rows(std::FILE* file, const Image& image, PngError& error) {
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, on_png_error, on_png_warning);
  if (png == nullptr) return false;
  png_infop info = png_create_info_struct(png);
  if (info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_init_io(png, file);
  png_set_IHDR(png, info, image.width_px, image.height_px, 8, PNG_COLOR_TYPE_RGB,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(png, 9);
  png_write_info(png, info);
  png_set_filler(png, 0, PNG_FILLER_AFTER);  // rows are RGBA in memory: libpng drops the alpha
  for (int row = 0; row < image.height_px; ++row) {
    png_write_row(png, image.rgba.data() + static_cast<std::size_t>(row) * image.width_px * 4);
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

// The C part of reading into `image` (RGBA); false with the message in `error` on failure.
bool read_rows(std::FILE* file, Image& image, PngError& error) {
  png_structp png =
      png_create_read_struct(PNG_LIBPNG_VER_STRING, &error, on_png_error, on_png_warning);
  if (png == nullptr) return false;
  png_infop info = png_create_info_struct(png);
  if (info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  png_init_io(png, file);
  png_read_info(png, info);
  const int colour = png_get_color_type(png, info);
  if (png_get_bit_depth(png, info) != 8 ||
      (colour != PNG_COLOR_TYPE_RGB && colour != PNG_COLOR_TYPE_RGBA)) {
    error.message = "not an 8-bit RGB or RGBA image";
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  if (colour == PNG_COLOR_TYPE_RGB) png_set_filler(png, 0xff, PNG_FILLER_AFTER);
  png_read_update_info(png, info);
  const auto width = static_cast<int>(png_get_image_width(png, info));
  const auto height = static_cast<int>(png_get_image_height(png, info));
  image.width_px = width;
  image.height_px = height;
  image.rgba.assign(static_cast<std::size_t>(width) * height * 4, 0);
  for (int row = 0; row < height; ++row) {
    png_read_row(png, image.rgba.data() + static_cast<std::size_t>(row) * width * 4, nullptr);
  }
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

}  // namespace

void write_png(const Image& image, const std::string& path) {
  if (image.width_px <= 0 || image.height_px <= 0 ||
      image.rgba.size() != static_cast<std::size_t>(image.width_px) * image.height_px * 4) {
    throw std::invalid_argument("write_png " + path + ": the image is empty or inconsistent");
  }
  File file(std::fopen(path.c_str(), "wb"));
  if (!file) throw std::runtime_error("write_png: cannot open " + path + " for writing");
  PngError error;
  if (!write_rows(file.get(), image, error)) {
    throw std::runtime_error("write_png " + path + ": " +
                             (error.message.empty() ? "libpng failed" : error.message));
  }
  if (std::fflush(file.get()) != 0) throw std::runtime_error("write_png: cannot write " + path);
}

Image read_png(const std::string& path) {
  File file(std::fopen(path.c_str(), "rb"));
  if (!file) throw std::runtime_error("read_png: cannot open " + path);
  Image image;
  PngError error;
  if (!read_rows(file.get(), image, error)) {
    throw std::runtime_error("read_png " + path + ": " +
                             (error.message.empty() ? "libpng failed" : error.message));
  }
  return image;
}

}  // namespace fedsim::picture
