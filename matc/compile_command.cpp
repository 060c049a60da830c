#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "commands.h"
#include "facet/compiler/build.h"
#include "facet/ir/check.h"
#include "facet/ir/lexer.h"
#include "facet/package.h"

namespace facet::matc {

void printError(const std::string& message) { std::fprintf(stderr, "matc: error: %s\n", message.c_str()); }

namespace {

namespace fs = std::filesystem;

// Reads a material file, refusing files over the language's size limit before reading them.
bool readSource(const std::string& path, ir::SourceFile* out) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    printError("cannot read '" + path + "': " + (fs::exists(path, ec) ? "not a regular file" : "no such file"));
    return false;
  }
  uintmax_t size = fs::file_size(path, ec);
  if (ec || size > ir::kMaxSourceBytes) {
    printError("'" + path + "' is " + std::to_string(size) + " bytes; material files are limited to " +
               std::to_string(ir::kMaxSourceBytes) + " bytes");
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) {
    printError("cannot read '" + path + "'");
    return false;
  }
  out->path = path;
  out->text = text.str();
  return true;
}

bool writeSources(const std::string& dir, const std::vector<compiler::GeneratedFile>& files) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) {
    printError("cannot create '" + dir + "': " + ec.message());
    return false;
  }
  for (const compiler::GeneratedFile& f : files) {
    std::vector<uint8_t> bytes(f.text.begin(), f.text.end());
    std::string error;
    if (!package::writeFile((fs::path(dir) / f.name).string(), bytes, &error)) {
      printError(error);
      return false;
    }
  }
  return true;
}

}  // namespace

int compileCommand(const CompileArgs& args) {
  ir::SourceFile source;
  if (!readSource(args.input, &source)) return 1;

  ir::Diagnostics diags(source);
  std::optional<ir::Material> material = ir::compileSource(source, diags);
  std::fputs(diags.format().c_str(), stderr);
  if (!material) {
    std::fprintf(stderr, "%zu error%s generated.\n", diags.errorCount(), diags.errorCount() == 1 ? "" : "s");
    return 1;
  }

  compiler::BuildError buildError;
  std::optional<compiler::BuildResult> built = compiler::buildMaterial(*material, {}, &buildError);
  if (!built) {
    if (buildError.loc) {
      std::fputs(ir::formatDiagnostic(source, {ir::Severity::Error, *buildError.loc, buildError.message, "backend"}).c_str(),
                 stderr);
    } else {
      printError(buildError.message);
    }
    return 1;
  }
  std::string error;
  std::string output = args.output;
  if (output.empty()) output = fs::path(args.input).replace_extension(".matpkg").string();
  std::vector<uint8_t> bytes = package::write(built->package);
  if (!package::writeFile(output, bytes, &error)) {
    printError(error);
    return 1;
  }
  if (!args.emitSource.empty() && !writeSources(args.emitSource, built->sources)) return 1;
  std::printf("%s: %zu variant%s, %zu bytes -> %s\n", material->name.c_str(), built->package.variants.size(),
              built->package.variants.size() == 1 ? "" : "s", bytes.size(), output.c_str());
  return 0;
}

}  // namespace facet::matc
