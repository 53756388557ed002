// SubD kernel: the tangent plane at the centre of a ring that refinement maps onto itself
// by a rotation-invariant (circulant) matrix.
//
// Where one refinement maps the n points q_0..q_{n-1} of a ring around a point (in order
// around it) to the ring of the next level by the same weights at every position, the
// matrix is circulant, so its left eigenvectors are the discrete Fourier modes
// sum_j omega^{jk} q_j. Mode 0 is the centre; the subdominant pair is mode 1 (for the
// schemes here: Doo, Sabin 1978 for their V-faces, Kobbelt 2000 for sqrt(3), Peters, Reif
// 1997 for the midpoint polygon, Zorin, Schroeder, Sweldens 1996 for the butterfly at an
// extraordinary vertex), and its real and imaginary parts
//     t1 = sum_j cos(2 pi j / n) q_j,   t2 = sum_j sin(2 pi j / n) q_j
// span the tangent plane of the limit surface at the centre's limit point. With the ring
// counter-clockwise seen from outside, t1 x t2 points outside.
#ifndef SubDRingTangents_h
#define SubDRingTangents_h

#include "SubDMeshTopology.h"
#include "SubDStencilTable.h"

#include <cmath>
#include <vector>

namespace subd
{
/// Appends the two rows t1, t2 to `rows`; `addMember(j, w)` adds w * q_j to the current row.
template <typename AddMember>
void AppendRingTangentRows(Index n, AddMember&& addMember, StencilRows& rows)
{
  const double pi = 3.14159265358979323846;
  for (int axis = 0; axis < 2; ++axis)
  {
    for (Index j = 0; j < n; ++j)
    {
      const double angle = 2.0 * pi * static_cast<double>(j) / static_cast<double>(n);
      addMember(j, axis == 0 ? std::cos(angle) : std::sin(angle));
    }
    rows.EndRow();
  }
}

/// The ring of a manifold vertex v whose faces form a closed fan: for each face around v in
/// counter-clockwise order (MeshTopology::GetOrderedVertexFaces), the corner after v.
/// Returns false for a vertex without a closed fan.
SUBDKERNEL_EXPORT bool GetOrderedRing(const MeshTopology& topo, Index v, std::vector<Index>& faces,
  std::vector<Index>& corners, std::vector<Index>& ring);
}

#endif
