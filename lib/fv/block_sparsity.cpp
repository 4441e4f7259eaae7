#include "fv/block_sparsity.hpp"

#include <algorithm>
#include <stdexcept>

namespace rfmems {

BlockSparsity::BlockSparsity(const std::vector<std::set<Index>>& stencils, int block_size)
    : b_(block_size) {
  for (const auto& s : stencils) {
    block_cols_.insert(block_cols_.end(), s.begin(), s.end());  // std::set: sorted
    block_row_ptr_.push_back(static_cast<Index>(block_cols_.size()));
  }
  const Index n_block_rows = static_cast<Index>(stencils.size());
  for (Index r = 0; r < n_block_rows; ++r)
    for (int i = 0; i < b_; ++i) {
      for (Index k = block_row_ptr_[r]; k < block_row_ptr_[r + 1]; ++k)
        for (int j = 0; j < b_; ++j) pattern_.col_idx.push_back(block_cols_[k] * b_ + j);
      pattern_.row_ptr.push_back(pattern_.nnz());
    }
}

Index BlockSparsity::block_slot(Index row_cell, Index col_cell) const {
  auto first = block_cols_.begin() + block_row_ptr_[row_cell];
  auto last = block_cols_.begin() + block_row_ptr_[row_cell + 1];
  auto it = std::lower_bound(first, last, col_cell);
  if (it == last || *it != col_cell)
    throw std::logic_error("BlockSparsity: entry outside the stencil");
  return static_cast<Index>(it - first);
}

void BlockSparsity::add_block(std::span<Real> values, Index row_cell, Index col_cell,
                              const Mat3& block) const {
  const Index slot = block_slot(row_cell, col_cell);
  for (int i = 0; i < b_; ++i) {
    Index base = pattern_.row_ptr[row_cell * b_ + i] + slot * b_;
    for (int j = 0; j < b_; ++j) values[base + j] += block(i, j);
  }
}

void BlockSparsity::add(std::span<Real> values, Index row, Index col, Real value) const {
  const Index row_cell = row / b_, i = row % b_;
  const Index col_cell = col / b_, j = col % b_;
  values[pattern_.row_ptr[row_cell * b_ + i] + block_slot(row_cell, col_cell) * b_ + j] += value;
}

}  // namespace rfmems
