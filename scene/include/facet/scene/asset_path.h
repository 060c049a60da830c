// Where a file named by an untrusted input (a scene's images and meshes, a glTF file's buffers)
// really lies, and whether that is inside the folder the input may read from. One rule for every
// such file, so that a symbolic link or a `..` cannot lead out, and so that a path outside the
// folder gets the same answer whether or not its file exists (an error that told them apart
// would let a scene probe the machine's files).
#pragma once

#include <filesystem>

namespace facet::scene {

// `path` made absolute with every symbolic link resolved, dangling ones included, and `..`
// applied after the link before it (as the kernel does); components that do not exist are taken
// as written (`realpath -m`). "" when the file system refuses or the links loop (more than 40,
// the kernel's own limit).
std::filesystem::path realPath(const std::filesystem::path& path);

// Whether `real` is `root` or lies below it, both realPath results ("" is inside nothing).
bool isInside(const std::filesystem::path& root, const std::filesystem::path& real);

}  // namespace facet::scene
