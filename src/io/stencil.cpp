#include "membra/io/stencil.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "membra/core/units.hpp"

namespace membra {
namespace {

std::string mm(double metres) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4f", metres / units::mm);
  return buf;
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

std::string degrees(double radians) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6f", radians * 180.0 / std::numbers::pi);
  return buf;
}

bool all_segments(const CurveLoop& loop) {
  for (const PlaneCurve& c : loop)
    if (c.arc) return false;
  return true;
}

// SVG's coordinates: mm from the frame's top-left corner, y down.
struct SvgFrame {
  Box2 frame;
  std::string x(const Vec2& p) const { return mm(p.x() - frame.min.x()); }
  std::string y(const Vec2& p) const { return mm(frame.max.y() - p.y()); }

  // A loop as path data: segments as L, arcs as A in pieces of at most half a turn (y down
  // turns counter-clockwise arcs into sweep-flag 1, and the ellipse's angle into its negative).
  std::string path_data(const CurveLoop& loop) const {
    std::string d = "M" + x(loop.front().start()) + " " + y(loop.front().start());
    for (const PlaneCurve& c : loop) {
      if (!c.arc) {
        d += " L" + x(c.end()) + " " + y(c.end());
        continue;
      }
      const int halves = std::abs(c.t1 - c.t0) > std::numbers::pi ? 2 : 1;
      for (int h = 0; h < halves; ++h) {
        const PlaneCurve part =
            c.piece(static_cast<double>(h) / halves, static_cast<double>(h + 1) / halves);
        d.append(" A").append(mm(part.rx)).append(" ").append(mm(part.ry)).append(" ");
        d.append(degrees(-part.angle)).append(part.t1 > part.t0 ? " 0 1 " : " 0 0 ");
        d.append(x(part.end())).append(" ").append(y(part.end()));
      }
    }
    return d + " Z";
  }

  std::string element(const CurveLoop& loop) const {
    if (loop.size() == 1 && loop[0].full_ellipse()) {
      const PlaneCurve& e = loop[0];
      std::string s = "<ellipse cx=\"" + x(e.centre) + "\" cy=\"" + y(e.centre) + "\" rx=\"" +
                      mm(e.rx) + "\" ry=\"" + mm(e.ry) + "\"";
      if (std::abs(e.angle) > 1e-12)
        s += " transform=\"rotate(" + degrees(-e.angle) + " " + x(e.centre) + " " + y(e.centre) +
             ")\"";
      return s + "/>";
    }
    if (all_segments(loop)) {
      std::string s = "<polygon points=\"";
      for (size_t i = 0; i < loop.size(); ++i) {
        if (i) s += ' ';
        s.append(x(loop[i].start())).append(",").append(y(loop[i].start()));
      }
      return s + "\"/>";
    }
    return "<path d=\"" + path_data(loop) + "\"/>";
  }

  void group(std::ostream& out, const std::vector<CurveLoop>& loops, const char* id,
             const char* fill) const {
    out << "  <g id=\"" << id << "\" fill=\"" << fill << "\" fill-rule=\"nonzero\">\n";
    bool holes = false;
    for (const CurveLoop& l : loops) holes = holes || loop_area(l) < 0.0;
    if (holes) {
      out << "    <path d=\"";
      for (size_t i = 0; i < loops.size(); ++i) out << (i ? " " : "") << path_data(loops[i]);
      out << "\"/>\n";
    } else {
      for (const CurveLoop& l : loops) out << "    " << element(l) << "\n";
    }
    out << "  </g>\n";
  }
};

}  // namespace

void write_svg(std::ostream& out, const std::vector<CurveLoop>& outlines, const Box2& frame,
               const std::vector<CurveLoop>& underside) {
  const double w = frame.max.x() - frame.min.x(), h = frame.max.y() - frame.min.y();
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<!-- membra resin stencil, true scale, units mm; black = resin -->\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << mm(w) << "mm\" height=\"" << mm(h)
      << "mm\" viewBox=\"0 0 " << mm(w) << " " << mm(h) << "\">\n"
      << "  <rect id=\"frame\" x=\"0\" y=\"0\" width=\"" << mm(w) << "\" height=\"" << mm(h)
      << "\" fill=\"none\" stroke=\"red\" stroke-width=\"0.1\"/>\n";
  const SvgFrame f{frame};
  f.group(out, outlines, "resin", "black");
  if (!underside.empty()) {
    out << "  <!-- blue: resin on the bottom face (seen through from the top) -->\n";
    f.group(out, underside, "resin_bottom", "#2060c0");
  }
  out << "</svg>\n";
}

namespace {

struct DxfWriter {
  std::ostream& out;
  Box2 frame;

  void point(int code, const Vec2& p) {
    out << code << "\n"
        << mm(p.x() - frame.min.x()) << "\n"
        << code + 10 << "\n"
        << mm(p.y() - frame.min.y()) << "\n";
  }
  void polyline(const std::vector<Vec2>& pts, bool closed, const char* layer) {
    out << "0\nLWPOLYLINE\n100\nAcDbEntity\n8\n"
        << layer << "\n100\nAcDbPolyline\n90\n"
        << pts.size() << "\n70\n"
        << (closed ? 1 : 0) << "\n";
    for (const Vec2& p : pts) point(10, p);
  }
  // DXF's ellipse: the major axis as a vector, the minor/major ratio, and parameters running
  // counter-clockwise from the major axis.
  void ellipse(const PlaneCurve& c, const char* layer) {
    const bool x_major = c.rx >= c.ry;
    const double axis = x_major ? c.angle : c.angle + 0.5 * std::numbers::pi;
    const double major = x_major ? c.rx : c.ry, minor = x_major ? c.ry : c.rx;
    const double shift = x_major ? 0.0 : -0.5 * std::numbers::pi;
    // Counter-clockwise from a start in [0, 2 pi), as strict CAM readers want.
    const double turn = 2.0 * std::numbers::pi;
    double t0 = std::fmod(std::min(c.t0, c.t1) + shift, turn);
    if (t0 < 0.0) t0 += turn;
    double t1 = t0 + std::abs(c.t1 - c.t0);
    if (c.full_ellipse()) t0 = 0.0, t1 = turn;
    out << "0\nELLIPSE\n100\nAcDbEntity\n8\n" << layer << "\n100\nAcDbEllipse\n";
    point(10, c.centre);
    out << "30\n0.0\n11\n"
        << mm(major * std::cos(axis)) << "\n21\n"
        << mm(major * std::sin(axis)) << "\n31\n0.0\n40\n"
        << num(minor / major) << "\n41\n"
        << num(t0) << "\n42\n"
        << num(t1) << "\n";
  }
  void loop(const CurveLoop& l, const char* layer) {
    if (all_segments(l)) {
      std::vector<Vec2> pts;
      for (const PlaneCurve& c : l) pts.push_back(c.start());
      polyline(pts, true, layer);
      return;
    }
    std::vector<Vec2> run;  // the segments since the last arc, as one open polyline
    const auto flush = [&] {
      if (run.size() >= 2) polyline(run, false, layer);
      run.clear();
    };
    for (const PlaneCurve& c : l) {
      if (c.arc) {
        flush();
        ellipse(c, layer);
      } else {
        if (run.empty()) run.push_back(c.start());
        run.push_back(c.end());
      }
    }
    flush();
  }
};

}  // namespace

void write_dxf(std::ostream& out, const std::vector<CurveLoop>& outlines, const Box2& frame,
               const std::vector<CurveLoop>& underside) {
  out << "0\nSECTION\n2\nHEADER\n9\n$ACADVER\n1\nAC1015\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n"
      << "0\nSECTION\n2\nENTITIES\n";
  DxfWriter w{out, frame};
  w.polyline({frame.min, {frame.max.x(), frame.min.y()}, frame.max, {frame.min.x(), frame.max.y()}},
             true, "FRAME");
  for (const CurveLoop& l : outlines) w.loop(l, "RESIN");
  for (const CurveLoop& l : underside) w.loop(l, "RESIN_BOTTOM");
  out << "0\nENDSEC\n0\nEOF\n";
}

}  // namespace membra
