// Outputs appear whole or not at all: no partial file on failure or interrupt, no write through
// a device node or FIFO (facet/atomic_file.h).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "facet/atomic_file.h"
#include "facet/package.h"

namespace {

namespace fs = std::filesystem;

std::string freshDir(const std::string& name) {
  fs::path dir = fs::path(FACET_BINARY_DIR) / "test-scratch" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::vector<std::string> entries(const std::string& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST(AtomicFile, CommitReplacesTheDestinationAndLeavesNoTemporary) {
  std::string dir = freshDir("atomic-commit");
  std::string path = dir + "/out.bin";
  std::ofstream(path) << "old";
  std::string error;
  std::vector<uint8_t> bytes{1, 2, 3};
  ASSERT_TRUE(facet::package::writeFile(path, bytes, &error)) << error;
  EXPECT_EQ(fs::file_size(path), 3u);
  EXPECT_EQ(entries(dir), std::vector<std::string>{"out.bin"});
}

TEST(AtomicFile, AbandonedWriteLeavesNeitherTheFileNorATemporary) {
  std::string dir = freshDir("atomic-abandon");
  std::string error;
  {
    facet::AtomicFile file;
    ASSERT_TRUE(file.open(dir + "/out.bin", &error)) << error;
    std::vector<uint8_t> bytes(100, 7);
    ASSERT_TRUE(file.write(bytes, &error)) << error;
    EXPECT_TRUE(fs::exists(file.temporaryPath()));
  }  // no commit
  EXPECT_TRUE(entries(dir).empty());
}

TEST(AtomicFile, DestinationThatIsNotARegularFileIsRefused) {
  std::string dir = freshDir("atomic-special");
  std::string fifo = dir + "/pipe";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  std::string error;
  std::vector<uint8_t> bytes{1};
  EXPECT_FALSE(facet::package::writeFile(fifo, bytes, &error));
  EXPECT_EQ(error, "cannot write '" + fifo + "': it exists and is not a regular file");
  EXPECT_FALSE(facet::package::writeFile("/dev/null", bytes, &error));
  EXPECT_FALSE(facet::package::writeFile(dir, bytes, &error));
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_EQ(entries(dir), std::vector<std::string>{"pipe"});
}

// A real SIGTERM arrives while the temporary file is open: the handler removes it and the
// process still ends by that signal.
TEST(AtomicFile, SignalDuringAWriteRemovesTheTemporaryFile) {
  std::string dir = freshDir("atomic-signal");
  std::string path = dir + "/out.bin";
  pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    facet::removeTemporaryFilesOnSignals();
    facet::AtomicFile file;
    std::string error;
    std::vector<uint8_t> bytes(4096, 1);
    if (!file.open(path, &error) || !file.write(bytes, &error)) _exit(3);
    raise(SIGTERM);
    _exit(4);  // not reached: the handler re-raises with the default action
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "exit status " << WEXITSTATUS(status);
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_TRUE(entries(dir).empty());
}
