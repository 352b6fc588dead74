// The cell topology table (topology.hpp). Face and edge tables follow the Abaqus/CalculiX
// numbering (CalculiX User's Manual 2.20, sections 6.2.4 C3D4, 6.2.5 C3D10, 6.2.6 C3D6,
// 6.2.2 C3D20, and the face definitions of *DLOAD); tests/mesh/test_topology.cpp checks that every
// face is outward and that every face midside node is the midside node of its edge.
#include "abut/mesh/topology.hpp"

namespace abut {
namespace {

using F = FaceTopology;
using E = EdgeTopology;
using P = std::array<double, 3>;

// Hexahedra: corner faces from kHexFaces; a 20-node face adds the midside nodes of its edges.
constexpr std::array<E, 12> kHex20Edges = {{{0, 1, 8},
                                            {1, 2, 9},
                                            {2, 3, 10},
                                            {3, 0, 11},
                                            {4, 5, 12},
                                            {5, 6, 13},
                                            {6, 7, 14},
                                            {7, 4, 15},
                                            {0, 4, 16},
                                            {1, 5, 17},
                                            {2, 6, 18},
                                            {3, 7, 19}}};

constexpr std::array<E, 12> linear_edges(const std::array<E, 12>& edges) {
  std::array<E, 12> out{};
  for (std::size_t i = 0; i < edges.size(); ++i) out[i] = {edges[i].a, edges[i].b, -1};
  return out;
}

constexpr std::int8_t midside_of(const std::array<E, 12>& edges, int a, int b) {
  for (const E& e : edges)
    if ((e.a == a && e.b == b) || (e.a == b && e.b == a)) return e.mid;
  return -1;
}

constexpr std::array<F, 6> hex_faces(bool quadratic) {
  std::array<F, 6> out{};
  for (int f = 0; f < 6; ++f) {
    out[f].type = quadratic ? FaceType::quad8 : FaceType::quad4;
    for (int k = 0; k < 4; ++k) {
      out[f].nodes[k] = static_cast<std::int8_t>(kHexFaces[f][k]);
      if (quadratic)
        out[f].nodes[4 + k] = midside_of(kHex20Edges, kHexFaces[f][k], kHexFaces[f][(k + 1) % 4]);
    }
  }
  return out;
}

constexpr auto kHex8Faces = hex_faces(false);
constexpr auto kHex20Faces = hex_faces(true);
constexpr auto kHex8Edges = linear_edges(kHex20Edges);

constexpr std::array<P, 20> kHex20Natural = {
    {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1},  {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1},
     {-1, 1, 1},   {0, -1, -1}, {1, 0, -1},  {0, 1, -1},  {-1, 0, -1}, {0, -1, 1}, {1, 0, 1},
     {0, 1, 1},    {-1, 0, 1},  {-1, -1, 0}, {1, -1, 0},  {1, 1, 0},   {-1, 1, 0}}};

// Tetrahedra: S1 = 1-2-3, S2 = 1-4-2, S3 = 2-4-3, S4 = 3-4-1 (1-based), each turned outward.
constexpr std::array<F, 4> kTet4Faces = {{{FaceType::tri3, {0, 2, 1}},
                                          {FaceType::tri3, {0, 1, 3}},
                                          {FaceType::tri3, {1, 2, 3}},
                                          {FaceType::tri3, {2, 0, 3}}}};
constexpr std::array<F, 4> kTet10Faces = {{{FaceType::tri6, {0, 2, 1, 6, 5, 4}},
                                           {FaceType::tri6, {0, 1, 3, 4, 8, 7}},
                                           {FaceType::tri6, {1, 2, 3, 5, 9, 8}},
                                           {FaceType::tri6, {2, 0, 3, 6, 7, 9}}}};
constexpr std::array<E, 6> kTet10Edges = {
    {{0, 1, 4}, {1, 2, 5}, {2, 0, 6}, {0, 3, 7}, {1, 3, 8}, {2, 3, 9}}};
constexpr std::array<E, 6> kTet4Edges = {
    {{0, 1, -1}, {1, 2, -1}, {2, 0, -1}, {0, 3, -1}, {1, 3, -1}, {2, 3, -1}}};
constexpr std::array<P, 10> kTet10Natural = {{{0, 0, 0},
                                              {1, 0, 0},
                                              {0, 1, 0},
                                              {0, 0, 1},
                                              {0.5, 0, 0},
                                              {0.5, 0.5, 0},
                                              {0, 0.5, 0},
                                              {0, 0, 0.5},
                                              {0.5, 0, 0.5},
                                              {0, 0.5, 0.5}}};

// Wedge: S1 = 1-2-3, S2 = 4-5-6, S3 = 1-2-5-4, S4 = 2-3-6-5, S5 = 3-1-4-6, turned outward.
constexpr std::array<F, 5> kWedge6Faces = {{{FaceType::tri3, {0, 2, 1}},
                                            {FaceType::tri3, {3, 4, 5}},
                                            {FaceType::quad4, {0, 1, 4, 3}},
                                            {FaceType::quad4, {1, 2, 5, 4}},
                                            {FaceType::quad4, {2, 0, 3, 5}}}};
constexpr std::array<E, 9> kWedge6Edges = {{{0, 1, -1},
                                            {1, 2, -1},
                                            {2, 0, -1},
                                            {3, 4, -1},
                                            {4, 5, -1},
                                            {5, 3, -1},
                                            {0, 3, -1},
                                            {1, 4, -1},
                                            {2, 5, -1}}};
constexpr std::array<P, 6> kWedge6Natural = {
    {{0, 0, -1}, {1, 0, -1}, {0, 1, -1}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}}};

constexpr std::array<std::int8_t, 20> kIdentity = {0,  1,  2,  3,  4,  5,  6,  7,  8,  9,
                                                   10, 11, 12, 13, 14, 15, 16, 17, 18, 19};
constexpr std::array<std::int8_t, 6> kWedgeToVtk = {0, 2, 1, 3, 5, 4};

// VTK cell type ids (vtkCellType.h).
constexpr int kVtkTetra = 10, kVtkHexahedron = 12, kVtkWedge = 13, kVtkQuadraticTetra = 24,
              kVtkQuadraticHexahedron = 25;

template <class T, std::size_t N>
std::span<const T> first(const std::array<T, N>& a, std::size_t n) {
  return std::span<const T>(a.data(), n);
}

constexpr std::string_view kHexOrder =
    "nodes 1-4 counter-clockwise seen from nodes 5-8, which lie above them";
constexpr std::string_view kHex20Order =
    "corners 1-4 counter-clockwise seen from corners 5-8, which lie above them, then the midside "
    "nodes of edges 1-2, 2-3, 3-4, 4-1, 5-6, 6-7, 7-8, 8-5, 1-5, 2-6, 3-7, 4-8";
constexpr std::string_view kTetOrder = "nodes 1-3 counter-clockwise seen from node 4";
constexpr std::string_view kTet10Order =
    "corners 1-3 counter-clockwise seen from corner 4, then the midside nodes of edges 1-2, 2-3, "
    "3-1, 1-4, 2-4, 3-4";
constexpr std::string_view kWedgeOrder =
    "nodes 1-3 counter-clockwise seen from nodes 4-6, which lie above them";

const CellTopology kTable[] = {
    {CellType::hex8, "hex8", "C3D8", kHexOrder, 8, 8, 1, kHex8Faces, kHex8Edges,
     first(kHex20Natural, 8), kVtkHexahedron, first(kIdentity, 8)},
    {CellType::hex20, "hex20", "C3D20", kHex20Order, 20, 8, 2, kHex20Faces, kHex20Edges,
     kHex20Natural, kVtkQuadraticHexahedron, first(kIdentity, 20)},
    {CellType::tet4, "tet4", "C3D4", kTetOrder, 4, 4, 1, kTet4Faces, kTet4Edges,
     first(kTet10Natural, 4), kVtkTetra, first(kIdentity, 4)},
    {CellType::tet10, "tet10", "C3D10", kTet10Order, 10, 4, 2, kTet10Faces, kTet10Edges,
     kTet10Natural, kVtkQuadraticTetra, first(kIdentity, 10)},
    {CellType::wedge6, "wedge6", "C3D6", kWedgeOrder, 6, 6, 1, kWedge6Faces, kWedge6Edges,
     kWedge6Natural, kVtkWedge, kWedgeToVtk},
};

}  // namespace

const CellTopology& topology(CellType type) { return kTable[static_cast<int>(type)]; }

std::span<const std::array<std::int8_t, 4>> linear_facets(FaceType type) {
  using F = std::array<std::int8_t, 4>;
  static constexpr F kTri3[] = {{0, 1, 2, 2}};
  static constexpr F kQuad4[] = {{0, 1, 2, 3}};
  static constexpr F kTri6[] = {{0, 3, 5, 5}, {3, 1, 4, 4}, {5, 4, 2, 2}, {3, 4, 5, 5}};
  static constexpr F kQuad8[] = {
      {0, 4, 7, 7}, {4, 1, 5, 5}, {5, 2, 6, 6}, {6, 3, 7, 7}, {4, 5, 6, 7}};
  switch (type) {
    case FaceType::tri3:
      return kTri3;
    case FaceType::tri6:
      return kTri6;
    case FaceType::quad4:
      return kQuad4;
    case FaceType::quad8:
      return kQuad8;
  }
  return {};
}

}  // namespace abut
