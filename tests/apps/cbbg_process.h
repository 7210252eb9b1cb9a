#pragma once
// Runs the real `cbbg` binary (CBBG_BINARY) as a user would, for the command's tests.

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace cbbg::testing {

struct Outcome {
  int exit_code;       // -1 when it did not exit normally
  std::string output;  // stdout and stderr together
};

// Runs `cbbg ARGUMENTS` through the shell (so quoting works), with `environment` ("NAME=value
// ...", may be empty) before it, and waits for it.
inline Outcome cbbg(const std::string& arguments, const std::string& environment = "") {
  const std::string command =
      environment + " " + std::string(CBBG_BINARY) + " " + arguments + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string output;
  std::array<char, 4096> buffer{};
  while (const std::size_t read = fread(buffer.data(), 1, buffer.size(), pipe)) {
    output.append(buffer.data(), read);
  }
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

// Starts `cbbg` with `arguments` (split on spaces) without waiting; returns its pid.
inline pid_t start_cbbg(const std::string& arguments) {
  std::vector<std::string> words{CBBG_BINARY};
  std::istringstream split(arguments);
  for (std::string word; split >> word;) words.push_back(word);
  const pid_t pid = fork();
  if (pid == 0) {
    std::vector<char*> argv;
    for (auto& word : words) argv.push_back(word.data());
    argv.push_back(nullptr);
    if (freopen("/dev/null", "w", stdout) == nullptr ||
        freopen("/dev/null", "w", stderr) == nullptr) {
      _exit(126);
    }
    execv(argv[0], argv.data());
    _exit(127);
  }
  return pid;
}

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every file below `root` (relative path -> bytes), every directory (path -> "<dir>") and
// every FIFO, socket or device (path -> "<special>").
inline std::map<std::string, std::string> tree_of(const std::filesystem::path& root) {
  std::map<std::string, std::string> tree;
  std::error_code error;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root, error)) {
    const std::string name = std::filesystem::relative(entry.path(), root).string();
    // A FIFO or a device is named, never opened (reading a FIFO would block).
    tree[name] = entry.is_directory()      ? "<dir>"
                 : entry.is_regular_file() ? read_file(entry.path())
                                           : "<special>";
  }
  return tree;
}

}  // namespace cbbg::testing
