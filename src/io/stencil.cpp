#include "membra/io/stencil.hpp"

#include <cstdio>

#include "membra/core/units.hpp"

namespace membra {
namespace {

std::string mm(double metres) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4f", metres / units::mm);
  return buf;
}

}  // namespace

void write_svg(std::ostream& out, const std::vector<Polygon2>& outlines, const Box2& frame,
               const std::vector<Polygon2>& underside) {
  const double w = frame.max.x() - frame.min.x(), h = frame.max.y() - frame.min.y();
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<!-- membra resin stencil, true scale, units mm; black = resin -->\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << mm(w) << "mm\" height=\"" << mm(h)
      << "mm\" viewBox=\"0 0 " << mm(w) << " " << mm(h) << "\">\n"
      << "  <rect id=\"frame\" x=\"0\" y=\"0\" width=\"" << mm(w) << "\" height=\"" << mm(h)
      << "\" fill=\"none\" stroke=\"red\" stroke-width=\"0.1\"/>\n"
      << "  <path id=\"resin\" fill=\"black\" fill-rule=\"nonzero\" d=\"";
  const auto path = [&](const std::vector<Polygon2>& loops) {
    for (const Polygon2& loop : loops) {
      for (size_t i = 0; i < loop.size(); ++i)
        out << (i == 0 ? "M" : " L") << mm(loop[i].x() - frame.min.x()) << " "
            << mm(frame.max.y() - loop[i].y());
      out << " Z ";
    }
  };
  path(outlines);
  out << "\"/>\n";
  if (!underside.empty()) {
    out << "  <!-- blue: resin on the bottom face (seen through from the top) -->\n"
        << "  <path id=\"resin_bottom\" fill=\"#2060c0\" fill-rule=\"nonzero\" d=\"";
    path(underside);
    out << "\"/>\n";
  }
  out << "</svg>\n";
}

void write_dxf(std::ostream& out, const std::vector<Polygon2>& outlines, const Box2& frame,
               const std::vector<Polygon2>& underside) {
  out << "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n";
  auto polyline = [&](const Polygon2& loop, const char* layer) {
    out << "0\nPOLYLINE\n8\n" << layer << "\n66\n1\n70\n1\n";
    for (const Vec2& p : loop)
      out << "0\nVERTEX\n8\n"
          << layer << "\n10\n"
          << mm(p.x() - frame.min.x()) << "\n20\n"
          << mm(p.y() - frame.min.y()) << "\n";
    out << "0\nSEQEND\n";
  };
  polyline({frame.min, {frame.max.x(), frame.min.y()}, frame.max, {frame.min.x(), frame.max.y()}},
           "FRAME");
  for (const Polygon2& loop : outlines) polyline(loop, "RESIN");
  for (const Polygon2& loop : underside) polyline(loop, "RESIN_BOTTOM");
  out << "0\nENDSEC\n0\nEOF\n";
}

}  // namespace membra
