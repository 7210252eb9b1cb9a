#include "cbbg/framework/primitives/sine_source.h"

#include <stdexcept>
#include <utility>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/primitives/argument_checks.h"

namespace cbbg {

SineSource::SineSource(std::string name, double amplitude, double angular_frequency, double phase,
                       double bias)
    : SineSource(std::move(name), Vector::Constant(1, amplitude),
                 Vector::Constant(1, angular_frequency), Vector::Constant(1, phase),
                 Vector::Constant(1, bias)) {}

SineSource::SineSource(std::string name, const Vector& amplitude, const Vector& angular_frequency,
                       const Vector& phase, const Vector& bias)
    : Block(std::move(name)),
      amplitude_(amplitude),
      angular_frequency_(angular_frequency),
      phase_(phase),
      bias_(bias) {
  const std::string label = primitive_checks::label("SineSource", this->name());
  const int size = primitive_checks::checked_size(label, static_cast<int>(amplitude.size()));
  const auto check = [&](const char* what, const Vector& value) {
    if (value.size() != size) {
      throw std::invalid_argument(label + ": the " + std::string(what) + " has size " +
                                  std::to_string(value.size()) +
                                  "; it must have the amplitude's size, " + std::to_string(size));
    }
    primitive_checks::check_finite(label, what, value);
  };
  check("amplitude", amplitude);
  check("angular frequency", angular_frequency);
  check("phase", phase);
  check("bias", bias);
  declare_output_port<&SineSource::calc_y>("y", size, {}, "b + a sin(omega t + phi)");
}

void SineSource::calc_y(const BlockContext& context, VectorRef y) const {
  y.array() =
      bias_.array() +
      amplitude_.array() * (angular_frequency_.array() * context.time() + phase_.array()).sin();
}

}  // namespace cbbg
