#pragma once
// Files the viewer writes from a session: the session as a scene, the form as OBJ/PLY, the
// stencil as SVG/DXF. Each is written completely or not at all (a temporary file renamed).
#include <filesystem>

#include "membra/view/viewer_session.hpp"

namespace membra {

// Writes the session as a scene file (JSON). Throws OutputError naming the file.
void save_session_scene(const ViewerSession& session, const std::filesystem::path& file);
// Writes by extension: .obj or .ply (the current form, mm), .svg or .dxf (the resin applied so
// far and still painted, true scale). Throws InputError for another extension or no resin,
// OutputError when the file cannot be written.
void export_session(const ViewerSession& session, const std::filesystem::path& file);

}  // namespace membra
