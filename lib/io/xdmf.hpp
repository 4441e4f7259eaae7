// The XDMF sidecar of a result file: the light XML that lets ParaView and VisIt read the
// mesh and cell fields stored in the HDF5 file (which holds all the data).
#pragma once
#include <string>
#include <vector>

#include "core/types.hpp"

namespace rfmems {

struct XdmfField {
  std::string name;
  std::string dataset;  // path inside the HDF5 file, e.g. "/fields/000010/displacement"
  int n_components;     // 1 Scalar, 3 Vector, 6 Tensor6, 9 Tensor
};

struct XdmfStep {
  double time;
  std::vector<XdmfField> fields;
};

struct XdmfMesh {
  std::string h5_name;  // HDF5 file name as seen from the XDMF file (same directory)
  Index n_cells;
  Index n_nodes;
  Index topology_length;  // length of the flat "Mixed" topology list
};

// XDMF 3 text: a Temporal collection with one Uniform grid per step (mesh datasets
// /mesh/topology and /mesh/nodes, one cell-centred Attribute per field). Without steps, a
// single grid with the mesh alone.
std::string xdmf_text(const XdmfMesh& mesh, const std::vector<XdmfStep>& steps);

}  // namespace rfmems
