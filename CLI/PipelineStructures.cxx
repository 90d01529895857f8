#include "PipelineStructures.h"

#include "ContourRepair.h"
#include "Core/Lowercase.h"
#include "MemoryBudget.h"
#include "Core/MeasureText.h"
#include "Core/PlanarGeometry.h"
#include "PipelineStep.h"
#include "SmallComponentRemoval.h"
#include "VolumeSegmentation.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iostream>
#include <set>
#include <sstream>

namespace slicemesh::cli
{
namespace
{

/** How many of `values` are `value`, within 1% of it. */
std::size_t alikeCount(const std::vector<double>& values, double value)
{
  return static_cast<std::size_t>(
    std::count_if(values.begin(), values.end(), [value](double v) { return std::abs(v - value) <= 0.01 * value; }));
}

/** The value most of `values` share (within 1% of it; ties: the smallest); 0 for none. */
double mostCommon(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  double common = 0.0;
  std::size_t most = 0;
  for (double value : values)
    if (const std::size_t alike = alikeCount(values, value); alike > most)
      most = alike, common = value;
  return common;
}

/** mostCommon, when no other value is as common; else 0. */
double clearlyMostCommon(const std::vector<double>& values)
{
  const double common = mostCommon(values);
  if (common == 0.0)
    return 0.0;
  const std::size_t most = alikeCount(values, common);
  for (double value : values)
    if (std::abs(value - common) > 0.01 * common && alikeCount(values, value) == most)
      return 0.0;
  return common;
}

/** The slice spacings a structure set's ROIs are drawn at, each ROI's own: of every ROI in the file,
 *  chosen or not, so that what is meshed of one ROI does not depend on which others are asked for. */
struct SetSpacings
{
  std::vector<double> ofSeveralSlices; ///< ROIs of two slices or more
  std::vector<double> ofManySlices;    ///< ROIs of three slices or more: their spacing is a pattern, not one gap
};

SetSpacings setSpacings(const StructureSet& set, const ContourStackingOptions& stacking)
{
  SetSpacings spacings;
  for (const PlanarStructure& roi : set.structures)
  {
    if (roi.contours.empty())
      continue;
    try
    {
      const StackedContours stacked = stackContours(roi.contours, stacking);
      const std::size_t slices = stacked.stack.slices.size();
      if (slices > 1)
        spacings.ofSeveralSlices.push_back(stacked.stack.sliceSpacing);
      if (slices > 2)
        spacings.ofManySlices.push_back(stacked.stack.sliceSpacing);
    }
    catch (const Error&) // in one slice, or nothing to stack: no spacing of its own
    {
    }
  }
  return spacings;
}

/** The largest distance between two neighbouring slices of the stack (mm). */
double largestGap(const ContourStack& stack)
{
  double gap = 0.0;
  for (std::size_t k = 1; k < stack.slices.size(); ++k)
    gap = std::max(gap, stack.slices[k].z - stack.slices[k - 1].z);
  return gap;
}

} // namespace

std::string who(const Structure& s, const std::string& noun)
{
  return noun.empty() ? std::string() : noun + " " + std::to_string(s.report.label) + " (" + s.report.name + "): ";
}

Structure maskStructure(StoredVolume volume, const PipelineSettings& settings, std::string* automaticChoice)
{
  Structure s;
  // Edges found in 3D hold the float volume and the edge filter's own images beside it, about 20
  // bytes a voxel where the reading's check allows 9 (a 320^3 byte volume peaked at 693 MiB against
  // its 346 MiB estimate): checked again here, before they are made.
  const GrayscaleSegmentationOptions& grayscale = settings.segmentation.grayscale;
  if (settings.segmentation.kind != InputKind::LabelMap && grayscale.regions == RegionMode::Edges &&
      grayscale.dimension == ProcessingDimension::Volume3D)
    guarded(UnreadableInput,
            [&]
            {
              const double voxels = static_cast<double>(imageOf(volume)->GetBufferedRegion().GetNumberOfPixels());
              checkMemoryBudget(settings.inputVolume + ": edges found in 3D", runMemoryBytes(voxels, edgesBytesPerVoxel));
              return 0;
            });
  s.mask = guarded(EmptySegmentation,
                   [&] { return segmentStoredVolume(std::move(volume), settings.segmentation, automaticChoice); });
  if (settings.minimumComponentVolume > 0.0)
  {
    const SmallComponentRemoval removal =
      guarded(MeshingFailed, [&] { return removeSmallComponents(s.mask, settings.minimumComponentVolume); });
    if (removal.removedComponents == removal.components)
    {
      std::ostringstream message;
      message << "every one of the " << removal.components << " connected components of the segmentation of '"
              << settings.inputVolume << "' is smaller than the minimum component volume "
              << settings.minimumComponentVolume << " mm^3 (the largest is " << removal.largestComponentVolume
              << " mm^3)";
      throw PipelineFailure(EmptySegmentation, message.str());
    }
  }
  return s;
}

std::vector<LabelSource> labelMapSources(const StoredVolume& volume, const ColorTable& colors, NegativeLabels negative)
{
  std::vector<LabelSource> sources;
  const auto index = [&]
  { return std::visit([negative](const auto& image) { return indexLabels(image.GetPointer(), negative); }, volume); };
  for (const LabelExtent& e : guarded(EmptySegmentation, index))
  {
    const LabelColor entry = colors.entry(e.label);
    sources.push_back({ volume, e, e.label, entry.name, entry.rgba });
  }
  return sources;
}

std::vector<LabelSource> segmentSources(const SegmentationFile& file, const std::string& path)
{
  std::vector<std::vector<LabelExtent>> layerExtents;
  for (const ScalarVolume::Pointer& layer : file.layers)
  {
    try
    {
      layerExtents.push_back(indexLabels(layer));
    }
    catch (const std::exception& e)
    {
      throw PipelineFailure(UnreadableInput, path + ": " + e.what());
    }
  }
  std::vector<LabelSource> sources;
  for (const SegmentationFile::Segment& segment : file.segments)
  {
    LabelSource source{ file.layers[segment.layer], {}, segment.number, segment.name, segment.rgba };
    source.extent.label = segment.labelValue;
    for (const LabelExtent& e : layerExtents[segment.layer])
      if (e.label == segment.labelValue)
        source.extent = e;
    sources.push_back(source);
  }
  if (std::none_of(sources.begin(), sources.end(), [](const LabelSource& s) { return s.extent.voxels > 0; }))
    throw PipelineFailure(EmptySegmentation, path + ": every segment of the " + file.format + " is empty; nothing to mesh");
  return sources;
}

std::vector<Structure> labelStructures(std::vector<LabelSource> sources, const std::vector<int>& numbers,
                                       const std::vector<std::string>& names, bool segments,
                                       const PipelineSettings& settings)
{
  if (!numbers.empty() || !names.empty())
  {
    std::set<int> wanted(numbers.begin(), numbers.end());
    std::set<std::string> wantedNames;
    for (const std::string& name : names)
      wantedNames.insert(lowercase(name));
    std::vector<LabelSource> chosen;
    std::set<std::string> foundNames; // several labels may share a name: each is picked
    for (const LabelSource& source : sources)
    {
      const bool byNumber = wanted.erase(source.number) > 0;
      const bool byName = wantedNames.count(lowercase(source.name)) > 0;
      if (byName)
        foundNames.insert(lowercase(source.name));
      if (byNumber || byName)
        chosen.push_back(source);
    }
    for (const std::string& name : foundNames)
    {
      wantedNames.erase(name);
      // Said: asked for one structure by its name, the user may not know that two share it.
      std::vector<int> sharing;
      std::string asNamed;
      for (const LabelSource& source : chosen)
        if (lowercase(source.name) == name)
        {
          sharing.push_back(source.number);
          asNamed = source.name;
        }
      if (sharing.size() > 1)
      {
        std::cout << "SliceMesh: " << sharing.size() << (segments ? " segments" : " labels") << " are named '"
                  << asNamed << "', and each is meshed:";
        for (int number : sharing)
          std::cout << " " << number;
        std::cout << std::endl;
      }
    }
    if (!wanted.empty() || !wantedNames.empty())
    {
      std::ostringstream message;
      message << settings.inputVolume;
      if (!wanted.empty())
      {
        message << (segments ? ": no segment numbered" : ": no voxel has label");
        for (int label : wanted)
          message << " " << label;
      }
      else
      {
        message << (segments ? ": no segment named" : ": no label named");
        for (const std::string& name : names)
          if (wantedNames.count(lowercase(name)))
            message << " '" << name << "'";
      }
      if (segments || wanted.empty())
      {
        constexpr std::size_t listed = 20; // enough to spot a misspelling, short enough for one line
        message << (segments ? " (its segments:" : " (its labels:");
        for (std::size_t n = 0; n < std::min(sources.size(), listed); ++n)
          message << (n ? ", " : " ") << sources[n].number << " " << sources[n].name;
        if (sources.size() > listed)
          message << ", ... " << sources.size() << " in all";
        message << ")";
      }
      else
        message << " (" << sources.size() << " labels present)";
      throw PipelineFailure(EmptySegmentation, message.str());
    }
    sources = chosen;
  }
  if (sources.empty())
    throw PipelineFailure(EmptySegmentation, settings.inputVolume + ": every voxel is 0; nothing to mesh");
  if (!settings.segmentation.refinement.seeds.empty())
    std::cerr << "SliceMesh: warning: seed points are ignored when meshing every label separately" << std::endl;
  MaskRefinementOptions refinement = settings.segmentation.refinement;
  refinement.seeds.clear();

  std::vector<Structure> structures(sources.size());
  for (std::size_t n = 0; n < sources.size(); ++n)
  {
    Structure& s = structures[n];
    const LabelSource& source = sources[n];
    s.report.label = source.number;
    s.report.name = source.name;
    s.report.voxels = source.extent.voxels;
    s.rgba = source.rgba;
    if (source.extent.voxels == 0)
    {
      // An empty segment is not a failure: the file says it exists, it has nothing to mesh.
      s.report.dropped = true;
      s.report.droppedBecause = "the segment is empty";
      std::cerr << "SliceMesh: warning: segment " << source.number << " (" << source.name
                << ") is empty; no mesh" << std::endl;
      continue;
    }
    try
    {
      s.mask = std::visit([&](const auto& image) { return cropLabelMask(image.GetPointer(), source.extent); },
                          source.labelMap);
      if (refinement.any())
        refineMask(s.mask, refinement);
      if (settings.minimumComponentVolume > 0.0)
      {
        const SmallComponentRemoval removal = removeSmallComponents(s.mask, settings.minimumComponentVolume);
        s.report.removedComponents = removal.removedComponents;
        if (removal.removedComponents == removal.components)
        {
          // Specks only: dropped, not a failure (the option asks for exactly this).
          s.report.dropped = true;
          s.report.droppedBecause = "every piece below minimumComponentVolume";
          std::cerr << "SliceMesh: warning: label " << s.report.label << " (" << s.report.name << ") dropped: each of its "
                    << removal.components
                    << " connected components is smaller than the minimum component volume "
                    << settings.minimumComponentVolume << " mm^3 (the largest is " << removal.largestComponentVolume
                    << " mm^3)" << std::endl;
        }
      }
    }
    catch (const std::exception& e)
    {
      s.report.error = e.what();
    }
  }
  return structures;
}

namespace
{

/** How far the stacked contours' slices lie from the image's nearest slice (mm), for a stack on the
 *  image's slice direction. */
double distanceOffSlices(const StackedContours& contours, const VolumeGeometry& image)
{
  const itk::Vector<double, 3> normal = image.sliceNormal(); // a tilted CT's slices step sideways too
  const double distance = image.sliceDistance();
  const auto& frame = contours.frame;
  double farthest = 0.0;
  for (const Slice& slice : contours.stack.slices)
  {
    if (slice.contours.empty())
      continue;
    double along = 0.0; // the slice's position along the image's slice direction, from its first slice
    for (int k = 0; k < 3; ++k)
      along += (frame.origin[k] + frame.direction[k][2] * slice.z - image.origin[k]) * normal[k];
    const double slices = along / distance;
    farthest = std::max(farthest, std::abs(slices - std::round(slices)) * distance);
  }
  return farthest;
}

} // namespace

std::optional<std::string> speckNoiseWarning(const FinishedSurface& surface)
{
  const std::size_t specks = surface.smallPiecesRemeshed + surface.smallPiecesAsTiled;
  const std::size_t pieces = surface.validation.components;
  if (specks < speckNoiseCount || 2 * specks <= pieces)
    return std::nullopt;
  std::ostringstream text;
  text << specks << " of the " << pieces
       << " pieces are specks of a few voxels, more likely noise than anatomy: --minimumComponentVolume drops "
          "pieces smaller than a volume before meshing, and for a thresholded image --gaussianSigma smooths it "
          "first";
  return text.str();
}

bool volumeShortfall(const LabelReport& report)
{
  const double target = report.quality.targetVolume;
  return target > 0.0 && std::abs(report.validation.volume - target) > 0.05 * target;
}

std::string volumeShortfallWarning(const std::vector<Structure>& structures, const std::vector<std::size_t>& shortOfVolume,
                                   const std::string& noun, bool fromContours)
{
  const Structure& first = structures[shortOfVolume.front()];
  const double enclosed = first.report.validation.volume, target = first.report.quality.targetVolume;
  std::ostringstream text;
  if (structures.size() > 1)
    text << shortOfVolume.size() << " of the " << structures.size() << " meshes enclose more than 5% "
         << "more or less than their " << (fromContours ? "contours" : "voxels") << "; the first, " << noun << " "
         << first.report.label << " (" << first.report.name << "), ";
  else
    text << "the mesh ";
  text << "encloses " << measureText(enclosed, 1) << " mm^3, " << measureText(100.0 * std::abs(enclosed - target) / target, 0)
       << "% " << (enclosed < target ? "less" : "more") << " than the " << measureText(target, 1)
       << (fromContours ? " mm^3 of its contours' slabs" : " mm^3 of its voxels");
  if (first.report.quality.trianglesKeptTiled > 0)
    text << " (" << first.report.quality.trianglesKeptTiled
         << " triangles kept in their tiled shape where finished pieces crossed: structures thinner or closer than "
            "the target edge)";
  return text.str();
}

std::optional<std::string> frameOfReferenceWarning(const StructureSet& set, const VolumeGeometry& reference,
                                                   const ContourInputSettings& contours)
{
  const std::vector<std::string>& frames = set.framesOfReference;
  if (frames.empty() || reference.frameOfReference.empty() ||
      std::find(frames.begin(), frames.end(), reference.frameOfReference) != frames.end())
    return std::nullopt;
  return "'" + contours.path + "' names Frame of Reference " + frames.front() + (frames.size() > 1 ? " (and others)" : "") +
         ", '" + contours.referenceImage + "' is in " + reference.frameOfReference +
         ": the contours may have been drawn on another image; they are meshed where the structure set puts them";
}

std::vector<Structure> roiStructures(const StructureSet& set, const std::optional<VolumeGeometry>& reference,
                                     const PipelineSettings& settings)
{
  for (const std::string& note : set.notes)
    std::cerr << "SliceMesh: warning: " << oneLine(note) << std::endl;
  const std::vector<PlanarStructure> rois =
    guarded(EmptySegmentation, [&] { return chosenStructures(set, settings.contours.rois); });
  std::vector<Structure> structures(rois.size());
  ContourStackingOptions stacking;
  stacking.sliceNormal = set.sliceNormal;
  if (reference)
  {
    // The planes' normal and distance: a tilted CT's slices step sideways along its third axis.
    const itk::Vector<double, 3> normal = reference->sliceNormal();
    stacking.sliceNormal = Vector3{ normal[0], normal[1], normal[2] };
    stacking.expectedSliceSpacing = reference->sliceDistance();
  }
  auto stack = [&](std::size_t n)
  {
    try
    {
      structures[n].contours = stackContours(rois[n].contours, stacking);
      structures[n].report.error.clear();
      return true;
    }
    catch (const Error& e)
    {
      structures[n].report.error = e.what();
      return false;
    }
  };
  for (std::size_t n = 0; n < rois.size(); ++n)
  {
    Structure& s = structures[n];
    s.report.label = rois[n].number;
    s.report.name = rois[n].name;
    s.rgba = { rois[n].rgb[0], rois[n].rgb[1], rois[n].rgb[2], 255 };
    for (const std::string& note : rois[n].notes)
      std::cerr << "SliceMesh: warning: " << who(s, "ROI") << oneLine(note) << std::endl;
    if (!rois[n].unusableBecause.empty())
      s.report.error = rois[n].unusableBecause; // a fault of the file: it fails as an ROI that cannot be meshed does
    else if (rois[n].contours.empty())
    {
      // A point of interest (an isocentre, a marker: POINT items only) or an empty ROI is in nearly
      // every plan's structure set and has no surface: skipped, not failed, unless asked for by name.
      if (!settings.contours.rois.empty())
        s.report.error = "has no contours";
      else
      {
        s.report.dropped = true;
        s.report.droppedBecause = "no closed contour";
        std::cerr << "SliceMesh: warning: " << who(s, "ROI") << "has no closed contour (a point of interest, or empty): "
                  << "not meshed" << std::endl;
      }
    }
    else
      stack(n);
  }
  // The set's slice spacing: the most common of its ROIs' own. Most ROIs are drawn on every slice of
  // the planning image; the median of 2.5, 5 and 20 mm ROIs is not its spacing. An ROI in one slice
  // gets it as its thickness (ties: the smallest). An ROI drawn several of its slices apart is
  // stacked on them, stopping and starting again between its contours, only where the set shows
  // that spacing clearly: most of its ROIs of three slices or more are drawn at it, and no other
  // spacing as many. A liver drawn every 3 mm beside one MR target drawn every 1 mm is a liver of
  // 3 mm slices, not 29 discs on 1 mm ones.
  const SetSpacings spacings = setSpacings(set, stacking);
  stacking.fallbackSliceSpacing = mostCommon(spacings.ofSeveralSlices);
  stacking.setSliceSpacing = clearlyMostCommon(spacings.ofManySlices);
  for (std::size_t n = 0; n < rois.size(); ++n)
  {
    const bool oneSlice =
      !structures[n].report.error.empty() && !rois[n].contours.empty() && stacking.fallbackSliceSpacing > 0.0;
    const bool farApart = structures[n].report.error.empty() && !rois[n].contours.empty() &&
                          stacking.setSliceSpacing > 0.0 &&
                          structures[n].contours.stack.sliceSpacing > 2.5 * stacking.setSliceSpacing;
    if (oneSlice || farApart)
      stack(n);
  }
  // Contours off the image's slices are a mismatch of the whole set as a rule: one line for all.
  std::string offSlices;
  double largestDeviation = 0.0;
  for (const Structure& s : structures)
    if (s.report.error.empty() && s.contours.normalDeviationDegrees && !s.contours.givenNormalUsed)
    {
      offSlices += (offSlices.empty() ? "" : ", ") + std::to_string(s.report.label) + " (" + s.report.name + ")";
      largestDeviation = std::max(largestDeviation, *s.contours.normalDeviationDegrees);
    }
  if (!offSlices.empty())
  {
    std::ostringstream warning;
    warning.precision(3);
    warning << "the contours of ROI " << offSlices << " are not on the slices of '"
            << (reference ? settings.contours.referenceImage : settings.contours.path) << "': their slice normal is up to "
            << largestDeviation << " degrees from its slice direction (" << stacking.maxNormalDeviationDegrees
            << " allowed); each is stacked along its contours' own normal";
    std::cerr << "SliceMesh: warning: " << oneLine(warning.str()) << std::endl;
  }
  // Contours drawn on the image lie on its slices, to the rounding of their coordinates; between
  // them, they were drawn on another image of the same frame (another phase of a 4D CT, a rescan).
  if (reference)
  {
    std::string between;
    double farthest = 0.0;
    for (const Structure& s : structures)
      if (s.report.error.empty() && s.contours.givenNormalUsed)
      {
        const double off = distanceOffSlices(s.contours, *reference);
        if (off > 0.1 * reference->sliceDistance())
        {
          between += (between.empty() ? "" : ", ") + std::to_string(s.report.label) + " (" + s.report.name + ")";
          farthest = std::max(farthest, off);
        }
      }
    if (!between.empty())
    {
      std::ostringstream warning;
      warning.precision(3);
      warning << "the contours of ROI " << between << " lie between the slices of '" << settings.contours.referenceImage
              << "': up to " << farthest << " mm from the nearest (its slices are " << reference->sliceDistance()
              << " mm apart); they may have been drawn on another image of this Frame of Reference, and are meshed "
                 "where the structure set puts them";
      std::cerr << "SliceMesh: warning: " << oneLine(warning.str()) << std::endl;
    }
  }
  for (Structure& s : structures)
  {
    if (!s.report.meshed())
      continue;
    std::size_t filled = 0;
    for (const Slice& slice : s.contours.stack.slices)
      filled += slice.contours.empty() ? 0 : 1;
    if (filled == 1 && settings.meshing.reconstruction.capPlacement == CapPlacement::AtSlice)
    {
      s.report.error = "all its contours lie in one slice, which has no thickness with the caps at the slice "
                       "(--capPlacement AtSlice)";
      continue;
    }
    ContourRepairReport repair;
    try
    {
      s.contours.stack = repairContours(s.contours.stack, settings.contours.repair, &repair);
    }
    catch (const Error& e) // a point beyond any anatomy: this ROI fails, the others are meshed
    {
      s.report.error = e.what();
      continue;
    }
    if (repair.any()) // a keyhole's perimeter is not its contours'
    {
      const double pointSpacing = automaticPointSpacing(s.contours.stack);
      s.contours.spacing[0] = s.contours.spacing[1] = s.contours.frame.spacing[0] = s.contours.frame.spacing[1] =
        pointSpacing;
    }
    for (const std::string& note : s.contours.notes)
      std::cerr << "SliceMesh: warning: " << who(s, "ROI") << oneLine(note) << std::endl;
    // A gap between two slices is tiled whole, so a stray contour far from the others (a wrong
    // position along the normal) makes a wall as high as the gap: refused here if that would not
    // fit in memory, rather than tiled until the machine runs out of it.
    try
    {
      const double triangles = estimatedTilingTriangles(s.contours.stack, s.contours.spacing[0]);
      std::ostringstream what;
      what << "tiled across its largest gap between slices (" << measureText(largestGap(s.contours.stack), 1)
           << " mm), about " << measureText(triangles / 1e6, 1) << " million triangles,";
      checkMemoryBudget(what.str(), tilingMemoryBytes(triangles));
    }
    catch (const Error& e)
    {
      s.report.error = e.what();
      continue;
    }
    if (repair.any())
      std::cerr << "SliceMesh: warning: " << who(s, "ROI") << repair.summary(settings.contours.repair.channelWidth)
                << std::endl;
  }
  return structures;
}

std::size_t contourPoints(const ContourStack& stack)
{
  std::size_t points = 0;
  for (const Slice& slice : stack.slices)
    for (const Polygon2& contour : slice.contours)
      points += contour.size();
  return points;
}

} // namespace slicemesh::cli
