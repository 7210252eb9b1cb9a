#include "cbbg/codegen/c_export.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <stdexcept>
#include <vector>

#include "cbbg/framework/block.h"
#include "cbbg/framework/diagram.h"
#include "cbbg/framework/primitives/constant_source.h"

namespace cbbg::codegen {
namespace {

// One calculation of the export: a block's output and the arrays its inputs are read from.
struct Step {
  const Block* block = nullptr;
  int output = 0;
  int size = 0;
  std::vector<std::string> inputs;  // C expressions: a step's signal, a root input, a constant
  CCalculation calculation;
};

// The steps `output` needs, in the order they must run, found through direct feedthrough.
class Walk {
 public:
  Walk(const Diagram& root, const Context& context, const CExportOptions& options)
      : root_(root), context_(context), options_(options) {}

  // The name of the array that holds `port`'s values once its step has run.
  std::string visit(const OutputPort& port) {
    if (const auto found = visited_.find(&port); found != visited_.end()) return found->second;
    if (const auto other = options_.read_as.find(&port); other != options_.read_as.end()) {
      return visited_[&port] = visit(*other->second);
    }
    if (const auto value = options_.held.find(&port); value != options_.held.end()) {
      return visited_[&port] = constant("held", Vector::Constant(1, value->second));
    }
    const Block& block = port.block();
    if (const auto* source = dynamic_cast<const ConstantSource*>(&block)) {
      return visited_[&port] = constant("constant", source->value());
    }
    const auto* emitter = dynamic_cast<const EmitsC*>(&block);
    if (emitter == nullptr) {
      throw std::invalid_argument("block '" + block.path() +
                                  "' cannot be written as C: it does not implement "
                                  "codegen::EmitsC (the output '" +
                                  port.name() + "' of the export needs it)");
    }
    Step step;
    step.block = &block;
    step.output = port.index();
    step.size = port.size();
    for (const int read : block.output_reads(port.index())) {
      step.inputs.push_back(source_of(block.input_port(read)));
    }
    step.calculation = emitter->c_calculation(port.index(), context_);
    const std::string signal = "s" + std::to_string(steps.size());
    steps.push_back(std::move(step));
    visited_[&port] = signal;
    return signal;
  }

  std::vector<Step> steps;
  std::vector<int> root_inputs;  // the root's inputs read, in the order first read
  std::vector<CConstant> fixed;  // values fixed at build that the steps read

 private:
  std::string source_of(const InputPort& input) {
    const Diagram::InputOrigin origin = root_.origin_of(input);
    if (origin.output != nullptr) return visit(*origin.output);
    if (origin.fixed != nullptr) {
      return constant("fixed", *origin.fixed);
    }
    if (std::find(root_inputs.begin(), root_inputs.end(), origin.diagram_input) ==
        root_inputs.end()) {
      root_inputs.push_back(origin.diagram_input);
    }
    return root_input_name(root_.input_port(origin.diagram_input));
  }

  // A constant of the export's own (`kind`N), named as a block's body names its constants.
  std::string constant(const char* kind, const Vector& values) {
    fixed.push_back(
        {kind + std::to_string(fixed.size()), std::vector<double>(values.begin(), values.end())});
    return "$" + fixed.back().name;
  }

  static std::string root_input_name(const InputPort& port) {
    return is_c_identifier(port.name()) ? port.name() : "in" + std::to_string(port.index());
  }

  const Diagram& root_;
  const Context& context_;
  const CExportOptions& options_;
  std::map<const OutputPort*, std::string> visited_;
};

std::string upper(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return text;
}

std::string head_comment(const std::string& file, const CExportOptions& options) {
  std::string text = "/* " + file + ": written by cbbg export; do not edit.\n";
  for (const std::string& line : options.provenance) text += " * " + line + "\n";
  return text + " */\n";
}

bool is_identifier_character(char c, bool first) {
  const auto u = static_cast<unsigned char>(c);
  return std::isalpha(u) != 0 || c == '_' || (!first && std::isdigit(u) != 0);
}

// `body` with every $NAME replaced by `prefix`NAME; a name the constants lack, or a constant
// the body never names (C warns of it), is the block's mistake.
std::string with_constants(const std::string& body, const std::vector<CConstant>& constants,
                           const std::string& prefix, const Block& block) {
  std::string out;
  std::vector<std::string> named;
  for (std::size_t at = 0; at < body.size();) {
    if (body[at] != '$') {
      out += body[at++];
      continue;
    }
    std::size_t end = at + 1;
    while (end < body.size() && is_identifier_character(body[end], end == at + 1)) ++end;
    const std::string name = body.substr(at + 1, end - at - 1);
    const bool known = std::any_of(constants.begin(), constants.end(),
                                   [&name](const CConstant& c) { return c.name == name; });
    if (!known) {
      throw std::logic_error("block '" + block.path() + "' writes C naming constant '" + name +
                             "', which it does not declare");
    }
    named.push_back(name);
    out += prefix;
    out += name;
    at = end;
  }
  for (const CConstant& constant : constants) {
    if (std::find(named.begin(), named.end(), constant.name) == named.end()) {
      throw std::logic_error("block '" + block.path() + "' declares constant '" + constant.name +
                             "' its C never names");
    }
  }
  return out;
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

std::string step_function(const Step& step, int index, const std::string& name, Scalar scalar) {
  const std::string prefix = name + "_s" + std::to_string(index) + "_";
  std::string text = "\n/* block '" + step.block->path() + "', output '" +
                     step.block->output_port(step.output).name() + "' */\n";
  for (const CConstant& constant : step.calculation.constants) {
    text += constant_definition(constant, prefix, scalar);
  }
  text += "static void " + name + "_s" + std::to_string(index) + "(";
  for (std::size_t i = 0; i < step.inputs.size(); ++i) {
    text += "const real *in" + std::to_string(i) + ", ";
  }
  text += "real *out) {\n";
  text += with_constants(step.calculation.body, step.calculation.constants, prefix, *step.block);
  return text + "}\n";
}

}  // namespace

bool is_c_identifier(const std::string& name) {
  if (name.empty()) return false;
  for (std::size_t i = 0; i < name.size(); ++i) {
    if (!is_identifier_character(name[i], i == 0)) return false;
  }
  return true;
}

CSources export_c(const Diagram& root, const OutputPort& output, const Context& context,
                  const CExportOptions& options) {
  const std::string& name = options.name;
  if (!is_c_identifier(name)) {
    throw std::invalid_argument(
        "the export's name '" + name +
        "' is no C identifier (letters, digits and '_', not first a digit)");
  }
  if (output.size() != 1) {
    throw std::invalid_argument("output '" + output.path() + "' has " +
                                std::to_string(output.size()) +
                                " values; the export writes one action");
  }
  Walk walk(root, context, options);
  const std::string result = walk.visit(output);
  const std::string macro = upper(name);
  const bool single = options.scalar == Scalar::kFloat;

  CSources sources;
  std::string& h = sources.header;
  h = head_comment(name + ".h", options);
  h += "#ifndef " + macro + "_H\n#define " + macro + "_H\n\n";
  h += "#define " + macro + "_EXPORT_VERSION " + std::to_string(kExportVersion) + "\n";
  std::string parameters;
  for (const int input : walk.root_inputs) {
    const InputPort& port = root.input_port(input);
    const std::string array =
        is_c_identifier(port.name()) ? port.name() : "in" + std::to_string(input);
    const std::string size_macro = macro + "_" + upper(array) + "_SIZE";
    h += "#define " + size_macro + " " + std::to_string(port.size()) + "\n";
    parameters += (parameters.empty() ? "" : ", ") + std::string("const ") + name + "_real " +
                  array + "[" + size_macro + "]";
  }
  h += "\ntypedef " + std::string(single ? "float" : "double") + " " + name + "_real;\n\n";
  h += "#ifdef __cplusplus\nextern \"C\" {\n#endif\n\n";
  h += "/* The output '" + output.name() + "' of block '" + output.block().path() +
       "' for the inputs given. */\n";
  h += name + "_real " + name + "_step(" + (parameters.empty() ? "void" : parameters) + ");\n";
  h += "\n#ifdef __cplusplus\n}\n#endif\n\n#endif\n";

  std::string& c = sources.source;
  c = head_comment(name + ".c", options);
  c += "#include <math.h>\n\n#include \"" + name + ".h\"\n\n";
  c += "typedef " + name + "_real real;\n";
  c += std::string("#define CBBG_EXP ") + (single ? "expf" : "exp") + "\n";
  c += std::string("#define CBBG_SQRT ") + (single ? "sqrtf" : "sqrt") + "\n";
  for (const CConstant& constant : walk.fixed)
    c += constant_definition(constant, name + "_", options.scalar);
  for (std::size_t i = 0; i < walk.steps.size(); ++i) {
    c += step_function(walk.steps[i], static_cast<int>(i), name, options.scalar);
  }
  c += "\n" + name + "_real " + name + "_step(" + (parameters.empty() ? "void" : parameters) +
       ") {\n";
  for (std::size_t i = 0; i < walk.steps.size(); ++i) {
    c += "  real s" + std::to_string(i) + "[" + std::to_string(walk.steps[i].size) + "];\n";
  }
  for (std::size_t i = 0; i < walk.steps.size(); ++i) {
    std::string call = "  " + name + "_s" + std::to_string(i) + "(";
    for (const std::string& input : walk.steps[i].inputs) {
      call += (input[0] == '$' ? name + "_" + input.substr(1) : input) + ", ";
    }
    c += call + "s" + std::to_string(i) + ");\n";
  }
  c += "  return " + result + "[0];\n}\n";
  return sources;
}

}  // namespace cbbg::codegen
