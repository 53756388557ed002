#include "vtkSubDGLTFWriter.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkGLTFWriter.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

vtkStandardNewMacro(vtkSubDGLTFWriter);

void vtkSubDGLTFWriter::WriteFile(vtkPolyData* input, std::ostream& file)
{
  if (input->GetNumberOfLines() + input->GetNumberOfVerts() > 0)
  {
    vtkWarningMacro("The glTF file holds the polygons only: " << input->GetNumberOfLines() << " lines and "
                                                              << input->GetNumberOfVerts() << " verts are not written.");
  }
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(input->GetPoints());
  mesh->SetPolys(input->GetPolys());
  mesh->SetStrips(input->GetStrips());
  mesh->GetPointData()->SetTCoords(input->GetPointData()->GetTCoords());
  vtkDataArray* normals = input->GetPointData()->GetNormals();
  if (normals)
  {
    vtkNew<vtkFloatArray> gltfNormals; // the name VTK's writer looks for
    gltfNormals->DeepCopy(normals);
    gltfNormals->SetName("NORMAL");
    mesh->GetPointData()->AddArray(gltfNormals);
  }
  // VTK's writer takes the blocks of a CityGML scene: buildings made of pieces.
  vtkNew<vtkMultiBlockDataSet> building;
  building->SetBlock(0, mesh);
  vtkNew<vtkMultiBlockDataSet> scene;
  scene->SetBlock(0, building);
  vtkNew<vtkGLTFWriter> writer;
  writer->SetInlineData(true);
  writer->SetSaveNormal(normals != nullptr);
  writer->WriteToStream(file, scene);
}

void vtkSubDGLTFWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
