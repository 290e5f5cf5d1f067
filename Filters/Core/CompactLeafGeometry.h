// The Draco section of the compact tree file (CompactTreeFormat.h): every leaf of a tree as one
// Draco mesh, the per-point data the unfolder needs as integer attributes (lossless), positions
// quantised on an explicit grid. Internal to the compact format.
#ifndef foldingmeshes_CompactLeafGeometry_h
#define foldingmeshes_CompactLeafGeometry_h

#include "FoldingTree.h"

#include <string>
#include <vector>

namespace foldingmeshes
{
/// How the leaves are coded; written to the tree section, needed to decode.
struct LeafGeometryCoding
{
  Vec3 origin = Vec3::Zero(); ///< grid corner (the stored points' bounding box minimum)
  double range = 1.0;         ///< grid extent (the bounding box's largest side, > 0)
  int bits = 11;              ///< quantisation bits per coordinate
  /// Keep every leaf's point and triangle order (Draco's sequential coding, larger): needed
  /// when per-point / per-triangle data is stored beside the geometry in that order.
  bool keepOrder = false;
  /// Each point's palette symbol is a Draco attribute; else the symbols are coded beside the
  /// mesh (CompactPointSymbols.h) and DecodedLeaf::symbols comes back empty.
  bool symbolAttribute = true;
  /// Encoder only: points of different leaves at exactly the same position share one Draco
  /// position (the leaf and symbol attributes then have a seam there), so that leaves that
  /// meet along a tear are coded as one surface; the decoder sees one point per leaf as
  /// before. Not with keepOrder.
  bool weldPositions = false;

  /// The largest distance between a point and its decoded position (grid half-step in 3D plus
  /// single-precision rounding).
  double QuantizationError() const;
};

/// One leaf to encode: its points and triangles, and per point the codes of everything else.
struct LeafToEncode
{
  const FoldingLeafMesh* mesh = nullptr;
  std::vector<uint32_t> symbols; ///< per point: index into the tree's palette of point data
};

/// A decoded leaf: points, triangles, and per point its symbol.
struct DecodedLeaf
{
  std::vector<Vec3> points;
  std::vector<Triangle> triangles;
  std::vector<uint32_t> symbols;
};

/**
 * Encodes the leaves as one Draco mesh (edgebreaker; sequential coding when edgebreaker would
 * drop or add faces, checked by decoding; sequential only with coding.keepOrder, checked to
 * give back every triangle in order). `decoded` receives the leaves as a decoder sees them.
 * False with `error` when Draco fails.
 */
bool EncodeLeafGeometry(const std::vector<LeafToEncode>& leaves,
  const LeafGeometryCoding& coding,
  int dracoSpeed,
  std::string& out,
  std::vector<DecodedLeaf>& decoded,
  std::string& error);

/// Decodes `numberOfLeaves` leaves; false with `error` for data Draco rejects or that does not
/// fit the coding (a face across leaves, a leaf index out of range).
bool DecodeLeafGeometry(const char* data,
  size_t size,
  const LeafGeometryCoding& coding,
  int numberOfLeaves,
  std::vector<DecodedLeaf>& leaves,
  std::string& error);
}

#endif
