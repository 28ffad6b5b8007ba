#include "lumavel/host/render/view_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace lumavel::host::render {
namespace {

constexpr int kMaxDepth = 2;       // up to 4x4 sub-rectangles per pixel
constexpr double kSkewTol = 0.2;   // footprint departure from a rectangle
constexpr int kMaxPlanes = kMaxScenePlanes;

// A plane seen from one camera pose: pixel (u, v) -> plane coordinates is a
// homography, s = cs + (S.U)/(D.U), v = cv + (V.U)/(D.U), U = (u, v, 1);
// the ray parameter lambda = g/(D.U) must be positive.
struct Corner {
  double s = 0, t = 0, lambda = 0;
  bool ok = false;
};

struct PlaneView {
  const ScenePlane* plane = nullptr;
  // Pixel-corner values along the top and bottom edges of the current row
  // (index u - u0 + 0.5): shared by neighbouring pixels and rows.
  std::vector<Corner> top, bottom;
  int bottom_row = -2;  // row whose bottom edge `bottom` holds
  Eigen::Vector3d D, S, V;
  double cs = 0, cv = 0, g = 0;
  int u0 = 0, u1 = -1, r0 = 0, r1 = -1;  // pixel bounding box (inclusive)
  double bu0 = 0, bu1 = 0, bv0 = 0, bv1 = 0;  // same, unclipped (ideal pinhole coordinates)

  bool eval(double u, double v, double& s, double& t, double& lambda) const {
    const double d = D[0] * u + D[1] * v + D[2];
    if (d == 0.0) return false;
    lambda = g / d;
    if (!(lambda > 0)) return false;
    const double inv = 1.0 / d;
    s = cs + (S[0] * u + S[1] * v + S[2]) * inv;
    t = cv + (V[0] * u + V[1] * v + V[2]) * inv;
    return true;
  }

  void fill_edge(std::vector<Corner>& edge, double v) const {
    edge.resize(static_cast<size_t>(u1 - u0 + 2));
    for (size_t i = 0; i < edge.size(); ++i) {
      Corner& c = edge[i];
      c.ok = eval(u0 - 0.5 + static_cast<double>(i), v, c.s, c.t, c.lambda);
    }
  }
  // Makes top/bottom hold the edges of row r (rows are visited in order).
  void prepare_row(int r) {
    if (bottom_row == r - 1) {
      top.swap(bottom);
    } else {
      fill_edge(top, r - 0.5);
    }
    fill_edge(bottom, r + 0.5);
    bottom_row = r;
  }
};

Eigen::Matrix3d pixel_to_ray(const Pinhole& c) {
  Eigen::Matrix3d K_inv;
  K_inv << 1 / c.fu, 0, -c.cu / c.fu,  //
      0, 1 / c.fv, -c.cv / c.fv,       //
      0, 0, 1;
  return K_inv;
}

// Sets up the homography and the image bounding box of the plane's rectangle
// (its corners clipped to the half-space in front of the camera). Without
// `clip_to_image` (distorted lens: the rays reach beyond the pinhole image)
// only the unclipped box is set.
bool make_view(const ScenePlane& p, const Pinhole& cam, const RigidPose& T_WC, PlaneView& pv,
               bool clip_to_image = true) {
  const Eigen::Vector3d& C = T_WC.t;
  pv.plane = &p;
  pv.g = (p.origin - C).dot(p.normal);
  if (std::fabs(pv.g) < 1e-9) return false;  // camera in the plane: seen edge-on
  const Eigen::Matrix3d M = T_WC.R * pixel_to_ray(cam);
  pv.D = M.transpose() * p.normal;
  pv.S = pv.g * (M.transpose() * p.e_s);
  pv.V = pv.g * (M.transpose() * p.e_v);
  pv.cs = (C - p.origin).dot(p.e_s);
  pv.cv = (C - p.origin).dot(p.e_v);

  const Eigen::Vector3d corner[4] = {p.origin, p.origin + p.length * p.e_s,
                                     p.origin + p.length * p.e_s + p.height * p.e_v,
                                     p.origin + p.height * p.e_v};
  Eigen::Vector3d cc[4];
  for (int i = 0; i < 4; ++i) cc[i] = T_WC.R.transpose() * (corner[i] - C);
  // Clip the quadrilateral to z >= z_near (Sutherland-Hodgman, one plane).
  constexpr double z_near = 1e-4;
  Eigen::Vector3d poly[8];
  int n = 0;
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d& a = cc[i];
    const Eigen::Vector3d& b = cc[(i + 1) % 4];
    const bool ina = a.z() >= z_near, inb = b.z() >= z_near;
    if (ina) poly[n++] = a;
    if (ina != inb) poly[n++] = a + (b - a) * ((z_near - a.z()) / (b.z() - a.z()));
  }
  if (n == 0) return false;
  double umin = 1e300, umax = -1e300, vmin = 1e300, vmax = -1e300;
  for (int i = 0; i < n; ++i) {
    const double u = cam.fu * poly[i].x() / poly[i].z() + cam.cu;
    const double v = cam.fv * poly[i].y() / poly[i].z() + cam.cv;
    umin = std::min(umin, u);
    umax = std::max(umax, u);
    vmin = std::min(vmin, v);
    vmax = std::max(vmax, v);
  }
  pv.bu0 = umin;
  pv.bu1 = umax;
  pv.bv0 = vmin;
  pv.bv1 = vmax;
  if (!clip_to_image) return true;
  if (umax < -1 || vmax < -1 || umin > cam.width || vmin > cam.height) return false;
  pv.u0 = static_cast<int>(std::max(0.0, std::floor(umin)));
  pv.u1 = static_cast<int>(std::min(cam.width - 1.0, std::ceil(umax)));
  pv.r0 = static_cast<int>(std::max(0.0, std::floor(vmin)));
  pv.r1 = static_cast<int>(std::min(cam.height - 1.0, std::ceil(vmax)));
  return pv.u0 <= pv.u1 && pv.r0 <= pv.r1;
}

struct Hit {
  double lambda, cover;
  double s0, s1, t0, t1;  // footprint clipped to the plane; s0 == s1: a point
  const SurfacePattern* pattern;
  bool skewed;  // footprint far from a rectangle: split if this plane shows
  double value() const {
    if (s1 > s0 && t1 > t0) return pattern->integral(s0, s1, t0, t1) / ((s1 - s0) * (t1 - t0));
    return pattern->mean_over(s0, s1, t0, t1);
  }
};

// Area average over the image rectangle [ua,ub] x [va,vb]; returns the value
// and adds the background fraction to `bg`. Geometry first, then patterns
// are integrated front to back only for the planes that actually show.
// `col` >= 0: the rectangle is pixel `col` of the prepared row, whose corners
// are cached in the views; -1: evaluate the corners.
double sample_rect(const PlaneView* const* cands, int nc, double background, double ua, double ub,
                   double va, double vb, int depth, double& bg, int col = -1) {
  Hit hits[kMaxPlanes];
  int nh = 0;
  bool split = false;
  const double uc = 0.5 * (ua + ub), vc = 0.5 * (va + vb);
  for (int k = 0; k < nc && !split; ++k) {
    const PlaneView& pv = *cands[k];
    const ScenePlane& pl = *pv.plane;
    double s[4] = {}, t[4] = {}, lam[4] = {};
    const double cu[4] = {ua, ub, ua, ub}, cvv[4] = {va, va, vb, vb};
    int valid = 0;
    if (col >= 0) {
      const size_t i = static_cast<size_t>(col - pv.u0);
      const Corner* cs[4] = {&pv.top[i], &pv.top[i + 1], &pv.bottom[i], &pv.bottom[i + 1]};
      for (int c = 0; c < 4; ++c) {
        s[c] = cs[c]->s;
        t[c] = cs[c]->t;
        lam[c] = cs[c]->lambda;
        valid += cs[c]->ok ? 1 : 0;
      }
    } else {
      for (int c = 0; c < 4; ++c) valid += pv.eval(cu[c], cvv[c], s[c], t[c], lam[c]) ? 1 : 0;
    }
    if (valid != 4) {
      if (valid > 0 && depth < kMaxDepth) {
        split = true;
        continue;
      }
      if (valid == 0) continue;
      // Deepest level straddling the plane's horizon: point-sample the centre.
      double sc, tc, lc;
      if (!pv.eval(uc, vc, sc, tc, lc)) continue;
      if (sc < 0 || sc > pl.length || tc < 0 || tc > pl.height) continue;
      hits[nh++] = Hit{lc, 1.0, sc, sc, tc, tc, pl.pattern.get(), false};
      continue;
    }
    // Edges of the footprint: left/right along s, top/bottom along v.
    const double sl = 0.5 * (s[0] + s[2]), sr = 0.5 * (s[1] + s[3]);
    const double vt = 0.5 * (t[0] + t[1]), vbm = 0.5 * (t[2] + t[3]);
    const double ws = std::fabs(sr - sl), wv = std::fabs(vbm - vt);
    const double csa = std::max(std::min(sl, sr), 0.0), csb = std::min(std::max(sl, sr), pl.length);
    const double cta = std::max(std::min(vt, vbm), 0.0), ctb = std::min(std::max(vt, vbm), pl.height);
    if (csb < csa || ctb < cta) continue;
    const double area = ws * wv;
    double cover = 1;
    if (area > 0) {
      const double clipped = (csb - csa) * (ctb - cta);
      if (clipped <= 0) continue;
      cover = std::min(clipped / area, 1.0);
    }
    bool skewed = false;
    if (depth < kMaxDepth) {
      const double skew = std::max(std::fabs(s[0] - s[2]), std::fabs(s[1] - s[3])) / (ws + 1e-300) +
                          std::max(std::fabs(t[0] - t[1]), std::fabs(t[2] - t[3])) / (wv + 1e-300);
      skewed = skew > kSkewTol;
    }
    // Depth at the centre orders the planes; alone, a plane needs no order.
    double sc, tc, lc = lam[0];
    if (nc > 1 && !pv.eval(uc, vc, sc, tc, lc)) lc = lam[0];
    hits[nh++] = Hit{lc, cover, csa, csb, cta, ctb, pl.pattern.get(), skewed};
  }
  std::sort(hits, hits + nh, [](const Hit& a, const Hit& b) { return a.lambda < b.lambda; });
  double remaining = 1;
  for (int k = 0; k < nh && remaining > 0; ++k) {
    split = split || hits[k].skewed;  // only planes that show can ask for a split
    remaining -= std::min(hits[k].cover, remaining);
  }
  if (split) {
    const double um = uc, vm = vc;
    double bq = 0;
    const double sum = sample_rect(cands, nc, background, ua, um, va, vm, depth + 1, bq) +
                       sample_rect(cands, nc, background, um, ub, va, vm, depth + 1, bq) +
                       sample_rect(cands, nc, background, ua, um, vm, vb, depth + 1, bq) +
                       sample_rect(cands, nc, background, um, ub, vm, vb, depth + 1, bq);
    bg += 0.25 * bq;
    return 0.25 * sum;
  }
  // Front to back, each plane taking its covered fraction out of what is
  // still uncovered (coverages taken as disjoint: exact for a partial plane
  // in front of a full one and for planes that abut, e.g. wall sections).
  double rem = 1, acc = 0;
  for (int k = 0; k < nh && rem > 0; ++k) {
    const double c = std::min(hits[k].cover, rem);
    acc += c * hits[k].value();
    rem -= c;
  }
  bg += rem;
  return acc + rem * background;
}

// Distorted lens: each output pixel is split into kLensSubdiv^2 equal
// sub-pixels of the recorded (distorted) image; each sub-pixel's corners are
// undistorted and its footprint in the pinhole image, taken as the rectangle
// between its mean edges, is area-averaged like an undistorted pixel. The
// sub-pixels weigh equally, so the result is the area average over the
// distorted pixel up to the lens's variation inside a quarter pixel.
double render_view_distorted(const Scene& scene, const Pinhole& cam, const RigidPose& T_WC,
                             double gain, std::vector<double>& accum) {
  const std::shared_ptr<const LensGrid> grid = cam.lens_grid ? cam.lens_grid : make_lens_grid(cam);
  std::vector<PlaneView> views;
  views.reserve(scene.planes.size());
  for (const auto& p : scene.planes) {
    PlaneView pv;
    if (make_view(p, cam, T_WC, pv, false)) views.push_back(pv);
  }
  if (views.size() > static_cast<size_t>(kMaxPlanes)) views.resize(kMaxPlanes);
  constexpr double kSubWeight = 1.0 / (kLensSubdiv * kLensSubdiv);
  const size_t gw = static_cast<size_t>(grid->w);
  double bg_total = 0;
  const PlaneView* cands[kMaxPlanes];
  for (int r = 0; r < cam.height; ++r) {
    double* out = accum.data() + static_cast<size_t>(r) * static_cast<size_t>(cam.width);
    for (int c = 0; c < cam.width; ++c) {
      double sum = 0, bg = 0;
      for (int sy = 0; sy < kLensSubdiv; ++sy) {
        for (int sx = 0; sx < kLensSubdiv; ++sx) {
          const size_t i = static_cast<size_t>(kLensSubdiv * c + sx);
          const size_t j = static_cast<size_t>(kLensSubdiv * r + sy);
          const size_t k[4] = {j * gw + i, j * gw + i + 1, (j + 1) * gw + i, (j + 1) * gw + i + 1};
          const double* U = grid->u.data();
          const double* V = grid->v.data();
          const double ua = 0.5 * (U[k[0]] + U[k[2]]), ub = 0.5 * (U[k[1]] + U[k[3]]);
          const double va = 0.5 * (V[k[0]] + V[k[1]]), vb = 0.5 * (V[k[2]] + V[k[3]]);
          if (!(std::isfinite(ua) && std::isfinite(ub) && std::isfinite(va) && std::isfinite(vb))) {
            sum += scene.background;  // no ray: nothing is seen there
            bg += 1;
            continue;
          }
          double lo_u = U[k[0]], hi_u = lo_u, lo_v = V[k[0]], hi_v = lo_v;
          for (int q = 1; q < 4; ++q) {
            lo_u = std::min(lo_u, U[k[q]]);
            hi_u = std::max(hi_u, U[k[q]]);
            lo_v = std::min(lo_v, V[k[q]]);
            hi_v = std::max(hi_v, V[k[q]]);
          }
          int nc = 0;
          for (const auto& pv : views)
            if (pv.bu1 >= lo_u - 1 && pv.bu0 <= hi_u + 1 && pv.bv1 >= lo_v - 1 && pv.bv0 <= hi_v + 1)
              cands[nc++] = &pv;
          // One level of further splitting (2x2) for oblique planes and horizons.
          sum += sample_rect(cands, nc, scene.background, ua, ub, va, vb, kMaxDepth - 1, bg);
        }
      }
      out[c] += gain * sum * kSubWeight;
      bg_total += bg * kSubWeight;
    }
  }
  return bg_total / (static_cast<double>(cam.width) * cam.height);
}

}  // namespace

double render_view(const Scene& scene, const Pinhole& cam, const RigidPose& T_WC, double gain,
                   std::vector<double>& accum) {
  if (!cam.lens.none()) return render_view_distorted(scene, cam, T_WC, gain, accum);
  std::vector<PlaneView> views;
  views.reserve(scene.planes.size());
  for (const auto& p : scene.planes) {
    PlaneView pv;
    if (make_view(p, cam, T_WC, pv)) views.push_back(pv);
  }
  if (views.size() > static_cast<size_t>(kMaxPlanes)) views.resize(kMaxPlanes);
  double bg_total = 0;
  const PlaneView* row_cands[kMaxPlanes];
  const PlaneView* cands[kMaxPlanes];
  for (int r = 0; r < cam.height; ++r) {
    int nr = 0;
    for (auto& pv : views) {
      if (r < pv.r0 || r > pv.r1) continue;
      pv.prepare_row(r);
      row_cands[nr++] = &pv;
    }
    double* out = accum.data() + static_cast<size_t>(r) * static_cast<size_t>(cam.width);
    for (int c = 0; c < cam.width; ++c) {
      int nc = 0;
      for (int k = 0; k < nr; ++k)
        if (c >= row_cands[k]->u0 && c <= row_cands[k]->u1) cands[nc++] = row_cands[k];
      double bg = 0;
      const double v = sample_rect(cands, nc, scene.background, c - 0.5, c + 0.5, r - 0.5, r + 0.5,
                                   0, bg, c);
      out[c] += gain * v;
      bg_total += bg;
    }
  }
  return bg_total / (static_cast<double>(cam.width) * cam.height);
}

bool pixel_hit(const Scene& scene, const Pinhole& cam, const RigidPose& T_WC, double u, double v,
               Eigen::Vector3d& hit) {
  if (!cam.lens.none() && !undistort_pixel(cam, u, v, u, v)) return false;
  double best = 1e300;
  bool found = false;
  for (const auto& p : scene.planes) {
    PlaneView pv;
    if (!make_view(p, cam, T_WC, pv)) continue;
    double s, t, lam;
    if (!pv.eval(u, v, s, t, lam)) continue;
    if (s < 0 || s > p.length || t < 0 || t > p.height || lam >= best) continue;
    best = lam;
    hit = p.origin + s * p.e_s + t * p.e_v;
    found = true;
  }
  return found;
}

bool project(const Pinhole& cam, const RigidPose& T_WC, const Eigen::Vector3d& p_w, double& u,
             double& v) {
  const Eigen::Vector3d p = T_WC.R.transpose() * (p_w - T_WC.t);
  if (p.z() <= 1e-9) return false;
  u = cam.fu * p.x() / p.z() + cam.cu;
  v = cam.fv * p.y() / p.z() + cam.cv;
  if (!cam.lens.none()) distort_pixel(cam, u, v, u, v);
  return true;
}

}  // namespace lumavel::host::render
