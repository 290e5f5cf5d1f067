// The compact folding-tree file (.fmz, CompactTreeFormat.h), on trees of procedural meshes
// with nested folds and segmentations (a three-plane shape, a blob with an asymmetric
// attachment, a rigidly moved bilateral blob) and on a single-leaf tree:
// - round trip: the structure is exact (kinds, children, depths, leaf reasons, epsilons,
//   face counts, leaf point and triangle counts, per-leaf multisets of tear / plane masks,
//   projected and input-border flags, mirrored-flag records), planes within 1e-6, every stored
//   point within the stated quantisation error of a stored point of the same leaf (and the
//   other way), triangles oriented as stored (normals agree with the nearest original
//   triangle's), budgets never above the original's minus the quantisation error (the leaf's
//   smallest, or below a rotation node the largest of the original points within the error);
// - unfolding the decoded tree stays within the root epsilon of the input (proved Hausdorff
//   bound over whole surfaces), quantisation included, for automatic and for 8 bits;
// - the same bytes for the same tree (determinism), fewer bytes with fewer bits; the tree
//   section field by field (the default) and record by record both read back;
// - user arrays (per point, per triangle) come back byte for byte, the leaves' order kept;
// - bad input fails cleanly with an error, never a crash: every truncation of a file, flipped
//   bytes (checksum), flipped bytes in the tree section behind a valid checksum (a small fuzz
//   corpus), another version, another magic number, huge counts, an invalid tree to encode,
//   quantisation bits out of range;
// - fans folded with rotation nodes, written at 8 bits: one pole, their own faces and area;
// - a sector cut along its half-planes: its points' budget levels let the decoded tree unfold
//   to about the faces of the tree in memory.
#include "CompactTreeFormat.h"
#include "CoreTestUtilities.h"
#include "ProceduralMeshes.h"
#include "RotationTestShapes.h"
#include "SurfaceDistance.h"

#include <zlib.h>

#include <limits>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <random>
#include <set>
#include <tuple>

using namespace foldingmeshes;
namespace pm = foldingmeshes::testing;

namespace
{
std::string Encode(const FoldingTree& tree,
  int bits,
  CompactTreeStats* stats = nullptr,
  bool symbolsBeside = true,
  bool weld = true,
  bool columns = true)
{
  CompactTreeOptions options;
  options.quantizationBits = bits;
  options.symbolsBesideGeometry = symbolsBeside;
  options.weldLeaves = weld;
  options.nodeColumns = columns;
  std::string bytes, error;
  const bool ok = EncodeCompactTree(tree, options, bytes, stats, error);
  REQUIRE(ok, "EncodeCompactTree failed: " << error);
  return bytes;
}

uint32_t Crc(const std::string& b, size_t n)
{
  return static_cast<uint32_t>(
    crc32(crc32(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(b.data()), static_cast<uInt>(n)));
}

/// Rewrites the checksum so that a change gets past it to the parsers.
void Reseal(std::string& b)
{
  const uint32_t crc = Crc(b, b.size() - 4);
  std::memcpy(&b[b.size() - 4], &crc, 4);
}

/// The file with its tree section replaced by `raw` (deflated, sizes and checksum updated).
std::string WithTreeSection(const std::string& file, const std::string& raw)
{
  uint32_t packedSize;
  std::memcpy(&packedSize, file.data() + 8, 4);
  uLongf size = compressBound(static_cast<uLong>(raw.size()));
  std::string packed(size, '\0');
  compress2(reinterpret_cast<Bytef*>(&packed[0]),
    &size,
    reinterpret_cast<const Bytef*>(raw.data()),
    static_cast<uLong>(raw.size()),
    9);
  packed.resize(size);
  std::string out = file.substr(0, 8);
  const uint32_t sizes[2] = { static_cast<uint32_t>(packed.size()),
    static_cast<uint32_t>(raw.size()) };
  out.append(reinterpret_cast<const char*>(sizes), 8);
  out += packed;
  out += file.substr(16 + packedSize);
  Reseal(out);
  return out;
}

std::string TreeSection(const std::string& file)
{
  uint32_t sizes[2];
  std::memcpy(sizes, file.data() + 8, 8);
  std::string raw(sizes[1], '\0');
  uLongf got = sizes[1];
  uncompress(reinterpret_cast<Bytef*>(&raw[0]),
    &got,
    reinterpret_cast<const Bytef*>(file.data() + 16),
    sizes[0]);
  return raw;
}

bool Rejected(const std::string& bytes, const std::string& what)
{
  FoldingTree tree;
  std::string error;
  const bool ok = DecodeCompactTree(bytes, tree, error);
  EXPECT(
    !ok && !error.empty() && tree.Empty(), what << ": rejected with an error (" << error << ")");
  return !ok;
}

using PointKey =
  std::tuple<uint64_t, uint64_t, int, int, std::vector<std::tuple<int, int, uint64_t>>>;

std::multiset<PointKey> PointData(const FoldingLeafMesh& m)
{
  std::map<int, std::vector<std::tuple<int, int, uint64_t>>> mirrored;
  for (const MirroredFlag& f : m.mirroredFlags)
    mirrored[f.point].emplace_back(f.level, static_cast<int>(f.flag), f.mirrorMask);
  std::multiset<PointKey> keys;
  for (int v = 0; v < m.NumberOfPoints(); ++v)
    keys.emplace(m.tearMask[v],
      m.planeMask[v],
      m.projected[v],
      m.inputBoundary.empty() ? -1 : m.inputBoundary[v],
      mirrored[v]);
  return keys;
}

double NearestDistance(const Vec3& p, const std::vector<Vec3>& points)
{
  double best = std::numeric_limits<double>::infinity();
  for (const Vec3& q : points)
    best = std::min(best, (p - q).norm());
  return best;
}

void CompareTrees(const FoldingTree& a, const FoldingTree& b, double quantization, const char* name)
{
  REQUIRE(a.NumberOfNodes() == b.NumberOfNodes(), name << ": node count");
  EXPECT(a.numberOfOriginalFaces == b.numberOfOriginalFaces &&
      a.numberOfOriginalPoints == b.numberOfOriginalPoints &&
      a.numberOfDroppedFaces == b.numberOfDroppedFaces && a.diagonal == b.diagonal &&
      a.rootEpsilon == b.rootEpsilon && a.originalArea == b.originalArea,
    name << ": counts and lengths");
  int pointsOff = 0, orientationOff = 0, budgetsOff = 0;
  for (int i = 0; i < a.NumberOfNodes(); ++i)
  {
    const FoldingNode &x = a.nodes[i], &y = b.nodes[i];
    EXPECT(x.kind == y.kind && x.children == y.children && x.parent == y.parent &&
        x.depth == y.depth && x.foldsAbove == y.foldsAbove && x.leafReason == y.leafReason &&
        x.numberOfFaces == y.numberOfFaces,
      name << ": node " << i << " structure");
    EXPECT(std::abs(x.epsilon - y.epsilon) <= 1e-7 * a.rootEpsilon,
      name << ": node " << i << " epsilon");
    if (x.kind == FoldingNodeKind::Folding)
      EXPECT((x.plane.normal - y.plane.normal).norm() < 1e-6 &&
          std::abs(x.plane.SignedDistance(y.plane.origin)) < 1e-6 * a.diagonal &&
          x.discardedFaces == y.discardedFaces,
        name << ": node " << i << " plane");
    if (x.kind != FoldingNodeKind::Leaf)
      continue;
    const FoldingLeafMesh &m = x.mesh, &n = y.mesh;
    EXPECT(m.NumberOfPoints() == n.NumberOfPoints() && m.NumberOfFaces() == n.NumberOfFaces(),
      name << ": leaf " << i << " counts " << m.NumberOfPoints() << "/" << n.NumberOfPoints()
           << " points, " << m.NumberOfFaces() << "/" << n.NumberOfFaces() << " triangles");
    EXPECT(PointData(m) == PointData(n), name << ": leaf " << i << " point flags and masks");
    EXPECT(m.errorBudget.empty() == n.errorBudget.empty(), name << ": leaf " << i << " budgets");
    if (!m.errorBudget.empty() && !n.errorBudget.empty())
    {
      // The leaf's smallest budget, or (a leaf below a rotation node: budget levels) at most
      // the largest of the original points the decoded one may stand for.
      const double smallest = *std::min_element(m.errorBudget.begin(), m.errorBudget.end());
      for (int v = 0; v < n.NumberOfPoints(); ++v)
      {
        double allowed = smallest;
        for (int u = 0; u < m.NumberOfPoints(); ++u)
          if ((m.points[u] - n.points[v]).norm() <= quantization * (1.0 + 1e-9))
            allowed = std::max(allowed, m.errorBudget[u]);
        budgetsOff +=
          n.errorBudget[v] > std::max(0.0, allowed - quantization) + 1e-12 * a.rootEpsilon;
      }
    }
    for (const Vec3& p : n.points)
      pointsOff += NearestDistance(p, m.points) > quantization;
    for (const Vec3& p : m.points)
      pointsOff += NearestDistance(p, n.points) > quantization;
    // Orientation: the original triangle whose corners are nearest to the decoded one's, in
    // one of the three rotations of the same order or of the reversed order; flipped when the
    // best match is reversed.
    for (const Triangle& t : n.triangles)
    {
      double same = std::numeric_limits<double>::infinity(), reversed = same;
      for (const Triangle& u : m.triangles)
        for (int r = 0; r < 3; ++r)
        {
          double d = 0.0, e = 0.0;
          for (int k = 0; k < 3; ++k)
          {
            d += (n.points[t[k]] - m.points[u[(k + r) % 3]]).norm();
            e += (n.points[t[k]] - m.points[u[(r + 3 - k) % 3]]).norm();
          }
          same = std::min(same, d);
          reversed = std::min(reversed, e);
        }
      orientationOff += reversed < same;
    }
  }
  EXPECT(pointsOff == 0,
    name << ": " << pointsOff << " points farther than the quantisation error " << quantization);
  EXPECT(orientationOff == 0, name << ": " << orientationOff << " triangles flipped");
  EXPECT(budgetsOff == 0,
    name << ": " << budgetsOff << " budgets above the original's minus quantisation");
}

/// Encodes, decodes, compares, unfolds and bounds the distance to the input; `symbolsBeside`
/// false writes the points' symbols as a Draco attribute (the first files' layout), `weld`
/// false never welds the leaves' common points, `columns` false writes the tree section's
/// nodes and palette record by record (the first files' layout).
void RoundTrip(const TriangleMesh& input,
  const FoldingTree& tree,
  int bits,
  const char* name,
  bool symbolsBeside = true,
  bool weld = true,
  bool columns = true)
{
  CompactTreeStats stats;
  const std::string bytes = Encode(tree, bits, &stats, symbolsBeside, weld, columns);
  EXPECT(Encode(tree, bits, nullptr, symbolsBeside, weld, columns) == bytes,
    name << ": the same bytes twice");
  const bool beside = (bytes.size() > 6 && (bytes[6] & 2));
  EXPECT(beside == symbolsBeside,
    name << ": symbols " << (beside ? "beside" : "inside") << " the Draco mesh");
  EXPECT(columns || (bytes.size() > 6 && !(bytes[6] & 4)),
    name << ": without columns the tree section is written record by record");
  FoldingTree decoded;
  std::string error;
  double quantization = -1;
  REQUIRE(DecodeCompactTree(bytes, decoded, error, &quantization), name << ": decode: " << error);
  EXPECT(quantization > 0 && quantization <= stats.quantizationError,
    name << ": quantisation error stored");
  EXPECT(stats.bytes == bytes.size() && (bits == 0 || stats.quantizationBits == bits),
    name << ": stats");
  CompareTrees(tree, decoded, stats.quantizationError, name);
  const UnfoldedMesh unfolded = coretest::Unfold(decoded);
  TriangleMesh result;
  result.points = unfolded.points;
  result.triangles = unfolded.triangles;
  const HausdorffBounds bound = SymmetricHausdorffBounds(input, result, 1e-4 * tree.diagonal);
  std::printf("%s (%d bits): %zu bytes, %d stored triangles, quantisation %.3g of epsilon, "
              "proved Hausdorff <= %.4f epsilon\n",
    name,
    stats.quantizationBits,
    bytes.size(),
    tree.StoredFaces(),
    stats.quantizationError / tree.rootEpsilon,
    bound.upper / tree.rootEpsilon);
  EXPECT(bound.upper <= tree.rootEpsilon,
    name << ": unfolded within the root epsilon (" << bound.upper / tree.rootEpsilon
         << " epsilon)");
}

/// User arrays: a per-point float and a per-triangle int array come back byte for byte, the
/// leaves in the same point and triangle order; wrongly sized arrays are refused.
void Arrays(const FoldingTree& tree)
{
  std::vector<CompactArray> arrays(2);
  arrays[0].name = "value";
  arrays[0].elementSize = 4;
  arrays[0].components = 2;
  arrays[1].name = "patch";
  arrays[1].perTriangle = true;
  arrays[1].elementSize = 8;
  int k = 0;
  for (const FoldingNode& node : tree.nodes)
  {
    if (node.kind != FoldingNodeKind::Leaf)
      continue;
    std::vector<float> values;
    for (const Vec3& p : node.mesh.points)
      values.insert(values.end(), { static_cast<float>(p.x()), static_cast<float>(k++) });
    std::vector<int64_t> patches(node.mesh.triangles.size(), k);
    arrays[0].leaves.emplace_back(reinterpret_cast<const char*>(values.data()), values.size() * 4);
    arrays[1].leaves.emplace_back(
      reinterpret_cast<const char*>(patches.data()), patches.size() * 8);
  }
  std::string bytes, error;
  CompactTreeStats stats;
  REQUIRE(EncodeCompactTree(tree, CompactTreeOptions(), bytes, &stats, error, &arrays),
    "encode with arrays: " << error);
  FoldingTree decoded;
  std::vector<CompactArray> back;
  REQUIRE(
    DecodeCompactTree(bytes, decoded, error, nullptr, &back), "decode with arrays: " << error);
  EXPECT(back.size() == 2 && back[0].name == "value" && back[1].name == "patch" &&
      back[0].components == 2 && back[1].perTriangle && back[0].leaves == arrays[0].leaves &&
      back[1].leaves == arrays[1].leaves,
    "arrays come back byte for byte");
  bool ordered = true;
  for (size_t i = 0; i < tree.nodes.size(); ++i)
    ordered = ordered && decoded.nodes[i].mesh.triangles == tree.nodes[i].mesh.triangles;
  EXPECT(ordered, "with arrays the leaves keep their triangles' order");
  std::printf("arrays: %zu bytes (%zu of them the arrays section), %zu without\n",
    bytes.size(),
    stats.arrayBytes,
    Encode(tree, 0).size());
  arrays[1].leaves[0].pop_back();
  EXPECT(!EncodeCompactTree(tree, CompactTreeOptions(), bytes, nullptr, error, &arrays) &&
      !error.empty(),
    "a wrongly sized array is refused");
}

void BadInput(const FoldingTree& tree)
{
  const std::string good = Encode(tree, 0);
  // Truncations (every length on a small file).
  int accepted = 0;
  for (size_t n = 0; n < good.size(); n += std::max<size_t>(1, good.size() / 400))
  {
    FoldingTree t;
    std::string error;
    accepted += DecodeCompactTree(good.substr(0, n), t, error);
  }
  EXPECT(accepted == 0, "truncated files: " << accepted << " accepted");
  // Flipped bytes: the checksum catches them.
  std::mt19937 random(7);
  accepted = 0;
  for (int k = 0; k < 200; ++k)
  {
    std::string bad = good;
    bad[random() % bad.size()] ^= static_cast<char>(1 + random() % 255);
    FoldingTree t;
    std::string error;
    accepted += DecodeCompactTree(bad, t, error);
  }
  EXPECT(accepted == 0, "flipped bytes: " << accepted << " accepted");
  // Flipped bytes behind a valid checksum: in the geometry section (Draco) and in the tree
  // section; they may decode to another valid tree, but must never crash, and whatever decodes
  // must validate.
  int rejected = 0, total = 0;
  const std::string raw = TreeSection(good);
  for (int k = 0; k < 300; ++k, ++total)
  {
    std::string bad;
    if (k % 2)
    {
      bad = good;
      bad[16 + random() % (bad.size() - 20)] ^= static_cast<char>(1 + random() % 255);
      Reseal(bad);
    }
    else
    {
      std::string r = raw;
      r[random() % r.size()] ^= static_cast<char>(1 + random() % 255);
      bad = WithTreeSection(good, r);
    }
    FoldingTree t;
    std::string error;
    if (!DecodeCompactTree(bad, t, error))
      ++rejected;
    else
      EXPECT(t.Validate().empty(), "a corrupted file decoded to an invalid tree");
  }
  std::printf(
    "fuzz: %d of %d corrupted files behind a valid checksum rejected, the rest valid trees\n",
    rejected,
    total);
  EXPECT(rejected > total / 4, "most corrupted files are rejected");
  // Another version, another magic number.
  std::string version = good;
  version[4] = 9;
  Reseal(version);
  Rejected(version, "format version 9");
  // The symbols' layout flag switched: Draco's attribute is missing, or the tree section has
  // bytes left over.
  std::string layout = good;
  layout[6] ^= 2;
  Reseal(layout);
  Rejected(layout, "the symbols' layout flag switched");
  std::string columns = good;
  columns[6] ^= 4;
  Reseal(columns);
  Rejected(columns, "the column flag switched");
  std::string unknown = good;
  unknown[6] |= 8;
  Reseal(unknown);
  Rejected(unknown, "an unknown flag");
  std::string magic = good;
  magic[0] = 'X';
  Rejected(magic, "another magic number");
  Rejected(std::string(), "an empty file");
  Rejected("FMZ\x1a", "a header only");
  // Huge counts: the node count (after the fixed fields) set to 2^40.
  std::string huge = raw;
  size_t at = 0;
  for (int k = 0; k < 3; ++k) // three varints of counts
    while (static_cast<uint8_t>(huge[at++]) & 0x80)
      ;
  at += 8 * 3 + 1 + 8 * 4 + 1; // area, diagonal, epsilon, aborted, grid, bits
  std::string varint;
  for (uint64_t v = uint64_t(1) << 40; v >= 0x80; v >>= 7)
    varint += static_cast<char>((v & 0x7f) | 0x80);
  varint += static_cast<char>(0x2);
  size_t end = at;
  while (static_cast<uint8_t>(huge[end++]) & 0x80)
    ;
  huge.replace(at, end - at, varint);
  Rejected(WithTreeSection(good, huge), "a node count of 2^40");
  // Encoding errors.
  CompactTreeOptions options;
  options.quantizationBits = 30;
  std::string bytes, error;
  EXPECT(!EncodeCompactTree(tree, options, bytes, nullptr, error) && !error.empty(),
    "30 quantisation bits rejected");
  FoldingTree invalid = tree;
  invalid.rootEpsilon = -1;
  options.quantizationBits = 0;
  EXPECT(!EncodeCompactTree(invalid, options, bytes, nullptr, error) && !error.empty(),
    "an invalid tree is not encoded");
  EXPECT(!EncodeCompactTree(FoldingTree(), options, bytes, nullptr, error),
    "an empty tree is not encoded");
}
}

/// Fans of 5, 6 and 12 triangles about a centre, moved, folded with rotation nodes (the root a
/// rotation node, one face stored): written at 8 bits (the pole then lies off the axis by up to
/// the quantisation error) and read back, they unfold with one pole and their own faces and
/// area, within the root epsilon.
void RotationFans()
{
  for (int n : { 5, 6, 12 })
    for (unsigned seed : { 3u, 8u, 203u, 208u })
    {
      // Seeds 3, 8: a rotation about a random axis and a shift; 203, 208: rotationtest::Motion
      // (its fan of 12 at seed 203 read back with its pole split in two, before the unfolder
      // moved a pole near the axis onto it).
      TriangleMesh fan = rotationtest::MakeFan(n);
      if (seed > 200)
      {
        const Eigen::Isometry3d motion = rotationtest::Motion(seed);
        for (Vec3& p : fan.points)
          p = motion * p;
      }
      else
      {
        std::mt19937 g(seed);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        const Eigen::Matrix3d turn =
          Eigen::AngleAxisd(3.0 * u(g), Vec3(u(g), u(g), u(g)).normalized()).toRotationMatrix();
        const Vec3 shift(5.0 * u(g), 5.0 * u(g), 5.0 * u(g));
        for (Vec3& p : fan.points)
          p = turn * p + shift;
      }
      FoldingTreeOptions options;
      options.rotationNodes = true;
      options.useMinimumFaces = false;
      const FoldingTree tree = coretest::Fold(fan, 0.02 * coretest::Diagonal(fan), options);
      const std::string name = "fan of " + std::to_string(n) + ", seed " + std::to_string(seed);
      REQUIRE(!tree.nodes.empty() && tree.nodes[0].kind == FoldingNodeKind::Rotation,
        name << ": the root is not a rotation node");
      RoundTrip(fan, tree, 8, name.c_str());
      FoldingTree decoded;
      std::string error;
      REQUIRE(DecodeCompactTree(Encode(tree, 8), decoded, error), name << ": decode: " << error);
      const UnfoldedMesh unfolded = coretest::Unfold(decoded);
      const double area = coretest::SurfaceArea(unfolded.points, unfolded.triangles);
      const double expected = 0.5 * n * std::sin(2.0 * EIGEN_PI / n);
      EXPECT(static_cast<int>(unfolded.triangles.size()) == n &&
          static_cast<int>(unfolded.points.size()) == n + 1 &&
          std::abs(area / expected - 1.0) < 0.01,
        name << " at 8 bits: " << unfolded.triangles.size() << " faces, " << unfolded.points.size()
             << " points, area ratio " << area / expected);
    }
}

/// A vase whose rings are turned against each other (12 segments, caps with poles), folded with
/// rotation nodes: a sector cut along its half-planes, whose k turned copies the unfolder thins
/// within the points' error budgets. The points below a rotation node carry budget levels in
/// the file, so the decoded tree unfolds to about the faces of the tree in memory (1,108 faces
/// for 1,050; with the leaf's smallest budget for every point 1,266, which fails the check),
/// within the root epsilon (RoundTrip).
void RotationSectorBudgets()
{
  rotationtest::VaseShape s;
  s.staggered = 1.0;
  const TriangleMesh m = rotationtest::MakeVase(s, 12, 24);
  FoldingTreeOptions options;
  options.rotationNodes = true;
  const FoldingTree tree = coretest::Fold(m, 0.02 * coretest::Diagonal(m), options);
  REQUIRE(!tree.nodes.empty() && tree.nodes[0].kind == FoldingNodeKind::Rotation,
    "staggered vase: the root is not a rotation node");
  RoundTrip(m, tree, 0, "staggered vase");
  FoldingTree decoded;
  std::string error;
  REQUIRE(DecodeCompactTree(Encode(tree, 0), decoded, error), "staggered vase: " << error);
  const size_t inMemory = coretest::Unfold(tree).triangles.size();
  const size_t readBack = coretest::Unfold(decoded).triangles.size();
  std::printf("staggered vase: %zu faces, unfolded %zu in memory, %zu read back\n",
    m.triangles.size(),
    inMemory,
    readBack);
  EXPECT(readBack <= 1.1 * inMemory,
    "staggered vase: read back it unfolds to " << readBack << " faces, in memory " << inMemory);
}

/// The automatic bits keep the quantisation error within half of every segmentation node's
/// epsilon (its seams' stitch tolerance for two copies rounded apart), unless
/// segmentationSeamBits is off (a caller that proves its file), which never takes more bits.
void SegmentationSeamBits(const FoldingTree& tree, const char* name)
{
  double seams = std::numeric_limits<double>::infinity();
  for (const FoldingNode& node : tree.nodes)
    if (node.kind == FoldingNodeKind::Segmentation && node.children.size() > 1)
      seams = std::min(seams, 0.5 * node.epsilon);
  CompactTreeOptions options;
  CompactTreeStats with, without;
  std::string bytes, error;
  REQUIRE(EncodeCompactTree(tree, options, bytes, &with, error), name << ": " << error);
  options.segmentationSeamBits = false;
  REQUIRE(EncodeCompactTree(tree, options, bytes, &without, error), name << ": " << error);
  std::printf("%s: %d bits (error %.3g of the smallest segmentation epsilon's half %.3g), %d "
              "without the seams' rule\n",
    name,
    with.quantizationBits,
    with.quantizationError,
    seams,
    without.quantizationBits);
  // stats.quantizationError adds the planes' rounding (PlaneError), far below a bit's step.
  EXPECT(with.quantizationBits == MaximumQuantizationBits ||
      with.quantizationError <= seams + 1e-5 * tree.diagonal,
    name << ": quantisation error " << with.quantizationError << " above " << seams);
  EXPECT(
    without.quantizationBits <= with.quantizationBits, name << ": the seams' rule took fewer bits");
  // The rule binds: the same tree with its segmentations' epsilons a tenth (a tighter stitch)
  // takes more bits with the rule, the same without it.
  if (!std::isfinite(seams))
    return;
  FoldingTree tighter = tree;
  for (FoldingNode& node : tighter.nodes)
    if (node.kind == FoldingNodeKind::Segmentation && node.parent >= 0) // the root's is the tree's
      node.epsilon *= 0.1;
  REQUIRE(tighter.Validate().empty(), name << ": tighter tree: " << tighter.Validate());
  CompactTreeStats tight, tightWithout;
  options.segmentationSeamBits = true;
  REQUIRE(EncodeCompactTree(tighter, options, bytes, &tight, error), name << ": " << error);
  options.segmentationSeamBits = false;
  REQUIRE(EncodeCompactTree(tighter, options, bytes, &tightWithout, error), name << ": " << error);
  std::printf("%s, segmentations' epsilons a tenth: %d bits, %d without the seams' rule\n",
    name,
    tight.quantizationBits,
    tightWithout.quantizationBits);
  EXPECT(tight.quantizationBits > with.quantizationBits &&
      tightWithout.quantizationBits == without.quantizationBits,
    name << ": the seams' rule did not follow the segmentations' epsilon");
}

int main()
{
  RotationFans();
  RotationSectorBudgets();
  struct Case
  {
    const char* name;
    pm::ProceduralMesh mesh;
    double minimumAreaFraction;
  };
  pm::ProceduralMesh moved = pm::MakeBilateralBlob(3000, 3);
  pm::ApplyRigidMotion(moved, pm::RandomRigidMotion(11));
  std::vector<Case> cases;
  cases.push_back({ "three-plane shape", pm::MakeThreePlaneShape(3000), 0.13 });
  cases.push_back({ "blob with attachment", pm::MakeBlobWithAsymmetricPart(3000, 0.1, 2), 0.05 });
  cases.push_back({ "moved bilateral blob", moved, 0.05 });
  FoldingTree first, columned; // the first tree; the first whose tree section is in columns
  for (const Case& c : cases)
  {
    const TriangleMesh input = coretest::ToTriangleMesh(c.mesh.mesh);
    FoldingTreeOptions options;
    options.minimumAreaFraction = c.minimumAreaFraction;
    const FoldingTree tree = coretest::Fold(input, 0.02 * pm::BoundsDiagonal(c.mesh.mesh), options);
    EXPECT(tree.NumberOfFolds() >= 1, c.name << ": folded");
    RoundTrip(input, tree, 0, c.name);
    RoundTrip(input, tree, 8, c.name);
    RoundTrip(input, tree, 0, c.name, false);
    RoundTrip(input, tree, 0, c.name, true, false);
    RoundTrip(input, tree, 0, c.name, true, true, false);
    const std::string smaller = Encode(tree, 0);
    const size_t records = Encode(tree, 0, nullptr, true, true, false).size();
    std::printf("%s: %zu bytes with the tree section %s, %zu record by record\n",
      c.name,
      smaller.size(),
      (smaller[6] & 4) ? "field by field" : "record by record",
      records);
    EXPECT(smaller.size() <= records, c.name << ": trying both layouts never costs bytes");
    const size_t welded = Encode(tree, 0).size();
    const size_t separate = Encode(tree, 0, nullptr, true, false).size();
    std::printf("%s: %zu bytes with the leaves' common points welded, %zu without\n",
      c.name,
      welded,
      separate);
    int leaves = 0;
    for (const FoldingNode& node : tree.nodes)
      leaves += node.kind == FoldingNodeKind::Leaf;
    EXPECT(leaves > 1 ? welded < separate : welded == separate,
      c.name << ": " << leaves << " leaves, welded " << welded << " bytes, separate " << separate);
    EXPECT(Encode(tree, 0).size() < Encode(tree, 0, nullptr, false).size(),
      c.name << ": symbols beside the Draco mesh take fewer bytes");
    EXPECT(Encode(tree, 8).size() < Encode(tree, 16).size(), c.name << ": fewer bits, fewer bytes");
    SegmentationSeamBits(tree, c.name);
    if (first.Empty())
      first = tree;
    if (columned.Empty() && (smaller[6] & 4))
      columned = tree;
  }
  // A single-leaf tree (no fold allowed).
  const TriangleMesh sphere = coretest::ToTriangleMesh(pm::MakeSphere(2000).mesh);
  FoldingTreeOptions noFolds;
  noFolds.maximumFolds = 0;
  const FoldingTree leaf =
    coretest::Fold(sphere, 0.02 * pm::BoundsDiagonal(pm::MakeSphere(2000).mesh), noFolds);
  EXPECT(leaf.NumberOfNodes() == 1, "maximumFolds 0: a single leaf");
  RoundTrip(sphere, leaf, 0, "single leaf");
  Arrays(first);
  BadInput(first);
  REQUIRE(!columned.Empty(), "no tree was written field by field");
  BadInput(columned); // the column reader against the same corruptions
  return coretest::Finish("TestCompactTreeFormat");
}
