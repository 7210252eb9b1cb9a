// The config engine alone (config/key_registry.cc), in a program without the run's tree: it
// has exactly the keys registered, in the places their registrations asked for.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/config/declared_keys.h"

namespace cbbg::config {
namespace {

using ::testing::ThrowsMessage;

struct Gains {
  double k = 1.0;
  long long n = 3;

  template <class Archive>
  void describe(Archive& a) {
    a.number("k", k, "a gain", kPositive);
    a.integer("n", n, "a count", interval(1, 10));
  }
};

std::vector<std::string> paths() {
  std::vector<std::string> all;
  for (const KeySpec& key : schema()) all.push_back(key.path);
  return all;
}

TEST(KeyRegistry, HoldsTheKeysRegisteredWhereTheyAskedAndNoneOfItsOwn) {
  EXPECT_TRUE(schema().empty());  // no block, plant or protocol is linked into this program
  EXPECT_THAT([] { Config().set("critic.gamma=0.5"); },
              ThrowsMessage<ConfigError>("--set critic.gamma=0.5: unknown key 'critic.gamma'; "
                                         "`cbbg list` shows every key"));

  register_keys(declared_keys(Gains{}, "outer"));
  register_keys(declared_keys(Gains{}, "last"));
  register_keys(declared_keys(Gains{}, "inner"), "outer");
  register_leading_keys(declared_keys(Gains{}, "first"));
  EXPECT_EQ(paths(), (std::vector<std::string>{"first.k", "first.n", "outer.k", "outer.n",
                                               "inner.k", "inner.n", "last.k", "last.n"}));

  Config config;
  config.set("inner.n=7");
  EXPECT_EQ(config.integer("inner.n"), 7);
  EXPECT_EQ(read_section<Gains>(config, "inner").n, 7);
  EXPECT_EQ(config.to_yaml(),
            "first:\n  k: 1\n  n: 3\nouter:\n  k: 1\n  n: 3\ninner:\n  k: 1\n  n: 7\n"
            "last:\n  k: 1\n  n: 3\n");

  EXPECT_THAT([] { register_keys(declared_keys(Gains{}, "more"), "nowhere"); },
              ThrowsMessage<std::invalid_argument>(
                  "config keys cannot follow 'nowhere': no key or section has that name yet"));
  EXPECT_THAT([] { register_keys(declared_keys(Gains{}, "outer")); },
              ThrowsMessage<std::invalid_argument>("config key 'outer.k' is declared twice"));
  EXPECT_EQ(schema().size(), 8U);  // a refused registration adds nothing
}

struct Model {
  std::string file{};

  template <class Archive>
  void describe(Archive& a) {
    a.file("file", file, "a model file");
  }
};

// A file's path is kept absolute, read from where it was written: a config file's folder, or
// the working directory for --set; empty is none, and a path on more than one line is refused.
TEST(KeyRegistry, AFilesPathIsReadFromWhereItWasWritten) {
  register_keys(declared_keys(Model{}, "robot"));
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / "cbbg_key_registry_file_test";
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "run.yaml") << "robot:\n  file: models/arm.xml\n";
  Config from_file;
  from_file.merge_file(folder / "run.yaml");
  EXPECT_EQ(from_file.text("robot.file"), (folder / "models" / "arm.xml").string());
  std::filesystem::remove_all(folder);

  Config from_flag;
  from_flag.set("robot.file=arm.xml");
  EXPECT_EQ(from_flag.text("robot.file"), (std::filesystem::current_path() / "arm.xml").string());
  from_flag.set("robot.file=/models/arm.xml");
  EXPECT_EQ(from_flag.text("robot.file"), "/models/arm.xml");
  from_flag.set("robot.file=''");
  EXPECT_EQ(from_flag.text("robot.file"), "");
  Config reloaded;  // config.yaml reads back the same path
  reloaded.merge_yaml(from_flag.to_yaml(), "config.yaml");
  EXPECT_EQ(reloaded, from_flag);
  EXPECT_THAT([] { Config().set("robot.file=[a, b]"); },
              ThrowsMessage<ConfigError>(
                  "--set robot.file=[a, b]: robot.file must be a file's path on one line; got "
                  "[a, b]"));
}

struct Kind {
  std::string kind = "one";

  template <class Archive>
  void describe(Archive& a) {
    a.choice("kind", kind, "one (the first) | two",
             Choices<std::string>{{"one", "one"}, {"two", "two"}});
  }
};

// What a notebook's registration takes back: a word given to a key, with its meaning, and
// keys, with their words.
TEST(KeyRegistry, UnregisteringTakesBackWordsAndKeysExactly) {
  register_keys(declared_keys(Kind{}, "plant_like"));
  const KeySpec before = schema().back();
  register_choice("plant_like.kind", "three", "a third (with parentheses)");
  EXPECT_EQ(schema().back().meaning, before.meaning + " | three (a third (with parentheses))");
  unregister_choice("plant_like.kind", "three");
  EXPECT_EQ(schema().back().meaning, before.meaning);
  EXPECT_EQ(schema().back().choices, before.choices);
  EXPECT_THAT([] { unregister_choice("plant_like.kind", "two"); },
              ThrowsMessage<std::invalid_argument>(
                  "config key 'plant_like.kind' was not given 'two' by a registration"));

  register_keys(declared_keys(Gains{}, "notebook"));
  EXPECT_THAT(
      [] {
        unregister_keys({"notebook.k", "notebook.x"});
      },
      ThrowsMessage<std::invalid_argument>("no config key 'notebook.x' to unregister"));
  unregister_keys({"notebook.k", "notebook.n"});
  EXPECT_EQ(std::count_if(schema().begin(), schema().end(),
                          [](const KeySpec& key) { return key.path.starts_with("notebook."); }),
            0);
  register_keys(declared_keys(Gains{}, "notebook"));  // registered again, as a cell reruns
}

}  // namespace
}  // namespace cbbg::config
