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

void LocalIbFaceValues::update(std::span<const Real> f, std::span<const Real> owner_values) {
  for (const Index c : part_.band)
    std::copy_n(f.data() + c * n_, n_, global_f_.data() + part_.global_cell[c] * n_);
  // The owners' values at this part's IB faces, on the global graph's boundary faces (the
  // other ranks' IB faces keep older values: their factors are never read here).
  const FaceGraph& local = part_.local.graph;
  const Index g0 = global_.graph.n_interior_faces;
  global_owner_.resize((global_.graph.n_faces() - g0) * n_);
  for (Index face = local.n_interior_faces; face < local.n_faces(); ++face)
    if (part_.local.ib_face[face] >= 0)
      std::copy_n(owner_values.data() + (face - local.n_interior_faces) * n_, n_,
                  global_owner_.data() + (part_.global_face[face] - g0) * n_);
  global_values_.update(global_f_, global_owner_);
}

void LocalIbFaceValues::fill(Index face, std::span<const Real> owner_values,
                             std::span<Real> out) const {
  global_values_.fill(part_.global_face[face], owner_values, out);
}

bool LocalIbFaceValues::covers_every_stencil() {
  for (const Index c : part_.band)
    std::fill_n(global_f_.data() + part_.global_cell[c] * n_, n_, 1.0);
  const FaceGraph& g = global_.graph;
  global_owner_.assign((g.n_faces() - g.n_interior_faces) * n_, 1.0);
  global_values_.update(global_f_, global_owner_);
  std::vector<Real> out(n_);
  const std::vector<Real> owner(n_, 1.0);
  bool ok = true;
  for (Index face = g.n_interior_faces; face < g.n_faces() && ok; ++face) {
    if (global_.ib_face[face] < 0) continue;
    global_values_.fill(face, owner, out);
    ok = std::all_of(out.begin(), out.end(), [](Real x) { return std::isfinite(x); });
  }
  return ok;
}

}  // namespace rfmems
