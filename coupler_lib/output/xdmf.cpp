#include "coupler_lib/output/xdmf.hpp"

#include <iomanip>
#include <sstream>

namespace lbdem {

namespace {

void data_item(std::ostringstream& x, const XdmfArray& a, const char* indent) {
  x << indent << "<DataItem Dimensions=\"";
  for (size_t i = 0; i < a.dims.size(); ++i) x << (i ? " " : "") << a.dims[i];
  x << "\" NumberType=\"" << a.number_type << "\" Precision=\"" << a.precision
    << "\" Format=\"HDF\">" << a.source << "</DataItem>\n";
}

void inline_triple(std::ostringstream& x, const std::array<double, 3>& v) {
  x << "        <DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">"
    << v[0] << " " << v[1] << " " << v[2] << "</DataItem>\n";
}

void mesh(std::ostringstream& x, const XdmfLattice& m) {
  x << "      <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"" << m.dims[0] << " "
    << m.dims[1] << " " << m.dims[2] << "\"/>\n"
    << "      <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n";
  inline_triple(x, m.origin);
  inline_triple(x, m.spacing);
  x << "      </Geometry>\n";
}

void mesh(std::ostringstream& x, const XdmfPoints& m) {
  x << "      <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << m.count
    << "\" NodesPerElement=\"1\"/>\n"
    << "      <Geometry GeometryType=\"XYZ\">\n";
  data_item(x, m.positions, "        ");
  x << "      </Geometry>\n";
}

void mesh(std::ostringstream& x, const XdmfTriangles& m) {
  x << "      <Topology TopologyType=\"Triangle\" NumberOfElements=\"" << m.triangles << "\">\n";
  data_item(x, m.connectivity, "        ");
  x << "      </Topology>\n"
    << "      <Geometry GeometryType=\"XYZ\">\n";
  data_item(x, m.positions, "        ");
  x << "      </Geometry>\n";
}

}  // namespace

std::string xdmf_series(const std::string& name, const std::vector<XdmfGrid>& grids) {
  std::ostringstream x;
  x << std::setprecision(17);  // round-trips every double
  x << "<?xml version=\"1.0\" ?>\n"
    << "<Xdmf Version=\"3.0\">\n"
    << "  <Domain>\n"
    << "    <Grid Name=\"" << name << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const auto& g : grids) {
    x << "    <Grid Name=\"" << g.name << "\" GridType=\"Uniform\">\n"
      << "      <Time Value=\"" << g.time << "\"/>\n";
    std::visit([&](const auto& m) { mesh(x, m); }, g.mesh);
    for (const auto& a : g.attributes) {
      x << "      <Attribute Name=\"" << a.name << "\" AttributeType=\"" << a.type
        << "\" Center=\"Node\">\n";
      data_item(x, a.data, "        ");
      x << "      </Attribute>\n";
    }
    x << "    </Grid>\n";
  }
  x << "    </Grid>\n"
    << "  </Domain>\n"
    << "</Xdmf>\n";
  return x.str();
}

}  // namespace lbdem
