#pragma once
// A sweep: a grid of config values, the cartesian product of a few keys' values, each grid
// point running the configured experiment over its arms and seeds. Axes come from
// `cbbg run --grid KEY=V1,V2,...` and from the `sweep:` section of a config file
// (`sweep: {actor.alpha: [0.1, 0.2]}`); values are YAML, as --set takes them.

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "cbbg/config/config.h"

namespace cbbg::config {

struct SweepAxis {
  std::string key;
  std::vector<std::string> values;  // each one YAML text, as --set takes it
  std::string source;               // "--grid KEY=..." or "FILE: sweep.KEY", for messages
};

class Sweep {
 public:
  // "KEY=V1,V2,...": values split at commas outside brackets ([1, 2] is one value).
  void add_flag(std::string_view assignment);
  // The `sweep:` section of a YAML document, if it has one.
  void add_yaml(const std::string& text, const std::string& source);
  void add_file(const std::filesystem::path& path);

  bool empty() const { return axes_.empty(); }
  const std::vector<SweepAxis>& axes() const { return axes_; }
  // Grid points: the product of the axes' sizes, the first axis slowest; 1 without axes.
  std::size_t points() const;
  // The values of grid point `point`, one per axis.
  std::vector<std::string> values(std::size_t point) const;
  // `base` with point `point`'s values set; throws ConfigError naming the axis's source.
  Config config(const Config& base, std::size_t point) const;
  // Sets every value of every axis on `base` (each alone), so a bad value fails before
  // anything runs.
  void check(const Config& base) const;
  // "sweep:\n  KEY: [V1, V2]\n" (empty without axes): what config.yaml adds.
  std::string to_yaml() const;

 private:
  void add_axis(SweepAxis axis);

  std::vector<SweepAxis> axes_;
};

// At most this many grid points: a sweep larger than this is a typing slip.
inline constexpr std::size_t kMaxSweepPoints = 10000;

}  // namespace cbbg::config
