// SUNDIALS' MPI parallel N_Vector for distributed unknowns (used inside lib/solvers only:
// it brings mpi.h). Without a running MPI (the serial communicator has no MPI_Comm) the
// serial N_Vector stands in; the local span covers this rank's entries either way.
#pragma once
#include <nvector/nvector_parallel.h>

#include "parallel/communicator.hpp"
#include "solvers/sundials_handles.hpp"

namespace rfmems::sundials {

Vector make_parallel_vector(const Communicator& comm, Index n_local, SUNContext ctx);

// Turns on the fused vector operations (N_VDotProdMulti and the like as one pass and one
// reduction) of a parallel or serial vector and of the vectors later cloned from it.
void enable_fused_operations(N_Vector v);

inline std::span<Real> local_span(N_Vector v) {
  if (N_VGetVectorID(v) == SUNDIALS_NVEC_PARALLEL)
    return {N_VGetArrayPointer(v), static_cast<std::size_t>(N_VGetLocalLength_Parallel(v))};
  return as_span(v);
}

}  // namespace rfmems::sundials
