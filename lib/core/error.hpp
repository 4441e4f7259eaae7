// Error types. Each maps to one behaviour of the drivers:
//   InputError       bad case file / mesh / option: one line naming file, key, value; exit 2
//   MeshError        degenerate or inverted geometry (an InputError when it comes from a file)
//   RecoverableError a step that failed for a reason a smaller step may cure (the solver layer
//                    maps it to SUNDIALS' "> 0" return so the integrator retries)
//   SolverError      an integrator or nonlinear solver that failed for good
#pragma once
#include <stdexcept>
#include <string>

namespace rfmems {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class MeshError : public InputError {
 public:
  using InputError::InputError;
};

class RecoverableError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class SolverError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace rfmems
