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
}
