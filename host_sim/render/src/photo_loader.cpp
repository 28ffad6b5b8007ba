// Photographs for textures: any PNG (libpng's simplified API converts colour
// to gray), JPEG (libjpeg, decoded as grayscale) or binary PGM.
#include <png.h>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#if LUMAVEL_HAVE_JPEG
#include <jpeglib.h>
#endif

#include "lumavel/host/render/surface_pattern.hpp"
#include "lumavel/host/image_io.hpp"
#include "lumavel/host/path_check.hpp"

namespace lumavel::host::render {
namespace {

// The largest photo decoded, checked on its header before its pixels are
// allocated: a damaged header (or a 65000x65000 JPEG of a few megabytes)
// claimed gigabytes, then 'std::bad_alloc'. Its summed-area table takes 8
// bytes a pixel, 32 mirrored: 1 GB at this size; the cameras see a few
// hundred of its pixels across.
constexpr uint64_t kMaxPhotoPixels = uint64_t{1} << 25;

// "" when a photo of w x h pixels may be decoded, else why not.
std::string why_photo_too_big(uint64_t w, uint64_t h) {
  if (w * h <= kMaxPhotoPixels) return "";
  return "is " + std::to_string(w) + "x" + std::to_string(h) + " pixels: a photo may have at most " +
         std::to_string(kMaxPhotoPixels) + " pixels (8192x4096): scale it down";
}

std::vector<unsigned char> load_png(const std::string& path, int& w, int& h) {
  png_image img{};
  img.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&img, path.c_str()))
    throw std::runtime_error(path + ": cannot read PNG: " + img.message);
  if (const std::string why = why_photo_too_big(img.width, img.height); !why.empty()) {
    png_image_free(&img);
    throw std::runtime_error(path + ": " + why);
  }
  // 16-bit samples without gAMA or sRGB chunk: the simplified API takes them
  // as linear light by default, and a 16-bit copy of a photo (as GIMP,
  // ImageMagick or PIL write it, the same encoding as the 8-bit one) was
  // rendered brighter and flatter than the 8-bit photo (levels 64 and 192 as
  // 136 and 224), exit 0. Read as sRGB, as its 8-bit twin is (libpng's
  // recommendation for files from elsewhere); a gAMA or sRGB chunk still rules.
  img.flags |= PNG_IMAGE_FLAG_16BIT_sRGB;
  // A photo with transparency (an alpha channel or a tRNS chunk): the
  // simplified API composes it onto black when it converts to gray, so a
  // photo whose pixels were transparent was rendered black, exit 0 (a fully
  // transparent one a plain black wall). Refused where a pixel is not opaque.
  if ((img.format & PNG_FORMAT_FLAG_ALPHA) != 0) {
    png_image ga{};
    ga.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&ga, path.c_str())) {
      png_image_free(&img);
      throw std::runtime_error(path + ": cannot read PNG: " + ga.message);
    }
    ga.flags |= PNG_IMAGE_FLAG_16BIT_sRGB;
    ga.format = PNG_FORMAT_GA;
    std::vector<unsigned char> gray_alpha(PNG_IMAGE_SIZE(ga));
    if (!png_image_finish_read(&ga, nullptr, gray_alpha.data(), 0, nullptr)) {
      const std::string msg = ga.message;
      png_image_free(&ga);
      png_image_free(&img);
      throw std::runtime_error(path + ": corrupt PNG: " + msg);
    }
    uint64_t seen = 0;
    size_t first = 0;
    for (size_t i = 1; i < gray_alpha.size(); i += 2)
      if (gray_alpha[i] != 255 && seen++ == 0) first = i / 2;
    if (seen > 0) {
      const uint64_t all = uint64_t{ga.width} * ga.height;
      png_image_free(&img);
      throw std::runtime_error(
          path + ": " + std::to_string(seen) + " of its " + std::to_string(all) +
          " pixels are transparent or partly so (the first at column " + std::to_string(first % ga.width) + ", row " +
          std::to_string(first / ga.width) + ", alpha " + std::to_string(gray_alpha[2 * first + 1]) +
          " of 255): a photo paints its plane opaque, and what shows through is not known (it would be read as "
          "composed onto black); flatten it onto a background first");
    }
  }
  img.format = PNG_FORMAT_GRAY;
  std::vector<unsigned char> px(PNG_IMAGE_SIZE(img));
  if (!png_image_finish_read(&img, nullptr, px.data(), 0, nullptr)) {
    const std::string msg = img.message;
    png_image_free(&img);
    throw std::runtime_error(path + ": corrupt PNG: " + msg);
  }
  // The simplified API reads past damaged image data with a warning, which
  // it keeps in the message (the first one) and does not fail on: a photo
  // whose header says fewer rows than its data holds, or with data after its
  // zlib stream, was rendered from what the header says, exit 0. Refused as
  // a recording's frame is, by the same rule.
  if ((img.warning_or_error & PNG_IMAGE_WARNING) != 0 && png_warning_is_about_pixels(img.message))
    throw std::runtime_error(path + ": corrupt PNG: " + img.message);
  w = static_cast<int>(img.width);
  h = static_cast<int>(img.height);
  return px;
}

#if LUMAVEL_HAVE_JPEG
struct JpegError {
  jpeg_error_mgr mgr;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

void jpeg_fail(j_common_ptr cinfo) {
  auto* err = reinterpret_cast<JpegError*>(cinfo->err);
  (*cinfo->err->format_message)(cinfo, err->message);
  std::longjmp(err->jump, 1);
}

// A warning (level -1) is damaged data that libjpeg would decode anyway,
// the missing part gray ('Premature end of JPEG file' on stderr, exit 0):
// an error here. Trace messages (level >= 0) stay silent.
void jpeg_warning_fails(j_common_ptr cinfo, int level) {
  if (level < 0) jpeg_fail(cinfo);
}

std::vector<unsigned char> load_jpeg(const std::string& path, int& w, int& h) {
  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) throw std::runtime_error(path + ": cannot open JPEG");
  jpeg_decompress_struct cinfo{};
  JpegError err{};
  cinfo.err = jpeg_std_error(&err.mgr);
  err.mgr.error_exit = jpeg_fail;
  err.mgr.emit_message = jpeg_warning_fails;
  std::vector<unsigned char> px;  // declared before setjmp: no non-trivial locals after it
  std::string too_big;
  if (setjmp(err.jump)) {
    jpeg_destroy_decompress(&cinfo);
    throw std::runtime_error(path + ": corrupt JPEG: " + err.message);
  }
  jpeg_create_decompress(&cinfo);
  jpeg_stdio_src(&cinfo, f.get());
  jpeg_read_header(&cinfo, TRUE);
  // libjpeg converts gray, YCbCr and RGB to gray, not CMYK or YCCK (print
  // files): refused as 'corrupt JPEG: Unsupported color conversion request',
  // a valid file called damaged. Said with its colour space.
  if (cinfo.jpeg_color_space == JCS_CMYK || cinfo.jpeg_color_space == JCS_YCCK) {
    const char* const space = cinfo.jpeg_color_space == JCS_CMYK ? "CMYK" : "YCCK";
    jpeg_destroy_decompress(&cinfo);
    throw std::runtime_error(path + ": a " + space +
                             " JPEG: photos are read from grayscale, RGB or YCbCr JPEGs (save it as RGB or grayscale)");
  }
  too_big = why_photo_too_big(cinfo.image_width, cinfo.image_height);
  if (!too_big.empty()) {
    jpeg_destroy_decompress(&cinfo);
    throw std::runtime_error(path + ": " + too_big);
  }
  cinfo.out_color_space = JCS_GRAYSCALE;
  jpeg_start_decompress(&cinfo);
  w = static_cast<int>(cinfo.output_width);
  h = static_cast<int>(cinfo.output_height);
  px.resize(static_cast<size_t>(w) * static_cast<size_t>(h));
  while (cinfo.output_scanline < cinfo.output_height) {
    JSAMPROW row = px.data() + static_cast<size_t>(cinfo.output_scanline) * static_cast<size_t>(w);
    jpeg_read_scanlines(&cinfo, &row, 1);
  }
  jpeg_finish_decompress(&cinfo);
  jpeg_destroy_decompress(&cinfo);
  return px;
}

#else
std::vector<unsigned char> load_jpeg(const std::string& path, int&, int&) {
  throw std::runtime_error(path + ": JPEG photos need libjpeg (apt: libjpeg-dev) at build time");
}
#endif

// Binary PGM through the recording's own reader (image_io: one parser of the
// format, its header rules and messages; it was a second one here), then
// the photo's pixel limit.
std::vector<unsigned char> load_pgm(const std::string& path, int& w, int& h) {
  GrayImage img = read_gray_image(path);
  if (const std::string why = why_photo_too_big(static_cast<uint64_t>(img.width), static_cast<uint64_t>(img.height));
      !why.empty())
    throw std::runtime_error(path + ": " + why);
  w = img.width;
  h = img.height;
  return std::move(img.px);
}

}  // namespace

std::vector<unsigned char> load_photo_gray(const std::string& path, int& w, int& h) {
  unsigned char sig[8] = {};
  if (const std::string why = why_not_a_file(path); !why.empty()) throw std::runtime_error(path + ": photo " + why);
  {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot open photo");
    in.read(reinterpret_cast<char*>(sig), 8);
  }
  if (sig[0] == 0x89 && sig[1] == 'P' && sig[2] == 'N' && sig[3] == 'G') return load_png(path, w, h);
  if (sig[0] == 0xFF && sig[1] == 0xD8) return load_jpeg(path, w, h);
  if (sig[0] == 'P' && sig[1] == '5') return load_pgm(path, w, h);
  throw std::runtime_error(path + ": photo is neither PNG, JPEG nor binary PGM");
}

}  // namespace lumavel::host::render
