#include "sweep_command.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <vector>

namespace membra::cli {

int cmd_sweep(const SweepArgs& args) {
#ifndef MEMBRA_PYTHON_DIR
  (void)args;
  std::cerr << "membra: error: this membra was built without its Python module "
               "(-DMEMBRA_PYTHON=OFF); sweeps need it\n";
  return 1;
#else
  // The package beside this build first, then whatever the user has.
  std::string path = MEMBRA_PYTHON_DIR;
  if (const char* old = std::getenv("PYTHONPATH"); old && *old) path += std::string(":") + old;
  setenv("PYTHONPATH", path.c_str(), 1);
  std::vector<std::string> words = {
      MEMBRA_PYTHON_EXECUTABLE,    "-m", "membra", "sweep", args.file, "--workers",
      std::to_string(args.workers)};
  if (!args.out_dir.empty()) words.insert(words.end(), {"--out", args.out_dir});
  if (!args.scheduler.empty()) words.insert(words.end(), {"--scheduler", args.scheduler});
  if (args.no_resume) words.push_back("--no-resume");
  if (args.quiet) words.push_back("--quiet");
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  std::cout.flush();
  execv(argv[0], argv.data());
  std::cerr << "membra: error: cannot start " << argv[0] << ": " << std::strerror(errno) << "\n";
  return 1;
#endif
}

}  // namespace membra::cli
