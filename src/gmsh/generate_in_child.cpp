#include "gmsh/generate_in_child.h"

#include <gmsh.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <type_traits>
#include <vector>

#include "core/error.h"
#include "gmsh/gmsh_call.h"

namespace homesh::gmsh_adapter {
namespace {

// The mesh of one model entity, as Gmsh's API gives and takes it.
struct EntityMesh {
  int dim = 0, tag = 0;
  std::vector<std::size_t> node_tags;
  std::vector<double> coords, parametric;
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> element_tags, element_nodes;
};

class Writer {
 public:
  explicit Writer(int fd) : fd_(fd) {}
  template <class T>
  void scalar(T v) {
    bytes(&v, sizeof v);
  }
  template <class T>
  void vector(const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    scalar<std::uint64_t>(v.size());
    bytes(v.data(), v.size() * sizeof(T));
  }

 private:
  void bytes(const void* p, std::size_t n) {
    const char* c = static_cast<const char*>(p);
    while (n > 0) {
      const ssize_t w = write(fd_, c, n);
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) throw Error(std::string("cannot send the mesh back: ") + std::strerror(errno));
      c += w;
      n -= static_cast<std::size_t>(w);
    }
  }
  int fd_;
};

class Reader {
 public:
  explicit Reader(const std::string& s) : s_(s) {}
  template <class T>
  T scalar() {
    T v;
    bytes(&v, sizeof v);
    return v;
  }
  template <class T>
  std::vector<T> vector() {
    const auto n = scalar<std::uint64_t>();
    if (n > (s_.size() - at_) / sizeof(T)) throw Error("the mesher's child sent a cut mesh");
    std::vector<T> v(n);
    bytes(v.data(), n * sizeof(T));
    return v;
  }
  bool done() const { return at_ == s_.size(); }

 private:
  void bytes(void* p, std::size_t n) {
    if (n == 0) return;  // an empty vector's data() may be null, which memcpy may not take
    if (n > s_.size() - at_) throw Error("the mesher's child sent a cut mesh");
    std::memcpy(p, s_.data() + at_, n);
    at_ += n;
  }
  const std::string& s_;
  std::size_t at_ = 0;
};

std::size_t count_elements(int dim) {
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> tags, nodes;
  gmsh::model::mesh::getElements(types, tags, nodes, dim, -1);
  std::size_t n = 0;
  for (const auto& t : tags) n += t.size();
  return n;
}

void check_count(const std::string& subject, std::size_t count, std::size_t max,
                 const std::string& what) {
  if (max > 0 && count > max)
    throw Error(subject + ": Gmsh's mesher made " + std::to_string(count) + " " + what +
                ", more than the limit of " + std::to_string(max) +
                " (mesh:max_triangles): are the mesh sizes (mesh:factor, size_max, the .geo's) "
                "too small?");
}

// In the child: mesh, check the counts, send every entity's mesh to `fd`.
void mesh_and_send(const std::string& subject, const MeshingLimits& limits, int fd) {
  gmsh_call(subject + ": Gmsh's mesher", [&] {
    gmsh::option::setNumber("General.NumThreads", 1);  // no OpenMP pool in a forked child
    gmsh::option::setNumber("Mesh.MaxNumThreads1D", 1);
    gmsh::option::setNumber("Mesh.MaxNumThreads2D", 1);
    gmsh::option::setNumber("Mesh.MaxNumThreads3D", 1);
    gmsh::model::mesh::clear();
    gmsh::model::mesh::generate(1);
  });
  check_count(subject, count_elements(1), limits.max_elements, "boundary lines");
  gmsh_call(subject + ": Gmsh's mesher", [] { gmsh::model::mesh::generate(2); });
  check_count(subject, count_elements(2), limits.max_elements, "triangles");
  if (limits.dim == 3) {
    gmsh_call(subject + ": Gmsh's mesher", [] { gmsh::model::mesh::generate(3); });
    check_count(subject, count_elements(3), limits.max_elements, "tetrahedra");
  }

  Writer out(fd);
  gmsh::vectorpair entities;
  gmsh::model::getEntities(entities, -1);
  out.scalar<std::uint64_t>(entities.size());
  for (const auto& [dim, tag] : entities) {
    EntityMesh m;
    gmsh::model::mesh::getNodes(m.node_tags, m.coords, m.parametric, dim, tag, false, true);
    gmsh::model::mesh::getElements(m.types, m.element_tags, m.element_nodes, dim, tag);
    out.scalar(dim);
    out.scalar(tag);
    out.vector(m.node_tags);
    out.vector(m.coords);
    out.vector(m.parametric);
    out.vector(m.types);
    for (std::size_t k = 0; k < m.types.size(); ++k) {
      out.vector(m.element_tags[k]);
      out.vector(m.element_nodes[k]);
    }
  }
}

std::vector<EntityMesh> decode(const std::string& bytes) {
  Reader in(bytes);
  const auto n = in.scalar<std::uint64_t>();
  if (n > bytes.size()) throw Error("the mesher's child sent a cut mesh");
  std::vector<EntityMesh> entities(n);
  for (EntityMesh& m : entities) {
    m.dim = in.scalar<int>();
    m.tag = in.scalar<int>();
    m.node_tags = in.vector<std::size_t>();
    m.coords = in.vector<double>();
    m.parametric = in.vector<double>();
    m.types = in.vector<int>();
    for (std::size_t k = 0; k < m.types.size(); ++k) {
      m.element_tags.push_back(in.vector<std::size_t>());
      m.element_nodes.push_back(in.vector<std::size_t>());
    }
  }
  if (!in.done()) throw Error("the mesher's child sent more than a mesh");
  return entities;
}

}  // namespace

std::uint64_t default_memory_cap() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return 0;
  return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page) / 4 * 3;
}

void generate_in_child(const std::string& subject, const MeshingLimits& limits) {
  const std::string bytes =
      run_in_child(limits.child,
                   {subject, "Gmsh's mesher", "",
                    "are the mesh sizes too small? (mesh:max_seconds raises the "
                    "time limit)"},
                   [&](int fd) { mesh_and_send(subject, limits, fd); });
  std::vector<EntityMesh> entities;
  try {
    entities = decode(bytes);
  } catch (const Error& e) {
    throw Error(subject + ": " + e.what());
  }
  gmsh_call(subject + ": taking Gmsh's mesh", [&] {
    gmsh::model::mesh::clear();
    for (const EntityMesh& m : entities)  // every node first: elements name nodes of other entities
      if (!m.node_tags.empty())
        gmsh::model::mesh::addNodes(m.dim, m.tag, m.node_tags, m.coords, m.parametric);
    for (const EntityMesh& m : entities)
      for (std::size_t k = 0; k < m.types.size(); ++k)
        gmsh::model::mesh::addElementsByType(m.tag, m.types[k], m.element_tags[k],
                                             m.element_nodes[k]);
  });
}

}  // namespace homesh::gmsh_adapter
