#include "checksum.h"

#include <array>
#include <memory>
#include <new>

#include <xxhash.h>

#include "format.h"

namespace facet::package::detail {

uint64_t fileChecksum(std::span<const uint8_t> file) {
  // Streaming, so the reader never copies a file that may be up to 1 GiB to zero one field.
  std::unique_ptr<XXH3_state_t, decltype(&XXH3_freeState)> state(XXH3_createState(), &XXH3_freeState);
  if (!state) throw std::bad_alloc();
  const std::array<uint8_t, 8> zeros{};
  XXH3_64bits_reset(state.get());
  XXH3_64bits_update(state.get(), file.data(), kChecksumOffset);
  XXH3_64bits_update(state.get(), zeros.data(), zeros.size());
  XXH3_64bits_update(state.get(), file.data() + kChecksumOffset + 8, file.size() - (kChecksumOffset + 8));
  return XXH3_64bits_digest(state.get());
}

uint64_t contentHash(std::span<const uint8_t> code) { return XXH3_64bits(code.data(), code.size()); }

}  // namespace facet::package::detail
