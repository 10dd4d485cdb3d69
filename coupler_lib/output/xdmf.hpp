#pragma once
// The one XDMF (version 3) writer of both programs: a temporal collection of uniform grids whose
// arrays live in HDF5 files, which ParaView opens with its XDMF readers. The fluid fields are
// lattices (3DCoRectMesh, origin and spacing inline); the bodies are points (Polyvertex) and
// their surfaces triangles. The text is rewritten whole after each output step through
// write_file_atomically, so a reader never sees a half-written file.
#include <array>
#include <string>
#include <variant>
#include <vector>

namespace lbdem {

// An array stored in HDF5: `source` is "<file>.h5:/<group>/<dataset>", the file relative to the
// XDMF file. Dimensions are listed slowest first, as XDMF expects.
struct XdmfArray {
  std::vector<long> dims;
  std::string number_type = "Float";  // "Float" or "Int"
  int precision = 8;                  // bytes per value
  std::string source;
};

struct XdmfAttribute {
  std::string name;
  std::string type;  // "Scalar", "Vector", "Tensor" or "Matrix"
  XdmfArray data;    // one value per node
};

// A co-rectilinear lattice; dims, origin and spacing slowest axis first (z, y, x).
struct XdmfLattice {
  std::array<long, 3> dims{};
  std::array<double, 3> origin{}, spacing{};
};

// Unconnected points, their coordinates an n x 3 array (x, y, z).
struct XdmfPoints {
  long count = 0;
  XdmfArray positions;
};

// A triangle surface: point coordinates (n x 3) and connectivity (triangles x 3, 0-based indices
// into the points).
struct XdmfTriangles {
  long points = 0;
  XdmfArray positions;
  long triangles = 0;
  XdmfArray connectivity;
};

struct XdmfGrid {
  std::string name;
  double time = 0;
  std::variant<XdmfLattice, XdmfPoints, XdmfTriangles> mesh;
  std::vector<XdmfAttribute> attributes;  // all node-centred
};

// The complete XDMF text of a temporal collection called `name` holding `grids` in order.
std::string xdmf_series(const std::string& name, const std::vector<XdmfGrid>& grids);

}  // namespace lbdem
