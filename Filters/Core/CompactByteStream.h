// Little-endian byte writer and bounds-checked reader for the compact tree file
// (CompactTreeFormat.h): fixed-size numbers and LEB128 variable-length unsigned integers; and
// the zlib helpers of its sections (CompactByteStream.cxx).
#ifndef foldingmeshes_CompactByteStream_h
#define foldingmeshes_CompactByteStream_h

#include <cstdint>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace foldingmeshes
{
/// Thrown by ByteReader on a read past the end or an impossible value (caught by the decoder,
/// which turns it into an error message: a corrupt file never crashes).
struct CompactFormatError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// CRC-32 (zlib's) of `size` bytes.
uint32_t Crc(const char* data, size_t size);
/// zlib-compressed bytes (level 9); empty when zlib fails (a deflated section is never empty).
std::string Deflate(const std::string& raw);
/// Inflates a zlib section that must give exactly `rawSize` bytes; memory grows with what zlib
/// really produces. Throws CompactFormatError for corrupt data or another size.
std::string Inflate(const char* data, size_t size, size_t rawSize);

class ByteWriter
{
public:
  void U8(uint8_t v) { this->Bytes.push_back(static_cast<char>(v)); }
  void U16(uint16_t v) { this->Fixed(v); }
  void U32(uint32_t v) { this->Fixed(v); }
  void F32(float v) { this->Fixed(v); }
  void F64(double v) { this->Fixed(v); }
  void VarUInt(uint64_t v)
  {
    while (v >= 0x80)
    {
      this->U8(static_cast<uint8_t>(v) | 0x80);
      v >>= 7;
    }
    this->U8(static_cast<uint8_t>(v));
  }
  void Raw(const std::string& bytes) { this->Bytes += bytes; }
  std::string Bytes;

private:
  template <typename T>
  void Fixed(T v) // the machines we build for are little-endian (static_assert in the .cxx)
  {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    this->Bytes.append(b, sizeof(T));
  }
};

class ByteReader
{
public:
  ByteReader(const char* data, size_t size, const char* what)
    : Data(data)
    , Size(size)
    , What(what)
  {
  }
  uint8_t U8() { return static_cast<uint8_t>(*this->Take(1)); }
  uint16_t U16() { return this->Fixed<uint16_t>(); }
  uint32_t U32() { return this->Fixed<uint32_t>(); }
  float F32() { return this->Fixed<float>(); }
  double F64() { return this->Fixed<double>(); }
  uint64_t VarUInt()
  {
    uint64_t v = 0;
    for (int shift = 0; shift < 64; shift += 7)
    {
      const uint8_t b = this->U8();
      v |= static_cast<uint64_t>(b & 0x7f) << shift;
      if (!(b & 0x80))
        return v;
    }
    throw CompactFormatError(std::string(this->What) + ": malformed variable-length number");
  }
  /// A count that must not exceed `limit` (guards allocations against corrupt counts).
  size_t Count(uint64_t limit, const char* name)
  {
    const uint64_t v = this->VarUInt();
    if (v > limit)
      throw CompactFormatError(std::string(this->What) + ": " + name + " " + std::to_string(v) +
        " exceeds " + std::to_string(limit));
    return static_cast<size_t>(v);
  }
  const char* Take(size_t n)
  {
    if (n > this->Size - this->Position)
      throw CompactFormatError(std::string(this->What) + ": truncated");
    const char* p = this->Data + this->Position;
    this->Position += n;
    return p;
  }
  size_t Remaining() const { return this->Size - this->Position; }

private:
  template <typename T>
  T Fixed()
  {
    T v;
    std::memcpy(&v, this->Take(sizeof(T)), sizeof(T));
    return v;
  }
  const char* Data;
  size_t Size;
  size_t Position = 0;
  const char* What;
};

/**
 * Fields written column by column: column c collects one kind of field of every record (all
 * node kinds, then all child counts, ...), which zlib codes in fewer bytes than the same
 * fields record by record. With `columns` false every column is the writer itself (records
 * one after another, the first files' layout), so one piece of code writes both layouts.
 * Finish appends, in columns mode, each column's byte length and then the columns.
 */
class ColumnWriter
{
public:
  ColumnWriter(ByteWriter& out, bool columns, int count)
    : Out(out)
    , Columns(columns ? count : 0)
  {
  }
  ByteWriter& operator[](int c) { return this->Columns.empty() ? this->Out : this->Columns[c]; }
  void Finish()
  {
    for (const ByteWriter& column : this->Columns)
      this->Out.VarUInt(column.Bytes.size());
    for (const ByteWriter& column : this->Columns)
      this->Out.Raw(column.Bytes);
  }

private:
  ByteWriter& Out;
  std::vector<ByteWriter> Columns;
};

/// Reads what ColumnWriter wrote: in columns mode the lengths, then a reader per column;
/// else every column is `in` itself. Finish throws unless every column was read to its end.
class ColumnReader
{
public:
  ColumnReader(ByteReader& in, bool columns, int count, const char* what)
    : In(in)
  {
    if (!columns)
      return;
    std::vector<size_t> sizes;
    for (int c = 0; c < count; ++c)
      sizes.push_back(in.Count(in.Remaining(), "column length"));
    for (size_t size : sizes)
      this->Columns.emplace_back(in.Take(size), size, what);
  }
  ByteReader& operator[](int c) { return this->Columns.empty() ? this->In : this->Columns[c]; }
  void Finish() const
  {
    for (const ByteReader& column : this->Columns)
      if (column.Remaining() != 0)
        throw CompactFormatError("tree section: unexpected bytes at the end of a column");
  }

private:
  ByteReader& In;
  std::vector<ByteReader> Columns;
};
}

#endif
