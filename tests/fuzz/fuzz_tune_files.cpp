// libFuzzer target for `matc tune`'s input files: the budgets file (tune::parseBudgets) and the
// tuning file (tune::parseChoices, read against red_plastic and brushed_gold, a dielectric and an
// anisotropic metal). Every input goes to both readers. Any bytes end in figures within the
// documented ranges (a budgets file) or a tuning file that writes back to itself (write, read,
// write: the same text), or in an error naming the file; never a crash, a hang or an exception.
// Seeded with examples/lint/tune_budgets.json and examples/materials/*.tuning.json. Built by
// scripts/fuzz.sh with ASan + UBSan.
//
// Reproduce a finding:  build/fuzz/tests/fuzz/fuzz_tune_files path/to/input
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "facet/ir/check.h"
#include "facet/tune/budgets.h"
#include "facet/tune/choices.h"

namespace {

[[noreturn]] void broken(const char* what, const std::string& detail) {
  std::fprintf(stderr, "fuzz_tune_files: %s: %.300s\n", what, detail.c_str());
  std::abort();
}

facet::ir::Material example(const char* name) {
  const std::string path = std::string(FACET_EXAMPLES_DIR) + "/materials/" + name + ".mat";
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) broken("cannot read the example material", path);
  std::string text;
  char buffer[4096];
  for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, f)) > 0;) text.append(buffer, n);
  std::fclose(f);
  facet::ir::SourceFile file{std::string(name) + ".mat", text};
  facet::ir::Diagnostics diags(file);
  auto m = facet::ir::compileSource(file, diags);
  if (!m) broken("the example material does not compile", diags.format());
  return *m;
}

void budgets(const std::string& text) {
  std::string error;
  const auto b = facet::tune::parseBudgets("fuzz.json", text, &error);
  if (!b) {
    if (error.rfind("fuzz.json:", 0) != 0) broken("an error that does not name the file", error);
    return;
  }
  if (!std::isfinite(b->verticesPerPixel) || b->verticesPerPixel < 0)
    broken("vertices_per_pixel out of range", std::to_string(b->verticesPerPixel));
  auto check = [](const facet::tune::TierBudget& t) {
    if (!(t.minPsnrDb >= 0 && t.minPsnrDb <= 200)) broken("min_psnr_db out of range", std::to_string(t.minPsnrDb));
    if (t.maxCost && !(std::isfinite(*t.maxCost) && *t.maxCost >= 0))
      broken("max_cost out of range", std::to_string(*t.maxCost));
  };
  for (const auto& [tier, t] : b->tiers) check(t);
  for (const auto& [material, tiers] : b->materials)
    for (const auto& [tier, t] : tiers) check(t);
}

void choices(const std::string& text, const facet::ir::Material& material) {
  std::string error;
  const auto c = facet::tune::parseChoices("fuzz.tuning.json", text, material, &error);
  if (!c) {
    if (error.rfind("fuzz.tuning.json:", 0) != 0) broken("an error that does not name the file", error);
    return;
  }
  const std::string written = facet::tune::writeChoices(*c);
  const auto again = facet::tune::parseChoices("written.tuning.json", written, material, &error);
  if (!again) broken("a file read does not read back once written", error + "\n" + written);
  if (facet::tune::writeChoices(*again) != written) broken("a file read writes back differently", written);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const facet::ir::Material dielectric = example("red_plastic");
  static const facet::ir::Material metal = example("brushed_gold");
  const std::string text(reinterpret_cast<const char*>(data), size);
  budgets(text);
  choices(text, dielectric);
  choices(text, metal);
  return 0;
}
