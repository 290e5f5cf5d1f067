#include "CommandLine.h"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace foldingmeshes
{
namespace cli
{
int ParseUpAxis(const std::string& value)
{
  if (value == "auto")
    return -1;
  if (value == "x" || value == "y" || value == "z")
    return value[0] - 'x';
  throw std::runtime_error("--up must be auto, x, y or z, got '" + value + "'");
}

const char* const Usage = R"(usage: foldingmeshes detect MESH [options]
       foldingmeshes fold MESH [fold options]
       foldingmeshes unfold TREE.vtm [unfold options]
       foldingmeshes roundtrip MESH [fold options]
       foldingmeshes compress MESH [fold options] [--quantization-bits N|auto] [--keep-arrays]
                              [--search]
       foldingmeshes decompress FILE.fmz [unfold options]
       foldingmeshes --help | --version

COMMAND --help prints this text too.

MESH is a .vtp .vtk .ply .obj .stl or .off file; outputs are named after its stem.

detect: finds the dominant planar reflection symmetry of a triangle mesh and the largest
connected region that has it (Folding meshes, SGP 2006, section 3).
  --tolerance F            epsilon as a fraction of the bounding-box diagonal (default 0.02,
                           range 1e-12..1)
  --absolute-tolerance L   epsilon as a length (overrides --tolerance)
  --method robust|paper    several starts judged by final region (default) or the paper's one start
  --initial-plane OX,OY,OZ,NX,NY,NZ
                           start from this plane too (robust: an extra start; paper:
                           instead of the principal axes)
  --candidates N           voted candidate planes tried by the robust method (default 8,
                           range 0..64)
  --sampled-search-above N meshes with more than N faces search candidate planes on a
                           sampled copy (default 15000; 0: always; a huge N: the full search)
  --separate-parts         regions never span separate parts (default: parts touching within
                           epsilon are connected)
  --seed N                 seed of the candidate sampling (default 1)
  --rotation               also find the best rotational axis and order k (a turn by 360/k
                           maps a region onto itself within epsilon); writes the axis glyph
  --max-rotation-order N   largest order tried with --rotation (default 64, range 2..360)
  --output FILE            labelled mesh (default: MESH stem + "_symmetry.vtp" in --outdir)
  --plane-output FILE      plane glyph (default: MESH stem + "_plane.vtp" in --outdir)
  --axis-output FILE       axis glyph with --rotation (default: MESH stem + "_axis.vtp")
  --picture FILE           PNG picture (default: MESH stem + "_symmetry.png" in --outdir)
  --up auto|x|y|z          the picture's up axis (default auto: the longest axis lying in the
                           plane; files differ in which axis is up)
  --outdir DIR             folder for default outputs (default: current folder)
  --no-files               write nothing, only print
  --json                   print the result as JSON
  --quiet                  no progress on stderr
  --help                   this text

fold: folds the mesh into a folding tree (section 4.1-4.2) and writes, in --outdir,
STEM_tree.vtm (the tree, XML multiblock; its pieces go to the folder STEM_tree/),
STEM_segmentation.vtp (the mesh with cell arrays FoldingLeafId, FoldingDepth, FoldingRole)
and STEM_segmentation.png (coloured by FoldingLeafId: a mirrored face like its leaf); prints
original and stored faces, compression, tree height, folds, leaves and time.
  --tolerance F            root epsilon as a fraction of the diagonal (default 0.02), halved
                           below every fold
  --absolute-tolerance L   root epsilon as a length (overrides --tolerance)
  --keep more|fewer        a fold keeps the half with more faces (default, the paper's) or
                           fewer (less storage)
  --min-area-fraction F    leaf when a region's area is below F of the mesh's (default 0.05)
  --max-folds N            leaf when N folds lie above a region (default 8, at most 63)
  --min-faces N            leaf when a region has fewer than N faces (default 50)
  --method robust|paper    every node's detection, as for detect (default robust)
  --separate-parts         as for detect: regions and components never span separate parts
  --rotation               rotation nodes: where no fold lies above, keep one sector of a
                           rotational symmetry of order k (a turn by 360/k) and fold on
                           within it, on any mesh (docs/builder.md, "Rotation nodes")
  --rotation-when-axial    --rotation only where MESH's second moments are axially symmetric
                           (two eigenvalues within 2% of the larger): no cost elsewhere
                           (the default)
  --no-rotation            no rotation nodes (also turns compress's rule off)
  --max-rotation-order N   largest order tried with --rotation (default 64, range 2..360)
  --seed N                 seed of the candidate sampling, as for detect (default 1)
  --tight-symmetry         fold only clear symmetries (RMS mirror distance <= 0.35 epsilon);
                           default: every epsilon-symmetric region of >= 10% area, as the paper
  --no-verify-bound        skip the proof that unfold(tree) is within epsilon of MESH (and the
                           rebuilds that keep the faces where it fails out of every fold)
  --sampled-search-above N regions with more than N faces search candidate planes on a sampled
                           copy (default 1000; 0: every region; a huge N: the full search)
  --keep-projected-points  (roundtrip only) as for unfold
  --keep-copy-density      (roundtrip only) as for unfold
  --no-stitch              (roundtrip only) as for unfold
  --no-close-holes         (roundtrip only) as for unfold
  --distance-locator static|facetree
                           (roundtrip only) what answers the closest-triangle queries of its
                           distances: vtkStaticCellLocator (default, as unfold --original) or
                           the core's face tree (the same distances, 7-10x faster)
  Other builder parameters (the Use* switches of the stop criteria, RequireMeaningfulSymmetry)
  keep their defaults here; they are set in C++, Python and ParaView.
  --up auto|x|y|z          the picture's up axis (default auto: +Y, +Z when Y is the thinnest
                           extent)
  --outdir DIR             folder for the outputs (default: current folder)
  --json                   print the result as JSON
  --quiet                  no progress on stderr

unfold: reconstructs the mesh from a tree written by fold (section 4.3) and writes, in
--outdir, STEM_unfolded.vtp and STEM_unfolded.png (coloured by FoldingLeafId), where STEM is
the tree's file stem without a trailing "_tree"; prints faces, open edges, stitched vertices,
projected points removed and left, points removed from mirrored copies, and stitch gaps
(before the final repair).
  --no-stitch              the raw union of the copies: no stitching or smoothing of tears,
                           no final weld and no final repair
  --no-close-holes         no final repair (non-manifold faces dropped, orientation made
                           consistent, holes that are not the input's border filled)
  --keep-projected-points  keep the vertices the builder projected onto fold planes (default:
                           removed after mirroring and their 1-rings re-triangulated where the
                           error budget allows, so the vertex count stays close to the input's)
  --keep-copy-density      keep every mirrored copy as dense as the half it mirrors (default:
                           thinned to the face count of the fold's region where the error
                           budget allows: a fold whose halves were tessellated differently
                           keeps the denser half, whose mirror image would double it; and a
                           rotation node's copies of its sector towards its region's face count)
  --original MESH          also measure the distance to MESH (the folded input): Hausdorff
                           and mean distance, also as fractions of its diagonal (-1 without)
  --up auto|x|y|z          the picture's up axis, as for fold
  --outdir DIR             folder for the outputs (default: current folder)
  --json, --quiet          as for fold

roundtrip: folds MESH (fold options), writes STEM_tree.vtm, reads it back, unfolds it, writes
STEM_unfolded.vtp and reports the symmetric Hausdorff distance between the (triangulated)
input and the unfolded mesh as a fraction of the input's bounding-box diagonal: the maximum
and the mean over the vertices and face centroids of both meshes of the distance to the other
surface, and the maximum over every point of both surfaces (a proved upper bound, within 1e-5
of the diagonal). Also prints the open (boundary) edges and the vertices before and after
(vertices at identical positions counted as one). Fails with exit code 4 when the proved bound
exceeds the root epsilon (decided to 1e-7 of the diagonal). No pictures.

compress: folds MESH (fold options) and writes STEM.fmz in --outdir: the compact folding tree,
only what unfolding needs, the leaves coded with Draco; prints (JSON: "output", "bytes")
its size, the stored faces and the quantisation. Unless given, compress folds with
--min-faces 400 (fewer, larger leaves: files up to 39% smaller) and --rotation-when-axial;
a tree that gets rotation nodes so is compared with the fold without them (--no-rotation)
and the smaller file kept (JSON "foldOptions": what it added to the options given, "" none;
the other fold options keep the fold command's defaults). The file kept is decompressed and its distance to
MESH proved, and a closed MESH to come back closed ("proved bound", JSON "provedBound",
"provedWithin"); with the automatic bits it
is written again with two more bits while not within the root epsilon (JSON "proofRetries";
a warning where even 24 bits do not prove it).
  --quantization-bits N    position bits per coordinate, 6..24, or auto (default): the fewest
                           (at least 8) whose error is at most half of the smallest error
                           budget of a stored point (and, with rotation nodes, at most their
                           seams' stitch tolerance), raised by two while the file is not
                           proved within the root epsilon (up to 24; given bits: no more)
  --keep-arrays            also store the mesh's point and cell arrays (lossless; a larger
                           file: the geometry is then coded in the leaves' order)
  --search                 also fold with up to six other settings (the options given alone,
                           --keep fewer, --min-faces 400, --min-area-fraction 0.2 and
                           combinations, --rotation --min-faces 400, on top of the options
                           given; settings already folded are not folded again; all but the
                           last without rotation nodes unless a rotation option is given, so
                           labelled --no-rotation on an axial MESH; with --no-rotation, none
                           with rotation nodes) and keep the smallest file
                           (JSON "foldOptions", "foldSettingsTried"); up to eight folds: about
                           eight times the time
decompress: unfolds a .fmz file like unfold (same options, --original too) and writes
STEM.vtp and STEM.png in --outdir (JSON: "output"). Not kept in a .fmz: input ids, and user
arrays without --keep-arrays (keep the .vtm for those). unfold reads .fmz files too.

Pictures need a display: without $DISPLAY they are skipped with a message (use xvfb-run -a).

exit codes: 0 success, 1 bad command line, 2 unreadable or invalid input, 3 cannot write,
            4 roundtrip: Hausdorff distance above the root epsilon (the paper's bound;
              proved over whole surfaces, to 1e-7 of the diagonal)
)";

double ParseNumber(const std::string& what,
  const std::string& text,
  double lo,
  double hi,
  bool positive)
{
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || !(x >= lo && x <= hi) || (positive && !(x > 0.0)))
  {
    std::ostringstream msg;
    msg << what << " needs a number" << (positive ? " > 0" : "") << " in [" << lo << ", " << hi
        << "], got '" << text << "'";
    throw std::runtime_error(msg.str());
  }
  return x;
}

int ParseInteger(const std::string& what, const std::string& text, int lo, int hi)
{
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || !(x >= lo && x <= hi) || x != std::floor(x))
  {
    std::ostringstream msg;
    msg << what << " needs an integer in [" << lo << ", " << hi << "], got '" << text << "'";
    throw std::runtime_error(msg.str());
  }
  return static_cast<int>(x);
}

bool ParseNumbers(const std::string& text, std::vector<double>& values)
{
  std::stringstream in(text);
  std::string item;
  values.clear();
  while (std::getline(in, item, ','))
  {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (end == item.c_str() || *end != '\0' || !std::isfinite(v))
      return false;
    values.push_back(v);
  }
  return true;
}

std::string JsonString(const std::string& s)
{
  std::string out = "\"";
  for (char c : s)
  {
    if (c == '"' || c == '\\')
      out += '\\';
    out += c;
  }
  return out + "\"";
}
}
}
