#include "SubDCrease.h"

namespace subd
{
const char* ToString(VertexRule rule)
{
  switch (rule)
  {
    case VertexRule::Smooth:
      return "Smooth";
    case VertexRule::Dart:
      return "Dart";
    case VertexRule::Crease:
      return "Crease";
    case VertexRule::Corner:
      return "Corner";
  }
  return "Unknown";
}

const char* ToString(CreaseMethod method)
{
  return method == CreaseMethod::Chaikin ? "Chaikin" : "Uniform";
}

float SubdivideEdgeSharpnessAtVertex(
  float edgeSharpness, CreaseMethod method, const float* sharpnessAtVertex, Index count)
{
  if (method == CreaseMethod::Uniform || !IsSemiSharp(edgeSharpness) || count < 2)
  {
    return DecaySharpness(edgeSharpness);
  }
  // The sum is accumulated in double, where a few floats add exactly: the result must not
  // depend on the order the edges are listed in (a vertex's edges are ordered differently
  // in a piece of the mesh, SubDLocalLevel.h, than in the whole).
  double semiSharpSum = 0.0;
  Index semiSharpCount = 0;
  for (Index i = 0; i < count; ++i)
  {
    if (IsSemiSharp(sharpnessAtVertex[i]))
    {
      semiSharpSum += sharpnessAtVertex[i];
      ++semiSharpCount;
    }
  }
  float averaged = edgeSharpness;
  if (semiSharpCount > 1)
  {
    const float othersMean = static_cast<float>((semiSharpSum - edgeSharpness) / (semiSharpCount - 1));
    averaged = 0.75f * edgeSharpness + 0.25f * othersMean;
  }
  averaged -= 1.0f;
  return IsSharp(averaged) ? averaged : SharpnessSmooth;
}

float TransitionWeightAtVertex(float parentVertexSharpness, float childVertexSharpness,
  const float* parentEdgeSharpness, const float* childEdgeSharpness, Index count)
{
  Index transitions = 0;
  double sum = 0.0; // in double: independent of the order of the edges (see above)
  if (IsSharp(parentVertexSharpness) && !IsSharp(childVertexSharpness))
  {
    transitions = 1;
    sum = parentVertexSharpness;
  }
  for (Index i = 0; i < count; ++i)
  {
    if (IsSharp(parentEdgeSharpness[i]) && !IsSharp(childEdgeSharpness[i]))
    {
      sum += parentEdgeSharpness[i];
      ++transitions;
    }
  }
  if (transitions == 0)
  {
    return 0.0f;
  }
  const float weight = static_cast<float>(sum / transitions);
  return weight > 1.0f ? 1.0f : weight;
}
}
