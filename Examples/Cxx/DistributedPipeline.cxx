// Example: Loop subdivision of a mesh split over MPI ranks, in C++ with VTK's pieces.
// Every rank makes the same sphere; vtkExtractPolyDataPiece keeps the rank's share of its
// triangles plus the layers of ghost triangles that the SubD filter asks for (its
// RequestUpdateExtent passes GetRequiredGhostLevels() upstream); the filter outputs only the
// children of the rank's own triangles, so the pieces together are the serial result. Each
// rank writes its piece; rank 0 writes the .pvtp that names them, and checks that the ranks'
// faces add up to the serial count. Given a third name, rank 0 also writes the serial result
// there, to compare (the test does, with Testing/Parallel/ComparePieceFiles).
//
//   mpirun -np 4 DistributedPipeline [output.pvtp] [levels] [serial.vtp]
#include "vtkSubDLoopFilter.h"

#include "vtkExtractPolyDataPiece.h"
#include "vtkMPIController.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"
#include "vtkXMLPPolyDataWriter.h"
#include "vtkXMLPolyDataWriter.h"

#include <cstdlib>
#include <iostream>

int main(int argc, char* argv[])
{
  vtkNew<vtkMPIController> controller;
  controller->Initialize(&argc, &argv);
  vtkMultiProcessController::SetGlobalController(controller);
  const int rank = controller->GetLocalProcessId();
  const int ranks = controller->GetNumberOfProcesses();
  const char* output = argc > 1 ? argv[1] : "sphere-loop.pvtp";
  const int levels = argc > 2 ? std::atoi(argv[2]) : 3;

  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(24);
  sphere->SetPhiResolution(16);
  vtkNew<vtkExtractPolyDataPiece> piece; // asks for the whole sphere, keeps one piece
  piece->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkSubDLoopFilter> loop;
  loop->SetInputConnection(piece->GetOutputPort());
  loop->SetNumberOfSubdivisions(levels);

  // The writer asks for piece `rank` of `ranks`; the request travels up the pipeline.
  vtkNew<vtkXMLPPolyDataWriter> writer;
  writer->SetInputConnection(loop->GetOutputPort());
  writer->SetController(controller);
  writer->SetFileName(output);
  writer->SetNumberOfPieces(ranks);
  writer->SetStartPiece(rank);
  writer->SetEndPiece(rank);
  writer->SetDataModeToBinary();
  const int written = writer->Write();

  // Loop makes 4 triangles of each triangle per level: the pieces must add up to that.
  long long faces = loop->GetOutput()->GetNumberOfPolys(), total = 0;
  controller->Reduce(&faces, &total, 1, vtkCommunicator::SUM_OP, 0);
  int status = written ? EXIT_SUCCESS : EXIT_FAILURE;
  if (rank == 0)
  {
    sphere->Update();
    long long expected = sphere->GetOutput()->GetNumberOfPolys();
    for (int level = 0; level < levels; ++level)
      expected *= 4;
    std::cout << ranks << " ranks, " << levels << " levels: " << total << " triangles (serially " << expected
              << "), written to " << output << "\n";
    if (total != expected)
      status = EXIT_FAILURE;
    if (argc > 3)
    {
      vtkNew<vtkSubDLoopFilter> serial;
      serial->SetInputConnection(sphere->GetOutputPort());
      serial->SetNumberOfSubdivisions(levels);
      vtkNew<vtkXMLPolyDataWriter> serialWriter;
      serialWriter->SetInputConnection(serial->GetOutputPort());
      serialWriter->SetFileName(argv[3]);
      if (!serialWriter->Write())
        status = EXIT_FAILURE;
    }
  }
  controller->Broadcast(&status, 1, 0);
  controller->Finalize();
  return status;
}
