// libFuzzer target for the package readers: package::read and the lazy PackageReader apps use
// (open, then each blob on request), the code apps run on files they did not build, the
// runtime's preshader interpreter on every program a package carries, and the runtime's loader
// (LoadedMaterial) on every variant: SPIR-V validation, its stage, its reflected interface against
// the tables. Built only in the clang configuration of scripts/fuzz.sh (-DFACET_FUZZ=ON), with
// ASan + UBSan; a crash, a sanitizer report, a leak, a hang or a broken invariant below is a
// finding.
//
// Most random bytes die at the checksum, so the custom mutator below reseals most mutants (file
// size field and XXH3 checksum recomputed): those are the "semantic" mutations, which reach the
// table of contents, the sections, the blob table and zstd. Seeds are real packages
// (tests/fuzz/package_corpus/, README there).
//
// Reproduce a finding:  build/fuzz/tests/fuzz/fuzz_package path/to/input
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <span>
#include <string>

#include "checksum.h"
#include "facet/package/package.h"
#include "facet/package/package_reader.h"
#include "facet/runtime/material.h"
#include "facet/runtime/preshader.h"
#include "format.h"

extern "C" size_t LLVMFuzzerMutate(uint8_t* data, size_t size, size_t maxSize);

namespace {

[[noreturn]] void broken(const char* what) {
  std::fprintf(stderr, "fuzz_package: invariant broken: %s\n", what);
  std::abort();
}

void storeLE(uint8_t* p, uint64_t v, int n) {
  for (int i = 0; i < n; ++i) p[i] = uint8_t(v >> (8 * i));
}

}  // namespace

extern "C" size_t LLVMFuzzerCustomMutator(uint8_t* data, size_t size, size_t maxSize, unsigned int seed) {
  size = LLVMFuzzerMutate(data, size, maxSize);
  // One mutant in eight keeps its damage visible to the checksum check; the rest are resealed.
  using namespace facet::package::detail;
  if (seed % 8 != 0 && size >= kHeaderSize) {
    storeLE(data + kFileSizeOffset, size, 8);
    storeLE(data + kChecksumOffset, fileChecksum({data, size}), 8);
  }
  return size;
}

namespace {

// The lazy path: open, the semantic check on the tables, then every shader and texture on
// request. Agrees with package::read: where read succeeded every request succeeds with the same
// bytes; where it failed, open or some request fails.
void checkLazyReader(std::span<const uint8_t> bytes, const facet::package::ReadResult& whole) {
  namespace pkg = facet::package;
  std::string error;
  std::optional<pkg::PackageReader> reader = pkg::PackageReader::open(bytes, &error);
  if (!reader) {
    if (error.empty()) broken("PackageReader::open failed without an error message");
    if (whole.package) broken("PackageReader::open refused a package read() accepted");
    return;
  }
  if (reader->bytesDecompressed() != 0) broken("PackageReader::open decompressed a blob");
  (void)reader->semanticError();
  bool allDecoded = true;
  for (size_t v = 0; v < reader->variants().size(); ++v) {
    const pkg::VariantInfo& variant = reader->variants()[v];
    for (size_t s = 0; s < variant.shaders.size(); ++s) {
      const pkg::ShaderInfo& shader = variant.shaders[s];
      error.clear();
      std::optional<std::span<const uint8_t>> code = reader->blob(shader.blob, &error);
      if (!code) {
        if (error.empty()) broken("a blob request failed without an error message");
        allDecoded = false;
        continue;
      }
      if (code->size() != reader->blobs()[shader.blob].rawSize) broken("a decoded blob is not its declared size");
      if (whole.package) {
        const std::vector<uint8_t>& expected = whole.package->variants[v].shaders[s].code;
        if (!std::equal(code->begin(), code->end(), expected.begin(), expected.end()))
          broken("the lazy reader and read() disagree on a shader's code");
      }
    }
  }
  for (size_t t = 0; t < reader->textures().size(); ++t) {
    error.clear();
    if (!reader->texels(t, &error)) {
      if (error.empty()) broken("a texture request failed without an error message");
      allDecoded = false;
    }
  }
  if (whole.package && !allDecoded) broken("the lazy reader failed a blob read() decoded");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  namespace pkg = facet::package;
  pkg::ReadResult r = pkg::read(std::span<const uint8_t>(data, size));
  checkLazyReader(std::span<const uint8_t>(data, size), r);
  if (!r.package) {
    if (r.error.empty()) broken("read failed without an error message");
    return 0;
  }
  if (!r.error.empty()) broken("read succeeded with an error message");
  if (r.stats.size() != r.package->variants.size()) broken("stats do not match the variants");
  // The runtime's semantic check (what an app runs on an untrusted package) on whatever decoded.
  (void)pkg::semanticError(*r.package);
  // Every preshader program of a package whose meaning is sound runs (the runtime's interpreter,
  // on a block whose parameters are the input's own bytes: any float bits, NaN and infinities
  // included). The loader never runs one of a package whose meaning is not.
  const bool sound = pkg::preshaderSemanticError(r.package->material, r.package->preshader).empty();
  for (const pkg::PreshaderProgram& program : r.package->preshader.programs) {
    if (!sound) break;
    std::vector<uint8_t> block(r.package->preshader.blockSize, 0);
    std::memcpy(block.data(), data, std::min<size_t>(size, r.package->material.paramBlockSize));
    std::string error;
    if (!facet::runtime::runPreshader(program.ops, r.package->material.paramBlockSize, block, &error))
      broken("the interpreter refused a preshader program semanticError accepted");
  }
  // The loader an app runs on the same bytes, every variant's program: an answer, never a crash.
  {
    std::string error;
    auto material =
        facet::runtime::LoadedMaterial::loadFromMemory(std::span<const uint8_t>(data, size), "fuzz", &error);
    if (!material && error.empty()) broken("LoadedMaterial refused a package without an error message");
    if (material && !material->checkEveryVariant(&error) && error.empty())
      broken("LoadedMaterial refused a variant without an error message");
  }
  // What was read writes and reads back to a package that writes the same bytes (compared as
  // bytes: a NaN default value is legal and never equals itself).
  const std::vector<uint8_t> written = pkg::write(*r.package);
  pkg::ReadResult again = pkg::read(written);
  if (!again.package) broken("a package that was read cannot be written and read back");
  if (pkg::write(*again.package) != written) broken("write + read does not round-trip a package that was read");
  return 0;
}
