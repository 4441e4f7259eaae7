#include "ibm/cell_marking.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

#include "core/error.hpp"
#include "ibm/boost_geometry.hpp"

namespace rfmems {

using namespace ibm_geometry;

struct CellMarker::Index2D {
  std::vector<Polygon> cell_polygon;
  BoxTree cell_boxes;
};

Index CellMarking::count(CellClass k) const { return std::count(cell.begin(), cell.end(), k); }

Index CellMarking::count(FaceClass k) const { return std::count(face.begin(), face.end(), k); }

std::vector<Index> CellMarking::cells_of(CellClass k) const {
  std::vector<Index> out;
  for (Index c = 0; c < static_cast<Index>(cell.size()); ++c)
    if (cell[c] == k) out.push_back(c);
  return out;
}

Real CellMarking::area(const Mesh& mesh, CellClass k) const {
  Real a = 0;
  for (Index c = 0; c < static_cast<Index>(cell.size()); ++c)
    if (cell[c] == k) a += mesh.cell_volume(c);
  return a;
}

CellMarker::CellMarker(const Mesh& background, CellMarkingOptions options)
    : mesh_(background), options_(options), index_(new Index2D) {
  if (background.dim() != 2) throw MeshError("cell marking: the background mesh is not 2D");
  if (!(options.snap_fraction >= 0 && options.snap_fraction < 0.5))
    throw InputError("cell marking: snap_fraction is not in [0, 0.5)");
  std::vector<BoxValue> boxes;
  boxes.reserve(background.n_cells());
  for (Index c = 0; c < background.n_cells(); ++c) {
    Polygon poly;
    for (Index n : background.cell_nodes(c)) bg::append(poly.outer(), point(background.nodes()[n]));
    bg::correct(poly);  // closes the ring (and orients it, should a cell be clockwise)
    Box b;
    bg::envelope(poly, b);
    boxes.emplace_back(b, c);
    index_->cell_polygon.push_back(std::move(poly));
  }
  index_->cell_boxes = BoxTree(boxes.begin(), boxes.end());  // bulk loading (packing)
}

CellMarker::~CellMarker() = default;

ImmersedSurface CellMarker::snapped(const ImmersedSurface& body, Index* n_snapped,
                                    bool* rejected) const {
  if (n_snapped) *n_snapped = 0;
  if (rejected) *rejected = false;
  const Real fraction = options_.snap_fraction;
  if (!(fraction > 0)) return body;
  const std::vector<Vec3>& v0 = body.vertices();
  const std::size_t n = v0.size();
  std::vector<Vec3> v = v0;
  Index moved = 0;
  std::vector<BoxValue> hits;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& x = v0[i];
    const Vec3& prev = v0[(i + n - 1) % n];
    const Vec3& next = v0[(i + 1) % n];
    hits.clear();
    index_->cell_boxes.query(bgi::intersects(box_of(x, x)), std::back_inserter(hits));
    // The nearest axis-aligned edge line within fraction of the width of a cell holding x,
    // per direction (x and y independently: near a cell corner the vertex goes to the node).
    Real best_x = std::numeric_limits<Real>::infinity(), best_y = best_x;
    Real to_x = x.x(), to_y = x.y(), band_x = 0, band_y = 0;
    for (const auto& [box, c] : hits) {
      const Real wx = box.max_corner().x() - box.min_corner().x();
      const Real wy = box.max_corner().y() - box.min_corner().y();
      const auto nodes = mesh_.cell_nodes(c);
      for (std::size_t j = 0; j < nodes.size(); ++j) {
        const Vec3& a = mesh_.nodes()[nodes[j]];
        const Vec3& b = mesh_.nodes()[nodes[(j + 1) % nodes.size()]];
        if (a.x() == b.x()) {
          const Real d = std::abs(x.x() - a.x());
          if (d <= fraction * wx && d < best_x) best_x = d, to_x = a.x(), band_x = fraction * wx;
        }
        if (a.y() == b.y()) {
          const Real d = std::abs(x.y() - a.y());
          if (d <= fraction * wy && d < best_y) best_y = d, to_y = a.y(), band_y = fraction * wy;
        }
      }
    }
    // Only where the surface runs along the line: an adjacent segment more parallel than
    // across it, with its other end in the band too. Moving a vertex along the surface (x at
    // a circle's top) would only shuffle vertices (measured: a spike on a 2560-gon).
    auto along_x = [&](const Vec3& w) {
      return std::abs(w.x() - to_x) <= band_x && std::abs(w.y() - x.y()) >= std::abs(w.x() - x.x());
    };
    auto along_y = [&](const Vec3& w) {
      return std::abs(w.y() - to_y) <= band_y && std::abs(w.x() - x.x()) >= std::abs(w.y() - x.y());
    };
    if (!(along_x(prev) || along_x(next))) to_x = x.x();
    if (!(along_y(prev) || along_y(next))) to_y = x.y();
    if (to_x != x.x() || to_y != x.y()) {
      v[i] = Vec3(to_x, to_y, 0);
      ++moved;
    }
  }
  if (moved == 0) return body;
  // A body thinner than 2 fraction h across a grid line would collapse onto it: keep the
  // true surface then.
  Polygon poly;
  for (const Vec3& x : v) bg::append(poly.outer(), point(x));
  bg::append(poly.outer(), point(v.front()));
  if (!bg::is_valid(poly)) {
    if (rejected) *rejected = true;
    return body;
  }
  ImmersedSurface out = body;
  out.set_vertices(std::move(v));
  if (n_snapped) *n_snapped = moved;
  return out;
}

CellMarking CellMarker::mark(const ImmersedSurface& true_body) const {
  const Mesh& mesh = mesh_;
  Index n_snapped = 0;
  bool snap_rejected = false;
  const ImmersedSurface body = snapped(true_body, &n_snapped, &snap_rejected);
  const Index nc = mesh.n_cells(), nf = mesh.n_faces();
  enum : std::uint8_t { Unknown, Fluid, Solid, Cut };
  std::vector<std::uint8_t> state(nc, Unknown);

  // Step 1: cells whose interior a segment's interior meets.
  const bg::de9im::mask interiors_meet("T********");
  std::vector<std::vector<Index>> cutting(nc);
  std::vector<BoxValue> hits;
  for (Index k = 0; k < body.n_segments(); ++k) {
    if (body.start(k) == body.end(k)) continue;  // a segment snapped to a point cuts nothing
    const Linestring s = segment(body.start(k), body.end(k));
    hits.clear();
    index_->cell_boxes.query(bgi::intersects(box_of(body.start(k), body.end(k))),
                             std::back_inserter(hits));
    for (const auto& [box, c] : hits)
      if (bg::relate(s, index_->cell_polygon[c], interiors_meet)) {
        state[c] = Cut;
        cutting[c].push_back(k);
      }
  }

  CellMarking m;
  m.n_snapped_vertices = n_snapped;
  m.snap_rejected = snap_rejected;
  m.centroid_inside.resize(nc);
  const Vec3 lo = body.lower(), hi = body.upper();
  for (Index c = 0; c < nc; ++c) {
    const Vec3& x = mesh.cell_centroid(c);
    const bool in_box = x.x() > lo.x() && x.x() < hi.x() && x.y() > lo.y() && x.y() < hi.y();
    m.centroid_inside[c] = in_box && body.contains(x);
  }

  // Step 2: flood fill from the uncut boundary cells outside the body.
  std::deque<Index> queue;
  for (Index f = mesh.n_interior_faces(); f < nf; ++f) {
    const Index c = mesh.face_owner(f);
    if (state[c] == Unknown && !m.centroid_inside[c]) {
      state[c] = Fluid;
      queue.push_back(c);
    }
  }
  while (!queue.empty()) {
    const Index c = queue.front();
    queue.pop_front();
    for (Index f : mesh.cell_faces(c)) {
      if (mesh.is_boundary(f)) continue;
      const Index n = mesh.face_owner(f) == c ? mesh.face_neighbour(f) : mesh.face_owner(f);
      // An uncut neighbour lies wholly on one side of the surface: the side of its centroid.
      if (state[n] != Unknown || m.centroid_inside[n]) continue;
      state[n] = Fluid;
      queue.push_back(n);
    }
  }

  // Step 3: the rest is solid.
  m.cell.resize(nc);
  for (Index c = 0; c < nc; ++c) {
    switch (state[c]) {
      case Fluid:
        m.cell[c] = CellClass::Fluid;
        break;
      case Cut:
        m.cell[c] = CellClass::ImmersedBoundary;
        break;
      default:
        m.cell[c] = CellClass::Solid;
        if (!m.centroid_inside[c]) ++m.n_unreached_outside;
    }
  }
  m.cut_offsets.assign(1, 0);
  for (Index c = 0; c < nc; ++c) {
    m.cut_segments.insert(m.cut_segments.end(), cutting[c].begin(), cutting[c].end());
    m.cut_offsets.push_back(static_cast<Index>(m.cut_segments.size()));
  }

  // Faces.
  m.face.resize(nf);
  for (Index f = 0; f < nf; ++f) {
    const Index o = mesh.face_owner(f), n = mesh.face_neighbour(f);
    const bool fluid_o = m.cell[o] == CellClass::Fluid;
    if (n < 0) {
      m.face[f] = fluid_o ? FaceClass::Fluid : FaceClass::Solid;
      continue;
    }
    const bool fluid_n = m.cell[n] == CellClass::Fluid;
    if (fluid_o && fluid_n) {
      m.face[f] = FaceClass::Fluid;
    } else if (!fluid_o && !fluid_n) {
      m.face[f] = FaceClass::Solid;
    } else {
      m.face[f] = FaceClass::ImmersedBoundary;
      const Vec3 n_out = mesh.face_area(f).normalized();  // out of the owner
      m.ib_faces.push_back(f);
      m.ib_face_fluid_cell.push_back(fluid_o ? o : n);
      m.ib_face_normal.push_back(fluid_o ? n_out : Vec3(-n_out));
    }
  }
  return m;
}

}  // namespace rfmems
