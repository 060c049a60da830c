#include "facet/scene/json_document.h"

#include <cstdio>
#include <set>
#include <vector>

namespace facet::scene {
namespace {

using nlohmann::json;

struct DuplicateKey {
  std::string pointer;
};

// Where the parser is: one frame per open object or array, so a duplicate can be named by its
// JSON pointer (the callback sees keys and values, not positions).
class KeyTracker {
 public:
  bool operator()(int, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start: {
        std::string pointer = frames_.empty() ? "" : childPointer();
        if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
        frames_.push_back({event == json::parse_event_t::array_start, 0, {}, "", std::move(pointer)});
        break;
      }
      case json::parse_event_t::key: {
        Frame& f = frames_.back();
        f.key = parsed.get<std::string>();
        if (!f.keys.insert(f.key).second) throw DuplicateKey{childPointer()};
        break;
      }
      case json::parse_event_t::value:
        if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
        break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end: frames_.pop_back(); break;
    }
    return true;
  }

 private:
  struct Frame {
    bool array;
    size_t index;
    std::set<std::string> keys;
    std::string key;
    std::string pointer;
  };

  std::string childPointer() const {
    const Frame& f = frames_.back();
    return f.pointer + "/" + (f.array ? std::to_string(f.index) : pointerSegment(f.key));
  }

  std::vector<Frame> frames_;
};

// nlohmann's message after its "[json.exception...] " prefix and "syntax error while parsing" noise.
std::string reason(const json::exception& e) {
  std::string what = e.what();
  size_t at = what.find("] ");
  if (at != std::string::npos) what = what.substr(at + 2);
  if (size_t error = what.find("error: "); error != std::string::npos) what = what.substr(error + 7);
  return what.size() > 200 ? what.substr(0, 200) + "..." : what;
}

}  // namespace

namespace {

// At most kShown characters of `text`, control characters escaped, and (for a pointer segment)
// ~ and / escaped as RFC 6901 says.
std::string shortened(std::string_view text, bool pointerEscapes) {
  constexpr size_t kShown = 48;
  std::string out;
  size_t shown = 0;
  for (char c : text) {
    if (shown++ == kShown) break;
    if (pointerEscapes && c == '~')
      out += "~0";
    else if (pointerEscapes && c == '/')
      out += "~1";
    else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", unsigned(c));
      out += buf;
    } else {
      out += c;
    }
  }
  if (text.size() > kShown) out += "...(" + std::to_string(text.size()) + " bytes)";
  return out;
}

}  // namespace

std::optional<size_t> jsonTooDeepAt(std::string_view text, size_t maxDepth) {
  size_t depth = 0;
  bool inString = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (c == '\\')
        ++i;  // the escaped character cannot end the string
      else if (c == '"')
        inString = false;
      continue;
    }
    if (c == '"')
      inString = true;
    else if (c == '[' || c == '{') {
      if (++depth > maxDepth) return i;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return std::nullopt;
}

std::string jsonLineColumn(std::string_view text, size_t offset) {
  offset = std::min(offset, text.size());
  size_t line = 1, column = 1;
  for (size_t i = 0; i < offset; ++i) {
    bool newline = text[i] == '\n';
    line += newline;
    column = newline ? 1 : column + 1;
  }
  return std::to_string(line) + ":" + std::to_string(column);
}

std::string pointerSegment(std::string_view key) { return shortened(key, true); }

std::string shownValue(std::string_view value) { return shortened(value, false); }

std::optional<nlohmann::json> parseJsonDocument(const std::string& path, const std::string& text, std::string* error) {
  if (std::optional<size_t> at = jsonTooDeepAt(text)) {
    *error = path + ":" + jsonLineColumn(text, *at) + ": error: arrays and objects nest more than " +
             std::to_string(kMaxJsonDepth) + " deep here (Facet reads JSON at most that deep)";
    return std::nullopt;
  }
  try {
    KeyTracker tracker;
    return json::parse(text, std::ref(tracker));
  } catch (const DuplicateKey& d) {
    *error = path + ": error: " + d.pointer + ": duplicate key (JSON objects keep one value per key)";
  } catch (const json::parse_error& e) {
    *error = path + ":" + jsonLineColumn(text, e.byte == 0 ? 0 : e.byte - 1) + ": error: invalid JSON: " + reason(e);
  } catch (const json::exception& e) {
    // out_of_range 406 "number overflow parsing '1e400'": no offset given; find the token.
    std::string where;
    std::string what = e.what();
    size_t q = what.find('\'');
    size_t q2 = q == std::string::npos ? q : what.find('\'', q + 1);
    if (q2 != std::string::npos) {
      size_t at = text.find(what.substr(q + 1, q2 - q - 1));
      if (at != std::string::npos) where = ":" + jsonLineColumn(text, at);
    }
    *error = path + where + ": error: invalid JSON: " + reason(e);
  }
  return std::nullopt;
}

}  // namespace facet::scene
