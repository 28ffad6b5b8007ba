#include "barrel_lens.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "lumavel/host/lens_distortion.hpp"
#include "lumavel/host/lens_table.hpp"
#include "lumavel/protocol/descriptor.hpp"
#include "lumavel/protocol/lens.hpp"
#include "lumavel/units/si.hpp"

namespace lumavel::stream {

double undistort(double xd, double k1) {
  host::LensDistortion lens;
  lens.k = {k1, 0, 0, 0};  // radial-tangential with k1 only, on the principal row (y = 0)
  double x = xd, y = 0;
  if (!lens.undistort(xd, 0, x, y)) {  // cannot happen for the k1 above; say so if it does
    std::fprintf(stderr, "barrel lens: k1 = %g cannot be inverted at x_d = %g\n", k1, xd);
    std::exit(1);
  }
  return x;
}

std::vector<EdgeOffsetQ15> barrel_edge_offsets(const CameraGeometry& g, uint16_t width, double k1) {
  const double fu = si::Pixel::to_si(g.fu), cu = si::Pixel::to_si(g.cu), axis = si::Angle::to_si(g.axis_yaw);
  std::vector<AngleQ28> edges;
  for (int u = 0; u <= width; ++u) {
    const double edge = axis + g.u_sign * std::atan(undistort((u - 0.5 - cu) / fu, k1));
    edges.push_back(si::Angle::from_si(edge));
  }
  const host::LensTable t = host::lens_table(g, width, edges);
  if (t.bad_edge >= 0) {  // cannot happen for the k1 above; say so if it does
    std::fprintf(stderr, "barrel lens: correction of edge %d (%g rad) does not fit Q15\n", t.bad_edge,
                 t.bad_offset_rad);
    std::exit(1);
  }
  return t.offsets;
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
