// Grayscale image files of a recording: 8-bit grayscale PNG (libpng) and
// binary PGM (P5, maxval 255). Anything else is refused with a RecordingError
// naming the file, so a recording never yields a silently wrong frame.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "lumavel/host/recording_error.hpp"

namespace lumavel::host {

// The largest width or height of a frame, in pixels: an image file's header
// claiming more is refused before anything is allocated, and a sensor.yaml's
// resolution, a scenario's and render --resolution are held to it (each side
// 1..kMaxImageSide; the pixel count has its own limit, why_too_many_pixels).
constexpr int kMaxImageSide = 16384;

struct GrayImage {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> px;  // width * height bytes, row-major, no padding
};

// Reads an 8-bit grayscale PNG or a binary PGM (P5, maxval 255), chosen by the
// file's signature, not its name. Colour, alpha, palette, 16-bit or sub-byte
// depth, truncated or corrupt files throw RecordingError naming `path`.
GrayImage read_gray_image(const std::string& path);

// Same, for a frame whose size is known (its sensor.yaml's resolution): an
// image of another size comes back with its width and height and no pixels
// (px empty), never decoded nor allocated, so that a small file whose header
// claims 16384x16384 pixels costs nothing; the caller refuses it by its size.
GrayImage read_gray_image(const std::string& path, int expect_width, int expect_height);

// Same, from bytes already in memory; `name` is used in error messages.
GrayImage decode_gray_image(const uint8_t* data, size_t size, const std::string& name);

// Whether a warning libpng gives while it reads on (one of its "benign"
// errors) is about the image data: more rows than the header says, data
// after the zlib stream, IDAT chunks out of place. Such a file is damaged and
// refused; a warning about an ancillary chunk (a colour profile known to be
// wrong, a bad text chunk) does not touch the pixels. One rule for the
// frames read here and the photos a scenario's walls show.
bool png_warning_is_about_pixels(const char* message);

// Writes an 8-bit grayscale PNG. Favours speed (zlib level 1): the renderer
// writes thousands of frames. Throws RecordingError naming `path` on failure.
void write_png_gray(const std::string& path, const uint8_t* px, int w, int h);

// Writes a binary PGM (P5, maxval 255). Throws RecordingError on failure.
void write_pgm(const std::string& path, const uint8_t* px, int w, int h);

}  // namespace lumavel::host
