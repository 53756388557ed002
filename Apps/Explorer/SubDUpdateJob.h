// SubD Explorer: one update of the views, run on a worker thread so that the GUI never
// freezes. The job owns a copy of the cage (the GUI keeps drawing its own), runs each
// view's filter through the scheme registry, and exposes its progress and a cancel flag as
// atomics; cancelling aborts the running filter at its next progress report (VTK's
// AbortExecute) and skips the remaining views.
#ifndef SubDUpdateJob_h
#define SubDUpdateJob_h

#include "SubDSchemeRegistry.h"

#include "vtkSmartPointer.h"

#include <atomic>
#include <functional>
#include <string>
#include <thread>
#include <vector>

class vtkPolyData;

namespace subdexplorer
{
class UpdateJob
{
public:
  struct ViewTask
  {
    const subdapp::SchemeEntry* Entry = nullptr; ///< null: the view keeps its result (skipped)
    subdapp::SchemeOptions Options;
  };
  struct ViewResult
  {
    vtkSmartPointer<vtkPolyData> Surface; ///< null on an error or when cancelled
    std::string Errors, Warnings;
    double Milliseconds = 0.0;
  };

  /// Copies `cage` (deeply: the worker never reads what the GUI draws).
  UpdateJob(vtkPolyData* cage, std::vector<ViewTask> tasks);
  /// Cancels and waits for the worker.
  ~UpdateJob();
  UpdateJob(const UpdateJob&) = delete;
  UpdateJob& operator=(const UpdateJob&) = delete;

  /// Starts the worker; `finished` is called on the worker thread when it is done.
  void Start(std::function<void()> finished);
  /// Waits for the worker (after `finished`, this returns at once).
  void Wait();
  void Cancel() { this->CancelRequested = true; }
  bool IsCancelled() const { return this->CancelRequested; }
  /// In [0, 1] over all views.
  double GetProgress() const { return this->Progress; }
  const std::vector<ViewTask>& GetTasks() const { return this->Tasks; }
  /// One per task; complete once `finished` was called.
  const std::vector<ViewResult>& GetResults() const { return this->Results; }

private:
  void Run();

  vtkSmartPointer<vtkPolyData> Cage;
  std::vector<ViewTask> Tasks;
  std::vector<ViewResult> Results;
  std::atomic<bool> CancelRequested{ false };
  std::atomic<double> Progress{ 0.0 };
  std::function<void()> Finished;
  std::thread Worker;
};
}

#endif
