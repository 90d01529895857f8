// Parses argv against the module's parameter table (flags, values, positions, checks).
#ifndef CommandLine_h
#define CommandLine_h

#include "ModuleDescription.h"

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace slicemesh::cli
{

/** A command line that breaks the table's rules; the message is one line for stderr. */
class ArgumentError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/** The parsed command line: every non-return parameter has a value (given or default). */
class ParsedArguments
{
public:
  bool help = false;
  bool echo = false;
  bool xml = false;
  bool version = false;
  std::string returnParameterFile;
  std::string processInformationAddress; ///< accepted and ignored: executables never get a real one

  const std::string& text(const std::string& name) const;
  bool flag(const std::string& name) const;
  long integer(const std::string& name) const;
  double number(const std::string& name) const;
  /** True when the value came from the command line rather than the XML default. */
  bool given(const std::string& name) const;

  std::map<std::string, std::string> values; ///< by parameter name (multiple values joined by ';')
  std::map<std::string, bool> wasGiven;
};

/** Builds the arguments from argv (without argv[0]). Throws ArgumentError on an unknown option,
 *  a missing or malformed value, an enumeration value outside its elements, a value outside its
 *  constraints, a missing or extra positional argument, or a file extension the XML does not list.
 *  When --help, --xml or --version is present, missing positional arguments are not an error. */
ParsedArguments parseCommandLine(const ModuleDescription& module, const std::vector<std::string>& arguments);

} // namespace slicemesh::cli

#endif
