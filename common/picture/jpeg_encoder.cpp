#include "common/picture/jpeg_encoder.hpp"

#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

#include <jpeglib.h>

namespace fedsim::picture {
namespace {

// libjpeg reports errors through error_exit, which by default exits the process: this one
// jumps back to the caller, which throws (no C++ object lives between setjmp and the jump).
struct JpegError {
  jpeg_error_mgr manager;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

void on_jpeg_error(j_common_ptr info) {
  auto* error = reinterpret_cast<JpegError*>(info->err);
  (*info->err->format_message)(info, error->message);
  std::longjmp(error->jump, 1);
}

}  // namespace

void validate(const JpegOptions& options) {
  if (options.quality < 1 || options.quality > 100) {
    throw std::invalid_argument("jpeg quality " + std::to_string(options.quality) + ": 1..100");
  }
  if (options.downscale < 1 || options.downscale > 8) {
    throw std::invalid_argument("jpeg downscale " + std::to_string(options.downscale) + ": 1..8");
  }
}

Image downscale(const Image& image, int factor) {
  if (factor < 1 || image.width_px < factor || image.height_px < factor) {
    throw std::invalid_argument("downscale by " + std::to_string(factor) + " of a " +
                                std::to_string(image.width_px) + "x" + std::to_string(image.height_px) +
                                " image");
  }
  if (factor == 1) return image;
  Image out(image.width_px / factor, image.height_px / factor);
  const int area = factor * factor;
  for (int row = 0; row < out.height_px; ++row) {
    for (int column = 0; column < out.width_px; ++column) {
      int sum[3] = {0, 0, 0};
      for (int dy = 0; dy < factor; ++dy) {
        const std::uint8_t* p =
            &image.rgba[(static_cast<std::size_t>(row * factor + dy) * image.width_px + column * factor) * 4];
        for (int dx = 0; dx < factor; ++dx, p += 4) {
          sum[0] += p[0];
          sum[1] += p[1];
          sum[2] += p[2];
        }
      }
      std::uint8_t* q = &out.rgba[(static_cast<std::size_t>(row) * out.width_px + column) * 4];
      for (int k = 0; k < 3; ++k) q[k] = static_cast<std::uint8_t>((sum[k] + area / 2) / area);
      q[3] = 255;
    }
  }
  return out;
}

void encode_jpeg(const Image& image, const JpegOptions& options, std::vector<std::uint8_t>& out) {
  validate(options);
  if (image.width_px <= 0 || image.height_px <= 0 ||
      image.rgba.size() != static_cast<std::size_t>(image.width_px) * image.height_px * 4) {
    throw std::invalid_argument("encode_jpeg: an empty or inconsistent image");
  }
  jpeg_compress_struct info;
  JpegError error;
  info.err = jpeg_std_error(&error.manager);
  error.manager.error_exit = on_jpeg_error;
  unsigned char* buffer = nullptr;
  unsigned long size = 0;
  if (setjmp(error.jump)) {
    jpeg_destroy_compress(&info);
    std::free(buffer);
    throw std::runtime_error(std::string("JPEG encoding failed: ") + error.message);
  }
  jpeg_create_compress(&info);
  jpeg_mem_dest(&info, &buffer, &size);
  info.image_width = static_cast<JDIMENSION>(image.width_px);
  info.image_height = static_cast<JDIMENSION>(image.height_px);
  info.input_components = 4;
  info.in_color_space = JCS_EXT_RGBA;  // libjpeg-turbo: RGBA rows straight from the frame
  jpeg_set_defaults(&info);
  jpeg_set_quality(&info, options.quality, TRUE);
  jpeg_start_compress(&info, TRUE);
  while (info.next_scanline < info.image_height) {
    JSAMPROW row = const_cast<JSAMPROW>(&image.rgba[static_cast<std::size_t>(info.next_scanline) * image.width_px * 4]);
    jpeg_write_scanlines(&info, &row, 1);
  }
  jpeg_finish_compress(&info);
  out.assign(buffer, buffer + size);
  jpeg_destroy_compress(&info);
  std::free(buffer);
}

Image decode_jpeg(const std::uint8_t* data, std::size_t size) {
  jpeg_decompress_struct info;
  JpegError error;
  info.err = jpeg_std_error(&error.manager);
  error.manager.error_exit = on_jpeg_error;
  Image* result = new Image();  // outside the jump's reach: freed on both paths below
  if (setjmp(error.jump)) {
    jpeg_destroy_decompress(&info);
    delete result;
    throw std::runtime_error(std::string("JPEG decoding failed: ") + error.message);
  }
  jpeg_create_decompress(&info);
  jpeg_mem_src(&info, const_cast<unsigned char*>(data), static_cast<unsigned long>(size));
  jpeg_read_header(&info, TRUE);
  info.out_color_space = JCS_EXT_RGBA;
  jpeg_start_decompress(&info);
  *result = Image(static_cast<int>(info.output_width), static_cast<int>(info.output_height));
  while (info.output_scanline < info.output_height) {
    JSAMPROW row = &result->rgba[static_cast<std::size_t>(info.output_scanline) * result->width_px * 4];
    jpeg_read_scanlines(&info, &row, 1);
  }
  jpeg_finish_decompress(&info);
  jpeg_destroy_decompress(&info);
  Image image = std::move(*result);
  delete result;
  return image;
}

}  // namespace fedsim::picture
