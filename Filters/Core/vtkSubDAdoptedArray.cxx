#include "vtkSubDAdoptedArray.h"

#include <mutex>
#include <unordered_map>

namespace
{
struct AdoptedVectors
{
  std::mutex Mutex;
  std::unordered_map<const void*, std::vector<std::int32_t>> ByStorage;
};

AdoptedVectors& Registry()
{
  static AdoptedVectors* registry = new AdoptedVectors; // never destroyed: arrays may outlive statics
  return *registry;
}

void FreeAdopted(void* storage)
{
  std::vector<std::int32_t> released;
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

vtkSmartPointer<vtkTypeInt32Array> vtkSubDAdoptVector(std::vector<std::int32_t>&& values)
{
  auto array = vtkSmartPointer<vtkTypeInt32Array>::New();
  if (values.empty())
  {
    values = std::vector<std::int32_t>();
    return array;
  }
  std::int32_t* storage = values.data();
  const vtkIdType size = static_cast<vtkIdType>(values.size());
  {
    AdoptedVectors& registry = Registry();
    std::lock_guard<std::mutex> lock(registry.Mutex);
    registry.ByStorage.emplace(storage, std::move(values)); // moving keeps the storage
  }
  values = std::vector<std::int32_t>();
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
