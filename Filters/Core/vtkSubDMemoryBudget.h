// Private helper of SubD's filters: the default memory budget of the size guard.
#ifndef vtkSubDMemoryBudget_h
#define vtkSubDMemoryBudget_h

/// Half the machine's physical memory, in MiB (16384 where it cannot be read): the default
/// MaximumMemory, leaving the other half to the rest of the pipeline and the system.
double vtkSubDDefaultMemoryBudget();

#endif
