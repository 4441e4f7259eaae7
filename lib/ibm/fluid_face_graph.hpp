// The FaceGraph of the FLUID cells of a marked background mesh: the domain of the immersed
// kinetic gas (immersed_kinetic_gas.hpp). Its boundary faces are the background's boundary
// faces of FLUID cells (their patches kept) and the IB faces (FLUID | non-FLUID), gathered on
// one extra patch "immersed" whose face values come from the IB interpolation.
//
// Why a graph of the FLUID cells rather than the whole background with inactive cells: the
// kinetic operator, its sweeps and its mass and force integrals then need no notion of an
// inactive cell (no edit of lib/physics/gas/kinetic beyond the External boundary kind), and a
// non-FLUID cell costs nothing. The price is a rebuild when a cell changes class (O(cells),
// measured ~ms on 150 x 50; see docs/ibm.md), after which the distribution is carried over by
// background cell (ImmersedKineticGas::set_body).
//
// IB face area vectors point out of the FLUID cell (the face's owner here), as
// CellMarking::ib_face_normal does.
#pragma once
#include <vector>

#include "core/types.hpp"
#include "fv/face_graph.hpp"
#include "ibm/cell_marking.hpp"

namespace rfmems {

struct FluidFaceGraph {
  FaceGraph graph;                     // FLUID cells; background patches, then "immersed"
  std::vector<Index> background_cell;  // per graph cell
  std::vector<Index> fluid_cell;       // per background cell, -1 if not FLUID
  std::vector<Index> ib_face;          // per graph face: index into marking.ib_faces, or -1
  int immersed_patch = -1;
};

// `background` is face_graph_of(the marked mesh).
FluidFaceGraph fluid_face_graph(const FaceGraph& background, const CellMarking& marking);

}  // namespace rfmems
