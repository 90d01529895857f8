// A plugin for the loader's tests (PluginLoadingTest.cxx): one table as this build lays it out, and
// one as a plugin of another version would (a different size).
#include "TestPlugin.h"

namespace
{

int answer()
{
  return 42;
}

} // namespace

extern "C" __attribute__((visibility("default"))) const slicemesh::testing::TestPluginFunctions* slicemeshTestPluginFunctions()
{
  static const slicemesh::testing::TestPluginFunctions functions{ sizeof(slicemesh::testing::TestPluginFunctions), &answer };
  return &functions;
}

extern "C" __attribute__((visibility("default"))) const slicemesh::testing::TestPluginFunctions* slicemeshOtherVersionFunctions()
{
  static const slicemesh::testing::TestPluginFunctions functions{ sizeof(slicemesh::testing::TestPluginFunctions) + 8,
                                                                  &answer };
  return &functions;
}
