#pragma once
// Calculation: one of a block's output, update, derivative or advance functions, bound when the
// block declares it. Two kinds, called the same way:
//  - a named calculation, a const member function of the block (`&Actor::calc_action`), given
//    as a template argument to Block's declare_* functions: a trampoline instantiated for that
//    member calls it directly (a call the compiler may inline), so a call costs one plain
//    function-pointer call and no std::function;
//  - a callable (a lambda), for a user's small block: kept in a std::function that the same
//    pointer calls.

#include <functional>
#include <memory>
#include <type_traits>
#include <utility>

#include "cbbg/framework/types.h"

namespace cbbg {

namespace detail {
// The class of a const member function pointer.
template <typename Method>
struct MemberClass {
  static_assert(sizeof(Method) == 0,
                "a named calculation is a const member function of the block: it must not "
                "change the block, whose state lives in the context");
};
template <typename Class, typename Result, typename... Args>
struct MemberClass<Result (Class::*)(Args...) const> {
  using type = Class;
};
template <typename Class, typename Result, typename... Args>
struct MemberClass<Result (Class::*)(Args...) const noexcept> {
  using type = Class;
};

// How a calculation's function pointer takes each argument. A VectorRef goes as its data and
// size, in registers, and becomes a view again in the callee: an Eigen::Ref copied between
// frames is read back whole from the two stores that wrote it, which stalls the processor for
// longer than the call takes. Anything else goes as declared.
struct VectorArgument {
  double* data;
  Eigen::Index size;
};
template <typename T>
struct Passing {
  using Type = T;
  template <typename U>
  static T in(U&& value) {
    return std::forward<U>(value);
  }
  static T out(T value) { return value; }
};
template <>
struct Passing<VectorRef> {
  using Type = VectorArgument;
  template <typename U>
  static VectorArgument in(U&& value) {
    VectorRef view(value);  // checks the type; optimised away
    return {view.data(), view.size()};
  }
  static VectorRef out(VectorArgument value) { return VectorView(value.data, value.size); }
};

}  // namespace detail

template <typename Result, typename... Args>
class Calculation {
 public:
  using Callable = std::function<Result(Args...)>;
  using Function = Result (*)(const void* target, typename detail::Passing<Args>::Type... args);

  // What a call needs: the function and what it is called on. Small and trivially copied, for
  // the compiled schedule's flat arrays.
  struct Direct {
    Function function = nullptr;
    const void* target = nullptr;
    template <typename... CallArgs>
    Result operator()(CallArgs&&... args) const {
      return function(target, detail::Passing<Args>::in(std::forward<CallArgs>(args))...);
    }
  };

  Calculation() = default;

  // `Method`, a const member function of `block`'s class (or of a base of it), on `block`.
  template <auto Method, typename Owner>
  static Calculation member(const Owner& block) {
    using Class = typename detail::MemberClass<decltype(Method)>::type;
    static_assert(std::is_base_of_v<Owner, Class> || std::is_base_of_v<Class, Owner>,
                  "a named calculation must be a member function of the declaring block");
    Calculation calculation;
    calculation.direct_.target = static_cast<const Class*>(&block);
    calculation.direct_.function = [](const void* target,
                                      typename detail::Passing<Args>::Type... args) -> Result {
      return (static_cast<const Class*>(target)->*Method)(detail::Passing<Args>::out(args)...);
    };
    return calculation;
  }

  // A callable, kept alive by the calculation and its copies.
  static Calculation callable(Callable function) {
    Calculation calculation;
    if (!function) return calculation;
    calculation.owned_ = std::make_shared<const Callable>(std::move(function));
    calculation.direct_.target = calculation.owned_.get();
    calculation.direct_.function = [](const void* target,
                                      typename detail::Passing<Args>::Type... args) -> Result {
      return (*static_cast<const Callable*>(target))(detail::Passing<Args>::out(args)...);
    };
    return calculation;
  }

  template <typename... CallArgs>
  Result operator()(CallArgs&&... args) const {
    return direct_(std::forward<CallArgs>(args)...);
  }
  explicit operator bool() const { return direct_.function != nullptr; }
  const Direct& direct() const { return direct_; }

 private:
  Direct direct_;
  std::shared_ptr<const Callable> owned_;  // a callable's storage; null for a named calculation
};

}  // namespace cbbg
