// The module's parameter table, read from its Slicer Execution Model XML (SliceMesh.xml).
#ifndef ModuleDescription_h
#define ModuleDescription_h

#include <optional>
#include <string>
#include <vector>

namespace slicemesh::cli
{

/** One parameter of the XML, as the command line and --help see it. */
struct ModuleParameter
{
  std::string tag;          ///< XML element: integer, double, boolean, string-enumeration, image, ...
  std::string name;         ///< identifier; key of the return-parameter file
  std::string flag;         ///< one letter without '-', or empty
  std::string longflag;     ///< without '--', or empty
  std::optional<int> index; ///< position of a flagless argument
  std::string label;
  std::string description;
  std::string defaultValue;
  std::string channel;                 ///< input, output, or empty
  std::vector<std::string> elements;   ///< allowed values of an enumeration
  std::optional<double> minimum;
  std::optional<double> maximum;
  std::vector<std::string> fileExtensions; ///< lowercase, with the dot
  bool multiple = false;
  bool hidden = false;

  bool isBoolean() const { return tag == "boolean"; }
  bool isEnumeration() const;
  bool isInteger() const { return tag == "integer" || tag == "integer-enumeration"; }
  bool isFloating() const;
  bool isVector() const;
  /** A scalar output with neither flag nor index: written to --returnparameterfile, never given. */
  bool isReturnParameter() const { return channel == "output" && flag.empty() && longflag.empty() && !index; }
  /** "--label" / "-l" / "<inputVolume>": how the user writes it. */
  std::string spelling() const;
};

struct ParameterGroup
{
  std::string label;
  std::string description;
  bool advanced = false;
  std::vector<ModuleParameter> parameters;
};

struct ModuleDescription
{
  std::string title;
  std::string category;
  std::string description;
  std::string version;
  std::string documentationUrl;
  std::vector<ParameterGroup> groups;

  /** Every parameter of every group, in XML order. */
  std::vector<const ModuleParameter*> parameters() const;
  const ModuleParameter* findByName(const std::string& name) const;
  /** Flagless parameters sorted by index. */
  std::vector<const ModuleParameter*> indexedParameters() const;
};

/** Parses the XML; throws slicemesh::Error naming the fault when it breaks a rule the command line
 *  relies on (identifier names, one-letter flags, no flag with an index, unique flags). */
ModuleDescription parseModuleDescription(const std::string& xml);

} // namespace slicemesh::cli

#endif
