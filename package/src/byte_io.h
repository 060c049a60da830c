// Little-endian encoding with explicit byte order, so files are the same on every host.
#pragma once

#include <bit>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace facet::package::detail {

class ByteWriter {
 public:
  explicit ByteWriter(std::vector<uint8_t>& out) : out_(out) {}

  void u8(uint8_t v) { out_.push_back(v); }
  void u16(uint16_t v) { le(v, 2); }
  void u32(uint32_t v) { le(v, 4); }
  void u64(uint64_t v) { le(v, 8); }
  void f64(double v) { u64(std::bit_cast<uint64_t>(v)); }
  void bytes(std::span<const uint8_t> b) { out_.insert(out_.end(), b.begin(), b.end()); }
  void string(std::string_view s) {
    u32(uint32_t(s.size()));
    out_.insert(out_.end(), s.begin(), s.end());
  }
  void padTo(uint64_t alignment) {
    while (out_.size() % alignment != 0) out_.push_back(0);
  }
  uint64_t size() const { return out_.size(); }

 private:
  void le(uint64_t v, int n) {
    for (int i = 0; i < n; ++i) out_.push_back(uint8_t(v >> (8 * i)));
  }
  std::vector<uint8_t>& out_;
};

inline uint64_t loadLE(const uint8_t* p, int n) {
  uint64_t v = 0;
  for (int i = 0; i < n; ++i) v |= uint64_t(p[i]) << (8 * i);
  return v;
}

inline void storeLE(uint8_t* p, uint64_t v, int n) {
  for (int i = 0; i < n; ++i) p[i] = uint8_t(v >> (8 * i));
}

// Reads one section [begin, end) of a file. Failure is sticky: after the first error every read
// returns zero and consumes nothing, so decoding loops end quickly and the first (most precise)
// message is the one reported. Positions in messages are absolute file offsets.
class ByteReader {
 public:
  ByteReader(std::span<const uint8_t> file, uint64_t begin, uint64_t end, std::string_view section)
      : file_(file), pos_(begin), end_(end), section_(section) {}

  uint8_t u8() { return uint8_t(fixed(1, "a u8")); }
  uint16_t u16() { return uint16_t(fixed(2, "a u16")); }
  uint32_t u32() { return uint32_t(fixed(4, "a u32")); }
  uint64_t u64() { return fixed(8, "a u64"); }
  double f64() { return std::bit_cast<double>(fixed(8, "an f64")); }

  // u32 byte length, then the bytes.
  std::string string(std::string_view what) {
    uint64_t at = pos_;
    uint32_t n = u32();
    if (!ok()) return {};
    if (n > remaining()) {
      fail(std::string(what) + " at byte " + std::to_string(at) + " claims " + std::to_string(n) + " bytes but only " +
           std::to_string(remaining()) + " remain in section '" + section_ + "'");
      return {};
    }
    std::string s(reinterpret_cast<const char*>(file_.data() + pos_), n);
    pos_ += n;
    return s;
  }

  // A u32 element count, accepted only if `count * minElementSize` bytes remain, so the caller
  // may reserve() for it without trusting the file.
  uint32_t count(uint64_t minElementSize, std::string_view what) {
    uint64_t at = pos_;
    uint32_t n = u32();
    if (!ok()) return 0;
    if (uint64_t(n) * minElementSize > remaining()) {
      fail(std::string(what) + " " + std::to_string(n) + " at byte " + std::to_string(at) + " needs at least " +
           std::to_string(uint64_t(n) * minElementSize) + " bytes but only " + std::to_string(remaining()) +
           " remain in section '" + section_ + "'");
      return 0;
    }
    return n;
  }

  // Every section is decoded completely; stray bytes mean writer and reader disagree.
  void expectEnd() {
    if (ok() && pos_ != end_)
      fail("section '" + section_ + "' has " + std::to_string(end_ - pos_) + " unexpected trailing bytes at byte " +
           std::to_string(pos_));
  }

  void fail(std::string message) {
    if (error_.empty()) error_ = std::move(message);
  }

  bool ok() const { return error_.empty(); }
  const std::string& error() const { return error_; }
  uint64_t position() const { return pos_; }
  uint64_t remaining() const { return end_ - pos_; }
  const std::string& section() const { return section_; }

 private:
  uint64_t fixed(int n, const char* what) {
    if (!ok()) return 0;
    if (uint64_t(n) > remaining()) {
      fail("section '" + section_ + "' is truncated: " + what + " at byte " + std::to_string(pos_) +
           " runs past its end at byte " + std::to_string(end_));
      return 0;
    }
    uint64_t v = loadLE(file_.data() + pos_, n);
    pos_ += uint64_t(n);
    return v;
  }

  std::span<const uint8_t> file_;
  uint64_t pos_;
  uint64_t end_;
  std::string section_;
  std::string error_;
};

}  // namespace facet::package::detail
