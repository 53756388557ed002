#include "SubDMeshIO.h"

#include "SubDFileChecks.h"
#include "SubDMessageCollector.h"
#include "vtkAlgorithm.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPolyData.h"
#include "vtkPolyDataWriter.h"
#include "vtkSTLReader.h"
#include "vtkSTLWriter.h"
#include "vtkSubDGLTFReader.h"
#include "vtkSubDGLTFWriter.h"
#include "vtkSubDLegacyReader.h"
#include "vtkSubDOBJReader.h"
#include "vtkSubDOBJWriter.h"
#include "vtkSubDOFFReader.h"
#include "vtkSubDOFFWriter.h"
#include "vtkSubDPLYReader.h"
#include "vtkSubDPLYWriter.h"
#include "vtkTriangleFilter.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"
#include "vtkXMLWriter.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <new>
#include <unistd.h>

namespace subdapp
{
namespace
{
bool FileReadable(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return static_cast<bool>(in);
}

// Some readers report a broken file only through a generic warning, attached to no object
// (vtkDataReader: "Error reading ascii data. Possible mismatch of datasize with declaration."),
// and return what they read so far. While a reader runs, this output window keeps such
// messages as errors of the read; it puts the previous window back when it goes.
class GenericMessageCapture : public vtkOutputWindow
{
public:
  static GenericMessageCapture* New();
  vtkTypeMacro(GenericMessageCapture, vtkOutputWindow);
  void DisplayText(const char*) override {}
  void DisplayErrorText(const char* text) override { this->Keep(text); }
  void DisplayGenericWarningText(const char* text) override { this->Keep(text); }
  std::string Captured;

private:
  void Keep(const char* text)
  {
    std::string message = text ? text : "";
    if (message.find("returned failure for request") != std::string::npos)
    {
      return; // the executive's follow-up to an error the reader reported itself
    }
    const auto newline = message.find('\n'); // drop the "... In file, line N" first line
    if (newline != std::string::npos && message.substr(0, newline).find(", line ") != std::string::npos)
    {
      message = message.substr(newline + 1);
    }
    this->Captured += message;
  }
};
vtkStandardNewMacro(GenericMessageCapture);

template <typename Reader>
vtkSmartPointer<vtkPolyData> RunReader(const std::string& path, std::string& error)
{
  vtkNew<Reader> reader;
  MessageCollector messages;
  messages.Watch(reader);
  reader->SetFileName(path.c_str());
  vtkSmartPointer<vtkOutputWindow> previous = vtkOutputWindow::GetInstance();
  vtkNew<GenericMessageCapture> capture;
  vtkOutputWindow::SetInstance(capture);
  try
  {
    reader->Update();
  }
  catch (const std::bad_alloc&)
  {
    // A header that promises more than memory holds, past the checks made before reading.
    capture->Captured += "the file announces more data than memory can hold";
  }
  vtkOutputWindow::SetInstance(previous);
  messages.Errors += capture->Captured;
  vtkPolyData* out = reader->GetOutput();
  if (!messages.Errors.empty() || reader->GetErrorCode() != 0)
  {
    std::string why = messages.Errors.empty() ? std::string("the file is not valid") : messages.Errors;
    while (!why.empty() && why.back() == '\n')
    {
      why.pop_back();
    }
    const std::string named = "'" + path + "'"; // SubD's readers name the file themselves
    error = "cannot read " + (why.compare(0, named.size(), named) == 0 ? why : named + ": " + why);
    return nullptr;
  }
  if (!out || out->GetNumberOfPoints() == 0)
  {
    error = "'" + path + "' holds no points (empty or not a valid file of its type)";
    return nullptr;
  }
  vtkSmartPointer<vtkPolyData> mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(out);
  return mesh;
}
}

std::string LowerExtension(const std::string& path)
{
  const auto dot = path.find_last_of('.');
  const auto slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
  {
    return "";
  }
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

const char* SupportedExtensions()
{
  return ".vtp .vtk .obj .ply .stl .off .gltf .glb";
}

const char* WritableExtensions()
{
  return ".vtp .vtk .obj .ply .stl .off .gltf";
}

bool CanWrite(const std::string& path)
{
  const std::string ext = LowerExtension(path);
  const std::string known = std::string(WritableExtensions()) + " ";
  return !ext.empty() && known.find(ext + " ") != std::string::npos;
}

vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path, std::string& error)
{
  if (!FileReadable(path))
  {
    error = "cannot open '" + path + "' for reading";
    return nullptr;
  }
  const std::string ext = LowerExtension(path);
  if (ext == ".vtp")
  {
    return CheckXMLPolyDataFile(path, error) ? RunReader<vtkXMLPolyDataReader>(path, error) : nullptr;
  }
  if (ext == ".vtk")
  {
    return RunReader<vtkSubDLegacyReader>(path, error);
  }
  if (ext == ".obj")
  {
    return RunReader<vtkSubDOBJReader>(path, error);
  }
  if (ext == ".ply")
  {
    return RunReader<vtkSubDPLYReader>(path, error);
  }
  if (ext == ".stl")
  {
    return CheckSTLFile(path, error) ? RunReader<vtkSTLReader>(path, error) : nullptr;
  }
  if (ext == ".off")
  {
    return RunReader<vtkSubDOFFReader>(path, error);
  }
  if (ext == ".gltf" || ext == ".glb")
  {
    return RunReader<vtkSubDGLTFReader>(path, error);
  }
  error = "'" + path + "': unknown file type '" + ext + "' (supported: " + SupportedExtensions() + ")";
  return nullptr;
}

namespace
{
template <typename Writer>
vtkSmartPointer<vtkAlgorithm> NewWriter(const std::string& fileName)
{
  auto writer = vtkSmartPointer<Writer>::New();
  writer->SetFileName(fileName.c_str());
  return writer;
}

// A writer for the extension, writing to fileName; nullptr for an unknown extension.
vtkSmartPointer<vtkAlgorithm> MakeWriter(const std::string& ext, const std::string& fileName, bool compress)
{
  if (ext == ".vtp")
  {
    // Appended raw arrays: VTK's default (inline base64 of zlib blocks) took 40 s for a
    // 10-million-quad mesh that this writes in about a second.
    auto writer = NewWriter<vtkXMLPolyDataWriter>(fileName);
    auto* xml = vtkXMLPolyDataWriter::SafeDownCast(writer);
    xml->SetDataModeToAppended();
    xml->EncodeAppendedDataOff();
    if (compress)
    {
      xml->SetCompressorTypeToZLib();
    }
    else
    {
      xml->SetCompressorTypeToNone();
    }
    return writer;
  }
  if (ext == ".vtk")
  {
    auto writer = NewWriter<vtkPolyDataWriter>(fileName);
    vtkPolyDataWriter::SafeDownCast(writer)->SetFileTypeToBinary();
    return writer;
  }
  if (ext == ".obj")
  {
    return NewWriter<vtkSubDOBJWriter>(fileName);
  }
  if (ext == ".ply")
  {
    return NewWriter<vtkSubDPLYWriter>(fileName); // double points stay double
  }
  if (ext == ".stl")
  {
    auto writer = NewWriter<vtkSTLWriter>(fileName);
    vtkSTLWriter::SafeDownCast(writer)->SetFileTypeToBinary();
    return writer;
  }
  if (ext == ".off")
  {
    return NewWriter<vtkSubDOFFWriter>(fileName);
  }
  if (ext == ".gltf")
  {
    return NewWriter<vtkSubDGLTFWriter>(fileName);
  }
  return nullptr;
}
}

bool WriteMesh(vtkPolyData* mesh, const std::string& path, std::string& error, bool compress)
{
  const std::string ext = LowerExtension(path);
  // The marker goes before the extension: some writers (PLY) append theirs otherwise.
  const std::string temporary =
    path.substr(0, path.size() - ext.size()) + ".tmp-" + std::to_string(::getpid()) + ext;
  vtkSmartPointer<vtkAlgorithm> writer = MakeWriter(ext, temporary, compress);
  if (!writer)
  {
    error = "'" + path + "': unknown output type '" + ext + "' (supported: " + WritableExtensions() + ")";
    return false;
  }
  vtkSmartPointer<vtkPolyData> data = mesh;
  if (ext == ".stl")
  {
    // STL stores triangles only.
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputData(mesh);
    triangles->Update();
    data = triangles->GetOutput();
  }
  MessageCollector messages;
  messages.Watch(writer);
  writer->SetInputDataObject(data);
  // vtkWriter and vtkXMLWriter share no base class that declares Write().
  if (auto* legacy = vtkWriter::SafeDownCast(writer))
  {
    legacy->Write();
  }
  else if (auto* xml = vtkXMLWriter::SafeDownCast(writer))
  {
    xml->Write();
  }
  if (writer->GetErrorCode() != 0 || !messages.Errors.empty() || !FileReadable(temporary))
  {
    std::remove(temporary.c_str());
    error = "cannot write '" + path + "'" + (messages.Errors.empty() ? "" : ": " + messages.Errors);
    return false;
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0)
  {
    std::remove(temporary.c_str());
    error = "cannot move the finished output to '" + path + "'";
    return false;
  }
  return true;
}
}
