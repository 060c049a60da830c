// A material package loaded by an app: variant lookup and parameter block packing.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "facet/package.h"
#include "facet/render_backend.h"

namespace facet::runtime {

class LoadedMaterial {
 public:
  // Reads and validates a .matpkg; nullopt with *error on any problem with the file.
  static std::optional<LoadedMaterial> load(const std::string& path, std::string* error);

  const package::MaterialInfo& info() const { return package_.material; }
  const package::Package& package() const { return package_; }

  // The shaders of one variant, for every API. A key the package was not built with is an
  // error that lists the keys it has (the compiler builds only what a scene asks for).
  std::optional<ShaderProgram> program(const std::string& variantKey, std::string* error) const;

  // The std140 "MaterialParams" bytes: declared defaults, overridden by `values` (by name;
  // colour values are sRGB-encoded, as authored, and converted to linear here). Unknown names,
  // wrong component counts and values outside a declared range are errors.
  std::optional<std::vector<uint8_t>> paramBlock(const std::map<std::string, std::vector<double>>& values,
                                                 std::string* error) const;

 private:
  package::Package package_;
};

}  // namespace facet::runtime
