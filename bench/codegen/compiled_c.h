#pragma once
// What the export benchmarks share: a C source pair compiled by gcc -O2 into a shared object
// of its own and loaded, its code and data bytes read from the object, and the measured
// signals each call is fed.

#include <dlfcn.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cbbg/blocks/normaliser.h"
#include "cbbg/codegen/c_export.h"
#include "cbbg/framework/types.h"

namespace cbbg::bench {

// What the features see for 49, 343 and 2401 features.
inline blocks::NormalisedInputs inputs_for(int features) {
  return features == 49    ? blocks::NormalisedInputs::kPitch
         : features == 343 ? blocks::NormalisedInputs::kPitchWheelRate
                           : blocks::NormalisedInputs::kPitchWheels;
}

// A measured state that moves a little each call, within the grid and the failure angle.
inline void next_measured(Vector& measured, long call) {
  const double s = std::sin(1e-3 * static_cast<double>(call));
  measured << 0.1 * s, 0.2 * s, 0.5 * s, 0.5 * s, 1.0 * s, 1.0 * s;
}

// The baseline of benchmark `name` when it is one of `exported`'s: `baseline`'s of the same
// feature count (EXPORTED/features:49/float:0 against BASELINE/49); empty otherwise.
inline std::string baseline_by_features(const std::string& name, const std::string& exported,
                                        const std::string& baseline) {
  const auto at = name.find("features:");
  if (name.rfind(exported, 0) != 0 || at == std::string::npos) return std::string();
  return baseline + "/" + name.substr(at + 9, name.find('/', at) - at - 9);
}

// `sources` (NAME.h, NAME.c) and `more` other C files, compiled by gcc -O2 in a directory of
// their own (removed at the end) into a shared object, loaded.
class CompiledC {
 public:
  CompiledC(const std::string& tag, const std::string& name, const codegen::CSources& sources,
            const std::vector<std::pair<std::string, std::string>>& more = {})
      : directory_(std::filesystem::temp_directory_path() /
                   ("cbbg-bench-" + tag + "-" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(directory_);
    std::ofstream(directory_ / (name + ".h")) << sources.header;
    std::ofstream(directory_ / (name + ".c")) << sources.source;
    std::string files = (directory_ / (name + ".c")).string();
    for (const auto& [file, text] : more) {
      std::ofstream(directory_ / file) << text;
      files += ' ';  // piecewise: GCC 12 warns falsely (-Wrestrict) on " " + ...
      files += (directory_ / file).string();
    }
    const std::string object = (directory_ / (name + ".o")).string();
    shell("gcc -std=c99 -O2 -c " + (directory_ / (name + ".c")).string() + " -o " + object);
    read_sizes(object);
    const std::string library = (directory_ / (name + ".so")).string();
    shell("gcc -std=c99 -O2 -shared -fPIC " + files + " -lm -o " + library);
    library_ = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (library_ == nullptr) throw std::runtime_error(dlerror());
  }
  ~CompiledC() {
    if (library_ != nullptr) dlclose(library_);
    std::filesystem::remove_all(directory_);
  }
  CompiledC(const CompiledC&) = delete;
  CompiledC& operator=(const CompiledC&) = delete;

  template <typename Function>
  Function function(const char* symbol) const {
    void* address = dlsym(library_, symbol);
    if (address == nullptr) throw std::runtime_error(std::string("no symbol ") + symbol);
    return reinterpret_cast<Function>(address);
  }

  long code_bytes = 0;  // .text of NAME.o
  long data_bytes = 0;  // .rodata and .data of NAME.o

 private:
  static void shell(const std::string& command) {
    if (std::system(command.c_str()) != 0) throw std::runtime_error("failed: " + command);
  }
  void read_sizes(const std::string& object) {
    FILE* pipe = popen(("size -A -d " + object).c_str(), "r");
    char section[128];
    long bytes = 0;
    char line[256];
    while (fgets(line, sizeof line, pipe) != nullptr) {
      if (std::sscanf(line, "%127s %ld", section, &bytes) != 2) continue;
      const std::string name = section;
      if (name == ".text") code_bytes += bytes;
      if (name.rfind(".rodata", 0) == 0 || name == ".data") data_bytes += bytes;
    }
    pclose(pipe);
  }

  std::filesystem::path directory_;
  void* library_ = nullptr;
};

}  // namespace cbbg::bench
