// Per-slice contours of a binary mask by marching squares (ITK's ContourExtractor2DImageFilter).
#include "ContourExtraction.h"

#include "SliceSmoothing.h"

#include "Core/ParallelFor.h"

#include "itkContourExtractor2DImageFilter.h"

#include <algorithm>
#include <atomic>
#include <sstream>

namespace slicemesh
{
namespace
{

using SliceImage = itk::Image<float, 2>;
using ContourFilter = itk::ContourExtractor2DImageFilter<SliceImage>;

/** The index box of the foreground of one slice; empty when the slice has no foreground. */
struct ForegroundBox
{
  long iMin = 0, iMax = -1, jMin = 0, jMax = -1;
  bool empty() const { return iMax < iMin; }
};

ForegroundBox foregroundBoxOf(const unsigned char* slice, long width, long height)
{
  ForegroundBox box;
  box.iMin = width;
  box.jMin = height;
  for (long j = 0; j < height; ++j)
  {
    const unsigned char* row = slice + j * width;
    const unsigned char* first = std::find_if(row, row + width, [](unsigned char v) { return v != 0; });
    if (first == row + width)
      continue;
    const unsigned char* last = row + width - 1;
    while (*last == 0)
      --last;
    box.iMin = std::min(box.iMin, static_cast<long>(first - row));
    box.iMax = std::max(box.iMax, static_cast<long>(last - row));
    box.jMin = std::min(box.jMin, j);
    box.jMax = j;
  }
  return box;
}

/** Extracts the contours of one slice. The slice's foreground box is copied into a float image
 *  with one voxel of zeros on every side, so that contours touching the image border close. The
 *  copy's region starts at index (iMin - 1, jMin - 1): the filter's continuous indices are then
 *  directly the slice's own (i, j), with no offset to undo. */
class SliceContourExtractor
{
public:
  SliceContourExtractor(double spacingX, double spacingY, double sigma = 0.0)
    : m_SpacingX(spacingX)
    , m_SpacingY(spacingY)
    , m_Sigma(sigma)
    , m_PadX(1 + gaussianRadius(sigma, spacingX))
    , m_PadY(1 + gaussianRadius(sigma, spacingY))
    , m_Image(SliceImage::New())
  {}

  std::vector<Polygon2> extract(const unsigned char* slice, long width, long height)
  {
    const ForegroundBox box = foregroundBoxOf(slice, width, height);
    if (box.empty())
      return {};

    // The padding ring is wider than one voxel when smoothing spreads the mask beyond its box.
    SliceImage::IndexType start = { { box.iMin - m_PadX, box.jMin - m_PadY } };
    SliceImage::SizeType size = { { static_cast<itk::SizeValueType>(box.iMax - box.iMin + 1 + 2 * m_PadX),
                                     static_cast<itk::SizeValueType>(box.jMax - box.jMin + 1 + 2 * m_PadY) } };
    m_Image->SetRegions(SliceImage::RegionType(start, size));
    m_Image->Allocate();
    // Zero the padding ring explicitly: Allocate(true) does not clear a reused, larger buffer.
    const long paddedWidth = static_cast<long>(size[0]);
    float* out = m_Image->GetBufferPointer();
    std::fill(out, out + size[0] * size[1], 0.0f);
    for (long j = box.jMin; j <= box.jMax; ++j)
    {
      const unsigned char* row = slice + j * width;
      float* outRow = out + (j - box.jMin + m_PadY) * paddedWidth + m_PadX;
      for (long i = box.iMin; i <= box.iMax; ++i)
        outRow[i - box.iMin] = row[i] ? 1.0f : 0.0f;
    }
    smoothSlice(out, paddedWidth, static_cast<long>(size[1]), m_SpacingX, m_SpacingY, m_Sigma);
    m_Image->Modified();

    // A fresh filter per slice (cheap next to the tracing): no pipeline state carries over.
    auto filter = ContourFilter::New();
    filter->SetContourValue(0.5);
    // Face (4-) connectivity of the foreground: at a saddle (two foreground voxels touching only
    // at a corner) the background stays connected and the two voxels get separate contours.
    // This is ITK's default; set explicitly because Logic relies on contours never touching.
    filter->VertexConnectHighPixelsOff();
    filter->ReverseContourOrientationOff();
    filter->SetInput(m_Image);
    filter->Update();

    std::vector<Polygon2> contours;
    contours.reserve(filter->GetNumberOfIndexedOutputs());
    for (unsigned int n = 0; n < filter->GetNumberOfIndexedOutputs(); ++n)
    {
      const auto* vertices = filter->GetOutput(n)->GetVertexList();
      Polygon2 polygon;
      polygon.reserve(vertices->Size());
      for (unsigned int v = 0; v < vertices->Size(); ++v)
      {
        const auto& index = vertices->ElementAt(v);
        polygon.push_back({ index[0] * m_SpacingX, index[1] * m_SpacingY });
      }
      // ITK closes a path by repeating its first vertex; Polygon2 closes implicitly.
      if (polygon.size() > 1 && polygon.front().x == polygon.back().x && polygon.front().y == polygon.back().y)
        polygon.pop_back();
      if (!polygon.empty())
        contours.push_back(std::move(polygon));
    }
    return contours;
  }

private:
  double               m_SpacingX;
  double               m_SpacingY;
  double               m_Sigma;
  long                 m_PadX;
  long                 m_PadY;
  SliceImage::Pointer  m_Image;
};

} // namespace

ContourStack extractContours(const MaskVolume* mask, double inPlaneSigma)
{
  if (!mask)
    throw Error("extractContours: no mask");
  const auto region = mask->GetBufferedRegion();
  if (region != mask->GetLargestPossibleRegion())
    throw Error("extractContours: the mask must be buffered whole (buffered region = largest possible region)");

  const long width = static_cast<long>(region.GetSize()[0]);
  const long height = static_cast<long>(region.GetSize()[1]);
  const long depth = static_cast<long>(region.GetSize()[2]);
  const std::array<double, 3> spacing = meshingSpacing(mask);

  ContourStack stack;
  stack.sliceSpacing = spacing[2];
  stack.slices.resize(static_cast<std::size_t>(depth));
  for (long k = 0; k < depth; ++k)
    stack.slices[k].z = k * spacing[2];

  // Slices are independent: split them among the cores, each worker with its own filter. Every
  // slice is written by exactly one worker to its own place, so the result does not depend on
  // the number of threads.
  const unsigned char* buffer = mask->GetBufferPointer();
  const std::size_t sliceSize = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  const std::size_t workers = static_cast<std::size_t>(std::max<long>(1, std::min<long>(depth, threadCount(0))));
  try
  {
    // One task per worker, not per slice: each builds its filter once, then takes the next slice
    // not yet taken. (With every other slice each, on the large scaling ellipsoid one worker was
    // still tracing a tenth of a second after the other had finished.)
    std::atomic<long> next{ 0 };
    parallelFor(workers, static_cast<unsigned int>(workers),
                [&](std::size_t)
                {
                  SliceContourExtractor extractor(spacing[0], spacing[1], inPlaneSigma);
                  for (long k = next++; k < depth; k = next++)
                    stack.slices[k].contours = extractor.extract(buffer + k * sliceSize, width, height);
                });
  }
  catch (const itk::ExceptionObject& error)
  {
    throw Error(std::string("extractContours: ITK failed: ") + error.GetDescription());
  }
  return stack;
}

} // namespace slicemesh
