#include "physics/structure/residual_stress.hpp"

#include <fmt/format.h>

namespace rfmems {

Mat3 read_residual_stress(const CaseNode& material, int dim, int film_axes) {
  const std::vector<Real> given =
      material.get_quantity_or_list("residual_stress", Dimension::Pressure, 0.0);
  Mat3 s = Mat3::Zero();
  if (given.size() == 1) {
    for (int i = 0; i < film_axes; ++i) s(i, i) = given[0];
    return s;
  }
  const std::size_t expected = dim == 3 ? 6 : 3;
  if (given.size() != expected)
    material.fail("residual_stress", dim == 3 ? "expected one stress or 6: [xx, yy, zz, yz, xz, xy]"
                                              : "expected one stress or 3: [xx, yy, xy]");
  if (dim == 3) {
    s << given[0], given[5], given[4], given[5], given[1], given[3], given[4], given[3], given[2];
  } else {
    s(0, 0) = given[0];
    s(1, 1) = given[1];
    s(0, 1) = s(1, 0) = given[2];
  }
  return s;
}

void require_released_edges_free(const CaseNode& material, const Mat3& sigma0, const Mesh& mesh,
                                 const std::function<bool(int patch)>& released) {
  const Real scale = sigma0.cwiseAbs().maxCoeff();
  if (scale == 0) return;
  for (std::size_t p = 0; p < mesh.patches().size(); ++p) {
    if (!released(static_cast<int>(p))) continue;
    const Patch& patch = mesh.patches()[p];
    for (Index f = patch.first_face; f < patch.first_face + patch.n_faces; ++f) {
      const Vec3 n = mesh.face_area(f).normalized();
      const Vec3 traction = sigma0 * n;
      if (traction.norm() <= 1e-9 * scale) continue;
      material.fail(
          "residual_stress",
          fmt::format("not in equilibrium at the unsupported edge '{}' (sigma n = [{:.4g}, "
                      "{:.4g}, {:.4g}] Pa there, a free edge carries none); give the stress the "
                      "released structure holds, e.g. [sigma (1 - nu), 0, 0] along a bridge "
                      "with free sides",
                      patch.name, traction.x(), traction.y(), traction.z()));
    }
  }
}

}  // namespace rfmems
