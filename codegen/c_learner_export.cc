#include "cbbg/codegen/c_learner_export.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "cbbg/codegen/c_random.h"
#include "cbbg/codegen/c_text.h"
#include "cbbg/codegen/c_walk.h"
#include "cbbg/framework/block.h"
#include "cbbg/framework/context.h"
#include "cbbg/framework/diagram.h"

namespace cbbg::codegen {
namespace {

// A block the learner carries: its member of NAME_state and its updates' C.
struct Member {
  const UpdatedBlock* entry = nullptr;
  std::string name;  // "critic": the member NAME_state.critic of type NAME_critic_state
  std::vector<CCalculation> updates;          // its periodic update, if any
  std::vector<CCalculation> initializations;  // its initialization updates

  const Block& block() const { return *entry->block; }
  bool has_state() const { return !block().discrete_state_parts().empty(); }
  // Whether an update of its draws from its generator (it then has one in the learner).
  bool draws() const {
    const auto drawing = [](const CCalculation& c) { return c.draws; };
    return std::any_of(updates.begin(), updates.end(), drawing) ||
           std::any_of(initializations.begin(), initializations.end(), drawing);
  }
};

void check_updates(const Block& block, double period) {
  const auto& updates = block.periodic_updates();
  if (updates.size() > 1) {
    throw std::invalid_argument("block '" + block.path() + "' has " +
                                std::to_string(updates.size()) +
                                " periodic updates; the learner export writes one a block");
  }
  for (const PeriodicUpdate& update : updates) {
    if (std::abs(update.period - period) > 1e-12 * period || update.offset != 0.0) {
      throw std::invalid_argument("block '" + block.path() +
                                  "' updates at another period or offset than the learner's "
                                  "tick, every " +
                                  std::to_string(period) + " s from 0");
    }
  }
  for (const StatePart& part : block.discrete_state_parts()) {
    if (!is_c_identifier(part.name) || text::is_c_keyword(part.name)) {
      throw std::invalid_argument("block '" + block.path() + "' has a state part '" + part.name +
                                  "' whose name is no C identifier or is a C keyword");
    }
  }
}

// The block's name, or "blockK" where it is no C identifier, a keyword or taken.
std::string member_name(const Block& block, const std::vector<std::string>& taken) {
  const auto free = [&taken](const std::string& name) {
    return is_c_identifier(name) && !text::is_c_keyword(name) &&
           std::find(taken.begin(), taken.end(), name) == taken.end();
  };
  if (free(block.name())) return block.name();
  for (std::size_t k = taken.size();; ++k) {
    if (const std::string name = "block" + std::to_string(k); free(name)) return name;
  }
}

std::vector<Member> members_of(const Walk& walk, const Context& context, double period) {
  std::vector<Member> members;
  std::vector<std::string> names;
  for (const UpdatedBlock& entry : walk.updated) {
    const Block& block = *entry.block;
    check_updates(block, period);
    const auto& emitter = dynamic_cast<const EmitsC&>(block);  // every step's block emits C
    Member member;
    member.entry = &entry;
    for (std::size_t k = 0; k < block.periodic_updates().size(); ++k)
      member.updates.push_back(emitter.c_update(static_cast<int>(k), context));
    for (std::size_t k = 0; k < block.initialization_updates().size(); ++k)
      member.initializations.push_back(emitter.c_initialization(static_cast<int>(k), context));
    member.name = member_name(block, names);
    names.push_back(member.name);
    members.push_back(std::move(member));
  }
  return members;
}

const Member* member_of(const std::vector<Member>& members, const Block& block) {
  for (const Member& member : members)
    if (&member.block() == &block) return &member;
  return nullptr;
}

// What the learner's C is written from, and the names it writes.
struct Learner {
  const CLearnerOptions& options;
  const Context& context;
  const Walk& walk;
  std::vector<Member> members;

  const std::string& name() const { return options.name; }
  std::string state_type(const Member& m) const { return name() + "_" + m.name + "_state"; }
  bool draws() const {
    return std::any_of(members.begin(), members.end(), [](const Member& m) { return m.draws(); });
  }
};

// A body's names in a learner: @part the state before the instant, @@part after it.
text::BodyNames body_names(const std::string& constant_prefix, bool update) {
  text::BodyNames names;
  names.constant_prefix = constant_prefix;
  names.part = [update](const std::string& part, bool next) {
    if (next && !update) {
      throw std::logic_error("@@" + part + " in an output's C: only an update writes its state");
    }
    return std::string(next ? "next->" : "state->") + part;
  };
  return names;
}

std::string constants_text(const CCalculation& c, const std::string& prefix, Scalar scalar) {
  std::string text;
  for (const CConstant& constant : c.constants)
    text += text::constant_definition(constant, prefix, scalar);
  return text;
}

std::string output_function(const Learner& l, const Step& step, int index) {
  const std::string function = l.name() + "_s" + std::to_string(index);
  const Member* member = member_of(l.members, *step.block);
  const bool stateful = member != nullptr && member->has_state();
  std::string c = "\n/* block '" + step.block->path() + "', output '" +
                  step.block->output_port(step.output).name() + "' */\n";
  c += constants_text(step.calculation, function + "_", l.options.scalar);
  c += "static void " + function + "(";
  if (stateful) c += "const " + l.state_type(*member) + " *state, ";
  for (std::size_t i = 0; i < step.inputs.size(); ++i)
    c += "const real *in" + std::to_string(i) + ", ";
  c += "real *out) {\n";
  if (stateful) c += "  (void)state;\n";
  c += text::resolve(step.calculation.body, step.calculation.constants,
                     body_names(function + "_", false), *step.block);
  return c + "}\n";
}

// The parameters of `m`'s update function: a periodic one's read the inputs and outputs too.
std::string update_parameters(const Learner& l, const Member& m, bool periodic) {
  std::vector<std::string> list;
  if (m.has_state()) {
    list.push_back("const " + l.state_type(m) + " *state");
    list.push_back(l.state_type(m) + " *next");
  }
  if (periodic) {
    for (std::size_t i = 0; i < m.entry->inputs.size(); ++i)
      list.push_back("const real *in" + std::to_string(i));
    for (std::size_t i = 0; i < m.entry->outputs.size(); ++i)
      list.push_back("const real *out" + std::to_string(i));
  }
  if (m.draws()) list.push_back(l.name() + "_random *rng");
  std::string text;
  for (const std::string& p : list) text += (text.empty() ? "" : ", ") + p;
  return text.empty() ? "void" : text;
}

// `(void)x;` for each parameter a body may leave unread (C warns of it).
std::string unread_parameters(const std::string& parameters) {
  std::string text;
  for (std::size_t at = 0; at < parameters.size();) {
    std::size_t end = parameters.find(", ", at);
    if (end == std::string::npos) end = parameters.size();
    const std::string parameter = parameters.substr(at, end - at);
    const std::size_t star = parameter.rfind('*');
    if (star != std::string::npos) text += "  (void)" + parameter.substr(star + 1) + ";\n";
    at = end + 2;
  }
  return text;
}

std::string update_function(const Learner& l, const Member& m, const CCalculation& c,
                            const std::string& function, bool periodic) {
  const std::string parameters = update_parameters(l, m, periodic);
  std::string text = "\n/* block '" + m.block().path() + "', its " +
                     (periodic ? "periodic" : "initialization") + " update */\n";
  text += constants_text(c, function + "_", l.options.scalar);
  text += "static int " + function + "(" + parameters + ") {\n" + unread_parameters(parameters);
  text += text::resolve(c.body, c.constants, body_names(function + "_", true), m.block());
  return text + "  return 0;\n}\n";
}

// The call of update `function` of `m` from NAME_step or NAME_start_trial, into its state in
// place or through a copy.
std::string update_call(const Learner& l, const Member& m, const std::string& function,
                        bool periodic, bool in_place) {
  const std::string state = "&learner->" + m.name;
  std::vector<std::string> arguments;
  if (m.has_state()) {
    arguments.push_back(state);
    arguments.push_back(in_place ? state : "&next");
  }
  if (periodic) {
    for (const std::string& input : m.entry->inputs)
      arguments.push_back(input[0] == '$' ? l.name() + "_" + input.substr(1) : input);
    for (const std::string& output : m.entry->outputs) arguments.push_back(output);
  }
  if (m.draws()) arguments.push_back("&learner->" + m.name + "_random");
  std::string call = function + "(";
  for (std::size_t i = 0; i < arguments.size(); ++i) call += (i ? ", " : "") + arguments[i];
  call += ")";
  const std::string run = periodic ? "ended |= " + call + ";" : "(void)" + call + ";";
  if (!m.has_state() || in_place) return "  " + run + "\n";
  return "  {\n    " + l.state_type(m) + " next = learner->" + m.name + ";\n    " + run +
         "\n    learner->" + m.name + " = next;\n  }\n";
}

std::string step_parameters(const Learner& l) {
  std::string text = l.name() + "_state *learner";
  for (const Argument& argument : l.walk.arguments) {
    text += ", const " + l.name() + "_real " + argument.name + "[" + text::upper(l.name()) + "_" +
            text::upper(argument.name) + "_SIZE]";
  }
  return text + ", " + l.name() + "_real *action";
}

std::string state_types(const Learner& l) {
  std::string h;
  for (const Member& m : l.members) {
    if (!m.has_state()) continue;
    h += "\n/* The state of block '" + m.block().path() + "'. */\ntypedef struct {\n";
    for (const StatePart& part : m.block().discrete_state_parts())
      h += "  " + l.name() + "_real " + part.name + "[" + std::to_string(part.size) + "];\n";
    h += "} " + l.state_type(m) + ";\n";
  }
  h += "\n/* The learner: what each block keeps between ticks. The caller owns it. */\n";
  h += "typedef struct {\n";
  for (const Member& m : l.members) {
    if (m.has_state()) h += "  " + l.state_type(m) + " " + m.name + ";\n";
    if (m.draws()) h += "  " + l.name() + "_random " + m.name + "_random;\n";
  }
  return h + "} " + l.name() + "_state;\n";
}

std::string header(const Learner& l, const OutputPort& action) {
  const std::string& n = l.name();
  const std::string macro = text::upper(n);
  const bool single = l.options.scalar == Scalar::kFloat;
  std::string h = text::head_comment(n + ".h", l.options.provenance);
  h += "#ifndef " + macro + "_H\n#define " + macro + "_H\n\n#include <stdint.h>\n\n";
  h += "#define " + macro + "_EXPORT_VERSION " + std::to_string(kExportVersion) + "\n";
  h += "/* The tick, in seconds, " + n + "_step must be called at. */\n";
  h += "#define " + macro + "_PERIOD " + c_literal(l.options.period, Scalar::kDouble) + "\n";
  for (const Argument& argument : l.walk.arguments) {
    h += "#define " + macro + "_" + text::upper(argument.name) + "_SIZE " +
         std::to_string(argument.size) + "\n";
  }
  h += "\ntypedef " + std::string(single ? "float" : "double") + " " + n + "_real;\n\n";
  h += c_random_type(n) + state_types(l);
  h += "\n#ifdef __cplusplus\nextern \"C\" {\n#endif\n\n";
  h += "/* The learner as exported: its learnt state and its generators as they stood. */\n";
  h += "void " + n + "_init(" + n + "_state *learner);\n";
  h += "/* Every generator as a run of `seed` starts it. */\n";
  h += "void " + n + "_seed(" + n + "_state *learner, uint64_t seed);\n";
  h += "/* A new trial: the per-trial state back to its start, then the initializations. */\n";
  h += "void " + n + "_start_trial(" + n + "_state *learner);\n";
  h += "/* One tick: *action, the output '" + action.name() + "' of block '" +
       action.block().path() +
       "', then every block's update. Returns 1 when the trial ends, else 0. */\n";
  h += "int " + n + "_step(" + step_parameters(l) + ");\n";
  return h + "\n#ifdef __cplusplus\n}\n#endif\n\n#endif\n";
}

// A part's values as a brace list of C literals.
std::string values_list(const Eigen::Ref<const Vector>& values, Scalar scalar) {
  std::string text = "{";
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    text += (i % 4 == 0 ? "\n    " : " ") + c_literal(values[i], scalar);
    if (i + 1 < values.size()) text += ",";
  }
  return text + "}";
}

// The state the learner starts from (NAME_init), and each per-trial part's start.
std::string exported_state(const Learner& l) {
  std::string c;
  for (const Member& m : l.members) {
    const Block& block = m.block();
    if (m.has_state()) {
      const ConstVectorView state = l.context.discrete_state(block);
      std::string fields;
      for (const StatePart& part : block.discrete_state_parts())
        fields += (fields.empty() ? "" : ",\n  ") + values_list(part.of(state), l.options.scalar);
      c += "\nstatic const " + l.state_type(m) + " " + l.name() + "_" + m.name +
           "_exported = {\n  " + fields + "\n};\n";
      for (const StatePart& part : block.discrete_state_parts()) {
        if (part.lifetime != StateLifetime::kPerTrial) continue;
        const auto start = part.of(block.initial_discrete_state());
        c += text::constant_definition(
            {m.name + "_" + part.name + "_start", std::vector<double>(start.begin(), start.end())},
            l.name() + "_", l.options.scalar);
      }
    }
    if (m.draws()) {
      c += "\nstatic const " + l.name() + "_random " + l.name() + "_" + m.name +
           "_random_exported = " + c_random_state(l.context.random_generator(block)) + ";\n";
    }
  }
  return c;
}

std::string init_function(const Learner& l) {
  std::string c = "\nvoid " + l.name() + "_init(" + l.name() + "_state *learner) {\n";
  for (const Member& m : l.members) {
    const std::string exported = l.name() + "_" + m.name;
    if (m.has_state()) c += "  learner->" + m.name + " = " + exported + "_exported;\n";
    if (m.draws()) c += "  learner->" + m.name + "_random = " + exported + "_random_exported;\n";
  }
  return c + "}\n";
}

std::string seed_function(const Learner& l) {
  std::string c =
      "\nvoid " + l.name() + "_seed(" + l.name() + "_state *learner, uint64_t seed) {\n";
  if (!l.draws()) return c + "  (void)learner;\n  (void)seed;\n}\n";
  const std::string root = l.context.diagram().path() + "/";
  for (const Member& m : l.members) {
    if (!m.draws()) continue;
    const std::string stream = m.block().path().substr(root.size());  // Context's stream name
    c += "  " + l.name() + "_random_seed(&learner->" + m.name + "_random, " + l.name() +
         "_derive_seed(seed, " + c_uint64(path_hash(stream)) + "));  /* '" + stream + "' */\n";
  }
  return c + "}\n";
}

std::string start_trial_function(const Learner& l) {
  std::string resets, initializations;
  for (const Member& m : l.members) {
    for (const StatePart& part : m.block().discrete_state_parts()) {
      if (part.lifetime != StateLifetime::kPerTrial) continue;
      resets += "  for (i = 0; i < " + std::to_string(part.size) + "; ++i) learner->" + m.name +
                "." + part.name + "[i] = " + l.name() + "_" + m.name + "_" + part.name +
                "_start[i];\n";
    }
    for (std::size_t k = 0; k < m.initializations.size(); ++k) {
      initializations +=
          update_call(l, m, l.name() + "_" + m.name + "_i" + std::to_string(k), false, false);
    }
  }
  std::string c = "\nvoid " + l.name() + "_start_trial(" + l.name() + "_state *learner) {\n";
  if (!resets.empty()) c += "  int i;\n";
  if (resets.empty() && initializations.empty()) c += "  (void)learner;\n";
  return c + resets + initializations + "}\n";
}

std::string step_function(const Learner& l, const std::string& action) {
  const auto& steps = l.walk.steps;
  std::string c = "\nint " + l.name() + "_step(" + step_parameters(l) + ") {\n  int ended = 0;\n";
  for (std::size_t i = 0; i < steps.size(); ++i)
    c += "  real s" + std::to_string(i) + "[" + std::to_string(steps[i].size) + "];\n";
  for (std::size_t i = 0; i < steps.size(); ++i) {
    std::string call = "  " + l.name() + "_s" + std::to_string(i) + "(";
    if (const Member* m = member_of(l.members, *steps[i].block); m != nullptr && m->has_state())
      call += "&learner->" + m->name + ", ";
    for (const std::string& input : steps[i].inputs)
      call += (input[0] == '$' ? l.name() + "_" + input.substr(1) : input) + ", ";
    c += call + "s" + std::to_string(i) + ");\n";
  }
  c += "  *action = " + action + "[0];\n";
  for (const Member& m : l.members) {
    if (m.updates.empty()) continue;
    const bool in_place = m.block().periodic_updates()[0].writes == UpdateWrites::kInPlace;
    c += update_call(l, m, l.name() + "_" + m.name + "_u0", true, in_place);
  }
  return c + "  return ended;\n}\n";
}

std::string source(const Learner& l, const std::string& action) {
  const std::string& n = l.name();
  std::string c = text::head_comment(n + ".c", l.options.provenance);
  c += "#include <math.h>\n#include <stdint.h>\n\n#include \"" + n + ".h\"\n\n";
  c += "typedef " + n + "_real real;\n" + text::math_macros(l.options.scalar);
  if (l.draws()) c += c_random_functions(n, l.options.scalar);
  for (const CConstant& constant : l.walk.fixed)
    c += text::constant_definition(constant, n + "_", l.options.scalar);
  for (std::size_t i = 0; i < l.walk.steps.size(); ++i)
    c += output_function(l, l.walk.steps[i], static_cast<int>(i));
  for (const Member& m : l.members) {
    for (std::size_t k = 0; k < m.updates.size(); ++k)
      c += update_function(l, m, m.updates[k], n + "_" + m.name + "_u" + std::to_string(k), true);
    for (std::size_t k = 0; k < m.initializations.size(); ++k) {
      c += update_function(l, m, m.initializations[k], n + "_" + m.name + "_i" + std::to_string(k),
                           false);
    }
  }
  c += exported_state(l) + init_function(l) + seed_function(l) + start_trial_function(l);
  return c + step_function(l, action);
}

}  // namespace

CSources export_learner_c(const Diagram& root, const OutputPort& action, const Context& context,
                          const CLearnerOptions& options) {
  if (!is_c_identifier(options.name)) {
    throw std::invalid_argument(
        "the export's name '" + options.name +
        "' is no C identifier (letters, digits and '_', not first a digit)");
  }
  if (action.size() != 1) {
    throw std::invalid_argument("output '" + action.path() + "' has " +
                                std::to_string(action.size()) +
                                " values; the export writes one action");
  }
  Walk walk(root, context, {{}, {}, options.given, true});
  const std::string result = walk.visit(action);
  for (const OutputPort* watched : options.watched) walk.visit(*watched);
  walk.visit_updated_blocks();
  Learner learner{options, context, walk, members_of(walk, context, options.period)};
  if (learner.members.empty()) {
    throw std::invalid_argument("output '" + action.path() +
                                "' needs no block with state or updates: there is nothing to "
                                "learn; export the policy instead");
  }
  return {header(learner, action), source(learner, result)};
}

}  // namespace cbbg::codegen
