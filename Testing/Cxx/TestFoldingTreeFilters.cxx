// vtkFoldingTreeBuilder and vtkFoldingTreeUnfolder (the VTK layer over the core folding tree)
// on procedural meshes carrying a point scalar, a cell scalar and a 3-component point vector
// (the position, which every mirror plane through the origin maps like the geometry):
// - output 0 is a vtkMultiBlockDataSet laid out as documented in vtkFoldingTreeBuilder.h:
//   top level (root node, "Tree"), block names "Leaf i" / "Fold i (depth d)" /
//   "Segmentation i (depth d)" / "Plane" / "Node", node kinds, depths, epsilon halved below
//   every fold and kept below segmentation nodes, root epsilon = 2% of the diagonal, Tree
//   statistics; expected shapes: the three-plane shape (MinimumAreaFraction 0.13) folds three
//   times into one leaf storing about 1/8, the bilateral blob (MaximumFolds 1) once, the blob
//   with an asymmetric attachment becomes a segmentation node whose first child is a fold;
// - leaves carry the input arrays with the values of their original ids, the tree arrays
//   (OriginalPointId, TearMask/PlaneMask as vtkTypeUInt64Array, Projected, OriginalCellId);
// - output 1: FoldingLeafId / FoldingDepth / FoldingRole consistent with the leaves;
// - .vtm round trip: the tree written with vtkXMLMultiBlockDataWriter, in inline binary mode (what
//   the project writes) and in the writer's default appended mode (what ParaView and users
//   write; unreadable by VTK 9.2's own reader on a current expat, VTK issue 19258), and read
//   back with vtkExpatSafeXMLMultiBlockDataReader without an error, unfolds to exactly the same
//   mesh (points, cells, every array) as the tree in memory;
// - unfold(fold(M)) is within the root epsilon of M (vertex-to-surface distances both ways
//   with vtkStaticCellLocator), closed where stitched for the exactly symmetric shapes, with
//   the carried scalars equal to the input's at the original ids and the vector reflected on
//   mirrored copies (|v - position| small, while an unreflected copy would be far off);
// - malformed trees (a fold's plane metadata removed, a leaf replaced by vtkImageData, a node
//   kind changed) and bad builder input (empty mesh) fail with an ErrorEvent.
// The tree-walking and comparison helpers are in TestFoldingTreeChecks.cxx, the bad-input tests
// in TestFoldingTreeMalformed.cxx.
#include "TestFoldingTreeChecks.h"
#include "vtkExpatSafeXMLMultiBlockDataReader.h"
#include "vtkFoldingTreeBuilder.h"
#include "vtkFoldingTreeIO.h"
#include "vtkFoldingTreeUnfolder.h"

#include <vtkCallbackCommand.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkTypeUInt64Array.h>
#include <vtkXMLMultiBlockDataWriter.h>

#include <bitset>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace foldingtreetest;

namespace
{
struct Case
{
  std::string label;
  pm::ProceduralMesh shape;
  std::function<void(vtkFoldingTreeBuilder*)> configure;
  std::function<void(const std::vector<NodeInfo>&)> structure;
  bool exactlySymmetric = true;    // closed after stitching is required
  bool planesThroughOrigin = true; // the "Position" point vector must follow the geometry
  int maximumCopies = 0;           // most copies of one leaf (0: not checked)
};

vtkSmartPointer<vtkMultiBlockDataSet> RunCase(const Case& c, const std::string& tempDir)
{
  vtkSmartPointer<vtkPolyData> input = WithArrays(c.shape.mesh);
  vtkNew<vtkFoldingTreeBuilder> builder;
  builder->SetInputData(input);
  if (c.configure)
    c.configure(builder);
  EventLog log;
  const int status = UpdateCapturing(builder, log);
  EXPECT(status == 1 && log.errors.empty(),
    c.label << ": build failed: " << (log.errors.empty() ? "" : log.errors[0]));
  auto tree = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  tree->ShallowCopy(vtkMultiBlockDataSet::SafeDownCast(builder->GetOutputDataObject(0)));
  vtkPolyData* segmentation = vtkPolyData::SafeDownCast(builder->GetOutputDataObject(1));
  if (status != 1 || tree->GetNumberOfBlocks() != 2 || !segmentation)
  {
    EXPECT(false, c.label << ": no tree");
    return tree;
  }

  // Top level and Tree statistics.
  EXPECT(BlockName(tree, 1) && std::string(BlockName(tree, 1)) == "Tree",
    c.label << ": block 1 not named Tree");
  vtkPolyData* info = vtkPolyData::SafeDownCast(tree->GetBlock(1));
  EXPECT(info, c.label << ": Tree block is not polydata");
  if (!info)
    return tree;
  vtkFieldData* fd = info->GetFieldData();
  const double diagonal = FieldValue(fd, "Diagonal");
  const double rootEpsilon = FieldValue(fd, "RootEpsilon");
  const double originalFaces = FieldValue(fd, "OriginalFaces");
  const double storedFaces = FieldValue(fd, "StoredFaces");
  const double compression = FieldValue(fd, "Compression");
  EXPECT(std::abs(diagonal - pm::BoundsDiagonal(input)) <= 1e-9 * diagonal,
    c.label << ": Diagonal " << diagonal);
  // The requested epsilon, or after a near-miss rebuild of the proof (VerifyBound) a little
  // less; RequestedEpsilon is always the requested one.
  const double requested = FieldValue(fd, "RequestedEpsilon");
  const double rounds = FieldValue(fd, "VerificationRounds");
  EXPECT(std::abs(requested - 0.02 * diagonal) <= 1e-9 * diagonal,
    c.label << ": RequestedEpsilon " << requested);
  EXPECT(std::abs(rootEpsilon - requested) <= 1e-9 * diagonal ||
      (rounds >= 1 && rootEpsilon < requested && rootEpsilon >= 0.97 / 1.25 * requested),
    c.label << ": RootEpsilon " << rootEpsilon << " of the requested " << requested);
  EXPECT(
    originalFaces == input->GetNumberOfCells(), c.label << ": OriginalFaces " << originalFaces);
  EXPECT(std::abs(compression - (1.0 - storedFaces / originalFaces)) < 1e-12,
    c.label << ": Compression " << compression);
  for (const char* name : { "TreeHeight", "BuildSeconds", "StoredPoints", "NumberOfLeaves" })
    EXPECT(std::isfinite(FieldValue(fd, name)), c.label << ": Tree has no " << name);
  std::printf("%s: %g faces -> %g stored (compression %.3f), height %g, %g leaves, %.3f s\n",
    c.label.c_str(),
    originalFaces,
    storedFaces,
    compression,
    FieldValue(fd, "TreeHeight"),
    FieldValue(fd, "NumberOfLeaves"),
    FieldValue(fd, "BuildSeconds"));

  // Node blocks.
  std::vector<NodeInfo> nodes;
  const char* rootName = BlockName(tree, 0);
  Walk(tree->GetBlock(0), rootName ? rootName : "", 0, 0.0, -1, nodes, c.label);
  EXPECT(!nodes.empty() && std::abs(nodes[0].epsilon - rootEpsilon) <= 1e-12 * rootEpsilon,
    c.label << ": root epsilon");
  int leaves = 0;
  long long leafFaces = 0;
  for (const NodeInfo& n : nodes)
    if (n.leaf)
    {
      ++leaves;
      leafFaces += n.leaf->GetNumberOfCells();
    }
  EXPECT(leaves == FieldValue(fd, "NumberOfLeaves") && leafFaces == storedFaces,
    c.label << ": " << leaves << " leaves with " << leafFaces << " faces");
  if (c.structure)
    c.structure(nodes);
  CheckLeafArrays(nodes, input, c.label);

  // Detection statistics per node: starts tried and wall time, within the build time.
  {
    foldingmeshes::FoldingTree decoded;
    std::string error;
    EXPECT(foldingmeshes::MultiBlockToFoldingTree(tree, decoded, error),
      c.label << ": tree not decodable: " << error);
    double detectionSeconds = 0.0;
    int detections = 0;
    for (const foldingmeshes::FoldingNode& node : decoded.nodes)
    {
      if (node.detectionRun)
      {
        ++detections;
        detectionSeconds += node.detectionSeconds;
      }
      EXPECT(node.detectionRun ? node.detectionStarts >= 1 && node.detectionSeconds >= 0.0 &&
            std::isfinite(node.detectionSeconds)
                               : node.detectionStarts == 0 && node.detectionSeconds == 0.0,
        c.label << ": node " << node.depth << " detection " << node.detectionRun << " starts "
                << node.detectionStarts << " seconds " << node.detectionSeconds);
    }
    EXPECT(detections >= 1 || decoded.nodes.size() == 1, c.label << ": no detection recorded");
    EXPECT(detectionSeconds <= FieldValue(fd, "BuildSeconds") + 1e-6,
      c.label << ": detections " << detectionSeconds << " s > build "
              << FieldValue(fd, "BuildSeconds") << " s");
  }

  // Output 1.
  vtkDataArray* leafId = segmentation->GetCellData()->GetArray("FoldingLeafId");
  vtkDataArray* depth = segmentation->GetCellData()->GetArray("FoldingDepth");
  vtkDataArray* role = segmentation->GetCellData()->GetArray("FoldingRole");
  EXPECT(leafId && depth && role && segmentation->GetCellData()->GetArray("Label"),
    c.label << ": output 1 arrays missing");
  if (leafId && depth && role)
  {
    std::map<int, int> leafDepth;
    for (const NodeInfo& n : nodes)
      if (n.leaf)
        leafDepth[n.index] = n.depth;
    // Depths of the folding nodes above each leaf: a mirrored-away face must name a leaf
    // below the fold that removed it.
    std::map<int, std::set<int>> foldDepthsAbove;
    std::function<void(int, std::set<int>)> descend = [&](int position, std::set<int> folds)
    {
      const NodeInfo& n = nodes[position];
      if (n.leaf)
        foldDepthsAbove[n.index] = folds;
      if (n.kind == 1)
        folds.insert(n.depth);
      for (int child : n.children)
        descend(child, folds);
    };
    if (!nodes.empty())
      descend(0, {});
    int kept = 0, mirrored = 0, bad = 0;
    for (vtkIdType f = 0; f < segmentation->GetNumberOfCells(); ++f)
    {
      const int r = static_cast<int>(role->GetTuple1(f));
      const int l = static_cast<int>(leafId->GetTuple1(f));
      if (r == 0 || r == 2)
      {
        ++kept;
        bad += !leafDepth.count(l) || leafDepth[l] != depth->GetTuple1(f);
      }
      else if (r == 1)
      {
        ++mirrored;
        const int d = static_cast<int>(depth->GetTuple1(f));
        bad += !leafDepth.count(l) || !foldDepthsAbove[l].count(d);
      }
      else
        bad += r != -1 || l != -1;
    }
    EXPECT(bad == 0, c.label << ": " << bad << " inconsistent output-1 cells");
    EXPECT(kept == storedFaces, c.label << ": " << kept << " kept cells, stored " << storedFaces);
    EXPECT(mirrored > 0, c.label << ": no mirrored-away cells");
  }

  // Unfold in memory and after a .vtm round trip in both binary data modes.
  vtkNew<vtkFoldingTreeUnfolder> unfolder;
  unfolder->SetInputData(tree);
  EventLog log1;
  EXPECT(UpdateCapturing(unfolder, log1) == 1 && log1.errors.empty(),
    c.label << ": unfold failed: " << (log1.errors.empty() ? "" : log1.errors[0]));
  vtkPolyData* unfolded = unfolder->GetOutput();
  for (const bool appended : { false, true })
  {
    const std::string mode = appended ? "appended" : "binary";
    const std::string file = tempDir + "/TestFoldingTreeFilters_" +
      std::to_string(std::hash<std::string>()(c.label) % 100000) + "_" + mode + ".vtm";
    vtkNew<vtkXMLMultiBlockDataWriter> writer;
    writer->SetInputData(tree);
    writer->SetFileName(file.c_str());
    if (appended)
      writer->SetDataModeToAppended();
    else
      writer->SetDataModeToBinary();
    EXPECT(writer->Write() == 1, c.label << ": could not write " << file);
    vtkNew<vtkExpatSafeXMLMultiBlockDataReader> reader;
    reader->SetFileName(file.c_str());
    EventLog readLog;
    const int readStatus = UpdateCapturing(reader, readLog);
    EXPECT(readStatus == 1 && readLog.errors.empty(),
      c.label << ": reading the " << mode
              << " .vtm failed: " << (readLog.errors.empty() ? "" : readLog.errors[0]));
    vtkMultiBlockDataSet* readBack = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput());
    EXPECT(readBack, c.label << ": nothing read back from the " << mode << " .vtm");
    if (readStatus != 1 || !readLog.errors.empty() || !readBack)
      continue;
    // The read-back tree has the same structure and names.
    std::vector<NodeInfo> readNodes;
    const char* name = BlockName(readBack, 0);
    Walk(readBack->GetBlock(0), name ? name : "", 0, 0.0, -1, readNodes, c.label + " (read)");
    EXPECT(readNodes.size() == nodes.size(),
      c.label << ": read-back tree has " << readNodes.size() << " nodes");
    CompareTrees(tree, readBack, c.label + " (" + mode + " vtm)");
    vtkNew<vtkFoldingTreeUnfolder> unfolderRead;
    unfolderRead->SetInputData(readBack);
    EventLog log2;
    EXPECT(UpdateCapturing(unfolderRead, log2) == 1 && log2.errors.empty(),
      c.label << ": unfold of the read-back tree failed: "
              << (log2.errors.empty() ? "" : log2.errors[0]));
    ExpectIdentical(unfolded, unfolderRead->GetOutput(), c.label + " (" + mode + " vtm)");
  }

  // unfold(fold(M)) against M.
  const double toOriginal = MaximumVertexDistance(unfolded, input);
  const double fromOriginal = MaximumVertexDistance(input, unfolded);
  int open = 0, nonManifold = 0;
  CountEdges(unfolded, open, nonManifold);
  vtkFieldData* ufd = unfolded->GetFieldData();
  std::printf("%s: unfolded %lld points / %lld faces (input %lld / %lld), distance %.3g / %.3g "
              "of epsilon, open %d, non-manifold %d, gaps %g (length %g), stitched %g\n",
    c.label.c_str(),
    static_cast<long long>(unfolded->GetNumberOfPoints()),
    static_cast<long long>(unfolded->GetNumberOfCells()),
    static_cast<long long>(input->GetNumberOfPoints()),
    static_cast<long long>(input->GetNumberOfCells()),
    toOriginal / rootEpsilon,
    fromOriginal / rootEpsilon,
    open,
    nonManifold,
    FieldValue(ufd, "OpenGapCount"),
    FieldValue(ufd, "OpenGapLength"),
    FieldValue(ufd, "StitchedVertices"));
  EXPECT(toOriginal <= rootEpsilon && fromOriginal <= rootEpsilon,
    c.label << ": unfold(fold(M)) is " << toOriginal << " / " << fromOriginal << " from M, epsilon "
            << rootEpsilon);
  EXPECT(open == FieldValue(ufd, "OpenEdges") && nonManifold == FieldValue(ufd, "NonManifoldEdges"),
    c.label << ": reported open/non-manifold edges differ from the mesh's");
  if (c.exactlySymmetric)
    EXPECT(open == 0 && nonManifold == 0, c.label << ": stitched result not closed");
  EXPECT(
    FieldValue(ufd, "UnfoldedFaces") == unfolded->GetNumberOfCells(), c.label << ": UnfoldedFaces");
  for (const char* name : { "StitchedVertices", "OpenGapCount", "OpenGapLength" })
    EXPECT(std::isfinite(FieldValue(ufd, name)), c.label << ": no field " << name);

  // Carried arrays.
  vtkPointData* pd = unfolded->GetPointData();
  vtkCellData* cd = unfolded->GetCellData();
  vtkDataArray* ids = pd->GetArray("OriginalPointId");
  vtkDataArray* temperature = pd->GetArray("Temperature");
  vtkDataArray* position = pd->GetArray("Position");
  vtkDataArray* cids = cd->GetArray("OriginalCellId");
  vtkDataArray* label = cd->GetArray("Label");
  vtkDataArray* mirroredFlag = cd->GetArray("FoldingMirrored");
  EXPECT(ids && temperature && position && cids && label && mirroredFlag &&
      cd->GetArray("FoldingLeafId") && cd->GetArray("FoldingCopy"),
    c.label << ": unfolded arrays missing");
  EXPECT(!pd->GetArray("TearMask") && !pd->GetArray("PlaneMask"),
    c.label << ": builder-internal masks carried to the unfolded mesh");
  if (ids && temperature && position && cids && label && mirroredFlag)
  {
    vtkDataArray* inT = input->GetPointData()->GetArray("Temperature");
    vtkDataArray* inL = input->GetCellData()->GetArray("Label");
    int bad = 0, mirroredFaces = 0;
    vtkNew<vtkIdList> cellPoints;
    double vectorError = 0.0, mirroredVectorError = 0.0;
    for (vtkIdType i = 0; i < unfolded->GetNumberOfPoints(); ++i)
    {
      bad += temperature->GetTuple1(i) != inT->GetTuple1(static_cast<vtkIdType>(ids->GetTuple1(i)));
      double p[3], v[3];
      unfolded->GetPoint(i, p);
      position->GetTuple(i, v);
      vectorError = std::max(vectorError, (Vec3(p) - Vec3(v)).norm());
    }
    for (vtkIdType f = 0; f < unfolded->GetNumberOfCells(); ++f)
    {
      bad += label->GetTuple1(f) != inL->GetTuple1(static_cast<vtkIdType>(cids->GetTuple1(f)));
      if (mirroredFlag->GetTuple1(f) != 0)
      {
        ++mirroredFaces;
        unfolded->GetCellPoints(f, cellPoints);
        for (vtkIdType k = 0; k < cellPoints->GetNumberOfIds(); ++k)
        {
          double p[3], v[3];
          unfolded->GetPoint(cellPoints->GetId(k), p);
          position->GetTuple(cellPoints->GetId(k), v);
          mirroredVectorError = std::max(mirroredVectorError, (Vec3(p) - Vec3(v)).norm());
        }
      }
    }
    // Cell vectors: the carried input face normal follows the face (multiplied by the copy's
    // linear map: reflected on mirrored copies, whose triangles are also reversed), checked
    // against the normal of the unfolded triangle; an unreflected normal would be off by the
    // reflection. The id-like 3-component array is copied unchanged.
    vtkDataArray* normal = cd->GetArray("FaceNormal");
    vtkDataArray* tripleId = cd->GetArray("TripleId");
    vtkDataArray* inTriple = input->GetCellData()->GetArray("TripleId");
    vtkDataArray* filled = cd->GetArray("FoldingFilled");
    EXPECT(normal && tripleId && filled, c.label << ": cell vector arrays not carried");
    int checked = 0, aligned = 0, mirroredChecked = 0, mirroredAligned = 0;
    int unreflectedAligned = 0;
    for (vtkIdType f = 0; normal && tripleId && filled && f < unfolded->GetNumberOfCells(); ++f)
    {
      double t[3], u[3], v[3];
      tripleId->GetTuple(f, t);
      inTriple->GetTuple(static_cast<vtkIdType>(cids->GetTuple1(f)), u);
      bad += t[0] != u[0] || t[1] != u[1] || t[2] != u[2];
      const Vec3 n = FaceNormal(unfolded, f);
      if (filled->GetTuple1(f) != 0 || n.norm() == 0.0)
        continue;
      normal->GetTuple(f, v);
      const bool ok = n.dot(Vec3(v)) > 0.9;
      ++checked;
      aligned += ok;
      if (mirroredFlag->GetTuple1(f) != 0)
      {
        ++mirroredChecked;
        mirroredAligned += ok;
        // Control: the input's (unreflected) normal of the same face.
        vtkDataArray* inNormal = input->GetCellData()->GetArray("FaceNormal");
        inNormal->GetTuple(static_cast<vtkIdType>(cids->GetTuple1(f)), v);
        unreflectedAligned += n.dot(Vec3(v)) > 0.9;
      }
    }
    std::printf("%s: carried face normals aligned on %d / %d faces (%d / %d mirrored; "
                "unreflected input normals would be aligned on %d)\n",
      c.label.c_str(),
      aligned,
      checked,
      mirroredAligned,
      mirroredChecked,
      unreflectedAligned);
    // Exact folds keep every face; approximate ones (projected fold lines, stitched and
    // smoothed seams) tilt a few percent of the faces.
    const double fraction = c.exactlySymmetric ? 0.99 : 0.93;
    EXPECT(mirroredChecked > 0 && aligned >= fraction * checked &&
        mirroredAligned >= fraction * mirroredChecked &&
        unreflectedAligned < mirroredAligned - 0.2 * mirroredChecked,
      c.label << ": cell vector array not reflected with the geometry");
    // Copies: FoldingMirrored is the parity of FoldingMirrorMask, copy 0 is the stored leaf.
    auto* masks = vtkTypeUInt64Array::SafeDownCast(cd->GetAbstractArray("FoldingMirrorMask"));
    vtkDataArray* copies = cd->GetArray("FoldingCopy");
    EXPECT(masks && copies, c.label << ": FoldingMirrorMask / FoldingCopy missing");
    int badCopies = 0, maxCopy = 0;
    for (vtkIdType f = 0; masks && copies && f < unfolded->GetNumberOfCells(); ++f)
    {
      const uint64_t mask = masks->GetValue(f);
      const int parity = static_cast<int>(std::bitset<64>(mask).count() % 2);
      badCopies += parity != mirroredFlag->GetTuple1(f);
      badCopies += (copies->GetTuple1(f) == 0) != (mask == 0);
      maxCopy = std::max(maxCopy, static_cast<int>(copies->GetTuple1(f)));
    }
    EXPECT(badCopies == 0, c.label << ": " << badCopies << " inconsistent copy records");
    EXPECT(maxCopy + 1 == c.maximumCopies || c.maximumCopies == 0,
      c.label << ": " << maxCopy + 1 << " copies of a leaf, expected " << c.maximumCopies);
    EXPECT(bad == 0, c.label << ": " << bad << " carried scalar values differ from the input");
    EXPECT(mirroredFaces > 0, c.label << ": no mirrored faces");
    // When the planes pass (nearly) through the origin, the position vector mapped by the
    // copy's linear map stays within a couple of epsilons of the mapped position.
    EXPECT(!c.planesThroughOrigin || vectorError <= 2.0 * rootEpsilon,
      c.label << ": vector array not reflected with the geometry (error " << vectorError
              << ", on mirrored faces " << mirroredVectorError << ")");
  }
  return tree;
}
}

/// Progress events are sent; aborting from the first one keeps a valid, flagged tree.
void TestProgressAndAbort()
{
  pm::ProceduralMesh shape = pm::MakeThreePlaneShape(2000);
  struct Counter
  {
    int events = 0;
    bool abort = false;
    double last = 0.0;
  } counter;
  auto onProgress = [](vtkObject* caller, unsigned long, void* clientData, void* callData)
  {
    auto* c = static_cast<Counter*>(clientData);
    ++c->events;
    c->last = *static_cast<double*>(callData);
    if (c->abort)
      vtkAlgorithm::SafeDownCast(caller)->SetAbortExecute(1);
  };
  vtkNew<vtkCallbackCommand> callback;
  callback->SetCallback(onProgress);
  callback->SetClientData(&counter);
  vtkNew<vtkFoldingTreeBuilder> builder;
  builder->SetInputData(shape.mesh);
  builder->AddObserver(vtkCommand::ProgressEvent, callback);
  EventLog log;
  EXPECT(UpdateCapturing(builder, log) == 1, "progress run failed");
  EXPECT(counter.events > 2 && counter.last == 1.0,
    "builder progress: " << counter.events << " events, last " << counter.last);

  counter = Counter();
  counter.abort = true;
  vtkNew<vtkFoldingTreeBuilder> aborted;
  aborted->SetInputData(shape.mesh);
  aborted->AddObserver(vtkCommand::ProgressEvent, callback);
  vtkNew<vtkCallbackCommand> silence; // the abort warning
  aborted->AddObserver(vtkCommand::WarningEvent, silence);
  UpdateCapturing(aborted, log);
  auto* tree = vtkMultiBlockDataSet::SafeDownCast(aborted->GetOutputDataObject(0));
  vtkPolyData* info =
    tree && tree->GetNumberOfBlocks() == 2 ? vtkPolyData::SafeDownCast(tree->GetBlock(1)) : nullptr;
  std::printf("abort: %d progress events, tree %s, Aborted = %g\n",
    counter.events,
    info ? "present" : "absent",
    info ? FieldValue(info->GetFieldData(), "Aborted") : -1.0);
  EXPECT(
    !info || FieldValue(info->GetFieldData(), "Aborted") == 1.0, "an aborted build is not flagged");
}

int TestFoldingTreeFilters(int argc, char* argv[])
{
  const std::string tempDir = argc > 1 ? argv[1] : ".";

  vtkNew<vtkFoldingTreeBuilder> defaults;
  EXPECT(defaults->GetTolerance() == 0.02 && defaults->GetToleranceMode() == 0 &&
      defaults->GetKeepSide() == 0 && defaults->GetMinimumFaces() == 50 &&
      defaults->GetMinimumAreaFraction() == 0.05 && defaults->GetMaximumFolds() == 8 &&
      defaults->GetRequireMeaningfulSymmetry() && !defaults->GetRequireTightSymmetry() &&
      defaults->GetConnectNearbyParts() && defaults->GetMethod() == 0 &&
      defaults->GetRandomSeed() == 1 && defaults->GetSampledSearchAboveFaces() == 1000 &&
      defaults->GetRotationNodes() == vtkFoldingTreeBuilder::ROTATION_NODES_WHEN_AXIAL &&
      defaults->GetMaximumRotationOrder() == 64,
    "builder defaults differ from FoldingTreeOptions");

  std::vector<Case> cases;
  const auto threeFolds = [](const std::vector<NodeInfo>& nodes)
  {
    // Fold 0 -> Fold 1 -> Fold 2 -> Leaf 3.
    EXPECT(nodes.size() == 4, "three-plane shape: " << nodes.size() << " nodes");
    for (size_t k = 0; k < nodes.size() && k < 3; ++k)
      EXPECT(nodes[k].kind == 1 && nodes[k].index == static_cast<int>(k),
        "three-plane shape: node " << k << " is " << nodes[k].name);
    if (nodes.size() == 4)
      EXPECT(nodes[3].kind == 0 && nodes[3].name == "Leaf 3",
        "three-plane shape: last node " << nodes[3].name);
  };
  cases.push_back({ "three-plane shape",
    pm::MakeThreePlaneShape(4000),
    [](vtkFoldingTreeBuilder* b) { b->SetMinimumAreaFraction(0.13); },
    threeFolds,
    true,
    true,
    8 });
  // The sampled candidate search (default above 1000 faces: every node of this 4000-face
  // shape but the last) switched off, and on for every node: the same three folds.
  for (const int above : { 1000000000, 0 })
    cases.push_back({ above == 0 ? "three-plane shape, sampled search everywhere"
                                 : "three-plane shape, full search",
      pm::MakeThreePlaneShape(4000),
      [above](vtkFoldingTreeBuilder* b)
      {
        b->SetMinimumAreaFraction(0.13);
        b->SetSampledSearchAboveFaces(above);
        EXPECT(b->GetSampledSearchAboveFaces() == above, "SampledSearchAboveFaces not set");
      },
      threeFolds,
      true,
      true,
      8 });
  cases.push_back({ "bilateral blob",
    pm::MakeBilateralBlob(4000),
    [](vtkFoldingTreeBuilder* b) { b->SetMaximumFolds(1); },
    [](const std::vector<NodeInfo>& nodes)
    {
      EXPECT(nodes.size() == 2 && nodes[0].name == "Fold 0 (depth 0)" && nodes[1].name == "Leaf 1",
        "bilateral blob: " << nodes.size() << " nodes, root " << nodes[0].name);
    },
    true,
    true,
    2 });
  cases.push_back({ "blob + attachment",
    pm::MakeBlobWithAsymmetricPart(4000, 0.1),
    nullptr,
    [](const std::vector<NodeInfo>& nodes)
    {
      EXPECT(!nodes.empty() && nodes[0].kind == 2 && nodes[0].children.size() >= 2 &&
          nodes[nodes[0].children[0]].kind == 1,
        "blob + attachment: root " << (nodes.empty() ? "" : nodes[0].name)
                                   << " is not a segmentation node starting with a fold");
    },
    false,
    false });

  vtkSmartPointer<vtkMultiBlockDataSet> segmented;
  for (const Case& c : cases)
  {
    vtkSmartPointer<vtkMultiBlockDataSet> tree = RunCase(c, tempDir);
    segmented = tree;
  }
  if (segmented && segmented->GetNumberOfBlocks() == 2)
    TestMalformed(segmented);
  TestProgressAndAbort();

  if (failures)
  {
    std::printf("%d failure(s)\n", failures);
    return 1;
  }
  std::printf("All folding tree filter tests passed.\n");
  return 0;
}

int main(int argc, char* argv[])
{
  return TestFoldingTreeFilters(argc, argv);
}
