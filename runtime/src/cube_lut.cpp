// Adobe/Resolve .cube files (Adobe "Cube LUT Specification" 1.0, 2013): hostile input is refused
// with the file and line, never read past its bounds, and bounded in size before it is read.
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "facet/runtime/color_grading.h"

namespace facet::runtime {
namespace {

struct CubeError {
  size_t line;
  std::string message;
};

[[noreturn]] void fail(size_t line, std::string message) { throw CubeError{line, std::move(message)}; }

std::vector<std::string_view> tokens(std::string_view line) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

std::string shown(std::string_view token) {
  std::string s(token.substr(0, 40));
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
  return s + (token.size() > 40 ? "..." : "");
}

// A finite number: from_chars also reads "nan" and "inf", which a table may not hold. The fp16
// bound is the texture's: a larger value would saturate there anyway, silently. A number too
// small for a double (1e-400) is 0, as it would be in the half-float table (anything below 2^-25
// rounds to 0 there).
float number(std::string_view token, size_t line) {
  double v = 0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
  if (end != token.data() + token.size() || (ec != std::errc() && ec != std::errc::result_out_of_range))
    fail(line, "expected a number, not '" + shown(token) + "'");
  if (ec == std::errc::result_out_of_range) {
    // from_chars leaves v alone when out of range; strtod (on the same, already checked,
    // characters) tells an overflow (±HUGE_VAL) from an underflow.
    const double huge = std::strtod(std::string(token).c_str(), nullptr);
    if (std::isinf(huge))
      fail(line, "'" + shown(token) + "' is beyond the half-float range (65504) the table is stored in");
    v = 0;
  }
  if (!std::isfinite(v)) fail(line, "'" + shown(token) + "' is not a finite number");
  if (std::abs(v) > 65504)
    fail(line, "'" + shown(token) + "' is beyond the half-float range (65504) the table is stored in");
  return float(v);
}

std::array<float, 3> triple(const std::vector<std::string_view>& t, size_t first, size_t line, const char* what) {
  if (t.size() != first + 3) fail(line, std::string(what) + " takes three numbers");
  return {number(t[first], line), number(t[first + 1], line), number(t[first + 2], line)};
}

ColorLut parse(std::string_view text) {
  ColorLut lut;
  size_t expected = 0, lineNumber = 0;
  size_t domainLine = 0;  // the last DOMAIN_* line, checked once the header is over
  // A UTF-8 byte-order mark (what some Windows editors put first) is not text of the file.
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) fail(1, "an empty file: not a 3D .cube file");
  size_t pos = 0;
  while (pos < text.size()) {
    // Lines end in LF, CR LF or a lone CR (older Mac tools), as text editors write them.
    size_t lineEnd = text.find_first_of("\r\n", pos);
    if (lineEnd == std::string_view::npos) lineEnd = text.size();
    std::string_view line = text.substr(pos, lineEnd - pos);
    pos = lineEnd + (text.substr(lineEnd, 2) == "\r\n" ? 2 : 1);
    ++lineNumber;
    if (line.find('\0') != std::string_view::npos) fail(lineNumber, "a NUL byte: not a text file");
    const std::vector<std::string_view> t = tokens(line);
    if (t.empty() || t[0][0] == '#') continue;
    const std::string_view key = t[0];
    double scratch = 0;  // "nan" and "inf" start with letters but are (refused) numbers, not keywords
    const auto parsed = std::from_chars(key.data(), key.data() + key.size(), scratch);
    const bool keyword =
        ((key[0] >= 'A' && key[0] <= 'Z') || (key[0] >= 'a' && key[0] <= 'z')) && parsed.ptr != key.data() + key.size();
    if (keyword && !lut.rgb.empty()) fail(lineNumber, "'" + shown(key) + "' after the table's first entry");
    if (key == "TITLE") {
      const size_t open = line.find('"'), close = line.rfind('"');
      if (open == std::string_view::npos || close == open) fail(lineNumber, "TITLE takes a quoted string");
      lut.title = std::string(line.substr(open + 1, close - open - 1));
    } else if (key == "LUT_3D_SIZE") {
      if (expected != 0) fail(lineNumber, "a second LUT_3D_SIZE");
      if (t.size() != 2) fail(lineNumber, "LUT_3D_SIZE takes one whole number");
      // Digits only: read as a float, 2.00000001 was 2 and accepted.
      const std::string_view token = t[1];
      const char* const last = token.data() + token.size();
      double v = 0;
      const auto [vEnd, vError] = std::from_chars(token.data(), last, v);
      if (vEnd != last || (vError != std::errc() && vError != std::errc::result_out_of_range))
        fail(lineNumber, "expected a number, not '" + shown(token) + "'");
      uint32_t n = 0;
      const auto [nEnd, nError] = std::from_chars(token.data(), last, n);
      const bool digits = nEnd == last && nError == std::errc();
      const bool wholeOutside = vError == std::errc() && v == std::floor(v) && (v < 2 || v > kMaxCubeLutSize);
      if (!digits && !wholeOutside)
        fail(lineNumber, "LUT_3D_SIZE takes a whole number in digits, not '" + shown(token) + "'");
      if (!digits || n < 2 || n > kMaxCubeLutSize)
        fail(lineNumber, "LUT_3D_SIZE " + shown(t[1]) + " is outside 2.." + std::to_string(kMaxCubeLutSize));
      lut.size = n;
      expected = size_t(lut.size) * lut.size * lut.size;
      lut.rgb.reserve(expected * 3);
    } else if (key == "LUT_1D_SIZE") {
      fail(lineNumber, "a 1D LUT (LUT_1D_SIZE): only 3D tables are supported");
    } else if (key == "DOMAIN_MIN") {
      lut.domainMin = triple(t, 1, lineNumber, "DOMAIN_MIN");
      domainLine = lineNumber;
    } else if (key == "DOMAIN_MAX") {
      lut.domainMax = triple(t, 1, lineNumber, "DOMAIN_MAX");
      domainLine = lineNumber;
    } else if (key == "LUT_3D_INPUT_RANGE") {  // Resolve's form of one domain for all channels
      if (t.size() != 3) fail(lineNumber, "LUT_3D_INPUT_RANGE takes two numbers");
      const float lo = number(t[1], lineNumber), hi = number(t[2], lineNumber);
      lut.domainMin = {lo, lo, lo};
      lut.domainMax = {hi, hi, hi};
      domainLine = lineNumber;
    } else if (keyword) {
      fail(lineNumber, "unknown keyword '" + shown(key) + "'");
    } else {
      if (expected == 0) fail(lineNumber, "a table entry before LUT_3D_SIZE");
      if (lut.rgb.size() / 3 == expected)
        fail(lineNumber, "more than the " + std::to_string(expected) + " entries LUT_3D_SIZE " +
                             std::to_string(lut.size) + " gives");
      const std::array<float, 3> v = triple(t, 0, lineNumber, "a table entry");
      lut.rgb.insert(lut.rgb.end(), v.begin(), v.end());
    }
  }
  for (int c = 0; c < 3; ++c)
    if (!(lut.domainMin[c] < lut.domainMax[c]))
      fail(domainLine, "DOMAIN_MIN must be below DOMAIN_MAX in every channel");
  if (expected == 0) fail(lineNumber, "no LUT_3D_SIZE: not a 3D .cube file");
  if (lut.rgb.size() / 3 != expected)
    fail(lineNumber, "the table ends after " + std::to_string(lut.rgb.size() / 3) + " of the " +
                         std::to_string(expected) + " entries LUT_3D_SIZE " + std::to_string(lut.size) + " gives");
  return lut;
}

}  // namespace

std::optional<ColorLut> parseCubeLut(const std::string& name, std::string_view text, std::string* error) {
  try {
    return parse(text);
  } catch (const CubeError& e) {
    if (error) *error = name + ":" + std::to_string(e.line) + ": error: " + e.message;
  }
  return std::nullopt;
}

std::optional<ColorLut> loadCubeLut(const std::string& path, std::string* error) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    if (error) *error = path + ": error: not a regular file";
    return std::nullopt;
  }
  const uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec || size > kMaxCubeFileBytes) {
    if (error)
      *error =
          path + ": error: " +
          (ec ? ec.message()
              : "larger than the " + std::to_string(kMaxCubeFileBytes) + " bytes a .cube file of LUT_3D_SIZE 64 needs");
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) {
    if (error) *error = path + ": error: cannot read the file";
    return std::nullopt;
  }
  return parseCubeLut(path, text.str(), error);
}

}  // namespace facet::runtime
