// Compares a candidate PNG with a baseline PNG (vtkImageDifference's thresholded error, which
// tolerates one-pixel shifts), for programs that save their own pictures (the explorer).
//
//   CompareImages BASELINE CANDIDATE THRESHOLD
//
// A candidate of another size is resampled to the baseline's first (window decorations and
// font metrics may change the view area by a few pixels). With SUBD_REGENERATE_BASELINES set,
// the candidate replaces the baseline. Exit status 0 when the error is within the threshold.
#include "vtkImageData.h"
#include "vtkImageDifference.h"
#include "vtkImageExtractComponents.h"
#include "vtkImageResize.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkPNGWriter.h"

#include <cstdlib>
#include <fstream>
#include <iostream>

int main(int argc, char* argv[])
{
  if (argc != 4)
  {
    std::cerr << "usage: CompareImages BASELINE CANDIDATE THRESHOLD\n";
    return 2;
  }
  const char* baselinePath = argv[1];
  const char* candidatePath = argv[2];
  const double threshold = std::atof(argv[3]);
  if (std::getenv("SUBD_REGENERATE_BASELINES"))
  {
    std::ifstream in(candidatePath, std::ios::binary);
    std::ofstream out(baselinePath, std::ios::binary);
    out << in.rdbuf();
    std::cout << "baseline " << baselinePath << " regenerated\n";
    return in && out ? 0 : 1;
  }
  vtkNew<vtkPNGReader> baseline, candidate;
  for (auto* reader : { baseline.GetPointer(), candidate.GetPointer() })
  {
    const char* path = reader == baseline.GetPointer() ? baselinePath : candidatePath;
    if (!reader->CanReadFile(path))
    {
      std::cerr << "cannot read the PNG image '" << path << "'\n";
      return 1;
    }
    reader->SetFileName(path);
    reader->Update();
  }
  int baseSize[3], candidateSize[3];
  baseline->GetOutput()->GetDimensions(baseSize);
  candidate->GetOutput()->GetDimensions(candidateSize);
  // vtkImageDifference compares RGB: drop an alpha channel (Qt saves ARGB).
  vtkNew<vtkImageExtractComponents> baseRGB, candidateRGB;
  baseRGB->SetInputConnection(baseline->GetOutputPort());
  candidateRGB->SetInputConnection(candidate->GetOutputPort());
  for (auto* rgb : { baseRGB.GetPointer(), candidateRGB.GetPointer() })
  {
    rgb->SetComponents(0, 1, 2);
  }
  vtkNew<vtkImageResize> resize;
  resize->SetInputConnection(candidateRGB->GetOutputPort());
  resize->SetOutputDimensions(baseSize[0], baseSize[1], 1);
  vtkNew<vtkImageDifference> difference;
  difference->SetInputConnection(resize->GetOutputPort());
  difference->SetImageConnection(baseRGB->GetOutputPort());
  difference->Update();
  const double error = difference->GetThresholdedError();
  std::cout << "candidate " << candidateSize[0] << "x" << candidateSize[1] << ", baseline " << baseSize[0] << "x"
            << baseSize[1] << ": error " << error << " (threshold " << threshold << ")\n";
  if (error > threshold)
  {
    const std::string diffPath = std::string(candidatePath) + ".diff.png";
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputConnection(difference->GetOutputPort());
    writer->SetFileName(diffPath.c_str());
    writer->Write();
    std::cerr << "images differ; the difference image is " << diffPath << "\n";
    return 1;
  }
  return 0;
}
