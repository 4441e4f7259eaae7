#include "ibm/ib_kinetic_face_values.hpp"

#include <algorithm>
#include <map>

#include "core/error.hpp"
#include "physics/gas/kinetic/equilibrium.hpp"

namespace rfmems {

IbKineticFaceValues::IbKineticFaceValues(const Mesh& background, const FluidFaceGraph& fluid,
                                         const CellMarking& marking, const ImmersedSurface& body,
                                         std::span<const Vec3> segment_velocity,
                                         std::span<const Vec3> ib_face_velocity,
                                         const VelocityGrid& grid, const KineticGas& gas,
                                         Real reference_density, const IbKineticOptions& options)
    : fluid_(fluid),
      marking_(marking),
      body_(body),
      ib_face_velocity_(ib_face_velocity),
      grid_(grid),
      options_(options),
      reference_density_(reference_density) {
  const Index N = grid.size(), ns = body.n_segments(), nib = marking.ib_faces.size();
  if (static_cast<Index>(segment_velocity.size()) != ns ||
      static_cast<Index>(ib_face_velocity.size()) != nib)
    throw InputError("IB kinetic face values: one velocity per segment and per IB face");
  surface_ = compact(
      IbInterpolation::to_surface_points(background, marking, body, options.surface_options));
  // Step (iii): one interpolation per set of segments at which the ordinate leaves the wall.
  std::map<std::vector<bool>, Index> group_of;
  std::vector<Index> ordinate_group(N);
  for (Index k = 0; k < N; ++k) {
    std::vector<bool> leaves(ns);
    for (Index j = 0; j < ns; ++j) leaves[j] = grid.c[k].dot(body.normal(j)) > 0;
    auto [it, fresh] = group_of.emplace(leaves, static_cast<Index>(group_of.size()));
    ordinate_group[k] = it->second;
    if (fresh) group_ordinates_.emplace_back();
    group_ordinates_[it->second].push_back(k);
  }
  groups_.resize(group_of.size());
  for (const auto& [leaves, gid] : group_of) {
    IbInterpolationOptions o = options.face_options;
    o.wall_point_admissible = [&leaves](Index j) { return static_cast<bool>(leaves[j]); };
    const IbInterpolation ib(background, marking, body, o);
    groups_[gid] = compact(ib);
    for (Index i = 0; i < ib.n_faces(); ++i) fits_.push_back(ib.fit(i));
  }
  graph_face_of_ib_.assign(nib, -1);
  for (Index f = 0; f < fluid.graph.n_faces(); ++f)
    if (fluid.ib_face[f] >= 0) graph_face_of_ib_[fluid.ib_face[f]] = f;
  // Step (ii)'s wall Maxwellians, one equilibrium solve per distinct segment velocity.
  maxwellian_.assign(ns * N, 0.0);
  std::map<std::array<Real, 3>, Index> solved;
  for (Index j = 0; j < ns; ++j) {
    const Vec3& u = segment_velocity[j];
    const std::array<Real, 3> key{u.x(), u.y(), u.z()};
    std::span<Real> m(maxwellian_.data() + j * N, N);
    if (auto it = solved.find(key); it != solved.end()) {
      std::copy_n(maxwellian_.data() + it->second * N, N, m.begin());
      continue;
    }
    const EquilibriumCoefficients a =
        equilibrium(maxwellian_target(1.0, u, options.wall_temperature, gas), gas.model, grid);
    evaluate_equilibrium(a, grid, m);
    solved.emplace(key, j);
  }
  into_solid_.assign(ns * N, 0.0);
  wall_values_.assign(ns * N, 0.0);
  wall_density_.assign(ns, 0.0);
  entering_.assign(nib * N, 0.0);
  factor_.assign(nib, 1.0);
  segment_velocity_.assign(segment_velocity.begin(), segment_velocity.end());
}

IbKineticFaceValues::Stencils IbKineticFaceValues::compact(const IbInterpolation& ib) const {
  Stencils s;
  for (Index i = 0; i < ib.n_faces(); ++i) {
    for (const IbStencilPoint& p : ib.stencil(i)) {
      const bool wall = p.kind == IbStencilPoint::Kind::WallPoint;
      s.index.push_back(wall ? p.index : fluid_.fluid_cell[p.index]);
      s.wall.push_back(wall ? 1 : 0);
      s.weight.push_back(p.weight);
    }
    s.offsets.push_back(static_cast<Index>(s.index.size()));
  }
  return s;
}

void IbKineticFaceValues::update(std::span<const Real> f, std::span<const Real> owner_values) {
  const Index N = grid_.size(), ns = body_.n_segments();
  // (i) into-solid values at the segment midpoints, from FLUID cells (all ordinates: the
  // out-of-solid ones are overwritten in (ii) and never read).
  std::fill(into_solid_.begin(), into_solid_.end(), 0.0);
  for (Index j = 0; j < ns; ++j) {
    Real* g = into_solid_.data() + j * N;
    for (Index e = surface_.offsets[j]; e < surface_.offsets[j + 1]; ++e) {
      const Real w = surface_.weight[e];
      const Real* fc = f.data() + surface_.index[e] * N;
      for (Index k = 0; k < N; ++k) g[k] += w * fc[k];
    }
  }
  IbPositivityReport report;
  for (Index j = 0; j < ns; ++j) {
    const Vec3 n = body_.normal(j);
    const Real* g = into_solid_.data() + j * N;
    Real lo = 0, hi = 0;
    for (Index k = 0; k < N; ++k)
      if (grid_.c[k].dot(n) < 0) {
        report.negative_into_solid += g[k] < 0;
        lo = std::min(lo, g[k]);
        hi = std::max(hi, g[k]);
      }
    if (lo < 0 && hi > 0)
      report.most_negative_into_solid = std::min(report.most_negative_into_solid, lo / hi);
  }
  // (ii) diffuse reflection with zero net mass flux in the wall's frame.
  for (Index j = 0; j < ns; ++j) {
    const Vec3 n = body_.normal(j);
    const Real un = segment_velocity_[j].dot(n);
    const Real* g = into_solid_.data() + j * N;
    const Real* m = maxwellian_.data() + j * N;
    Real known = 0, per_density = 0;
    for (Index k = 0; k < N; ++k) {
      const Real cn = grid_.c[k].dot(n);
      const Real relative = grid_.w[k] * (cn - un);
      if (cn < 0)
        known += relative * g[k];
      else
        per_density += relative * m[k];
    }
    const Real density = -known / per_density;
    report.negative_wall_density += density < 0;
    wall_density_[j] = density;
    Real* W = wall_values_.data() + j * N;
    for (Index k = 0; k < N; ++k) W[k] = grid_.c[k].dot(n) > 0 ? density * m[k] : 0.0;
  }
  // (iii) entering-fluid values on the IB faces from FLUID cells and admissible wall values.
  std::fill(entering_.begin(), entering_.end(), 0.0);
  const FaceGraph& graph = fluid_.graph;
  const Index nib = static_cast<Index>(graph_face_of_ib_.size());
  for (std::size_t gid = 0; gid < groups_.size(); ++gid) {
    const Stencils& s = groups_[gid];
    const std::vector<Index>& ks = group_ordinates_[gid];
    for (Index i = 0; i < nib; ++i) {
      const Vec3& S = graph.face_area[graph_face_of_ib_[i]];
      Real* e_i = entering_.data() + i * N;
      for (Index e = s.offsets[i]; e < s.offsets[i + 1]; ++e) {
        const Real w = s.weight[e];
        const Real* src = (s.wall[e] ? wall_values_.data() : f.data()) + s.index[e] * N;
        for (const Index k : ks)
          if (grid_.c[k].dot(S) < 0) e_i[k] += w * src[k];
      }
    }
  }
  // Positivity: count, then clip the entering values (the mass flux is restored below). A face
  // whose entering values are all <= 0 takes its FLUID cell's (counted in faces_from_cell).
  for (Index i = 0; i < nib; ++i) {
    const Vec3& S = graph.face_area[graph_face_of_ib_[i]];
    Real* e_i = entering_.data() + i * N;
    Real lo = 0, hi = 0, raw_flux = 0, clipped_flux = 0;
    Index negative = 0;
    for (Index k = 0; k < N; ++k) {
      const Real cs = grid_.w[k] * grid_.c[k].dot(S);
      if (!(cs < 0)) continue;
      ++report.entering_values;
      lo = std::min(lo, e_i[k]);
      hi = std::max(hi, e_i[k]);
      raw_flux += cs * e_i[k];
      negative += e_i[k] < 0;
      clipped_flux += cs * std::max(e_i[k], 0.0);
    }
    report.negative_entering += negative;
    report.faces_with_negative += negative > 0;
    if (lo < 0)
      report.most_negative_entering =
          std::min(report.most_negative_entering, lo / std::max(hi, -lo));
    if (negative == 0 || !options_.clip_negative) continue;
    if (!(clipped_flux < 0)) {
      // No entering value > 0: the FLUID cell's own values (a degree-0 fit), which the factor
      // below scales to the face's mass flux.
      ++report.faces_from_cell;
      const Real* fo = f.data() + graph.face_owner[graph_face_of_ib_[i]] * N;
      for (Index k = 0; k < N; ++k)
        if (grid_.c[k].dot(S) < 0) e_i[k] = fo[k];
      continue;
    }
    // Without the balance below, keep the unclipped entering mass flux.
    const Real scale =
        options_.balance_mass_flux || !(raw_flux < 0) ? 1.0 : raw_flux / clipped_flux;
    for (Index k = 0; k < N; ++k)
      if (grid_.c[k].dot(S) < 0) e_i[k] = std::max(e_i[k], 0.0) * scale;
  }
  positivity_ = report;
  // The face's mass flux: that of an impermeable wall at u_i (see the header).
  for (Index i = 0; i < nib; ++i) {
    factor_[i] = 1.0;
    if (!options_.balance_mass_flux) continue;
    const Index face = graph_face_of_ib_[i];
    const Vec3& S = graph.face_area[face];
    const Real* fo = owner_values.data() + (face - graph.n_interior_faces) * N;  // leaving
    const Real* e_i = entering_.data() + i * N;
    Real out_flux = 0, in_flux = 0;
    for (Index k = 0; k < N; ++k) {
      const Real cs = grid_.w[k] * grid_.c[k].dot(S);
      if (cs >= 0)
        out_flux += cs * fo[k];
      else
        in_flux += cs * e_i[k];
    }
    const Real target = reference_density_ * ib_face_velocity_[i].dot(S);
    if (in_flux < 0) factor_[i] = (target - out_flux) / in_flux;
  }
}

void IbKineticFaceValues::fill(Index face, std::span<const Real> owner_values,
                               std::span<Real> out) const {
  const Index N = grid_.size();
  const Index i = fluid_.ib_face[face];
  const Vec3& S = fluid_.graph.face_area[face];
  const Real* fo = owner_values.data();
  const Real* e_i = entering_.data() + i * N;
  const Real a = factor_[i];
  for (Index k = 0; k < N; ++k) out[k] = grid_.c[k].dot(S) >= 0 ? fo[k] : a * e_i[k];
}

Index IbKineticFaceValues::count_one_sided() const {
  return std::count_if(fits_.begin(), fits_.end(), [](auto& f) { return f.one_sided; });
}

Index IbKineticFaceValues::count_degree(int degree) const {
  return std::count_if(fits_.begin(), fits_.end(), [&](auto& f) { return f.degree == degree; });
}

}  // namespace rfmems
