// matc eval and matc texture run facet-eval and facet-texture, git-style: the evaluation renders
// on lavapipe, so its program links the runtime, Vulkan and GL, and texture encoding links Arm's
// astcenc and the runtime's image decoding, none of which a build-time compiler must need (ctest
// matc_link_weight).
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "commands.h"
#include "facet/cli/inputs.h"

namespace facet::matc {

int runHelperProgram(const std::string& matc, const std::string& command, const std::string& program,
                     const std::string& target, const std::vector<std::string>& args) {
  namespace fs = std::filesystem;
  // Its argv[0] names it "<matc> <command>", so that its usage and messages read as matc's.
  std::vector<std::string> words{matc + " " + command};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  // First the program built or installed with this matc (the folder of the executable itself,
  // whatever path ran it), then PATH's.
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  const std::string beside = ec ? std::string() : (self.parent_path() / program).string();
  if (!beside.empty() && ::access(beside.c_str(), X_OK) == 0) {
    ::execv(beside.c_str(), argv.data());
    cli::printError("cannot run '" + beside + "': " + std::strerror(errno));
    return 1;
  }
  ::execvp(program.c_str(), argv.data());
  if (errno != ENOENT) {
    cli::printError("cannot run " + program + ": " + std::strerror(errno));
    return 1;
  }
  cli::printError("matc " + command + " runs " + program + ", which is neither beside matc" +
                  (beside.empty() ? std::string() : " (" + beside + ")") + " nor on PATH: build the " + target +
                  " target, or install Facet with it");
  return 1;
}

}  // namespace facet::matc
