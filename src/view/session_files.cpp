#include "membra/view/session_files.hpp"

#include <fstream>
#include <sstream>

#include "membra/core/input_error.hpp"
#include "membra/io/obj.hpp"
#include "membra/io/ply.hpp"
#include "membra/io/stencil.hpp"
#include "membra/model/pattern_outline.hpp"
#include "membra/output/output_set.hpp"

namespace membra {
namespace {

// Writes `text` to a temporary file beside `file`, then renames it: never a partial file.
void write_whole(const std::filesystem::path& file, const std::string& text) {
  const std::filesystem::path tmp = file.string() + ".part";
  {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    out.flush();
    if (!out) {
      std::error_code ec;
      std::filesystem::remove(tmp, ec);
      throw OutputError(file.string() + ": cannot write (is the folder there and writable?)");
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, file, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw OutputError(file.string() + ": cannot write: " + ec.message());
  }
}

}  // namespace

void save_session_scene(const ViewerSession& session, const std::filesystem::path& file) {
  write_whole(file, session.to_scene_json().dump(2) + "\n");
}

void export_session(const ViewerSession& session, const std::filesystem::path& file) {
  const std::string ext = file.extension().string();
  const Membrane& m = session.membrane();
  std::ostringstream out;
  if (ext == ".obj") {
    write_obj(out, m.state.x, m.sheet.triangles);
  } else if (ext == ".ply") {
    write_ply(out, m.state.x, m.sheet.triangles, {}, {});
  } else if (ext == ".svg" || ext == ".dxf") {
    // The stencil: what the saved scene impregnates, and what is painted but not yet applied.
    const Scene saved = parse_scene(session.to_scene_json(), session.scene().file.parent_path());
    std::vector<PatternPtr> parts;
    if (PatternPtr p = scene_pattern(saved)) parts.push_back(p);
    if (PatternPtr p = session.resin_pattern()) parts.push_back(p);
    if (parts.empty()) throw InputError(file.string(), "there is no resin to export yet");
    const PatternPtr all = make_union(parts);
    const Box2 frame = scene_frame(saved);
    const auto outlines = stencil_outline(*all, frame);
    if (ext == ".svg")
      write_svg(out, outlines, frame);
    else
      write_dxf(out, outlines, frame);
  } else {
    throw InputError(file.string(), "export writes .obj, .ply, .svg or .dxf, not '" + ext + "'");
  }
  write_whole(file, out.str());
}

}  // namespace membra
