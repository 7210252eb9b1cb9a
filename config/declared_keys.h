#pragma once
// The config's keys made from params structs' declarations (framework/parameters.h), and the
// structs read back from a config. The config knows no section of its own: the run's tree
// (parameters/parameters.h) registers the blocks' and plants' sections, each protocol its own,
// and a user's section joins them the same way:
//
//   struct DlqrParams {
//     double q_theta = 100.0;
//     template <class Archive> void describe(Archive& a) {
//       a.number("q_theta", q_theta, "state weight on the pitch", cbbg::kNonNegative);
//     }
//   };
//   cbbg::config::register_section<DlqrParams>("dlqr");   // before any Config is made
//   ... --set dlqr.q_theta=50, --grid dlqr.q_theta=10,100, config.yaml, `cbbg list` ...
//   // below the edge, from the typed tree (parameters/parameters.h) a factory is given:
//   const DlqrParams dlqr = cbbg::config::read_section<DlqrParams>(parameters.own, "dlqr");

#include <array>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "cbbg/config/config.h"
#include "cbbg/config/own_sections.h"
#include "cbbg/framework/parameters.h"

namespace cbbg::config {

// The archive that turns declarations into the config's keys.
class KeyCollector {
 public:
  KeyCollector(std::string prefix, std::vector<KeySpec>& keys)
      : prefix_(std::move(prefix)), keys_(keys) {}

  void number(std::string_view key, double& value, std::string_view meaning, const Bounds& b) {
    add(key, Kind::kNumber, value, meaning, {}, b, 0);
  }
  void integer(std::string_view key, long long& value, std::string_view meaning, const Bounds& b) {
    add(key, Kind::kInteger, value, meaning, {}, b, 0);
  }
  void numbers(std::string_view key, std::vector<double>& values, std::string_view meaning,
               const Bounds& b) {
    add(key, Kind::kNumbers, values, meaning, {}, b, 0);
  }
  template <std::size_t N>
  void numbers(std::string_view key, std::array<double, N>& values, std::string_view meaning,
               const Bounds& b) {
    add(key, Kind::kNumbers, std::vector<double>(values.begin(), values.end()), meaning, {}, b,
        static_cast<int>(N));
  }
  void text(std::string_view key, std::string& value, std::string_view meaning,
            std::vector<std::string> words) {
    add(key, Kind::kText, value, meaning, std::move(words), {}, 0);
  }
  template <typename T>
  void choice(std::string_view key, T& value, std::string_view meaning, const Choices<T>& choices) {
    std::string word;
    std::vector<std::string> words;
    for (const Choice<T>& choice : choices) {
      words.emplace_back(choice.word);
      if (choice.value == value) word = choice.word;
    }
    add(key, Kind::kText, word, meaning, std::move(words), {}, 0);
  }
  void names(std::string_view key, std::vector<std::string>& values, std::string_view meaning,
             std::vector<std::string> words) {
    add(key, Kind::kNames, values, meaning, std::move(words), {}, 0);
  }
  void file(std::string_view key, std::string& path, std::string_view meaning) {
    add(key, Kind::kFile, path, meaning, {}, {}, 0);
  }
  void annealing(std::string_view key, std::vector<AnnealingStep>& steps,
                 std::string_view meaning) {
    add(key, Kind::kAnnealing, steps, meaning, {}, {}, 0);
  }
  void settings(std::string_view key, std::vector<std::string>& entries, std::string_view meaning) {
    add(key, Kind::kSettings, entries, meaning, {}, {}, 0);
  }
  template <typename Params>
  void section(std::string_view name, Params& params) {
    KeyCollector inner(prefix_ + std::string(name) + ".", keys_);
    params.describe(inner);
  }

 private:
  void add(std::string_view key, Kind kind, Value value, std::string_view meaning,
           std::vector<std::string> words, const Bounds& b, int size) {
    keys_.push_back(KeySpec{prefix_ + std::string(key), kind, std::move(value),
                            std::string(meaning), std::move(words), b.min, b.max, b.min_open,
                            b.max_open, size});
  }

  std::string prefix_;
  std::vector<KeySpec>& keys_;
};

// The archive that fills a params struct from a Config or OwnSections (`Source`: anything
// with value(key)), whose values were checked against the same declarations as they
// arrived.
template <class Source>
class KeyReader {
 public:
  KeyReader(const Source& config, std::string prefix)
      : config_(config), prefix_(std::move(prefix)) {}

  void number(std::string_view key, double& value, std::string_view, const Bounds&) {
    value = read<double>(key);
  }
  void integer(std::string_view key, long long& value, std::string_view, const Bounds&) {
    value = read<long long>(key);
  }
  void numbers(std::string_view key, std::vector<double>& values, std::string_view, const Bounds&) {
    values = read<std::vector<double>>(key);
  }
  template <std::size_t N>
  void numbers(std::string_view key, std::array<double, N>& values, std::string_view,
               const Bounds&) {
    const auto& list = read<std::vector<double>>(key);
    for (std::size_t i = 0; i < N && i < list.size(); ++i) values[i] = list[i];
  }
  void text(std::string_view key, std::string& value, std::string_view,
            const std::vector<std::string>&) {
    value = read<std::string>(key);
  }
  template <typename T>
  void choice(std::string_view key, T& value, std::string_view, const Choices<T>& choices) {
    const std::string& word = read<std::string>(key);
    for (const Choice<T>& choice : choices) {
      if (word == choice.word) value = choice.value;
    }
  }
  void names(std::string_view key, std::vector<std::string>& values, std::string_view,
             const std::vector<std::string>&) {
    values = read<std::vector<std::string>>(key);
  }
  void file(std::string_view key, std::string& path, std::string_view) {
    path = read<std::string>(key);
  }
  void annealing(std::string_view key, std::vector<AnnealingStep>& steps, std::string_view) {
    steps = read<std::vector<AnnealingStep>>(key);
  }
  void settings(std::string_view key, std::vector<std::string>& entries, std::string_view) {
    entries = read<std::vector<std::string>>(key);
  }
  template <typename Params>
  void section(std::string_view name, Params& params) {
    KeyReader inner(config_, prefix_ + std::string(name) + ".");
    params.describe(inner);
  }

 private:
  std::string path(std::string_view key) const { return prefix_ + std::string(key); }
  // The value of `key`, of the kind its declaration gave it.
  template <typename T>
  const T& read(std::string_view key) const {
    return std::get<T>(config_.value(path(key)));
  }

  const Source& config_;
  std::string prefix_;
};

// The archive that writes a params struct into a config, value by value.
class KeyWriter {
 public:
  KeyWriter(Config& config, std::string prefix) : config_(config), prefix_(std::move(prefix)) {}

  void number(std::string_view key, double& value, std::string_view, const Bounds&) {
    config_.assign(path(key), value);
  }
  void integer(std::string_view key, long long& value, std::string_view, const Bounds&) {
    config_.assign(path(key), value);
  }
  void numbers(std::string_view key, std::vector<double>& values, std::string_view, const Bounds&) {
    config_.assign(path(key), values);
  }
  void file(std::string_view key, std::string& value, std::string_view) {
    config_.assign(path(key), value);
  }
  template <std::size_t N>
  void numbers(std::string_view key, std::array<double, N>& values, std::string_view,
               const Bounds&) {
    config_.assign(path(key), std::vector<double>(values.begin(), values.end()));
  }
  void text(std::string_view key, std::string& value, std::string_view,
            const std::vector<std::string>&) {
    config_.assign(path(key), value);
  }
  template <typename T>
  void choice(std::string_view key, T& value, std::string_view, const Choices<T>& choices) {
    for (const Choice<T>& choice : choices) {
      if (choice.value == value) config_.assign(path(key), std::string(choice.word));
    }
  }
  void names(std::string_view key, std::vector<std::string>& values, std::string_view,
             const std::vector<std::string>&) {
    config_.assign(path(key), values);
  }
  void annealing(std::string_view key, std::vector<AnnealingStep>& steps, std::string_view) {
    config_.assign(path(key), steps);
  }
  void settings(std::string_view key, std::vector<std::string>& entries, std::string_view) {
    config_.assign(path(key), entries);
  }
  template <typename Params>
  void section(std::string_view name, Params& params) {
    KeyWriter inner(config_, prefix_ + std::string(name) + ".");
    params.describe(inner);
  }

 private:
  std::string path(std::string_view key) const { return prefix_ + std::string(key); }

  Config& config_;
  std::string prefix_;
};

// The keys `params` declares under `section` ("" for none), its values as their defaults.
template <typename Params>
std::vector<KeySpec> declared_keys(Params params, std::string_view section) {
  std::vector<KeySpec> keys;
  KeyCollector collector(section.empty() ? std::string() : std::string(section) + ".", keys);
  params.describe(collector);
  return keys;
}

// Adds keys to the schema: after the last key of `after` (a key, or a section's name) where
// given, else at the end. Throws std::invalid_argument naming a key that is there already,
// whose default its declaration refuses (check_default), or an `after` no key has. Register
// before making any Config: a Config holds the keys that existed when it was made.
void register_keys(std::vector<KeySpec> keys, std::string_view after = {});
// Adds keys before every other: the run's own tree (parameters/parameters.h), registered
// before main. Throws as register_keys.
void register_leading_keys(std::vector<KeySpec> keys);

// Removes the keys whose paths are `paths` (a user's section or protocol unregistered), and
// the words registered for them. Throws std::invalid_argument naming a path no key has,
// before removing any.
void unregister_keys(const std::vector<std::string>& paths);

// `words` and the words registered for the text key `key` since (register_choice): what a key
// open to a user's words declares it allows.
std::vector<std::string> with_registered_words(std::string_view key,
                                               std::vector<std::string> words);

// One more word the text key `key` allows (a plant kind a user registers for plant.kind),
// with its meaning appended to the key's. Throws std::invalid_argument for a key that is not
// a text key with a list of words, or a word it has already.
void register_choice(std::string_view key, const std::string& word, std::string_view meaning);
// Takes back a word register_choice added, its meaning with it. Throws
// std::invalid_argument for a word the key was not given so.
void unregister_choice(std::string_view key, const std::string& word);

// The section `name` of `config` (a Config, or the OwnSections of the typed tree) as its
// struct; `name` "" for a struct of keys without a section.
template <typename Params, class Source>
Params read_section(const Source& config, std::string_view name) {
  Params params;
  KeyReader reader(config, name.empty() ? std::string() : std::string(name) + ".");
  params.describe(reader);
  return params;
}

// A check of a registered section's values beyond each key's own range (how they go
// together, what a factory will build from them), run at the edge of every run with the
// library's own checks (diagrams::validated_parameters), before any work. It throws
// config::ConfigError or std::invalid_argument with a one-line message naming the keys.
using SectionCheck = std::function<void(const OwnSections& own)>;
// Adds `check` for the section `name`. Throws std::invalid_argument for an empty check.
void register_section_check(const std::string& name, SectionCheck check);
// Removes the checks of section `name` (none: nothing changes).
void unregister_section_check(const std::string& name);
// Runs every registered check on `own`. Throws config::ConfigError.
void check_own_sections(const OwnSections& own);

// A user's section: its struct's declared keys under `name`, and its checks: the struct's
// own `validate() const` if it has one (as the library's params structs do), then `check`.
// Throws std::invalid_argument for a key declared twice or a default its declaration refuses.
template <typename Params>
void register_section(std::string_view name, std::function<void(const Params&)> check = {}) {
  register_keys(declared_keys(Params{}, name));
  const std::string section(name);
  if constexpr (requires(const Params& params) { params.validate(); }) {
    register_section_check(section, [section](const OwnSections& own) {
      read_section<Params>(own, section).validate();
    });
  }
  if (check) {
    register_section_check(section, [section, check](const OwnSections& own) {
      check(read_section<Params>(own, section));
    });
  }
}

}  // namespace cbbg::config
