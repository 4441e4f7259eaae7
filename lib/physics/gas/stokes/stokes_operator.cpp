// Stokes flow on a MAC grid, staggered finite volumes in stress-divergence form: see
// stokes_operator.hpp.
#include "physics/gas/stokes/stokes_operator.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace rfmems {

namespace {

// Offsets along a direction: d = 0 (x, the u faces) or 1 (y, the v faces).
struct Offset {
  int di, dj;
};
constexpr Offset kAlong[2] = {{1, 0}, {0, 1}};

}  // namespace

StokesOperator::StokesOperator(const MacGrid& grid, StokesProblem problem)
    : grid_(grid), problem_(std::move(problem)) {
  if (!(problem_.viscosity > 0)) throw InputError("StokesOperator: viscosity must be > 0");
  if (problem_.boundaries.blocks.size() != grid_.blocks().size())
    throw InputError("StokesOperator: one wall condition per solid block is needed");
  const int nx = grid_.nx(), ny = grid_.ny();
  u_index_.assign(static_cast<std::size_t>(nx + 1) * ny, -1);
  v_index_.assign(static_cast<std::size_t>(nx) * (ny + 1), -1);
  p_index_.assign(static_cast<std::size_t>(nx) * ny, -1);
  // Number the unknown faces: gas on both sides, or gas on one side and an open side on the
  // other (the face() test below, before any index exists, sees them as terms).
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      auto f = face(i, j, true);
      if (f && !f->terms.empty()) u_index_[i + (nx + 1) * j] = n_++;
    }
  n_u_ = n_;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i < nx; ++i) {
      auto f = face(i, j, false);
      if (f && !f->terms.empty()) v_index_[i + nx * j] = n_++;
    }
  n_v_ = n_ - n_u_;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      if (grid_.fluid(i, j)) p_index_[i + nx * j] = n_++;
  bool open = false;
  for (const StokesSide& s : problem_.boundaries.sides) open |= s.kind == StokesSide::Kind::Open;
  if (!open) throw InputError("StokesOperator: no open side fixes the pressure level");
  assemble();
}

Across StokesOperator::across_cell(int i, int j, Side beyond) const {
  if (grid_.in_range(i, j))
    return grid_.fluid(i, j) ? Across{} : Across::block(grid_.block_of(i, j));
  return Across::side(beyond);
}

std::optional<AffineForm> StokesOperator::face(int i, int j, bool vertical) const {
  const int nx = grid_.nx(), ny = grid_.ny();
  const int d = vertical ? 0 : 1;
  if (vertical ? (i < 0 || i > nx || j < 0 || j >= ny) : (i < 0 || i >= nx || j < 0 || j > ny))
    return std::nullopt;
  const auto& index = vertical ? u_index_ : v_index_;
  const Index k = vertical ? index[i + (nx + 1) * j] : index[i + nx * j];
  if (k >= 0) return AffineForm::unknown(k);
  const int bi = i - kAlong[d].di, bj = j - kAlong[d].dj;  // the cell before the face
  const bool before = grid_.fluid(bi, bj), after = grid_.fluid(i, j);
  if (before == after) {
    if (!before) return std::nullopt;
    return AffineForm::unknown(-1);  // interior; numbered in the constructor
  }
  const Point2 at = vertical ? grid_.u_face(i, j) : grid_.v_face(i, j);
  const Side beyond =
      vertical ? (before ? Side::Right : Side::Left) : (before ? Side::Top : Side::Bottom);
  const Across wall = before ? across_cell(i, j, beyond) : across_cell(bi, bj, beyond);
  if (wall.kind == Across::Kind::Block)
    return AffineForm::known(problem_.boundaries.blocks[wall.index].velocity(at)[d]);
  const StokesSide& side = problem_.boundaries.sides[wall.index];
  switch (side.kind) {
    case StokesSide::Kind::Wall:
      return AffineForm::known(side.wall.velocity(at)[d]);
    case StokesSide::Kind::Symmetry:
      return AffineForm::known(0.0);
    case StokesSide::Kind::Open:
      return AffineForm::unknown(-1);
  }
  return std::nullopt;
}

std::optional<AffineForm> StokesOperator::u(int i, int j) const { return face(i, j, true); }
std::optional<AffineForm> StokesOperator::v(int i, int j) const { return face(i, j, false); }

AffineForm StokesOperator::pressure(int i, int j) const {
  return AffineForm::unknown(p_index_[i + grid_.nx() * j]);
}

AffineForm StokesOperator::sigma_xx(int i, int j) const {
  return (2 * problem_.viscosity / grid_.h()) * (*u(i + 1, j) - *u(i, j)) - pressure(i, j);
}

AffineForm StokesOperator::sigma_yy(int i, int j) const {
  return (2 * problem_.viscosity / grid_.h()) * (*v(i, j + 1) - *v(i, j)) - pressure(i, j);
}

AffineForm StokesOperator::shear(int i, int j) const {
  const Real h = grid_.h();
  const Point2 at = grid_.node(i, j);
  auto u_above = u(i, j), u_below = u(i, j - 1), v_right = v(i, j), v_left = v(i - 1, j);
  if ((!u_above && !u_below) || (!v_right && !v_left)) return {};
  bool wall = false, zero_stress = false;
  // The boundary along the line beyond the node, between cells a and b (neither is gas):
  // a block if either is one, else the side that line is.
  auto ghost = [&](int ai, int aj, int bi, int bj, Side side, int tangential,
                   const AffineForm& inside) {
    const int block = std::max(grid_.block_of(ai, aj), grid_.block_of(bi, bj));
    if (block >= 0) {
      wall = true;
      return wall_tangential_ghost(problem_.boundaries.blocks[block], at, tangential, inside, h);
    }
    const StokesSide& s = problem_.boundaries.side(side);
    wall |= s.kind == StokesSide::Kind::Wall;
    zero_stress |= s.kind == StokesSide::Kind::Open && s.tangential == OpenTangential::ZeroStress;
    return side_tangential_ghost(s, at, tangential, inside, h);
  };
  if (!u_above) u_above = ghost(i - 1, j, i, j, Side::Top, 0, *u_below);
  if (!u_below) u_below = ghost(i - 1, j - 1, i, j - 1, Side::Bottom, 0, *u_above);
  if (!v_right) v_right = ghost(i, j - 1, i, j, Side::Right, 1, *v_left);
  if (!v_left) v_left = ghost(i - 1, j - 1, i - 1, j, Side::Left, 1, *v_right);
  // ZeroStress: tau = 0 on the open side, except where it meets a wall (a corner node on the
  // wall's line, whose shear the wall's gas cells need).
  if (zero_stress && !wall) return {};
  return (problem_.viscosity / h) * (*u_above - *u_below + *v_right - *v_left);
}

// The gas part of face (i, j)'s control volume, d the momentum component (0: u face, x; 1: v
// face, y) and t the other direction: edges normal to d at the centres of the cells before and
// after the face (sigma_dd), and the two edges along d, each split into the halves over those
// cells, at the nodes (i, j) and (i, j) + e_t (tau).
ControlVolumeBalance StokesOperator::balance(int i, int j, bool vertical) const {
  const int d = vertical ? 0 : 1, t = 1 - d;
  const Real h = grid_.h();
  const Offset ed = kAlong[d], et = kAlong[t];
  const int bi = i - ed.di, bj = j - ed.dj;
  const bool before = grid_.fluid(bi, bj), after = grid_.fluid(i, j);
  const Point2 at = vertical ? grid_.u_face(i, j) : grid_.v_face(i, j);
  const Side after_side = vertical ? Side::Right : Side::Top;
  const Side before_side = vertical ? Side::Left : Side::Bottom;
  const Side plus_side = vertical ? Side::Top : Side::Right;
  const Side minus_side = vertical ? Side::Bottom : Side::Left;
  auto normal_stress = [&](int ci, int cj) {
    return vertical ? sigma_xx(ci, cj) : sigma_yy(ci, cj);
  };
  ControlVolumeBalance b;
  // The edge normal to d on one side (sign +1 after the face, -1 before it).
  auto normal_edge = [&](bool gas, int ci, int cj, Side beyond, Real sign) {
    if (gas) {
      b.edges.push_back({sign * h * normal_stress(ci, cj), Across{}});
      return;
    }
    const Across a = across_cell(ci, cj, beyond);
    if (a.kind == Across::Kind::Side &&
        problem_.boundaries.sides[a.index].kind == StokesSide::Kind::Open) {
      // Traction of the ambient gas, -(p_a + Z u_n) n, n = sign e_d, u_n = sign u_face.
      const StokesSide& side = problem_.boundaries.sides[a.index];
      AffineForm traction = AffineForm::known(-sign * side.ambient_pressure(at) * h);
      if (side.normal_impedance != 0)
        traction -= (side.normal_impedance * h) * *face(i, j, vertical);
      b.edges.push_back({traction, a});
      return;
    }
    b.reaction = a;
  };
  normal_edge(after, i, j, after_side, 1.0);
  normal_edge(before, bi, bj, before_side, -1.0);
  // The half edges along d over each gas cell c, at the nodes of the face's two ends.
  const AffineForm tau_plus = shear(i + et.di, j + et.dj), tau_minus = shear(i, j);
  for (int k = 0; k < 2; ++k) {
    const bool gas = k == 0 ? before : after;
    if (!gas) continue;
    const int ci = k == 0 ? bi : i, cj = k == 0 ? bj : j;
    b.edges.push_back({0.5 * h * tau_plus, across_cell(ci + et.di, cj + et.dj, plus_side)});
    b.edges.push_back({-0.5 * h * tau_minus, across_cell(ci - et.di, cj - et.dj, minus_side)});
  }
  if (problem_.body_force) {
    // At the centroid of the gas part: the face, or h/4 into its one gas half.
    const Real shift = 0.25 * h * ((after ? 1 : 0) - (before ? 1 : 0));
    Point2 centroid = at;
    centroid[d] += shift;
    const Real area = 0.5 * h * h * ((before ? 1 : 0) + (after ? 1 : 0));
    b.body_force = problem_.body_force(centroid)[d] * area;
  }
  return b;
}

ControlVolumeBalance StokesOperator::u_balance(int i, int j) const { return balance(i, j, true); }
ControlVolumeBalance StokesOperator::v_balance(int i, int j) const { return balance(i, j, false); }

void StokesOperator::assemble() {
  const int nx = grid_.nx(), ny = grid_.ny();
  const Real h = grid_.h(), mu = problem_.viscosity;
  rhs_.assign(n_, 0.0);
  row_scale_.assign(n_, 1.0);
  column_scale_.assign(n_, 1.0);
  for (Index k = n_u_ + n_v_; k < n_; ++k) column_scale_[k] = mu / h;
  std::vector<std::pair<Index, Real>> row;
  auto add_row = [&](Index r, const AffineForm& f, Real scale) {
    row = f.terms;
    std::sort(row.begin(), row.end());
    for (std::size_t a = 0; a < row.size();) {
      std::size_t e = a;
      Real sum = 0;
      for (; e < row.size() && row[e].first == row[a].first; ++e) sum += row[e].second;
      pattern_.col_idx.push_back(row[a].first);
      values_.push_back(sum);
      a = e;
    }
    pattern_.row_ptr.push_back(pattern_.nnz());
    rhs_[r] = -f.constant;
    row_scale_[r] = scale;
  };
  // Rows in unknown order: face k's momentum balance is row k, cell k's continuity row k.
  auto momentum_row = [&](int i, int j, bool vertical) {
    const ControlVolumeBalance b = balance(i, j, vertical);
    AffineForm sum = AffineForm::known(b.body_force);
    for (const auto& e : b.edges) sum += e.force;
    return sum;
  };
  Index r = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i <= nx; ++i)
      if (u_index_[i + (nx + 1) * j] >= 0) add_row(r++, momentum_row(i, j, true), 1 / mu);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i < nx; ++i)
      if (v_index_[i + nx * j] >= 0) add_row(r++, momentum_row(i, j, false), 1 / mu);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      if (grid_.fluid(i, j))  // the volume flux out of the cell, h div u
        add_row(r++, h * (*u(i + 1, j) - *u(i, j) + *v(i, j + 1) - *v(i, j)), 1 / h);
}

}  // namespace rfmems
