#include "vtkSubDGLTFReader.h"

#include "vtkAppendPolyData.h"
#include "vtkCallbackCommand.h"
#include "vtkCompositeDataIterator.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkGLTFReader.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSubDGLTFCheck.h"

#include <string>

vtkStandardNewMacro(vtkSubDGLTFReader);

namespace
{
// A primitive as SubD takes it: TEXCOORD_0 as TCoords in VTK's convention, no cage normals.
vtkSmartPointer<vtkPolyData> Primitive(vtkPolyData* block)
{
  auto primitive = vtkSmartPointer<vtkPolyData>::New();
  primitive->ShallowCopy(block);
  vtkPointData* data = primitive->GetPointData();
  data->RemoveArray("NORMAL");
  data->RemoveArray("TANGENT");
  if (vtkDataArray* gltf = data->GetArray("TEXCOORD_0"))
  {
    vtkSmartPointer<vtkDataArray> tcoords;
    tcoords.TakeReference(gltf->NewInstance());
    tcoords->DeepCopy(gltf);
    tcoords->SetName("TCoords");
    for (vtkIdType i = 0; i < tcoords->GetNumberOfTuples(); ++i)
    {
      tcoords->SetComponent(i, 1, 1.0 - tcoords->GetComponent(i, 1));
    }
    data->RemoveArray("TEXCOORD_0");
    data->SetTCoords(tcoords);
  }
  return primitive;
}

void KeepError(vtkObject*, unsigned long, void* clientData, void* callData)
{
  auto* message = static_cast<std::string*>(clientData);
  *message += callData ? static_cast<const char*>(callData) : "";
}
}

bool vtkSubDGLTFReader::ReadFile(std::istream&, vtkPolyData* output)
{
  std::string problem;
  if (!vtkSubDCheckGLTF(this->FileName, problem))
  {
    return this->Fail(0, problem);
  }
  vtkNew<vtkGLTFReader> reader;
  reader->SetFileName(this->FileName);
  std::string message;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetCallback(KeepError);
  onError->SetClientData(&message);
  reader->AddObserver(vtkCommand::ErrorEvent, onError);
  if (!reader->GetExecutive()->Update())
  {
    return this->Fail(0, "VTK's glTF reader failed" + (message.empty() ? std::string() : ": " + message));
  }
  vtkNew<vtkAppendPolyData> append;
  vtkSmartPointer<vtkCompositeDataIterator> blocks;
  blocks.TakeReference(reader->GetOutput()->NewIterator());
  for (blocks->InitTraversal(); !blocks->IsDoneWithTraversal(); blocks->GoToNextItem())
  {
    if (auto* block = vtkPolyData::SafeDownCast(blocks->GetCurrentDataObject()))
    {
      append->AddInputData(Primitive(block));
    }
  }
  if (append->GetNumberOfInputConnections(0) == 0)
  {
    return this->Fail(0, "the scene holds no mesh");
  }
  append->Update();
  output->ShallowCopy(append->GetOutput());
  return true;
}

void vtkSubDGLTFReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
