#include "vtkSubDCage.h"

#include "vtkSubDInputFaces.h"
#include "vtkSubDPieces.h"
#include "vtkSubDSharpFeatures.h"

#include "vtkPointData.h"

#include <algorithm>

namespace
{
// The input's points welded where they coincide (vtkSubDSeams.h), and the arrays that differ
// there; faces that welding leaves with a repeated point are dropped, with a warning.
vtkSubDSeams WeldSeams(vtkPolyData* input, subd::FaceScreening& screened, std::string& warning)
{
  subd::Index dropped = 0;
  vtkSubDSeams seams = vtkSubDWeldCoincidentPoints(input, screened, false, dropped);
  // Corner sharpness and a piece's ghost marks are no data to carry.
  vtkPointData* pd = input->GetPointData();
  std::vector<int>& arrays = seams.Arrays;
  arrays.erase(std::remove_if(arrays.begin(), arrays.end(), [&](int a) {
    return pd->GetArray(a) == input->GetPointGhostArray() ||
      (pd->GetArray(a)->GetName() && std::string(pd->GetArray(a)->GetName()) == "CornerSharpness");
  }), arrays.end());
  if (arrays.empty())
  {
    seams.ValueOfCorner.clear();
  }
  if (dropped > 0)
  {
    warning += (warning.empty() ? "" : "; ") + std::to_string(dropped) +
      " polygon(s) that welding left with a repeated point were dropped";
  }
  return seams;
}

// False, naming the first, when a face is not a triangle.
bool OnlyTriangles(
  const subd::FaceScreening& screened, const subd::LevelArray<vtkIdType>& faceCell, std::string& error)
{
  for (size_t f = 0; f + 1 < screened.Offsets.size(); ++f)
  {
    const subd::Index size = screened.Offsets[f + 1] - screened.Offsets[f];
    if (size != 3)
    {
      error = "cell " + std::to_string(faceCell[f]) + " has " + std::to_string(size) +
        " points; Loop needs triangles (use vtkTriangleFilter)";
      return false;
    }
  }
  return true;
}

// Each input cell's face; a polygon split into triangles is no face of its own (its triangles
// are consecutive): locations cannot name it.
std::unordered_map<vtkIdType, subd::Index> FacesOfWholeCells(const subd::LevelArray<vtkIdType>& faceCell)
{
  std::unordered_map<vtkIdType, subd::Index> faceOf;
  for (size_t f = 0; f < faceCell.size(); ++f)
  {
    const bool whole =
      (f == 0 || faceCell[f - 1] != faceCell[f]) && (f + 1 == faceCell.size() || faceCell[f + 1] != faceCell[f]);
    if (whole)
    {
      faceOf.emplace(faceCell[f], static_cast<subd::Index>(f));
    }
  }
  return faceOf;
}
}

bool vtkSubDReadCage(vtkPolyData* input, vtkSubDCageFaces kind, subd::RepeatedCorners repeated,
  subd::BoundaryRule rule, subd::CreaseMethod creasing, vtkSubDCage& cage, std::string& error, std::string& warning,
  bool weld)
{
  const vtkIdType numPoints = input && input->GetPoints() ? input->GetNumberOfPoints() : 0;
  const vtkSubDInputFaces faces = input ? vtkSubDGatherFaces(input) : vtkSubDInputFaces();
  if (numPoints == 0 || faces.NumFaces == 0)
  {
    error = "the input has no polygons to evaluate the limit surface of";
    return false;
  }
  const vtkIdType badPoint = vtkSubDFirstNonFinitePoint(input->GetPoints());
  if (badPoint >= 0)
  {
    error = "point " + std::to_string(badPoint) + " has a non-finite coordinate";
    return false;
  }
  // Faces screened as the surface filters screen them.
  const vtkIdType numPolys = input->GetNumberOfPolys();
  subd::FaceScreening screened;
  if (!vtkSubDScreenFaces(faces, numPoints, numPolys, repeated, screened, error, warning))
  {
    return false;
  }
  const subd::Index split =
    kind == vtkSubDCageFaces::Triangulated ? vtkSubDTriangulateFaces(screened, input->GetPoints()) : 0;
  if (split > 0)
  {
    warning += (warning.empty() ? "" : "; ") + vtkSubDSplitPolygonsWarning(split);
  }
  if (weld)
  {
    cage.Seams = WeldSeams(input, screened, warning);
  }
  for (subd::Index f : screened.KeptFaces)
  {
    cage.FaceCell.push_back(faces.CellIdOf(f, numPolys));
  }
  if (kind == vtkSubDCageFaces::Triangles && !OnlyTriangles(screened, cage.FaceCell, error))
  {
    return false;
  }
  if (screened.KeptFaces.empty())
  {
    error = "no usable polygon remains after removing degenerate ones";
    return false;
  }
  cage.Points.resize(static_cast<size_t>(numPoints) * 3);
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    input->GetPoint(i, &cage.Points[3 * i]);
  }
  subd::MeshTopology topology =
    subd::MeshTopology::Build(static_cast<subd::Index>(numPoints), screened.Offsets, screened.Vertices);
  cage.FaceIsGhost = vtkSubDGhostFaces(input, cage.FaceCell);
  const std::string nonManifold = vtkSubDNonManifoldWarning(topology, cage.FaceIsGhost);
  if (!nonManifold.empty())
  {
    warning += (warning.empty() ? "" : "; ") + nonManifold;
  }
  vtkSubDSharpFeatures features;
  if (!features.Read(input, cage.FaceCell, error))
  {
    return false;
  }
  std::vector<subd::Index> unmatched;
  const subd::BaseTags tags = features.ToBaseTags(topology, input->GetPoints(), 0.0, creasing, unmatched);
  cage.Level = subd::MakeBaseLevel(std::move(topology), tags, rule);
  cage.FaceOfCell = FacesOfWholeCells(cage.FaceCell);
  return true;
}

void vtkSubDMakeCageChannel(vtkSubDCage& cage, subd::FaceVaryingInterpolation mode)
{
  if (cage.HasChannel())
  {
    cage.Channel = subd::MakeFaceVaryingBase(cage.Level, cage.Seams.ValueOfCorner.data(), mode);
  }
}

std::int64_t vtkSubDCage::SeamSideOfCorner(subd::Index f, subd::Index k) const
{
  return this->HasChannel() ? this->Channel.Values.Topology.GetFaceVertices(f)[k] + 1 : 0;
}

std::int64_t vtkSubDCage::SeamSideOfEdge(subd::Index f, subd::Index k) const
{
  if (!this->HasChannel())
  {
    return 0;
  }
  const subd::IndexSpan values = this->Channel.Values.Topology.GetFaceVertices(f);
  const subd::Index n = static_cast<subd::Index>(values.size());
  const subd::Index e = this->Level.Topology.GetFaceEdges(f)[k];
  const bool forward = this->Level.Topology.GetEdgeVertices(e)[0] == this->Level.Topology.GetFaceVertices(f)[k];
  const std::int64_t a = values[k], b = values[(k + 1) % n];
  return forward ? (a << 32) + b + 1 : (b << 32) + a + 1;
}
