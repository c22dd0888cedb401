#include "membra/geometry/size_field.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace membra {
namespace {

std::vector<SizeField::Segment> segments_of(const std::vector<Polyline2>& boundaries) {
  std::vector<SizeField::Segment> out;
  for (const Polyline2& poly : boundaries) {
    if (poly.size() < 3) continue;
    for (size_t i = 0; i < poly.size(); ++i) {
      const Vec2& a = poly[i];
      const Vec2& b = poly[(i + 1) % poly.size()];
      if ((b - a).norm() > 0.0) out.push_back({a, b});
    }
  }
  return out;
}

// Distance along the ray p + t d (|d| = 1) to the first segment it crosses, other than `self`;
// infinity when it leaves without meeting one. Hits closer than `eps` are the sample's own.
double ray_distance(const Vec2& p, const Vec2& d, const std::vector<SizeField::Segment>& segs,
                    size_t self, double eps) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < segs.size(); ++k) {
    if (k == self) continue;
    const Vec2 e = segs[k].b - segs[k].a;
    const double den = d.x() * e.y() - d.y() * e.x();  // cross(d, e)
    if (std::abs(den) < 1e-14 * e.norm()) continue;    // parallel: no single crossing
    const Vec2 w = segs[k].a - p;
    const double t = (w.x() * e.y() - w.y() * e.x()) / den;
    const double u = (w.x() * d.y() - w.y() * d.x()) / den;
    if (t > eps && t < best && u >= 0.0 && u <= 1.0) best = t;
  }
  return best;
}

}  // namespace

SizeField::SizeField(const std::vector<Polyline2>& boundaries, const Vec2& domain_min,
                     const Vec2& domain_max, const SizeFieldOptions& options)
    : options_(options), origin_(domain_min), extent_(domain_max - domain_min) {
  if (!(options.max_edge > 0.0)) throw std::invalid_argument("max_edge must be positive");
  if (options.elements_across < 1) throw std::invalid_argument("elements_across must be >= 1");
  if (!(options.grading > 0.0)) throw std::invalid_argument("grading must be positive");
  if (!(extent_.x() > 0.0) || !(extent_.y() > 0.0))
    throw std::invalid_argument("size field: the domain is empty");
  rasterize(measure(boundaries));
}

namespace {

// Calls width(p, w) at samples `spacing` apart along every boundary segment, w the width of the
// narrower region beside it (a ray along the normal each way to the next boundary); samples
// that see no boundary on either side are skipped.
template <typename Width>
void measure_widths(const std::vector<SizeField::Segment>& segs, double eps, double spacing,
                    Width&& width) {
  for (size_t k = 0; k < segs.size(); ++k) {
    const Vec2 e = segs[k].b - segs[k].a;
    const double len = e.norm();
    const Vec2 normal = Vec2(-e.y(), e.x()) / len;
    const int n = std::max(1, static_cast<int>(std::ceil(len / spacing)));
    for (int s = 0; s < n; ++s) {
      const Vec2 p = segs[k].a + ((s + 0.5) / n) * e;
      // The regions on both sides of the boundary: a resin piece and a latex gap.
      const double w =
          std::min(ray_distance(p, normal, segs, k, eps), ray_distance(p, -normal, segs, k, eps));
      if (std::isfinite(w)) width(p, w);
    }
  }
}

}  // namespace

NarrowestFeature narrowest_feature(const std::vector<Polyline2>& boundaries, double spacing,
                                   double min_length) {
  if (!(spacing > 0.0)) throw std::invalid_argument("narrowest_feature: spacing must be positive");
  const std::vector<SizeField::Segment> all = segments_of(boundaries);
  double extent = 0.0;
  for (const auto& seg : all) extent = std::max({extent, seg.a.norm(), seg.b.norm()});
  NarrowestFeature out{std::numeric_limits<double>::infinity(), Vec2::Zero()};
  size_t first = 0;  // segments_of keeps the polygons' order: each one's segments in a run
  for (const Polyline2& poly : boundaries) {
    const size_t count = segments_of({poly}).size();
    struct Sample {
      double width, length;
      Vec2 at;
    };
    std::vector<Sample> samples;
    double perimeter = 0.0;
    for (size_t k = first; k < first + count; ++k) {
      const double len = (all[k].b - all[k].a).norm();
      perimeter += len;
      const int n = std::max(1, static_cast<int>(std::ceil(len / spacing)));
      const Vec2 e = (all[k].b - all[k].a) / len, normal(-e.y(), e.x());
      for (int i = 0; i < n; ++i) {
        const Vec2 p = all[k].a + ((i + 0.5) / n) * len * e;
        const double w = std::min(ray_distance(p, normal, all, k, 1e-9 * extent),
                                  ray_distance(p, -normal, all, k, 1e-9 * extent));
        if (std::isfinite(w)) samples.push_back({w, len / n, p});
      }
    }
    first += count;
    // The width below which the boundary runs for the length asked: a pinch (a corner near
    // another boundary, a wedge where a boundary meets the rim) is narrow only along a little of
    // it, a strip along all of it.
    std::sort(samples.begin(), samples.end(),
              [](const Sample& a, const Sample& b) { return a.width < b.width; });
    const double wanted = std::min(min_length, 0.5 * perimeter);
    double run = 0.0;
    for (const Sample& smp : samples) {
      run += smp.length;
      if (run < wanted) continue;
      if (smp.width < out.width) out = {smp.width, smp.at};
      break;
    }
  }
  return std::isfinite(out.width) ? out : NarrowestFeature{};
}

std::vector<SizeField::Source> SizeField::measure(const std::vector<Polyline2>& boundaries) {
  const std::vector<Segment> segs = segments_of(boundaries);
  narrowest_.width = std::numeric_limits<double>::infinity();
  std::vector<Source> sources;
  measure_widths(
      segs, 1e-9 * extent_.norm(), 0.5 * options_.max_edge, [&](const Vec2& p, double w) {
        if (w < narrowest_.width) narrowest_ = {w, p};
        sources.push_back({p, std::min(options_.max_edge, w / options_.elements_across)});
      });
  if (!std::isfinite(narrowest_.width)) narrowest_ = {0.0, Vec2::Zero()};
  return densify(segs, sources);
}

// The sizes measured every max_edge / 2 along each segment, laid along it every half of the
// finest size, so that the field grows from the whole boundary and not from sparse points.
std::vector<SizeField::Source> SizeField::densify(const std::vector<Segment>& segs,
                                                  const std::vector<Source>& measured) const {
  double finest = options_.max_edge;
  for (const Source& s : measured) finest = std::min(finest, s.size);
  std::vector<Source> out;
  size_t next = 0;  // measured samples come segment by segment, in order along each
  for (const Segment& seg : segs) {
    const Vec2 e = seg.b - seg.a;
    std::vector<Source> own;
    while (next < measured.size() &&
           std::abs((measured[next].at - seg.a).x() * e.y() -
                    (measured[next].at - seg.a).y() * e.x()) <= 1e-9 * e.squaredNorm() &&
           (measured[next].at - seg.a).dot(e) >= 0.0 && (measured[next].at - seg.b).dot(e) <= 0.0)
      own.push_back(measured[next++]);
    if (own.empty()) continue;  // a segment that sees no other boundary asks for nothing
    const int n = std::max(1, static_cast<int>(std::ceil(e.norm() / (0.5 * finest))));
    for (int k = 0; k <= n; ++k) {
      const Vec2 p = seg.a + (static_cast<double>(k) / n) * e;
      const Source* nearest = &own[0];
      for (const Source& s : own)
        if ((s.at - p).squaredNorm() < (nearest->at - p).squaredNorm()) nearest = &s;
      out.push_back({p, nearest->size});
    }
  }
  return out;
}

// Sources seeded into their cells, then the cone h + grading x distance spread by two chamfer
// sweeps (8 neighbours): linear in the cells, whatever the number of sources.
void SizeField::rasterize(const std::vector<Source>& sources) {
  double finest = options_.max_edge;
  for (const Source& s : sources) finest = std::min(finest, s.size);
  const double area = extent_.x() * extent_.y();
  cell_ = std::max(0.5 * finest, std::sqrt(area / 4e6));  // at most about 4 million cells
  nx_ = static_cast<int>(std::ceil(extent_.x() / cell_)) + 1;
  ny_ = static_cast<int>(std::ceil(extent_.y() / cell_)) + 1;
  h_.assign(static_cast<size_t>(nx_) * ny_, options_.max_edge);
  const double g = options_.grading;
  for (const Source& s : sources) {
    const Vec2 q = (s.at - origin_) / cell_;
    const int i0 = std::clamp(static_cast<int>(std::floor(q.x())), 0, nx_ - 2);
    const int j0 = std::clamp(static_cast<int>(std::floor(q.y())), 0, ny_ - 2);
    for (int j = j0; j <= j0 + 1; ++j)
      for (int i = i0; i <= i0 + 1; ++i) {
        double& h = h_[static_cast<size_t>(j) * nx_ + i];
        h = std::min(h, s.size + g * cell_ * (Vec2(i, j) - q).norm());
      }
  }
  const double straight = g * cell_, diagonal = g * cell_ * std::sqrt(2.0);
  auto relax = [&](int i, int j, int di, int dj) {
    const int a = i + di, b = j + dj;
    if (a < 0 || b < 0 || a >= nx_ || b >= ny_) return;
    double& h = h_[static_cast<size_t>(j) * nx_ + i];
    h = std::min(h, cell_value(a, b) + (di != 0 && dj != 0 ? diagonal : straight));
  };
  for (int pass = 0; pass < 2; ++pass) {
    for (int j = 0; j < ny_; ++j)
      for (int i = 0; i < nx_; ++i)
        relax(i, j, -1, 0), relax(i, j, -1, -1), relax(i, j, 0, -1), relax(i, j, 1, -1);
    for (int j = ny_ - 1; j >= 0; --j)
      for (int i = nx_ - 1; i >= 0; --i)
        relax(i, j, 1, 0), relax(i, j, 1, 1), relax(i, j, 0, 1), relax(i, j, -1, 1);
  }
  smallest_ = *std::min_element(h_.begin(), h_.end());
}

double SizeField::operator()(const Vec2& p) const {
  const Vec2 q = (p - origin_) / cell_;
  const double x = std::clamp(q.x(), 0.0, nx_ - 1.0), y = std::clamp(q.y(), 0.0, ny_ - 1.0);
  const int i = std::min(static_cast<int>(x), nx_ - 2), j = std::min(static_cast<int>(y), ny_ - 2);
  const double u = x - i, v = y - j;
  return (1 - v) * ((1 - u) * cell_value(i, j) + u * cell_value(i + 1, j)) +
         v * ((1 - u) * cell_value(i, j + 1) + u * cell_value(i + 1, j + 1));
}

double SizeField::expected_triangles() const {
  double sum = 0.0;  // over the cells, each at its centre's size and its area inside the domain
  for (int j = 0; j + 1 < ny_; ++j)
    for (int i = 0; i + 1 < nx_; ++i) {
      const double w = std::min(cell_, extent_.x() - i * cell_),
                   h = std::min(cell_, extent_.y() - j * cell_);
      if (w <= 0.0 || h <= 0.0) continue;
      const double size = (*this)(origin_ + Vec2(i * cell_ + 0.5 * w, j * cell_ + 0.5 * h));
      sum += w * h / (size * size);
    }
  return sum * 4.0 / std::sqrt(3.0);
}

}  // namespace membra
