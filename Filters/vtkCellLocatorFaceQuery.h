// The core's closest-face query (Core/ClosestFaceQuery.h) answered by a VTK cell locator:
// vtkStaticCellLocator by default, or a new instance of the locator a filter's user set
// (SetLocator, as VTK's own distance filters take one). Internal header of
// FoldingMeshes::Filters.
#ifndef vtkCellLocatorFaceQuery_h
#define vtkCellLocatorFaceQuery_h

#include "Core/ClosestFaceQuery.h"

class vtkAbstractCellLocator;

namespace foldingmeshes
{
/**
 * A factory of closest-face queries over a vtkUnstructuredGrid of the surface's triangles (one
 * cell per triangle, in order, so cell ids are triangle ids; a triangle whose corners are
 * collinear is a polyline around its edges, one whose corners coincide a vertex: measured as
 * SurfaceDistance.h defines it). `prototype` null: vtkStaticCellLocator; else each query uses
 * prototype->NewInstance() (its settings are not copied). vtkStaticCellLocator is queried from
 * several threads at once (its closest-point search keeps its state per call); other locators
 * are queried one thread at a time.
 */
ClosestFaceQueryFactory CellLocatorFaceQueryFactory(vtkAbstractCellLocator* prototype);
}

#endif
