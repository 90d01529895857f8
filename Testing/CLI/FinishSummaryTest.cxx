// The finishing part of the summary line says what each piece got, not only the least finished one.
#include "QualityReport.h"

#include <gtest/gtest.h>

namespace slicemesh::cli
{
namespace
{

RunQuality remeshedAsked()
{
  RunQuality q;
  q.requestedFinish = "Remeshed";
  q.finish = "Remeshed";
  q.targetEdgeLength = 1.1;
  return q;
}

TEST(FinishSummary, EveryPieceAsAsked)
{
  RunQuality q = remeshedAsked();
  q.piecesByFinish = { 2149, 0, 0 };
  EXPECT_EQ(finishSummary(q), "finish Remeshed (target edge 1.10 mm)");
}

TEST(FinishSummary, AFewPiecesLessThanAskedAreCountedNotTheWholeSurface)
{
  RunQuality q = remeshedAsked();
  q.finish = "Tiled"; // the least finished piece
  q.fallback = "3 of 2149 pieces were finished less than asked";
  q.piecesByFinish = { 2146, 2, 1 };
  EXPECT_EQ(finishSummary(q), "finish Remeshed (target edge 1.10 mm; 3 of 2149 pieces 2 smoothed only, 1 left as tiled, "
                              "see the warning)");
  // Specks are left as tiled by design: counted apart, not as pieces that got less.
  q.smallPiecesAsTiled = 40;
  q.piecesByFinish = { 2106, 2, 41 };
  EXPECT_EQ(finishSummary(q), "finish Remeshed (target edge 1.10 mm; 3 of 2149 pieces 2 smoothed only, 1 left as tiled, "
                              "see the warning; 40 specks kept as tiled)");
  q.fallback.clear();
  q.finish = "Remeshed";
  q.piecesByFinish = { 2109, 0, 40 };
  EXPECT_EQ(finishSummary(q), "finish Remeshed (target edge 1.10 mm; 40 specks kept as tiled)");
}

TEST(FinishSummary, NothingAsAskedNamesWhatWasApplied)
{
  RunQuality q = remeshedAsked();
  q.finish = "Tiled";
  q.fallback = "the tiling is not a valid surface, so it is not finished";
  EXPECT_EQ(finishSummary(q), "finish Tiled (Remeshed asked; see the warning)");
  q.piecesByFinish = { 0, 0, 5 };
  EXPECT_EQ(finishSummary(q), "finish Tiled (Remeshed asked; see the warning)");
}

TEST(FinishSummary, SmoothedAskedHasNoEdgeLength)
{
  RunQuality q;
  q.requestedFinish = q.finish = "Smoothed";
  q.piecesByFinish = { 0, 7, 0 };
  EXPECT_EQ(finishSummary(q), "finish Smoothed");
}

} // namespace
} // namespace slicemesh::cli
