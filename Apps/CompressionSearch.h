// The fold settings `foldingmeshes compress --search` (and BenchmarkCompression --search) try
// besides the user's own, keeping the smallest .fmz file: fewer, larger leaves cost fewer bytes
// more often than they cost stored faces, since every leaf's border is coded on its own.
#ifndef foldingmeshes_CompressionSearch_h
#define foldingmeshes_CompressionSearch_h

#include "vtkFoldingTreeBuilder.h"

namespace foldingmeshes
{
struct FoldSearchVariant
{
  const char* options;        ///< as the command line spells them (JSON "foldOptions")
  bool keepFewer;             ///< KeepSide FEWER_FACES
  int minimumFaces;           ///< MinimumFaces; 0: left as it is
  double minimumAreaFraction; ///< MinimumAreaFraction; 0: left as it is
};

/// In the order tried after the user's settings (a tie keeps the earlier file; a variant whose
/// settings, on top of the user's, were folded already is skipped). Each is the
/// smallest on at least one Table 1 stand-in (docs/compression.md, 2026-12-05).
constexpr FoldSearchVariant FoldSearchVariants[] = {
  { "--keep fewer", true, 0, 0.0 },
  { "--min-area-fraction 0.2", false, 0, 0.2 },
  { "--min-faces 400", false, 400, 0.0 },
  { "--keep fewer --min-faces 400", true, 400, 0.0 },
  { "--keep fewer --min-area-fraction 0.2", true, 0, 0.2 },
};

/// The variant's settings on a builder configured with the user's (the rest stays theirs).
inline void ApplyFoldSearchVariant(vtkFoldingTreeBuilder* builder, const FoldSearchVariant& v)
{
  if (v.keepFewer)
    builder->SetKeepSide(vtkFoldingTreeBuilder::FEWER_FACES);
  if (v.minimumFaces > 0)
  {
    builder->SetUseMinimumFaces(true);
    builder->SetMinimumFaces(v.minimumFaces);
  }
  if (v.minimumAreaFraction > 0.0)
  {
    builder->SetUseMinimumAreaFraction(true);
    builder->SetMinimumAreaFraction(v.minimumAreaFraction);
  }
}
}

#endif
