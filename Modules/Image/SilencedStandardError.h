// The process's standard error sent nowhere while a third-party reader probes or parses a file.
#ifndef SilencedStandardError_h
#define SilencedStandardError_h

#include <cstdio>
#include <fcntl.h>
#include <unistd.h>

namespace slicemesh
{

/** While it lives, file descriptor 2 goes to /dev/null: GDCM's trace and the NIfTI library write
 *  several lines there on a damaged file (with fprintf, below std::cerr), before ITK throws the
 *  exception SliceMesh turns into its one error line. Only for single-threaded stretches of reading:
 *  the descriptor is the whole process's. */
class SilencedStandardError
{
public:
  SilencedStandardError()
  {
    std::fflush(stderr);
    m_Saved = ::dup(2);
    const int nowhere = ::open("/dev/null", O_WRONLY);
    if (m_Saved >= 0 && nowhere >= 0)
      ::dup2(nowhere, 2);
    if (nowhere >= 0)
      ::close(nowhere);
  }
  ~SilencedStandardError()
  {
    std::fflush(stderr);
    if (m_Saved >= 0)
    {
      ::dup2(m_Saved, 2);
      ::close(m_Saved);
    }
  }
  SilencedStandardError(const SilencedStandardError&) = delete;
  SilencedStandardError& operator=(const SilencedStandardError&) = delete;

private:
  int m_Saved = -1;
};

} // namespace slicemesh

#endif
