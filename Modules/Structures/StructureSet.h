// The structures of a structure set or contour file: each ROI's number, name, colour and closed
// planar contours in patient (LPS) millimetres, as read, before they become contour stacks.
#ifndef StructureSet_h
#define StructureSet_h

#include "Contours/ContourStacking.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace slicemesh
{

/** One ROI: closed planar contours, LPS mm. */
struct PlanarStructure
{
  int number = 0;
  std::string name; ///< UTF-8 (an RT Structure Set's converted from its Specific Character Set)
  std::array<unsigned char, 3> rgb{ 128, 128, 128 };
  std::vector<Polygon3> contours;
  /** One line each: items of the file skipped for this ROI (points, open contours). */
  std::vector<std::string> notes;
  /** Why the ROI cannot be meshed though the file lists it, one line (an RT Structure Set's ROI
   *  number shared by another ROI: neither's contours are known; a contour value that is no number:
   *  then it keeps no contours); empty when it can. */
  std::string unusableBecause;
};

struct StructureSet
{
  std::vector<PlanarStructure> structures;
  /** The slice normal the file states (the referenced image series' orientation), when it does. */
  std::optional<Vector3> sliceNormal;
  /** The Frames of Reference (UIDs) the file says its contours are in: an RT Structure Set's
   *  referenced frames and its ROIs'; empty when it names none. */
  std::vector<std::string> framesOfReference;
  /** One line each: faults of the file as a whole, which the reader worked around (e.g. names it
   *  could not convert to UTF-8). */
  std::vector<std::string> notes;
};

/** What a contour file holds, by its content. */
enum class ContourFileKind
{
  Automatic, ///< detect from the file
  RTStruct,  ///< DICOM RT Structure Set
  PolyData,  ///< VTK polydata (.vtk or .vtp) of closed polylines, one ROI per file (3D Slicer's planar contours)
  Json       ///< SliceMesh's JSON contour format (Documentation/ContourFiles.md)
};

/** The kind of a file from its first bytes: DICOM (DICM after the preamble, or a dataset stored
 *  without it) with Modality RTSTRUCT, a VTK legacy or XML polydata file, a JSON object (after a
 *  byte order mark, if any); empty when it is none of them (e.g. an image volume). Reads only
 *  the start of the file and never throws on content; a DICOM file of another modality is not a
 *  structure set. */
std::optional<ContourFileKind> detectContourFileKind(const std::string& path);

/** Reads the file as the given kind (Automatic: detected). Throws slicemesh::Error (one line,
 *  naming the file) when it cannot be read as that kind: missing, truncated, another modality,
 *  malformed. */
StructureSet readStructureSet(const std::string& path, ContourFileKind kind = ContourFileKind::Automatic);

/** The readers, by kind (readStructureSet dispatches to them). */
StructureSet readRTStructureSet(const std::string& path);
StructureSet readContourPolyData(const std::string& path);
StructureSet readContourJson(const std::string& path);

/** Marks the ROIs of `set` that share an ROI number with another as unusable: one note of the file
 *  (`path`) for each such number, naming its ROIs and the `consequence`; each ROI's unusableBecause
 *  names the others and the `reason`. Returns the shared numbers. The number is an ROI's identity
 *  (what --rois picks, the merged model's Label, the prefix of its file), so two ROIs cannot have one. */
std::vector<int> markSharedRoiNumbers(StructureSet& set, const std::string& path, const std::string& consequence,
                                      const std::string& reason);

/** The structures whose name or number is in `wanted` (numbers as text), in the set's order; all
 *  when it is empty. Throws Error naming what matches no ROI, and the ROIs there are. */
std::vector<PlanarStructure> chosenStructures(const StructureSet& set, const std::vector<std::string>& wanted);

} // namespace slicemesh

#endif
