// What a loader checks before a driver sees a package the app did not build (docs/security.md,
// "What a package can and cannot do"): the tables' meaning and whether this runtime can draw
// them, then, per variant, each shader's code: its kind, SPIR-V validated (SPIRV-Tools) and
// reflected (SPIRV-Cross), and its interface against the package's (program_interface.h). One
// implementation for both callers: the runtime core (LoadedMaterial) before any backend sees the
// code, and `matc info`, which says whether an app would draw a package without linking a
// renderer. None of these needs a GPU.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "facet/package/package_reader.h"
#include "facet/package/program_interface.h"

namespace facet::package {

// A texture the compiler generates (section TEXS) that the runtime binds: its name, its binding
// (shader_abi.h) and the shape the shaders address it with.
struct GeneratedTextureSlot {
  const char* name;
  uint32_t binding;
  uint32_t width, height;
};
// nullptr for a texture the runtime has no slot for.
const GeneratedTextureSlot* generatedTextureSlot(const std::string& name);
// What a variant that samples such a texture is told.
std::string unknownTextureError(const std::string& material, const std::string& variantKey, const std::string& texture);

// "" when an app can load the package read by `reader`: the tables' meaning (semanticError), an
// environment of the form this runtime binds, generated textures of the shape the shaders
// address. Else why not, without the package's name.
std::string loadError(const PackageReader& reader);

// What the draws of reader.variants()[variant] bind, from the package's tables.
std::optional<ProgramInterface> variantInterface(const PackageReader& reader, size_t variant, std::string* error);

// The code of one variant for the runtime's APIs (Metal is not one: its code stays compressed),
// each shader checked and each SPIR-V stage's interface held against the package's.
struct CheckedVariant {
  std::vector<uint32_t> vertexSpirv, fragmentSpirv;
  std::string vertexGlslEs, fragmentGlslEs;
  ProgramInterface interface;
};
std::optional<CheckedVariant> checkVariant(const PackageReader& reader, size_t variant, std::string* error);
// checkVariant on every variant; false with the first variant's error.
bool checkEveryVariant(const PackageReader& reader, std::string* error);

}  // namespace facet::package
