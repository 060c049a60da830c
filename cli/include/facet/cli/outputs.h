// The one rule for the files every command of matc and facet-eval writes: an output is never one
// of the command's inputs and never another of its outputs, and its outputs land together.
// Commands list what they read and write and call these before writing anything.
#pragma once

#include <string>
#include <vector>

#include "facet/package/package.h"

namespace facet::cli {

// A file as the user gave it; `role` names the argument in messages ("-o", "--depfile", "the
// input material", "the --config file").
struct NamedFile {
  std::string role;
  std::string path;
};

// False, after printing the two arguments, when an output is an input or another output. Files
// are compared by device and inode, so another spelling of the path, a symbolic link or a hard
// link is caught; an output that does not exist yet is compared by the nearest folder above it
// that exists and the names below that folder.
bool outputsSpareInputs(const std::vector<NamedFile>& inputs, const std::vector<NamedFile>& outputs);

// Creates `folders` ("" stands for none), then package::writeFiles: every output to its temporary
// file, then the renames, so a failure before the renames leaves no output changed. False after
// printing the error.
bool writeOutputs(const std::vector<std::string>& folders, const std::vector<package::OutputFile>& files);

}  // namespace facet::cli
