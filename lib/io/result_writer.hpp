// Result files: one HDF5 file per run, plus an XDMF sidecar for ParaView/VisIt.
//
// Layout:
//   /mesh/nodes            n_nodes × 3 double
//   /mesh/topology         int64, XDMF "Mixed": per cell its type id (3 polygon + node count,
//                          4 triangle, 5 quad, 6 tetra, 7 pyramid, 8 prism, 9 hexa) and nodes
//   /mesh/cell_centroids   n_cells × 3,  /mesh/cell_volumes  n_cells (area in 2D)
//   /mesh                  attributes dim, n_cells, n_nodes
//   /fields/<step:06d>/<name>  n_cells × n_components, attributes time, units, components
//                          (group: time, step)
//   /fields/times, /fields/steps   output times and step indices, in step order
//   /<group>/<name>/time, /<group>/<name>/values (n_t × n_comp)   time series (probes, stats),
//                          each with its units (values: one per component)
//   /metadata              attributes: strings (case text, overrides, git hash) and numbers
//   /                      attributes format = "rfmems-result", format_version
//
// The file is written ATOMICALLY: everything goes to "<path>.tmp.<pid>", which finish()
// renames to <path>. A writer destroyed without finish() (an exception unwinding a failed
// run) deletes its temporary, so a failed run leaves no result file. A stale <path> from an
// earlier run is removed when the writer is created, for the same reason.
//
// Only the owned cells [0, n_owned_cells) are written (serial: all cells).
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace rfmems {

class ResultWriter {
 public:
  // Creates the temporary file (and the parent directory) and writes the mesh.
  // HDF5 failures → std::runtime_error naming the file.
  ResultWriter(const std::string& path, const Mesh& mesh);
  ~ResultWriter();
  ResultWriter(const ResultWriter&) = delete;
  ResultWriter& operator=(const ResultWriter&) = delete;

  // Writes /fields/<step:06d>/<name>. values holds n_components per cell, cell by cell, for
  // the owned cells or all cells (ghosts are ignored). n_components must be 1, 3 (vectors:
  // give z even in 2D), 6 (symmetric tensor, Voigt order xx yy zz yz xz xy) or 9.
  // All fields of one step_index must share its time. component_names, if given, is stored
  // as the dataset attribute "components"; the field's unit (io/quantity_units.hpp: a name
  // without one is a programming error) as "units".
  void write_cell_field_at(int step_index, double time, const std::string& name,
                           const std::vector<double>& values, int n_components,
                           const std::vector<std::string>& component_names = {});

  // Writes /<group>/<name>/time (n_t) and /<group>/<name>/values (n_t × n_comp; values[i]
  // is the sample at t[i], all of the same length). group may be nested ("stats/solver").
  // abscissa names the first dataset instead of "time" (a curve in another variable, e.g.
  // the voltage-deflection curve of a pull-in study). Units ("units" attributes): the
  // abscissa's by its name; the components' as given, else by their names ("" for a name
  // io/quantity_units.hpp does not know, such as a probe's own).
  void write_time_series(const std::string& group, const std::string& name,
                         const std::vector<double>& t,
                         const std::vector<std::vector<double>>& values,
                         const std::vector<std::string>& component_names = {},
                         const std::string& abscissa = "time",
                         const std::vector<std::string>& component_units = {});

  // Attributes of /metadata; a name written twice keeps the last value. "git_hash" is
  // already set from the build.
  void write_metadata(const std::map<std::string, std::string>& strings,
                      const std::map<std::string, double>& numbers = {});

  // Writes /fields/times and /fields/steps, closes the file, writes the XDMF sidecar (same
  // name, .xdmf instead of .h5; also temp + rename) and renames the temporary to path.
  void finish();

  const std::string& path() const;
  const std::string& xdmf_path() const;
  // The XDMF sidecar of a result path: .h5 / .hdf5 replaced by .xdmf, else .xdmf appended.
  static std::string sidecar_path(const std::string& path);
  bool finished() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rfmems
