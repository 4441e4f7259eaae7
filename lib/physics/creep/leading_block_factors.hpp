// The LU factors of the leading n x n block of a CSR matrix known by its first n rows: a creep
// system's structural tangent (its structural rows' columns of structural unknowns), which
// equilibrate() and the Schur-complement preconditioner factorise when a relaxing residual
// stress makes it depend on the creep state. The block's pattern is taken once; its values are
// gathered from the rows' and refactorised at each call (solvers/sparse_lu.hpp: KLU keeping its
// pivots, or UMFPACK on its symbolic analysis).
#pragma once
#include <memory>
#include <span>
#include <vector>

#include "core/system_operator.hpp"
#include "solvers/sparse_lu.hpp"

namespace rfmems {

class LeadingBlockFactors {
 public:
  // The block of `pattern`'s first n rows and columns; n = 0: none.
  void set_pattern(const CsrPattern& pattern, Index n) {
    block_ = CsrPattern{};
    source_.clear();
    lu_.reset();
    for (Index row = 0; row < n; ++row) {
      for (Index p = pattern.row_ptr[row]; p < pattern.row_ptr[row + 1]; ++p)
        if (pattern.col_idx[p] < n) {
          block_.col_idx.push_back(pattern.col_idx[p]);
          source_.push_back(p);
        }
      block_.row_ptr.push_back(block_.nnz());
    }
  }
  // The factors of the block of `rows` (the first n rows' values, in the pattern's order).
  SparseLu& factorize(std::span<const Real> rows) {
    values_.resize(source_.size());
    for (std::size_t k = 0; k < source_.size(); ++k) values_[k] = rows[source_[k]];
    if (lu_)
      lu_->refactor(values_);
    else
      lu_ = std::make_unique<SparseLu>(block_, values_);
    return *lu_;
  }
  // Forget the factors (a new pattern of the rows follows).
  void reset() { lu_.reset(); }

 private:
  CsrPattern block_;
  std::vector<Index> source_;  // the block's entries' positions in the rows
  std::vector<Real> values_;
  std::unique_ptr<SparseLu> lu_;
};

}  // namespace rfmems
