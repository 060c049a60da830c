// The budgets and tuning files' reading: a failure is thrown with its JSON pointer and caught once
// per file, which reports it as "<path>: error: <pointer>: <what>".
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "facet/scene/json_document.h"

namespace facet::tune {

struct Invalid {
  std::string pointer, message;
};

[[noreturn]] inline void fail(const std::string& pointer, const std::string& message) {
  throw Invalid{pointer, message};
}

inline std::string child(const std::string& pointer, const std::string& key) {
  return pointer + "/" + scene::pointerSegment(key);
}

inline const nlohmann::json& object(const nlohmann::json& j, const std::string& pointer) {
  if (!j.is_object()) fail(pointer, "expected an object");
  return j;
}

inline std::string shortest(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

inline double number(const nlohmann::json& j, const std::string& pointer, double least, double most) {
  if (!j.is_number()) fail(pointer, "expected a number");
  const double v = j.get<double>();
  if (!std::isfinite(v) || v < least || v > most)
    fail(pointer, "expected a number from " + shortest(least) + " to " + shortest(most));
  return v;
}

// The ranges both files read figures in. A PSNR of 8-bit images is at most 10·log10(255² · 3N)
// for N pixels with one step of error: 200 dB would take 10^15 pixels. Costs are cycles per pixel.
inline constexpr double kMaxPsnrDb = 200;
inline constexpr double kMaxCost = 1e6;
inline constexpr double kMaxVerticesPerPixel = 16;

inline std::string invalidMessage(const std::string& path, const Invalid& e) {
  return path + ": error: " + (e.pointer.empty() ? "/" : e.pointer) + ": " + e.message;
}

}  // namespace facet::tune
