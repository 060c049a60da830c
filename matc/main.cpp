// matc: the Facet material compiler's command line. Argument parsing and wiring only; the work
// happens in the ir, compiler and package libraries.
#include <CLI/CLI.hpp>

#include "commands.h"

int main(int argc, char** argv) {
  CLI::App app{"matc: compiles Facet materials (.mat) into shader packages (.matpkg)"};
  app.require_subcommand(1);

  facet::matc::CompileArgs compile;
  CLI::App* compileCmd = app.add_subcommand("compile", "compile a material into a .matpkg package");
  compileCmd->add_option("input", compile.input, "material source (.mat)")->required();
  compileCmd->add_option("-o,--output", compile.output, "package to write (default: <input>.matpkg)");
  compileCmd->add_option("--emit-source", compile.emitSource,
                         "also write every generated shader source to this folder (readable GLSL, SPIR-V "
                         "disassembly: produced only with this option)");
  compileCmd->add_option("--depfile", compile.depfile,
                         "also write a Makefile-syntax depfile (package: material, scene, matc, templates and "
                         "chunks used) for Ninja/Make");
  CLI::Option* cacheOption = compileCmd->add_option(
      "--cache", compile.cacheDir,
      "cache of compiled variants (default: $XDG_CACHE_HOME/facet/matc or ~/.cache/facet/matc); the package is the same "
      "bytes with or without it");
  compileCmd->add_flag("--no-cache", compile.noCache, "neither read nor write the cache")->excludes(cacheOption);
  compileCmd->add_option("-j,--jobs", compile.jobs, "variants compiled at once (default: one per core); the "
                         "package is byte-identical for any value")
      ->check(CLI::Range(1u, 256u));
  compileCmd->add_option("--tiers", compile.tiers, "tiers to build (reference, high, ...); default: all supported")
      ->delimiter(',');
  compileCmd->add_option("--scene", compile.scene, "scene JSON: build only the variants this scene can request");
  compileCmd->add_option("--point-lights", compile.pointLights,
                         "point/spot light counts to build, from 0, 1, 2, 4 (default: 0; a --scene decides its own)")
      ->delimiter(',')
      ->check(CLI::IsMember({0, 1, 2, 4}));
  compileCmd->add_flag("--fp16-emulation", compile.fp16Emulation,
                       "testing only: round every mediump result to binary16 in the SPIR-V of mediump tiers "
                       "(docs/fp16-emulation.md); never ship such a package");

  facet::matc::InfoArgs info;
  CLI::App* infoCmd = app.add_subcommand("info", "describe a package, or print one of its shaders");
  infoCmd->add_option("input", info.input, "package (.matpkg)")->required();
  infoCmd->add_option("--variant", info.variant, "variant key, e.g. high.dir1 (with --stage and --target)");
  infoCmd->add_option("--scene", info.scene, "scene JSON: the variant it asks this material for, and whether it is built");
  infoCmd->add_flag("--json", info.json, "print the summary as JSON (sizes, variants, parameters)");
  infoCmd->add_option("--stage", info.stage, "vertex | fragment")->check(CLI::IsMember({"vertex", "fragment"}));
  infoCmd->add_option("--target", info.target, "glsl_es_300 | spirv | msl")
      ->check(CLI::IsMember({"glsl_es_300", "spirv", "msl"}));

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  }
  if (compileCmd->parsed()) return facet::matc::compileCommand(compile);
  if (infoCmd->parsed()) return facet::matc::infoCommand(info);
  return 2;
}
