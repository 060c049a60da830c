// Strict reading of the JSON files Facet takes from users (scenes, lint budgets and baselines):
// what nlohmann::json accepts silently is an error here, with a place to look.
//   - a key given twice in one object (nlohmann keeps the last: a second "objects": [] would
//     empty a scene) -> "<path>: error: <json pointer>: duplicate key"
//   - a number beyond the double range (1e400; nlohmann throws out_of_range, which callers
//     that catch only parse errors let escape) -> "<path>:<line>:<col>: error: invalid JSON: ..."
//   - a syntax error -> "<path>:<line>:<col>: error: invalid JSON: ..."
//   - arrays and objects nested deeper than kMaxJsonDepth -> "<path>:<line>:<col>: error: ..."
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace facet::scene {

// The deepest nesting of arrays and objects any JSON file Facet reads may have. The example scenes
// and lint files nest at most 5 deep; glTF reaches 8 (a texture transform's offset inside a
// material) plus whatever its `extras` hold. The bound exists because
// parsers and the code walking their result recurse (a 40 KB glTF of 20,000 nested arrays
// overflowed tinygltf's stack), and a parser that tracks where it is keeps a frame per level.
constexpr size_t kMaxJsonDepth = 64;

// Where `text` first opens an array or object deeper than `maxDepth`, by a linear scan that
// skips string contents and never recurses; nullopt when it does not. It is a bound, not a
// parser: text that is not JSON passes or fails it by its brackets alone, and the parser run
// after it reports the syntax. Run it before any parser that recurses sees the text.
std::optional<size_t> jsonTooDeepAt(std::string_view text, size_t maxDepth = kMaxJsonDepth);

// "<line>:<col>" of a byte offset in `text`, both counted from 1.
std::string jsonLineColumn(std::string_view text, size_t offset);

std::optional<nlohmann::json> parseJsonDocument(const std::string& path, const std::string& text, std::string* error);

// A JSON pointer segment for `key` (RFC 6901: ~ -> ~0, / -> ~1), shortened to its first 48
// characters with its length when longer, and with control characters escaped: a hostile 15 MB
// key must not be echoed in full, and a NUL must not cut the message short.
std::string pointerSegment(std::string_view key);

// A string value from the file, for a message: shortened and escaped as pointerSegment, but with
// ~ and / as written (a path stays readable).
std::string shownValue(std::string_view value);

}  // namespace facet::scene
