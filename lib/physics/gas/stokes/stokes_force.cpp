// Wall forces and side flows of a Stokes solution: see stokes_force.hpp.
#include "physics/gas/stokes/stokes_force.hpp"

namespace rfmems {

namespace {

// The force on `on` from one control volume's balance (one component).
Real force_from(const ControlVolumeBalance& b, std::span<const Real> x, const Across& on) {
  Real across = 0, others = b.body_force;
  for (const auto& e : b.edges) (e.across == on ? across : others) += e.force.evaluate(x);
  // The reaction F_r = -(sum of all edges + body) acts on the gas; the wall gets
  // -(F_r + its listed edges) = the other edges + body.
  if (b.reaction && *b.reaction == on) return others;
  return -across;
}

}  // namespace

Point2 boundary_force(const StokesOperator& op, std::span<const Real> x, const Across& on) {
  const MacGrid& g = op.grid();
  Point2 f(0, 0);
  for (int j = 0; j < g.ny(); ++j)
    for (int i = 0; i <= g.nx(); ++i)
      if (op.u(i, j)) f.x() += force_from(op.u_balance(i, j), x, on);
  for (int j = 0; j <= g.ny(); ++j)
    for (int i = 0; i < g.nx(); ++i)
      if (op.v(i, j)) f.y() += force_from(op.v_balance(i, j), x, on);
  return f;
}

Real side_outflow(const StokesOperator& op, std::span<const Real> x, Side side) {
  const MacGrid& g = op.grid();
  const Real h = g.h();
  Real q = 0;
  const bool vertical = side == Side::Left || side == Side::Right;
  const int n = vertical ? g.ny() : g.nx();
  for (int k = 0; k < n; ++k) {
    const auto face = side == Side::Left     ? op.u(0, k)
                      : side == Side::Right  ? op.u(g.nx(), k)
                      : side == Side::Bottom ? op.v(k, 0)
                                             : op.v(k, g.ny());
    if (!face) continue;
    const Real outward = (side == Side::Left || side == Side::Bottom) ? -1 : 1;
    q += outward * h * face->evaluate(x);
  }
  return q;
}

}  // namespace rfmems
