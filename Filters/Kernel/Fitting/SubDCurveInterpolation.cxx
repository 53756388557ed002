#include "SubDCurveInterpolation.h"

#include "SubDCurveLimit.h"

namespace subd
{
namespace
{
bool SameRow(const SparseRow& a, const StencilRows& rows, Index r, const Index* ids)
{
  const Index begin = rows.Offsets[r], end = rows.Offsets[r + 1];
  if (a.Points.size() != static_cast<size_t>(end - begin))
  {
    return false;
  }
  for (Index k = begin; k < end; ++k)
  {
    if (a.Points[k - begin] != ids[rows.Sources[k]] || a.Weights[k - begin] != rows.Weights[k])
    {
      return false;
    }
  }
  return true;
}
}

void BuildCurveLimitRows(const CurveRules& rules, const CurvePieces& pieces, Index numPoints,
  std::vector<SparseRow>& rows, std::vector<std::string>& problems)
{
  rows.assign(static_cast<size_t>(numPoints), SparseRow());
  problems.assign(static_cast<size_t>(numPoints), std::string());
  std::vector<char> seen(static_cast<size_t>(numPoints), 0);
  StencilRows local;
  for (Index p = 0; p < pieces.GetNumPieces(); ++p)
  {
    const IndexSpan piece = pieces.GetPiece(p);
    local.Clear();
    for (Index j = 0; j < piece.size(); ++j)
    {
      AppendCurveLimitMask(rules, piece.size(), pieces.IsClosed(p), j, local);
    }
    for (Index j = 0; j < piece.size(); ++j)
    {
      const Index point = piece[j];
      if (!problems[point].empty())
      {
        continue;
      }
      if (seen[point])
      {
        if (!SameRow(rows[point], local, j, piece.Data))
        {
          rows[point] = SparseRow();
          problems[point] = "it is on several curves and inside at least one of them, so it has one limit point "
                            "per curve (make it a sharp corner, or an end of each curve)";
        }
        continue;
      }
      seen[point] = 1;
      SparseRow& row = rows[point];
      for (Index k = local.Offsets[j]; k < local.Offsets[j + 1]; ++k)
      {
        row.Points.push_back(piece[local.Sources[k]]);
        row.Weights.push_back(local.Weights[k]);
      }
    }
  }
}
}
