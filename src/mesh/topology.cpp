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

// Lagrange quadrilaterals of order p: the face lattice (topology.hpp, face_lattice).
template <int P>
struct QuadLattice {
  static constexpr int kNodes = (P + 1) * (P + 1);
  std::array<std::array<std::int8_t, 2>, kNodes> st{};
  constexpr QuadLattice() {
    constexpr int corner[4][2] = {{0, 0}, {P, 0}, {P, P}, {0, P}};
    int n = 0;
    for (const auto& c : corner)
      st[n++] = {static_cast<std::int8_t>(c[0]), static_cast<std::int8_t>(c[1])};
    for (int k = 0; k < 4; ++k) {
      const auto& a = corner[k];
      const auto& b = corner[(k + 1) % 4];
      for (int m = 1; m < P; ++m)
        st[n++] = {static_cast<std::int8_t>(a[0] + m * (b[0] - a[0]) / P),
                   static_cast<std::int8_t>(a[1] + m * (b[1] - a[1]) / P)};
    }
    for (int t = 1; t < P; ++t)
      for (int s = 1; s < P; ++s)
        st[n++] = {static_cast<std::int8_t>(s), static_cast<std::int8_t>(t)};
  }
  // The face-local index of lattice point (s, t).
  constexpr int at(int s, int t) const {
    for (int a = 0; a < kNodes; ++a)
      if (st[a][0] == s && st[a][1] == t) return a;
    return -1;
  }
  // The p x p facets of the lattice, counter-clockwise like the face.
  constexpr std::array<std::array<std::int8_t, 4>, P * P> facets() const {
    std::array<std::array<std::int8_t, 4>, P * P> out{};
    int f = 0;
    for (int t = 0; t < P; ++t)
      for (int s = 0; s < P; ++s)
        out[f++] = {static_cast<std::int8_t>(at(s, t)), static_cast<std::int8_t>(at(s + 1, t)),
                    static_cast<std::int8_t>(at(s + 1, t + 1)),
                    static_cast<std::int8_t>(at(s, t + 1))};
    return out;
  }
};
constexpr QuadLattice<2> kQuad9Lattice;
constexpr QuadLattice<3> kQuad16Lattice;

// Lagrange hexahedra of order p: the (p + 1)^3 lattice nodes in VTK's order (topology.hpp), their
// natural coordinates, and the faces S1..S6 (the corners of kHexFaces) as Lagrange quadrilaterals
// whose lattice runs from corner 0 towards corners 1 and 3.
template <int P>
struct LagrangeHex {
  static constexpr int kNodes = (P + 1) * (P + 1) * (P + 1);
  std::array<std::array<int, 3>, kNodes> ijk{};
  std::array<std::array<double, 3>, kNodes> natural{};
  std::array<F, 6> faces{};
  constexpr LagrangeHex(const QuadLattice<P>& lattice) {
    constexpr int corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                  {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    constexpr int edge[12][2] = {{0, 1}, {1, 2}, {3, 2}, {0, 3}, {4, 5}, {5, 6},
                                 {7, 6}, {4, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    int n = 0;
    for (const auto& c : corner) ijk[n++] = {c[0] * P, c[1] * P, c[2] * P};
    for (const auto& e : edge)
      for (int m = 1; m < P; ++m, ++n)
        for (int r = 0; r < 3; ++r)
          ijk[n][r] = corner[e[0]][r] * P + m * (corner[e[1]][r] - corner[e[0]][r]);
    for (int axis = 0; axis < 3; ++axis)
      for (const int side : {0, P}) {
        const int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;
        for (int b = 1; b < P; ++b)
          for (int a = 1; a < P; ++a, ++n) {
            ijk[n][axis] = side;
            ijk[n][u] = a;
            ijk[n][v] = b;
          }
      }
    for (int k = 1; k < P; ++k)
      for (int j = 1; j < P; ++j)
        for (int i = 1; i < P; ++i) ijk[n++] = {i, j, k};
    for (int a = 0; a < kNodes; ++a)
      for (int r = 0; r < 3; ++r) natural[a][r] = -1.0 + 2.0 * ijk[a][r] / P;
    for (int f = 0; f < 6; ++f) {
      faces[f].type = P == 2 ? FaceType::quad9 : FaceType::quad16;
      const int* c0 = corner[kHexFaces[f][0]];
      const int* c1 = corner[kHexFaces[f][1]];
      const int* c3 = corner[kHexFaces[f][3]];
      for (int a = 0; a < QuadLattice<P>::kNodes; ++a) {
        std::array<int, 3> x{};
        for (int r = 0; r < 3; ++r)
          x[r] =
              c0[r] * P + lattice.st[a][0] * (c1[r] - c0[r]) + lattice.st[a][1] * (c3[r] - c0[r]);
        faces[f].nodes[a] = static_cast<std::int8_t>(index(x));
      }
    }
  }
  constexpr int index(const std::array<int, 3>& x) const {
    for (int a = 0; a < kNodes; ++a)
      if (ijk[a] == x) return a;
    return -1;
  }
};
constexpr LagrangeHex<2> kHex27(kQuad9Lattice);
constexpr LagrangeHex<3> kHex64(kQuad16Lattice);
constexpr auto kQuad9Facets = kQuad9Lattice.facets();
constexpr auto kQuad16Facets = kQuad16Lattice.facets();

constexpr std::array<std::int8_t, 64> kIdentity = [] {
  std::array<std::int8_t, 64> out{};
  for (int a = 0; a < 64; ++a) out[a] = static_cast<std::int8_t>(a);
  return out;
}();
constexpr std::array<std::int8_t, 6> kWedgeToVtk = {0, 2, 1, 3, 5, 4};

// VTK cell type ids (vtkCellType.h).
constexpr int kVtkTetra = 10, kVtkHexahedron = 12, kVtkWedge = 13, kVtkQuadraticTetra = 24,
              kVtkQuadraticHexahedron = 25, kVtkLagrangeHexahedron = 72;

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
constexpr std::string_view kLagrangeOrder =
    "VTK's order of a Lagrange hexahedron (corners as an 8-node hexahedron, then the edge, face "
    "and interior nodes of the equispaced lattice)";
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
    {CellType::hex27, "hex27", "", kLagrangeOrder, 27, 8, 2, kHex27.faces, kHex20Edges,
     kHex27.natural, kVtkLagrangeHexahedron, first(kIdentity, 27)},
    {CellType::hex64, "hex64", "", kLagrangeOrder, 64, 8, 3, kHex64.faces, kHex8Edges,
     kHex64.natural, kVtkLagrangeHexahedron, first(kIdentity, 64)},
};

}  // namespace

const CellTopology& topology(CellType type) { return kTable[static_cast<int>(type)]; }

std::span<const std::array<std::int8_t, 4>> linear_facets(FaceType type) {
  using Facet = std::array<std::int8_t, 4>;
  static constexpr Facet kTri3[] = {{0, 1, 2, 2}};
  static constexpr Facet kQuad4[] = {{0, 1, 2, 3}};
  static constexpr Facet kTri6[] = {{0, 3, 5, 5}, {3, 1, 4, 4}, {5, 4, 2, 2}, {3, 4, 5, 5}};
  static constexpr Facet kQuad8[] = {
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
    case FaceType::quad9:
      return kQuad9Facets;
    case FaceType::quad16:
      return kQuad16Facets;
  }
  return {};
}

std::span<const std::array<std::int8_t, 2>> face_lattice(FaceType type) {
  if (type == FaceType::quad9) return kQuad9Lattice.st;
  if (type == FaceType::quad16) return kQuad16Lattice.st;
  return {};
}

}  // namespace abut
