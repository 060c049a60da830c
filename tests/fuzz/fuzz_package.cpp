// libFuzzer target for the package reader (package::read), the code apps run on files they did
// not build. Built only in the clang configuration of scripts/fuzz.sh (-DFACET_FUZZ=ON), with
// ASan + UBSan; a crash, a sanitizer report, a leak, a hang or a broken invariant below is a
// finding.
//
// Most random bytes die at the checksum, so the custom mutator below reseals most mutants (file
// size field and XXH3 checksum recomputed): those are the "semantic" mutations, which reach the
// table of contents, the sections, the blob table and zstd. Seeds are real packages
// (tests/fuzz/package_corpus/, README there).
//
// Reproduce a finding:  build/fuzz/tests/fuzz/fuzz_package path/to/input
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <span>

#include "checksum.h"
#include "facet/package.h"
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

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  namespace pkg = facet::package;
  pkg::ReadResult r = pkg::read(std::span<const uint8_t>(data, size));
  if (!r.package) {
    if (r.error.empty()) broken("read failed without an error message");
    return 0;
  }
  if (!r.error.empty()) broken("read succeeded with an error message");
  if (r.stats.size() != r.package->variants.size()) broken("stats do not match the variants");
  // The runtime's semantic check (what an app runs on an untrusted package) on whatever decoded.
  (void)pkg::semanticError(*r.package);
  // What was read writes and reads back to a package that writes the same bytes (compared as
  // bytes: a NaN default value is legal and never equals itself).
  const std::vector<uint8_t> written = pkg::write(*r.package);
  pkg::ReadResult again = pkg::read(written);
  if (!again.package) broken("a package that was read cannot be written and read back");
  if (pkg::write(*again.package) != written) broken("write + read does not round-trip a package that was read");
  return 0;
}
