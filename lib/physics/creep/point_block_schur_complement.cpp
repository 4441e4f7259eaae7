#include "physics/creep/point_block_schur_complement.hpp"

#include <algorithm>
#include <stdexcept>

namespace rfmems {

PointBlockSchurComplement::PointBlockSchurComplement(const CsrPattern& pattern, Index n_structural,
                                                     Index group_size, int block)
    : ns_(n_structural), m_(group_size), block_(block) {
  const Index n = pattern.n_rows();
  if (group_size <= 0 || block <= 0 || group_size % block != 0 || (n - ns_) % group_size != 0)
    throw std::logic_error("PointBlockSchurComplement: states do not form groups of blocks");
  n_groups_ = (n - ns_) / m_;
  auto group_of = [&](Index col) { return (col - ns_) / m_; };
  rows_.assign(n_groups_, {});
  cols_.assign(n_groups_, {});
  for (Index r = 0; r < ns_; ++r)
    for (Index p = pattern.row_ptr[r]; p < pattern.row_ptr[r + 1]; ++p) {
      const Index col = pattern.col_idx[p];
      if (col < ns_) continue;
      std::vector<Index>& rows = rows_[group_of(col)];
      if (rows.empty() || rows.back() != r) rows.push_back(r);
    }
  for (Index g = 0; g < n_groups_; ++g) {
    std::vector<Index>& cols = cols_[g];
    for (Index q = ns_ + g * m_; q < ns_ + (g + 1) * m_; ++q)
      for (Index p = pattern.row_ptr[q]; p < pattern.row_ptr[q + 1]; ++p) {
        const Index col = pattern.col_idx[p];
        if (col < ns_) {
          cols.push_back(col);
        } else if ((col - ns_) / block_ != (q - ns_) / block_) {
          throw std::logic_error("PointBlockSchurComplement: a point's row reaches another point");
        }
      }
    std::sort(cols.begin(), cols.end());
    cols.erase(std::unique(cols.begin(), cols.end()), cols.end());
  }

  // S's pattern: K's and every R_g x C_g.
  std::vector<std::vector<Index>> s_rows(ns_);
  for (Index r = 0; r < ns_; ++r)
    for (Index p = pattern.row_ptr[r]; p < pattern.row_ptr[r + 1]; ++p)
      if (pattern.col_idx[p] < ns_) s_rows[r].push_back(pattern.col_idx[p]);
  for (Index g = 0; g < n_groups_; ++g)
    for (Index r : rows_[g]) s_rows[r].insert(s_rows[r].end(), cols_[g].begin(), cols_[g].end());
  pattern_ = CsrPattern{};
  for (std::vector<Index>& row : s_rows) {
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    pattern_.col_idx.insert(pattern_.col_idx.end(), row.begin(), row.end());
    pattern_.row_ptr.push_back(pattern_.nnz());
  }
  for (Index r = 0; r < ns_; ++r)
    for (Index p = pattern.row_ptr[r]; p < pattern.row_ptr[r + 1]; ++p)
      if (pattern.col_idx[p] < ns_)
        k_position_.emplace_back(p, pattern_.find(r, pattern.col_idx[p]));

  // Positions of P_g, G_g, the point blocks and S's R_g x C_g.
  p_position_.assign(n_groups_, {});
  g_position_.assign(n_groups_, {});
  d_position_.assign(n_groups_, {});
  s_position_.assign(n_groups_, {});
  for (Index g = 0; g < n_groups_; ++g) {
    const Index first = ns_ + g * m_;
    const std::vector<Index>&rows = rows_[g], &cols = cols_[g];
    std::vector<Index>& pp = p_position_[g];
    pp.assign(rows.size() * m_, -1);
    for (std::size_t a = 0; a < rows.size(); ++a)
      for (Index p = pattern.row_ptr[rows[a]]; p < pattern.row_ptr[rows[a] + 1]; ++p) {
        const Index col = pattern.col_idx[p];
        if (col >= first && col < first + m_) pp[a * m_ + (col - first)] = p;
      }
    std::vector<Index>& gp = g_position_[g];
    gp.assign(m_ * cols.size(), -1);
    std::vector<Index>& dp = d_position_[g];
    dp.assign(m_ * block_, -1);
    for (Index l = 0; l < m_; ++l)
      for (Index p = pattern.row_ptr[first + l]; p < pattern.row_ptr[first + l + 1]; ++p) {
        const Index col = pattern.col_idx[p];
        if (col < ns_)
          gp[l * cols.size() + (std::lower_bound(cols.begin(), cols.end(), col) - cols.begin())] =
              p;
        else
          dp[l * block_ + (col - first) % block_] = p;
      }
    std::vector<Index>& sp = s_position_[g];
    sp.reserve(rows.size() * cols.size());
    for (Index r : rows)
      for (Index c : cols) sp.push_back(pattern_.find(r, c));
  }
  values_.assign(pattern_.nnz(), 0.0);
  p_.resize(n_groups_);
  x_.resize(n_groups_);
  d_inverse_.resize(n_groups_ * (m_ / block_));
}

PointBlockSchurComplement::~PointBlockSchurComplement() = default;

void PointBlockSchurComplement::setup(std::span<const Real> values) {
  std::fill(values_.begin(), values_.end(), 0.0);
  for (const auto& [j, s] : k_position_) values_[s] += values[j];
  const Index points = m_ / block_;
  for (Index g = 0; g < n_groups_; ++g) {
    const Index nr = static_cast<Index>(rows_[g].size()), nc = static_cast<Index>(cols_[g].size());
    auto gather = [&](const std::vector<Index>& position, Index rows, Index cols) {
      Matrix a(rows, cols);
      for (Index k = 0; k < rows * cols; ++k)
        a.data()[k] = position[k] >= 0 ? values[position[k]] : 0.0;
      return a;
    };
    p_[g] = gather(p_position_[g], nr, m_);
    const Matrix G = gather(g_position_[g], m_, nc);
    const Matrix D = gather(d_position_[g], m_, block_);  // the point blocks, stacked
    Matrix& X = x_[g];
    X.resize(m_, nc);
    for (Index i = 0; i < points; ++i) {
      Matrix& inverse = d_inverse_[g * points + i];
      inverse = D.middleRows(i * block_, block_).inverse();
      X.middleRows(i * block_, block_) = inverse * G.middleRows(i * block_, block_);
    }
    const Matrix M = p_[g] * X;
    const std::vector<Index>& sp = s_position_[g];
    for (Index k = 0; k < nr * nc; ++k) values_[sp[k]] -= M.data()[k];
  }
  if (lu_)
    lu_->refactor(values_);
  else
    lu_ = std::make_unique<KluFactorization>(pattern_, values_, KluOrdering::Colamd);
  ++factorizations_;
}

void PointBlockSchurComplement::solve(std::span<const Real> r, std::span<Real> z) {
  if (!lu_) throw std::logic_error("PointBlockSchurComplement: solve before setup");
  const Index points = m_ / block_;
  // z_q' = D^-1 r_q (into z's q part).
  for (Index g = 0; g < n_groups_; ++g)
    for (Index i = 0; i < points; ++i) {
      const Index first = ns_ + g * m_ + i * block_;
      Eigen::Map<const Eigen::VectorXd> rq(r.data() + first, block_);
      Eigen::Map<Eigen::VectorXd>(z.data() + first, block_) = d_inverse_[g * points + i] * rq;
    }
  // z_y = S^-1 (r_y - P z_q').
  rhs_.assign(r.begin(), r.begin() + ns_);
  for (Index g = 0; g < n_groups_; ++g) {
    const Eigen::VectorXd pz =
        p_[g] * Eigen::Map<const Eigen::VectorXd>(z.data() + ns_ + g * m_, m_);
    for (std::size_t a = 0; a < rows_[g].size(); ++a) rhs_[rows_[g][a]] -= pz[a];
  }
  lu_->solve(rhs_);
  std::copy(rhs_.begin(), rhs_.end(), z.begin());
  // z_q = z_q' - D^-1 G z_y.
  for (Index g = 0; g < n_groups_; ++g) {
    Eigen::VectorXd zy(cols_[g].size());
    for (std::size_t c = 0; c < cols_[g].size(); ++c) zy[c] = rhs_[cols_[g][c]];
    Eigen::Map<Eigen::VectorXd>(z.data() + ns_ + g * m_, m_) -= x_[g] * zy;
  }
}

}  // namespace rfmems
