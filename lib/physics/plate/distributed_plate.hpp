// The FV Mindlin-Reissner plate operator on a distributed mesh: the serial
// PlateOperator on each rank's local mesh (parallel/distributed_local_operator.hpp), its
// edges' conditions by patch name, the cut through the last ghost layer clamped (only that
// layer's rows see it), pressure, point loads on the cells the rank holds and the
// reconstruction degree of the global operator. Six ghost layers (measured, not derived: with
// four, some owned rows' local patterns hold entries the serial pattern lacks): the owned
// Jacobian rows equal the serial ones to 7.8e-19 of max |K|, entries outside the serial
// pattern are below that, and a clamped 16 x 16 plate's static solution equals the serial KLU
// one to 2e-11 on 2 and 3 ranks (test/mpi/test_distributed_structure.cpp).
//
// Static solves only: a plate transient neglects the rotary inertia
// (core/reduced_inertia_system.hpp), which has no distributed counterpart yet.
#pragma once
#include "parallel/distributed_local_operator.hpp"
#include "physics/plate/plate_operator.hpp"

namespace rfmems {

class DistributedPlate : public DistributedLocalOperator {
 public:
  static constexpr int kGhostLayers = 6;  // see above
  // Collective.
  DistributedPlate(const PlateOperator& global, const Communicator& comm);
};

}  // namespace rfmems
