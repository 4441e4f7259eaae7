// Sparsity of an FV Jacobian with dense b x b blocks per (cell, cell) pair, flattened to
// scalar CSR (row = cell*b + component). The pattern is built once from each cell's stencil;
// values are then refilled block by block.
#pragma once
#include <set>
#include <span>
#include <vector>

#include "core/system_operator.hpp"

namespace rfmems {

class BlockSparsity {
 public:
  // stencils[c]: the cells whose unknowns appear in the equations of cell c.
  BlockSparsity(const std::vector<std::set<Index>>& stencils, int block_size);
  const CsrPattern& pattern() const { return pattern_; }
  int block_size() const { return b_; }
  // Adds the top-left b x b part of `block` at block (row_cell, col_cell).
  void add_block(std::span<Real> values, Index row_cell, Index col_cell, const Mat3& block) const;
  // Adds a scalar at (row, col) of the scalar matrix.
  void add(std::span<Real> values, Index row, Index col, Real value) const;

 private:
  Index block_slot(Index row_cell, Index col_cell) const;
  int b_;
  std::vector<Index> block_row_ptr_{0}, block_cols_;
  CsrPattern pattern_;
};

}  // namespace rfmems
