// The table of the loader tests' plugin (TestPlugin.cxx).
#ifndef TestPlugin_h
#define TestPlugin_h

#include <cstddef>

namespace slicemesh::testing
{

struct TestPluginFunctions
{
  std::size_t size;
  int (*answer)();
};

} // namespace slicemesh::testing

#endif
