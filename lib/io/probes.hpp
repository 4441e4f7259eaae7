// Probes: named points where a run records the displacement over time.
//
//   probes:
//     - {name: tip, at: [2 m, 0 m]}      # 2 or 3 coordinates, lengths with optional units
//
// Each probe is attached to the cell whose centroid is nearest to its point (KD-tree search,
// io/point_locator.hpp); its value is that cell's linear reconstruction evaluated at the point
// (ElasticityOperator::displacement_at). A point outside the mesh's bounding box (beyond a
// tolerance of 1e-6 of its largest edge) is an InputError naming the probe. A point inside the
// box but outside the body (in a hole) takes the value extrapolated from the nearest cell.
#pragma once
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "io/case_file.hpp"
#include "mesh/mesh.hpp"

namespace rfmems {

struct Probe {
  std::string name;
  Vec3 at = Vec3::Zero();
  Index cell = -1;  // nearest cell (by centroid)
};

class PointLocator;

// Points given in a case (probes, point loads): `at: [x, y(, z)]` with length units, checked
// against the mesh's bounding box (tolerance 1e-6 of its largest edge; outside: InputError
// naming the item), attached to the cell with the nearest centroid.
class CasePointFinder {
 public:
  explicit CasePointFinder(const Mesh& mesh);
  ~CasePointFinder();
  // The point item[key] and its cell; `what` names it in messages ("probe 'tip'").
  std::pair<Vec3, Index> find(const CaseNode& item, const std::string& key,
                              const std::string& what) const;

 private:
  const Mesh& mesh_;
  Vec3 lo_, hi_;
  std::unique_ptr<PointLocator> locator_;
};

// Reads the `probes` sequence (an empty node gives no probes). Names must be unique and
// usable as HDF5 names (non-empty, no '/').
std::vector<Probe> read_probes(const CaseNode& probes_node, const Mesh& mesh);

// Samples of every probe over time: values[i][p] is probe p at times[i].
class ProbeHistory {
 public:
  explicit ProbeHistory(std::size_t n_probes) : n_probes_(n_probes) {}
  void add(Real t, std::vector<Vec3> values);

  std::size_t n_samples() const { return times_.size(); }
  const std::vector<Real>& times() const { return times_; }
  // Probe p at sample i.
  const Vec3& value(std::size_t i, std::size_t p) const { return values_[i][p]; }
  // Largest |component k| of probe p over all samples (0 without samples).
  Real max_abs(std::size_t p, int k) const;
  // Series of probe p as rows (ux, uy, uz), for ResultWriter::write_time_series.
  std::vector<std::vector<double>> series(std::size_t p) const;

 private:
  std::size_t n_probes_;
  std::vector<Real> times_;
  std::vector<std::vector<Vec3>> values_;
};

// The keys read_probes reads (probes.keys.yaml; io/case_schema.hpp).
CaseSchema probes_case_keys();

}  // namespace rfmems
