#pragma once
// A reference to something callable, as C++26's std::function_ref: no copy of the callable and no
// allocation, so that a loop that runs every step (Newton's iterations, the conjugate gradients'
// products) can take its callbacks by argument. It refers to the callable it was made from,
// which must outlive it: make one from a named lambda or a member, never from a temporary kept
// beyond the call it is passed to.
#include <functional>
#include <memory>
#include <type_traits>
#include <utility>

namespace dinam {

template <class Signature>
class FunctionRef;

template <class Result, class... Args>
class FunctionRef<Result(Args...)> {
 public:
  template <class Callable>
  requires(!std::is_same_v<std::remove_cvref_t<Callable>, FunctionRef> &&
           std::is_invocable_r_v<Result, Callable&, Args...>) FunctionRef(Callable&& callable)
  noexcept  // NOLINT(google-explicit-constructor): as std::function
      : object_(const_cast<void*>(static_cast<const void*>(std::addressof(callable)))),
        call_([](void* object, Args... args) -> Result {
          return std::invoke(*static_cast<std::remove_reference_t<Callable>*>(object),
                             std::forward<Args>(args)...);
        }) {}

  Result operator()(Args... args) const { return call_(object_, std::forward<Args>(args)...); }

 private:
  void* object_;
  Result (*call_)(void*, Args...);
};

}  // namespace dinam
