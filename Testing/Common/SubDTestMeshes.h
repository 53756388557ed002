// Test fixtures: small control meshes generated in code (closed, open, mixed face sizes,
// valences 3..8, non-manifold, faces that repeat a vertex), with deterministic jitter so that no symmetry hides a wrong
// weight. Shared by the kernel, property and oracle tests.
#ifndef SubDTestMeshes_h
#define SubDTestMeshes_h

#include "SubDRefiner.h"
#include "SubDTypes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace subdtest
{
struct TestMesh
{
  std::string Name;
  std::vector<double> Points; // xyz per vertex
  std::vector<subd::Index> Offsets{ 0 };
  std::vector<subd::Index> Vertices;

  subd::Index NumVertices() const { return static_cast<subd::Index>(Points.size() / 3); }
  subd::Index NumFaces() const { return static_cast<subd::Index>(Offsets.size()) - 1; }
  void AddPoint(double x, double y, double z) { Points.insert(Points.end(), { x, y, z }); }
  void AddFace(std::initializer_list<subd::Index> f)
  {
    Vertices.insert(Vertices.end(), f);
    Offsets.push_back(static_cast<subd::Index>(Vertices.size()));
  }
  void AddFace(const std::vector<subd::Index>& f)
  {
    Vertices.insert(Vertices.end(), f.begin(), f.end());
    Offsets.push_back(static_cast<subd::Index>(Vertices.size()));
  }
  /// The same surface with every face split into the fan (v0, vk, vk+1).
  TestMesh Triangulated() const
  {
    TestMesh t;
    t.Name = Name + "-tri";
    t.Points = Points;
    for (subd::Index f = 0; f < NumFaces(); ++f)
    {
      for (subd::Index k = Offsets[f] + 1; k + 1 < Offsets[f + 1]; ++k)
      {
        t.AddFace({ Vertices[Offsets[f]], Vertices[k], Vertices[k + 1] });
      }
    }
    return t;
  }
  /// Moves every point by a small deterministic pseudo-random offset.
  TestMesh& Jitter(double amount)
  {
    std::uint32_t state = 12345u;
    for (double& x : Points)
    {
      state = state * 1664525u + 1013904223u;
      x += amount * ((state >> 8) / double(1u << 24) - 0.5);
    }
    return *this;
  }
};

/// The base level of a fixture with no tags (what the kernel tests refine).
inline subd::Level BaseLevel(const TestMesh& mesh, subd::BoundaryRule rule = subd::BoundaryRule::EdgeOnly)
{
  return subd::MakeBaseLevel(subd::MeshTopology::Build(mesh.NumVertices(), mesh.Offsets, mesh.Vertices), {}, rule);
}

/// Tags with every kind of sharp feature: every fifth edge semi-sharp (1.6, decaying to
/// smooth within two levels), every seventh of the others infinitely sharp, vertex 0
/// semi-sharp (2.3), under `method`.
inline subd::BaseTags MixedSharpnessTags(const subd::MeshTopology& topology, subd::CreaseMethod method)
{
  subd::BaseTags tags;
  tags.Creasing = method;
  tags.EdgeSharpness.resize(static_cast<size_t>(topology.GetNumEdges()));
  for (size_t e = 0; e < tags.EdgeSharpness.size(); ++e)
    tags.EdgeSharpness[e] = e % 5 == 0 ? 1.6f : (e % 7 == 0 ? subd::SharpnessInfinite : 0.0f);
  tags.VertexSharpness.assign(static_cast<size_t>(topology.GetNumVertices()), 0.0f);
  tags.VertexSharpness[0] = 2.3f;
  return tags;
}

/// Every face's origin and hole flag (read through Level's accessors, whatever the level keeps).
inline std::vector<std::pair<subd::Index, bool>> FaceTags(const subd::Level& level)
{
  std::vector<std::pair<subd::Index, bool>> tags;
  for (subd::Index f = 0; f < level.Topology.GetNumFaces(); ++f)
    tags.emplace_back(level.GetFaceOrigin(f), level.IsFaceHole(f));
  return tags;
}

/// The rows of `table` applied to xyz points (one level down, or limit/tangent rows).
inline std::vector<double> ApplyToPoints(const subd::StencilTable& table, const std::vector<double>& points)
{
  std::vector<double> out(static_cast<size_t>(table.GetNumRows()) * 3);
  table.Apply(points.data(), out.data(), 3);
  return out;
}

/// Refines a fixture `levels` times into `h` and returns the finest points (xyz triples).
inline std::vector<double> RefineFixture(const subd::Scheme& scheme, const TestMesh& mesh, int levels,
  subd::Hierarchy& h, subd::BoundaryRule rule = subd::BoundaryRule::EdgeOnly)
{
  subd::Refine(scheme, BaseLevel(mesh, rule), levels, h);
  std::vector<double> points(static_cast<size_t>(h.GetNumFinestPoints()) * 3);
  h.Evaluate(mesh.Points.data(), 3, points.data());
  return points;
}

/// nx by ny quads; closed directions wrap around (both closed: a torus, all valence 4).
inline TestMesh Grid(int nx, int ny, bool closedX, bool closedY)
{
  TestMesh m;
  m.Name = std::string(closedX && closedY ? "torus" : "grid") + std::to_string(nx) + "x" + std::to_string(ny);
  const int px = closedX ? nx : nx + 1, py = closedY ? ny : ny + 1;
  const double pi = 3.14159265358979323846;
  for (int j = 0; j < py; ++j)
  {
    for (int i = 0; i < px; ++i)
    {
      if (closedX && closedY)
      {
        const double u = 2 * pi * i / nx, v = 2 * pi * j / ny;
        m.AddPoint((2 + std::cos(v)) * std::cos(u), (2 + std::cos(v)) * std::sin(u), std::sin(v));
      }
      else
      {
        m.AddPoint(i, j, 0.1 * i * j - 0.05 * i * i);
      }
    }
  }
  auto id = [&](int i, int j) { return static_cast<subd::Index>((j % py) * px + (i % px)); };
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      m.AddFace({ id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1) });
    }
  }
  return m;
}

inline TestMesh Cube()
{
  TestMesh m;
  m.Name = "cube";
  const double p[8][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
    { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } };
  for (auto& q : p)
  {
    m.AddPoint(q[0], q[1], q[2]);
  }
  m.AddFace({ 0, 3, 2, 1 });
  m.AddFace({ 4, 5, 6, 7 });
  m.AddFace({ 0, 1, 5, 4 });
  m.AddFace({ 1, 2, 6, 5 });
  m.AddFace({ 2, 3, 7, 6 });
  m.AddFace({ 3, 0, 4, 7 });
  return m;
}

/// A closed house: pentagon gables, quad walls and roof, a floor split into two triangles.
/// `open` leaves the floor out.
inline TestMesh House(bool open)
{
  TestMesh m;
  m.Name = open ? "house-open" : "house";
  const double p[10][3] = { { 0, 0, 0 }, { 2, 0, 0 }, { 2, 0, 1 }, { 1, 0, 1.8 }, { 0, 0, 1 },
    { 0, 3, 0 }, { 2, 3, 0 }, { 2, 3, 1 }, { 1, 3, 1.8 }, { 0, 3, 1 } };
  for (auto& q : p)
  {
    m.AddPoint(q[0], q[1], q[2]);
  }
  m.AddFace({ 0, 1, 2, 3, 4 });  // front gable (pentagon)
  m.AddFace({ 5, 9, 8, 7, 6 });  // back gable
  m.AddFace({ 1, 6, 7, 2 });     // right wall
  m.AddFace({ 0, 4, 9, 5 });     // left wall
  m.AddFace({ 2, 7, 8, 3 });     // right roof
  m.AddFace({ 4, 3, 8, 9 });     // left roof
  if (!open)
  {
    m.AddFace({ 0, 5, 6 });      // floor, two triangles
    m.AddFace({ 0, 6, 1 });
  }
  return m;
}

/// An n-gon prism (two n-gon caps, n quads) joined to an n-sided bipyramid-like fan: the
/// apex of the fan has valence n, so n in 3..8 gives every extraordinary valence.
inline TestMesh Star(int n)
{
  TestMesh m;
  m.Name = "star" + std::to_string(n);
  const double pi = 3.14159265358979323846;
  for (int k = 0; k < n; ++k)
  {
    const double a = 2 * pi * k / n;
    m.AddPoint(std::cos(a), std::sin(a), 0.0);
    m.AddPoint(std::cos(a), std::sin(a), 1.0);
  }
  m.AddPoint(0, 0, 2.0); // apex over the top cap
  const subd::Index apex = 2 * n;
  std::vector<subd::Index> bottom;
  for (int k = n - 1; k >= 0; --k)
  {
    bottom.push_back(2 * k);
  }
  m.AddFace(bottom); // bottom cap, an n-gon
  for (int k = 0; k < n; ++k)
  {
    const int k1 = (k + 1) % n;
    m.AddFace({ 2 * k, 2 * k1, 2 * k1 + 1, 2 * k + 1 }); // side quad
    m.AddFace({ 2 * k + 1, 2 * k1 + 1, apex });          // roof triangle
  }
  return m;
}

/// Three quads sharing one edge (a non-manifold "fin"), plus a bow-tie vertex.
inline TestMesh NonManifold()
{
  TestMesh m;
  m.Name = "non-manifold";
  m.AddPoint(0, 0, 0);  // 0: shared edge
  m.AddPoint(0, 1, 0);  // 1: shared edge
  m.AddPoint(1, 0, 0);  // 2
  m.AddPoint(1, 1, 0);  // 3
  m.AddPoint(-1, 0, 0); // 4
  m.AddPoint(-1, 1, 0); // 5
  m.AddPoint(0, 0, 1);  // 6
  m.AddPoint(0, 1, 1);  // 7
  m.AddFace({ 0, 2, 3, 1 });
  m.AddFace({ 1, 5, 4, 0 });
  m.AddFace({ 0, 1, 7, 6 });
  // bow-tie: two triangles touching only at vertex 3
  m.AddPoint(2, 1, 0);  // 8
  m.AddPoint(2, 2, 0);  // 9
  m.AddPoint(0.5, 2, 0.5); // 10
  m.AddPoint(0, 2, 0.5);   // 11
  m.AddFace({ 3, 8, 9 });
  m.AddFace({ 3, 10, 11 });
  return m;
}

/// Two cubes touching at one vertex: a pinch whose faces form two closed fans, non-manifold
/// without any boundary or non-manifold edge.
inline TestMesh PinchedCubes()
{
  TestMesh m = Cube();
  m.Name = "pinched-cubes";
  const TestMesh second = Cube();
  const subd::Index shared = 6, offset = 8;
  auto map = [&](subd::Index v) { return v == 0 ? shared : offset + v - 1; };
  for (subd::Index v = 1; v < 8; ++v)
  {
    m.AddPoint(second.Points[3 * v] + 1, second.Points[3 * v + 1] + 1, second.Points[3 * v + 2] + 1);
  }
  for (subd::Index f = 0; f < second.NumFaces(); ++f)
  {
    std::vector<subd::Index> face;
    for (subd::Index k = second.Offsets[f]; k < second.Offsets[f + 1]; ++k)
    {
      face.push_back(map(second.Vertices[k]));
    }
    m.AddFace(face);
  }
  return m;
}

/// An n-sided bipyramid: two apexes of valence n, an equator of valence 4 (all triangles).
inline TestMesh Bipyramid(int n)
{
  TestMesh m;
  m.Name = "bipyramid" + std::to_string(n);
  const double pi = 3.14159265358979323846;
  for (int k = 0; k < n; ++k)
  {
    m.AddPoint(std::cos(2 * pi * k / n), std::sin(2 * pi * k / n), 0.0);
  }
  m.AddPoint(0, 0, 1.2);
  m.AddPoint(0, 0, -0.8);
  for (int k = 0; k < n; ++k)
  {
    const int k1 = (k + 1) % n;
    m.AddFace({ k, k1, n });
    m.AddFace({ k1, k, n + 1 });
  }
  return m;
}

/// The triangle fixtures (for Loop and other triangle schemes): the standard set
/// triangulated, plus bipyramids for valences 3..12.
inline std::vector<TestMesh> TriangleMeshes();

// A cylinder of n side quads, open at the bottom, closed at the top by a pole fan of n quads
// that repeat the pole (s_i, s_i+1, T, T), the repeated pair turned through the four slots.
inline TestMesh RepeatedCornerPole(int n)
{
  TestMesh m;
  m.Name = "pole" + std::to_string(n);
  const double pi = 3.14159265358979323846;
  for (int k = 0; k < n; ++k)
  {
    const double a = 2 * pi * k / n;
    m.AddPoint(std::cos(a), std::sin(a), 0.0);
    m.AddPoint(std::cos(a), std::sin(a), 1.0);
  }
  m.AddPoint(0, 0, 1.5);
  const subd::Index pole = 2 * n;
  for (int k = 0; k < n; ++k)
  {
    const subd::Index r0 = 2 * k, r1 = 2 * ((k + 1) % n);
    m.AddFace({ r0, r1, r1 + 1, r0 + 1 });
    std::vector<subd::Index> cap{ r0 + 1, r1 + 1, pole, pole };
    std::rotate(cap.begin(), cap.begin() + k % 4, cap.end());
    m.AddFace(cap);
  }
  return m;
}

// Quads, a quad and a pentagon with consecutive repeats (one and two degenerate edges), a
// pentagon that passes a vertex twice (a vertex pair met twice in one face), and a
// non-manifold edge (three faces on 0-1).
inline TestMesh RepeatedCornerMix()
{
  TestMesh m;
  m.Name = "repeat-mix";
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)
      m.AddPoint(i, j, 0.1 * ((i * 7 + j * 3) % 5));
  m.AddPoint(0.5, 0.0, 1.0);
  m.AddFace({ 0, 1, 5, 4 });
  m.AddFace({ 1, 2, 6, 5 });
  m.AddFace({ 2, 3, 7, 6 });
  m.AddFace({ 4, 5, 9, 8 });
  m.AddFace({ 5, 6, 10, 10 });
  m.AddFace({ 6, 7, 7, 11, 11 });
  m.AddFace({ 9, 13, 9, 12, 8 });
  m.AddFace({ 10, 11, 15, 14 });
  m.AddFace({ 1, 0, 16 });
  m.AddFace({ 0, 1, 16 });
  return m;
}

/// The oracle and property fixture set.
inline std::vector<TestMesh> StandardMeshes()
{
  std::vector<TestMesh> meshes;
  meshes.push_back(Cube().Jitter(0.1));
  meshes.push_back(Grid(4, 3, false, false).Jitter(0.1));
  meshes.push_back(Grid(6, 5, true, true).Jitter(0.05));
  meshes.push_back(House(false).Jitter(0.1));
  meshes.push_back(House(true).Jitter(0.1));
  for (int n = 3; n <= 8; ++n)
  {
    meshes.push_back(Star(n).Jitter(0.1));
  }
  meshes.push_back(NonManifold().Jitter(0.05));
  meshes.push_back(PinchedCubes().Jitter(0.05));
  return meshes;
}

inline std::vector<TestMesh> TriangleMeshes()
{
  std::vector<TestMesh> meshes;
  for (const TestMesh& m : StandardMeshes())
  {
    meshes.push_back(m.Triangulated());
  }
  for (int n : { 3, 4, 5, 7, 8, 12 })
  {
    meshes.push_back(Bipyramid(n).Jitter(0.1));
  }
  return meshes;
}
}

#endif
