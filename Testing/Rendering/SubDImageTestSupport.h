// Image regression tests: compare a rendered window with a baseline PNG under
// Testing/Data/Baseline (vtkTesting's image difference), or regenerate the baseline.
//
// The threshold is vtkTesting's image error (vtkImageDifference, which tolerates one-pixel
// shifts): 0 for identical images, about 0.3 between a Loop cube at levels 1 and 3.
// Regenerate every baseline:   SUBD_REGENERATE_BASELINES=1 ctest --test-dir build -R Image
// A mismatch (or a missing baseline) leaves the candidate image and the difference image in
// SUBD_IMAGE_TEMP_DIR (build/Testing/Temporary); the failure message names both.
#ifndef SubDImageTestSupport_h
#define SubDImageTestSupport_h

#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkRenderWindow.h"
#include "vtkTesting.h"
#include "vtkWindowToImageFilter.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>
#include <string>

namespace subdtest
{
// The images are the same with or without an X server; make sure none is used.
inline bool UnsetDisplay()
{
  ::unsetenv("DISPLAY");
  return true;
}
static const bool DisplayUnset = UnsetDisplay();

inline void CompareWithBaseline(vtkRenderWindow* window, const std::string& name, double threshold = 0.1)
{
  const std::string baseline = std::string(SUBD_BASELINE_DIR) + "/" + name + ".png";
  if (std::getenv("SUBD_REGENERATE_BASELINES"))
  {
    vtkNew<vtkWindowToImageFilter> capture;
    capture->SetInput(window);
    capture->ReadFrontBufferOff();
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputConnection(capture->GetOutputPort());
    writer->SetFileName(baseline.c_str());
    writer->Write();
    ASSERT_EQ(writer->GetErrorCode(), 0u) << "cannot write " << baseline;
    return;
  }
  vtkNew<vtkTesting> testing;
  for (const std::string& argument : { std::string("-V"), baseline, std::string("-T"), std::string(SUBD_IMAGE_TEMP_DIR) })
  {
    testing->AddArgument(argument.c_str());
  }
  testing->SetRenderWindow(window);
  std::ostringstream log;
  const int result = testing->RegressionTest(threshold, log);
  EXPECT_EQ(result, vtkTesting::PASSED)
    << "image " << name << " differs from " << baseline << " (threshold " << threshold
    << "); candidate and difference images: " << SUBD_IMAGE_TEMP_DIR << "/" << name << ".png, "
    << SUBD_IMAGE_TEMP_DIR << "/" << name << ".diff.png\n"
    << log.str();
}
}

#endif
