// libFuzzer target: arbitrary bytes as a YAML config file, given to Config::merge_yaml.
// A bad document may only be refused with config::ConfigError, leaving the config as it was;
// any other exception, a crash, a hang or a sanitizer report is a bug.

#include <cstddef>
#include <cstdint>
#include <string>

#include "cbbg/config/config.h"
#include "tests/fuzz/config_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  cbbg::config::Config config;
  try {
    config.merge_yaml(text, "fuzz.yaml");
  } catch (const cbbg::config::ConfigError&) {
    cbbg::fuzz::require_defaults(config);
    return 0;
  }
  cbbg::fuzz::require_round_trip(config);
  return 0;
}
