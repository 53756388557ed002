#include "vtkSubDMemoryBudget.h"

#include <unistd.h>

double vtkSubDDefaultMemoryBudget()
{
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long pageSize = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || pageSize <= 0)
  {
    return 16384.0;
  }
  return 0.5 * static_cast<double>(pages) * static_cast<double>(pageSize) / (1024.0 * 1024.0);
}
