// SubD kernel: the limit point and tangent plane at a vertex of any valence and any vertex
// rule (smooth, dart, crease, corner), from the eigenstructure of the subdivision matrix of
// the vertex's neighbourhood (Doo, Sabin 1978; Halstead, Kass, DeRose 1993; Zorin,
// "Stationary Subdivision and Multiresolution Surface Representations", 1998).
//
// The neighbourhood N of a vertex v (v and the other corners of its faces, or of the faces
// on one side of a crease: the crease rules never look across) maps onto itself under one
// refinement: N' = S N, S read off the scheme's own stencils. With S's right and left
// eigenvectors r_k, l_k (normalised l_k r_k = 1), N after m levels is sum lambda_k^m P_k N
// with the projectors P_k = r_k l_k. So
//   - the limit point is the row of v in P_1 (lambda = 1): the limit mask,
//   - the next eigenvalues by magnitude (the subdominant pair: one double eigenvalue at a
//     smooth vertex; along and across the crease at a crease) span the tangent plane, and
//     T_j = (P_T N)_j is the tangent of the limit curve leaving v along its edge to
//     neighbour j, scaled so that the points along that edge approach v as lambda^m T_j.
// At a regular vertex lambda = 1/2 and T_j is the parametric derivative along the edge; at
// an extraordinary vertex the parametrisation is singular (derivatives vanish or blow up
// as (2 lambda)^m), and T_j is the natural finite stand-in with the right direction.
//
// The vertex's rule must be stable (edges and vertex smooth or infinitely sharp, no
// transition): semi-sharp features are refined away first.
#ifndef SubDVertexLimit_h
#define SubDVertexLimit_h

#include "SubDRegularPatch.h" // IsStableCorner
#include "SubDScheme.h"

#include <string>
#include <vector>

namespace subd
{
struct VertexLimit
{
  std::vector<Index> Points;          ///< points of the level
  std::vector<double> Position;       ///< weights of the limit point
  std::vector<double> TangentNext;    ///< along the face's edge to its next corner
  std::vector<double> TangentPrevious;///< along the face's edge to its previous corner
};

/// Limit point and tangents at corner `corner` of `face`, on `face`'s side of any crease.
/// Returns false (with the reason) if the corner cannot be analysed (IsStableCorner).
SUBDKERNEL_EXPORT bool ComputeVertexLimit(const Scheme& scheme, const Level& level, Index face, Index corner,
  VertexLimit& out, std::string& error);
}

#endif
