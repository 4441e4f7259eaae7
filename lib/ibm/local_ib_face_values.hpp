// The IB-face distributions of one rank's part of the immersed gas (fluid_graph_part.hpp): the
// ExternalFaceValues of the local KineticOperator's "immersed" patch, computed by the global
// IbKineticFaceValues (the thesis's three steps, unchanged) on every rank.
//
// update(f_local, owner values) copies the IB band's cells of the local distribution into a
// distribution on the global FLUID graph (and this part's IB faces' owner values onto the
// global faces) and runs the global update on it; fill(local face) asks the global object for
// its global face with the owner's values given. Cells outside the band are NaN in the
// global copy: a stencil reaching beyond the band would give NaN face values, and
// covers_every_stencil() checks this once per set of fits (every IB face and every ordinate
// finite), so a too-thin band fails loudly instead of reading stale data.
//
// The values are the serial ones bit for bit when the band cells hold the serial values: the
// same fits, the same sums in the same order.
#pragma once
#include <span>
#include <vector>

#include "core/types.hpp"
#include "ibm/fluid_graph_part.hpp"
#include "ibm/ib_kinetic_face_values.hpp"
#include "physics/gas/kinetic/external_face_values.hpp"

namespace rfmems {

class LocalIbFaceValues : public ExternalFaceValues {
 public:
  // global_values: on the global FLUID graph `global`; both and `part` must outlive this.
  // buffer: the global copy, kept by the caller across the objects made for one part (only
  // band cells are ever written, so the rest stays NaN without a refill each step: a 50 MB
  // fill per set_body on the case scene); empty or of another size, it is (re)filled with NaN.
  // The caller must clear it when the part changes.
  LocalIbFaceValues(IbKineticFaceValues& global_values, const FluidFaceGraph& global,
                    const FluidGraphPart& part, Index n_ordinates, std::vector<Real>& buffer);

  void update(std::span<const Real> f, std::span<const Real> owner_values) override;
  void fill(Index face, std::span<const Real> owner_values, std::span<Real> out) const override;

  // Runs the global update with 1 in every band cell and NaN elsewhere: true if every IB
  // face's values come out finite (the band covers every stencil). Overwrites the last
  // update (call update() afterwards).
  bool covers_every_stencil();

 private:
  IbKineticFaceValues& global_values_;
  const FluidFaceGraph& global_;
  const FluidGraphPart& part_;
  Index n_;
  std::vector<Real>& global_f_;     // per global FLUID cell x N; NaN outside the band
  std::vector<Real> global_owner_;  // per global boundary face x N: owners' values (ours)
};

}  // namespace rfmems
