// Stack frame -> physical space, and VTK writers chosen by file extension, written atomically.
#include "MeshWriter.h"

#include "Core/Determinant3.h"
#include "Core/Lowercase.h"
#include "Core/ParallelFor.h"
#include "DeflateCompressor.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkExecutive.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkUnsignedCharArray.h>
#include <vtkNew.h>
#include <vtkPLYWriter.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkSTLWriter.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkTypeInt32Array.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>
#include <unistd.h>

namespace slicemesh
{

namespace
{

/** Why a write that ran out of room failed, where the writer gives no reason of its own. */
const char* const WriteFailed = "writing the file failed (disk full?)";

const char* spaceName(CoordinateSystem system)
{
  return system == CoordinateSystem::RAS ? "RAS" : "LPS";
}

/** "SPACE=LPS": the tag vtkMRMLModelStorageNode looks for in headers and comments. */
std::string spaceTag(CoordinateSystem system)
{
  return std::string("SPACE=") + spaceName(system);
}

/** The mesh as vtkPolyData, with the SPACE string array in its field data (how Slicer tags .vtp).
 *  The arrays are filled in place, not point by point and cell by cell through VTK's insertion
 *  calls; the triangles are stored with 32-bit indices (as the mesh holds them), which halves the
 *  connectivity a .vtp file has to compress and write. */
vtkSmartPointer<vtkPolyData> toPolyData(const TriangleMesh& mesh, CoordinateSystem system)
{
  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(static_cast<vtkIdType>(mesh.points.size()));
  // The copies on every thread: the first touch of a whole-body model's arrays (page faults) and
  // the copying were a second of its run on one thread, before the writing.
  double* xyz = coordinates->GetPointer(0);
  parallelForRanges(mesh.points.size(), 0,
                    [&](std::size_t first, std::size_t last)
                    {
                      for (std::size_t v = first; v < last; ++v)
                      {
                        xyz[3 * v] = mesh.points[v].x;
                        xyz[3 * v + 1] = mesh.points[v].y;
                        xyz[3 * v + 2] = mesh.points[v].z;
                      }
                    });
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  const std::size_t triangles = mesh.triangles.size(); // at most what 32-bit offsets hold (writeMesh)
  vtkNew<vtkTypeInt32Array> offsets;
  vtkNew<vtkTypeInt32Array> connectivity;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(triangles + 1));
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(3 * triangles));
  std::int32_t* offset = offsets->GetPointer(0);
  std::int32_t* corner = connectivity->GetPointer(0);
  offset[triangles] = static_cast<std::int32_t>(3 * triangles);
  parallelForRanges(triangles, 0,
                    [&](std::size_t first, std::size_t last)
                    {
                      for (std::size_t t = first; t < last; ++t)
                      {
                        offset[t] = static_cast<std::int32_t>(3 * t);
                        for (int k = 0; k < 3; ++k)
                          corner[3 * t + static_cast<std::size_t>(k)] = mesh.triangles[t][k];
                      }
                    });
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetPolys(polys);

  vtkNew<vtkStringArray> space;
  space->SetName("SPACE");
  space->InsertNextValue(spaceName(system));
  polyData->GetFieldData()->AddArray(space);
  return polyData;
}

/** Adds the label and colour arrays (cell data) and the structure list (field data). */
void addAttributes(vtkPolyData* polyData, const MeshAttributes& attributes)
{
  const vtkIdType cells = polyData->GetNumberOfCells();
  if (!attributes.cellLabels.empty())
  {
    vtkNew<vtkIntArray> labels;
    labels->SetName("Label");
    labels->SetNumberOfValues(cells);
    int* label = labels->GetPointer(0);
    parallelForRanges(static_cast<std::size_t>(cells), 0,
                      [&](std::size_t first, std::size_t last)
                      {
                        std::copy(attributes.cellLabels.begin() + static_cast<std::ptrdiff_t>(first),
                                  attributes.cellLabels.begin() + static_cast<std::ptrdiff_t>(last), label + first);
                      });
    polyData->GetCellData()->AddArray(labels);
  }
  if (!attributes.cellColors.empty())
  {
    vtkNew<vtkUnsignedCharArray> colors;
    colors->SetName("Color");
    colors->SetNumberOfComponents(3);
    colors->SetNumberOfTuples(cells);
    unsigned char* rgb = colors->GetPointer(0);
    parallelForRanges(static_cast<std::size_t>(cells), 0,
                      [&](std::size_t first, std::size_t last)
                      {
                        for (std::size_t c = first; c < last; ++c)
                          for (std::size_t k = 0; k < 3; ++k)
                            rgb[3 * c + k] = attributes.cellColors[c][k];
                      });
    polyData->GetCellData()->SetScalars(colors);
  }
  if (!attributes.structures.empty())
  {
    vtkNew<vtkIntArray> values;
    values->SetName("LabelValue");
    vtkNew<vtkStringArray> names;
    names->SetName("LabelName");
    vtkNew<vtkFloatArray> rgba;
    rgba->SetName("LabelColor");
    rgba->SetNumberOfComponents(4);
    for (const MeshAttributes::Structure& s : attributes.structures)
    {
      values->InsertNextValue(s.value);
      names->InsertNextValue(s.name);
      const float color[4] = { s.rgba[0] / 255.0f, s.rgba[1] / 255.0f, s.rgba[2] / 255.0f, s.rgba[3] / 255.0f };
      rgba->InsertNextTypedTuple(color);
    }
    polyData->GetFieldData()->AddArray(values);
    polyData->GetFieldData()->AddArray(names);
    polyData->GetFieldData()->AddArray(rgba);
  }
}

/** Collects VTK's error messages instead of letting them go to the console, so the caller can
 *  report one line. */
class VTKErrorCollector
{
public:
  explicit VTKErrorCollector(vtkAlgorithm* watched)
  {
    this->Callback->SetClientData(this);
    this->Callback->SetCallback(
      [](vtkObject* caller, unsigned long, void* clientData, void* callData)
      {
        auto* self = static_cast<VTKErrorCollector*>(clientData);
        if (self->FirstMessage.empty() && caller == self->Executive)
        {
          // The executive's report of a failed RequestData is a dump of the pipeline request
          // ("FORWARD_DIRECTION: 0"), nothing about the file; coming first, it means the writer
          // failed without saying why.
          self->FirstMessage = WriteFailed;
        }
        else if (self->FirstMessage.empty() && callData)
        {
          std::string text = static_cast<const char*>(callData);
          // VTK messages span several lines ("ERROR: In file, line ...\nvtkX (0x..): message"): keep the last.
          while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
          {
            text.pop_back();
          }
          const std::size_t lastBreak = text.find_last_of('\n');
          self->FirstMessage = lastBreak == std::string::npos ? text : text.substr(lastBreak + 1);
        }
      });
    // The executive reports a failed RequestData on its own, so watch it as well.
    this->Executive = watched->GetExecutive();
    for (vtkObject* object : { static_cast<vtkObject*>(watched), static_cast<vtkObject*>(this->Executive) })
    {
      object->AddObserver(vtkCommand::ErrorEvent, this->Callback);
      object->AddObserver(vtkCommand::WarningEvent, this->Callback);
    }
  }
  const std::string& firstMessage() const { return this->FirstMessage; }

private:
  vtkNew<vtkCallbackCommand> Callback;
  vtkObject* Executive = nullptr;
  std::string FirstMessage;
};

/** A VTK writer's message as a user reads it: without the "vtkXMLPolyDataWriter (0x55d7...): "
 *  object prefix, and naming the output file rather than the temporary one written first. */
std::string userMessage(std::string message, const std::string& temporary, const std::string& path)
{
  message = std::regex_replace(message, std::regex("^vtk[A-Za-z0-9]+ \\(0x[0-9a-fA-F]+\\): "), "");
  for (std::size_t at = message.find(temporary); at != std::string::npos; at = message.find(temporary, at + path.size()))
    message.replace(at, temporary.size(), path);
  return message;
}

/** Runs a configured VTK writer (vtkWriter or vtkXMLWriter: both have Write() but share no base
 *  that declares it); returns an empty string on success, else why it failed. */
template <typename WriterType>
std::string runVTKWriter(WriterType* writer)
{
  VTKErrorCollector errors(writer);
  const int written = writer->Write();
  if (written == 1 && writer->GetErrorCode() == 0 && errors.firstMessage().empty())
  {
    return {};
  }
  return errors.firstMessage().empty() ? std::string("the VTK writer failed") : errors.firstMessage();
}

/** Wavefront OBJ written directly: VTK 9.1's vtkOBJWriter has no way to add the SPACE comment
 *  that vtkOBJReader::GetComment (and so Slicer) reads from the file's leading comment lines. */
std::string writeOBJ(const TriangleMesh& mesh, CoordinateSystem system, const std::string& path)
{
  std::ofstream out(path, std::ios::binary);
  if (!out)
  {
    return "cannot open the file for writing";
  }
  out << "# SliceMesh output. " << spaceTag(system) << "\n";
  out << std::setprecision(std::numeric_limits<double>::max_digits10);
  for (const Point3& p : mesh.points)
  {
    out << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
  }
  for (const Triangle& t : mesh.triangles)
  {
    out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  }
  out.flush();
  return out ? std::string() : std::string(WriteFailed);
}

/** Bytes of one value of a PLY property type; 0 for a type the format does not have. */
std::size_t plyTypeBytes(const std::string& type)
{
  static const std::map<std::string, std::size_t> bytes = {
    { "char", 1 },   { "uchar", 1 },  { "int8", 1 },   { "uint8", 1 },   { "short", 2 },  { "ushort", 2 },
    { "int16", 2 },  { "uint16", 2 }, { "int", 4 },    { "uint", 4 },    { "float", 4 },  { "int32", 4 },
    { "uint32", 4 }, { "float32", 4 }, { "double", 8 }, { "float64", 8 }
  };
  const auto found = bytes.find(type);
  return found == bytes.end() ? 0 : found->second;
}

/** Whether a binary .ply file of triangles is as long as its own header says: each element's count
 *  times the bytes of its properties, a face's index list holding 3. vtkPLYWriter writes through C
 *  stdio and reports no failed write, so a full disk leaves a cut file behind a success; reading it
 *  back is no check, as vtkPLYReader crashes on a cut file. */
bool isWholePLY(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::uintmax_t dataBytes = 0;
  std::uintmax_t elementCount = 0;
  std::string line;
  while (std::getline(in, line))
  {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "end_header")
    {
      const std::streamoff headerBytes = in.tellg(); // -1 if the file ends inside this line
      std::error_code error;
      const std::uintmax_t fileBytes = std::filesystem::file_size(path, error);
      return headerBytes > 0 && !error && fileBytes == static_cast<std::uintmax_t>(headerBytes) + dataBytes;
    }
    if (keyword == "element")
    {
      std::string name;
      words >> name >> elementCount;
    }
    else if (keyword == "property")
    {
      std::string type;
      words >> type;
      std::size_t bytes = plyTypeBytes(type);
      if (type == "list")
      {
        std::string countType, indexType;
        words >> countType >> indexType;
        const std::size_t countBytes = plyTypeBytes(countType), indexBytes = plyTypeBytes(indexType);
        bytes = countBytes && indexBytes ? countBytes + 3 * indexBytes : 0;
      }
      if (bytes == 0)
        return false;
      dataBytes += elementCount * bytes;
    }
  }
  return false; // the file ends inside its header
}

/** Writes to path in the format its extension names; returns an empty string on success. */
std::string writeByExtension(const TriangleMesh& mesh, CoordinateSystem system, const std::string& extension,
                             const std::string& path, const MeshAttributes* attributes = nullptr)
{
  if (extension == ".obj")
  {
    return writeOBJ(mesh, system, path);
  }
  const vtkSmartPointer<vtkPolyData> polyData = toPolyData(mesh, system);
  if (attributes)
    addAttributes(polyData, *attributes);
  const std::string header = "SliceMesh output. " + spaceTag(system);
  if (extension == ".vtp")
  {
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(polyData);
    writer->SetFileName(path.c_str());
    writer->SetDataModeToAppended();
    // Raw bytes after the XML, as ParaView writes them: VTK's default encodes them in base64, a
    // third larger and a pass over every byte more.
    writer->EncodeAppendedDataOff();
    // zlib blocks made by libdeflate (DeflateCompressor): float coordinates barely compress, and
    // zlib itself, even at its fastest level, took a tenth of a run's wall time on one core.
    vtkNew<DeflateCompressor> compressor;
    writer->SetCompressor(compressor);
    return runVTKWriter(writer.GetPointer());
  }
  if (extension == ".vtk")
  {
    vtkNew<vtkPolyDataWriter> writer;
    writer->SetInputData(polyData);
    writer->SetFileName(path.c_str());
    writer->SetFileTypeToBinary();
    // Legacy 4.2, as Slicer writes it: 5.1 files are unreadable for VTK < 9 and most other tools.
    writer->SetFileVersion(42);
    writer->SetHeader(header.c_str());
    return runVTKWriter(writer.GetPointer());
  }
  if (extension == ".stl")
  {
    vtkNew<vtkSTLWriter> writer;
    writer->SetInputData(polyData);
    writer->SetFileName(path.c_str());
    writer->SetFileTypeToBinary();
    writer->SetHeader(header.c_str());
    return runVTKWriter(writer.GetPointer());
  }
  if (extension == ".ply")
  {
    vtkNew<vtkPLYWriter> writer;
    writer->SetInputData(polyData);
    writer->SetFileName(path.c_str());
    writer->SetFileTypeToBinary();
    writer->AddComment(spaceTag(system));
    if (attributes && !attributes->cellColors.empty())
    {
      writer->SetArrayName("Color");
      writer->SetColorModeToDefault();
    }
    const std::string failure = runVTKWriter(writer.GetPointer());
    if (!failure.empty())
      return failure;
    return isWholePLY(path) ? std::string() : std::string(WriteFailed);
  }
  return "unsupported extension";
}

} // namespace

TriangleMesh mapToPhysicalSpace(const TriangleMesh& stackMesh, const SliceFrame& frame, CoordinateSystem system)
{
  const auto& d = frame.direction;
  // LPS -> RAS negates x and y: a rotation by 180 degrees (determinant +1), so only the
  // direction matrix can mirror the mesh.
  const double sign = system == CoordinateSystem::RAS ? -1.0 : 1.0;
  // A mirror turns outward normals inward; swapping two corners turns them back.
  const bool mirrored = determinant3(d) < 0.0;
  TriangleMesh physical;
  physical.points.resize(stackMesh.points.size());
  physical.triangles.resize(stackMesh.triangles.size());
  // On every thread: a large surface's copy ran on one while the other waited before the writing.
  parallelForRanges(stackMesh.points.size(), 0,
                    [&](std::size_t first, std::size_t last)
                    {
                      for (std::size_t v = first; v < last; ++v)
                      {
                        const Point3& s = stackMesh.points[v];
                        Point3& p = physical.points[v];
                        p.x = sign * (frame.origin[0] + d[0][0] * s.x + d[0][1] * s.y + d[0][2] * s.z);
                        p.y = sign * (frame.origin[1] + d[1][0] * s.x + d[1][1] * s.y + d[1][2] * s.z);
                        p.z = frame.origin[2] + d[2][0] * s.x + d[2][1] * s.y + d[2][2] * s.z;
                      }
                    });
  parallelForRanges(stackMesh.triangles.size(), 0,
                    [&](std::size_t first, std::size_t last)
                    {
                      for (std::size_t t = first; t < last; ++t)
                      {
                        Triangle& triangle = physical.triangles[t];
                        triangle = stackMesh.triangles[t];
                        if (mirrored)
                          std::swap(triangle[1], triangle[2]);
                      }
                    });
  return physical;
}

void writeMesh(const TriangleMesh& physicalMesh, CoordinateSystem system, const std::string& path)
{
  writeMesh(physicalMesh, system, path, MeshAttributes());
}

void writeMesh(const TriangleMesh& physicalMesh, CoordinateSystem system, const std::string& path,
               const MeshAttributes& attributes)
{
  writeMeshUncommitted(physicalMesh, system, path, attributes)->commit();
}

std::unique_ptr<FileReplacement> writeMeshUncommitted(const TriangleMesh& physicalMesh, CoordinateSystem system,
                                                      const std::string& path, const MeshAttributes& attributes)
{
  const std::size_t triangles = physicalMesh.triangles.size();
  if ((!attributes.cellLabels.empty() && attributes.cellLabels.size() != triangles) ||
      (!attributes.cellColors.empty() && attributes.cellColors.size() != triangles))
    throw Error("cannot write mesh '" + path + "': the per-triangle labels or colours do not match the triangles");
  if (3 * triangles > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw Error("cannot write mesh '" + path + "': " + std::to_string(triangles) +
                " triangles are more than a file's 32-bit indices can hold");
  const bool hasAttributes =
    !attributes.cellLabels.empty() || !attributes.cellColors.empty() || !attributes.structures.empty();
  const std::string extension = lowercase(std::filesystem::path(path).extension().string());
  if (extension != ".vtp" && extension != ".vtk" && extension != ".stl" && extension != ".ply" && extension != ".obj")
  {
    throw Error("cannot write mesh '" + path + "': unknown extension '" + extension +
                "' (use .vtp, .vtk, .stl, .ply or .obj)");
  }
  auto file = std::make_unique<FileReplacement>(path, "mesh");
  const std::string failure =
    writeByExtension(physicalMesh, system, extension, file->temporary(), hasAttributes ? &attributes : nullptr);
  if (!failure.empty())
    throw Error("cannot write mesh '" + path + "': " + userMessage(failure, file->temporary(), path));
  return file;
}

} // namespace slicemesh
