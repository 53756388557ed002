#include "SubDTypes.h"

namespace subd
{
const char* ToString(BoundaryRule rule)
{
  switch (rule)
  {
    case BoundaryRule::None:
      return "None";
    case BoundaryRule::EdgeOnly:
      return "EdgeOnly";
    case BoundaryRule::EdgeAndCorner:
      return "EdgeAndCorner";
  }
  return "Unknown";
}
}
