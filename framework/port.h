#pragma once
// Named, fixed-size ports of a block.

#include <string>

namespace cbbg {

class Block;

// What every port has: its block, its index there, a name, a size and a description.
class Port {
 public:
  const Block& block() const { return *block_; }
  int index() const { return index_; }
  const std::string& name() const { return name_; }
  int size() const { return size_; }
  const std::string& description() const { return description_; }
  // "diagram/block.port": how every error message names this port.
  std::string path() const;

 protected:
  Port(const Block& block, int index, std::string name, int size, std::string description)
      : block_(&block),
        index_(index),
        name_(std::move(name)),
        size_(size),
        description_(std::move(description)) {}

 private:
  const Block* block_;
  int index_;
  std::string name_;
  int size_;
  std::string description_;
};

// An input port: a vector the block reads. Distinct types keep inputs and outputs apart in
// connect(source, destination).
class InputPort final : public Port {
 public:
  InputPort(const Block& block, int index, std::string name, int size, std::string description)
      : Port(block, index, std::move(name), size, std::move(description)) {}
};

// An output port: a vector the block computes from the context.
class OutputPort final : public Port {
 public:
  OutputPort(const Block& block, int index, std::string name, int size, std::string description)
      : Port(block, index, std::move(name), size, std::move(description)) {}
};

}  // namespace cbbg
