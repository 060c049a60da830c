#include "gltf_document.h"

#include <algorithm>
#include <cctype>
#include <iterator>

#include "facet/scene/json_document.h"

namespace facet::runtime::gltf {
namespace {

using nlohmann::json;

// The member `key` of `object`, or null.
const json* member(const json& object, const char* key) {
  if (!object.is_object()) return nullptr;
  auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

// "2.0" -> {2, 0}; nullopt unless <major>.<minor> in digits (the schema's pattern).
std::optional<std::pair<unsigned long, unsigned long>> version(const std::string& text) {
  const size_t dot = text.find('.');
  const auto digits = [](std::string_view s) {
    return !s.empty() && s.size() <= 9 && s.find_first_not_of("0123456789") == std::string_view::npos;
  };
  if (dot == std::string::npos || !digits(std::string_view(text).substr(0, dot)) ||
      !digits(std::string_view(text).substr(dot + 1)))
    return std::nullopt;
  return std::make_pair(std::stoul(text.substr(0, dot)), std::stoul(text.substr(dot + 1)));
}

bool checkAsset(const json& document, std::string* error) {
  const json* asset = member(document, "asset");
  const json* given = asset ? member(*asset, "version") : nullptr;
  if (!given || !given->is_string()) {
    *error = "/asset/version: missing (a glTF 2.0 file says \"version\": \"2.0\")";
    return false;
  }
  const auto v = version(given->get<std::string>());
  if (!v || v->first != 2) {
    *error = "/asset/version: '" + scene::shownValue(given->get<std::string>()) +
             "' is not a glTF 2.x version (this loader reads glTF 2.0)";
    return false;
  }
  if (const json* minimum = member(*asset, "minVersion")) {
    const auto m = minimum->is_string() ? version(minimum->get<std::string>()) : std::nullopt;
    if (!m || *m > std::make_pair(2ul, 0ul) || *m > *v) {
      *error =
          "/asset/minVersion: " +
          (minimum->is_string() ? "'" + scene::shownValue(minimum->get<std::string>()) + "'" : minimum->type_name()) +
          " is not a version this loader supports (glTF 2.0), or is above the asset's version";
      return false;
    }
  }
  return true;
}

// The required extensions Facet implements: KHR_mesh_quantization (integer attribute types, read
// by gltf_mesh.cpp) and KHR_texture_transform (the materials `matc import` writes apply it:
// gltf_materials.cpp). Every other one is refused, as the glTF spec asks.
constexpr const char* kImplementedExtensions[] = {"KHR_mesh_quantization", "KHR_texture_transform"};

bool checkExtensions(const json& document, std::string* error) {
  const json* required = member(document, "extensionsRequired");
  if (!required) return true;
  if (!required->is_array()) {
    *error = "/extensionsRequired: expected an array of extension names";
    return false;
  }
  for (size_t i = 0; i < required->size(); ++i) {
    const json& name = (*required)[i];
    if (name.is_string() && std::find(std::begin(kImplementedExtensions), std::end(kImplementedExtensions),
                                      name.get<std::string>()) != std::end(kImplementedExtensions)) {
      continue;
    }
    *error = "/extensionsRequired/" + std::to_string(i) + ": the file requires " +
             (name.is_string() ? "extension '" + scene::shownValue(name.get<std::string>()) + "'"
                               : std::string("an extension")) +
             ", which this loader does not implement (it implements KHR_mesh_quantization and KHR_texture_transform; "
             "the glTF spec says "
             "such a file must not be loaded)";
    return false;
  }
  return true;
}

// glTF 2.0 (section 3.12, and every schema's `extensions` property): `extensions` is an object
// whose members are objects, one per extension. tinygltf drops a member of any other type without
// a word, so `"KHR_materials_sheen": 1` used to import as a material without sheen. `extras` is
// application data the spec leaves free, so nothing under it is checked. The recursion is bounded
// by the depth check the text passed before it was parsed (gltf_source.cpp).
bool checkExtensionObjects(const json& value, const std::string& at, std::string* error) {
  if (value.is_array()) {
    for (size_t i = 0; i < value.size(); ++i)
      if (!checkExtensionObjects(value[i], at + "/" + std::to_string(i), error)) return false;
    return true;
  }
  if (!value.is_object()) return true;
  for (const auto& [key, member] : value.items()) {
    if (key == "extras") continue;
    const std::string where = at + "/" + scene::pointerSegment(key);
    if (key == "extensions") {
      if (!member.is_object()) {
        *error =
            where + ": expected an object (glTF 2.0's extensions, one member per extension), got " + member.type_name();
        return false;
      }
      for (const auto& [name, extension] : member.items()) {
        if (!extension.is_object()) {
          *error = where + "/" + scene::pointerSegment(name) +
                   ": expected an object (an extension's value in glTF 2.0), got " + extension.type_name();
          return false;
        }
      }
    }
    if (!checkExtensionObjects(member, where, error)) return false;
  }
  return true;
}

bool checkStrides(const json& document, std::string* error) {
  const json* views = member(document, "bufferViews");
  if (!views || !views->is_array()) return true;  // tinygltf reports a wrong type
  for (size_t i = 0; i < views->size(); ++i) {
    const json* stride = member((*views)[i], "byteStride");
    if (!stride) continue;
    const bool valid = stride->is_number_unsigned() && stride->get<uint64_t>() >= 4 && stride->get<uint64_t>() <= 252 &&
                       stride->get<uint64_t>() % 4 == 0;
    if (!valid) {
      *error = "/bufferViews/" + std::to_string(i) + "/byteStride: " + scene::shownValue(stride->dump()) +
               " is not a multiple of 4 in 4..252 (glTF 2.0 bufferView.byteStride)";
      return false;
    }
  }
  return true;
}

int hexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

bool isBase64BufferUri(const std::string& uri) {
  return uri.rfind("data:application/octet-stream;base64,", 0) == 0 ||
         uri.rfind("data:application/gltf-buffer;base64,", 0) == 0;
}

std::optional<std::vector<ExternalBuffer>> checkBuffers(const json& document, bool binary, std::string* error) {
  std::vector<ExternalBuffer> external;
  const json* buffers = member(document, "buffers");
  if (!buffers || !buffers->is_array()) return external;  // tinygltf reports a wrong type
  for (size_t i = 0; i < buffers->size(); ++i) {
    const std::string pointer = "/buffers/" + std::to_string(i);
    const json& buffer = (*buffers)[i];
    const json* length = member(buffer, "byteLength");
    // At least 1, as the schema says: tinygltf copies a .glb's BIN chunk to &data.at(0), which
    // throws on an empty buffer.
    if (!length || !length->is_number_unsigned() || length->get<uint64_t>() == 0) {
      *error = pointer + "/byteLength: expected a whole number of bytes, at least 1";
      return std::nullopt;
    }
    const json* uri = member(buffer, "uri");
    if (!uri) {
      if (binary && i == 0) continue;  // the BIN chunk
      *error = pointer + ": no uri (only the first buffer of a .glb may omit it, for the BIN chunk)";
      return std::nullopt;
    }
    if (!uri->is_string()) {
      *error = pointer + "/uri: expected a string";
      return std::nullopt;
    }
    const std::string& text = uri->get_ref<const std::string&>();
    if (isBase64BufferUri(text)) continue;  // decoded by tinygltf from the JSON: bounded by its size
    std::string why;
    std::string path = uriPath(text, &why);
    if (path.empty()) {
      *error = pointer + "/uri: " + why;
      return std::nullopt;
    }
    external.push_back({pointer + "/uri", text, std::move(path), length->get<uint64_t>()});
  }
  return external;
}

}  // namespace

std::string uriPath(const std::string& uri, std::string* why) {
  if (uri.empty()) {
    *why = "is empty";
    return {};
  }
  // A scheme (RFC 3986 §3.1) before the first '/': http:, file:, C: (another data: type).
  const size_t colon = uri.find(':');
  if (colon != std::string::npos && colon < uri.find('/') && std::isalpha(static_cast<unsigned char>(uri[0])) &&
      uri.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+-.", 0) == colon) {
    *why = "'" + scene::shownValue(uri) +
           "' is neither a relative path nor a base64 data: URI of type application/octet-stream "
           "or application/gltf-buffer";
    return {};
  }
  std::string path;
  for (size_t i = 0; i < uri.size(); ++i) {
    const char c = uri[i];
    if (c == '\0') {
      *why = "'" + scene::shownValue(uri) + "' holds a NUL character, which would cut the file name short";
      return {};
    }
    if (c == '?' || c == '#') {
      *why = "'" + scene::shownValue(uri) +
             "' has a query or fragment (a buffer is a file: write '?' and '#' as %3F and %23)";
      return {};
    }
    if (c != '%') {
      path += c;
      continue;
    }
    const int high = i + 2 < uri.size() ? hexDigit(uri[i + 1]) : -1,
              low = i + 2 < uri.size() ? hexDigit(uri[i + 2]) : -1;
    if (high < 0 || low < 0 || (high == 0 && low == 0)) {
      *why = "'" + scene::shownValue(uri) + "' has a malformed %-escape or %00 at character " + std::to_string(i);
      return {};
    }
    path += char(high * 16 + low);
    i += 2;
  }
  return path;
}

std::optional<std::vector<ExternalBuffer>> checkDocument(const json& document, bool binary, std::string* error) {
  if (!document.is_object()) {
    *error = "/: expected a JSON object";
    return std::nullopt;
  }
  if (!checkAsset(document, error) || !checkExtensions(document, error) ||
      !checkExtensionObjects(document, "", error) || !checkStrides(document, error))
    return std::nullopt;
  return checkBuffers(document, binary, error);
}

}  // namespace facet::runtime::gltf
