#include "solvers/umfpack_factorization.hpp"

#include <fmt/format.h>
#include <umfpack.h>

#include <vector>

#include "core/error.hpp"

namespace rfmems {

// UMFPACK factorises compressed-column matrices; a CSR matrix is the CSC form of its
// transpose, so we factorise A^T and solve with UMFPACK_At.
struct UmfpackFactorization::Impl {
  std::vector<SuiteSparse_long> ptr, idx;
  std::vector<Real> values, x;
  double control[UMFPACK_CONTROL];
  double info[UMFPACK_INFO];
  void* numeric = nullptr;
};

UmfpackFactorization::UmfpackFactorization(const CsrPattern& pattern, std::span<const Real> values)
    : impl_(new Impl) {
  Impl& u = *impl_;
  const auto n = static_cast<SuiteSparse_long>(pattern.n_rows());
  u.ptr.assign(pattern.row_ptr.begin(), pattern.row_ptr.end());
  u.idx.assign(pattern.col_idx.begin(), pattern.col_idx.end());
  u.values.assign(values.begin(), values.end());
  u.x.resize(static_cast<std::size_t>(n));
  umfpack_dl_defaults(u.control);
  // No iterative refinement in the solves: each step costs a residual and another solve, and
  // the callers (shift-invert iterations) need no more than the factorisation's accuracy.
  u.control[UMFPACK_IRSTEP] = 0;
  // METIS nested dissection: on the 40,000-cell cubic plate 27.6 CPU s for the modal analysis
  // against 35.5 s with UMFPACK's default (AMD/COLAMD) ordering.
  u.control[UMFPACK_ORDERING] = UMFPACK_ORDERING_METIS;
  void* symbolic = nullptr;
  SuiteSparse_long status = umfpack_dl_symbolic(n, n, u.ptr.data(), u.idx.data(), u.values.data(),
                                                &symbolic, u.control, u.info);
  if (status == UMFPACK_OK)
    status = umfpack_dl_numeric(u.ptr.data(), u.idx.data(), u.values.data(), symbolic, &u.numeric,
                                u.control, u.info);
  umfpack_dl_free_symbolic(&symbolic);
  if (status != UMFPACK_OK) {
    umfpack_dl_free_numeric(&u.numeric);
    delete impl_;
    throw SolverError(status == UMFPACK_WARNING_singular_matrix
                          ? std::string("UMFPACK factorisation: singular matrix")
                          : fmt::format("UMFPACK factorisation failed (status {})", status));
  }
}

UmfpackFactorization::~UmfpackFactorization() {
  umfpack_dl_free_numeric(&impl_->numeric);
  delete impl_;
}

void UmfpackFactorization::solve(std::span<Real> b) {
  Impl& u = *impl_;
  const SuiteSparse_long status =
      umfpack_dl_solve(UMFPACK_At, u.ptr.data(), u.idx.data(), u.values.data(), u.x.data(),
                       b.data(), u.numeric, u.control, u.info);
  if (status != UMFPACK_OK)
    throw SolverError(fmt::format("UMFPACK solve failed (status {})", status));
  std::copy(u.x.begin(), u.x.end(), b.begin());
}

}  // namespace rfmems
