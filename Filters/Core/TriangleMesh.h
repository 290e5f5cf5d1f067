// Plain triangle-mesh types shared by the FoldingMeshes algorithms (no VTK types).
#ifndef foldingmeshes_TriangleMesh_h
#define foldingmeshes_TriangleMesh_h

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <utility>
#include <vector>

namespace foldingmeshes
{
using Vec3 = Eigen::Vector3d;
using Triangle = std::array<int, 3>;

/// Indexed triangle soup: the input of MeshPreparation.
struct TriangleMesh
{
  std::vector<Vec3> points;
  std::vector<Triangle> triangles;
};

/**
 * A triangle mesh made ready for symmetry detection: coincident points welded,
 * faces consistently oriented (outward on closed parts), normals, areas,
 * edge adjacency and parts (edge-connected components).
 */
struct PreparedMesh
{
  std::vector<Vec3> points;        ///< welded points
  std::vector<Triangle> triangles; ///< one per input triangle, same order, oriented
  std::vector<int> inputToWelded;  ///< input point id -> welded point id
  std::vector<int> weldedToInput;  ///< welded point id -> first input point id

  std::vector<Vec3> faceNormals;   ///< unit, zero for degenerate faces
  std::vector<Vec3> vertexNormals; ///< unit (area-weighted mean of oriented face normals)
  std::vector<Vec3> faceCentroids;
  std::vector<double> faceAreas;
  std::vector<double> vertexAreas;  ///< one third of the incident face areas
  std::vector<char> faceDegenerate; ///< zero area (ignored by distance queries)

  /// Faces sharing an edge with face f: faceNeighbors[faceNeighborOffsets[f] .. [f+1]).
  std::vector<int> faceNeighborOffsets;
  std::vector<int> faceNeighbors;
  /// Faces incident to vertex v: vertexFaces[vertexFaceOffsets[v] .. [v+1]).
  std::vector<int> vertexFaceOffsets;
  std::vector<int> vertexFaces;

  std::vector<int> facePart; ///< edge-connected component of each face
  int numberOfParts = 0;
  /// Vertex pairs of different parts lying within the proximity gap (see LinkNearbyParts).
  std::vector<std::pair<int, int>> proximityLinks;

  int numberOfBoundaryEdges = 0;
  int numberOfNonManifoldEdges = 0;
  int numberOfFlippedFaces = 0; ///< faces whose input orientation was reversed

  Vec3 boundsMin = Vec3::Zero();
  Vec3 boundsMax = Vec3::Zero();
  double diagonal = 0.0;
  double totalArea = 0.0;

  int NumberOfPoints() const { return static_cast<int>(points.size()); }
  int NumberOfFaces() const { return static_cast<int>(triangles.size()); }
};
}

#endif
