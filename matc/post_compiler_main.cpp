// facet_post_compiler: `matc post` on its own, for the runtime's build. The runtime embeds the
// post pass this writes (runtime/CMakeLists.txt); it cannot run matc itself, because matc links
// facet_eval, which links the runtime: a dependency cycle. Same code as `matc post`.
#include <CLI/CLI.hpp>

#include "commands.h"

int main(int argc, char** argv) {
  CLI::App app{"facet_post_compiler: compiles the runtime's post pass into C++ source (as `matc post`)"};
  facet::matc::PostArgs post;
  facet::matc::addPostOptions(&app, &post);
  CLI11_PARSE(app, argc, argv);
  return facet::matc::postCommand(post);
}
