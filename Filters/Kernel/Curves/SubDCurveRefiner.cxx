#include "SubDCurveRefiner.h"

#include <algorithm>

namespace subd
{
void CurvePieces::AddPiece(const Index* begin, const Index* end, bool closed)
{
  this->Points.insert(this->Points.end(), begin, end);
  this->Offsets.push_back(static_cast<Index>(this->Points.size()));
  this->Closed.push_back(closed ? 1 : 0);
}

void SplitAtCorners(const CurveLines& lines, CurvePieces& pieces, std::vector<Index>& firstPiece)
{
  pieces = CurvePieces();
  const std::vector<Index>& offsets = *lines.Offsets;
  const std::vector<Index>& ids = *lines.Ids;
  const Index numLines = static_cast<Index>(offsets.size()) - 1;
  firstPiece.assign(1, 0);
  std::vector<Index> ring;
  auto isCorner = [&](Index id) { return lines.IsCorner && !lines.IsCorner->empty() && (*lines.IsCorner)[id] != 0; };
  for (Index line = 0; line < numLines; ++line)
  {
    const Index* begin = ids.data() + offsets[line];
    const Index n = offsets[line + 1] - offsets[line];
    const bool closed = IsClosedPolygon(n, (*lines.Closed)[line] != 0);
    Index start = 0; // where the open sequence starts
    if (closed)
    {
      while (start < n && !isCorner(begin[start]))
      {
        ++start;
      }
      if (start == n)
      {
        pieces.AddPiece(begin, begin + n, true);
        firstPiece.push_back(pieces.GetNumPieces());
        continue;
      }
    }
    // The open sequence: the polyline itself, or a closed one rotated to start and end at its
    // first corner.
    ring.clear();
    for (Index k = 0; k < n; ++k)
    {
      ring.push_back(begin[(start + k) % n]);
    }
    if (closed)
    {
      ring.push_back(ring.front());
    }
    const Index m = static_cast<Index>(ring.size());
    Index pieceStart = 0;
    for (Index k = 1; k + 1 < m; ++k)
    {
      if (isCorner(ring[k]))
      {
        pieces.AddPiece(ring.data() + pieceStart, ring.data() + k + 1, false);
        pieceStart = k;
      }
    }
    if (m > 0)
    {
      pieces.AddPiece(ring.data() + pieceStart, ring.data() + m, false);
    }
    firstPiece.push_back(pieces.GetNumPieces());
  }
}

namespace
{
// Interior points of a piece: those that are not anchors.
Index InteriorCount(Index n, bool closed)
{
  return closed ? n : std::max<Index>(n - 2, 0);
}

// The gather table: anchors (distinct end points of open pieces) first, then each piece's
// interior points; `gathered` gets the pieces in that numbering.
void Gather(Index numBasePoints, const CurvePieces& base, StencilTable& table, CurvePieces& gathered)
{
  std::vector<Index> anchorOf(static_cast<size_t>(numBasePoints), InvalidIndex);
  StencilRows rows;
  Index next = 0;
  auto anchor = [&](Index id) {
    if (anchorOf[id] == InvalidIndex)
    {
      anchorOf[id] = next++;
      rows.Add(id, 1.0);
      rows.EndRow();
    }
    return anchorOf[id];
  };
  for (Index p = 0; p < base.GetNumPieces(); ++p)
  {
    const IndexSpan piece = base.GetPiece(p);
    if (!base.IsClosed(p) && piece.size() > 0)
    {
      anchor(piece[0]);
      anchor(piece[piece.size() - 1]);
    }
  }
  gathered = CurvePieces();
  gathered.NumAnchors = next;
  std::vector<Index> points;
  for (Index p = 0; p < base.GetNumPieces(); ++p)
  {
    const IndexSpan piece = base.GetPiece(p);
    const bool closed = base.IsClosed(p);
    points.clear();
    for (Index k = 0; k < piece.size(); ++k)
    {
      const bool end = !closed && (k == 0 || k == piece.size() - 1);
      if (end)
      {
        points.push_back(anchorOf[piece[k]]);
      }
      else
      {
        points.push_back(next++);
        rows.Add(piece[k], 1.0);
        rows.EndRow();
      }
    }
    gathered.AddPiece(points.data(), points.data() + points.size(), closed);
  }
  table = rows.ToStencilTable(numBasePoints);
}

void RefineLevel(const CurveRules& rules, const CurvePieces& parent, StencilTable& table, CurvePieces& child)
{
  StencilRows rows;
  for (Index a = 0; a < parent.NumAnchors; ++a)
  {
    rows.Add(a, 1.0);
    rows.EndRow();
  }
  child = CurvePieces();
  child.NumAnchors = parent.NumAnchors;
  Index next = parent.NumAnchors;
  StencilRows local;
  std::vector<Index> points;
  for (Index p = 0; p < parent.GetNumPieces(); ++p)
  {
    const IndexSpan piece = parent.GetPiece(p);
    const Index n = piece.size();
    const bool closed = parent.IsClosed(p);
    local.Clear();
    AppendCurveChildRows(rules, n, closed, local);
    // An open polygon's first and last children are its anchors (every scheme keeps the end
    // points); the others are new points of this piece.
    const Index children = local.GetNumRows();
    const Index first = closed ? 0 : 1, last = closed ? children : std::max<Index>(children - 1, first);
    rows.AppendRenumbered(local, first, last, piece.Data);
    points.clear();
    if (!closed)
    {
      points.push_back(piece[0]);
    }
    for (Index c = first; c < last; ++c)
    {
      points.push_back(next++);
    }
    if (!closed && children > 1)
    {
      points.push_back(piece[n - 1]);
    }
    child.AddPiece(points.data(), points.data() + points.size(), closed);
  }
  Index numParents = parent.NumAnchors;
  for (Index p = 0; p < parent.GetNumPieces(); ++p)
  {
    numParents += InteriorCount(parent.GetPiece(p).size(), parent.IsClosed(p));
  }
  table = rows.ToStencilTable(numParents);
}
}

double PredictCurvePoints(const CurveRules& rules, const CurvePieces& pieces, int levels)
{
  double total = 0.0;
  for (Index p = 0; p < pieces.GetNumPieces(); ++p)
  {
    const bool closed = pieces.IsClosed(p);
    double n = pieces.GetPiece(p).size();
    for (int l = 0; l < levels && n > 1; ++l)
    {
      n = closed ? 2 * n : (rules.Scheme == CurveScheme::Chaikin && n > 2 ? 2 * n - 2 : 2 * n - 1);
    }
    total += n; // anchors shared by pieces are counted once per piece: an upper bound
  }
  return total;
}

bool RefineCurves(const CurveRules& rules, Index numBasePoints, const CurvePieces& base, int levels,
  Hierarchy& out, CurvePieces& finest, const ProgressCallback& progress)
{
  out = Hierarchy();
  out.NumBasePoints = numBasePoints;
  out.Stencils.resize(static_cast<size_t>(levels) + 1);
  Gather(numBasePoints, base, out.Stencils[0], finest);
  for (int l = 0; l < levels; ++l)
  {
    if (progress && !progress(static_cast<double>(l) / levels))
    {
      return false;
    }
    CurvePieces child;
    RefineLevel(rules, finest, out.Stencils[static_cast<size_t>(l) + 1], child);
    finest = std::move(child);
  }
  return true;
}
}
