// SubD kernel: crease sharpness and the classification of vertices by their creases.
//
// Sharpness follows OpenSubdiv's scale (Sdc::Crease): 0 is smooth, values >= 10 are
// infinitely sharp, and values in between are semi-sharp: they lose one unit per level
// (CreaseMethod::Uniform), or, with CreaseMethod::Chaikin, each half of an edge first takes
// 3/4 of its own sharpness plus 1/4 of the mean of the other semi-sharp edges at its end
// vertex, so sharpness varies smoothly along a crease (DeRose et al. 1998, section 3).
// A vertex is classified from its own sharpness and the number of sharp edges it touches
// (DeRose, Kass, Truong, "Subdivision Surfaces in Character Animation", SIGGRAPH 1998;
// Hoppe et al., "Piecewise Smooth Surface Reconstruction", SIGGRAPH 1994):
//   sharp vertex or >= 3 sharp edges -> Corner (the vertex stays put),
//   exactly 2 sharp edges            -> Crease (the curve rule along the two edges),
//   exactly 1 sharp edge             -> Dart   (the smooth rule),
//   no sharp edge                    -> Smooth.
#ifndef SubDCrease_h
#define SubDCrease_h

#include "SubDTypes.h"

namespace subd
{
constexpr float SharpnessSmooth = 0.0f;
constexpr float SharpnessInfinite = 10.0f;

inline bool IsSharp(float sharpness)
{
  return sharpness > SharpnessSmooth;
}
inline bool IsInfinitelySharp(float sharpness)
{
  return sharpness >= SharpnessInfinite;
}
inline bool IsSemiSharp(float sharpness)
{
  return IsSharp(sharpness) && !IsInfinitelySharp(sharpness);
}

/// How semi-sharp edges lose sharpness from one level to the next.
enum class CreaseMethod : std::uint8_t
{
  Uniform = 0, ///< every semi-sharp value loses one unit
  Chaikin = 1  ///< each half is first averaged with the other creases at its end vertex
};
SUBDKERNEL_EXPORT const char* ToString(CreaseMethod method);
/// Sharpness of an edge or vertex child one level down: infinite stays infinite, the rest
/// loses one unit, never below zero (OpenSubdiv's uniform decay).
inline float DecaySharpness(float sharpness)
{
  return IsInfinitelySharp(sharpness) ? SharpnessInfinite
                                      : (sharpness > 1.0f ? sharpness - 1.0f : SharpnessSmooth);
}

enum class VertexRule : std::uint8_t
{
  Smooth = 0,
  Dart = 1,
  Crease = 2,
  Corner = 3
};

inline VertexRule ClassifyVertex(float vertexSharpness, Index sharpEdgeCount)
{
  if (IsSharp(vertexSharpness) || sharpEdgeCount > 2)
  {
    return VertexRule::Corner;
  }
  if (sharpEdgeCount == 2)
  {
    return VertexRule::Crease;
  }
  return sharpEdgeCount == 1 ? VertexRule::Dart : VertexRule::Smooth;
}

SUBDKERNEL_EXPORT const char* ToString(VertexRule rule);

/// Sharpness of the half of an edge that ends at vertex v, from the edge's sharpness and
/// the sharpness of all `count` edges at v (the edge included). Computed in float, as
/// OpenSubdiv does (Sdc::Crease::SubdivideEdgeSharpnessAtVertex), so transitions happen
/// at the same level in both.
SUBDKERNEL_EXPORT float SubdivideEdgeSharpnessAtVertex(
  float edgeSharpness, CreaseMethod method, const float* sharpnessAtVertex, Index count);

/// The weight of the parent's mask when a vertex's rule changes from one level to the next
/// (a semi-sharp feature decays to smooth): the mean sharpness of the vertex and of the
/// edges that were sharp in the parent and are smooth in the child, clamped to 1 — a
/// sharpness of 0.3 contributes 30% of the sharp rule at the level where it vanishes
/// (OpenSubdiv's Sdc::Crease::ComputeFractionalWeightAtVertex). In float, as there.
SUBDKERNEL_EXPORT float TransitionWeightAtVertex(float parentVertexSharpness,
  float childVertexSharpness, const float* parentEdgeSharpness, const float* childEdgeSharpness,
  Index count);
}

#endif
