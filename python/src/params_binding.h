#pragma once
// A params struct in Python, bound in one line from the keys its describe() declares
// (framework/parameters.h), so the keys are declared once, in C++:
//
//   bind_params<blocks::CriticParams>(m, "CriticParams", "Config keys critic.*.");
//
// gives cbbg.CriticParams(beta=0.2), a read/write property per key (same names), to_dict(),
// __repr__, __eq__, and validate() where the struct has one. Numbers are floats, integers
// ints, lists of numbers or words Python lists, choices (enums) their words ("improved"), a
// section a nested params object (its own type bound first). Setting a key checks its type
// (and a choice's word, a fixed-size list's length); a value's range is checked where C++
// checks it: by validate() and by the block made from the params, with the config's keyed
// messages.
//
// A struct without describe(), or with fields describe() leaves out because they are not
// config keys (CriticParams::frozen), gets a ParamsDeclarations specialisation that declares
// them with the same archive calls, plus flag(key, bool&, meaning) for a boolean.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cbbg/framework/parameters.h"

namespace cbbg::python {

namespace py = pybind11;

// What a params struct declares; specialise it for a struct without describe() or with
// undeclared fields.
template <class Params>
struct ParamsDeclarations {
  template <class Archive>
  static void describe(Archive& a, Params& params) {
    params.describe(a);
  }
};

namespace params_binding {

// "must be finite and > 0" for a declared range; a specialisation may give its own words.
inline std::string requirement_of(const Bounds& bounds) { return bounds.requirement(); }
inline std::string requirement_of(std::string_view words) { return std::string(words); }

inline std::string joined(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& word : words) text += (text.empty() ? "" : ", ") + word;
  return text;
}

// Qualified names, so that a nested struct reads as "PidController.Params".
inline std::string type_name_of(py::handle value) {
  return py::str(py::type::of(value).attr("__qualname__"));
}

// The Python name of a bound C++ type ("RobotParams").
template <class T>
std::string class_name_of() {
  return py::str(py::type::of<T>().attr("__qualname__"));
}

// One declared key, as the class's property sees it.
struct Key {
  std::string name;
  std::string doc;
  bool section = false;  // its value is a nested params object
};

// The archive that lists the keys (on a default-constructed struct, at import).
class KeyCollector {
 public:
  explicit KeyCollector(std::vector<Key>& keys) : keys_(keys) {}

  template <class Range>
  void number(std::string_view key, double&, std::string_view meaning, const Range& range) {
    add(key, "float: " + std::string(meaning) + " (" + requirement_of(range) + ")");
  }
  template <class Range>
  void integer(std::string_view key, long long&, std::string_view meaning, const Range& range) {
    add(key, "int: " + std::string(meaning) + " (" + requirement_of(range) + ")");
  }
  template <class List, class Range>
  void numbers(std::string_view key, List&, std::string_view meaning, const Range& range) {
    add(key, "list of float: " + std::string(meaning) + " (each " + requirement_of(range) + ")");
  }
  template <class T>
  void choice(std::string_view key, T&, std::string_view meaning, const Choices<T>& choices) {
    std::vector<std::string> words;
    for (const Choice<T>& choice : choices) words.emplace_back(choice.word);
    add(key, "str, one of " + joined(words) + ": " + std::string(meaning));
  }
  void text(std::string_view key, std::string&, std::string_view meaning,
            const std::vector<std::string>& words) {
    add(key,
        "str" + (words.empty() ? "" : ", one of " + joined(words)) + ": " + std::string(meaning));
  }
  void names(std::string_view key, std::vector<std::string>&, std::string_view meaning,
             const std::vector<std::string>& words) {
    add(key, "list of str" + (words.empty() ? "" : ", each one of " + joined(words)) + ": " +
                 std::string(meaning));
  }
  void file(std::string_view key, std::string&, std::string_view meaning) {
    add(key, "str, a file's path: " + std::string(meaning));
  }
  void settings(std::string_view key, std::vector<std::string>&, std::string_view meaning) {
    add(key, "list of str, \"other.key=value\" entries: " + std::string(meaning));
  }
  template <class Steps>
  void annealing(std::string_view key, Steps&, std::string_view meaning) {
    add(key, std::string(meaning));
  }
  void flag(std::string_view key, bool&, std::string_view meaning) {
    add(key, "bool: " + std::string(meaning));
  }
  template <class Section>
  void section(std::string_view name, Section&) {
    // Checked here, at import, rather than at the first access.
    if (py::detail::get_type_info(typeid(Section)) == nullptr) {
      throw std::logic_error("bind_params: bind the type of section '" + std::string(name) +
                             "' before the struct that holds it");
    }
    add(name, "the section " + std::string(name) + ".* (" + class_name_of<Section>() + ")");
    keys_.back().section = true;
  }

 private:
  void add(std::string_view key, std::string doc) {
    keys_.push_back({std::string(key), std::move(doc)});
  }

  std::vector<Key>& keys_;
};

// The archive that reads one key of a struct as a Python object.
class KeyReader {
 public:
  // `owner`: the Python object of the struct, kept alive by a nested section handed out.
  KeyReader(std::string_view key, py::handle owner) : key_(key), owner_(owner) {}

  py::object value() const { return value_; }

  template <class Range>
  void number(std::string_view key, double& value, std::string_view, const Range&) {
    if (key == key_) value_ = py::float_(value);
  }
  template <class Range>
  void integer(std::string_view key, long long& value, std::string_view, const Range&) {
    if (key == key_) value_ = py::int_(value);
  }
  template <class List, class Range>
  void numbers(std::string_view key, List& values, std::string_view, const Range&) {
    if (key == key_) value_ = py::cast(std::vector<double>(values.begin(), values.end()));
  }
  template <class T>
  void choice(std::string_view key, T& value, std::string_view, const Choices<T>& choices) {
    if (key != key_) return;
    for (const Choice<T>& choice : choices) {
      if (choice.value == value) value_ = py::str(choice.word);
    }
  }
  void text(std::string_view key, std::string& value, std::string_view,
            const std::vector<std::string>&) {
    if (key == key_) value_ = py::str(value);
  }
  void names(std::string_view key, std::vector<std::string>& values, std::string_view,
             const std::vector<std::string>&) {
    if (key == key_) value_ = py::cast(values);
  }
  void file(std::string_view key, std::string& value, std::string_view) {
    if (key == key_) value_ = py::str(value);
  }
  void settings(std::string_view key, std::vector<std::string>& values, std::string_view) {
    if (key == key_) value_ = py::cast(values);
  }
  template <class Steps>
  void annealing(std::string_view key, Steps& steps, std::string_view) {
    if (key == key_) value_ = py::cast(steps);
  }
  void flag(std::string_view key, bool& value, std::string_view) {
    if (key == key_) value_ = py::bool_(value);
  }
  // The nested struct itself, not a copy: params.section.key = v changes params.
  template <class Section>
  void section(std::string_view name, Section& section) {
    if (name == key_)
      value_ = py::cast(&section, py::return_value_policy::reference_internal, owner_);
  }

 private:
  std::string_view key_;
  py::handle owner_;
  py::object value_ = py::none();
};

// The archive that sets one key of a struct from a Python object; a value of the wrong type
// throws TypeError, a word outside a choice or a list of the wrong length ValueError, each
// naming "<Class>.<key>".
class KeyWriter {
 public:
  KeyWriter(std::string_view key, py::handle value, std::string label)
      : key_(key), value_(value), label_(std::move(label)) {}

  template <class Range>
  void number(std::string_view key, double& value, std::string_view, const Range&) {
    if (key == key_) value = as<double>("a number");
  }
  template <class Range>
  void integer(std::string_view key, long long& value, std::string_view, const Range&) {
    if (key == key_) value = as<long long>("an integer");
  }
  template <class Range>
  void numbers(std::string_view key, std::vector<double>& values, std::string_view, const Range&) {
    if (key == key_) values = as<std::vector<double>>("a list of numbers");
  }
  template <std::size_t N, class Range>
  void numbers(std::string_view key, std::array<double, N>& values, std::string_view,
               const Range&) {
    if (key != key_) return;
    const auto list = as<std::vector<double>>("a list of numbers");
    if (list.size() != N) {
      throw py::value_error(label_ + " takes " + std::to_string(N) + " numbers, got " +
                            std::to_string(list.size()));
    }
    std::copy(list.begin(), list.end(), values.begin());
  }
  template <class T>
  void choice(std::string_view key, T& value, std::string_view, const Choices<T>& choices) {
    if (key != key_) return;
    const auto word = as<std::string>("a word");
    std::vector<std::string> words;
    for (const Choice<T>& choice : choices) {
      if (word == choice.word) {
        value = choice.value;
        return;
      }
      words.emplace_back(choice.word);
    }
    throw py::value_error(label_ + " must be one of " + joined(words) + "; got '" + word + "'");
  }
  void text(std::string_view key, std::string& value, std::string_view,
            const std::vector<std::string>&) {
    if (key == key_) value = as<std::string>("a str");
  }
  void names(std::string_view key, std::vector<std::string>& values, std::string_view,
             const std::vector<std::string>&) {
    if (key == key_) values = as<std::vector<std::string>>("a list of str");
  }
  void file(std::string_view key, std::string& value, std::string_view) {
    if (key == key_) value = as<std::string>("a str");
  }
  void settings(std::string_view key, std::vector<std::string>& values, std::string_view) {
    if (key == key_) values = as<std::vector<std::string>>("a list of str");
  }
  template <class Steps>
  void annealing(std::string_view key, Steps& steps, std::string_view) {
    if (key == key_) steps = as<Steps>("a list of annealing steps");
  }
  void flag(std::string_view key, bool& value, std::string_view) {
    if (key != key_) return;
    // Strict: 0 or 1.5 for a bool is more likely a mistake than a wish.
    if (!py::isinstance<py::bool_>(value_)) throw wrong_type("True or False");
    value = value_.cast<bool>();
  }
  template <class Section>
  void section(std::string_view name, Section& section) {
    if (name != key_) return;
    if (!py::isinstance<Section>(value_)) {
      throw wrong_type(class_name_of<Section>());
    }
    section = value_.cast<const Section&>();
  }

 private:
  template <class T>
  T as(const char* what) const {
    try {
      return value_.cast<T>();
    } catch (const py::cast_error&) {
      throw wrong_type(what);
    }
  }
  py::type_error wrong_type(const std::string& what) const {
    return py::type_error(label_ + " takes " + what + ", got " + type_name_of(value_) + " " +
                          std::string(py::repr(value_)));
  }

  std::string_view key_;
  py::handle value_;
  std::string label_;
};

// The keys of Params, collected once.
template <class Params>
std::shared_ptr<const std::vector<Key>> collect_keys() {
  auto keys = std::make_shared<std::vector<Key>>();
  Params defaults;
  KeyCollector collector(*keys);
  ParamsDeclarations<Params>::describe(collector, defaults);
  return keys;
}

template <class Params>
py::object read_key(py::handle self, const std::string& key) {
  KeyReader reader(key, self);
  ParamsDeclarations<Params>::describe(reader, self.cast<Params&>());
  return reader.value();
}

template <class Params>
void write_key(Params& params, const std::string& key, py::handle value,
               const std::string& class_name) {
  KeyWriter writer(key, value, class_name + "." + key);
  ParamsDeclarations<Params>::describe(writer, params);
}

// Throws ValueError naming `name` and listing the keys unless it is one of them.
inline void check_known(const std::vector<Key>& keys, const std::string& name,
                        const std::string& class_name) {
  std::vector<std::string> names;
  for (const Key& key : keys) {
    if (key.name == name) return;
    names.push_back(key.name);
  }
  throw py::value_error(class_name + ": unknown keyword '" + name + "'; the keys are " +
                        joined(names));
}

template <class Params>
py::dict to_dict(py::handle self, const std::vector<Key>& keys) {
  py::dict dict;
  for (const Key& key : keys) {
    py::object value = read_key<Params>(self, key.name);
    dict[py::str(key.name)] = key.section ? value.attr("to_dict")() : value;
  }
  return dict;
}

template <class Params>
std::string repr(py::handle self, const std::vector<Key>& keys) {
  std::string text = type_name_of(self) + "(";
  for (std::size_t i = 0; i < keys.size(); ++i) {
    text += (i == 0 ? "" : ", ") + keys[i].name + "=" +
            std::string(py::repr(read_key<Params>(self, keys[i].name)));
  }
  return text + ")";
}

}  // namespace params_binding

// Binds Params as `name` in `scope` (a module, or a class for a nested struct).
template <class Params>
py::class_<Params> bind_params(py::handle scope, const char* name, const std::string& doc) {
  namespace pb = params_binding;
  const auto keys = pb::collect_keys<Params>();
  std::string full_doc =
      doc + "\n\nMade with keywords, each key's default otherwise: " + name + "(";
  for (std::size_t i = 0; i < keys->size(); ++i) {
    full_doc += (i == 0 ? "" : ", ") + (*keys)[i].name + "=...";
  }
  full_doc += ").";

  py::class_<Params> cls(scope, name, full_doc.c_str());
  cls.def(py::init([keys, class_name = pb::class_name_of<Params>()](const py::kwargs& kwargs) {
            Params params;
            for (const std::pair<py::handle, py::handle> item : kwargs) {
              const auto key_name = py::cast<std::string>(item.first);
              pb::check_known(*keys, key_name, class_name);
              pb::write_key(params, key_name, item.second, class_name);
            }
            return params;
          }),
          "Every key its default, or the value given by keyword.")
      .def(
          "to_dict", [keys](py::handle self) { return pb::to_dict<Params>(self, *keys); },
          "Every key and its value, in declaration order; a section as a nested dict.")
      .def("__repr__", [keys](py::handle self) { return pb::repr<Params>(self, *keys); })
      .def("__eq__", [keys](py::handle self, py::handle other) {
        return py::isinstance<Params>(other) &&
               pb::to_dict<Params>(self, *keys).equal(pb::to_dict<Params>(other, *keys));
      });
  for (const pb::Key& key : *keys) {
    cls.def_property(
        key.name.c_str(),
        [key_name = key.name](py::handle self) { return pb::read_key<Params>(self, key_name); },
        [key_name = key.name](py::handle self, py::handle value) {
          pb::write_key(self.cast<Params&>(), key_name, value, pb::type_name_of(self));
        },
        key.doc.c_str());
  }
  if constexpr (requires(const Params& params) { params.validate(); }) {
    cls.def("validate", &Params::validate,
            "Throws ValueError naming the first key whose value is outside its declaration.");
  }
  return cls;
}

}  // namespace cbbg::python
