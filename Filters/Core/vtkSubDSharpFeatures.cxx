#include "vtkSubDSharpFeatures.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkMath.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace
{
// A sharpness value checked and clamped to OpenSubdiv's scale; false when not usable.
bool CheckSharpness(double value, float& sharpness)
{
  if (!(value >= 0.0)) // negative or NaN
  {
    return false;
  }
  sharpness = static_cast<float>(std::min(value, static_cast<double>(subd::SharpnessInfinite)));
  return true;
}

// Newell's normal of a face (unnormalized); correct for non-planar and concave polygons.
void FaceNormal(const subd::MeshTopology& topology, subd::Index f, vtkPoints* points, double n[3])
{
  n[0] = n[1] = n[2] = 0.0;
  const subd::IndexSpan fv = topology.GetFaceVertices(f);
  double a[3], b[3];
  for (subd::Index k = 0; k < fv.size(); ++k)
  {
    points->GetPoint(fv[k], a);
    points->GetPoint(fv[(k + 1) % fv.size()], b);
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
}
}

vtkDataArray* vtkSubDNamedArray(vtkFieldData* data, const std::string& name)
{
  return name.empty() ? nullptr : data->GetArray(name.c_str());
}

bool vtkSubDSharpFeatures::Read(vtkPolyData* input, const subd::LevelArray<vtkIdType>& faceCells, std::string& error,
  const vtkSubDFeatureArrayNames& names)
{
  *this = vtkSubDSharpFeatures();
  this->Names = names;
  vtkCellData* cd = input->GetCellData();
  vtkDataArray* sharpness = vtkSubDNamedArray(cd, names.Sharpness);
  vtkDataArray* holes = vtkSubDNamedArray(cd, names.Hole);
  vtkDataArray* corners = vtkSubDNamedArray(input->GetPointData(), names.CornerSharpness);
  for (vtkDataArray* array : { sharpness, holes, corners })
  {
    const vtkIdType needed = array == corners ? input->GetNumberOfPoints() : input->GetNumberOfCells();
    if (array && array->GetNumberOfTuples() < needed)
    {
      std::ostringstream message;
      message << "Array '" << array->GetName() << "' has " << array->GetNumberOfTuples()
              << " values but the input has " << needed << (array == corners ? " points." : " cells.");
      error = message.str();
      return false;
    }
  }
  vtkCellArray* lines = input->GetLines();
  const vtkIdType firstLineCell = input->GetNumberOfVerts();
  if (lines && lines->GetNumberOfCells() > 0)
  {
    vtkIdType n;
    const vtkIdType* pts;
    vtkIdType cell = firstLineCell;
    for (lines->InitTraversal(); lines->GetNextCell(n, pts); ++cell)
    {
      float s = subd::SharpnessInfinite;
      if (sharpness && !CheckSharpness(sharpness->GetComponent(cell, 0), s))
      {
        std::ostringstream message;
        message << "Line cell " << cell << " has sharpness " << sharpness->GetComponent(cell, 0)
                << "; sharpness must be a number >= 0 (0 smooth, 10 or more infinitely sharp).";
        error = message.str();
        return false;
      }
      for (vtkIdType k = 0; k < n; ++k)
      {
        if (pts[k] < 0 || pts[k] >= input->GetNumberOfPoints())
        {
          std::ostringstream message;
          message << "Line cell " << cell << " uses point id " << pts[k] << " but the input has "
                  << input->GetNumberOfPoints() << " points.";
          error = message.str();
          return false;
        }
      }
      for (vtkIdType k = 0; k + 1 < n; ++k)
      {
        this->SegmentPoints.push_back(static_cast<subd::Index>(pts[k]));
        this->SegmentPoints.push_back(static_cast<subd::Index>(pts[k + 1]));
        this->SegmentSharpness.push_back(s);
        this->SegmentCell.push_back(cell);
      }
    }
  }
  if (corners)
  {
    const vtkIdType numPoints = input->GetNumberOfPoints();
    this->CornerSharpness.resize(static_cast<size_t>(numPoints));
    for (vtkIdType i = 0; i < numPoints; ++i)
    {
      if (!CheckSharpness(corners->GetComponent(i, 0), this->CornerSharpness[i]))
      {
        std::ostringstream message;
        message << "Point " << i << " has " << names.CornerSharpness << " " << corners->GetComponent(i, 0)
                << "; sharpness must be a number >= 0 (0 smooth, 10 or more infinitely sharp).";
        error = message.str();
        return false;
      }
    }
  }
  if (holes)
  {
    this->FaceIsHole.resize(faceCells.size());
    for (size_t f = 0; f < faceCells.size(); ++f)
    {
      this->FaceIsHole[f] = holes->GetComponent(faceCells[f], 0) != 0.0;
    }
  }
  return true;
}

bool vtkSubDSharpFeatures::Any() const
{
  auto nonZero = [](auto value) { return value != 0; };
  return std::any_of(this->SegmentSharpness.begin(), this->SegmentSharpness.end(), nonZero) ||
    std::any_of(this->CornerSharpness.begin(), this->CornerSharpness.end(), nonZero) ||
    std::any_of(this->FaceIsHole.begin(), this->FaceIsHole.end(), nonZero);
}

subd::BaseTags vtkSubDSharpFeatures::ToBaseTags(const subd::MeshTopology& topology, vtkPoints* points,
  double featureAngle, subd::CreaseMethod method, std::vector<subd::Index>& unmatched) const
{
  subd::BaseTags tags;
  tags.Creasing = method;
  unmatched.clear();
  const subd::Index numEdges = topology.GetNumEdges();
  if (!this->SegmentSharpness.empty() || featureAngle > 0.0)
  {
    tags.EdgeSharpness.assign(static_cast<size_t>(numEdges), subd::SharpnessSmooth);
  }
  for (size_t i = 0; i < this->SegmentSharpness.size(); ++i)
  {
    const subd::Index a = this->SegmentPoints[2 * i], b = this->SegmentPoints[2 * i + 1];
    const bool inRange = a >= 0 && b >= 0 && a < topology.GetNumVertices() && b < topology.GetNumVertices();
    const subd::Index e = inRange ? topology.FindEdge(a, b) : subd::InvalidIndex;
    if (e == subd::InvalidIndex)
    {
      unmatched.push_back(static_cast<subd::Index>(i));
      continue;
    }
    // A segment given twice keeps the larger sharpness.
    tags.EdgeSharpness[e] = std::max(tags.EdgeSharpness[e], this->SegmentSharpness[i]);
  }
  if (featureAngle > 0.0)
  {
    const double cosLimit = std::cos(vtkMath::RadiansFromDegrees(featureAngle));
    std::vector<double> normals(3 * static_cast<size_t>(topology.GetNumFaces()));
    for (subd::Index f = 0; f < topology.GetNumFaces(); ++f)
    {
      FaceNormal(topology, f, points, &normals[3 * f]);
      vtkMath::Normalize(&normals[3 * f]);
    }
    for (subd::Index e = 0; e < numEdges; ++e)
    {
      const subd::IndexSpan ef = topology.GetEdgeFaces(e);
      if (ef.size() == 2 && vtkMath::Dot(&normals[3 * ef[0]], &normals[3 * ef[1]]) < cosLimit)
      {
        tags.EdgeSharpness[e] = subd::SharpnessInfinite;
      }
    }
  }
  tags.VertexSharpness = this->CornerSharpness;
  tags.FaceIsHole = this->FaceIsHole;
  return tags;
}

std::vector<float> vtkSubDWriteSharpFeatures(const vtkSubDSharpFeatures& features,
  const std::vector<subd::Index>& unmatched, const subd::Level& finest, const vtkSubDOutputPointMap& map,
  vtkPolyData* input, const std::vector<std::pair<vtkDataArray*, vtkDataArray*>>& arrays,
  vtkPolyData* output, vtkSubDSeamLines* seams)
{
  vtkPoints* points = output->GetPoints();
  vtkPointData* outPD = output->GetPointData();
  if (seams)
  {
    seams->LineIsCopy.clear();
  }
  if (!features.CornerSharpness.empty())
  {
    const vtkIdType numOutput = points->GetNumberOfPoints();
    vtkNew<vtkFloatArray> corners;
    corners->SetName(features.Names.CornerSharpness.c_str());
    corners->SetNumberOfTuples(numOutput);
    for (vtkIdType o = 0; o < numOutput; ++o)
    {
      corners->SetValue(o, finest.VertexSharpness.empty() ? 0.0f : finest.VertexSharpness[map.FinestOfOutput(o)]);
    }
    outPD->AddArray(corners);
  }

  std::vector<float> sharpness;
  vtkNew<vtkCellArray> lines;
  const subd::MeshTopology& topo = finest.Topology;
  for (subd::Index e = 0; e < topo.GetNumEdges() && !finest.EdgeSharpness.empty(); ++e)
  {
    const subd::EdgeTag tag = topo.GetEdgeTag(e);
    if (!subd::IsSharp(finest.EdgeSharpness[e]) || tag.Boundary || tag.NonManifold)
    {
      continue;
    }
    const bool copy = seams && seams->EdgeIsCopy[e];
    if (copy && !seams->WriteCopies)
    {
      continue; // another piece outputs it
    }
    const subd::Index* ev = topo.GetEdgeVertices(e);
    const vtkIdType ends[2] = { map.OutputOfFinest(ev[0]), map.OutputOfFinest(ev[1]) };
    if (ends[0] >= 0 && ends[1] >= 0)
    {
      lines->InsertNextCell(2, ends);
      sharpness.push_back(finest.EdgeSharpness[e]);
      if (seams)
      {
        seams->LineIsCopy.push_back(copy ? 1 : 0);
      }
    }
  }

  // Segments that are not surface edges: unchanged, on copies of their input points.
  vtkDataArray* inputCorners = vtkSubDNamedArray(input->GetPointData(), features.Names.CornerSharpness);
  vtkDataArray* outputCorners = vtkSubDNamedArray(outPD, features.Names.CornerSharpness);
  for (subd::Index segment : unmatched)
  {
    vtkIdType ends[2];
    for (int k = 0; k < 2; ++k)
    {
      const vtkIdType p = features.SegmentPoints[2 * segment + k];
      ends[k] = points->InsertNextPoint(input->GetPoint(p));
      for (const auto& pair : arrays)
      {
        pair.second->InsertNextTuple(p, pair.first);
      }
      if (inputCorners && outputCorners)
      {
        outputCorners->InsertNextTuple(p, inputCorners);
      }
    }
    lines->InsertNextCell(2, ends);
    sharpness.push_back(features.SegmentSharpness[segment]);
  }
  // The limit normals and curvature (computed before) have no value at the copies, which are
  // not on the surface: 0, as where the surface has no tangent plane.
  const vtkIdType numPoints = points->GetNumberOfPoints();
  for (int a = 0; a < outPD->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = outPD->GetArray(a);
    // InsertTuple grows the array keeping its values (SetNumberOfTuples need not keep them).
    const std::vector<double> zeros(array ? static_cast<size_t>(array->GetNumberOfComponents()) : 0, 0.0);
    for (vtkIdType t = array ? array->GetNumberOfTuples() : numPoints; t < numPoints; ++t)
    {
      array->InsertTuple(t, zeros.data());
    }
  }
  if (lines->GetNumberOfCells() > 0)
  {
    output->SetLines(lines);
  }
  return sharpness;
}
