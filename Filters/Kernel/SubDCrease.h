// SubD kernel: crease sharpness and the classification of vertices by their creases.
//
// Sharpness follows OpenSubdiv's scale (Sdc::Crease): 0 is smooth, values >= 10 are
// infinitely sharp, and values in between are semi-sharp (they lose one unit per level).
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
}

#endif
