// The config's keys, as the code that declares them registers them (config/declared_keys.h).

#include <algorithm>
#include <map>
#include <stdexcept>
#include <utility>

#include "cbbg/config/declared_keys.h"

namespace cbbg::config {
namespace {

std::vector<KeySpec>& keys() {
  static std::vector<KeySpec> all;
  return all;
}

// The words users registered, by key.
std::map<std::string, std::vector<std::string>, std::less<>>& registered_words() {
  static std::map<std::string, std::vector<std::string>, std::less<>> words;
  return words;
}

void check_new_keys(const std::vector<KeySpec>& added) {
  for (const KeySpec& key : added) {
    try {
      check_default(key);
    } catch (const ConfigError& error) {
      throw std::invalid_argument(error.what());
    }
    for (const KeySpec& existing : keys()) {
      if (existing.path == key.path) {
        throw std::invalid_argument("config key '" + key.path + "' is declared twice");
      }
    }
  }
}

bool is_in(const KeySpec& key, std::string_view key_or_section) {
  return key.path == key_or_section ||
         (key.path.size() > key_or_section.size() && key.path.starts_with(key_or_section) &&
          key.path[key_or_section.size()] == '.');
}

// Where keys that follow `after` go: past its last key.
std::vector<KeySpec>::iterator position_after(std::string_view after) {
  if (after.empty()) return keys().end();
  const auto last = std::find_if(keys().rbegin(), keys().rend(),
                                 [after](const KeySpec& key) { return is_in(key, after); });
  if (last == keys().rend()) {
    throw std::invalid_argument("config keys cannot follow '" + std::string(after) +
                                "': no key or section has that name yet");
  }
  return last.base();
}

}  // namespace

const std::vector<KeySpec>& schema() { return keys(); }

void register_keys(std::vector<KeySpec> added, std::string_view after) {
  check_new_keys(added);
  const auto at = position_after(after);
  keys().insert(at, std::make_move_iterator(added.begin()), std::make_move_iterator(added.end()));
}

void register_leading_keys(std::vector<KeySpec> added) {
  check_new_keys(added);
  keys().insert(keys().begin(), std::make_move_iterator(added.begin()),
                std::make_move_iterator(added.end()));
}

void unregister_keys(const std::vector<std::string>& paths) {
  for (const std::string& path : paths) {
    if (std::none_of(keys().begin(), keys().end(),
                     [&path](const KeySpec& key) { return key.path == path; })) {
      throw std::invalid_argument("no config key '" + path + "' to unregister");
    }
  }
  std::erase_if(keys(), [&paths](const KeySpec& key) {
    return std::find(paths.begin(), paths.end(), key.path) != paths.end();
  });
  for (const std::string& path : paths) registered_words().erase(path);
}

std::vector<std::string> with_registered_words(std::string_view key,
                                               std::vector<std::string> words) {
  if (const auto found = registered_words().find(key); found != registered_words().end()) {
    words.insert(words.end(), found->second.begin(), found->second.end());
  }
  return words;
}

void register_choice(std::string_view key, const std::string& word, std::string_view meaning) {
  for (KeySpec& spec : keys()) {
    if (spec.path != key) continue;
    if (spec.kind != Kind::kText || spec.choices.empty()) {
      throw std::invalid_argument("config key '" + spec.path + "' takes no list of words");
    }
    if (std::find(spec.choices.begin(), spec.choices.end(), word) != spec.choices.end()) {
      throw std::invalid_argument("config key '" + spec.path + "' allows '" + word + "' already");
    }
    registered_words()[spec.path].push_back(word);
    spec.choices.push_back(word);
    spec.meaning += " | " + word + (meaning.empty() ? "" : " (" + std::string(meaning) + ")");
    return;
  }
  throw std::invalid_argument("no config key '" + std::string(key) + "'");
}

void unregister_choice(std::string_view key, const std::string& word) {
  const auto found = registered_words().find(key);
  if (found == registered_words().end() ||
      std::find(found->second.begin(), found->second.end(), word) == found->second.end()) {
    throw std::invalid_argument("config key '" + std::string(key) + "' was not given '" + word +
                                "' by a registration");
  }
  std::erase(found->second, word);
  for (KeySpec& spec : keys()) {
    if (spec.path != key) continue;
    std::erase(spec.choices, word);
    // The meaning register_choice appended: " | word" and its own meaning in parentheses.
    const std::string appended = " | " + word;
    if (const auto at = spec.meaning.find(appended); at != std::string::npos) {
      auto end = at + appended.size();
      if (spec.meaning.compare(end, 2, " (") == 0) {
        int depth = 0;
        for (; end < spec.meaning.size(); ++end) {
          depth += spec.meaning[end] == '(' ? 1 : spec.meaning[end] == ')' ? -1 : 0;
          if (spec.meaning[end] == ')' && depth == 0) {
            ++end;
            break;
          }
        }
      }
      spec.meaning.erase(at, end - at);
    }
  }
}

}  // namespace cbbg::config
