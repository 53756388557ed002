#include "vtkSubDAdoptedArray.h"

#include <memory>
#include <mutex>
#include <type_traits>
#include <unordered_map>

static_assert(std::is_same<subd::Index, vtkTypeInt32>::value, "kernel indices are VTK's 32-bit ints");

namespace
{
struct AdoptedVectors
{
  std::mutex Mutex;
  std::unordered_map<const void*, std::shared_ptr<void>> ByStorage; // the vector owning it
};

AdoptedVectors& Registry()
{
  static AdoptedVectors* registry = new AdoptedVectors; // never destroyed: arrays may outlive statics
  return *registry;
}

void FreeAdopted(void* storage)
{
  std::shared_ptr<void> released;
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

// Gives `array` the storage of `values` (not empty), which the registry keeps until VTK
// frees it.
template <typename ArrayType, typename Vector>
void Adopt(ArrayType* array, Vector&& values)
{
  auto owner = std::make_shared<std::decay_t<Vector>>(std::move(values)); // moving keeps the storage
  auto* storage = owner->data();
  const vtkIdType size = static_cast<vtkIdType>(owner->size());
  {
    AdoptedVectors& registry = Registry();
    std::lock_guard<std::mutex> lock(registry.Mutex);
    registry.ByStorage.emplace(storage, std::move(owner));
  }
  array->SetArray(storage, size, 0, vtkAbstractArray::VTK_DATA_ARRAY_USER_DEFINED);
  array->SetArrayFreeFunction(&FreeAdopted);
}
}

vtkSmartPointer<vtkTypeInt32Array> vtkSubDAdoptVector(subd::IndexArray&& values)
{
  auto array = vtkSmartPointer<vtkTypeInt32Array>::New();
  if (!values.empty())
  {
    Adopt(array.Get(), std::move(values));
  }
  values = subd::IndexArray();
  return array;
}

std::size_t vtkSubDNumberOfAdoptedVectors()
{
  AdoptedVectors& registry = Registry();
  std::lock_guard<std::mutex> lock(registry.Mutex);
  return registry.ByStorage.size();
}
