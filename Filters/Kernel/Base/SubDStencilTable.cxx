#include "SubDStencilTable.h"

#include <algorithm>

namespace subd
{
StencilTable StencilTable::FromSource(std::shared_ptr<const RowSource> source)
{
  StencilTable table(source->GetNumParents());
  table.BlockEnds = source->GetBlockEnds();
  table.Source = std::move(source);
  return table;
}

void StencilTable::FinalizeSizes()
{
  this->FinalizeSizesUnfilled();
  std::fill(this->Sources.begin(), this->Sources.end(), InvalidIndex);
  std::fill(this->Weights.begin(), this->Weights.end(), 0.0);
}

void StencilTable::FinalizeSizesUnfilled()
{
  for (size_t i = 1; i < this->Offsets.size(); ++i)
  {
    this->Offsets[i] += this->Offsets[i - 1];
  }
  this->Sources.resize(static_cast<size_t>(this->Offsets.back()));
  this->Weights.resize(static_cast<size_t>(this->Offsets.back()));
}

double StencilTable::GetRowSum(Index row) const
{
  double sum = 0.0;
  const double* w = this->GetWeights(row);
  for (Index k = 0; k < this->GetSources(row).size(); ++k)
  {
    sum += w[k];
  }
  return sum;
}

void StencilRows::Clear()
{
  this->Offsets.assign(1, 0);
  this->Sources.clear();
  this->Weights.clear();
}

void StencilRows::Add(Index source, double w)
{
  for (size_t k = static_cast<size_t>(this->Offsets.back()); k < this->Sources.size(); ++k)
  {
    if (this->Sources[k] == source)
    {
      this->Weights[k] += w;
      return;
    }
  }
  this->Sources.push_back(source);
  this->Weights.push_back(w);
}

void StencilRows::AppendRenumbered(const StencilRows& local, Index begin, Index end, const Index* ids)
{
  for (Index r = begin; r < end; ++r)
  {
    for (Index k = local.Offsets[r]; k < local.Offsets[r + 1]; ++k)
    {
      this->Add(ids[local.Sources[k]], local.Weights[k]);
    }
    this->EndRow();
  }
}

void StencilRows::AddRow(const StencilTable& table, Index row, double scale)
{
  const IndexSpan sources = table.GetSources(row);
  const double* weights = table.GetWeights(row);
  for (Index k = 0; k < sources.size(); ++k)
  {
    if (sources[k] < table.GetNumParents())
    {
      this->Add(sources[k], scale * weights[k]);
    }
    else
    {
      this->AddRow(table, sources[k] - table.GetNumParents(), scale * weights[k]);
    }
  }
}

StencilTable StencilRows::ToStencilTable(Index numParents) const
{
  StencilTable table(numParents);
  const Index numRows = this->GetNumRows();
  table.ReserveRows(numRows);
  for (Index r = 0; r < numRows; ++r)
  {
    table.SetRowSize(r, this->Offsets[r + 1] - this->Offsets[r]);
  }
  table.FinalizeSizes();
  for (Index r = 0; r < numRows; ++r)
  {
    std::copy(this->Sources.begin() + this->Offsets[r], this->Sources.begin() + this->Offsets[r + 1],
      table.GetMutableSources(r));
    std::copy(this->Weights.begin() + this->Offsets[r], this->Weights.begin() + this->Offsets[r + 1],
      table.GetMutableWeights(r));
  }
  table.EndBlock(numRows);
  return table;
}
}
