#include "solvers/umfpack_factorization.hpp"

#include <fmt/format.h>
#include <umfpack.h>

#include <vector>

#include "core/error.hpp"
#include "solvers/klu_factorization.hpp"

namespace rfmems {

// UMFPACK factorises compressed-column matrices; a CSR matrix is the CSC form of its
// transpose, so we factorise A^T and solve with UMFPACK_At.
struct UmfpackFactorization::Impl {
  std::vector<SuiteSparse_long> ptr, idx;
  std::vector<Real> values, x;
  double control[UMFPACK_CONTROL];
  double info[UMFPACK_INFO];
  void* symbolic = nullptr;
  void* numeric = nullptr;
  long factorizations = 0;

  ~Impl() {
    umfpack_dl_free_numeric(&numeric);
    umfpack_dl_free_symbolic(&symbolic);
  }
  // The numeric factorisation of `values` on the symbolic analysis.
  void factorize() {
    umfpack_dl_free_numeric(&numeric);
    const SuiteSparse_long status = umfpack_dl_numeric(ptr.data(), idx.data(), values.data(),
                                                       symbolic, &numeric, control, info);
    if (status != UMFPACK_OK) {
      umfpack_dl_free_numeric(&numeric);
      throw SolverError(status == UMFPACK_WARNING_singular_matrix
                            ? std::string("UMFPACK factorisation: singular matrix")
                            : fmt::format("UMFPACK factorisation failed (status {})", status));
    }
    ++factorizations;
  }
};

UmfpackFactorization::UmfpackFactorization(const CsrPattern& pattern, std::span<const Real> values,
                                           int refinement_steps, UmfpackOrdering ordering)
    : impl_(new Impl) {
  Impl& u = *impl_;
  const auto n = static_cast<SuiteSparse_long>(pattern.n_rows());
  u.ptr.assign(pattern.row_ptr.begin(), pattern.row_ptr.end());
  u.idx.assign(pattern.col_idx.begin(), pattern.col_idx.end());
  u.values.assign(values.begin(), values.end());
  u.x.resize(static_cast<std::size_t>(n));
  umfpack_dl_defaults(u.control);
  u.control[UMFPACK_IRSTEP] = refinement_steps;
  // METIS nested dissection: on the 40,000-cell cubic plate 27.6 CPU s for the modal analysis
  // against 35.5 s with UMFPACK's default (AMD/COLAMD) ordering.
  u.control[UMFPACK_ORDERING] = UMFPACK_ORDERING_METIS;
  try {
    SuiteSparse_long status = 0;
    if (ordering == UmfpackOrdering::SymmetricNestedDissection) {
      // The order is symmetric (of A + A^T), so it serves A^T, which UMFPACK sees, as well.
      const std::vector<Index> order = nested_dissection_order(pattern);
      const std::vector<SuiteSparse_long> q(order.begin(), order.end());
      u.control[UMFPACK_STRATEGY] = UMFPACK_STRATEGY_SYMMETRIC;
      u.control[UMFPACK_ORDERING] = UMFPACK_ORDERING_GIVEN;
      status = umfpack_dl_qsymbolic(n, n, u.ptr.data(), u.idx.data(), u.values.data(), q.data(),
                                    &u.symbolic, u.control, u.info);
    } else {
      status = umfpack_dl_symbolic(n, n, u.ptr.data(), u.idx.data(), u.values.data(), &u.symbolic,
                                   u.control, u.info);
    }
    if (status != UMFPACK_OK)
      throw SolverError(fmt::format("UMFPACK symbolic analysis failed (status {})", status));
    u.factorize();
  } catch (...) {
    delete impl_;
    throw;
  }
}

UmfpackFactorization::~UmfpackFactorization() { delete impl_; }

void UmfpackFactorization::refactor(std::span<const Real> values) {
  impl_->values.assign(values.begin(), values.end());
  impl_->factorize();
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

long UmfpackFactorization::factorizations() const { return impl_->factorizations; }

long UmfpackFactorization::factor_entries() const {
  // UMFPACK_LNZ and UMFPACK_UNZ both count the diagonal; L's is unit.
  return static_cast<long>(impl_->info[UMFPACK_LNZ] + impl_->info[UMFPACK_UNZ]) -
         static_cast<long>(impl_->x.size());
}

}  // namespace rfmems
