// zlib blocks for VTK's XML writers, made by libdeflate.
#ifndef DeflateCompressor_h
#define DeflateCompressor_h

#include <vtkZLibDataCompressor.h>

struct libdeflate_compressor;

namespace slicemesh
{

/** VTK's zlib compressor with the compressing done by libdeflate, which makes the same format
 *  (each block a zlib stream, inflated by any VTK reader) about twice as fast as zlib at a size
 *  as small. Writing a mesh was a tenth of a run's wall time, on one core, most of it zlib.
 *  A block that barely compresses (a smoothed surface's double coordinates: 6% smaller at level 2,
 *  for half of the writing's time) is stored as it is.
 *  Not a VTK type of its own (no vtkTypeMacro): the writer records the compressor's class name in
 *  the file, and readers must see VTK's zlib compressor there to inflate the blocks. */
class DeflateCompressor : public vtkZLibDataCompressor
{
public:
  static DeflateCompressor* New();

  DeflateCompressor(const DeflateCompressor&) = delete;
  void operator=(const DeflateCompressor&) = delete;

  /** The larger of zlib's bound and libdeflate's for `size` bytes. */
  size_t GetMaximumCompressionSpace(size_t size) override;

protected:
  DeflateCompressor() = default;
  ~DeflateCompressor() override;

  size_t CompressBuffer(unsigned char const* uncompressedData, size_t uncompressedSize,
                        unsigned char* compressedBuffer, size_t compressionSpace) override;

private:
  /** libdeflate's compressor of the level, made at first use and kept for every block after it;
   *  null if it could not be made. */
  libdeflate_compressor* compressorOf(libdeflate_compressor*& made, int level);
  /** Whether a block barely compresses, judged by compressing its start fast (level 1). */
  bool barelyCompresses(unsigned char const* data, size_t size);

  libdeflate_compressor* compressor = nullptr; ///< level 2: every block that compresses
  libdeflate_compressor* prober = nullptr;     ///< level 1: the start of each block
  libdeflate_compressor* storer = nullptr;     ///< level 0: stored blocks, a valid stream all the same
};

} // namespace slicemesh

#endif
