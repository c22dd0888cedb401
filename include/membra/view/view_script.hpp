#pragma once
// The viewer's scripted mode (`membra view SCENE --script FILE`): one command a line, checked
// completely before the window opens, then carried out frame by frame. Commands that need the
// window (screenshot, fps, quit) are the app's; the rest act on the session and settings here.
#include <istream>
#include <string>
#include <vector>

#include "membra/view/view_settings.hpp"
#include "membra/view/viewer_session.hpp"

namespace membra {

struct ScriptCommand {
  std::string where;               // "file:line", for messages
  std::string name;                // e.g. "paint"
  std::vector<std::string> words;  // the arguments as written
  double number(size_t i) const;   // argument i as a number (checked by the parser)
};

// Reads a script; '#' starts a comment, blank lines are skipped. Throws InputError naming
// file:line for an unknown command, a wrong number of arguments or a bad value.
std::vector<ScriptCommand> parse_view_script(std::istream& in, const std::string& name);
// The commands and their arguments, for --help and the docs.
std::string view_script_help();

// Carries out a command that needs no window. Returns false if it is a window command
// (screenshot, fps, save, export, quit, tool, drag, click, holesize) left to the caller. Throws
// InputError naming the line when the session refuses (e.g. impregnate before stretch).
bool run_session_command(const ScriptCommand& command, ViewerSession& session,
                         ViewSettings& settings);

}  // namespace membra
