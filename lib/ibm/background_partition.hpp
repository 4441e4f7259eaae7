// The immersed background's partition under MPI, shared by the distributed
// ESBGK gas and the distributed electrostatics: METIS k-way on the background's cell graph,
// weight 16 for a cell FLUID at the given (rest) marking and 1 otherwise (the work is per
// FLUID cell), computed on the root and broadcast so that every rank holds the same answer
// whatever METIS does. Fixed for the run: a cell keeps its owner across re-markings.
#pragma once
#include "ibm/cell_marking.hpp"
#include "mesh/mesh.hpp"
#include "mesh/partition.hpp"
#include "parallel/communicator.hpp"

namespace rfmems {

// One part per rank of comm; part, edge_cut and imbalance the same on every rank.
// Collective.
Partition partition_fluid_background(const Mesh& background, const CellMarking& rest,
                                     const Communicator& comm);

}  // namespace rfmems
