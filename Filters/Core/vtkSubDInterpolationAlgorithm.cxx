#include "vtkSubDInterpolationAlgorithm.h"

#include "SubDInterpolation.h"
#include "vtkSubDInterpolationSupport.h"
#include "vtkSubDOutOfMemory.h"
#include "vtkSubDPieces.h"

#include "vtkErrorCode.h"
#include "vtkInformationVector.h"
#include "vtkPolyData.h"

vtkSubDInterpolationAlgorithm::vtkSubDInterpolationAlgorithm()
{
  this->SetInterpolationArrayName("Interpolate");
}

vtkSubDInterpolationAlgorithm::~vtkSubDInterpolationAlgorithm()
{
  this->SetInterpolationArrayName(nullptr);
}

int vtkSubDInterpolationAlgorithm::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  vtkSubDRequestWholeInput(inputVector, this->GetNumberOfInputPorts());
  return 1;
}

int vtkSubDInterpolationAlgorithm::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();
  this->SetErrorCode(vtkErrorCode::NoError);
  this->Residual = 0.0;
  this->ConditionEstimate = 0.0;
  this->NumberOfTaggedPoints = 0;
  if (vtkSubDPieceRequest(outputVector->GetInformationObject(0)).IsLaterPiece())
  {
    return 1; // piece 0 holds the whole result
  }
  return vtkSubDRunCatchingOutOfMemory(
    this, output, [&]() { return this->Execute(request, inputVector, outputVector); },
    [this](unsigned long code) { this->SetErrorCode(code); });
}

int vtkSubDInterpolationAlgorithm::Fail(vtkPolyData* output, const std::string& why)
{
  vtkErrorMacro(<< vtkSubDSentence(why));
  output->Initialize();
  this->SetErrorCode(vtkErrorCode::UserError);
  return 0;
}

bool vtkSubDInterpolationAlgorithm::Solve(const std::vector<subd::SparseRow>& rows, const std::vector<char>& tagged,
  const std::vector<double>& targets, std::vector<double>& points, std::string& error)
{
  subd::InterpolationReport report;
  const bool solved = subd::SolveInterpolation(
    rows, tagged, targets, this->Tolerance, static_cast<subd::InterpolationSolver>(this->Solver), points, report, error);
  this->Residual = report.Residual;
  this->ConditionEstimate = report.Condition;
  this->NumberOfTaggedPoints = solved ? report.NumTagged : 0;
  return solved;
}

void vtkSubDInterpolationAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "InterpolationArrayName: "
     << (this->InterpolationArrayName ? this->InterpolationArrayName : "(none)") << "\n";
  os << indent << "Solver: " << this->Solver << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "Residual: " << this->Residual << "\n";
  os << indent << "ConditionEstimate: " << this->ConditionEstimate << "\n";
  os << indent << "NumberOfTaggedPoints: " << this->NumberOfTaggedPoints << "\n";
}
