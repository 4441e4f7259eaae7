// One rank's part of the immersed gas's FLUID graph (fluid_face_graph.hpp) under
// MPI: the FLUID cells of the background cells this rank owns, then ghost FLUID cells, with
// the faces of the owned cells and a GhostExchange over them.
//
// Why every rank holds the global FLUID graph and restricts it here: the marking, the IB
// fits and the structure are O(surface) and deterministic, so every rank computes them from
// the same global data and no geometry travels; only the distribution's ghost values do.
// The background's partition is fixed (it is the background's, METIS once), so a cell keeps
// its owner across re-markings.
//
// Ghosts, two kinds:
//   - transport: the FLUID face neighbours of owned FLUID cells (the upwind stencil);
//   - the IB band: every FLUID cell within `band_rings` background face rings of a non-FLUID
//     cell, on every rank. The IB-face values (IbKineticFaceValues, the thesis's three steps)
//     are computed redundantly on every rank from the global fits, which read FLUID cells up
//     to 4 rings from the seed of a surface point and 3 from an IB face's FLUID cell
//     (IbInterpolation's ring caps); the band holds those values current after each sweep.
//     LocalIbFaceValues (local_ib_face_values.hpp) checks that the band covers every stencil.
// Owned cells are in ascending global FLUID order, ghosts after them in ascending global
// order; faces keep the global graph's order (interior first, then the outer patches and the
// IB faces), so a cell sums its face fluxes in the serial order.
//
// The local FluidFaceGraph's fluid_cell maps a background cell to its LOCAL index (-1: not
// FLUID or not held here); ib_face maps a local face to its IB face (marking order).
#pragma once
#include <span>
#include <vector>

#include "core/types.hpp"
#include "fv/face_graph.hpp"
#include "ibm/cell_marking.hpp"
#include "ibm/fluid_face_graph.hpp"
#include "parallel/communicator.hpp"
#include "parallel/ghost_exchange.hpp"

namespace rfmems {

struct FluidGraphPart {
  FluidFaceGraph local;                // owned FLUID cells, then ghosts; faces of owned cells
  std::vector<Index> global_cell;      // per local cell: its index in the global FLUID graph
  std::vector<int> owner_rank;         // per local cell
  std::vector<Index> global_face;      // per local face: the global FLUID graph's face
  std::vector<Index> band;             // local cells in the IB band (owned or ghost)
  std::vector<Index> local_of_global;  // per global FLUID cell: local index, -1 if not held
  GhostExchange exchange;              // collective to build: every rank of comm together
};

// background: the face graph of the marked mesh; part: owner rank per background cell.
// Collective over comm (the GhostExchange).
FluidGraphPart restrict_fluid_graph(const FluidFaceGraph& global, const FaceGraph& background,
                                    const CellMarking& marking, std::span<const int> part,
                                    const Communicator& comm, int band_rings);

}  // namespace rfmems
