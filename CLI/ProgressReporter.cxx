// Slicer reads the CLI's stdout every 0.1 s and takes the most recent tag (SLICER_CLI.md 2.5), so
// every tag is flushed at once and progress is only ever reported upwards.
#include "ProgressReporter.h"

#include <algorithm>
#include <iomanip>
#include <numeric>

namespace slicemesh::cli
{

namespace
{
/** Updates finer than this are not printed: Slicer's bar has 100 steps, the text bar 40. */
constexpr double minimumStep = 0.005;
} // namespace

ProgressReporter::ProgressReporter(std::vector<ProgressStage> stages, std::ostream* tags, std::ostream* bar)
  : Stages(std::move(stages))
  , Tags(tags)
  , Bar(bar)
{
  for (const ProgressStage& stage : this->Stages)
  {
    this->StageStart.push_back(this->TotalWeight);
    this->TotalWeight += stage.weight;
  }
  for (double& start : this->StageStart)
  {
    start /= this->TotalWeight;
  }
}

void ProgressReporter::start(std::size_t stage)
{
  if (this->Open)
  {
    this->end();
  }
  this->Current = std::min(stage, this->Stages.size() - 1);
  this->Open = true;
  this->StageBegan = std::chrono::steady_clock::now();
  const ProgressStage& s = this->Stages[this->Current];
  if (this->Tags)
  {
    *this->Tags << "<filter-start>\n"
                << "<filter-name>" << s.name << "</filter-name>\n"
                << "<filter-comment> \"" << s.comment << "\" </filter-comment>\n"
                << "</filter-start>\n"
                << std::flush;
  }
  this->emitProgress(0.0, true);
}

void ProgressReporter::update(double fraction)
{
  if (this->Open)
  {
    this->emitProgress(std::clamp(fraction, 0.0, 1.0), false);
  }
}

void ProgressReporter::end()
{
  if (this->Open)
  {
    this->emitProgress(1.0, true);
    this->emitEnd();
  }
}

void ProgressReporter::finish(bool succeeded)
{
  if (this->Open)
  {
    if (succeeded)
    {
      this->emitProgress(1.0, true);
    }
    this->emitEnd();
  }
  if (this->Bar)
  {
    *this->Bar << "\n" << std::flush;
    this->Bar = nullptr;
  }
}

void ProgressReporter::emitEnd()
{
  this->Open = false;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - this->StageBegan).count();
  if (this->Tags)
  {
    *this->Tags << "<filter-end>\n"
                << "<filter-name>" << this->Stages[this->Current].name << "</filter-name>\n"
                << "<filter-time>" << std::fixed << std::setprecision(3) << seconds << std::defaultfloat
                << "</filter-time>\n"
                << "</filter-end>\n"
                << std::flush;
  }
}

void ProgressReporter::emitProgress(double stageFraction, bool force)
{
  const double weight = this->Stages[this->Current].weight / this->TotalWeight;
  const double overall = std::max(this->Overall, this->StageStart[this->Current] + stageFraction * weight);
  this->Overall = std::min(overall, 1.0);
  if (!force && this->Overall - this->LastEmitted < minimumStep)
  {
    return;
  }
  this->LastEmitted = this->Overall;
  if (this->Tags)
  {
    *this->Tags << std::setprecision(4) << "<filter-progress>" << this->Overall << "</filter-progress>\n"
                << "<filter-stage-progress>" << stageFraction << "</filter-stage-progress>\n"
                << std::defaultfloat << std::setprecision(6) << std::flush;
  }
  if (this->Bar)
  {
    constexpr int width = 40;
    const int filled = static_cast<int>(this->Overall * width + 0.5);
    *this->Bar << "\r[" << std::string(filled, '#') << std::string(width - filled, '.') << "] " << std::setw(3)
               << static_cast<int>(this->Overall * 100 + 0.5) << "% " << std::left << std::setw(14)
               << this->Stages[this->Current].name << std::right << std::flush;
  }
}

} // namespace slicemesh::cli
