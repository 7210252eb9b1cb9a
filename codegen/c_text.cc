#include "cbbg/codegen/c_text.h"

#include <algorithm>
#include <cctype>
#include <iterator>
#include <stdexcept>

#include "cbbg/codegen/c_export.h"
#include "cbbg/framework/block.h"

namespace cbbg::codegen {

bool is_c_identifier(const std::string& name) {
  if (name.empty()) return false;
  for (std::size_t i = 0; i < name.size(); ++i) {
    if (!text::is_identifier_character(name[i], i == 0)) return false;
  }
  return true;
}

namespace text {
namespace {

// The identifier that starts at `at` in `body`.
std::string identifier_at(const std::string& body, std::size_t at) {
  std::size_t end = at;
  while (end < body.size() && is_identifier_character(body[end], end == at)) ++end;
  return body.substr(at, end - at);
}

bool has_part(const Block& block, const std::string& name) {
  const auto& parts = block.discrete_state_parts();
  return std::any_of(parts.begin(), parts.end(),
                     [&name](const StatePart& part) { return part.name == name; });
}

std::string constant_reference(const std::string& name, const std::vector<CConstant>& constants,
                               const std::string& prefix, const Block& block) {
  const bool known = std::any_of(constants.begin(), constants.end(),
                                 [&name](const CConstant& c) { return c.name == name; });
  if (!known) {
    throw std::logic_error("block '" + block.path() + "' writes C naming constant '" + name +
                           "', which it does not declare");
  }
  return prefix + name;
}

std::string part_reference(const std::string& name, bool next, const BodyNames& names,
                           const Block& block) {
  if (!has_part(block, name)) {
    throw std::logic_error("block '" + block.path() + "' writes C naming state part '" + name +
                           "', which it does not have");
  }
  return names.part(name, next);
}

}  // namespace

bool is_identifier_character(char c, bool first) {
  const auto u = static_cast<unsigned char>(c);
  return std::isalpha(u) != 0 || c == '_' || (!first && std::isdigit(u) != 0);
}

bool is_c_keyword(const std::string& word) {
  static const char* const keywords[] = {
      "auto",     "break",  "case",   "char",     "const",     "continue", "default",  "do",
      "double",   "else",   "enum",   "extern",   "float",     "for",      "goto",     "if",
      "inline",   "int",    "long",   "register", "restrict",  "return",   "short",    "signed",
      "sizeof",   "static", "struct", "switch",   "typedef",   "union",    "unsigned", "void",
      "volatile", "while",  "_Bool",  "_Complex", "_Imaginary"};
  return std::any_of(std::begin(keywords), std::end(keywords),
                     [&word](const char* keyword) { return word == keyword; });
}

std::string upper(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return text;
}

std::string head_comment(const std::string& file, const std::vector<std::string>& provenance) {
  std::string text = "/* " + file + ": written by cbbg export; do not edit.\n";
  for (const std::string& line : provenance) text += " * " + line + "\n";
  return text + " */\n";
}

std::string math_macros(Scalar scalar) {
  std::string text;
  for (const char* function : {"exp", "exp2", "sqrt", "log", "cos", "fabs"}) {
    text += "#define CBBG_" + upper(function) + " " + function +
            (scalar == Scalar::kFloat ? "f" : "") + "\n";
  }
  return text;
}

std::string constant_definition(const CConstant& constant, const std::string& prefix,
                                Scalar scalar) {
  std::string text = "static const real " + prefix + constant.name;
  if (!constant.array) {
    if (constant.values.size() != 1) {
      throw std::logic_error("constant '" + constant.name + "' is one number, not " +
                             std::to_string(constant.values.size()));
    }
    return text + " = " + c_literal(constant.values[0], scalar) + ";\n";
  }
  // Piece by piece: GCC 12 warns falsely (-Wrestrict) on chains of operator+ here.
  text += '[';
  text += std::to_string(constant.values.size());
  text += "] = {";
  for (std::size_t i = 0; i < constant.values.size(); ++i) {
    text += i % 4 == 0 ? "\n    " : " ";
    text += c_literal(constant.values[i], scalar);
    if (i + 1 < constant.values.size()) text += ',';
  }
  return text + "\n};\n";
}

std::string resolve(const std::string& body, const std::vector<CConstant>& constants,
                    const BodyNames& names, const Block& block) {
  std::string out;
  std::vector<std::string> named;
  for (std::size_t at = 0; at < body.size();) {
    if (body[at] == '$') {
      const std::string name = identifier_at(body, at + 1);
      out += constant_reference(name, constants, names.constant_prefix, block);
      named.push_back(name);
      at += 1 + name.size();
    } else if (body[at] == '@') {
      const bool next = at + 1 < body.size() && body[at + 1] == '@';
      const std::string name = identifier_at(body, at + (next ? 2 : 1));
      out += part_reference(name, next, names, block);
      at += (next ? 2 : 1) + name.size();
    } else {
      out += body[at++];
    }
  }
  for (const CConstant& constant : constants) {
    if (std::find(named.begin(), named.end(), constant.name) == named.end()) {
      throw std::logic_error("block '" + block.path() + "' declares constant '" + constant.name +
                             "' its C never names");
    }
  }
  return out;
}

}  // namespace text
}  // namespace cbbg::codegen
