#include "ReturnParameters.h"

#include "Core/SliceMeshTypes.h"

#include <fstream>

namespace slicemesh::cli
{

void writeReturnParameters(const std::string& path, const ReturnValues& values)
{
  std::ofstream out(path);
  for (const auto& [name, value] : values)
  {
    out << name << " = " << value << "\n";
  }
  out.close();
  if (!out)
  {
    throw Error("cannot write the return-parameter file '" + path + "'");
  }
}

} // namespace slicemesh::cli
