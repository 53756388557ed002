/**
 * @class   vtkSubDInterpolationAlgorithm
 * @brief   what SubD's interpolation filters share: tagged points, solver, tolerance, report
 *
 * The base of vtkSubDInterpolateFilter (surfaces) and vtkSubDCurveInterpolateFilter (curves).
 * Both solve a square sparse system whose rows are the limit masks of the tagged points and
 * identity rows for the others (SubDInterpolation.h). Here: which points are tagged
 * (InterpolationArrayName), the linear solver (Solver), the accepted residual (Tolerance),
 * and after an update the solve's residual, condition estimate and number of tagged points.
 * A failed solve is an error naming the cause, with an empty output. The solve couples all
 * points, so in a distributed pipeline the filter asks for the whole mesh and outputs it as
 * piece 0 (the other pieces are empty).
 *
 * @sa vtkSubDInterpolateFilter vtkSubDCurveInterpolateFilter
 */
#ifndef vtkSubDInterpolationAlgorithm_h
#define vtkSubDInterpolationAlgorithm_h

#include "SubDFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <string> // for Fail
#include <vector> // for Solve

namespace subd
{
struct SparseRow;
}

class SUBDFILTERS_EXPORT vtkSubDInterpolationAlgorithm : public vtkPolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkSubDInterpolationAlgorithm, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The point-data array that tags the points to interpolate (non-zero: tagged; default
  /// "Interpolate"). Without such an array every point is tagged.
  vtkSetStringMacro(InterpolationArrayName);
  vtkGetStringMacro(InterpolationArrayName);
  ///@}

  enum Solvers
  {
    SOLVER_AUTOMATIC = 0, ///< direct up to 20000 points, iterative above
    SOLVER_DIRECT = 1,    ///< Eigen's SparseLU (COLAMD ordering)
    SOLVER_ITERATIVE = 2  ///< Eigen's BiCGSTAB with a diagonal preconditioner
  };
  ///@{
  /// The linear solver (default SOLVER_AUTOMATIC; SubDInterpolation.h explains the choice).
  vtkSetClampMacro(Solver, int, SOLVER_AUTOMATIC, SOLVER_ITERATIVE);
  vtkGetMacro(Solver, int);
  ///@}

  ///@{
  /// Largest residual accepted, relative to the targets' extent (max |coordinate|, at least
  /// 1); default 1e-9, 0..1.
  vtkSetClampMacro(Tolerance, double, 0.0, 1.0);
  vtkGetMacro(Tolerance, double);
  ///@}

  /// After an update: the residual max |M x - t| of the last solve, a lower bound of the
  /// system's condition number (above 1e10 the solve is refused as singular), and the number
  /// of tagged points (those whose limit point was prescribed).
  vtkGetMacro(Residual, double);
  vtkGetMacro(ConditionEstimate, double);
  vtkGetMacro(NumberOfTaggedPoints, vtkIdType);

protected:
  vtkSubDInterpolationAlgorithm();
  ~vtkSubDInterpolationAlgorithm() override;

  /// The solve couples every point: asked for one piece of several, the filter asks upstream
  /// for the whole mesh; piece 0 gets the whole result, the other pieces are empty.
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// Clears the report and runs Execute, turning running out of memory into an error.
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  virtual int Execute(vtkInformation*, vtkInformationVector**, vtkInformationVector*) = 0;

  /// Reports `why` as an error (a sentence), empties `output`; returns 0.
  int Fail(vtkPolyData* output, const std::string& why);

  /// Solves for the points (3 coordinates each) and fills the report; false with the reason.
  bool Solve(const std::vector<subd::SparseRow>& rows, const std::vector<char>& tagged,
    const std::vector<double>& targets, std::vector<double>& points, std::string& error);

  char* InterpolationArrayName = nullptr;
  int Solver = SOLVER_AUTOMATIC;
  double Tolerance = 1e-9;
  double Residual = 0.0;
  double ConditionEstimate = 0.0;
  vtkIdType NumberOfTaggedPoints = 0;

private:
  vtkSubDInterpolationAlgorithm(const vtkSubDInterpolationAlgorithm&) = delete;
  void operator=(const vtkSubDInterpolationAlgorithm&) = delete;
};

#endif
