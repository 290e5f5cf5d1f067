// Draco coding of the compact tree file's leaves (CompactLeafGeometry.h).
#include "CompactLeafGeometry.h"

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>

namespace foldingmeshes
{
namespace
{
// Attribute unique ids in the Draco mesh (stable across Draco's reordering of attributes).
enum AttributeId : uint32_t
{
  PositionId = 0,
  LeafId = 1,  // uint32: the leaf's ordinal among the tree's leaves (preorder)
  SymbolId = 2 // uint32: the point's entry in the tree's palette of point data
};

/// An attribute with one value per point, or (values > 0) `values` values the caller maps to
/// the points (SetExplicitMapping).
template <typename T>
int AddAttribute(draco::Mesh& mesh,
  draco::GeometryAttribute::Type type,
  draco::DataType dataType,
  int components,
  uint32_t uniqueId,
  uint32_t values = 0)
{
  draco::GeometryAttribute ga;
  ga.Init(type,
    nullptr,
    static_cast<uint8_t>(components),
    dataType,
    false,
    static_cast<int64_t>(sizeof(T)) * components,
    0);
  const int id = values > 0 ? mesh.AddAttribute(ga, false, values)
                            : mesh.AddAttribute(ga, true, mesh.num_points());
  mesh.attribute(id)->set_unique_id(uniqueId);
  return id;
}

/// The Draco position of every point of the leaves (in leaf order): its own, or with
/// coding.weldPositions the first one at exactly its coordinates from another leaf.
std::vector<uint32_t> PositionIndices(const std::vector<LeafToEncode>& leaves,
  const LeafGeometryCoding& coding,
  std::vector<Vec3>& positions)
{
  std::vector<uint32_t> indices;
  std::map<std::array<double, 3>, uint32_t> first; // coordinates -> position
  std::vector<size_t> lastLeaf;                    // per position: the last leaf using it
  const bool weld = coding.weldPositions && !coding.keepOrder;
  for (size_t l = 0; l < leaves.size(); ++l)
    for (const Vec3& p : leaves[l].mesh->points)
    {
      const std::array<double, 3> key{ p.x(), p.y(), p.z() };
      const auto found = weld ? first.find(key) : first.end();
      // Never two points of one leaf on one position: that would make degenerate faces.
      if (found != first.end() && lastLeaf[found->second] != l)
      {
        lastLeaf[found->second] = l;
        indices.push_back(found->second);
        continue;
      }
      const uint32_t index = static_cast<uint32_t>(positions.size());
      positions.push_back(p);
      lastLeaf.push_back(l);
      if (weld)
        first.emplace(key, index);
      indices.push_back(index);
    }
  return indices;
}

std::unique_ptr<draco::Mesh> BuildMesh(const std::vector<LeafToEncode>& leaves,
  const LeafGeometryCoding& coding)
{
  auto mesh = std::make_unique<draco::Mesh>();
  std::vector<Vec3> positions;
  const std::vector<uint32_t> positionOf = PositionIndices(leaves, coding, positions);
  const uint32_t points = static_cast<uint32_t>(positionOf.size());
  mesh->set_num_points(points);
  const int position = AddAttribute<float>(*mesh,
    draco::GeometryAttribute::POSITION,
    draco::DT_FLOAT32,
    3,
    PositionId,
    static_cast<uint32_t>(positions.size()));
  for (size_t i = 0; i < positions.size(); ++i)
  {
    const Vec3 offset = positions[i] - coding.origin;
    const std::array<float, 3> xyz{ static_cast<float>(offset.x()),
      static_cast<float>(offset.y()),
      static_cast<float>(offset.z()) };
    mesh->attribute(position)->SetAttributeValue(
      draco::AttributeValueIndex(static_cast<uint32_t>(i)), xyz.data());
  }
  mesh->attribute(position)->SetExplicitMapping(points);
  for (uint32_t p = 0; p < points; ++p)
    mesh->attribute(position)->SetPointMapEntry(
      draco::PointIndex(p), draco::AttributeValueIndex(positionOf[p]));
  const int leafAttribute =
    AddAttribute<uint32_t>(*mesh, draco::GeometryAttribute::GENERIC, draco::DT_UINT32, 1, LeafId);
  const int symbol = coding.symbolAttribute
    ? AddAttribute<uint32_t>(*mesh, draco::GeometryAttribute::GENERIC, draco::DT_UINT32, 1, SymbolId)
    : -1;

  uint32_t base = 0;
  for (size_t l = 0; l < leaves.size(); ++l)
  {
    const FoldingLeafMesh& m = *leaves[l].mesh;
    for (int v = 0; v < m.NumberOfPoints(); ++v)
    {
      const draco::AttributeValueIndex at(base + static_cast<uint32_t>(v));
      const uint32_t leafIndex = static_cast<uint32_t>(l);
      mesh->attribute(leafAttribute)->SetAttributeValue(at, &leafIndex);
      if (symbol >= 0)
        mesh->attribute(symbol)->SetAttributeValue(at, &leaves[l].symbols[v]);
    }
    for (const Triangle& t : m.triangles)
    {
      draco::Mesh::Face face;
      for (int k = 0; k < 3; ++k)
        face[k] = draco::PointIndex(base + static_cast<uint32_t>(t[k]));
      mesh->AddFace(face);
    }
    base += static_cast<uint32_t>(m.NumberOfPoints());
  }
  return mesh;
}

const draco::PointAttribute* Attribute(const draco::Mesh& mesh,
  uint32_t id,
  draco::DataType type,
  int components,
  std::string& error)
{
  const draco::PointAttribute* a = mesh.GetAttributeByUniqueId(id);
  if (!a || a->data_type() != type || a->num_components() != components)
  {
    error = "geometry section: attribute " + std::to_string(id) + " is missing or malformed";
    return nullptr;
  }
  return a;
}

template <typename T, int N>
std::array<T, N> Value(const draco::PointAttribute* a, uint32_t point)
{
  std::array<T, N> v{};
  a->GetMappedValue(draco::PointIndex(point), v.data());
  return v;
}

bool Decode(const char* data, size_t size, std::unique_ptr<draco::Mesh>& mesh, std::string& error)
{
  draco::DecoderBuffer buffer;
  buffer.Init(data, size);
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
  if (!decoded.ok())
  {
    error = std::string("geometry section: Draco cannot decode it (") +
      decoded.status().error_msg_string() + ")";
    return false;
  }
  mesh = std::move(decoded).value();
  return true;
}
}

double LeafGeometryCoding::QuantizationError() const
{
  const double step = this->range / (std::ldexp(1.0, this->bits) - 1.0);
  // Half a grid step per coordinate, plus single-precision rounding of the offsets before
  // quantisation and of the dequantised values (a few units in the last place of the range).
  const double perCoordinate = 0.5 * step + 8.0 * this->range * std::ldexp(1.0, -24);
  return std::sqrt(3.0) * perCoordinate;
}

bool EncodeLeafGeometry(const std::vector<LeafToEncode>& leaves,
  const LeafGeometryCoding& coding,
  int dracoSpeed,
  std::string& out,
  std::vector<DecodedLeaf>& decoded,
  std::string& error)
{
  const std::unique_ptr<draco::Mesh> mesh = BuildMesh(leaves, coding);
  std::vector<int> faces(leaves.size());
  for (size_t l = 0; l < leaves.size(); ++l)
    faces[l] = leaves[l].mesh->NumberOfFaces();
  // Edgebreaker first (the small one); it may drop faces it finds degenerate or split a
  // leaf's non-manifold vertices, so the result is decoded and its faces counted per leaf.
  std::vector<int> methods{ draco::MESH_EDGEBREAKER_ENCODING, draco::MESH_SEQUENTIAL_ENCODING };
  if (coding.keepOrder)
    methods.erase(methods.begin());
  for (const int method : methods)
  {
    draco::Encoder encoder;
    encoder.SetSpeedOptions(dracoSpeed, dracoSpeed);
    const float origin[3] = { 0.0f, 0.0f, 0.0f };
    encoder.SetAttributeExplicitQuantization(
      draco::GeometryAttribute::POSITION, coding.bits, 3, origin, static_cast<float>(coding.range));
    encoder.SetEncodingMethod(method);
    draco::EncoderBuffer buffer;
    const draco::Status status = encoder.EncodeMeshToBuffer(*mesh, &buffer);
    if (!status.ok())
    {
      error = std::string("Draco cannot encode the leaves: ") + status.error_msg_string();
      return false;
    }
    std::vector<DecodedLeaf> check;
    std::string decodeError;
    if (!DecodeLeafGeometry(buffer.data(),
          buffer.size(),
          coding,
          static_cast<int>(leaves.size()),
          check,
          decodeError))
      continue;
    bool same = true;
    for (size_t l = 0; l < leaves.size() && same; ++l)
      same = static_cast<int>(check[l].triangles.size()) == faces[l] &&
        (!coding.keepOrder ||
          (check[l].triangles == leaves[l].mesh->triangles &&
            check[l].points.size() == leaves[l].mesh->points.size()));
    if (same)
    {
      out.assign(buffer.data(), buffer.size());
      decoded = std::move(check);
      return true;
    }
  }
  error = coding.keepOrder ? "Draco does not keep the order of the leaves' points and triangles"
                           : "Draco does not keep every stored triangle of the leaves";
  return false;
}

bool DecodeLeafGeometry(const char* data,
  size_t size,
  const LeafGeometryCoding& coding,
  int numberOfLeaves,
  std::vector<DecodedLeaf>& leaves,
  std::string& error)
{
  std::unique_ptr<draco::Mesh> mesh;
  if (!Decode(data, size, mesh, error))
    return false;
  const draco::PointAttribute* position = Attribute(*mesh, PositionId, draco::DT_FLOAT32, 3, error);
  const draco::PointAttribute* leafAttribute = Attribute(*mesh, LeafId, draco::DT_UINT32, 1, error);
  const draco::PointAttribute* symbol = coding.symbolAttribute
    ? Attribute(*mesh, SymbolId, draco::DT_UINT32, 1, error)
    : nullptr;
  if (!position || !leafAttribute || (coding.symbolAttribute && !symbol))
    return false;

  leaves.assign(static_cast<size_t>(numberOfLeaves), DecodedLeaf());
  const uint32_t points = mesh->num_points();
  // Every point's values must exist (Draco's buffers are not bounds-checked when read).
  for (const draco::PointAttribute* a : { position, leafAttribute, symbol })
    for (uint32_t p = 0; a && p < points; ++p)
      if (a->mapped_index(draco::PointIndex(p)).value() >= a->size())
      {
        error = "geometry section: a point without attribute values";
        return false;
      }
  std::vector<int> local(points);
  std::vector<uint32_t> leafOf(points);
  for (uint32_t p = 0; p < points; ++p)
  {
    const uint32_t l = Value<uint32_t, 1>(leafAttribute, p)[0];
    if (l >= static_cast<uint32_t>(numberOfLeaves))
    {
      error = "geometry section: a point's leaf index is out of range";
      return false;
    }
    leafOf[p] = l;
    DecodedLeaf& leaf = leaves[l];
    local[p] = static_cast<int>(leaf.points.size());
    const auto xyz = Value<float, 3>(position, p);
    leaf.points.push_back(coding.origin + Vec3(xyz[0], xyz[1], xyz[2]));
    if (symbol)
      leaf.symbols.push_back(Value<uint32_t, 1>(symbol, p)[0]);
  }
  for (draco::FaceIndex f(0); f < mesh->num_faces(); ++f)
  {
    const draco::Mesh::Face& face = mesh->face(f);
    Triangle t;
    for (int k = 0; k < 3; ++k)
    {
      if (face[k].value() >= points || leafOf[face[k].value()] != leafOf[face[0].value()])
      {
        error = "geometry section: a triangle spans two leaves or has a point out of range";
        return false;
      }
      t[k] = local[face[k].value()];
    }
    leaves[leafOf[face[0].value()]].triangles.push_back(t);
  }
  return true;
}
}
