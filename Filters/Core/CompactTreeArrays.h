// The optional arrays section of the compact tree file (CompactTreeFormat.h): user arrays of
// the leaves as raw values, in the leaves' point / triangle order. Internal to the format.
#ifndef foldingmeshes_CompactTreeArrays_h
#define foldingmeshes_CompactTreeArrays_h

#include "CompactByteStream.h"
#include "CompactTreeFormat.h"

#include <string>
#include <vector>

namespace foldingmeshes
{
/// Empty when every array has a name, valid sizes and one value block per leaf that fits the
/// leaf's points or triangles; else the first problem.
std::string CheckArrays(const std::vector<CompactArray>& arrays, const FoldingTree& tree);

/// The section: count, then per array its name, kind, type, components, element size and the
/// leaves' values.
void WriteArrays(const std::vector<CompactArray>& arrays, ByteWriter& w);

/// Reads a section written by WriteArrays for `tree`'s leaves; throws CompactFormatError.
std::vector<CompactArray> ReadArrays(ByteReader& r, const FoldingTree& tree);
}

#endif
