// Outputs appear whole or not at all: no partial file on failure or interrupt, no write through
// a device node or FIFO (facet/package/atomic_file.h).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>

#include "facet/package/atomic_file.h"
#include "facet/package/package.h"
#include "test_support.h"

namespace {

namespace fs = std::filesystem;

std::string freshDir(const std::string& name) {
  fs::path dir = fs::path(facet::test::binaryDir()) / "test-scratch" / name;
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

std::string contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
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

// Several outputs of one command land together: when one cannot be written, none is replaced
// and no temporary file is left, whatever its place in the list.
TEST(AtomicFile, WriteFilesChangesNoDestinationWhenOneCannotBeWritten) {
  std::string dir = freshDir("atomic-together");
  std::string first = dir + "/first.bin", last = dir + "/last.bin";
  std::ofstream(first) << "old first";
  std::ofstream(last) << "old last";
  const std::vector<uint8_t> bytes{1, 2, 3};
  for (const std::string& unwritable : {dir + "/no-such-folder/x.bin", dir}) {
    std::string error;
    EXPECT_FALSE(facet::package::writeFiles({{first, bytes}, {unwritable, bytes}, {last, bytes}}, &error));
    EXPECT_NE(error.find("cannot write '" + unwritable + "'"), std::string::npos) << error;
    EXPECT_EQ(contents(first), "old first");
    EXPECT_EQ(contents(last), "old last");
    EXPECT_EQ(entries(dir), (std::vector<std::string>{"first.bin", "last.bin"}));
  }
  std::string error;
  ASSERT_TRUE(facet::package::writeFiles({{first, bytes}, {last, bytes}}, &error)) << error;
  EXPECT_EQ(fs::file_size(first), 3u);
  EXPECT_EQ(fs::file_size(last), 3u);
}

// An interrupt while a command holds all its outputs staged (dozens of temporary files) removes
// every one of them.
TEST(AtomicFile, SignalWithManyStagedFilesRemovesEveryTemporaryFile) {
  std::string dir = freshDir("atomic-signal-many");
  pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    facet::removeTemporaryFilesOnSignals();
    std::vector<std::unique_ptr<facet::AtomicFile>> files;
    std::string error;
    std::vector<uint8_t> bytes(16, 1);
    for (int i = 0; i < 400; ++i) {
      files.push_back(std::make_unique<facet::AtomicFile>());
      if (!files.back()->open(dir + "/out" + std::to_string(i), &error) || !files.back()->write(bytes, &error) ||
          !files.back()->finish(&error))
        _exit(3);
    }
    raise(SIGTERM);
    _exit(4);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "exit status " << WEXITSTATUS(status);
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_TRUE(entries(dir).empty()) << entries(dir).size() << " files left";
}
