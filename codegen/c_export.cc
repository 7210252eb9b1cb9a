#include "cbbg/codegen/c_export.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "cbbg/codegen/c_text.h"
#include "cbbg/codegen/c_walk.h"
#include "cbbg/framework/block.h"
#include "cbbg/framework/context.h"

namespace cbbg::codegen {
namespace {

// A policy step's body with its names resolved, and the constants it needs: the block's own,
// and each state part the body names (@part), as `context` holds it.
struct StepText {
  std::string body;
  std::vector<CConstant> constants;
};

StepText step_text(const Step& step, const std::string& prefix, const Context& context) {
  StepText text;
  text.constants = step.calculation.constants;
  const ConstVectorView state = context.discrete_state(*step.block);
  text::BodyNames names;
  names.constant_prefix = prefix;
  names.part = [&](const std::string& name, bool next) {
    if (next) {
      throw std::logic_error("block '" + step.block->path() + "' writes @@" + name +
                             " in an output's C; only an update writes its next state");
    }
    const auto same_name = [&name](const CConstant& c) { return c.name == name; };
    const auto& own = step.calculation.constants;
    if (std::any_of(own.begin(), own.end(), same_name)) {
      throw std::logic_error("block '" + step.block->path() + "' names both constant '" + name +
                             "' and state part '" + name + "' in its C");
    }
    if (std::none_of(text.constants.begin(), text.constants.end(), same_name)) {
      const auto values = step.block->discrete_state_part(name).of(state);
      text.constants.push_back({name, std::vector<double>(values.begin(), values.end())});
    }
    return prefix + name;
  };
  text.body = text::resolve(step.calculation.body, step.calculation.constants, names, *step.block);
  return text;
}

std::string step_function(const Step& step, int index, const std::string& name,
                          const Context& context, Scalar scalar) {
  const std::string prefix = name + "_s" + std::to_string(index) + "_";
  const StepText body = step_text(step, prefix, context);
  std::string text = "\n/* block '" + step.block->path() + "', output '" +
                     step.block->output_port(step.output).name() + "' */\n";
  for (const CConstant& constant : body.constants) {
    text += text::constant_definition(constant, prefix, scalar);
  }
  text += "static void " + name + "_s" + std::to_string(index) + "(";
  for (std::size_t i = 0; i < step.inputs.size(); ++i) {
    text += "const real *in" + std::to_string(i) + ", ";
  }
  text += "real *out) {\n";
  text += body.body;
  return text + "}\n";
}

}  // namespace

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
  Walk walk(root, context, {options.read_as, options.held, {}, false});
  const std::string result = walk.visit(output);
  const std::string macro = text::upper(name);
  const bool single = options.scalar == Scalar::kFloat;

  CSources sources;
  std::string& h = sources.header;
  h = text::head_comment(name + ".h", options.provenance);
  h += "#ifndef " + macro + "_H\n#define " + macro + "_H\n\n";
  h += "#define " + macro + "_EXPORT_VERSION " + std::to_string(kExportVersion) + "\n";
  std::string parameters;
  for (const Argument& argument : walk.arguments) {
    const std::string size_macro = macro + "_" + text::upper(argument.name) + "_SIZE";
    h += "#define " + size_macro + " " + std::to_string(argument.size) + "\n";
    parameters += (parameters.empty() ? "" : ", ") + std::string("const ") + name + "_real " +
                  argument.name + "[" + size_macro + "]";
  }
  h += "\ntypedef " + std::string(single ? "float" : "double") + " " + name + "_real;\n\n";
  h += "#ifdef __cplusplus\nextern \"C\" {\n#endif\n\n";
  h += "/* The output '" + output.name() + "' of block '" + output.block().path() +
       "' for the inputs given. */\n";
  h += name + "_real " + name + "_step(" + (parameters.empty() ? "void" : parameters) + ");\n";
  h += "\n#ifdef __cplusplus\n}\n#endif\n\n#endif\n";

  std::string& c = sources.source;
  c = text::head_comment(name + ".c", options.provenance);
  c += "#include <math.h>\n\n#include \"" + name + ".h\"\n\n";
  c += "typedef " + name + "_real real;\n" + text::math_macros(options.scalar);
  for (const CConstant& constant : walk.fixed)
    c += text::constant_definition(constant, name + "_", options.scalar);
  for (std::size_t i = 0; i < walk.steps.size(); ++i) {
    c += step_function(walk.steps[i], static_cast<int>(i), name, context, options.scalar);
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
