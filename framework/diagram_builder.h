#pragma once
// DiagramBuilder: add blocks, connect ports, export or fix what stays open, then build().
// Every wiring mistake fails here or at build(), with the paths, ports and sizes involved.

#include <memory>
#include <string>
#include <string_view>
#include <utility>

#include "cbbg/framework/diagram.h"

namespace cbbg {

class DiagramBuilder {
 public:
  // Builds a new Diagram named `diagram_name`; build() returns it.
  explicit DiagramBuilder(std::string diagram_name);
  // Builds into `target`, a Diagram subclass under construction that has no blocks yet
  // (Drake's BuildInto; diagram.h shows the pattern); build_into() finishes it.
  explicit DiagramBuilder(Diagram& target);

  // Adds a block (a leaf or a built Diagram); its name must be unique in this diagram, and a
  // block belongs to one diagram. The diagram owns it, or shares it with whoever made it (the
  // Python bindings: the Python object stays the block's owner too).
  template <typename B>
  B& add(std::unique_ptr<B> block) {
    return add(std::shared_ptr<B>(std::move(block)));
  }
  template <typename B>
  B& add(std::shared_ptr<B> block) {
    B* added = block.get();
    add_block(std::shared_ptr<Block>(std::move(block)));
    return *added;
  }
  // Constructs a block in place: builder.emplace<Gain>("gain", 2.0).
  template <typename B, typename... Args>
  B& emplace(Args&&... args) {
    return add(std::make_unique<B>(std::forward<Args>(args)...));
  }

  // Wires an output to an input of the same size; each input has at most one source.
  void connect(const OutputPort& source, const InputPort& destination);
  void connect(const Block& source, std::string_view output, const Block& destination,
               std::string_view input);
  // Makes a child's input an input of the diagram. Exporting several inner inputs under one
  // name fans the diagram input out to all of them. Returns the diagram's port.
  const InputPort& export_input(const InputPort& inner, std::string name = {});
  const OutputPort& export_output(const OutputPort& inner, std::string name = {});
  // Feeds a child's input with a constant value.
  void fix_input(const InputPort& inner, Vector value);

  // Checks the wiring (every input connected, exported or fixed; no algebraic loop) and
  // fixes the evaluation order. The builder is spent afterwards.
  std::unique_ptr<Diagram> build();
  // The same for the target of DiagramBuilder(Diagram&).
  void build_into();

 private:
  void add_block(std::shared_ptr<Block> block);
  void check_child(const Block& block, const char* action) const;
  void check_input_free(const InputPort& port, const char* action) const;
  Diagram& diagram() const;
  void check_and_finalize();

  std::unique_ptr<Diagram> owned_;  // null when building into a target
  Diagram* diagram_;                // null once built
};

}  // namespace cbbg
