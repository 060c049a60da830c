// The mobile cost model's operation counts (compiler/mobile_cost.h, countOpClasses) of SPIR-V
// modules, as JSON, for the calibration against Mesa's compilers (docs/mesa-statistics.md):
// the fit's features are exactly what matc counts, so nothing here re-implements the walk.
//
//   spirv_op_counts red.matpkg   {"red.matpkg": {"high.dir1": {"fragment": {...}, "vertex": {...}}, ...}}
//   spirv_op_counts a.spv b.spv  {"a.spv": {...}, "b.spv": {...}}
//
// Every count is per scalar component (a vec3 multiply is 3); "fma_relaxed" is the mediump part
// of "fma"; "varyings" / "varyings_relaxed" are the fragment inputs' highp / mediump components.
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "facet/compiler/cost_figures.h"
#include "facet/package/package.h"

namespace {

using nlohmann::ordered_json;
using namespace facet;

ordered_json countsJson(const compiler::OpClassCounts& c) {
  ordered_json j;
  for (size_t k = 0; k < compiler::kOpClassCount; ++k) j[compiler::toString(compiler::OpClass(k))] = c.ops[k];
  compiler::StageFigures stage;
  stage.mobile.counts = c;
  using F = compiler::Figure;
  for (F f : {F::FmaRelaxed, F::FragmentVaryings, F::FragmentVaryingsRelaxed}) {
    const compiler::CostFigure& figure = compiler::costFigure(f);
    j[figure.name] = compiler::figureJson<ordered_json>(figure, stage);
  }
  return j;
}

bool count(const std::vector<uint32_t>& words, const std::string& what, ordered_json* out) {
  compiler::OpClassCounts counts;
  std::string error;
  if (!compiler::countOpClasses(words, &counts, &error)) {
    std::fprintf(stderr, "%s: error: %s\n", what.c_str(), error.c_str());
    return false;
  }
  *out = countsJson(counts);
  return true;
}

std::vector<uint32_t> toWords(const std::vector<uint8_t>& bytes) {
  std::vector<uint32_t> words(bytes.size() / 4);
  std::memcpy(words.data(), bytes.data(), words.size() * 4);
  return words;
}

bool countPackage(const std::string& path, ordered_json* out) {
  package::ReadResult r = package::readFile(path);
  if (!r.package) {
    std::fprintf(stderr, "%s: error: %s\n", path.c_str(), r.error.c_str());
    return false;
  }
  for (const package::Variant& v : r.package->variants)
    for (const package::Shader& s : v.shaders) {
      if (s.target != package::Target::Spirv) continue;
      if (!count(toWords(s.code), path + ": " + v.key, &(*out)[v.key][package::toString(s.stage)])) return false;
    }
  return true;
}

bool countSpirvFile(const std::string& path, ordered_json* out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "%s: error: cannot open\n", path.c_str());
    return false;
  }
  std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() % 4 != 0) {
    std::fprintf(stderr, "%s: error: not SPIR-V words (%zu bytes)\n", path.c_str(), bytes.size());
    return false;
  }
  return count(toWords(bytes), path, out);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s PACKAGE.matpkg | MODULE.spv...\n", argv[0]);
    return 2;
  }
  ordered_json out = ordered_json::object();
  for (int i = 1; i < argc; ++i) {
    std::string path = argv[i];
    bool isPackage = path.size() > 7 && path.compare(path.size() - 7, 7, ".matpkg") == 0;
    bool ok = isPackage ? countPackage(path, &out[path]) : countSpirvFile(path, &out[path]);
    if (!ok) return 1;
  }
  std::printf("%s\n", out.dump(1).c_str());
  return 0;
}
