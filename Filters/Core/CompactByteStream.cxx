// zlib helpers of the compact tree file's sections (CompactByteStream.h).
#include "CompactByteStream.h"

#include <zlib.h>

namespace foldingmeshes
{
uint32_t Crc(const char* data, size_t size)
{
  return static_cast<uint32_t>(
    crc32(crc32(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(data), static_cast<uInt>(size)));
}

std::string Deflate(const std::string& raw)
{
  uLongf size = compressBound(static_cast<uLong>(raw.size()));
  std::string out(size, '\0');
  if (compress2(reinterpret_cast<Bytef*>(&out[0]),
        &size,
        reinterpret_cast<const Bytef*>(raw.data()),
        static_cast<uLong>(raw.size()),
        9) != Z_OK)
    return std::string(); // the callers check: a deflated section is never empty
  out.resize(size);
  return out;
}

std::string Inflate(const char* data, size_t size, size_t rawSize)
{
  z_stream stream{};
  if (inflateInit(&stream) != Z_OK)
    throw CompactFormatError("zlib cannot inflate a section");
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data));
  stream.avail_in = static_cast<uInt>(size);
  std::string out;
  int status = Z_OK;
  char chunk[65536];
  while (status == Z_OK)
  {
    stream.next_out = reinterpret_cast<Bytef*>(chunk);
    stream.avail_out = sizeof(chunk);
    status = inflate(&stream, Z_NO_FLUSH);
    const size_t produced = sizeof(chunk) - stream.avail_out;
    if ((status != Z_OK && status != Z_STREAM_END) || out.size() + produced > rawSize ||
      (status == Z_OK && produced == 0 && stream.avail_in == 0))
    {
      inflateEnd(&stream);
      throw CompactFormatError("zlib cannot inflate a section (corrupt or wrong size)");
    }
    out.append(chunk, produced);
  }
  inflateEnd(&stream);
  if (out.size() != rawSize)
    throw CompactFormatError("zlib cannot inflate a section (wrong size)");
  return out;
}
}
