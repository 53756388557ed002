#include "SubDUpdateJob.h"

#include "SubDMessageCollector.h"

#include "vtkPolyData.h"

#include <chrono>

namespace subdexplorer
{
UpdateJob::UpdateJob(vtkPolyData* cage, std::vector<ViewTask> tasks)
  : Tasks(std::move(tasks))
{
  this->Cage = vtkSmartPointer<vtkPolyData>::New();
  this->Cage->DeepCopy(cage);
  this->Results.resize(this->Tasks.size());
}

UpdateJob::~UpdateJob()
{
  this->Cancel();
  this->Wait();
}

void UpdateJob::Start(std::function<void()> finished)
{
  this->Finished = std::move(finished);
  this->Worker = std::thread([this]() { this->Run(); });
}

void UpdateJob::Wait()
{
  if (this->Worker.joinable())
  {
    this->Worker.join();
  }
}

void UpdateJob::Run()
{
  const double count = static_cast<double>(this->Tasks.size());
  for (size_t v = 0; v < this->Tasks.size() && !this->CancelRequested; ++v)
  {
    if (!this->Tasks[v].Entry)
    {
      continue;
    }
    ViewResult& result = this->Results[v];
    subdapp::MessageCollector messages;
    const auto start = std::chrono::steady_clock::now();
    result.Surface = subdapp::RunScheme(*this->Tasks[v].Entry, this->Tasks[v].Options, this->Cage, messages,
      [this, v, count](double fraction) {
        this->Progress = (static_cast<double>(v) + fraction) / count;
        return !this->CancelRequested;
      });
    result.Milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    result.Errors = messages.Errors;
    result.Warnings = messages.Warnings;
  }
  this->Progress = 1.0;
  if (this->Finished)
  {
    this->Finished();
  }
}
}
