#include "facet/gpu_stats/mesa_compile.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

extern char** environ;

namespace facet::gpu_stats {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// mesa_compile.py's exit code when the compilers are not built (EXIT_NOT_BUILT).
constexpr int kExitNotBuilt = 2;

std::string envOr(const char* name, const std::string& fallback) {
  const char* v = std::getenv(name);
  return v && *v ? v : fallback;
}

bool writeText(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  return bool(out);
}

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The tool's stderr on one line, its "mesa_compile: " prefix dropped.
std::string oneLine(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  while (!text.empty() && text.back() == ' ') text.pop_back();
  const std::string prefix = "mesa_compile: ";
  if (text.rfind(prefix, 0) == 0) text.erase(0, prefix.size());
  return text.size() > 400 ? text.substr(0, 400) + " ..." : text;
}

// A private folder for the pairs and the tool's output, removed with the object.
struct TempDir {
  fs::path path;
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "facet-gpu-stats-XXXXXX").string();
    if (char* made = mkdtemp(pattern.data())) path = made;
  }
  ~TempDir() {
    std::error_code ec;
    if (!path.empty()) fs::remove_all(path, ec);
  }
};

// Runs argv with stdout and stderr to files; the exit status, or -1 with *error.
int run(const std::vector<std::string>& argv, const fs::path& out, const fs::path& err, std::string* error) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  int rc = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) {
    *error = "cannot run " + argv[0] + ": " + std::strerror(rc);
    return -1;
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) {
      *error = std::string("waitpid: ") + std::strerror(errno);
      return -1;
    }
  if (!WIFEXITED(status)) {
    *error = argv[0] + " was killed by signal " + std::to_string(WTERMSIG(status));
    return -1;
  }
  return WEXITSTATUS(status);
}

template <typename T>
std::optional<T> optionalNumber(const json& j, const char* key) {
  auto it = j.find(key);
  if (it == j.end() || !it->is_number()) return std::nullopt;
  return it->get<T>();
}

StageStats stageStats(const std::string& stage, const json& j) {
  StageStats s;
  s.stage = stage;
  s.instructions = j.value("instructions", 0.0);
  s.cycles = optionalNumber<double>(j, "cycles");
  s.threads = optionalNumber<int>(j, "threads");
  s.waves = optionalNumber<int>(j, "waves");
  s.spills = optionalNumber<int>(j, "spills");
  if (auto pipes = j.find("pipes"); pipes != j.end() && pipes->is_object()) {
    double most = -1;
    for (const auto& [name, value] : pipes->items())  // sorted by name: ties resolve the same way every run
      if (value.is_number() && value.get<double>() > most) {
        most = value.get<double>();
        s.bound = name;
      }
  }
  return s;
}

// The tool's JSON for one GPU into *stats; false with stats->unavailable set when it is not that.
bool readResult(const std::string& text, GpuStats* stats) {
  json doc = json::parse(text, nullptr, false);
  const json* gpu = nullptr;
  if (!doc.is_discarded() && doc.contains("gpus") && doc["gpus"].contains(stats->gpu)) gpu = &doc["gpus"][stats->gpu];
  if (!gpu || !gpu->is_object() || !gpu->contains("shaders") || !(*gpu)["shaders"].is_object()) {
    stats->unavailable = "mesa_compile.py printed no statistics for " + stats->gpu;
    return false;
  }
  stats->renderer = gpu->value("renderer", "");
  for (const auto& [pair, stages] : (*gpu)["shaders"].items()) {
    if (!stages.is_object()) continue;
    std::vector<StageStats>& out = stats->shaders[pair];
    for (const auto& [stage, value] : stages.items())
      if (value.is_object()) out.push_back(stageStats(stage, value));
  }
  return true;
}

}  // namespace

const std::vector<std::string>& knownGpus() {
  static const std::vector<std::string> gpus = {"mali-g52", "mali-g57", "adreno-630"};
  return gpus;
}

bool parseGpuList(const std::string& text, std::vector<std::string>* gpus, std::string* error) {
  gpus->clear();
  std::stringstream in(text);
  std::string name;
  while (std::getline(in, name, ',')) {
    if (name.empty()) continue;
    const auto& known = knownGpus();
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      std::string list;
      for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
      *error = "unknown GPU '" + name + "' (known: " + list + ")";
      return false;
    }
    if (std::find(gpus->begin(), gpus->end(), name) == gpus->end()) gpus->push_back(name);
  }
  if (gpus->empty()) {
    *error = "no GPU named in '" + text + "'";
    return false;
  }
  return true;
}

const StageStats* GpuStats::find(const std::string& pair, const std::string& stage) const {
  auto it = shaders.find(pair);
  if (it == shaders.end()) return nullptr;
  for (const StageStats& s : it->second)
    if (s.stage == stage) return &s;
  return nullptr;
}

std::vector<GpuStats> measure(const std::vector<ShaderPair>& pairs, const std::vector<std::string>& gpus,
                              const MesaTool& tool) {
  std::vector<GpuStats> out;
  for (const std::string& gpu : gpus) out.push_back(GpuStats{gpu, "", "", {}});
  auto allUnavailable = [&](const std::string& why) {
    for (GpuStats& g : out) g.unavailable = why;
    return out;
  };
  const std::string python = tool.python.empty() ? "python3" : tool.python;
  const std::string script =
      !tool.script.empty()
          ? tool.script
          : envOr("FACET_MESA_COMPILE", std::string(FACET_SOURCE_DIR) + "/tools/mesa_stats/mesa_compile.py");
  std::error_code ec;
  if (!fs::is_regular_file(script, ec))
    return allUnavailable("no mesa_compile.py at " + script + " (set FACET_MESA_COMPILE to its path)");

  TempDir dir;
  if (dir.path.empty()) return allUnavailable(std::string("cannot create a temporary folder: ") + std::strerror(errno));
  json list = json::array();
  for (size_t i = 0; i < pairs.size(); ++i) {
    fs::path vertexPath = dir.path / (std::to_string(i) + ".vert"),
             fragmentPath = dir.path / (std::to_string(i) + ".frag");
    if (!writeText(vertexPath, pairs[i].vertexGlsl) || !writeText(fragmentPath, pairs[i].fragmentGlsl))
      return allUnavailable("cannot write the shaders to " + dir.path.string());
    list.push_back({{"name", pairs[i].name}, {"vertex", vertexPath.string()}, {"fragment", fragmentPath.string()}});
  }
  const fs::path listPath = dir.path / "pairs.json";
  if (!writeText(listPath, list.dump())) return allUnavailable("cannot write " + listPath.string());

  for (GpuStats& g : out) {
    std::vector<std::string> argv = {python, script, "--gpu", g.gpu};
    if (!tool.prefix.empty()) argv.insert(argv.end(), {"--prefix", tool.prefix});
    argv.push_back(listPath.string());
    const fs::path stdoutPath = dir.path / (g.gpu + ".json"), stderrPath = dir.path / (g.gpu + ".err");
    std::string error;
    int status = run(argv, stdoutPath, stderrPath, &error);
    if (status < 0) {
      g.unavailable = error;
    } else if (status == kExitNotBuilt) {
      g.unavailable = oneLine(readText(stderrPath));
    } else if (status != 0) {
      g.unavailable = "mesa_compile.py failed (exit " + std::to_string(status) + "): " + oneLine(readText(stderrPath));
    } else {
      readResult(readText(stdoutPath), &g);
    }
  }
  return out;
}

}  // namespace facet::gpu_stats
