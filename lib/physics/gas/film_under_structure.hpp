// The Reynolds film under a structure's cells as a partitioned coupling steps it
// (structure_gas.hpp): film cell c lies under the structure unknown gap_unknown[c] (a plate's
// w), its gap g0 + u[gap_unknown[c]]; each advance steps the film under that gap, linear in
// time over the step (prescribed_gap_film.hpp), and loads the unknown with (p_c - p_a) A_c (a
// compressed film pushes the structure away from the electrode). The monolithic system
// (coupling/squeeze_film_switch_system.hpp) couples the same film with exact blocks.
#pragma once
#include <memory>
#include <vector>

#include "physics/gas/prescribed_gap_film.hpp"
#include "physics/gas/reynolds_film.hpp"
#include "physics/gas/structure_gas.hpp"

namespace rfmems {

class FilmUnderStructure : public StructureGas {
 public:
  // film outlives this; structure_size: the structure's unknowns; rest_gap: g0.
  FilmUnderStructure(const ReynoldsFilm& film, std::vector<Index> gap_unknown, Index structure_size,
                     Real rest_gap, Real rtol = 1e-6);

  std::string name() const override { return "reynolds"; }
  void reset(Real t0) override;
  StructureLoad advance(std::span<const Real> u, std::span<const Real> v, Real t, Real dt) override;
  void save_checkpoint() override { stepper().save_checkpoint(); }
  void restore_checkpoint() override { stepper().restore_checkpoint(); }
  Real max_knudsen() const override { return stepped_ ? stepped_->max_knudsen() : 0; }

 private:
  PrescribedGapFilm& stepper();
  const ReynoldsFilm& film_;
  std::vector<Index> gap_unknown_;
  Index structure_size_;
  Real rest_gap_, rtol_;
  std::unique_ptr<PrescribedGapFilm> stepped_;
};

}  // namespace rfmems
