// The budgets and tuning files' reading: a failure is thrown with its JSON pointer and caught once
// per file, which reports it as "<path>: error: <pointer>: <what>".
#pragma once

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

inline std::string invalidMessage(const std::string& path, const Invalid& e) {
  return path + ": error: " + (e.pointer.empty() ? "/" : e.pointer) + ": " + e.message;
}

}  // namespace facet::tune
