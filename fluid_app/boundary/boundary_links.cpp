#include "fluid_app/boundary/boundary_links.hpp"

#include "coupler_lib/scene/fluid_section.hpp"
#include "fluid_app/lattice/d3q19.hpp"

namespace lbdem {

namespace {

bool is_wall(int type) {
  return type == int(FaceType::wall) || type == int(FaceType::moving_wall);
}

}  // namespace

template <class T>
BoundaryLinks<T>::BoundaryLinks(const Decomposition& dec, const std::array<FaceRule, 6>& faces,
                                CellIndex stride)
    : faces_(faces), stride_(stride) {
  using namespace d3q19;
  const LocalBox& b = dec.box();
  for (int i = 0; i < Q; ++i) shift_[i] = b.shift(c[i][0], c[i][1], c[i][2]);
  for (int z = 1; z <= b.n[2]; ++z)
    for (int y = 1; y <= b.n[1]; ++y)
      for (int x = 1; x <= b.n[0]; ++x) {
        const int p[3] = {x, y, z};
        bool edge = false;
        for (int a = 0; a < 3; ++a) edge = edge || p[a] == 1 || p[a] == b.n[a];
        if (!edge) continue;
        Cell cell{b.index(x, y, z), std::uint32_t(link_i_.size()), 0, false};
        for (int i = 1; i < Q; ++i) {
          int e[3];
          for (int a = 0; a < 3; ++a) {
            const int t = p[a] + c[i][a];
            e[a] = t < 1 ? -1 : (t > b.n[a] ? 1 : 0);
          }
          if ((e[0] | e[1] | e[2]) == 0 || dec.neighbour(e[0], e[1], e[2]) != MPI_PROC_NULL)
            continue;
          // The global faces this link crosses; walls first, then the lower index.
          int face = -1;
          for (int a = 0; a < 3; ++a) {
            if (e[a] == 0 || dec.neighbour(a == 0 ? e[0] : 0, a == 1 ? e[1] : 0,
                                           a == 2 ? e[2] : 0) != MPI_PROC_NULL)
              continue;
            const int fa = 2 * a + (e[a] > 0 ? 1 : 0);
            if (face < 0 || (is_wall(faces[fa].type) && !is_wall(faces[face].type))) face = fa;
          }
          link_i_.push_back(std::int8_t(i));
          link_face_.push_back(std::int8_t(face));
          ++cell.count;
          cell.moments = cell.moments || faces[face].type != int(FaceType::wall);
        }
        if (cell.count > 0) cells_.push_back(cell);
      }
}

template <class T>
void BoundaryLinks<T>::apply(T* f, bool after_odd) const {
  using namespace d3q19;
  for (const Cell& cl : cells_) {
    // Post-collision population k of this cell, wherever the AA step left it.
    auto post = [&](int k) -> T& {
      return after_odd ? f[k * stride_ + cl.cell + shift_[k]] : f[opposite(k) * stride_ + cl.cell];
    };
    T rho = 0, ux = 0, uy = 0, uz = 0;
    if (cl.moments) {
      for (int k = 0; k < Q; ++k) {
        const T v = post(k);
        rho += v;
        ux += T(c[k][0]) * v;
        uy += T(c[k][1]) * v;
        uz += T(c[k][2]) * v;
      }
      ux /= rho;
      uy /= rho;
      uz /= rho;
    }
    for (std::uint32_t l = cl.first; l < cl.first + cl.count; ++l) {
      const int i = link_i_[l];
      const FaceRule& r = faces_[link_face_[l]];
      const T out = post(i);  // f*_i(x), leaving through the face
      T back = out;
      if (r.type == int(FaceType::moving_wall)) {
        const T cu = T(c[i][0] * r.velocity[0] + c[i][1] * r.velocity[1] + c[i][2] * r.velocity[2]);
        back = out - T(6 * w[i]) * rho * cu;
      } else if (r.type == int(FaceType::pressure)) {
        const T cu = T(c[i][0]) * ux + T(c[i][1]) * uy + T(c[i][2]) * uz;
        const T uu = ux * ux + uy * uy + uz * uz;
        back = -out + T(2 * w[i] * r.density) * (T(1) + T(4.5) * cu * cu - T(1.5) * uu);
      }
      // Where the next step reads f_ibar(x): slot ibar of x after an odd step; after an even
      // step slot i of the ghost x + c_i, from where the odd step pulls it.
      if (after_odd)
        f[opposite(i) * stride_ + cl.cell] = back;
      else
        f[i * stride_ + cl.cell + shift_[i]] = back;
    }
  }
}

template class BoundaryLinks<double>;
template class BoundaryLinks<float>;

}  // namespace lbdem
