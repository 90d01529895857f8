// Reports progress through the pipeline's stages: Slicer's <filter-...> tags on stdout, and a
// progress bar for people at a terminal.
#ifndef ProgressReporter_h
#define ProgressReporter_h

#include <chrono>
#include <ostream>
#include <string>
#include <vector>

namespace slicemesh::cli
{

struct ProgressStage
{
  std::string name;    ///< <filter-name>, e.g. "Tiling"
  std::string comment; ///< <filter-comment>, what the stage does
  double weight = 1.0; ///< share of the whole run, relative to the other stages
};

class ProgressReporter
{
public:
  /** tags: where Slicer's tags go (null: none). bar: where a one-line text bar goes (null: none). */
  ProgressReporter(std::vector<ProgressStage> stages, std::ostream* tags, std::ostream* bar);

  /** Begins stage number stage (in the order given), ending the current one if still open. */
  void start(std::size_t stage);
  /** Fraction 0..1 of the current stage. Overall progress never goes backwards. */
  void update(double fraction);
  /** Ends the current stage with its time; overall progress reaches the stage's end. */
  void end();
  /** Call once when the run stops: ends an open stage (reaching its end only if succeeded, so a
   *  failed stage is not shown as done) and finishes the bar's line. */
  void finish(bool succeeded);

  double overall() const { return this->Overall; }

private:
  void emitProgress(double stageFraction, bool force);
  void emitEnd();

  std::vector<ProgressStage> Stages;
  std::vector<double> StageStart; ///< overall fraction where each stage starts
  double TotalWeight = 0.0;
  std::ostream* Tags;
  std::ostream* Bar;
  std::size_t Current = 0;
  bool Open = false;
  double Overall = 0.0;
  double LastEmitted = -1.0;
  std::chrono::steady_clock::time_point StageBegan;
};

} // namespace slicemesh::cli

#endif
