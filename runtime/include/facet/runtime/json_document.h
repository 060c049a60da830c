// Strict reading of the JSON files Facet takes from users (scenes, lint budgets and baselines):
// what nlohmann::json accepts silently is an error here, with a place to look.
//   - a key given twice in one object (nlohmann keeps the last: a second "objects": [] would
//     empty a scene) -> "<path>: error: <json pointer>: duplicate key"
//   - a number beyond the double range (1e400; nlohmann throws out_of_range, which callers
//     that catch only parse errors let escape) -> "<path>:<line>:<col>: error: invalid JSON: ..."
//   - a syntax error -> "<path>:<line>:<col>: error: invalid JSON: ..."
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace facet::runtime {

std::optional<nlohmann::json> parseJsonDocument(const std::string& path, const std::string& text, std::string* error);

// A JSON pointer segment for `key` (RFC 6901: ~ -> ~0, / -> ~1), shortened to its first 48
// characters with its length when longer, and with control characters escaped: a hostile 15 MB
// key must not be echoed in full, and a NUL must not cut the message short.
std::string pointerSegment(std::string_view key);

// A string value from the file, for a message: shortened and escaped as pointerSegment, but with
// ~ and / as written (a path stays readable).
std::string shownValue(std::string_view value);

}  // namespace facet::runtime
