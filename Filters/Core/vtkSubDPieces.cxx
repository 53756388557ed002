#include "vtkSubDPieces.h"

#include "SubDMeshTopology.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>

std::vector<std::uint8_t> vtkSubDGhostFaces(vtkPolyData* input, const subd::LevelArray<vtkIdType>& faceCells)
{
  std::vector<std::uint8_t> ghost;
  vtkUnsignedCharArray* marks = input->GetCellGhostArray();
  if (!marks)
  {
    return ghost;
  }
  ghost.resize(faceCells.size());
  bool any = false;
  for (size_t f = 0; f < faceCells.size(); ++f)
  {
    ghost[f] = (marks->GetValue(faceCells[f]) & vtkDataSetAttributes::DUPLICATECELL) != 0;
    any = any || ghost[f];
  }
  if (!any)
  {
    ghost.clear();
  }
  return ghost;
}

std::vector<std::uint8_t> vtkSubDGhostLayers(
  const subd::MeshTopology& topology, const std::vector<std::uint8_t>& faceIsGhost, int maxLayer)
{
  const subd::Index numFaces = topology.GetNumFaces();
  std::vector<std::uint8_t> layer(static_cast<size_t>(numFaces), 255);
  std::vector<subd::Index> front, next;
  for (subd::Index f = 0; f < numFaces; ++f)
  {
    if (!faceIsGhost[f])
    {
      layer[f] = 0;
      front.push_back(f);
    }
  }
  for (int k = 1; k <= maxLayer && !front.empty(); ++k)
  {
    next.clear();
    for (subd::Index f : front)
    {
      for (subd::Index v : topology.GetFaceVertices(f))
      {
        for (subd::Index g : topology.GetVertexFaces(v))
        {
          if (layer[g] == 255)
          {
            layer[g] = static_cast<std::uint8_t>(k);
            next.push_back(g);
          }
        }
      }
    }
    front.swap(next);
  }
  return layer;
}

void vtkSubDMarkGhostPoints(vtkPolyData* output)
{
  auto* cellMarks =
    vtkUnsignedCharArray::SafeDownCast(output->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName()));
  if (!cellMarks)
  {
    return;
  }
  vtkNew<vtkUnsignedCharArray> pointMarks;
  pointMarks->SetName(vtkDataSetAttributes::GhostArrayName());
  pointMarks->SetNumberOfTuples(output->GetNumberOfPoints());
  pointMarks->FillValue(vtkDataSetAttributes::DUPLICATEPOINT);
  vtkIdType cell = 0, n;
  const vtkIdType* points;
  for (vtkCellArray* cells : { output->GetVerts(), output->GetLines(), output->GetPolys(), output->GetStrips() })
  {
    for (cells->InitTraversal(); cells->GetNextCell(n, points); ++cell)
    {
      if ((cellMarks->GetValue(cell) & vtkDataSetAttributes::DUPLICATECELL) == 0)
      {
        for (vtkIdType k = 0; k < n; ++k)
        {
          pointMarks->SetValue(points[k], 0);
        }
      }
    }
  }
  output->GetPointData()->RemoveArray(vtkDataSetAttributes::GhostArrayName());
  output->GetPointData()->AddArray(pointMarks);
}

void vtkSubDRequestPieceWithGhosts(vtkInformation* inInfo, vtkInformation* outInfo, int requiredLevels)
{
  using Pipeline = vtkStreamingDemandDrivenPipeline;
  const int numPieces = outInfo->Get(Pipeline::UPDATE_NUMBER_OF_PIECES());
  inInfo->Set(Pipeline::UPDATE_PIECE_NUMBER(), outInfo->Get(Pipeline::UPDATE_PIECE_NUMBER()));
  inInfo->Set(Pipeline::UPDATE_NUMBER_OF_PIECES(), numPieces);
  // Ghost cells asked of the output are made from ghost cells, which need layers beyond them.
  const int outputGhosts = outInfo->Get(Pipeline::UPDATE_NUMBER_OF_GHOST_LEVELS());
  inInfo->Set(Pipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), numPieces > 1 ? requiredLevels + outputGhosts : 0);
}

vtkSubDPieceRequest::vtkSubDPieceRequest(vtkInformation* outInfo)
{
  using Pipeline = vtkStreamingDemandDrivenPipeline;
  this->Piece = outInfo->Get(Pipeline::UPDATE_PIECE_NUMBER());
  this->OneOfMany = outInfo->Get(Pipeline::UPDATE_NUMBER_OF_PIECES()) > 1;
  this->OutputGhostLevels = this->OneOfMany ? outInfo->Get(Pipeline::UPDATE_NUMBER_OF_GHOST_LEVELS()) : 0;
}

bool vtkSubDPieceRequest::IsEmptyPiece(vtkPolyData* input) const
{
  return this->OneOfMany && (!input || input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0);
}

void vtkSubDRequestWholeInput(vtkInformationVector** inputVector, int numPorts)
{
  using Pipeline = vtkStreamingDemandDrivenPipeline;
  for (int port = 0; port < numPorts; ++port)
  {
    for (int i = 0; i < inputVector[port]->GetNumberOfInformationObjects(); ++i)
    {
      vtkInformation* inInfo = inputVector[port]->GetInformationObject(i);
      inInfo->Set(Pipeline::UPDATE_PIECE_NUMBER(), 0);
      inInfo->Set(Pipeline::UPDATE_NUMBER_OF_PIECES(), 1);
      inInfo->Set(Pipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
    }
  }
}

std::string vtkSubDMissingGhostsWarning(int piece, int requiredLevels)
{
  // Not an error: a piece may be a part of the mesh that touches no other piece. But more
  // often the pipeline upstream cannot make ghost cells, and the result is silently wrong.
  return "Piece " + std::to_string(piece) + " came without the ghost cells asked for (" +
    std::to_string(requiredLevels) +
    " layers): where it meets other pieces, its edges are treated as boundaries and the pieces together "
    "differ from the whole mesh processed at once. Make ghost cells upstream (vtkExtractPolyDataPiece, or "
    "vtkPDistributedDataFilter, ParaView's D3, which in ParaView 5.11 makes none for meshes with line cells).";
}

bool vtkSubDIsGhostCell(vtkPolyData* input, vtkIdType cell)
{
  vtkUnsignedCharArray* marks = input->GetCellGhostArray();
  return marks && (marks->GetValue(cell) & vtkDataSetAttributes::DUPLICATECELL) != 0;
}

namespace
{
// A face's corners' coordinates, sorted: equal only for faces on the same points.
std::vector<double> SortedCorners(vtkPolyData* input, const subd::Index* corners, subd::Index n)
{
  std::vector<std::array<double, 3>> points(static_cast<size_t>(n));
  for (subd::Index k = 0; k < n; ++k)
  {
    input->GetPoint(corners[k], points[k].data());
  }
  std::sort(points.begin(), points.end());
  std::vector<double> key;
  key.reserve(3 * static_cast<size_t>(n));
  for (const auto& p : points)
  {
    key.insert(key.end(), p.begin(), p.end());
  }
  return key;
}
}

namespace
{
// The kept faces in the order every piece agrees on.
std::vector<subd::Index> OrderAlike(
  vtkPolyData* input, const subd::FaceScreening& faces, const subd::LevelArray<vtkIdType>& faceCells)
{
  const size_t numFaces = faceCells.size();
  std::vector<subd::Index> order(numFaces);
  std::iota(order.begin(), order.end(), 0);
  vtkDataArray* ids = input->GetCellData()->GetGlobalIds();
  if (ids && ids->GetNumberOfComponents() == 1 && ids->GetNumberOfTuples() == input->GetNumberOfCells())
  {
    std::vector<double> id(numFaces);
    for (size_t f = 0; f < numFaces; ++f)
    {
      id[f] = ids->GetComponent(faceCells[f], 0);
    }
    std::stable_sort(order.begin(), order.end(), [&id](subd::Index a, subd::Index b) { return id[a] < id[b]; });
  }
  else
  {
    std::vector<std::vector<double>> key(numFaces);
    for (size_t f = 0; f < numFaces; ++f)
    {
      key[f] = SortedCorners(input, faces.Vertices.data() + faces.Offsets[f], faces.Offsets[f + 1] - faces.Offsets[f]);
    }
    std::stable_sort(order.begin(), order.end(), [&key](subd::Index a, subd::Index b) { return key[a] < key[b]; });
  }
  return order;
}
}

std::vector<subd::Index> vtkSubDFaceRanksAlikeInEveryPiece(
  vtkPolyData* input, const subd::FaceScreening& faces, const subd::LevelArray<vtkIdType>& faceCells)
{
  const std::vector<subd::Index> order = OrderAlike(input, faces, faceCells);
  std::vector<subd::Index> rank(order.size());
  for (size_t i = 0; i < order.size(); ++i)
  {
    rank[order[i]] = static_cast<subd::Index>(i);
  }
  return rank;
}

std::vector<std::uint8_t> vtkSubDSeamLineCopies(
  const subd::Level& finest, const std::vector<std::uint8_t>& faceGhostLayer, const std::vector<subd::Index>& baseFaceRank)
{
  const subd::MeshTopology& topology = finest.Topology;
  std::vector<std::uint8_t> copy(static_cast<size_t>(topology.GetNumEdges()), 0);
  for (subd::Index e = 0; e < topology.GetNumEdges() && !finest.EdgeSharpness.empty(); ++e)
  {
    if (!subd::IsSharp(finest.EdgeSharpness[e]))
    {
      continue;
    }
    // The line goes with the first of its faces' base faces in the shared order: a piece
    // that holds the edge without owning that face (a seam, or a corner where three pieces
    // meet) has a copy.
    bool firstIsOwn = false;
    subd::Index firstRank = std::numeric_limits<subd::Index>::max();
    for (subd::Index f : topology.GetEdgeFaces(e))
    {
      const subd::Index base = finest.GetFaceOrigin(f);
      if (baseFaceRank[base] < firstRank)
      {
        firstRank = baseFaceRank[base];
        firstIsOwn = faceGhostLayer[base] == 0;
      }
    }
    copy[e] = firstIsOwn ? 0 : 1;
  }
  return copy;
}

void vtkSubDOrderFacesAlikeInEveryPiece(vtkPolyData* input, subd::FaceScreening& faces, subd::LevelArray<vtkIdType>& faceCells)
{
  const size_t numFaces = faceCells.size();
  const std::vector<subd::Index> order = OrderAlike(input, faces, faceCells);
  subd::IndexArray offsets{ 0 }, vertices, kept;
  subd::LevelArray<vtkIdType> cells;
  vertices.reserve(faces.Vertices.size());
  kept.reserve(numFaces);
  cells.reserve(numFaces);
  for (subd::Index f : order)
  {
    vertices.insert(vertices.end(), faces.Vertices.begin() + faces.Offsets[f], faces.Vertices.begin() + faces.Offsets[f + 1]);
    offsets.push_back(static_cast<subd::Index>(vertices.size()));
    kept.push_back(faces.KeptFaces[f]);
    cells.push_back(faceCells[f]);
  }
  faces.Offsets.swap(offsets);
  faces.Vertices.swap(vertices);
  faces.KeptFaces.swap(kept);
  faceCells.swap(cells);
}
