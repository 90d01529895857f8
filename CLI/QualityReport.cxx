#include "QualityReport.h"

#include "Core/Utf8.h"
#include "FileReplacement.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace slicemesh::cli
{

std::string jsonString(const std::string& text)
{
  std::string out = "\"";
  forEachCharacter(text,
                   [&](const Utf8Character& c)
                   {
                     if (!c.wellFormed) // JSON is UTF-8: a byte of text in another encoding becomes U+FFFD
                       out += "\xEF\xBF\xBD";
                     else if (c.length > 1)
                       out.append(c.bytes, c.length);
                     else if (c.codePoint == '"')
                       out += "\\\"";
                     else if (c.codePoint == '\\')
                       out += "\\\\";
                     else if (c.codePoint == '\n')
                       out += "\\n";
                     else if (c.codePoint == '\t')
                       out += "\\t";
                     else if (c.codePoint < 0x20)
                     {
                       char buffer[8];
                       std::snprintf(buffer, sizeof buffer, "\\u%04x", static_cast<unsigned>(c.codePoint));
                       out += buffer;
                     }
                     else
                       out += *c.bytes;
                     return true;
                   });
  return out + "\"";
}

namespace
{

/** JSON has no infinity or NaN: null then. */
std::string jsonNumber(double value)
{
  if (!std::isfinite(value))
    return "null";
  std::ostringstream out;
  out << std::setprecision(10) << value;
  return out.str();
}

std::string percent(double fraction)
{
  std::ostringstream out;
  out << std::fixed << std::setprecision(1) << 100.0 * fraction << "%";
  return out.str();
}

} // namespace

std::string finishSummary(const RunQuality& q)
{
  const std::array<std::size_t, 3>& pieces = q.piecesByFinish;
  const std::size_t total = pieces[0] + pieces[1] + pieces[2];
  const std::size_t asked = q.requestedFinish == "Remeshed" ? 0 : q.requestedFinish == "Smoothed" ? 1 : 2;
  // Specks left as tiled count as finished as asked.
  const std::size_t smoothedOnly = asked == 0 ? pieces[1] : 0;
  const std::size_t leftTiled = asked < 2 ? pieces[2] - std::min(pieces[2], q.smallPiecesAsTiled) : 0;
  // The asked finish reached some pieces: say how many got less, not only the least finish.
  const bool partly = total > 0 && pieces[asked] > 0 && (smoothedOnly > 0 || leftTiled > 0);
  const bool asAsked = q.fallback.empty() || partly;
  const std::string shown = asAsked ? q.requestedFinish : q.finish.empty() ? "Tiled" : q.finish;
  std::vector<std::string> notes;
  if (shown == "Remeshed")
  {
    std::ostringstream edge;
    edge << "target edge " << measureText(q.targetEdgeLength, 2) << " mm";
    notes.push_back(edge.str());
  }
  if (partly)
  {
    std::ostringstream less;
    less << smoothedOnly + leftTiled << " of " << total << " pieces ";
    if (smoothedOnly > 0)
      less << smoothedOnly << " smoothed only" << (leftTiled > 0 ? ", " : "");
    if (leftTiled > 0)
      less << leftTiled << " left as tiled";
    less << ", see the warning";
    notes.push_back(less.str());
  }
  else if (!asAsked)
    notes.push_back(q.requestedFinish + " asked; see the warning");
  if (asAsked && q.smallPiecesAsTiled > 0)
    notes.push_back(std::to_string(q.smallPiecesAsTiled) + " specks kept as tiled");
  if (q.trianglesKeptTiled > 0)
    notes.push_back(std::to_string(q.trianglesKeptTiled) +
                    " triangles kept as tiled where the remesh crossed itself or another piece");
  std::ostringstream text;
  text << "finish " << shown;
  for (std::size_t n = 0; n < notes.size(); ++n)
    text << (n ? "; " : " (") << notes[n] << (n + 1 == notes.size() ? ")" : "");
  return text.str();
}

void StageTimes::start(const std::string& stage)
{
  m_Starts.emplace_back(stage, Clock::now());
}

std::vector<std::pair<std::string, double>> StageTimes::seconds() const
{
  std::vector<std::pair<std::string, double>> result;
  const Clock::time_point now = Clock::now();
  for (std::size_t i = 0; i < m_Starts.size(); ++i)
  {
    const Clock::time_point end = i + 1 < m_Starts.size() ? m_Starts[i + 1].second : now;
    result.emplace_back(m_Starts[i].first, std::chrono::duration<double>(end - m_Starts[i].second).count());
  }
  return result;
}

RunQuality combinedQuality(const std::vector<LabelReport>& labels, const MeshValidation& summed,
                           const TriangleMesh& allTriangles)
{
  RunQuality combined;
  combined.shape = measureMeshQuality(allTriangles);
  combined.genus = genusOf(summed);
  double points = 0.0;
  bool first = true;
  for (const LabelReport& label : labels)
  {
    if (!label.meshed())
      continue;
    const RunQuality& q = label.quality;
    if (first)
    {
      combined.requestedFinish = q.requestedFinish;
      combined.finish = q.finish;
      combined.targetEdgeLength = q.targetEdgeLength; // every label's mask has the volume's spacing
      combined.contourPreparation = q.contourPreparation;
      combined.capPlacement = q.capPlacement;
      combined.contourPointSpacing = q.contourPointSpacing;
      combined.contourSmoothingMaxShift = q.contourSmoothingMaxShift;
      combined.contourSimplification = q.contourSimplification;
      combined.smoothingIterations = q.smoothingIterations;
      combined.smoothingPassBand = q.smoothingPassBand;
      combined.smoothingMaxDisplacement = q.smoothingMaxDisplacement;
      combined.smoothingFeaturePairs = q.smoothingFeaturePairs;
      combined.smoothingMaxDisplacementAwayFromFeatures = q.smoothingMaxDisplacementAwayFromFeatures;
      first = false;
    }
    else if (combined.finish != q.finish)
      combined.finish = "Mixed";
    combined.smallPiecesRemeshed += q.smallPiecesRemeshed;
    combined.smallPiecesAsTiled += q.smallPiecesAsTiled;
    for (std::size_t f = 0; f < combined.piecesByFinish.size(); ++f)
      combined.piecesByFinish[f] += q.piecesByFinish[f];
    combined.unsmoothedVertices += q.unsmoothedVertices;
    combined.trianglesKeptTiled += q.trianglesKeptTiled;
    combined.targetVolume += q.targetVolume;
    combined.crossingRepairOperations += q.crossingRepairOperations;
    combined.narrowTrianglesWidened += q.narrowTrianglesWidened;
    if (!q.fallback.empty())
      combined.fallback += (combined.fallback.empty() ? "label " : "; label ") + std::to_string(label.label) + " (" +
                           label.name + "): " + q.fallback;
    const DirichletEnergy& d = label.quality.dirichlet;
    combined.dirichlet.energy += d.energy;
    combined.dirichlet.tilingTriangles += d.tilingTriangles;
    combined.dirichlet.flipCandidates += d.flipCandidates;
    combined.dirichlet.loweringFlips += d.loweringFlips;
    combined.dirichlet.largestDecrease = std::max(combined.dirichlet.largestDecrease, d.largestDecrease);
    combined.dirichlet.largestRelativeDecrease =
      std::max(combined.dirichlet.largestRelativeDecrease, d.largestRelativeDecrease);
    const double weight = static_cast<double>(label.contourPoints);
    combined.pointSpacing += weight * label.quality.pointSpacing;
    combined.sliceSpacing += weight * label.quality.sliceSpacing;
    points += weight;
  }
  if (points > 0.0)
  {
    combined.pointSpacing /= points;
    combined.sliceSpacing /= points;
  }
  return combined;
}

std::string qualitySummary(const MeshValidation& v, const RunQuality& q, bool eachStructure)
{
  std::ostringstream line;
  line << finishSummary(q);
  line << ", " << v.vertices << " vertices, " << v.components << (v.components == 1 ? " component, " : " components, ")
       << (v.manifold() ? "manifold, " : "NOT manifold, ")
       << (!v.selfIntersectionChecked ? "self-intersections not checked, "
           : v.selfIntersections == 0   ? (eachStructure ? "no self-intersections within a structure, " : "no self-intersections, ")
                                        : std::to_string(v.selfIntersections) + " self-intersecting pairs, ")
       << "Euler characteristic " << v.eulerCharacteristic << ", genus ";
  if (q.genus >= 0)
    line << q.genus;
  else
    line << "undefined";
  line << std::fixed << std::setprecision(1) << ", min angle " << q.shape.minAngleDegrees << " deg, <30 deg "
       << percent(q.shape.fractionBelow30) << ", <10 deg " << percent(q.shape.fractionBelow10)
       << ", aspect ratio mean " << measureText(q.shape.meanAspectRatio, 2) << " max "
       << measureText(q.shape.maxAspectRatio, 2) << ", area " << measureText(v.area, 1)
       << " mm^2, point/slice spacing " << measureText(q.sliceSpacing > 0.0 ? q.pointSpacing / q.sliceSpacing : 0.0, 2)
       << ", Dirichlet energy of the tiling " << measureText(q.dirichlet.energy, 1) << " mm^2";
  if (!q.stageSeconds.empty())
  {
    line << "; stages" << std::setprecision(2);
    for (std::size_t i = 0; i < q.stageSeconds.size(); ++i)
      line << (i ? ", " : " ") << q.stageSeconds[i].first << " " << q.stageSeconds[i].second << " s";
  }
  return line.str();
}

namespace
{

/** How the "mesh" block's validation figures were found: of one mesh checked whole, or summed over
 *  the structures of a combined model, each checked on its own. */
enum class ValidationScope
{
  WholeMesh,
  EachStructure
};

/** The "mesh", "quality" and "dirichletEnergy" blocks of one mesh, each line after `indent`. */
void writeMeshBlocks(std::ostream& json, const std::string& indent, const MeshValidation& v, const RunQuality& q,
                     ValidationScope scope = ValidationScope::WholeMesh)
{
  auto number = [&](const char* key, double value, bool last = false)
  { json << indent << "  " << jsonString(key) << ": " << jsonNumber(value) << (last ? "\n" : ",\n"); };
  auto flag = [&](const char* key, bool value)
  { json << indent << "  " << jsonString(key) << ": " << (value ? "true" : "false") << ",\n"; };
  // What was done to the tiling; the mesh and quality blocks below describe its result.
  json << indent << "\"finishing\": {\n";
  json << indent << "  \"finish\": " << jsonString(q.finish.empty() ? "Tiled" : q.finish) << ",\n";
  json << indent << "  \"requested\": " << jsonString(q.requestedFinish.empty() ? "Tiled" : q.requestedFinish)
       << ",\n";
  number("targetEdgeLengthMm", q.targetEdgeLength);
  number("smoothingIterations", q.smoothingIterations);
  number("smoothingPassBand", q.smoothingPassBand);
  json << indent << "  \"smoothingMaxDisplacementMm\": [" << jsonNumber(q.smoothingMaxDisplacement[0]) << ", "
       << jsonNumber(q.smoothingMaxDisplacement[1]) << ", " << jsonNumber(q.smoothingMaxDisplacement[2]) << "],\n";
  number("smoothingFeaturePairs", q.smoothingFeaturePairs);
  const std::array<double, 3>& away = q.smoothingMaxDisplacementAwayFromFeatures;
  json << indent << "  \"smoothingMaxDisplacementAwayFromFeaturesMm\": [" << jsonNumber(away[0]) << ", "
       << jsonNumber(away[1]) << ", " << jsonNumber(away[2]) << "],\n";
  number("smallPiecesRemeshed", static_cast<double>(q.smallPiecesRemeshed));
  number("smallPiecesLeftTiled", static_cast<double>(q.smallPiecesAsTiled));
  json << indent << "  \"pieces\": { \"remeshed\": " << q.piecesByFinish[0] << ", \"smoothedOnly\": "
       << q.piecesByFinish[1] << ", \"leftTiled\": " << q.piecesByFinish[2] << " },\n";
  number("verticesLeftUnsmoothed", static_cast<double>(q.unsmoothedVertices));
  number("trianglesKeptTiledAtCrossings", static_cast<double>(q.trianglesKeptTiled));
  json << indent << "  \"targetVolumeMm3\": " << (q.targetVolume > 0.0 ? jsonNumber(q.targetVolume) : "null") << ",\n";
  number("crossingRepairOperations", static_cast<double>(q.crossingRepairOperations));
  number("narrowTrianglesWidened", static_cast<double>(q.narrowTrianglesWidened));
  json << indent << "  \"fallback\": " << (q.fallback.empty() ? "null" : jsonString(q.fallback)) << "\n";
  json << indent << "},\n";
  json << indent << "\"resolvedOptions\": {\n";
  json << indent << "  \"contourPreparation\": " << jsonString(q.contourPreparation) << ",\n";
  number("contourPointSpacingMm", q.contourPointSpacing);
  number("contourSmoothingMaxShiftMm", q.contourSmoothingMaxShift);
  number("contourSimplificationMm", q.contourSimplification);
  json << indent << "  \"capPlacement\": " << jsonString(q.capPlacement.empty() ? "HalfSliceBeyond" : q.capPlacement)
       << ",\n";
  number("wallRowHeightMm", q.wallRowHeight);
  number("steinerSpacingMm", q.steinerSpacing, true);
  json << indent << "},\n";
  json << indent << "\"mesh\": {\n";
  // A combined model's structures are not checked against each other (a self-intersection test of
  // the whole model costs more than the run): touching labels may intersect, and "valid" is theirs.
  if (scope == ValidationScope::EachStructure)
    json << indent << "  \"validatedAs\": \"eachStructure\",\n"
         << indent << "  \"validationNote\": \"the figures sum those of each structure's mesh, checked on its "
                      "own; meshes of different structures may touch or intersect each other (not checked)\",\n";
  else
    json << indent << "  \"validatedAs\": \"wholeMesh\",\n";
  number("vertices", static_cast<double>(v.vertices));
  number("triangles", static_cast<double>(v.triangles));
  number("components", static_cast<double>(v.components));
  flag("closed", v.closed());
  flag("manifold", v.manifold());
  flag("oriented", v.oriented());
  flag("selfIntersectionChecked", v.selfIntersectionChecked);
  flag("selfIntersecting", v.selfIntersectionChecked && v.selfIntersections > 0);
  number("selfIntersectingPairs", static_cast<double>(v.selfIntersections));
  number("boundaryEdges", static_cast<double>(v.boundaryEdges));
  number("nonManifoldEdges", static_cast<double>(v.nonManifoldEdges));
  number("nonManifoldVertices", static_cast<double>(v.nonManifoldVertices));
  number("degenerateTriangles", static_cast<double>(v.degenerateTriangles));
  number("eulerCharacteristic", static_cast<double>(v.eulerCharacteristic));
  json << indent << "  \"genus\": " << (q.genus >= 0 ? std::to_string(q.genus) : std::string("null")) << ",\n";
  flag("valid", v.valid());
  number("areaMm2", v.area);
  number("volumeMm3", v.volume, true);
  json << indent << "},\n" << indent << "\"quality\": {\n";
  number("minAngleDegrees", q.shape.minAngleDegrees);
  number("maxAngleDegrees", q.shape.maxAngleDegrees);
  number("percentTrianglesBelow30Degrees", 100.0 * q.shape.fractionBelow30);
  number("percentTrianglesBelow10Degrees", 100.0 * q.shape.fractionBelow10);
  json << indent
       << "  \"aspectRatio\": { \"definition\": \"circumradius / (2 inradius), 1 for equilateral\", \"mean\": "
       << jsonNumber(q.shape.meanAspectRatio) << ", \"median\": " << jsonNumber(q.shape.medianAspectRatio)
       << ", \"p95\": " << jsonNumber(q.shape.p95AspectRatio) << ", \"max\": " << jsonNumber(q.shape.maxAspectRatio)
       << " },\n";
  number("pointSpacingMm", q.pointSpacing);
  number("sliceSpacingMm", q.sliceSpacing);
  number("pointToSliceSpacingRatio", q.sliceSpacing > 0.0 ? q.pointSpacing / q.sliceSpacing : 0.0, true);
  json << indent << "},\n" << indent << "\"dirichletEnergy\": {\n";
  json << indent << "  \"measuredOn\": \"the tiling, before finishing\",\n";
  number("energyMm2", q.dirichlet.energy);
  number("slopedTilingTriangles", static_cast<double>(q.dirichlet.tilingTriangles));
  number("flipCandidates", static_cast<double>(q.dirichlet.flipCandidates));
  number("loweringFlips", static_cast<double>(q.dirichlet.loweringFlips));
  number("largestDecreaseMm2", q.dirichlet.largestDecrease, true);
  json << indent << "}";
}

} // namespace

void writeQualityReport(const std::string& path, const std::string& inputVolume, const std::string& outputModel,
                        const MeshValidation& v, const RunQuality& q, double seconds,
                        const std::vector<LabelReport>& labels)
{
  FileReplacement file(path, "report");

  std::ostringstream json;
  json << "{\n  \"input\": " << jsonString(inputVolume) << ",\n  \"output\": " << jsonString(outputModel) << ",\n";
  writeMeshBlocks(json, "  ", v, q, labels.empty() ? ValidationScope::WholeMesh : ValidationScope::EachStructure);
  json << ",\n  \"seconds\": {\n";
  for (const auto& [stage, s] : q.stageSeconds)
    json << "    " << jsonString(stage) << ": " << jsonNumber(s) << ",\n";
  json << "    \"total\": " << jsonNumber(seconds) << "\n  }";
  if (!labels.empty())
  {
    // Failed and dropped labels keep their entry, without mesh blocks.
    json << ",\n  \"labels\": [";
    for (std::size_t n = 0; n < labels.size(); ++n)
    {
      const LabelReport& label = labels[n];
      json << (n ? ",\n" : "\n") << "    {\n      \"label\": " << label.label << ",\n      \"name\": "
           << jsonString(label.name) << ",\n      \"file\": " << (label.path.empty() ? "null" : jsonString(label.path))
           << ",\n      \"voxels\": " << label.voxels << ",\n      \"removedComponents\": "
           << label.removedComponents << ",\n      \"dropped\": " << (label.dropped ? "true" : "false")
           << ",\n      \"droppedBecause\": " << (label.dropped ? jsonString(label.droppedBecause) : "null")
           << ",\n      \"seconds\": " << jsonNumber(label.seconds)
           << ",\n      \"error\": " << (label.error.empty() ? "null" : jsonString(label.error));
      if (label.meshed())
      {
        json << ",\n";
        writeMeshBlocks(json, "      ", label.validation, label.quality);
      }
      json << "\n    }";
    }
    json << "\n  ]";
  }
  json << "\n}\n";

  {
    std::ofstream out(file.temporary());
    out << json.str();
    out.close();
    if (!out)
      throw Error("cannot write report '" + path + "'");
  }
  file.commit();
}

} // namespace slicemesh::cli
