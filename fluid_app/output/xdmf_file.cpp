#include "fluid_app/output/xdmf_file.hpp"

#include <cstdio>
#include <iomanip>
#include <sstream>

namespace lbdem {

namespace {

void attribute(std::ostringstream& x, const char* name, bool vector, const std::string& dims,
               int precision, const std::string& h5, const std::string& view) {
  x << "      <Attribute Name=\"" << name << "\" AttributeType=\"" << (vector ? "Vector" : "Scalar")
    << "\" Center=\"Node\">\n"
    << "        <DataItem Dimensions=\"" << dims << (vector ? " 3" : "")
    << "\" NumberType=\"Float\" Precision=\"" << precision << "\" Format=\"HDF\">" << h5 << ":/"
    << view << "/" << name << "</DataItem>\n"
    << "      </Attribute>\n";
}

}  // namespace

std::string xdmf_text(const FieldView& view, const FieldQuantities& what, double dx,
                      const std::vector<XdmfStep>& steps) {
  std::ostringstream x;
  x << std::setprecision(17);
  // 3DCoRectMesh lists dimensions, origin and spacing slowest axis first: z, y, x.
  const auto& a = view.axes;
  std::ostringstream dims;
  dims << a[2].count << " " << a[1].count << " " << a[0].count;
  const int precision = what.double_precision ? 8 : 4;
  x << "<?xml version=\"1.0\" ?>\n"
    << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
    << "<Xdmf Version=\"2.0\">\n"
    << "  <Domain>\n"
    << "    <Grid Name=\"" << view.name
    << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const auto& s : steps) {
    x << "    <Grid Name=\"" << view.name << "\" GridType=\"Uniform\">\n"
      << "      <Time Value=\"" << s.time << "\"/>\n"
      << "      <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"" << dims.str() << "\"/>\n"
      << "      <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n"
      << "        <DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" "
         "Format=\"XML\">"
      << (a[2].start + 0.5) * dx << " " << (a[1].start + 0.5) * dx << " " << (a[0].start + 0.5) * dx
      << "</DataItem>\n"
      << "        <DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" "
         "Format=\"XML\">"
      << a[2].stride * dx << " " << a[1].stride * dx << " " << a[0].stride * dx << "</DataItem>\n"
      << "      </Geometry>\n";
    if (what.velocity) attribute(x, "velocity", true, dims.str(), precision, s.h5_file, view.name);
    if (what.density) attribute(x, "density", false, dims.str(), precision, s.h5_file, view.name);
    if (what.pressure) attribute(x, "pressure", false, dims.str(), precision, s.h5_file, view.name);
    x << "    </Grid>\n";
  }
  x << "    </Grid>\n"
    << "  </Domain>\n"
    << "</Xdmf>\n";
  return x.str();
}

}  // namespace lbdem
