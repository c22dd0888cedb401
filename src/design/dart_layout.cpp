#include "membra/design/dart_layout.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "membra/core/units.hpp"
#include "membra/design/target_correspondence.hpp"
#include "membra/measure/curvature.hpp"
#include "membra/model/pattern_spec.hpp"

namespace membra {
namespace {

constexpr double kPi = std::numbers::pi;

// Where a ray from `from` (relative to the centre) leaves a footprint or sheet of half-sides
// `half`: on the disk's circle, or on the box's side.
double reach(const Vec2& half, bool disk, const Vec2& from, double theta) {
  const Vec2 d(std::cos(theta), std::sin(theta));
  if (disk) {
    const double b = from.dot(d), r = half.minCoeff();
    return -b + std::sqrt(std::max(b * b - from.squaredNorm() + r * r, 0.0));
  }
  double t = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 2; ++a)
    if (std::abs(d(a)) > 1e-12) t = std::min(t, ((d(a) > 0 ? half(a) : -half(a)) - from(a)) / d(a));
  return std::max(t, 0.0);
}

// y at t, linear between the samples (x ascending), held at the ends.
double interpolate(const std::vector<double>& x, const std::vector<double>& y, double t) {
  t = std::clamp(t, x.front(), x.back());
  const auto it = std::lower_bound(x.begin(), x.end(), t);
  const size_t i = std::clamp<size_t>(static_cast<size_t>(it - x.begin()), 1, x.size() - 1);
  const double w = (t - x[i - 1]) / std::max(x[i] - x[i - 1], 1e-15);
  return (1.0 - w) * y[i - 1] + w * y[i];
}

// Through mm, as a scene file holds it, so that the stencil simulated is the one written.
Vec2 polar(const Vec2& centre, double r, double theta) {
  const Vec2 p = centre + r * Vec2(std::cos(theta), std::sin(theta));
  return (p / units::mm) * units::mm;
}

// The polygon between two sides sampled in the same order (left up, right back down); empty when
// fewer than two samples.
PatternSpec outline(const std::vector<Vec2>& left, const std::vector<Vec2>& right) {
  PatternSpec p;
  p.kind = PatternSpec::Kind::polygon;
  if (left.size() < 2) return p;
  p.points = left;
  p.points.insert(p.points.end(), right.rbegin(), right.rend());
  return p;
}

// The frame's points for the profiles' centres: the footprint laid over the frame, centre on
// centre, each axis scaled to fit.
std::vector<Vec2> frame_centres(const std::vector<DartProfile>& profiles, const Box2& frame) {
  const Vec2 middle = 0.5 * (frame.min + frame.max), half = 0.5 * (frame.max - frame.min);
  std::vector<Vec2> out;
  for (const DartProfile& p : profiles)
    out.push_back(middle + p.centre.cwiseProduct(half.cwiseQuotient(p.footprint)));
  return out;
}

// Whether frame point q is in centre `own`'s Voronoi cell, `margin` short of its border.
bool in_cell(const std::vector<Vec2>& centres, size_t own, const Vec2& q, double margin) {
  for (size_t j = 0; j < centres.size(); ++j) {
    if (j == own) continue;
    const Vec2 axis = centres[j] - centres[own];
    // The signed distance past the bisector, towards centre j.
    if ((q - 0.5 * (centres[own] + centres[j])).dot(axis) / axis.norm() > -margin) return false;
  }
  return true;
}

// One dart around direction `theta` from centre `own`: the wedge from where it is min_feature
// wide to beyond the frame's corners (or its cell's border), as a polygon (empty when it is
// nowhere that wide).
PatternSpec dart(const std::vector<DartProfile>& profiles, const std::vector<Vec2>& centres,
                 size_t own, const Box2& frame, bool disk, double theta, const DartOptions& o) {
  const DartProfile& profile = profiles[own];
  const Vec2 centre = centres[own], half = 0.5 * (frame.max - frame.min);
  const Vec2 from = centre - 0.5 * (frame.min + frame.max);
  const double sector = 2.0 * kPi / o.darts, shrink = 1.0 - 1.0 / o.lambda;
  const double r_end = 1.05 * (from.cwiseAbs() + half).norm();
  constexpr int steps = 96, sub = 9;
  std::vector<Vec2> left, right;
  for (int i = 1; i <= steps; ++i) {
    const double r = r_end * i / steps;
    // The sector's mean deficit at this frame radius (each ray's u is r over its own reach).
    double deficit = 0.0;
    for (int j = 0; j < sub; ++j) {
      const double t = theta + sector * ((j + 0.5) / sub - 0.5);
      deficit += profile.at(t, std::min(r / reach(half, disk, from, t), 1.0)) / sub;
    }
    const double share = std::clamp(o.scale * deficit / shrink, 0.0, 1.0);
    const double arc = r * sector;  // the sector's width at r
    const double width = std::min(share * arc, arc - o.min_feature);
    if (width < o.min_feature) {
      if (!left.empty()) break;  // narrowing again: the dart ends here
      continue;
    }
    const double half_angle = 0.5 * width / r;
    const Vec2 l = polar(centre, r, theta - half_angle), rt = polar(centre, r, theta + half_angle);
    if (!in_cell(centres, own, l, 0.5 * o.min_feature) ||
        !in_cell(centres, own, rt, 0.5 * o.min_feature)) {
      if (!left.empty()) break;  // the dart ends at its cell's border
      continue;
    }
    left.push_back(l);
    right.push_back(rt);
  }
  return outline(left, right);
}

}  // namespace

double DartProfile::at(double theta, double u) const {
  if (rays == 0) return 0.0;
  double t = std::fmod(theta, 2.0 * kPi);
  if (t < 0.0) t += 2.0 * kPi;
  const int k = static_cast<int>(std::lround(t / (2.0 * kPi) * rays)) % rays;
  const std::vector<double>& sk = s[static_cast<size_t>(k)];
  return interpolate(sk, deficit[static_cast<size_t>(k)], std::clamp(u, 0.0, 1.0) * sk.back());
}

DartProfile dart_profile(const TargetSurface& target, int rays, int samples) {
  const Vec2 lo = target.x.topRows<2>().rowwise().minCoeff();
  const Vec2 hi = target.x.topRows<2>().rowwise().maxCoeff();
  return dart_profile(target, 0.5 * (lo + hi), rays, samples);
}

DartProfile dart_profile(const TargetSurface& target, const Vec2& c, int rays, int samples) {
  const Vec2 lo = target.x.topRows<2>().rowwise().minCoeff();
  const Vec2 hi = target.x.topRows<2>().rowwise().maxCoeff();
  const Vec2 half = 0.5 * (hi - lo), from = c - 0.5 * (lo + hi);
  const auto point = [&](double rho, double theta) {
    const Vec2 q = c + rho * Vec2(std::cos(theta), std::sin(theta));
    return Vec3(q.x(), q.y(), target_height(target, q));
  };
  DartProfile p;
  p.centre = from;
  p.footprint = half;
  p.rays = rays;
  p.s.assign(static_cast<size_t>(rays), {});
  p.deficit.assign(static_cast<size_t>(rays), {});
  const double dtheta = 1e-3;
  for (int k = 0; k < rays; ++k) {
    const double theta = 2.0 * kPi * k / rays, length = reach(half, target.disk, from, theta);
    auto& s = p.s[static_cast<size_t>(k)];
    auto& d = p.deficit[static_cast<size_t>(k)];
    s.push_back(0.0);
    d.push_back(0.0);
    Vec3 last = point(0.0, theta);
    for (int i = 1; i <= samples; ++i) {
      // The last sample a little inside the rim, so that the sideways points at theta +- dtheta
      // stay on a square footprint too (beyond it the target's height is its nearest vertex's).
      const double rho = length * i / samples * (1.0 - 4.0 * dtheta);
      const Vec3 x = point(rho, theta);
      s.push_back(s.back() + (x - last).norm());
      last = x;
      const double around = (point(rho, theta + dtheta) - point(rho, theta - dtheta)).norm() /
                            (2.0 * std::sin(dtheta));  // the chord of a circle: exact on a plane
      d.push_back(1.0 - around / s.back());
    }
    // The ray's length along the surface, scaled from where it leaves the footprint to the
    // inscribed half-width: the frame's half-width is laid over that (dart() and the frame fit).
    p.radius += s.back() * half.minCoeff() / (length * (1.0 - 4.0 * dtheta)) / rays;
  }
  return p;
}

namespace {

// The target's Gaussian curvature on an n x n grid over its footprint, from second differences
// `h` apart (wider than the target's triangles, whose heights are linear in between); points
// within h of the rim, or off a disk, are NaN.
std::vector<double> curvature_grid(const TargetSurface& target, int n, double h,
                                   std::vector<Vec2>& points) {
  const Vec2 lo = target.x.topRows<2>().rowwise().minCoeff();
  const Vec2 hi = target.x.topRows<2>().rowwise().maxCoeff();
  const Vec2 c = 0.5 * (lo + hi);
  std::vector<double> k;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vec2 p = lo + (hi - lo).cwiseProduct(Vec2(i, j) / (n - 1.0));
      points.push_back(p - c);
      const bool inside = target.disk
                              ? (p - c).norm() < 0.5 * (hi - lo).minCoeff() - h
                              : ((p - lo).array() > h).all() && ((hi - p).array() > h).all();
      if (!inside) {
        k.push_back(std::numeric_limits<double>::quiet_NaN());
        continue;
      }
      // The nine heights of the 3 x 3 stencil, each looked up once: z[1 + dx][1 + dy].
      double z[3][3];
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          z[1 + dx][1 + dy] = target_height(target, p + h * Vec2(dx, dy));
      const double zx = (z[2][1] - z[0][1]) / (2 * h), zy = (z[1][2] - z[1][0]) / (2 * h);
      const double zxx = (z[2][1] + z[0][1] - 2 * z[1][1]) / (h * h);
      const double zyy = (z[1][2] + z[1][0] - 2 * z[1][1]) / (h * h);
      const double zxy = (z[2][2] - z[2][0] - z[0][2] + z[0][0]) / (4 * h * h);
      const double g = 1.0 + zx * zx + zy * zy;
      k.push_back((zxx * zyy - zxy * zxy) / (g * g));
    }
  return k;
}

}  // namespace

std::vector<Vec2> curvature_peaks(const TargetSurface& target, double separation) {
  const Vec2 lo = target.x.topRows<2>().rowwise().minCoeff();
  const Vec2 hi = target.x.topRows<2>().rowwise().maxCoeff();
  constexpr int n = 61;
  std::vector<Vec2> p;
  const std::vector<double> k = curvature_grid(target, n, 0.1 * (hi - lo).minCoeff(), p);
  double top = 0.0;
  for (double v : k)
    if (std::isfinite(v)) top = std::max(top, v);
  // A point on the border of the grid's valid part cannot tell a peak from a slope cut off.
  const auto interior = [&](size_t i) {
    const int a = static_cast<int>(i) % n, b = static_cast<int>(i) / n;
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        const int x = a + di, y = b + dj;
        if (x < 0 || y < 0 || x >= n || y >= n || !std::isfinite(k[static_cast<size_t>(y * n + x)]))
          return false;
      }
    return true;
  };
  std::vector<std::pair<double, Vec2>> peaks;
  for (size_t i = 0; i < k.size(); ++i) {
    if (!std::isfinite(k[i]) || k[i] <= 0.0 || k[i] < 0.3 * top || !interior(i)) continue;
    double lowest = k[i];
    bool highest = true;
    for (size_t j = 0; j < k.size() && highest; ++j) {
      if (j == i || !std::isfinite(k[j]) || (p[j] - p[i]).norm() > separation) continue;
      highest = k[j] < k[i] || (k[j] == k[i] && j > i);  // of a tie, the first
      lowest = std::min(lowest, k[j]);
    }
    if (highest && k[i] - lowest >= 0.25 * k[i]) peaks.emplace_back(k[i], p[i]);
  }
  std::sort(peaks.begin(), peaks.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<Vec2> out;
  for (const auto& [value, point] : peaks)
    if (out.size() < 16) out.push_back(point);
  return out;
}

namespace {

// A polygon from its corners, through mm as a scene file holds them.
PatternSpec box_spec(const Vec2& lo, const Vec2& hi) {
  PatternSpec p;
  p.kind = PatternSpec::Kind::polygon;
  p.points = {lo, Vec2(hi.x(), lo.y()), hi, Vec2(lo.x(), hi.y())};
  for (Vec2& q : p.points) q = (q / units::mm) * units::mm;
  return p;
}

// The sheet's resin on each face (top, bottom) before the holes: the whole sheet on the top
// face, or with `face`, square cells of about `cell` on the face each names (empty when none).
std::array<PatternSpec, 2> faces_of(const Box2& frame, bool disk, const DartOptions& o) {
  const Vec2 centre = 0.5 * (frame.min + frame.max), half = 0.5 * (frame.max - frame.min);
  // The sheet, a little larger so that its edge particles are inside.
  const Vec2 lo = centre - 1.02 * half, hi = centre + 1.02 * half;
  const PatternSpec sheet = disk ? circle_spec(centre, 1.02 * half.minCoeff()) : box_spec(lo, hi);
  if (!o.face) return {sheet, {}};
  std::array<std::vector<PatternSpec>, 2> cells;
  const Vec2 size = frame.max - frame.min;
  const int nx = std::max(1, static_cast<int>(std::lround(size.x() / o.cell)));
  const int ny = std::max(1, static_cast<int>(std::lround(size.y() / o.cell)));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const Vec2 a = frame.min + size.cwiseProduct(Vec2(double(i) / nx, double(j) / ny));
      const Vec2 b = frame.min + size.cwiseProduct(Vec2(double(i + 1) / nx, double(j + 1) / ny));
      // Cells on the rim reach as far as the sheet's outline above.
      const Vec2 c0(i == 0 ? lo.x() : a.x(), j == 0 ? lo.y() : a.y());
      const Vec2 c1(i == nx - 1 ? hi.x() : b.x(), j == ny - 1 ? hi.y() : b.y());
      cells[o.face(0.5 * (a + b)) < 0 ? 1 : 0].push_back(box_spec(c0, c1));
    }
  // All on one face: the whole sheet there. Else each face is the sheet less the other's cells,
  // so that both stay inside its outline (a disk's too).
  if (cells[1].empty()) return {sheet, {}};
  if (cells[0].empty()) return {PatternSpec{}, sheet};
  std::array<PatternSpec, 2> out;
  for (int f = 0; f < 2; ++f) {
    std::vector<PatternSpec> parts = {sheet};
    for (PatternSpec& c : cells[1 - f]) parts.push_back(std::move(c));
    out[static_cast<size_t>(f)] = difference_spec(std::move(parts));
  }
  return out;
}

// The sheet in resin, less `holes` of bare latex (which leave it in one piece: each dart and
// lens ends inside the sheet or at its rim, never across it); with `o.face`, on two faces.
Stencil sheet_less(const std::vector<PatternSpec>& holes, const Box2& frame, bool disk,
                   const DartOptions& o) {
  const Vec2 centre = 0.5 * (frame.min + frame.max), half = 0.5 * (frame.max - frame.min);
  const std::array<PatternSpec, 2> base = faces_of(frame, disk, o);
  const auto less = [&](const PatternSpec& b) {
    std::vector<PatternSpec> parts = {b};
    for (const PatternSpec& h : holes)
      if (!h.points.empty()) parts.push_back(h);
    return parts.size() == 1 ? b : difference_spec(std::move(parts));
  };
  const auto empty = [](const PatternSpec& p) {
    return p.kind == PatternSpec::Kind::polygon && p.points.empty();
  };
  Stencil out;
  if (!empty(base[0])) {
    out.spec = less(base[0]);
    out.pattern = make_pattern(out.spec, frame.max - frame.min);
  }
  if (!empty(base[1])) {
    out.spec_bottom = less(base[1]);
    out.pattern_bottom = make_pattern(out.spec_bottom, frame.max - frame.min);
  }
  out.pieces = (out.pattern ? 1 : 0) + (out.pattern_bottom ? 1 : 0);
  // The resin's share of the sheet, counted on a fine grid.
  constexpr int n = 200;
  int inside = 0, resin = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vec2 q =
          frame.min + (frame.max - frame.min).cwiseProduct(Vec2((i + 0.5) / n, (j + 0.5) / n));
      if (disk && (q - centre).norm() > half.minCoeff()) continue;
      ++inside;
      resin += (out.pattern && out.pattern->contains(q)) ||
                       (out.pattern_bottom && out.pattern_bottom->contains(q))
                   ? 1
                   : 0;
    }
  out.outline_area = (frame.max - frame.min).prod() * inside / (n * n);
  out.resin_share = inside > 0 ? static_cast<double>(resin) / inside : 0.0;
  return out;
}

}  // namespace

Stencil layout_darts(const std::vector<DartProfile>& profiles, const Box2& frame, bool disk,
                     const DartOptions& options) {
  const std::vector<Vec2> centres = frame_centres(profiles, frame);
  std::vector<PatternSpec> darts;
  // Centred half a sector from the x axis: for an even count the darts are symmetric about
  // both axes (six darts: two on the y axis, none on the x axis).
  for (size_t c = 0; c < profiles.size(); ++c)
    for (int k = 0; k < options.darts; ++k)
      darts.push_back(
          dart(profiles, centres, c, frame, disk, 2.0 * kPi * (k + 0.5) / options.darts, options));
  return sheet_less(darts, frame, disk, options);
}

RowProfile row_profile(const TargetSurface& target, int axis, int bins) {
  if (bins < 3 || bins % 2 == 0)
    throw std::invalid_argument("row_profile: an odd number of bins, at least 3");
  const int across = 1 - axis;
  const double lo = target.x.row(across).minCoeff(), hi = target.x.row(across).maxCoeff();
  const double width = (hi - lo) / bins;
  // Angle defects over areas, per bin across.
  const GaussianCurvature k = gaussian_curvature(target.x, target.triangles);
  std::vector<double> defect(static_cast<size_t>(bins)), area(static_cast<size_t>(bins));
  // Each vertex shared between the two nearest bin centres (so a mirrored target bins mirrored).
  for (Eigen::Index i = 0; i < target.x.cols(); ++i) {
    if (!k.interior[static_cast<size_t>(i)]) continue;
    const double t = std::clamp((target.x(across, i) - lo) / width - 0.5, 0.0, bins - 1.0);
    const int b = std::min(static_cast<int>(t), bins - 2);
    const double w = t - b;
    for (const auto& [bin, weight] : {std::pair{b, 1.0 - w}, std::pair{b + 1, w}}) {
      defect[static_cast<size_t>(bin)] += weight * k.angle_defect[static_cast<size_t>(i)];
      area[static_cast<size_t>(bin)] += weight * k.area[static_cast<size_t>(i)];
    }
  }
  RowProfile p;
  p.axis = axis;
  std::vector<double> length(static_cast<size_t>(bins));
  // L'' = -K L outwards from the middle, L = 1 and L' = 0 there (bins of equal width).
  const auto curvature = [&](size_t b) { return area[b] > 0.0 ? defect[b] / area[b] : 0.0; };
  // Velocity Verlet from the middle bin (second order: exact for a constant K to O(K^2 v^4)).
  const int mid = bins / 2;
  for (int side : {-1, +1}) {
    double l = 1.0, slope = 0.0;
    length[static_cast<size_t>(mid)] = l;
    for (int b = mid; b + side >= 0 && b + side < bins; b += side) {
      slope -= 0.5 * curvature(static_cast<size_t>(b)) * l * width;
      l += slope * width;
      slope -= 0.5 * curvature(static_cast<size_t>(b + side)) * l * width;
      length[static_cast<size_t>(b + side)] = l;
    }
  }
  const double longest = *std::max_element(length.begin(), length.end());
  for (int b = 0; b < bins; ++b) {
    p.v.push_back(lo + (b + 0.5) * width - 0.5 * (lo + hi));
    p.share.push_back(1.0 - length[static_cast<size_t>(b)] / longest);
  }
  return p;
}

Stencil layout_fisheye_darts(const RowProfile& profile, const Box2& frame, const DartOptions& o) {
  const int a = profile.axis, b = 1 - a;
  const Vec2 centre = 0.5 * (frame.min + frame.max), half = 0.5 * (frame.max - frame.min);
  const double pitch = (frame.max(a) - frame.min(a)) / o.darts, shrink = 1.0 - 1.0 / o.lambda;
  // The target's footprint across laid over the frame's, centre on centre.
  const double reach = profile.v.back() + 0.5 * (profile.v[1] - profile.v[0]);  // half-width
  const auto share = [&](double v) {  // linear between bin centres, held beyond the last
    return interpolate(profile.v, profile.share, v / half(b) * reach);
  };
  std::vector<PatternSpec> lenses;
  constexpr int samples = 97;
  for (int k = 0; k < o.darts; ++k) {
    const double along = frame.min(a) + pitch * (k + 0.5);
    std::vector<Vec2> left, right;
    const auto close = [&] {  // a run of wide-enough samples becomes one lens
      lenses.push_back(outline(left, right));
      left.clear();
      right.clear();
    };
    for (int i = 0; i < samples; ++i) {
      // A resin border at least min_feature wide across both ends keeps the sheet one piece.
      const double v = (half(b) - o.min_feature) * (2.0 * i / (samples - 1) - 1.0);
      const double width = std::min(std::clamp(o.scale * share(v) / shrink, 0.0, 1.0) * pitch,
                                    pitch - o.min_feature);
      if (width < o.min_feature) {
        close();
        continue;
      }
      Vec2 l, r;
      l(a) = along - 0.5 * width;
      r(a) = along + 0.5 * width;
      l(b) = r(b) = centre(b) + v;
      left.push_back((l / units::mm) * units::mm);
      right.push_back((r / units::mm) * units::mm);
    }
    close();
  }
  return sheet_less(lenses, frame, false, o);
}

}  // namespace membra
