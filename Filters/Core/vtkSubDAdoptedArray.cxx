#include "vtkSubDAdoptedArray.h"

#include <mutex>
#include <type_traits>
#include <unordered_map>

static_assert(std::is_same<subd::Index, vtkTypeInt32>::value, "kernel indices are VTK's 32-bit ints");

namespace
{
struct AdoptedVectors
{
  std::mutex Mutex;
  std::unordered_map<const void*, subd::IndexArray> ByStorage;
};

AdoptedVectors& Registry()
{
  static AdoptedVectors* registry = new AdoptedVectors; // never destroyed: arrays may outlive statics
  return *registry;
}

void FreeAdopted(void* storage)
{
  subd::IndexArray released;
  {
    AdoptedVectors& registry = Registry();
    std::lock_guard<std::mutex> lock(registry.Mutex);
    auto found = registry.ByStorage.find(storage);
    if (found == registry.ByStorage.end())
    {
      return;
    }
    released = std::move(found->second);
    registry.ByStorage.erase(found);
  }
  // `released` is freed here, outside the lock.
}
}

vtkSmartPointer<vtkTypeInt32Array> vtkSubDAdoptVector(subd::IndexArray&& values)
{
  auto array = vtkSmartPointer<vtkTypeInt32Array>::New();
  if (values.empty())
  {
    values = subd::IndexArray();
    return array;
  }
  std::int32_t* storage = values.data();
  const vtkIdType size = static_cast<vtkIdType>(values.size());
  {
    AdoptedVectors& registry = Registry();
    std::lock_guard<std::mutex> lock(registry.Mutex);
    registry.ByStorage.emplace(storage, std::move(values)); // moving keeps the storage
  }
  values = subd::IndexArray();
  array->SetArray(storage, size, 0, vtkAbstractArray::VTK_DATA_ARRAY_USER_DEFINED);
  array->SetArrayFreeFunction(&FreeAdopted);
  return array;
}

std::size_t vtkSubDNumberOfAdoptedVectors()
{
  AdoptedVectors& registry = Registry();
  std::lock_guard<std::mutex> lock(registry.Mutex);
  return registry.ByStorage.size();
}
