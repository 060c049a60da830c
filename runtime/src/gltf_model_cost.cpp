#include "gltf_model_cost.h"

#include <tiny_gltf.h>
#include <nlohmann/json.hpp>

#include <map>
#include <vector>

namespace facet::runtime::gltf {
namespace {

using nlohmann::json;

// A value in tinygltf's JSON document (nlohmann: 16 bytes) and the copy tinygltf makes of a
// number or a small string when it reads it into its structs.
constexpr uint64_t kJsonValue = sizeof(json) + 16;
// An object member: a std::map node (tree links, the key as a std::string).
constexpr uint64_t kMember = 64;

// The struct each element of a top-level array becomes.
const std::map<std::string, uint64_t, std::less<>>& topLevelElements() {
  static const std::map<std::string, uint64_t, std::less<>> sizes = {
      {"accessors", sizeof(tinygltf::Accessor)}, {"animations", sizeof(tinygltf::Animation)},
      {"buffers", sizeof(tinygltf::Buffer)},     {"bufferViews", sizeof(tinygltf::BufferView)},
      {"cameras", sizeof(tinygltf::Camera)},     {"images", sizeof(tinygltf::Image)},
      {"materials", sizeof(tinygltf::Material)}, {"meshes", sizeof(tinygltf::Mesh)},
      {"nodes", sizeof(tinygltf::Node)},         {"samplers", sizeof(tinygltf::Sampler)},
      {"scenes", sizeof(tinygltf::Scene)},       {"skins", sizeof(tinygltf::Skin)},
      {"textures", sizeof(tinygltf::Texture)}};
  return sizes;
}

class CostWalk : public nlohmann::json_sax<json> {
 public:
  ModelCost result() const {
    ModelCost cost{total_, "", 0};
    for (const auto& [key, bytes] : byTopLevelKey_)
      if (bytes > cost.largestBytes) cost = {total_, "/" + key, bytes};
    return cost;
  }

  bool null() override { return value(0); }
  bool boolean(bool) override { return value(0); }
  bool number_integer(number_integer_t) override { return value(0); }
  bool number_unsigned(number_unsigned_t) override { return value(0); }
  bool number_float(number_float_t, const string_t&) override { return value(0); }
  bool string(string_t& s) override { return value(s.size()); }
  bool binary(binary_t&) override { return value(0); }  // not produced by the text parser
  bool key(string_t& k) override {
    key_ = k;
    return true;
  }
  bool start_object(std::size_t) override { return open(false); }
  bool start_array(std::size_t) override { return open(true); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

 private:
  struct Frame {
    bool array;
    bool asValues;         // tinygltf keeps what is inside as tinygltf::Value (or Parameter)
    uint64_t elementCost;  // the struct each element becomes (arrays)
    std::string key;       // the key this container sits under ("" for an array element)
  };

  // Prices one value (a scalar, or a container as it opens) in the frame on top of the stack.
  bool value(uint64_t stringBytes) {
    uint64_t cost = kJsonValue + 2 * stringBytes;
    if (!frames_.empty()) {
      const Frame& parent = frames_.back();
      if (!parent.array) cost += kMember + key_.size();
      if (parent.asValues) cost += sizeof(tinygltf::Value) + stringBytes + (parent.array ? 0 : kMember + key_.size());
      cost += parent.elementCost;
    }
    total_ += cost;
    if (frames_.size() >= 2) byTopLevelKey_[frames_[1].key] += cost;
    return total_ <= kMaxModelBytes;
  }

  // What each element of an array under `key` becomes, from where the array sits.
  uint64_t elementCost(const std::string& key) const {
    const size_t depth = frames_.size();  // the new array's parent is frames_[depth - 1]
    if (depth == 1) {
      auto it = topLevelElements().find(key);
      return it == topLevelElements().end() ? 0 : it->second;
    }
    if (depth == 3) {  // inside an element of a top-level array, or under a root extension
      const std::string& top = frames_[1].key;
      if (top == "meshes" && key == "primitives") return sizeof(tinygltf::Primitive);
      if (top == "animations" && key == "channels") return sizeof(tinygltf::AnimationChannel);
      if (top == "animations" && key == "samplers") return sizeof(tinygltf::AnimationSampler);
      if (top == "extensions" && frames_[2].key == "KHR_lights_punctual" && key == "lights")
        return sizeof(tinygltf::Light);
    }
    return 0;
  }

  bool open(bool array) {
    const std::string key = !frames_.empty() && frames_.back().array ? std::string() : key_;
    const bool parentValues = !frames_.empty() && frames_.back().asValues;
    const bool asValues =
        parentValues || key == "extras" || key == "extensions" || (frames_.size() == 1 && key == "materials");
    const uint64_t elements = array ? elementCost(key) : 0;
    if (!value(0)) return false;
    frames_.push_back({array, asValues, elements, key});
    return true;
  }

  bool close() {
    frames_.pop_back();
    return true;
  }

  std::vector<Frame> frames_;
  std::string key_;
  uint64_t total_ = 0;
  std::map<std::string, uint64_t> byTopLevelKey_;
};

}  // namespace

ModelCost estimateModelCost(std::string_view text) {
  CostWalk walk;
  json::sax_parse(text.begin(), text.end(), &walk);
  return walk.result();
}

}  // namespace facet::runtime::gltf
