// libFuzzer target for the material language front end: any bytes, read as a material file, go
// through the lexer, parser and checker (ir::compileSource), the diagnostics are formatted as
// matc prints them, and a checked material is emitted to GLSL (ir::emitSurface). Built only in
// the clang configuration of scripts/fuzz.sh (-DFACET_FUZZ=ON), with ASan + UBSan; a crash, a
// sanitizer report, a leak, a hang (-timeout) or a broken invariant below is a finding.
//
// Reproduce a finding:  build/fuzz/tests/fuzz/fuzz_material path/to/input
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "facet/ir/check.h"
#include "facet/ir/emit_glsl.h"

namespace {

[[noreturn]] void broken(const char* what) {
  std::fprintf(stderr, "fuzz_material: invariant broken: %s\n", what);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  facet::ir::SourceFile file{"fuzz.mat", std::string(reinterpret_cast<const char*>(data), size)};
  facet::ir::Diagnostics diags(file);
  std::optional<facet::ir::Material> material = facet::ir::compileSource(file, diags);

  // A rejected file always says why; an accepted one has no errors.
  if (!material && !diags.hasErrors()) broken("compileSource failed without reporting an error");
  if (material && diags.hasErrors()) broken("compileSource returned a material despite errors");
  for (const facet::ir::Diagnostic& d : diags.all()) {
    if (d.loc.line == 0 || d.loc.column == 0) broken("diagnostic without a source position");
    if (d.loc.offset > file.text.size()) broken("diagnostic position past the end of the file");
    if (d.message.empty()) broken("diagnostic without a message");
  }
  std::string text = diags.format();  // what matc prints: quotes source lines, draws carets
  if (diags.all().empty() != text.empty()) broken("formatted diagnostics do not match the list");

  if (material) {
    facet::ir::SurfaceGlsl glsl = facet::ir::emitSurface(*material);
    (void)glsl;
  }
  return 0;
}
