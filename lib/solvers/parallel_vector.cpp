#include "solvers/parallel_vector.hpp"

#include <nvector/nvector_serial.h>

#include "core/error.hpp"

namespace rfmems::sundials {

Vector make_parallel_vector(const Communicator& comm, Index n_local, SUNContext ctx) {
  if (!comm.handle()) return make_serial_vector(n_local, ctx);
  const Index n_global = comm.sum(n_local);
  N_Vector v = N_VNew_Parallel(static_cast<MPI_Comm>(comm.handle()), n_local, n_global, ctx);
  if (!v) throw SolverError("N_VNew_Parallel failed");
  N_VConst(0.0, v);
  return Vector(v);
}

void enable_fused_operations(N_Vector v) {
  if (N_VGetVectorID(v) == SUNDIALS_NVEC_PARALLEL)
    N_VEnableFusedOps_Parallel(v, SUNTRUE);
  else
    N_VEnableFusedOps_Serial(v, SUNTRUE);
}

}  // namespace rfmems::sundials
