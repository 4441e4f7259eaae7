// Boundary conditions of the squeeze-film Reynolds equation, one per mesh patch (an edge of
// the plate's mid-surface mesh):
//   Open  the film vents to the surrounding gas: p = p_ambient at the edge (the face centroid,
//         half a cell from the last centroid). Fine for edges whose gap is small against the
//         plate size; the end effect (the film continuing ~1 gap past the edge, Veijola's
//         elongation) is not modelled.
//   Wall  a sealed edge (or a symmetry line): zero mass flux.
#pragma once

namespace rfmems {

struct FilmBoundary {
  enum class Kind { Open, Wall };
  Kind kind = Kind::Wall;
};

}  // namespace rfmems
