#include "ibm/local_ib_face_values.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rfmems {

LocalIbFaceValues::LocalIbFaceValues(IbKineticFaceValues& global_values,
                                     const FluidFaceGraph& global, const FluidGraphPart& part,
                                     Index n_ordinates, std::vector<Real>& buffer)
    : global_values_(global_values),
      global_(global),
      part_(part),
      n_(n_ordinates),
      global_f_(buffer) {
  const std::size_t n = static_cast<std::size_t>(global.graph.n_cells() * n_ordinates);
  if (global_f_.size() != n) global_f_.assign(n, std::numeric_limits<Real>::quiet_NaN());
}

void LocalIbFaceValues::update(std::span<const Real> f) {
  for (const Index c : part_.band)
    std::copy_n(f.data() + c * n_, n_, global_f_.data() + part_.global_cell[c] * n_);
  global_values_.update(global_f_);
}

void LocalIbFaceValues::fill(Index face, std::span<const Real> f, std::span<Real> out) const {
  const Index owner = part_.local.graph.face_owner[face];
  std::copy_n(f.data() + owner * n_, n_, global_f_.data() + part_.global_cell[owner] * n_);
  global_values_.fill(part_.global_face[face], global_f_, out);
}

bool LocalIbFaceValues::covers_every_stencil() {
  for (const Index c : part_.band)
    std::fill_n(global_f_.data() + part_.global_cell[c] * n_, n_, 1.0);
  global_values_.update(global_f_);
  const FaceGraph& g = global_.graph;
  std::vector<Real> out(n_);
  bool ok = true;
  for (Index face = g.n_interior_faces; face < g.n_faces() && ok; ++face) {
    if (global_.ib_face[face] < 0) continue;
    global_values_.fill(face, global_f_, out);
    ok = std::all_of(out.begin(), out.end(), [](Real x) { return std::isfinite(x); });
  }
  return ok;
}

}  // namespace rfmems
