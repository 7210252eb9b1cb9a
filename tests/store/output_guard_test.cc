// The output discipline (store/output_guard.h): temporaries known and cleaned, a user's files
// and non-regular files refused with their path, manifests that survive a reread; and the
// task folder's own files told from a user's (store/task_store.h).

#include "cbbg/store/output_guard.h"

#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/config/config.h"
#include "cbbg/store/files.h"
#include "cbbg/store/task_store.h"
#include "tests/support/scratch_directory.h"

namespace cbbg::store {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

void touch(const fs::path& path, const std::string& text = "x") {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

std::string host() {
  char name[256] = {};
  ::gethostname(name, sizeof name - 1);
  return name;
}

TEST(OutputGuard, TemporariesAreKnownByTheirTagAndTheOldPattern) {
  EXPECT_TRUE(is_temporary(temporary_beside("dir/summary.json")));
  EXPECT_THAT(temporary_beside("dir/summary.json").string(),
              ::testing::StartsWith("dir/.summary.json.cbbg-tmp-" + host() + "-"));
  EXPECT_NE(temporary_beside("a"), temporary_beside("a"));
  EXPECT_TRUE(is_temporary("trials.csv.tmp-4242-7"));
  EXPECT_TRUE(is_temporary(".figures.cbbg-tmp-node-1-0"));
  for (const char* name : {"notes.tmp", "trials.csv", "x.tmp-a-1", "x.tmp-1", ".tmp-1-2", "tmp"}) {
    EXPECT_FALSE(is_temporary(name)) << name;
  }
}

TEST(OutputGuard, OnlyTheTemporariesOfAGoneWriterOnThisHostAreStale) {
  const std::string mine = std::to_string(::getpid());
  EXPECT_FALSE(is_stale_temporary(".a.cbbg-tmp-" + host() + "-" + mine + "-0"));  // alive
  EXPECT_TRUE(is_stale_temporary(".a.cbbg-tmp-" + host() + "-999999999-0"));      // gone
  EXPECT_FALSE(is_stale_temporary(".a.cbbg-tmp-other-host-999999999-0"));         // elsewhere
  EXPECT_FALSE(is_stale_temporary("a.json"));
}

TEST(OutputGuard, ATemporaryWhosePidAnotherProcessHasTakenIsStale) {
  // The name holds the writer's pid and start time (/proc/PID/stat, field 22): a killed
  // writer's pid taken by a newer process has another start.
  const std::string name = temporary_beside("x").filename().string();
  const std::string mine = std::to_string(::getpid()) + ".";
  ASSERT_NE(name.find("-" + mine), std::string::npos) << name;
  EXPECT_FALSE(is_stale_temporary(name));  // this process, which runs
  const std::string start = name.substr(name.find("-" + mine) + 1 + mine.size());
  const std::string other_start =
      ".x.cbbg-tmp-" + host() + "-" + mine + std::to_string(std::stoll(start) + 1) + "-0";
  EXPECT_TRUE(is_stale_temporary(other_start));  // the same pid, another process
}

TEST(OutputGuard, AZombiesTemporaryIsStale) {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ASSERT_GT(child, 0);
  // Until it is reaped, the child is a zombie: kill(pid, 0) still succeeds.
  while (true) {
    std::ifstream stat("/proc/" + std::to_string(child) + "/stat");
    std::string text;
    std::getline(stat, text);
    if (text.find(") Z ") != std::string::npos) break;
  }
  EXPECT_TRUE(is_stale_temporary(".x.cbbg-tmp-" + host() + "-" + std::to_string(child) + "-0"));
  ::waitpid(child, nullptr, 0);
}

TEST(OutputGuard, RemovesItsTemporariesAndNothingElse) {
  testing::ScratchDirectory scratch;
  const fs::path root = scratch.path();
  touch(root / "summary.json");
  touch(root / ".summary.json.cbbg-tmp-h-1-0");
  touch(root / "tasks" / "001" / "0.run.tmp-12-3");
  touch(root / ".figures.cbbg-tmp-h-1-0" / "failures.png");
  touch(root / "tasks" / "001" /
        (".0.run.cbbg-tmp-" + host() + "-" + std::to_string(::getpid()) + "-0"));
  touch(root / "notes.tmp");
  EXPECT_EQ(find_temporary(root).has_value(), true);
  // Only stale ones while others may write: this process's own temporary stays.
  EXPECT_EQ(remove_temporaries(root, Leftovers::kStale), 1);  // the old pattern
  EXPECT_EQ(remove_temporaries(root), 3);
  EXPECT_FALSE(find_temporary(root).has_value());
  EXPECT_TRUE(fs::exists(root / "summary.json"));
  EXPECT_TRUE(fs::exists(root / "notes.tmp"));
  EXPECT_NO_THROW(refuse_temporaries(root));
  touch(root / "weights" / ".a.txt.cbbg-tmp-h-1-0");
  EXPECT_THAT([&] { refuse_temporaries(root); },
              ThrowsMessage<std::runtime_error>(HasSubstr("not publishing '" + root.string() +
                                                          "': it holds '" + root.string() +
                                                          "/weights/.a.txt.cbbg-tmp-h-1-0'")));
}

TEST(OutputGuard, RemovesOnlyStaleStagingBesideAPath) {
  testing::ScratchDirectory scratch;
  const fs::path work = scratch.path() / "out.partial";
  const fs::path gone = scratch.path() / (".out.partial.cbbg-tmp-" + host() + "-999999999-0");
  const fs::path live = scratch.path() / (".out.partial.cbbg-tmp-" + host() + "-" +
                                          std::to_string(::getpid()) + "-0");
  const fs::path other = scratch.path() / ".other.partial.cbbg-tmp-h-999999999-0";
  for (const fs::path& folder : {gone, live, other}) fs::create_directories(folder / "tasks");
  remove_stale_staging(work);
  EXPECT_FALSE(fs::exists(gone));
  EXPECT_TRUE(fs::exists(live));
  EXPECT_TRUE(fs::exists(other));
  // A relative path looks beside itself in the working directory.
  fs::create_directories(gone);
  const fs::path here = fs::current_path();
  fs::current_path(scratch.path());
  remove_stale_staging("out.partial");
  fs::current_path(here);
  EXPECT_FALSE(fs::exists(gone));
}

TEST(OutputGuard, ReplacesOnlyAFileThatCarriesItsTag) {
  testing::ScratchDirectory scratch;
  const fs::path own = scratch.path() / "w.txt";
  const fs::path users = scratch.path() / "mine.txt";
  touch(own, "cbbg-weights 1\n...");
  touch(users, "my weights");
  EXPECT_NO_THROW(check_replaceable_file(own, "--save-weights", "cbbg-weights"));
  EXPECT_NO_THROW(check_replaceable_file(scratch.path() / "new.txt", "--save-weights", "x"));
  EXPECT_THAT([&] { check_replaceable_file(users, "--save-weights", "cbbg-weights"); },
              ThrowsMessage<config::ConfigError>("--save-weights '" + users.string() +
                                                 "' exists and cbbg did not write it; cbbg "
                                                 "never replaces a file of yours: give a new "
                                                 "path"));
}

TEST(OutputGuard, RefusesEveryKindOfNonRegularTargetWithoutOpeningIt) {
  testing::ScratchDirectory scratch;
  const fs::path fifo = scratch.path() / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  const fs::path socket_path = scratch.path() / "sock";
  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  socket_path.string().copy(address.sun_path, sizeof address.sun_path - 1);
  ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  const std::pair<fs::path, std::string> cases[] = {{fifo, "a FIFO"},
                                                    {socket_path, "a socket"},
                                                    {"/dev/null", "a device"},
                                                    {scratch.path(), "a directory"}};
  for (const auto& [path, kind] : cases) {
    EXPECT_EQ(non_regular_kind(path), kind);
    // Reading a FIFO would block here forever; the tag check must not open it.
    EXPECT_FALSE(carries_tag(path, "x"));
    EXPECT_THAT([&] { check_replaceable_file(path, "-o", "x"); },
                ThrowsMessage<config::ConfigError>("-o " + quoted_path(path) + " is " + kind +
                                                   "; give a regular file's path"));
  }
  ::close(fd);
}

TEST(OutputGuard, AManifestListsWhatCbbgWroteAndRefusesTheRest) {
  testing::ScratchDirectory scratch;
  const fs::path figures = scratch.path() / "figures";
  fs::create_directories(figures);
  touch(figures / "notes.txt");
  touch(figures / "failures.png");
  Manifest manifest(figures);
  EXPECT_TRUE(manifest.names().empty());
  EXPECT_THAT(
      [&] {
        manifest.check_writable({"diagram.svg", "failures.png"}, "cbbg plot");
      },
      ThrowsMessage<config::ConfigError>(
          "cbbg plot: '" + (figures / "failures.png").string() +
          "' exists and cbbg did not write it; cbbg never replaces a file of yours: "
          "move it away"));
  manifest.add({"failures.png", "diagram.svg"});
  manifest.add({"failures.png"});
  const Manifest reread(figures);
  EXPECT_EQ(reread.names(), (std::vector<std::string>{"failures.png", "diagram.svg"}));
  EXPECT_NO_THROW(reread.check_writable({"failures.png", "diagram.svg", "new.png"}, "x"));
  EXPECT_THROW(reread.check_writable({"notes.txt"}, "x"), config::ConfigError);
  EXPECT_EQ(read_text(figures / kManifestFile), "cbbg-written 1\nfailures.png\ndiagram.svg\n");
  // A file named like a manifest but not one is no manifest: nothing is cbbg's.
  touch(figures / kManifestFile, "my list\nnotes.txt\n");
  EXPECT_TRUE(Manifest(figures).names().empty());
}

TEST(TaskFiles, AUsersFileAmongTheTasksIsNamedAndKept) {
  testing::ScratchDirectory scratch;
  const fs::path tasks = scratch.path() / "tasks";
  for (const char* name : {"001/0.run", "001/0.steps.csv", "001/1.steps.csv.pending",
                           "001/0.weights.txt", "002/.3.run.cbbg-tmp-h-1-0", "4.run"}) {
    touch(tasks / name);
  }
  EXPECT_NO_THROW(check_own_tasks(tasks));
  touch(tasks / "002" / "notes.txt", "mine");
  EXPECT_THAT(
      [&] { check_own_tasks(tasks); },
      ThrowsMessage<config::ConfigError>(HasSubstr("'" + (tasks / "002" / "notes.txt").string() +
                                                   "' is not a task file of cbbg's")));
  remove_own_tasks(tasks);
  EXPECT_FALSE(fs::exists(tasks / "001"));
  EXPECT_EQ(read_text(tasks / "002" / "notes.txt"), "mine");
  EXPECT_FALSE(fs::exists(tasks / "4.run"));
  fs::remove(tasks / "002" / "notes.txt");
  remove_own_tasks(tasks);
  EXPECT_FALSE(fs::exists(tasks));
}

}  // namespace
}  // namespace cbbg::store
