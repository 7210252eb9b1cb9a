#pragma once
// Named, fixed-size ports of a block.

#include <string>

namespace cbbg {

class Block;

// An input port: a named vector of fixed size that a block reads.
class InputPort {
 public:
  InputPort(const Block& block, int index, std::string name, int size, std::string description)
      : block_(&block),
        index_(index),
        name_(std::move(name)),
        size_(size),
        description_(std::move(description)) {}

  const Block& block() const { return *block_; }
  int index() const { return index_; }
  const std::string& name() const { return name_; }
  int size() const { return size_; }
  const std::string& description() const { return description_; }
  // "diagram/block.port": how every error message names this port.
  std::string path() const;

 private:
  const Block* block_;
  int index_;
  std::string name_;
  int size_;
  std::string description_;
};

// An output port: a named vector of fixed size that a block computes from the context.
class OutputPort {
 public:
  OutputPort(const Block& block, int index, std::string name, int size, std::string description)
      : block_(&block),
        index_(index),
        name_(std::move(name)),
        size_(size),
        description_(std::move(description)) {}

  const Block& block() const { return *block_; }
  int index() const { return index_; }
  const std::string& name() const { return name_; }
  int size() const { return size_; }
  const std::string& description() const { return description_; }
  std::string path() const;

 private:
  const Block* block_;
  int index_;
  std::string name_;
  int size_;
  std::string description_;
};

}  // namespace cbbg
