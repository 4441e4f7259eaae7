// Generation of the XDMF sidecar text declared in xdmf.hpp.
#include "io/xdmf.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace rfmems {

namespace {

std::string xml_escape(const std::string& s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

const char* attribute_type(int n_components) {
  switch (n_components) {
    case 1:
      return "Scalar";
    case 3:
      return "Vector";
    case 6:
      return "Tensor6";
    case 9:
      return "Tensor";
  }
  throw std::invalid_argument(
      fmt::format("XDMF attribute with {} components (need 1, 3, 6 or 9)", n_components));
}

void append_mesh(std::string& out, const XdmfMesh& mesh, const std::string& indent) {
  const std::string h5 = xml_escape(mesh.h5_name);
  out += fmt::format("{}<Topology TopologyType=\"Mixed\" NumberOfElements=\"{}\">\n", indent,
                     mesh.n_cells);
  out += fmt::format(
      "{}  <DataItem Dimensions=\"{}\" NumberType=\"Int\" Precision=\"8\" "
      "Format=\"HDF\">{}:/mesh/topology</DataItem>\n",
      indent, mesh.topology_length, h5);
  out += fmt::format("{}</Topology>\n", indent);
  out += fmt::format("{}<Geometry GeometryType=\"XYZ\">\n", indent);
  out += fmt::format(
      "{}  <DataItem Dimensions=\"{} 3\" NumberType=\"Float\" Precision=\"8\" "
      "Format=\"HDF\">{}:/mesh/nodes</DataItem>\n",
      indent, mesh.n_nodes, h5);
  out += fmt::format("{}</Geometry>\n", indent);
}

}  // namespace

std::string xdmf_text(const XdmfMesh& mesh, const std::vector<XdmfStep>& steps) {
  std::string out =
      "<?xml version=\"1.0\" ?>\n"
      "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
      "<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
      "  <Domain>\n";
  if (steps.empty()) {
    out += "    <Grid Name=\"mesh\" GridType=\"Uniform\">\n";
    append_mesh(out, mesh, "      ");
    out += "    </Grid>\n";
  } else {
    out += "    <Grid Name=\"results\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (std::size_t s = 0; s < steps.size(); ++s) {
      out += fmt::format("      <Grid Name=\"step{}\" GridType=\"Uniform\">\n", s);
      // Shortest text that reads back to the same double.
      out += fmt::format("        <Time Value=\"{}\" />\n", steps[s].time);
      append_mesh(out, mesh, "        ");
      for (const auto& f : steps[s].fields) {
        out += fmt::format("        <Attribute Name=\"{}\" AttributeType=\"{}\" Center=\"Cell\">\n",
                           xml_escape(f.name), attribute_type(f.n_components));
        out += fmt::format(
            "          <DataItem Dimensions=\"{} {}\" NumberType=\"Float\" Precision=\"8\" "
            "Format=\"HDF\">{}:{}</DataItem>\n",
            mesh.n_cells, f.n_components, xml_escape(mesh.h5_name), xml_escape(f.dataset));
        out += "        </Attribute>\n";
      }
      out += "      </Grid>\n";
    }
    out += "    </Grid>\n";
  }
  out += "  </Domain>\n</Xdmf>\n";
  return out;
}

}  // namespace rfmems
