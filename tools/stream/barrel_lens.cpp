#include "barrel_lens.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "lumavel/core/kernel_bank.hpp"
#include "lumavel/protocol/descriptor.hpp"
#include "lumavel/protocol/lens.hpp"

namespace lumavel::stream {

double undistort(double xd, double k1) {
  double x = xd;
  for (int it = 0; it < 40; ++it) x = xd / (1 + k1 * x * x);
  return x;
}

std::vector<EdgeOffsetQ15> barrel_edge_offsets(const CameraGeometry& g, uint16_t width, double k1) {
  std::vector<AngleQ28> pin(size_t{width} + 1);
  pinhole_column_edges(g, width, pin.data());
  const double fu = std::ldexp(g.fu, -fx::kPixelFrac);
  const double cu = std::ldexp(g.cu, -fx::kPixelFrac);
  const double axis = std::ldexp(g.axis_yaw, -fx::kAngleFrac);
  std::vector<EdgeOffsetQ15> out;
  for (int u = 0; u <= width; ++u) {
    const double edge = axis + g.u_sign * std::atan(undistort((u - 0.5 - cu) / fu, k1));
    const double d = edge - std::ldexp(pin[static_cast<size_t>(u)], -fx::kAngleFrac);
    const long q = std::lround(std::ldexp(d, fx::kEdgeOffsetFrac));
    if (q < INT16_MIN || q > INT16_MAX) {  // cannot happen for the k1 above; say so if it does
      std::fprintf(stderr, "barrel lens: correction of edge %d (%g rad) does not fit Q15\n", u, d);
      std::exit(1);
    }
    out.push_back(static_cast<EdgeOffsetQ15>(q));
  }
  return out;
}

std::vector<std::vector<uint8_t>> lens_upload_reports(protocol::DeviceConfig c,
                                                      const std::vector<EdgeOffsetQ15> (&tables)[2]) {
  std::vector<std::vector<uint8_t>> out;
  for (uint8_t cam = 0; cam < 2; ++cam) {
    const std::vector<EdgeOffsetQ15>& t = tables[cam];
    for (size_t i = 0; i < protocol::lens_piece_count(t.size()); ++i) {
      std::vector<uint8_t> r(protocol::kLensChunkSize);
      if (protocol::encode_lens_chunk(protocol::lens_piece(cam, t.data(), t.size(), i), r.data(), r.size()) !=
          r.size())
        std::abort();
      out.push_back(r);
    }
  }
  c.lens = protocol::kLensCam0 | protocol::kLensCam1;
  const EdgeOffsetQ15* const named[2] = {tables[0].data(), tables[1].data()};
  c.lens_crc = protocol::lens_crc(named, c.lens, static_cast<uint16_t>(c.width + 1));
  std::vector<uint8_t> r(protocol::kConfigSize);
  if (protocol::encode_config(c, r.data(), r.size()) != r.size()) std::abort();
  out.push_back(r);
  return out;
}

}  // namespace lumavel::stream
