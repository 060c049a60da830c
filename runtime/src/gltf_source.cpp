#include "gltf_source.h"

#include <deque>
#include <filesystem>
#include <fstream>
#include <span>
#include <vector>

#include "facet/runtime/gltf_mesh.h"
#include "facet/scene/asset_path.h"
#include "facet/scene/json_document.h"
#include "gltf_document.h"
#include "gltf_glb.h"
#include "gltf_model_cost.h"

namespace facet::runtime::gltf {
namespace {

namespace fs = std::filesystem;

// Reads the files of one glTF load: regular files only (a FIFO or a device would block or never
// end), each size checked against what is left of the allowance before anything is allocated.
class BoundedReader {
 public:
  explicit BoundedReader(uint64_t allowance) : allowance_(allowance) {}

  // `expected`: the size the file must have, when the glTF declares one. *why: the reason,
  // after the file's name.
  bool read(const fs::path& path, std::optional<uint64_t> expected, std::vector<unsigned char>* out, std::string* why) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) {
      *why = "does not exist";
      return false;
    }
    if (!fs::is_regular_file(status)) {
      *why = "is not a regular file";
      return false;
    }
    const uintmax_t size = fs::file_size(path, ec);
    if (ec) {
      *why = "cannot be read: " + ec.message();
      return false;
    }
    if (size > allowance_ - used_) {
      *why = "is " + std::to_string(size) + " bytes; with the " + std::to_string(used_) +
             " read before it, more than the " + std::to_string(allowance_) +
             " bytes left for glTF files (a scene's glTF files and their buffers take at most " +
             std::to_string(GltfBudget::kMaxFileBytes >> 20) + " MiB together)";
      return false;
    }
    if (expected && size != *expected) {
      *why = "holds " + std::to_string(size) + " bytes, but its byteLength is " + std::to_string(*expected);
      return false;
    }
    std::ifstream in(path, std::ios::binary);
    out->resize(size_t(size));
    if (!in.read(reinterpret_cast<char*>(out->data()), std::streamsize(size)) || in.peek() != EOF) {
      *why = "could not be read whole";
      return false;
    }
    used_ += size;
    return true;
  }

  uint64_t used() const { return used_; }

 private:
  uint64_t allowance_;
  uint64_t used_ = 0;
};

// The path tinygltf 2.7 asks its ReadWholeFile callback for: the base folder joined with the URI
// decoded its way (dlib::urldecode: '+' is a space, %XX a byte). Only compared, to hand each
// buffer the bytes read for it.
std::string tinygltfPath(const std::string& folder, const std::string& uri) {
  std::string decoded;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '+') {
      decoded += ' ';
    } else if (uri[i] == '%' && uri.size() > i + 2) {
      decoded += char(std::stoi(uri.substr(i + 1, 2), nullptr, 16));  // checkDocument checked the digits
      i += 2;
    } else {
      decoded += uri[i];
    }
  }
  return folder.empty() || folder.back() == '/' ? folder + decoded : folder + "/" + decoded;
}

// The buffer files, read before tinygltf runs, handed over in the order it asks for them:
// buffers in order. Images come after them and get nothing: they are not part of a mesh.
struct PreparedFiles {
  struct File {
    std::string requested;  // tinygltfPath
    std::vector<unsigned char> bytes;
  };
  std::deque<File> buffers;
};

// tinygltf asks whether a file exists before reading it, and tries the current directory when
// it does not: every file it may read has been read already, so the answer is yes and the read
// (from memory) decides.
bool fileExists(const std::string&, void*) { return true; }

std::string expandPath(const std::string& path, void*) { return path; }  // no ~ or $VAR expansion

bool readPreparedFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  auto* files = static_cast<PreparedFiles*>(user);
  if (files->buffers.empty() || files->buffers.front().requested != path) {
    if (err) *err += "not read (only the buffers' files are)\n";
    return false;
  }
  *out = std::move(files->buffers.front().bytes);
  files->buffers.pop_front();
  return true;
}

bool writeWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err += "writing is not allowed\n";
  return false;
}

// Images are not part of a mesh: not decoded at all.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;
}

// An embedded image's encoded bytes, kept as they are (the image decoders check them when a
// scene loads them); their size is bounded by the file's, read within the budget.
bool keepImage(tinygltf::Image* image, const int, std::string*, std::string*, int, int, const unsigned char* bytes,
               int size, void*) {
  if (size > 0) image->image.assign(bytes, bytes + size);
  image->as_is = true;
  return true;
}

// tinygltf's error, on one line and short: it quotes names from the file in full (an image's name
// of megabytes) and ends each of its messages with a newline.
std::string tinygltfMessage(const std::string& err) {
  constexpr size_t kShown = 400;
  std::string out;
  for (size_t i = 0; i < err.size() && out.size() < kShown; ++i) {
    const unsigned char c = static_cast<unsigned char>(err[i]);
    if (c == '\n')
      out += i + 1 < err.size() ? "; " : "";
    else if (c < 0x20)
      out += ' ';
    else
      out += char(c);
  }
  if (out.size() >= kShown) out += "...(" + std::to_string(err.size()) + " bytes)";
  return out.empty() ? "not a valid glTF 2.0 file" : out;
}

// The JSON's depth, then what tinygltf would build from it, then its syntax (strictly: a key
// given twice is an error, as in every JSON file Facet reads); then the checks tinygltf lacks.
// For a .glb, lines and columns are those of the JSON chunk, and messages say so.
std::optional<std::vector<ExternalBuffer>> checkJson(const std::string& path, std::string_view text,
                                                     std::optional<size_t> glbOffset, std::string* error) {
  const std::string chunk = glbOffset ? "in the JSON chunk at byte " + std::to_string(*glbOffset) + ": " : "";
  if (std::optional<size_t> at = scene::jsonTooDeepAt(text)) {
    *error = path + ":" + scene::jsonLineColumn(text, *at) + ": error: " + chunk +
             "arrays and objects nest more than " + std::to_string(scene::kMaxJsonDepth) +
             " deep here (Facet reads JSON at most that deep)";
    return std::nullopt;
  }
  const ModelCost cost = estimateModelCost(text);
  if (cost.bytes > kMaxModelBytes) {
    *error = path + ": error: " + (cost.largest.empty() ? "/" : cost.largest) + ": " + chunk +
             "the JSON would take more than " + std::to_string(kMaxModelBytes >> 20) +
             " MiB once read into the glTF model (its elements are far larger in memory than in the file)";
    return std::nullopt;
  }
  std::optional<nlohmann::json> document = scene::parseJsonDocument(path, std::string(text), error);
  if (!document) {
    if (const size_t at = error->find(": error: "); glbOffset && at != std::string::npos) error->insert(at + 9, chunk);
    return std::nullopt;
  }
  std::string why;
  auto external = checkDocument(*document, glbOffset.has_value(), &why);
  if (!external) *error = path + ": error: " + why;
  return external;
}

}  // namespace

std::optional<tinygltf::Model> readSource(const std::string& path, const SourceOptions& options, uint64_t* bytesRead,
                                          std::string* error) {
  const bool binary = fs::path(path).extension() == ".glb";
  BoundedReader reader(options.fileBytes);
  std::vector<unsigned char> bytes;
  std::string why;
  if (!reader.read(path, std::nullopt, &bytes, &why)) {
    *error = path + ": error: the glTF file " + why;
    return std::nullopt;
  }
  std::string_view json(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  std::optional<size_t> glbOffset;
  if (binary) {
    auto chunks = readGlbContainer(bytes, &why);
    if (!chunks) {
      *error = path + ": error: " + why;
      return std::nullopt;
    }
    json = chunks->json;
    glbOffset = chunks->jsonOffset;
  }
  auto external = checkJson(path, json, glbOffset, error);
  if (!external) return std::nullopt;

  // Buffers are found from the file's real folder and must lie in the asset root, both real
  // paths (symbolic links followed): a link inside cannot lead out. Whether the file outside
  // exists is not said.
  const fs::path folder = scene::realPath(path).parent_path();
  const fs::path root = options.assetRoot.empty() ? folder : scene::realPath(options.assetRoot);
  PreparedFiles files;
  for (const ExternalBuffer& buffer : *external) {
    const fs::path real = scene::realPath(folder / buffer.path);
    if (!scene::isInside(root, real)) {
      *error = path + ": error: " + buffer.pointer + ": '" + scene::shownValue(buffer.uri) +
               "' is outside the folder this glTF file may read buffers from (" + root.string() + ")";
      return std::nullopt;
    }
    PreparedFiles::File file{tinygltfPath(folder.string(), buffer.uri), {}};
    if (!reader.read(real, buffer.byteLength, &file.bytes, &why)) {
      *error = path + ": error: " + buffer.pointer + ": '" + scene::shownValue(buffer.uri) + "' " + why;
      return std::nullopt;
    }
    files.buffers.push_back(std::move(file));
  }

  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks({fileExists, expandPath, readPreparedFile, writeWholeFile, &files});
  loader.SetImageLoader(options.keepImageBytes ? keepImage : skipImage, nullptr);
  tinygltf::Model model;
  std::string err, warn;
  const bool loaded =
      binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), folder.string())
             : loader.LoadASCIIFromString(&model, &err, &warn, json.data(), unsigned(json.size()), folder.string());
  if (!loaded) {
    *error = path + ": error: " + tinygltfMessage(err);
    return std::nullopt;
  }
  *bytesRead = reader.used();
  return model;
}

}  // namespace facet::runtime::gltf
