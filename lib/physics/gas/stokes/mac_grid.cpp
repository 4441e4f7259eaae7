// Uniform staggered grid with aligned solid blocks: see mac_grid.hpp.
#include "physics/gas/stokes/mac_grid.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"

namespace rfmems {

namespace {

// n with n h = length to 1e-9 of a cell, or InputError naming what is not aligned.
int whole_cells(Real length, Real h, const std::string& what) {
  const Real n = length / h;
  if (!(h > 0) || std::abs(n - std::round(n)) > 1e-9 * std::max(1.0, n) || n < 0)
    throw InputError("MacGrid: " + what + " = " + std::to_string(length) +
                     " m is not a whole number of cells of h = " + std::to_string(h) + " m");
  return static_cast<int>(std::round(n));
}

}  // namespace

MacGrid::MacGrid(Real width, Real height, Real h, std::vector<SolidBlock> blocks)
    : nx_(whole_cells(width, h, "width")),
      ny_(whole_cells(height, h, "height")),
      h_(h),
      blocks_(std::move(blocks)),
      block_(static_cast<std::size_t>(nx_) * ny_, -1) {
  if (nx_ < 1 || ny_ < 1) throw InputError("MacGrid: the rectangle holds no cell");
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    const SolidBlock& s = blocks_[b];
    const std::string name = "block " + std::to_string(b);
    const int i0 = whole_cells(s.x0, h, name + " x0"), i1 = whole_cells(s.x1, h, name + " x1");
    const int j0 = whole_cells(s.y0, h, name + " y0"), j1 = whole_cells(s.y1, h, name + " y1");
    if (i1 <= i0 || j1 <= j0 || i1 > nx_ || j1 > ny_)
      throw InputError("MacGrid: " + name + " is empty or leaves the rectangle");
    for (int j = j0; j < j1; ++j)
      for (int i = i0; i < i1; ++i) block_[i + nx_ * j] = static_cast<int>(b);
  }
  for (int b : block_) fluid_cells_ += b < 0;
}

}  // namespace rfmems
