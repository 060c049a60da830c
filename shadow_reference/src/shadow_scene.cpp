#include "facet/shadow_reference/shadow_scene.h"

#include "facet/scene/json_document.h"

namespace facet::shadow_reference {
namespace {

using nlohmann::json;

// Reads and removes a boolean flag; false with *error at its pointer when it is not a bool.
bool takeFlag(json* object, const char* key, const std::string& pointer, bool* value, const std::string& path,
              std::string* error) {
  if (!object->is_object() || !object->contains(key)) return true;
  const json& flag = (*object)[key];
  if (!flag.is_boolean()) {
    *error = path + ": error: " + pointer + "/" + key + ": expected true or false";
    return false;
  }
  *value = flag.get<bool>();
  object->erase(key);
  return true;
}

}  // namespace

std::optional<ShadowScene> parseShadowScene(const std::string& path, const std::string& text, std::string* error,
                                            const runtime::SceneReadOptions& options) {
  std::optional<json> document = scene::parseJsonDocument(path, text, error);
  if (!document) return std::nullopt;
  ShadowScene out;
  if (document->is_object()) {
    if (document->contains("sun") &&
        !takeFlag(&(*document)["sun"], "castShadows", "/sun", &out.sunCastsShadows, path, error))
      return std::nullopt;
    // The shadow map's settings are the renderer's: the reference ray-casts whatever they are.
    if (document->contains("shadows")) {
      if (!(*document)["shadows"].is_object()) {
        *error = path + ": error: /shadows: expected an object";
        return std::nullopt;
      }
      document->erase("shadows");
    }
    if (document->contains("objects") && (*document)["objects"].is_array()) {
      json& objects = (*document)["objects"];
      for (size_t i = 0; i < objects.size(); ++i) {
        const std::string pointer = "/objects/" + std::to_string(i);
        bool casts = true, receives = true;
        if (!takeFlag(&objects[i], "castShadows", pointer, &casts, path, error) ||
            !takeFlag(&objects[i], "receiveShadows", pointer, &receives, path, error))
          return std::nullopt;
        out.casts.push_back(casts);
        out.receives.push_back(receives);
      }
    }
  }
  // Only keys were removed: every JSON pointer the scene reader reports is still the file's.
  std::string stripped;
  try {
    stripped = document->dump();
  } catch (const json::exception& e) {  // the strict reader took only valid UTF-8: not expected
    *error = path + ": error: " + e.what();
    return std::nullopt;
  }
  std::optional<runtime::Scene> scene = runtime::parseScene(path, stripped, error, options);
  if (!scene) return std::nullopt;
  out.scene = std::move(*scene);
  out.casts.resize(out.scene.objects.size(), true);
  out.receives.resize(out.scene.objects.size(), true);
  return out;
}

std::optional<ShadowScene> loadShadowScene(const std::string& path, std::string* error,
                                           const runtime::SceneReadOptions& options) {
  std::optional<std::string> text = runtime::readSceneFile(path, error);
  if (!text) return std::nullopt;
  return parseShadowScene(path, *text, error, options);
}

}  // namespace facet::shadow_reference
