// SUNDIALS calls our residuals, Jacobians and preconditioners through C callbacks, which must
// not throw. A CallbackGuard runs a callback's body and maps a RecoverableError (a trial state
// the physics cannot evaluate: a closed gap, a negative film pressure) to SUNDIALS' recoverable
// return (> 0: IDA cuts the step, KINSOL damps the update); any other exception stops the solver
// (< 0) and is kept, to be rethrown by rethrow() once the solver call has returned.
#pragma once
#include <exception>
#include <utility>

#include "core/error.hpp"

namespace rfmems {

class CallbackGuard {
 public:
  template <class F>
  int run(F&& body) noexcept {
    try {
      body();
      return 0;
    } catch (const RecoverableError&) {
      return 1;
    } catch (...) {
      pending_ = std::current_exception();
      return -1;
    }
  }
  // For callbacks with no smaller step to retry (KINSOL's Jacobian): every exception stops the
  // solver and is rethrown as it was, a RecoverableError included.
  template <class F>
  int run_or_stop(F&& body) noexcept {
    try {
      body();
      return 0;
    } catch (...) {
      pending_ = std::current_exception();
      return -1;
    }
  }
  void rethrow() {
    if (pending_) std::rethrow_exception(std::exchange(pending_, nullptr));
  }

 private:
  std::exception_ptr pending_;
};

}  // namespace rfmems
