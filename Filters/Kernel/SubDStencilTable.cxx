#include "SubDStencilTable.h"

namespace subd
{
void StencilTable::FinalizeSizes()
{
  for (size_t i = 1; i < this->Offsets.size(); ++i)
  {
    this->Offsets[i] += this->Offsets[i - 1];
  }
  this->Sources.assign(static_cast<size_t>(this->Offsets.back()), InvalidIndex);
  this->Weights.assign(static_cast<size_t>(this->Offsets.back()), 0.0);
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
}
