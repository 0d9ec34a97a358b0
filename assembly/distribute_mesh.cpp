#include "assembly/distribute_mesh.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <algorithm>
#include <cstring>

#include "assembly/agree_on_errors.hpp"

namespace grout {

namespace {

// A flat byte buffer: the mesh's plain data in a fixed order.
class Buffer {
 public:
  std::vector<char> bytes;
  std::size_t at = 0;

  template <class T>
  void put(const T& value) {
    const char* p = reinterpret_cast<const char*>(&value);
    bytes.insert(bytes.end(), p, p + sizeof(T));
  }
  template <class T>
  void put(const std::vector<T>& values) {
    put(values.size());
    const char* p = reinterpret_cast<const char*>(values.data());
    bytes.insert(bytes.end(), p, p + values.size() * sizeof(T));
  }
  void put(const std::string& s) { put(std::vector<char>(s.begin(), s.end())); }

  template <class T>
  void get(T& value) {
    std::memcpy(&value, bytes.data() + at, sizeof(T));
    at += sizeof(T);
  }
  template <class T>
  void get(std::vector<T>& values) {
    std::size_t n = 0;
    get(n);
    values.resize(n);
    // An empty vector's data() may be null, which memcpy must not get even for 0 bytes.
    if (n > 0) std::memcpy(static_cast<void*>(values.data()), bytes.data() + at, n * sizeof(T));
    at += n * sizeof(T);
  }
  void get(std::string& s) {
    std::vector<char> chars;
    get(chars);
    s.assign(chars.begin(), chars.end());
  }
};

void pack(const Mesh& m, Buffer& b) {
  b.put(m.file);
  b.put(m.dimension);
  b.put(m.coordinates);
  b.put(m.blocks.size());
  for (const auto& x : m.blocks) {
    b.put(x.name), b.put(x.id), b.put(x.topology), b.put(x.nodes_per_element);
    b.put(x.first_element), b.put(x.connectivity);
  }
  b.put(m.side_sets.size());
  for (const auto& x : m.side_sets) b.put(x.name), b.put(x.id), b.put(x.elements), b.put(x.sides);
  b.put(m.node_sets.size());
  for (const auto& x : m.node_sets) b.put(x.name), b.put(x.id), b.put(x.nodes);
}

void unpack(Buffer& b, Mesh& m) {
  b.get(m.file);
  b.get(m.dimension);
  b.get(m.coordinates);
  std::size_t n = 0;
  b.get(n);
  m.blocks.resize(n);
  for (auto& x : m.blocks) {
    b.get(x.name), b.get(x.id), b.get(x.topology), b.get(x.nodes_per_element);
    b.get(x.first_element), b.get(x.connectivity);
  }
  b.get(n);
  m.side_sets.resize(n);
  for (auto& x : m.side_sets) b.get(x.name), b.get(x.id), b.get(x.elements), b.get(x.sides);
  b.get(n);
  m.node_sets.resize(n);
  for (auto& x : m.node_sets) b.get(x.name), b.get(x.id), b.get(x.nodes);
}

}  // namespace

Mesh read_and_broadcast_mesh(const Comm& comm, const std::function<Mesh()>& read) {
  // Any error of the reading rank (an InputError, std::bad_alloc, a library's exception) ends
  // every rank: the others would otherwise wait in the broadcast below for ever.
  Mesh mesh;
  agree_on_errors(comm, [&] {
    if (comm.getRank() == 0) mesh = read();
  });
  if (comm.getSize() == 1) return mesh;
  Buffer buffer;
  if (comm.getRank() == 0) pack(mesh, buffer);
  long long size = static_cast<long long>(buffer.bytes.size());
  Teuchos::broadcast(comm, 0, &size);
  buffer.bytes.resize(std::size_t(size));
  // MPI counts are int: a buffer over 2 GiB goes in pieces (one count of its size overflowed
  // into MPI_ERR_TRUNCATE).
  constexpr long long piece = 1LL << 30;
  for (long long at = 0; at < size; at += piece)
    Teuchos::broadcast(comm, 0, int(std::min(piece, size - at)), buffer.bytes.data() + at);
  if (comm.getRank() != 0) unpack(buffer, mesh);
  return mesh;
}

}  // namespace grout
