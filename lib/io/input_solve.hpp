// A solve that a reader makes on the input alone (the gas's discrete equilibrium at a wall's
// temperature on the case's velocity grid, say) fails only because of the input: bad input, not
// a solver failure.
#pragma once
#include <string>
#include <utility>

#include "core/error.hpp"
#include "io/case_file.hpp"

namespace rfmems {

// Returns build(); a SolverError or RecoverableError it throws becomes the InputError
// "<case file>: <what>: <the error>".
template <class Build>
auto read_with_input_solves(const CaseNode& root, const std::string& what, Build&& build) {
  try {
    return std::forward<Build>(build)();
  } catch (const SolverError& e) {
    throw InputError(root.file() + ": " + what + ": " + e.what());
  } catch (const RecoverableError& e) {
    throw InputError(root.file() + ": " + what + ": " + e.what());
  }
}

}  // namespace rfmems
