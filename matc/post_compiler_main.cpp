// facet_post_compiler: `matc post` on its own, for the runtime's build. The runtime embeds the
// post pass this writes (runtime/CMakeLists.txt); it cannot run matc itself, because matc links
// facet_eval, which links the runtime: a dependency cycle. Same code as `matc post`.
#include <CLI/CLI.hpp>

#include "commands.h"

int main(int argc, char** argv) {
  CLI::App app{"facet_post_compiler: compiles the runtime's post pass into C++ source (as `matc post`)"};
  facet::matc::PostArgs post;
  app.add_option("--cpp", post.cpp, "C++ file to write (defines facet::runtime::postShaders())")->required();
  app.add_option("--emit-source", post.emitSource, "also write every generated shader source to this folder");
  app.add_flag("!--no-tonemap", post.acesTonemap, "leave out the ACES tone curve (HDR clamped to [0, 1])");
  CLI11_PARSE(app, argc, argv);
  return facet::matc::postCommand(post);
}
