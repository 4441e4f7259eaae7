// Reader of Gmsh MSH 4.1 ASCII meshes (see gmsh_reader.hpp for what is kept).
//
// Layout of the sections read (one record per line, numbers separated by blanks):
//   $MeshFormat     version(4.1) file-type(0 = ASCII) data-size
//   $PhysicalNames  n, then: dim physicalTag "name"
//   $Entities       nPoints nCurves nSurfaces nVolumes, then per point:
//                   tag x y z nPhys physTags...; per curve/surface/volume:
//                   tag minX minY minZ maxX maxY maxZ nPhys physTags... nBound boundTags...
//   $Nodes          nBlocks nNodes minTag maxTag, then per block: entityDim entityTag
//                   parametric n, the n node tags, then n lines "x y z [u v w]"
//   $Elements       nBlocks nElements minTag maxTag, then per block: entityDim entityTag
//                   elementType n, then n lines "elementTag nodeTags..."
#include "mesh/gmsh_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/error.hpp"

namespace rfmems {
namespace {

using namespace std::string_literals;

using Tag = std::uint64_t;

// Splits the file into blank-separated tokens (or whole lines), counting lines for messages.
class Lexer {
 public:
  Lexer(std::string text, std::string path) : text_(std::move(text)), path_(std::move(path)) {}

  // Next token, or an empty view at the end of the file.
  std::string_view token() {
    skip_blanks();
    const std::size_t begin = pos_;
    while (pos_ < text_.size() && !is_blank(text_[pos_])) ++pos_;
    return std::string_view(text_).substr(begin, pos_ - begin);
  }

  // The rest of the current line (without its end of line); moves to the next line.
  std::string_view rest_of_line() {
    const std::size_t begin = pos_;
    std::size_t end = text_.find('\n', pos_);
    if (end == std::string::npos) end = text_.size();
    pos_ = std::min(end + 1, text_.size());
    if (end < text_.size()) ++line_;
    std::string_view line = std::string_view(text_).substr(begin, end - begin);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    return line;
  }

  // The next token as a number of type T; `section` names where we are for the message.
  template <class T>
  T number(std::string_view section) {
    const std::string_view tok = token();
    T value{};
    const auto [end, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), value);
    if (ec == std::errc() && end == tok.data() + tok.size()) return value;
    if (tok.empty()) fail("unexpected end of file in "s + std::string(section) + " section");
    if (tok.front() == '$')
      fail("truncated "s + std::string(section) + " section (found " + std::string(tok) + ")");
    fail("bad number '"s + std::string(tok) + "' in " + std::string(section) + " section");
  }

  // Reads the token that closes `section` ("$Nodes" -> "$EndNodes").
  void expect_end(std::string_view section) {
    const std::string end = "$End"s + std::string(section.substr(1));
    const std::string_view tok = token();
    if (tok != end)
      fail(std::string(section) + " section: expected " + end + ", found " +
           (tok.empty() ? std::string("end of file") : "'"s + std::string(tok) + "'"));
  }

  // Skips a section we do not read, up to its $End marker.
  void skip_section(std::string_view section) {
    const std::string end = "$End"s + std::string(section.substr(1));
    for (std::string_view tok = token(); tok != end; tok = token())
      if (tok.empty()) fail("unterminated "s + std::string(section) + " section");
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(path_ + ": line " + std::to_string(line_) + ": " + what);
  }

 private:
  static bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }
  void skip_blanks() {
    while (pos_ < text_.size() && is_blank(text_[pos_])) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }

  std::string text_;
  std::string path_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

// What we know about a Gmsh element type: its dimension and node count, and for first-order
// types the cell shape it becomes.
struct ElementType {
  int dim = -1;  // -1: unknown or unsupported type
  int n_nodes = 0;
  CellShape shape = CellShape::Triangle;
  const char* name = "";
};

ElementType element_type(int type) {
  switch (type) {
    case 1:
      return {1, 2, CellShape::Polygon, "2-node line"};
    case 2:
      return {2, 3, CellShape::Triangle, "3-node triangle"};
    case 3:
      return {2, 4, CellShape::Quad, "4-node quadrangle"};
    case 4:
      return {3, 4, CellShape::Tetra, "4-node tetrahedron"};
    case 5:
      return {3, 8, CellShape::Hexa, "8-node hexahedron"};
    case 6:
      return {3, 6, CellShape::Prism, "6-node prism"};
    case 7:
      return {3, 5, CellShape::Pyramid, "5-node pyramid"};
    case 15:
      return {0, 1, CellShape::Polygon, "1-node point"};
    // Named only for the error message.
    case 8:
      return {-1, 0, CellShape::Polygon, "3-node line"};
    case 9:
      return {-1, 0, CellShape::Polygon, "6-node triangle"};
    case 10:
      return {-1, 0, CellShape::Polygon, "9-node quadrangle"};
    case 11:
      return {-1, 0, CellShape::Polygon, "10-node tetrahedron"};
    case 12:
      return {-1, 0, CellShape::Polygon, "27-node hexahedron"};
    case 13:
      return {-1, 0, CellShape::Polygon, "18-node prism"};
    case 14:
      return {-1, 0, CellShape::Polygon, "14-node pyramid"};
    case 16:
      return {-1, 0, CellShape::Polygon, "8-node quadrangle"};
    case 17:
      return {-1, 0, CellShape::Polygon, "20-node hexahedron"};
    case 18:
      return {-1, 0, CellShape::Polygon, "15-node prism"};
    case 19:
      return {-1, 0, CellShape::Polygon, "13-node pyramid"};
    default:
      return {-1, 0, CellShape::Polygon, "unknown"};
  }
}

struct ElementBlock {
  int entity_dim = 0;
  int entity_tag = 0;
  int type = 0;
  bool supported = true;  // false: lines skipped, the type is reported if the block is used
  std::vector<Tag> tags;
  std::vector<Tag> nodes;  // n_nodes per element, flattened
};

// Everything read from the file, still keyed by Gmsh tags.
struct MshFile {
  std::map<std::pair<int, int>, std::string> physical_names;         // (dim, tag) -> name
  std::map<std::pair<int, int>, std::vector<int>> entity_physicals;  // (dim, tag) -> tags
  std::vector<Vec3> node_x;                                          // in file order
  std::unordered_map<Tag, Index> node_index;                         // tag -> file order
  std::vector<ElementBlock> blocks;
  bool has_nodes = false, has_elements = false;
};

std::string read_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path + ": no such file");
  if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open file");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw InputError(path + ": cannot read file");
  return std::move(buffer).str();
}

void read_mesh_format(Lexer& lex, const std::string& path) {
  const std::string version(lex.token());
  const std::string file_type(lex.token());
  if (version != "4.1")
    throw InputError(path + ": Gmsh MSH format " + (version.empty() ? "?" : version) +
                     " is not supported; write MSH 4.1 ASCII (gmsh -format msh41)");
  if (file_type != "0")
    throw InputError(path +
                     ": binary Gmsh MSH is not supported; write MSH 4.1 ASCII (gmsh -format "
                     "msh41, without -bin)");
  lex.token();  // data size
  lex.expect_end("$MeshFormat");
}

void read_physical_names(Lexer& lex, MshFile& msh) {
  const auto n = lex.number<std::size_t>("$PhysicalNames");
  lex.rest_of_line();
  for (std::size_t i = 0; i < n; ++i) {
    const int dim = lex.number<int>("$PhysicalNames");
    const int tag = lex.number<int>("$PhysicalNames");
    // The name is quoted and may contain blanks.
    std::string_view rest = lex.rest_of_line();
    const auto first = rest.find('"'), last = rest.rfind('"');
    if (first == std::string_view::npos || last == first)
      lex.fail("physical name of tag "s + std::to_string(tag) + " is not quoted");
    msh.physical_names[{dim, tag}] = std::string(rest.substr(first + 1, last - first - 1));
  }
  lex.expect_end("$PhysicalNames");
}

void read_entities(Lexer& lex, MshFile& msh) {
  constexpr std::string_view kSection = "$Entities";
  std::size_t count[4];
  for (auto& c : count) c = lex.number<std::size_t>(kSection);
  for (int dim = 0; dim < 4; ++dim) {
    for (std::size_t i = 0; i < count[dim]; ++i) {
      const int tag = lex.number<int>(kSection);
      // A point has its coordinates, the others their bounding box.
      for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) lex.number<double>(kSection);
      const auto n_physicals = lex.number<std::size_t>(kSection);
      std::vector<int> physicals;
      for (std::size_t k = 0; k < n_physicals; ++k) physicals.push_back(lex.number<int>(kSection));
      if (!physicals.empty()) msh.entity_physicals[{dim, tag}] = std::move(physicals);
      if (dim > 0) {
        const auto n_bounding = lex.number<std::size_t>(kSection);
        for (std::size_t k = 0; k < n_bounding; ++k) lex.number<int>(kSection);
      }
    }
  }
  lex.expect_end(kSection);
}

void read_nodes(Lexer& lex, MshFile& msh) {
  constexpr std::string_view kSection = "$Nodes";
  const auto n_blocks = lex.number<std::size_t>(kSection);
  const auto n_nodes = lex.number<std::size_t>(kSection);
  lex.number<Tag>(kSection);  // min tag
  lex.number<Tag>(kSection);  // max tag
  msh.node_index.reserve(n_nodes);
  std::vector<Tag> tags;
  for (std::size_t b = 0; b < n_blocks; ++b) {
    const int entity_dim = lex.number<int>(kSection);
    lex.number<int>(kSection);  // entity tag
    const int parametric = lex.number<int>(kSection);
    const auto n = lex.number<std::size_t>(kSection);
    tags.clear();
    for (std::size_t i = 0; i < n; ++i) tags.push_back(lex.number<Tag>(kSection));
    for (std::size_t i = 0; i < n; ++i) {
      Vec3 x;
      for (int k = 0; k < 3; ++k) x[k] = lex.number<double>(kSection);
      // Parametric nodes carry entity_dim extra coordinates (u, v, w) we do not need.
      if (parametric)
        for (int k = 0; k < entity_dim; ++k) lex.number<double>(kSection);
      const auto [it, inserted] =
          msh.node_index.emplace(tags[i], static_cast<Index>(msh.node_x.size()));
      if (!inserted) lex.fail("node "s + std::to_string(tags[i]) + " is defined twice");
      msh.node_x.push_back(x);
    }
  }
  lex.expect_end(kSection);
  msh.has_nodes = true;
}

void read_elements(Lexer& lex, MshFile& msh) {
  constexpr std::string_view kSection = "$Elements";
  const auto n_blocks = lex.number<std::size_t>(kSection);
  lex.number<std::size_t>(kSection);  // number of elements
  lex.number<Tag>(kSection);          // min tag
  lex.number<Tag>(kSection);          // max tag
  for (std::size_t b = 0; b < n_blocks; ++b) {
    ElementBlock block;
    block.entity_dim = lex.number<int>(kSection);
    block.entity_tag = lex.number<int>(kSection);
    block.type = lex.number<int>(kSection);
    const auto n = lex.number<std::size_t>(kSection);
    const ElementType type = element_type(block.type);
    if (type.dim >= 0) {
      if (type.dim != block.entity_dim)
        lex.fail(std::string(type.name) + " elements in an entity of dimension " +
                 std::to_string(block.entity_dim));
      for (std::size_t i = 0; i < n; ++i) {
        block.tags.push_back(lex.number<Tag>(kSection));
        for (int k = 0; k < type.n_nodes; ++k) block.nodes.push_back(lex.number<Tag>(kSection));
      }
    } else {
      // Unsupported type: skip its lines (one element per line); it is an error only if the
      // block turns out to hold cells or boundary faces.
      block.supported = false;
      lex.rest_of_line();
      for (std::size_t i = 0; i < n; ++i) {
        const std::string_view line = lex.rest_of_line();
        if (line.empty() || line.front() == '$') lex.fail("truncated $Elements section");
      }
    }
    msh.blocks.push_back(std::move(block));
  }
  lex.expect_end(kSection);
  msh.has_elements = true;
}

MshFile parse(const std::string& path) {
  Lexer lex(read_file(path), path);
  MshFile msh;
  if (lex.token() != "$MeshFormat")
    throw InputError(path + ": not a Gmsh MSH file (it does not start with $MeshFormat)");
  read_mesh_format(lex, path);
  for (std::string_view tok = lex.token(); !tok.empty(); tok = lex.token()) {
    if (tok == "$PhysicalNames") {
      read_physical_names(lex, msh);
    } else if (tok == "$Entities") {
      read_entities(lex, msh);
    } else if (tok == "$PartitionedEntities") {
      lex.fail("partitioned meshes are not supported");
    } else if (tok == "$Nodes") {
      read_nodes(lex, msh);
    } else if (tok == "$Elements") {
      read_elements(lex, msh);
    } else if (tok.front() == '$') {
      lex.skip_section(tok);
    } else {
      lex.fail("unexpected '"s + std::string(tok) + "' outside a section");
    }
  }
  if (!msh.has_nodes) throw InputError(path + ": no $Nodes section");
  if (!msh.has_elements) throw InputError(path + ": no $Elements section");
  return msh;
}

// The Gmsh node tags of element i of a block, mapped to file-order node indices.
std::vector<Index> element_nodes(const MshFile& msh, const ElementBlock& block, std::size_t i,
                                 const std::string& path) {
  const int n = element_type(block.type).n_nodes;
  std::vector<Index> nodes(n);
  for (int k = 0; k < n; ++k) {
    const Tag tag = block.nodes[i * n + k];
    const auto it = msh.node_index.find(tag);
    if (it == msh.node_index.end())
      throw InputError(path + ": element " + std::to_string(block.tags[i]) +
                       " references undefined node " + std::to_string(tag));
    nodes[k] = it->second;
  }
  return nodes;
}

void require_supported(const ElementBlock& block, const std::string& path) {
  if (!block.supported || element_type(block.type).dim < 0)
    throw InputError(path + ": element type " + std::to_string(block.type) + " (" +
                     element_type(block.type).name +
                     ") is not supported; only first-order elements are");
}

// Name of the patch of a boundary-face entity, or empty if it is in no physical group.
// An entity in several groups goes to the first: a face can belong to one patch only.
std::string patch_name(const MshFile& msh, int dim, int entity_tag) {
  const auto it = msh.entity_physicals.find({dim, entity_tag});
  if (it == msh.entity_physicals.end()) return {};
  const int physical = std::abs(it->second.front());
  const auto name = msh.physical_names.find({dim, physical});
  return name != msh.physical_names.end() ? name->second : "physical_"s + std::to_string(physical);
}

}  // namespace

Mesh read_gmsh_mesh(const std::string& path, int dim) {
  const MshFile msh = parse(path);

  if (dim == 0) {
    for (const auto& block : msh.blocks)
      if (!block.tags.empty() || !block.supported) dim = std::max(dim, block.entity_dim);
    if (dim < 2) throw InputError(path + ": no 2D or 3D elements");
  } else if (dim != 2 && dim != 3) {
    throw InputError(path + ": mesh dimension must be 2 or 3, not " + std::to_string(dim));
  }

  // Cells, still in file-order node indices; remember the element tags for messages.
  std::vector<std::pair<CellShape, std::vector<Index>>> cells;
  std::vector<Tag> cell_tags;
  for (const auto& block : msh.blocks) {
    if (block.entity_dim != dim) continue;
    require_supported(block, path);
    for (std::size_t i = 0; i < block.tags.size(); ++i) {
      cells.emplace_back(element_type(block.type).shape, element_nodes(msh, block, i, path));
      cell_tags.push_back(block.tags[i]);
    }
  }
  if (cells.empty()) throw InputError(path + ": no " + std::to_string(dim) + "D elements");

  // Keep the nodes used by cells, in file order (Gmsh also lists unmeshed points).
  std::vector<Index> new_index(msh.node_x.size(), -1);
  for (const auto& cell : cells)
    for (const Index n : cell.second) new_index[n] = 0;
  MeshBuilder builder(dim);
  Real extent = 0.0;
  for (std::size_t n = 0; n < msh.node_x.size(); ++n)
    if (new_index[n] == 0) extent = std::max(extent, msh.node_x[n].cwiseAbs().maxCoeff());
  for (std::size_t n = 0; n < msh.node_x.size(); ++n) {
    if (new_index[n] < 0) continue;
    Vec3 x = msh.node_x[n];
    if (dim == 2) {
      // Round-off from the CAD kernel is tolerated; a tilted or offset plane is not.
      if (std::abs(x.z()) > 1e-10 * extent)
        throw InputError(path + ": a 2D mesh must lie in the z = 0 plane (a node has z = " +
                         std::to_string(x.z()) + ")");
      x.z() = 0.0;
    }
    new_index[n] = builder.add_node(x);
  }
  for (auto& [shape, nodes] : cells) {
    for (Index& n : nodes) n = new_index[n];
    builder.add_cell(shape, std::move(nodes));
  }

  // Orientation: Gmsh draws 2D cells counterclockwise about the surface normal, which is -z
  // for some geometries; then every cell is clockwise and the whole mesh is reversed.
  const auto message = [&](const char* what, Index c) {
    return path + ": " + what + " cell " + std::to_string(cell_tags[c]);
  };
  Index n_negative = 0, first_negative = -1, first_positive = -1;
  for (Index c = 0; c < builder.n_cells(); ++c) {
    const Real measure = builder.signed_measure(c);
    if (measure == 0.0) throw MeshError(message("degenerate", c));
    if (measure < 0.0) {
      ++n_negative;
      if (first_negative < 0) first_negative = c;
    } else if (first_positive < 0) {
      first_positive = c;
    }
  }
  if (dim == 2 && n_negative == builder.n_cells()) {
    builder.reverse_all_cells();
  } else if (n_negative > 0) {
    // Blame the minority orientation (3D cells must all be positive).
    const bool blame_positive = dim == 2 && 2 * n_negative > builder.n_cells();
    throw MeshError(message("inverted", blame_positive ? first_positive : first_negative));
  }

  // Boundary faces: elements one dimension down on an entity of a physical group.
  for (const auto& block : msh.blocks) {
    if (block.entity_dim != dim - 1) continue;
    const std::string patch = patch_name(msh, dim - 1, block.entity_tag);
    if (patch.empty()) continue;
    require_supported(block, path);
    for (std::size_t i = 0; i < block.tags.size(); ++i) {
      std::vector<Index> nodes = element_nodes(msh, block, i, path);
      for (Index& n : nodes) {
        n = new_index[n];
        if (n < 0)
          throw InputError(path + ": boundary element " + std::to_string(block.tags[i]) + " of \"" +
                           patch + "\" has a node that belongs to no cell");
      }
      builder.add_boundary_face(std::move(nodes), patch);
    }
  }

  return builder.build(path, "unassigned");
}

}  // namespace rfmems
