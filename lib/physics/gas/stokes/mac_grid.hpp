// Uniform Cartesian staggered (MAC, Harlow and Welch 1965) grid over the rectangle
// [0, width] x [0, height], spacing h in both directions, with rectangular solid blocks whose
// edges lie on grid lines (the beam of the gas damping case). Indices:
//   cell (i, j), 0 <= i < nx, 0 <= j < ny:   centre ((i + 1/2) h, (j + 1/2) h), pressure
//   u-face (i, j), 0 <= i <= nx, j < ny:    ( i h, (j + 1/2) h), x-velocity
//   v-face (i, j), i < nx, 0 <= j <= ny:    ((i + 1/2) h, j h), y-velocity
//   node (i, j), 0 <= i <= nx, 0 <= j <= ny: (i h, j h), shear stress
// A cell is fluid unless it lies inside a block; everything outside the index ranges is
// neither fluid nor solid (the domain's sides).
#pragma once
#include <Eigen/Dense>
#include <vector>

#include "core/types.hpp"

namespace rfmems {

using Point2 = Eigen::Vector2d;

// An axis-aligned solid rectangle [x0, x1] x [y0, y1].
struct SolidBlock {
  Real x0 = 0, x1 = 0, y0 = 0, y1 = 0;
};

class MacGrid {
 public:
  // Throws InputError unless width, height and every block edge are whole multiples of h.
  MacGrid(Real width, Real height, Real h, std::vector<SolidBlock> blocks = {});

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  Real h() const { return h_; }
  const std::vector<SolidBlock>& blocks() const { return blocks_; }

  bool in_range(int i, int j) const { return i >= 0 && i < nx_ && j >= 0 && j < ny_; }
  // The block containing cell (i, j), or -1 (fluid, or outside the index ranges).
  int block_of(int i, int j) const { return in_range(i, j) ? block_[i + nx_ * j] : -1; }
  bool fluid(int i, int j) const { return in_range(i, j) && block_[i + nx_ * j] < 0; }
  Index fluid_cells() const { return fluid_cells_; }

  Point2 cell_centre(int i, int j) const { return {(i + 0.5) * h_, (j + 0.5) * h_}; }
  Point2 u_face(int i, int j) const { return {i * h_, (j + 0.5) * h_}; }
  Point2 v_face(int i, int j) const { return {(i + 0.5) * h_, j * h_}; }
  Point2 node(int i, int j) const { return {i * h_, j * h_}; }

 private:
  int nx_, ny_;
  Real h_;
  std::vector<SolidBlock> blocks_;
  std::vector<int> block_;
  Index fluid_cells_ = 0;
};

}  // namespace rfmems
