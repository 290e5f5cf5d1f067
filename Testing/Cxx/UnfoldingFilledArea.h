// The unfolder's FilledAreaRatio against a hole of known area (part of TestUnfoldingAccuracy).
#ifndef foldingmeshes_UnfoldingFilledArea_h
#define foldingmeshes_UnfoldingFilledArea_h

namespace foldingmeshes
{
namespace testing
{
/**
 * A one-leaf tree of a UV sphere (vtkSphereSource) without the faces around its north pole, as
 * if the builder had lost them (no input border there): the unfolder's final repair fills the
 * ring around the pole, a planar polygon, so the filled faces' area is the polygon's. Checks
 * FilledAreaRatio x the tree's OriginalArea against it and that the ring is closed. Returns the
 * number of failed checks.
 */
int CheckFilledArea();
}
}

#endif
