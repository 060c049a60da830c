// How every Facet command line ends a parse: help printed, exit 0; a usage error printed, exit 2
// (the exit codes the docs promise: 1 is for input errors).
#pragma once

#include <optional>

namespace CLI {
class App;
}

namespace facet::cli {

// Parses argv into `app`. nullopt when the command is to run; else the process's exit code, with
// CLI11's help or usage error printed.
std::optional<int> parseCommandLine(CLI::App& app, int argc, char** argv);

}  // namespace facet::cli
