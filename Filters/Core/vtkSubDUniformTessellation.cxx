#include "vtkSubDUniformTessellation.h"

#include <array>
#include <map>

namespace
{
// A point of the tessellation: a cage vertex, a point on a cage edge (t segments from its
// first vertex), on a segment inside a polygon, or inside a face; on a seam, one per side.
using SampleKey = std::array<vtkIdType, 4>;

// A watertight tessellation of the cage's faces at resolution R: triangles split into R^2
// triangles, quads into R x R quads, other polygons into one (R/2) x (R/2) grid of quads per
// corner. A point shared by faces (on a cage vertex or edge) is made once, owned by the first
// face that meets it.
class Tessellation
{
public:
  Tessellation(const vtkSubDCage& cage, int resolution, vtkSubDLimitSamples& samples)
    : Cage(cage)
    , Topo(cage.Level.Topology)
    , R(resolution)
    , Out(samples)
  {
  }
  void AddTriangle(subd::Index f);
  void AddPolygon(subd::Index f);

private:
  enum Kind
  {
    Vertex,
    Edge,
    Inside,
    Spoke,
    Centre
  };
  // The key of the point `t` segments (of R along the edge) from corner k toward the next
  // corner along edge k of face f.
  SampleKey EdgeKey(subd::Index f, subd::Index k, int t) const
  {
    const subd::IndexSpan fv = this->Topo.GetFaceVertices(f);
    const subd::Index e = this->Topo.GetFaceEdges(f)[k];
    const subd::Index next = (k + 1) % static_cast<subd::Index>(fv.size());
    if (t == 0)
      return { Vertex, fv[k], this->Cage.SeamSideOfCorner(f, k), 0 };
    if (t == this->R)
      return { Vertex, fv[next], this->Cage.SeamSideOfCorner(f, next), 0 };
    const bool forward = this->Topo.GetEdgeVertices(e)[0] == fv[k];
    return { Edge, e, forward ? t : this->R - t, this->Cage.SeamSideOfEdge(f, k) };
  }
  // The output point of `key`, made (and owned by `grid`) if new.
  vtkIdType Point(vtkSubDFaceSamples& grid, const SampleKey& key, double u, double v, subd::Index subFace)
  {
    auto found = this->IdOf.emplace(key, this->Out.Count);
    if (found.second)
    {
      SampleKey place = key; // the key without its side of a seam
      if (key[0] == Vertex)
        place[2] = 0;
      if (key[0] == Edge)
        place[3] = 0;
      auto first = this->PointAt.emplace(place, this->Out.Count);
      if (!first.second)
      {
        this->Out.SamePlace.emplace_back(this->Out.Count, first.first->second);
      }
      subd::FaceSample s;
      s.U = u;
      s.V = v;
      s.SubFace = subFace;
      grid.Owned.push_back(s);
      grid.OwnedIds.push_back(this->Out.Count++);
    }
    return found.first->second;
  }
  void AddCell(subd::Index f, vtkIdType size, const vtkIdType* ids)
  {
    this->Out.Cells->InsertNextCell(size, ids);
    this->Out.CellFace->InsertNextValue(this->Cage.FaceCell[f]);
  }
  void AddCornerGrid(vtkSubDFaceSamples& grid, subd::Index k);

  const vtkSubDCage& Cage;
  const subd::MeshTopology& Topo;
  const int R;
  vtkSubDLimitSamples& Out;
  std::map<SampleKey, vtkIdType> IdOf;
  std::map<SampleKey, vtkIdType> PointAt; ///< the first point at each place (seams have two)
};

void Tessellation::AddTriangle(subd::Index f)
{
  // (i, j) with i + j <= R: corners (0,0), (R,0), (0,R).
  vtkSubDFaceSamples grid{ f, {}, {} };
  const int R = this->R;
  auto index = [R](int i, int j) { return static_cast<size_t>(j * (R + 1) + i); };
  std::vector<vtkIdType> ids(static_cast<size_t>((R + 1) * (R + 1)), -1);
  for (int j = 0; j <= R; ++j)
  {
    for (int i = 0; i + j <= R; ++i)
    {
      SampleKey key{ Inside, f, i, j };
      if (j == 0)
        key = this->EdgeKey(f, 0, i);
      else if (i + j == R)
        key = this->EdgeKey(f, 1, j);
      else if (i == 0)
        key = this->EdgeKey(f, 2, R - j);
      ids[index(i, j)] = this->Point(grid, key, static_cast<double>(i) / R, static_cast<double>(j) / R, 0);
    }
  }
  for (int j = 0; j < R; ++j)
  {
    for (int i = 0; i + j < R; ++i)
    {
      const vtkIdType up[3] = { ids[index(i, j)], ids[index(i + 1, j)], ids[index(i, j + 1)] };
      this->AddCell(f, 3, up);
      if (i + j + 1 < R)
      {
        const vtkIdType down[3] = { ids[index(i + 1, j)], ids[index(i + 1, j + 1)], ids[index(i, j + 1)] };
        this->AddCell(f, 3, down);
      }
    }
  }
  this->Out.Grids.push_back(std::move(grid));
}

void Tessellation::AddPolygon(subd::Index f)
{
  vtkSubDFaceSamples grid{ f, {}, {} };
  const bool quad = this->Topo.GetFaceSize(f) == 4;
  for (subd::Index k = 0; k < (quad ? 1 : this->Topo.GetFaceSize(f)); ++k)
  {
    this->AddCornerGrid(grid, k);
  }
  this->Out.Grids.push_back(std::move(grid));
}

// Quads: one R x R grid (k = 0); other polygons: per corner k an S x S grid, S = R/2, with
// (0,0) at corner k, (S,0) at the middle of edge k, (S,S) at the centre.
void Tessellation::AddCornerGrid(vtkSubDFaceSamples& grid, subd::Index k)
{
  const subd::Index f = grid.Face;
  const subd::Index n = this->Topo.GetFaceSize(f);
  const bool whole = n == 4;
  const int S = whole ? this->R : this->R / 2;
  std::vector<vtkIdType> ids(static_cast<size_t>((S + 1) * (S + 1)));
  for (int j = 0; j <= S; ++j)
  {
    for (int i = 0; i <= S; ++i)
    {
      SampleKey key{ Inside, f, k * (S + 1) * (S + 1) + j * (S + 1) + i, 0 };
      if (whole)
      {
        if (j == 0)
          key = this->EdgeKey(f, 0, i);
        else if (i == S)
          key = this->EdgeKey(f, 1, j);
        else if (j == S)
          key = this->EdgeKey(f, 2, S - i);
        else if (i == 0)
          key = this->EdgeKey(f, 3, S - j);
      }
      else if (i == S && j == S)
        key = { Centre, f, 0, 0 };
      else if (j == 0)
        key = this->EdgeKey(f, k, i);
      else if (i == 0)
        key = this->EdgeKey(f, (k + n - 1) % n, this->R - j);
      else if (i == S)
        key = { Spoke, f, k, j };
      else if (j == S)
        key = { Spoke, f, (k + n - 1) % n, i };
      ids[static_cast<size_t>(j * (S + 1) + i)] =
        this->Point(grid, key, static_cast<double>(i) / S, static_cast<double>(j) / S, k);
    }
  }
  auto id = [&](int a, int b) { return ids[static_cast<size_t>(b * (S + 1) + a)]; };
  for (int j = 0; j < S; ++j)
  {
    for (int i = 0; i < S; ++i)
    {
      const vtkIdType quad[4] = { id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1) };
      this->AddCell(f, 4, quad);
    }
  }
}
}

void vtkSubDTessellateUniform(const vtkSubDCage& cage, const std::vector<subd::Index>& faces, bool quads,
  int resolution, vtkSubDLimitSamples& samples)
{
  const subd::MeshTopology& topo = cage.Level.Topology;
  bool polygons = false;
  for (subd::Index f = 0; f < topo.GetNumFaces() && quads; ++f)
  {
    polygons = polygons || topo.GetFaceSize(f) != 4;
  }
  // Other polygons than quads take a grid per corner of half the resolution: an even one.
  Tessellation tessellation(cage, polygons ? 2 * ((resolution + 1) / 2) : resolution, samples);
  for (subd::Index f : faces)
  {
    if (quads)
    {
      tessellation.AddPolygon(f);
    }
    else
    {
      tessellation.AddTriangle(f);
    }
  }
}
