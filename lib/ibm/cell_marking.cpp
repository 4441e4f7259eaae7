#include "ibm/cell_marking.hpp"

#include <algorithm>
#include <deque>

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

CellMarker::CellMarker(const Mesh& background) : mesh_(background), index_(new Index2D) {
  if (background.dim() != 2) throw MeshError("cell marking: the background mesh is not 2D");
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

CellMarking CellMarker::mark(const ImmersedSurface& body) const {
  const Mesh& mesh = mesh_;
  const Index nc = mesh.n_cells(), nf = mesh.n_faces();
  enum : std::uint8_t { Unknown, Fluid, Solid, Cut };
  std::vector<std::uint8_t> state(nc, Unknown);

  // Step 1: cells whose interior a segment's interior meets.
  const bg::de9im::mask interiors_meet("T********");
  std::vector<std::vector<Index>> cutting(nc);
  std::vector<BoxValue> hits;
  for (Index k = 0; k < body.n_segments(); ++k) {
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
      case Fluid: m.cell[c] = CellClass::Fluid; break;
      case Cut: m.cell[c] = CellClass::ImmersedBoundary; break;
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
