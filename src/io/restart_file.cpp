#include "restart_file.hpp"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "abut/core/error.hpp"
#include "io/output_file.hpp"

namespace abut::restart_file {

namespace {

constexpr char kMagic[8] = {'A', 'B', 'U', 'T', 'R', 'S', 'T', '\n'};
// 2: the simulation's state holds the conserved kinetic energy of the balance (issue 28).
// 3: the contact broad phase's grid has a cell size per axis (issue 28).
// 4: contacts keep the damping part of each point's force and the nodal damping forces of the
//    last step, whose work they book over the step after (issue 27).
// 5: the heat balance keeps the largest heat of the run; the simulation keeps the heat the contact
//    conducts apart from the mechanics' heat, and the thermal expansion work (issue 29).
// 6: the sensors' trigger times and the boundary conditions released at impact (issue 31).
constexpr std::uint32_t kVersion = 6;

// FNV-1a, 64 bits (Fowler, Noll, Vo): a checksum, not a cryptographic hash.
class Fnv {
 public:
  void add(const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) hash_ = (hash_ ^ p[i]) * 0x100000001b3ULL;
  }
  template <class T>
  void add_all(const std::vector<T>& v) {
    const std::uint64_t n = v.size();
    add(&n, sizeof n);
    add(v.data(), v.size() * sizeof(T));
  }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

// What a restart must share with the model that wrote it: the mesh (coordinates, elements and
// their parts). Materials, loads, contacts and times may change between the two runs; the
// state's own counts are then checked section by section (StateArchive::expect).
std::uint64_t fingerprint(const Model& model) {
  const Mesh& mesh = model.mesh;
  Fnv h;
  h.add_all(mesh.nodes.x);
  h.add_all(mesh.nodes.y);
  h.add_all(mesh.nodes.z);
  h.add_all(mesh.hexes);
  h.add_all(mesh.hex_part);
  h.add_all(mesh.shells);
  h.add_all(mesh.shell_part);
  for (const CellBlock& b : mesh.cells) {
    const auto type = static_cast<std::uint8_t>(b.type);
    h.add(&type, sizeof type);
    h.add_all(b.nodes);
    h.add_all(b.part);
  }
  return h.value();
}

template <class T>
void put(std::string& out, const T& v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof(T));
}

}  // namespace

void write(const std::filesystem::path& path, const Model& model, const StateArchive& archive) {
  const std::vector<char>& payload = archive.bytes();
  Fnv checksum;
  checksum.add(payload.data(), payload.size());
  std::string text(kMagic, sizeof kMagic);
  put(text, kVersion);
  put(text, fingerprint(model));
  put(text, static_cast<std::uint64_t>(payload.size()));
  text.append(payload.data(), payload.size());
  put(text, checksum.value());
  output_file::replace(path, text);
}

StateArchive read(const std::filesystem::path& path, const Model& model) {
  const SourceLocation where{path.string(), 0, "", ""};
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw InputError(where, "the restart file does not exist or is not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(where, "cannot read the restart file");
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  constexpr std::size_t kHeader = sizeof kMagic + sizeof(std::uint32_t) + 2 * sizeof(std::uint64_t);
  if (bytes.size() < kHeader || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    throw InputError(where, "not an abut restart file");
  std::size_t at = sizeof kMagic;
  const auto take = [&](auto& v) {
    std::memcpy(&v, bytes.data() + at, sizeof v);
    at += sizeof v;
  };
  std::uint32_t version = 0;
  std::uint64_t print = 0, size = 0, stored_checksum = 0;
  take(version);
  if (version != kVersion)
    throw InputError(where, "restart file format " + std::to_string(version) +
                                ", this abut reads format " + std::to_string(kVersion));
  take(print);
  if (print != fingerprint(model))
    throw InputError(where,
                     "the restart file was written for another mesh: restart with the deck (and "
                     "the same nodes, elements and parts) of the run that wrote it");
  take(size);
  if (size > bytes.size() - at || bytes.size() - at - size != sizeof stored_checksum)
    throw InputError(where, "the restart file is incomplete or damaged (size)");
  std::vector<char> payload(bytes.begin() + static_cast<std::ptrdiff_t>(at),
                            bytes.begin() + static_cast<std::ptrdiff_t>(at + size));
  at += size;
  take(stored_checksum);
  Fnv checksum;
  checksum.add(payload.data(), payload.size());
  if (checksum.value() != stored_checksum)
    throw InputError(where, "the restart file is damaged (checksum)");
  return StateArchive::for_loading(std::move(payload));
}

}  // namespace abut::restart_file
