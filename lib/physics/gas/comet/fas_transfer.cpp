#include "physics/gas/comet/fas_transfer.hpp"

#include <algorithm>

namespace rfmems {

void restrict_solution(const FaceGraph& fine, const Agglomeration& a, Index block,
                       std::span<const Real> fine_values, std::span<Real> coarse_values) {
  std::fill(coarse_values.begin(), coarse_values.end(), 0.0);
  for (Index c = 0; c < fine.n_owned_cells; ++c) {
    const Index k = a.coarse_of_fine[c];
    const Real w = fine.cell_volume[c] / a.coarse.cell_volume[k];
    const Real* src = &fine_values[c * block];
    Real* dst = &coarse_values[k * block];
    for (Index i = 0; i < block; ++i) dst[i] += w * src[i];
  }
}

void restrict_residual(const Agglomeration& a, Index block, std::span<const Real> fine_values,
                       std::span<Real> coarse_values) {
  std::fill(coarse_values.begin(), coarse_values.end(), 0.0);
  const Index nf = static_cast<Index>(a.coarse_of_fine.size());
  const Index n_coarse_owned = a.coarse.n_owned_cells;
  for (Index c = 0; c < nf; ++c) {
    if (a.coarse_of_fine[c] >= n_coarse_owned) continue;  // a fine ghost
    const Real* src = &fine_values[c * block];
    Real* dst = &coarse_values[a.coarse_of_fine[c] * block];
    for (Index i = 0; i < block; ++i) dst[i] += src[i];
  }
}

void prolong_correction(const Agglomeration& a, Index block,
                        std::span<const Real> coarse_correction, std::span<Real> fine_values) {
  const Index nf = static_cast<Index>(a.coarse_of_fine.size());
  const Index n_coarse_owned = a.coarse.n_owned_cells;
  for (Index c = 0; c < nf; ++c) {
    if (a.coarse_of_fine[c] >= n_coarse_owned) continue;  // a fine ghost
    const Real* src = &coarse_correction[a.coarse_of_fine[c] * block];
    Real* dst = &fine_values[c * block];
    for (Index i = 0; i < block; ++i) dst[i] += src[i];
  }
}

}  // namespace rfmems
