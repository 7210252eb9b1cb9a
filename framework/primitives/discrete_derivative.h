#pragma once

#include "cbbg/framework/block.h"

namespace cbbg {

/// DiscreteDerivative: the backward difference of its input sampled every period h. At the
/// sample instants t_k = offset + k h it stores u_k; its output is the difference of the
/// last two samples:
///
///   y = (u_k - u_{k-1}) / h  from just after t_k until t_{k+1} included
///
/// The state holds the last two samples, x_last = u_k and x_before = u_{k-1} (zero before
/// any sample), and a count of samples (up to 2); y = (x_last - x_before) / h reads only the
/// state, never u directly, so a derivative breaks feedback loops.
///
/// | port | dir | size | meaning                                |
/// |------|-----|------|----------------------------------------|
/// | u    | in  | n    | the signal to differentiate            |
/// | y    | out | n    | (u_k - u_{k-1}) / h, the last samples' |
///
/// Timing (simulator.h step 2): at t_k every output is evaluated before any update, so what
/// other blocks' updates and logs read at t_k is (u_{k-1} - u_{k-2}) / h, one period late
/// for a discrete block at the same period; a continuous block sees (u_k - u_{k-1}) / h
/// during (t_k, t_{k+1}]. So that the output never depends on when a downstream block
/// samples it (it is a function of the state alone), this design follows Drake's
/// DiscreteDerivative.
///
/// The initial transient: with InitialTransient::kSuppress (the default), y is zero until
/// two samples have been stored, that is until just after t_1; with kKeep, the samples
/// before the first are zero, so y is u_0 / h during (t_0, t_1]. A new trial
/// (Context::reset_trial_state) forgets the samples and the count.
class DiscreteDerivative final : public Block {
 public:
  enum class InitialTransient { kSuppress, kKeep };

  // Throws std::invalid_argument naming the block unless size >= 1, the period is positive
  // and finite and the offset is finite and >= 0.
  DiscreteDerivative(std::string name, int size, double period,
                     InitialTransient transient = InitialTransient::kSuppress, double offset = 0.0);

 private:
  // "y": (x_last - x_before) / h, zero while fewer than two samples are stored.
  void calc_y(const BlockContext& context, VectorRef y) const;
  // Stores u_k as the last sample, the last as the one before, and counts it. Writes in
  // place: it reads and writes its state through `next` alone.
  EventStatus sample(BlockContext& context, VectorRef next) const;

  double period_;
  const InputPort* u_;
  StatePart last_;
  StatePart before_;
  StatePart count_;
};

}  // namespace cbbg
