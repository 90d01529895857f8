// The seeds a property test runs, from the environment: SLICEMESH_PROPERTY_CASES masks per kind (a
// test's own default otherwise) or the one seed SLICEMESH_PROPERTY_SEED; SLICEMESH_PROPERTY_STRICT
// counts known Logic failures. Shared by the tests that draw randomMask, so the same variables
// lengthen, narrow or harden all of them.
#ifndef PropertySeeds_h
#define PropertySeeds_h

#include <cstdint>
#include <cstdlib>

namespace slicemesh::testing
{

struct SeedRange
{
  std::uint64_t begin = 0, end = 0; ///< seeds begin .. end - 1
};

inline std::uint64_t environmentNumber(const char* name, std::uint64_t fallback)
{
  const char* value = std::getenv(name);
  return value && *value ? std::strtoull(value, nullptr, 10) : fallback;
}

/** SLICEMESH_PROPERTY_STRICT is set: seeds listed as known Logic failures fail the run too. */
inline bool strictPropertyRun()
{
  return std::getenv("SLICEMESH_PROPERTY_STRICT") != nullptr;
}

/** firstSeed .. firstSeed + cases - 1, or only SLICEMESH_PROPERTY_SEED when it is set. A long run
 *  can be cut into pieces: SLICEMESH_PROPERTY_OFFSET=k starts at firstSeed + k. */
inline SeedRange propertySeeds(std::uint64_t firstSeed, std::uint64_t defaultCases)
{
  if (const char* only = std::getenv("SLICEMESH_PROPERTY_SEED"); only && *only)
  {
    const std::uint64_t seed = std::strtoull(only, nullptr, 10);
    return { seed, seed + 1 };
  }
  const std::uint64_t first = firstSeed + environmentNumber("SLICEMESH_PROPERTY_OFFSET", 0);
  return { first, first + environmentNumber("SLICEMESH_PROPERTY_CASES", defaultCases) };
}

} // namespace slicemesh::testing

#endif
